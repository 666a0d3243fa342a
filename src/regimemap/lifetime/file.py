"""The ``[lifetime]`` table of the design file: the climate and the options of the lifetime simulation.

:class:`LifetimeSpec` is the table as the file gives it; the keys it accepts,
with what each accepts, are in :mod:`regimemap.lifetime.file_keys`;
:func:`read_lifetime` reads the table with the line of every key refused
(:func:`regimemap.io.toml_lines.key_line`); :func:`lifetime_model` turns it into
a :class:`regimemap.lifetime.LifetimeModel`.  :mod:`regimemap.caisson.file` reads
the whole file and re-exports the public names.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from ..io.toml_errors import DesignFileError, did_you_mean
from ..io.toml_lines import key_line, key_text
from .file_keys import (
    ERROR_FACTORS,
    LIFETIME_KEYS,
    LIFETIME_TABLES,
    LifetimeSpec,
    default_of,
)

if TYPE_CHECKING:
    from regimemap.lifetime import LifetimeModel

    from .file_record import RecordSpec

__all__ = ["LifetimeSpec", "lifetime_model", "read_lifetime"]

_CLIMATE = ("either H0_10 and H0_50 (the 10- and 50-year return values of H0', metres) or "
            "annual_maxima (a list of annual maxima of H0', metres)")


class _LifetimeReader:
    """Reads ``[lifetime]`` with the line of every key in the messages."""

    def __init__(self, text: str, source: str) -> None:
        self.text = text
        self.source = source

    def where(self, table: str, key: str | None = None) -> str:
        line = key_line(self.text, table, key)
        return self.source if line is None else f"{self.source}, line {line}"

    def fail(self, table: str, key: str | None, what: str) -> DesignFileError:
        return DesignFileError(f"{self.where(table, key)}: {what}")

    def bad(self, table: str, key: str, value: Any, why: str) -> DesignFileError:
        accepted = LIFETIME_TABLES[table][key].accepted
        written = key_text(self.text, table, key) if not isinstance(value, list) else None
        shown = written if written is not None else repr(value)
        return self.fail(table, key, f"[{table}] {key} = {shown}: {why}; accepted: {accepted}")

    def check_names(self, table: str, data: Mapping[str, Any]) -> None:
        known = LIFETIME_TABLES[table]
        for key in data:
            if key not in known:
                raise self.fail(table, key, f"unknown key [{table}] {key}{did_you_mean(key, known)}; "
                                f"accepted keys in [{table}]: {', '.join(known)}")

    def number(self, table: str, data: Mapping[str, Any], key: str, value: Any,
               item: bool = False) -> float:
        """``value`` (``data[key]``, or an item of that list) checked as a number of ``key``."""
        spec = LIFETIME_TABLES[table][key]
        which = f"{value!r} in the list is " if item else ""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            found = f"{which}{_toml_type(value)}" if item else _toml_type(value)
            raise self.bad(table, key, data[key], f"expected {'numbers' if item else 'a number'}, "
                           f"found {found}")
        x = float(value)
        if not math.isfinite(x):
            raise self.bad(table, key, data[key], f"{which}not a finite number")
        if not spec.check(x):
            raise self.bad(table, key, data[key], f"{which}{spec.why(x)}")
        return x

    def value(self, table: str, data: Mapping[str, Any], key: str) -> Any:
        """The checked value of ``key`` (None when absent)."""
        if key not in data:
            return None
        kind = LIFETIME_TABLES[table][key].kind
        if kind == "number":
            return self.number(table, data, key, data[key])
        read = {"int": self._int, "text": self._text, "bool": self._bool, "numbers": self._numbers,
                "pair": self._pair, "limits": self._limits}.get(kind, self._table)
        return read(table, data, key)

    def _int(self, table: str, data: Mapping[str, Any], key: str) -> int:
        v = data[key]
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.bad(table, key, v, f"expected a whole number, found {_toml_type(v)}")
        if not LIFETIME_TABLES[table][key].check(v):
            raise self.bad(table, key, v, "out of range")
        return v

    def _text(self, table: str, data: Mapping[str, Any], key: str) -> str:
        v = data[key]
        if not isinstance(v, str):
            raise self.bad(table, key, v, f"expected a string, found {_toml_type(v)}")
        if not LIFETIME_TABLES[table][key].check(v):
            raise self.bad(table, key, v, "not one of the accepted values")
        return v

    def _bool(self, table: str, data: Mapping[str, Any], key: str) -> bool:
        v = data[key]
        if not isinstance(v, bool):
            raise self.bad(table, key, v, f"expected true or false, found {_toml_type(v)}")
        return v

    def _numbers(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, ...]:
        v = data[key]
        if not isinstance(v, list):
            raise self.bad(table, key, v, f"expected a list of numbers, found {_toml_type(v)}")
        if not v:
            raise self.bad(table, key, v, "the list is empty")
        return tuple(self.number(table, data, key, x, item=True) for x in v)

    def _pair(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, float]:
        v = data[key]
        if not isinstance(v, list) or len(v) != 2:
            found = f"a list of {len(v)}" if isinstance(v, list) else _toml_type(v)
            raise self.bad(table, key, v, f"expected [ratio, cov], found {found}")
        for x in v:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
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
                           f"expected a table {{sliding = probability}}, found {_toml_type(v)}")
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
            out[x] = float(p)
        return dict(sorted(out.items()))

    def _table(self, table: str, data: Mapping[str, Any], key: str) -> dict[str, Any]:
        v = data[key]
        if not isinstance(v, dict):
            raise self.bad(table, key, v, f"expected a table, found {_toml_type(v)}")
        return v

    def check_climate(self, t: str, got: Mapping[str, Any], data: Mapping[str, Any]) -> None:
        """The climate of return values or annual maxima: complete, consistent."""
        h10, h50, maxima = got["H0_10"], got["H0_50"], got["annual_maxima"]
        if maxima is not None and (h10 is not None or h50 is not None):
            raise self.fail(t, "annual_maxima", "[lifetime] annual_maxima together with "
                            f"{'H0_10' if h10 is not None else 'H0_50'}; accepted: {_CLIMATE}")
        if maxima is None:
            if h10 is None or h50 is None:
                if h10 is None and h50 is None:
                    raise self.fail(t, None, f"[lifetime] has no wave climate; accepted: {_CLIMATE}")
                given, missing = ("H0_10", "H0_50") if h50 is None else ("H0_50", "H0_10")
                raise self.fail(t, given, f"[lifetime] {missing} is missing ({given} = "
                                f"{data[given]!r} is given); accepted: {_CLIMATE}")
            if not h50 > h10:
                raise self.bad(t, "H0_50", data["H0_50"], f"not above [lifetime] H0_10 = {data['H0_10']!r}")
        else:
            if len(maxima) < 3:
                raise self.bad(t, "annual_maxima", data["annual_maxima"],
                               f"{len(maxima)} value{'s' if len(maxima) != 1 else ''}, fewer than three")
            if min(maxima) == max(maxima):
                raise self.bad(t, "annual_maxima", data["annual_maxima"], "the values are all equal")
            if got["storms_per_year"] is not None:
                raise self.fail(t, "storms_per_year", f"[lifetime] storms_per_year = "
                                f"{data['storms_per_year']!r} together with annual_maxima; accepted: "
                                "annual maxima are one storm a year: give H0_10 and H0_50 of the peaks "
                                "over a threshold with storms_per_year, or annual_maxima alone")
            if got["distribution"] != "gumbel" and got["shape"] is not None and not got["shape"] > 1.0:
                raise self.bad(t, "shape", data["shape"], "fitting annual_maxima with a Weibull "
                               "distribution needs k > 1 (the likelihood is unbounded for k <= 1)")

    def read(self, data: Mapping[str, Any]) -> LifetimeSpec:
        t = "lifetime"
        self.check_names(t, data)
        got = {key: self.value(t, data, key) for key in LIFETIME_KEYS}
        errors: dict[str, tuple[float, float]] = {}
        if got["errors"] is not None:
            self.check_names("lifetime.errors", got["errors"])
            for key in ERROR_FACTORS:
                pair = self.value("lifetime.errors", got["errors"], key)
                if pair is not None:
                    errors[key] = pair

        record = _record_table(self.text, self.source, got, data)
        if record is None:
            self.check_climate(t, got, data)
        if got["period"] is not None and got["steepness"] is not None:
            raise self.fail(t, "steepness", f"[lifetime] steepness = {data['steepness']!r} together with "
                            f"[lifetime] period = {data['period']!r}; accepted: one of them, or neither "
                            "(Goda's T1/3 = 3.3 H0'^0.63)")
        # every key as given, else its declared default; then those read with others
        values = {key: default_of(key) if got[key] is None else got[key] for key in LIFETIME_KEYS}
        values.update(
            thresholds=None if got["thresholds"] is None else tuple(sorted(set(got["thresholds"]))),
            errors=errors, record=record, climate_replicates=_replicates(got["climate_replicates"], record),
            written={key: _written(data[key]) for key in ("H0_10", "H0_50", "annual_maxima") if key in data})
        spec = LifetimeSpec(**values)
        try:  # anything the checks above missed, said the library's way
            lifetime_model(spec)
        except ValueError as exc:
            raise self.fail(t, None, f"[lifetime]: {exc}") from None
        return spec


def _replicates(given: int | None, record: RecordSpec | None) -> int:
    """``climate_replicates`` as given; with a record and none given,
    :data:`regimemap.lifetime.replicates.DEFAULT_REPLICATES` (a record's climate is judged with its
    uncertainty); 0 without a record."""
    from .replicates import DEFAULT_REPLICATES

    if given is not None:
        return int(given)
    return DEFAULT_REPLICATES if record is not None else 0


def _record_table(text: str, source: str, got: Mapping[str, Any], data: Mapping[str, Any]
                  ) -> RecordSpec | None:
    """``[lifetime.record]`` read by :func:`regimemap.lifetime.file_record.read_record_table`; refused
    beside another climate; ``climate_replicates`` only with it."""
    from .file_record import read_record_table

    if got["record"] is None:
        if got["climate_replicates"] is not None:
            raise DesignFileError(f"{source}: [lifetime] climate_replicates needs a [lifetime.record] "
                                  "table (the replicates are the bootstrap of the record's fit)")
        return None
    others = [k for k in ("H0_10", "H0_50", "annual_maxima", "storms_per_year", "distribution", "shape")
              if k in data]
    if others:
        line = key_line(text, "lifetime", others[0])
        where = source if line is None else f"{source}, line {line}"
        raise DesignFileError(f"{where}: [lifetime] {others[0]} together with [lifetime.record]; "
                              "accepted: the record alone (its fit gives the climate and the storm rate)")
    return read_record_table(text, source, got["record"])


def _flatten(table: Mapping[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    """The items of a table, nested tables joined by ``.`` (``{"0": {"1": p}}`` -> ``("0.1", p)``)."""
    out: list[tuple[str, Any]] = []
    for name, value in table.items():
        full = f"{prefix}.{name}" if prefix else str(name)
        out += _flatten(value, full) if isinstance(value, dict) else [(full, value)]
    return out


def _written(value: Any) -> str:
    """A parsed TOML value as the file wrote it (the shortest text that reads back the same)."""
    if isinstance(value, list):
        return "[" + ", ".join(_written(x) for x in value) + "]"
    return repr(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)


def _toml_type(v: Any) -> str:
    """The TOML name of a parsed value's type, for the messages."""
    names = {bool: "a boolean", int: "an integer", float: "a float", str: "a string", list: "an array",
             dict: "a table"}
    return names.get(type(v), type(v).__name__)


