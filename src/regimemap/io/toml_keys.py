"""The keys of an input file's tables, declared once (:func:`key`), and their reader (:class:`KeyReader`).

Each key of a table is one field of the table's dataclass, declared with :func:`key`: its type
and default (none: required), what it accepts in words, its TOML kind, its range test, why a
value out of range is refused, and its lines in the commented example.  From those fields come
the table's keys (:func:`keys_of`: the words of the messages, the "did you mean" of an unknown
key, the documentation's tables), a key's default (:func:`default_of`), the table's part of the
commented example (:func:`example_table`), and the reading of the table: :class:`KeyReader`
names the file, the line and the key of every value it refuses, with what is accepted.  The
design file's tables (:mod:`regimemap.caisson.file_keys`, :mod:`regimemap.lifetime.file_keys`,
:mod:`regimemap.lifetime.file_record`) and the study file's
(:mod:`regimemap.study.file_sections`) are declared and read with them.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Callable, Mapping
from dataclasses import MISSING, Field, dataclass, field, fields
from typing import Any, TypeVar

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

from .toml_errors import DesignFileError, did_you_mean
from .toml_lines import key_line, key_text

__all__ = ["KINDS", "Key", "KeyReader", "default_of", "example_table", "key", "keys_of", "load_toml",
           "number_of", "toml_type"]

#: The TOML kinds of a key's value, as the documentation's tables name them.
KINDS = ("number", "int", "text", "bool", "numbers", "pair", "limits", "table")


def _anything(x: Any) -> bool:
    return True


@dataclass(frozen=True)
class Key:
    """One key of a table: what it accepts in words, its TOML kind, its range test, whether it is
    required, why a value out of range is refused, and its lines in the commented example."""

    accepted: str                             # what is accepted, in words
    kind: str = "number"                      # one of KINDS
    check: Callable[[Any], bool] = _anything  # the range test of a value of its kind
    why: Callable[[float], str] | None = None  # why a value the check refuses is wrong
    required: bool = False
    example: str = ""                         # its lines in the commented example (none: not shown)

    def reason(self, x: float) -> str:
        """Why ``x`` is refused: ``why(x)``, else ``"out of range"``."""
        return "out of range" if self.why is None else self.why(x)


def key(accepted: str, check: Callable[[Any], bool] = _anything, *, kind: str = "number",
        why: Callable[[float], str] | None = None, default: Any = MISSING,
        factory: Callable[[], Any] | None = None, example: str = "") -> Any:
    """One key of an input file's table, declared once: the dataclass field of its value.

    Parameters
    ----------
    accepted : str
        What the key accepts, in words (the error messages and the docs say it).
    check : callable, optional
        The range test of a value (of a number, an item of a list, a text ...).
    kind : str
        Its TOML kind, one of :data:`KINDS` (default ``"number"``).
    why : callable, optional
        ``why(value)``: why a value out of range is refused (the physics, the likely unit slip);
        without it, ``"out of range"``.
    default : optional
        The value when the file does not give the key; without one (nor ``factory``) the key is
        required.
    factory : callable, optional
        Makes the default (a table's).
    example : str
        Its lines in the commented example file, as written there.
    """
    spec = Key(accepted, kind, check, why, required=default is MISSING and factory is None, example=example)
    if factory is not None:
        return field(default_factory=factory, metadata={"key": spec})
    return field(default=default, metadata={"key": spec})


def _key_fields(cls: type) -> list[Field[Any]]:
    return [f for f in fields(cls) if "key" in f.metadata]


def keys_of(cls: type) -> dict[str, Key]:
    """The keys a table's dataclass declares, in the order declared."""
    return {f.name: f.metadata["key"] for f in _key_fields(cls)}


def default_of(cls: type, name: str) -> Any:
    """The value of the key ``name`` of ``cls``'s table when the file leaves it out."""
    f = next(f for f in _key_fields(cls) if f.name == name)
    if f.default is MISSING:
        return f.default_factory()  # type: ignore[operator]
    return f.default


def example_table(title: str, cls: type) -> str:
    """The table ``[title]`` of a commented example: its header and its keys' example lines."""
    return f"[{title}]\n" + "".join(f"{k.example}\n" for k in keys_of(cls).values() if k.example)


def toml_type(v: Any) -> str:
    """The TOML name of a parsed value's type, for the messages (``"a string"``)."""
    names = {bool: "a boolean", int: "an integer", float: "a float", str: "a string", list: "an array",
             dict: "a table"}
    return names.get(type(v), type(v).__name__)


def number_of(v: Any) -> float | None:
    """A parsed TOML number as a float; None for anything else (a boolean included)."""
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def load_toml(text: str, error: Callable[[str, int | None, int | None], Exception]) -> dict[str, Any]:
    """The TOML ``text`` as a dict; a syntax error raises ``error(message, line, column)`` (the
    position cut from tomllib's message; None when it gives none)."""
    try:
        data: dict[str, Any] = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\s*\(at line (\d+), column (\d+)\)", msg)
        if m is None:
            raise error(msg, None, None) from None
        raise error(msg[:m.start()] + msg[m.end():], int(m.group(1)), int(m.group(2))) from None
    return data


def _flatten(table: Mapping[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    """The items of a table, nested tables joined by ``.`` (``{"0": {"1": p}}`` -> ``("0.1", p)``)."""
    out: list[tuple[str, Any]] = []
    for name, value in table.items():
        full = f"{prefix}.{name}" if prefix else str(name)
        out += _flatten(value, full) if isinstance(value, dict) else [(full, value)]
    return out


def _finite(x: Any) -> bool:
    return not isinstance(x, bool) and isinstance(x, (int, float)) and math.isfinite(x)


_Table = TypeVar("_Table")
#: The scalar kinds of a key: the type test of a value, what the messages say is expected, and why a
#: value its check refuses is wrong.
_SCALARS: dict[str, tuple[Callable[[Any], bool], str, str]] = {
    "int": (lambda v: isinstance(v, int) and not isinstance(v, bool), "a whole number", "out of range"),
    "text": (lambda v: isinstance(v, str), "a string", "not one of the accepted values"),
    "bool": (lambda v: isinstance(v, bool), "true or false", "out of range"),
}


class KeyReader:
    """Reads the tables of a parsed TOML file, checked against their declared keys; every error is
    a :class:`~regimemap.io.toml_errors.DesignFileError` that names the file, the line of the key
    (found in ``text``, :func:`~regimemap.io.toml_lines.key_line`), the key and what is accepted.

    Parameters
    ----------
    source : str
        The file's name, for the messages.
    text : str
        Its TOML text (for the lines, and the values as written).
    tables : mapping
        The keys of each table it reads (``{"site": keys_of(SiteSpec), ...}``).
    """

    def __init__(self, source: str, text: str, tables: Mapping[str, Mapping[str, Key]]) -> None:
        self.source = source
        self.text = text
        self.tables = tables

    def at(self, line: int | None) -> str:
        """``source, line N`` (``source`` when the line is not known)."""
        return self.source if line is None else f"{self.source}, line {line}"

    def where(self, table: str | None = None, key: str | None = None) -> str:
        """``source, line N`` of ``[table] key`` (of the table's header without ``key``)."""
        return self.at(None if table is None else key_line(self.text, table, key))

    def fail(self, what: str, table: str | None = None, key: str | None = None) -> DesignFileError:
        """The error ``what``, at the line of ``[table] key``."""
        return DesignFileError(f"{self.where(table, key)}: {what}")

    def written(self, table: str, key: str, value: object) -> str:
        """``value`` as the file writes it (``10.10``, ``1e300``), else its repr."""
        return key_text(self.text, table, key) or repr(value)

    def bad(self, table: str, key: str, value: Any, why: str) -> DesignFileError:
        """``[table] key = VALUE: why; accepted: ...`` at the key's line, the value as written."""
        shown = self.written(table, key, value)
        return self.fail(f"[{table}] {key} = {shown}: {why}; accepted: {self.tables[table][key].accepted}",
                         table, key)

    def check_keys(self, table: str, data: Mapping[str, Any]) -> None:
        """Refuse a key of ``data`` that ``table`` does not declare, with the closest one."""
        known = self.tables[table]
        for name in data:
            if name not in known:
                raise self.fail(f"unknown key [{table}] {name}{did_you_mean(name, known)}; "
                                f"accepted keys in [{table}]: {', '.join(known)}", table, name)

    def table(self, table: str, data: Mapping[str, Any], cls: type[_Table], **given: Any) -> _Table:
        """``[table]`` (``data``) as its dataclass ``cls``: each key read and checked in the order
        declared (its default when the file leaves an optional key out), but those ``given`` (read
        already, for a check across keys)."""
        values = dict(given)
        for name, spec in keys_of(cls).items():
            if name in values:
                continue
            if name in data:
                values[name] = self.value(table, data, name)
            elif spec.required:
                raise self.fail(f"[{table}] {name} is missing; accepted: {spec.accepted}", table)
        return cls(**values)

    def value(self, table: str, data: Mapping[str, Any], key: str) -> Any:
        """The checked value of ``data[key]``, read as its declared kind (None when absent)."""
        if key not in data:
            return None
        read = {"number": self._number, "int": self._scalar, "text": self._scalar, "bool": self._scalar,
                "numbers": self._numbers, "pair": self._pair, "limits": self._limits,
                "table": self._table}[self.tables[table][key].kind]
        return read(table, data, key)

    def number(self, table: str, data: Mapping[str, Any], key: str, value: Any, item: bool = False) -> float:
        """``value`` (``data[key]``, or an item of that list) checked as a number of ``key``."""
        spec = self.tables[table][key]
        which = f"{value!r} in the list is " if item else ""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            found = toml_type(value)
            raise self.bad(table, key, data[key], f"expected {'numbers' if item else 'a number'}, "
                           f"found {which}{found}")
        x = float(value)
        if not math.isfinite(x):
            raise self.bad(table, key, data[key], f"{which}not a finite number")
        if not spec.check(x):
            raise self.bad(table, key, data[key], f"{which}{spec.reason(x)}")
        return x

    def _number(self, table: str, data: Mapping[str, Any], key: str) -> float:
        return self.number(table, data, key, data[key])

    def _scalar(self, table: str, data: Mapping[str, Any], key: str) -> Any:
        """A whole number, a text or a boolean (:data:`_SCALARS`), of its type and passing its check."""
        v = data[key]
        is_kind, expected, refused = _SCALARS[self.tables[table][key].kind]
        if not is_kind(v):
            raise self.bad(table, key, v, f"expected {expected}, found {toml_type(v)}")
        if not self.tables[table][key].check(v):
            raise self.bad(table, key, v, refused)
        return v

    def _numbers(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, ...]:
        v = data[key]
        if not isinstance(v, list):
            raise self.bad(table, key, v, f"expected a list of numbers, found {toml_type(v)}")
        if not v:
            raise self.bad(table, key, v, "the list is empty")
        return tuple(self.number(table, data, key, x, item=True) for x in v)

    def _pair(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, float]:
        v = data[key]
        if not isinstance(v, list) or len(v) != 2:
            found = f"a list of {len(v)}" if isinstance(v, list) else toml_type(v)
            raise self.bad(table, key, v, f"expected [ratio, cov], found {found}")
        for x in v:
            if not _finite(x):
                raise self.bad(table, key, v, f"{x!r} is not a finite number")
        ratio, cov = float(v[0]), float(v[1])
        if not ratio > 0.0:
            raise self.bad(table, key, v, f"the ratio {v[0]!r} is not > 0")
        if not cov >= 0.0:
            raise self.bad(table, key, v, f"the cov {v[1]!r} is < 0")
        return ratio, cov

    def _limits(self, table: str, data: Mapping[str, Any], key: str) -> dict[float, float]:
        """``{sliding m: probability}``; a bare key ``0.1`` (TOML's dotted ``0`` . ``1``) reads as 0.1."""
        v = data[key]
        if not isinstance(v, dict):
            raise self.bad(table, key, v,
                           f"expected a table {{sliding = probability}}, found {toml_type(v)}")
        if not v:
            raise self.bad(table, key, v, "the table is empty")
        out: dict[float, float] = {}
        for name, p in _flatten(v):
            try:
                x = float(name)
            except ValueError:
                raise self.bad(table, key, v,
                               f"the key {name!r} is not a sliding distance in metres") from None
            if not (math.isfinite(x) and x > 0.0):
                raise self.bad(table, key, v, f"the sliding {name!r} is not > 0 m")
            if isinstance(p, bool) or not isinstance(p, (int, float)) or not 0.0 <= float(p) <= 1.0:
                raise self.bad(table, key, v, f"the probability {p!r} of {name} m is not in [0, 1]")
            if x in out:
                first = next(n for n, _ in _flatten(v) if float(n) == x)
                raise self.bad(table, key, v, f"the sliding {name!r} is given twice (also as {first!r})")
            out[x] = float(p)
        return dict(sorted(out.items()))

    def _table(self, table: str, data: Mapping[str, Any], key: str) -> dict[str, Any]:
        v = data[key]
        if not isinstance(v, dict):
            raise self.bad(table, key, v, f"expected a table, found {toml_type(v)}")
        return v