def lifetime_model(spec: LifetimeSpec, years: int | None = None) -> LifetimeModel:
    """The :class:`regimemap.lifetime.LifetimeModel` of a ``[lifetime]`` table (``years`` instead of its own).

    ``years`` is not checked here (:func:`check_lifetime_option` does).
    """
    import numpy as np

    from regimemap.lifetime import DEFAULT_ERRORS, DEFAULT_THRESHOLDS, Climate, ErrorFactor, LifetimeModel

    law = None
    if spec.record is not None:
        from .file_record import record_climate, record_period_law

        climate = record_climate(spec.record)
        if spec.period is None and spec.steepness is None:
            law = record_period_law(spec.record)
    else:
        try:  # an overflow of the fit is named here, not printed by numpy
            with np.errstate(all="raise"):
                if spec.annual_maxima is not None:
                    from regimemap.climate.life import climate_of_maxima

                    climate = climate_of_maxima(spec.annual_maxima, spec.distribution, spec.shape)
                else:
                    assert spec.H0_10 is not None and spec.H0_50 is not None
                    climate = Climate.from_return_values(spec.H0_10, spec.H0_50, spec.distribution,
                                                         spec.shape, spec.storms_per_year)
                climate.return_value(50.0)
        except (FloatingPointError, OverflowError) as exc:
            what = "annual_maxima" if spec.annual_maxima is not None else "H0_10 and H0_50"
            raise ValueError(f"the {spec.distribution} climate of {what} cannot be computed ({exc}): "
                             "the values are too far apart or too close together") from None
    errors = replace(DEFAULT_ERRORS, **{name: ErrorFactor(*pair) for name, pair in spec.errors.items()})
    return LifetimeModel(climate, years=spec.years if years is None else years,
                         storm_hours=spec.storm_hours, period=spec.period, steepness=spec.steepness,
                         tide_range=spec.tide_range, impulsive=spec.impulsive, truncate=spec.truncate,
                         period_law=law,
                         errors=errors,
                         thresholds=DEFAULT_THRESHOLDS if spec.thresholds is None else spec.thresholds)


def read_lifetime(text: str, source: str, table: Mapping[str, Any]) -> LifetimeSpec:
    """The checked ``[lifetime]`` table (``table``, as tomllib parsed it from ``text``).

    Raises
    ------
    DesignFileError
        Naming ``source``, the line of the key (from ``text``), the key, the
        value and what is accepted.
    """
    return _LifetimeReader(text, source).read(table)
