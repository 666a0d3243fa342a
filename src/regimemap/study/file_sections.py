"""The readers of a study file's parts: its keys, ``[[section]]`` and ``[[scenario]]``, the lines.

:mod:`regimemap.study.file` reads a study file with these: the keys each part
accepts, declared as the fields of :class:`StudyKeys`, :class:`SectionKeys` and
:class:`ScenarioKeys` (:func:`regimemap.io.toml_keys.key`), the line of a key inside
the n-th ``[[section]]`` (:class:`Where`), a section's design
tables merged and written back as TOML (:class:`Merged`) with where each line came
from, so the design reader's messages name the study file's (or the base's) line.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..caisson.file_keys import DESIGN_KEYS
from ..io.toml_errors import DesignFileError, did_you_mean
from ..io.toml_keys import Key, KeyReader, default_of, key, keys_of, number_of
from ..io.toml_keys import load_toml as toml_data
from ..lifetime.file_keys import LIFETIME_KEYS, MAX_TRIALS

if TYPE_CHECKING:
    from ..caisson.file import Design

__all__ = ["DESIGN_TABLES", "OVERRIDABLE", "SCENARIO_KEYS", "SECTION_KEYS", "STUDY_KEYS", "STUDY_WIDE",
           "Merged", "Origin", "ScenarioKeys", "SectionKeys", "StudyFileError", "StudyKeys", "Where",
           "check_names", "check_override", "design_of", "load_toml", "scenario_values",
           "section_key", "section_widths", "toml_value", "top_line", "year_table"]


class StudyFileError(DesignFileError):
    """A study file that cannot be read or accepted (file, line and key named)."""


@dataclass(frozen=True)
class StudyKeys:
    """The study's own keys at the top level (besides the design file's tables)."""

    base: str | None = key("a design file, relative to the study file (default: the tables inline)",
                           kind="text", default=None)
    seed: int | None = key("a whole number >= 0, the root seed of every task (default: [lifetime] seed)",
                           lambda x: x >= 0, kind="int", default=None)
    trials: int | None = key(f"lifetimes per task, 1 to {MAX_TRIALS} (default: [lifetime] trials)",
                             lambda x: 1 <= x <= MAX_TRIALS, kind="int", default=None)
    section: list[Any] = key("the [[section]] tables", kind="table", factory=list)
    scenario: list[Any] = key("the [[scenario]] tables", kind="table", factory=list)


@dataclass(frozen=True)
class SectionKeys:
    """The keys of a ``[[section]]`` besides the design's keys it overrides."""

    name: str = key("a name, unique among the sections", kind="text")
    chainage: float = key("the position along the breakwater in metres, never below the section before")
    width: float | None = key("the one width simulated, in metres (W' in proportion to the design's width)",
                              default=None)
    widths: tuple[float, ...] | None = key("a list of widths in metres, increasing (with target: at least "
                                           "two, the bracket of the width for the target)", kind="numbers",
                                           default=None)
    target: float | None = key("the tolerable ESD in metres, > 0: the width for it is searched",
                               lambda x: x > 0.0, default=None)
    tolerance: float = key("the width for the target to this many metres, > 0 (default 0.05)",
                           lambda x: x > 0.0, default=0.05)


@dataclass(frozen=True)
class ScenarioKeys:
    """The keys of a ``[[scenario]]``."""

    name: str = key("a name, unique among the scenarios", kind="text")
    sea_level_rise: Mapping[int, float] | None = key(
        "a table {year = metres} of the rise above today's mean sea level", kind="table", default=None)
    rate: float = key("a rate of sea-level rise in m/yr (with acceleration, instead of sea_level_rise)",
                      default=0.0)
    acceleration: float = key("an acceleration of sea-level rise in m/yr^2 (with rate)", default=0.0)
    wave_height_factor: Mapping[int, float] | None = key(
        "a table {year = factor > 0} on the storm peaks H0'", kind="table", default=None)
    storm_rate_factor: Mapping[int, float] | None = key(
        "a table {year = factor > 0} on the number of storms", kind="table", default=None)


#: The study's own keys at the top level, the keys of a ``[[section]]`` and of a ``[[scenario]]``.
STUDY_KEYS: dict[str, Key] = keys_of(StudyKeys)
SECTION_KEYS: dict[str, Key] = keys_of(SectionKeys)
SCENARIO_KEYS: dict[str, Key] = keys_of(ScenarioKeys)
#: The design's tables a section may override, and the ``[lifetime]`` keys the study fixes for all.
OVERRIDABLE = ("site", "caisson", "lifetime")
STUDY_WIDE = ("years", "trials", "seed", "record", "climate_replicates")
DESIGN_TABLES = ("site", "wave", "caisson", "lifetime")
#: The keys of each design table.
_KEYS = {**DESIGN_KEYS, "lifetime": LIFETIME_KEYS}


class Where(KeyReader):
    """The study file's reader: the lines of its keys (:class:`~regimemap.io.toml_keys.KeyReader`),
    also inside the n-th ``[[section]]`` or ``[[scenario]]``."""

    def __init__(self, text: str, source: str) -> None:
        super().__init__(source, text, {"section": SECTION_KEYS, "scenario": SCENARIO_KEYS})
        self.lines = text.splitlines()

    def item(self, array: str, index: int, key: str | None = None) -> int | None:
        """The line of ``key`` in the ``index``-th ``[[array]]`` (of its header when not found)."""
        header = re.compile(rf"^\s*\[\[\s*{array}\s*\]\]")
        starts = [n for n, line in enumerate(self.lines, start=1) if header.match(line)]
        if index >= len(starts):
            return None
        first = starts[index]
        end = len(self.lines)
        for n in range(first + 1, len(self.lines) + 1):
            if re.match(r"^\s*\[", self.lines[n - 1]) and not re.match(
                    rf"^\s*\[\s*{array}\s*\.", self.lines[n - 1]):
                end = n - 1
                break
        if key is not None:
            head = key.split(".")[0]
            pattern = re.compile(rf"^\s*(?:{re.escape(key)}|{re.escape(head)})\s*(?:=|\.)")
            sub = re.compile(rf"^\s*\[\s*{array}\s*\.\s*{re.escape(head)}\s*\]")
            for n in range(first + 1, end + 1):
                if pattern.match(self.lines[n - 1]) or sub.match(self.lines[n - 1]):
                    return n
        return first

    def fail_at(self, line: int | None, what: str) -> StudyFileError:
        """The error ``what`` at ``line``."""
        return StudyFileError(f"{self.at(line)}: {what}")


def load_toml(text: str, source: str) -> dict[str, Any]:
    """The TOML ``text`` of ``source`` (the study file or its base) as a dict; a syntax error names
    its line."""
    def error(msg: str, line: int | None, column: int | None) -> StudyFileError:
        where = source if line is None else f"{source}, line {line}"
        return StudyFileError(f"{where}: TOML syntax error: {msg}")

    return toml_data(text, error)


def toml_value(v: Any) -> str:
    """A parsed TOML value written back as TOML."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")  # pragma: no cover - tomllib's types only


@dataclass
class Origin:
    """Where a key of the merged design was written: a file and its line."""

    file: str
    line: int | None


def top_line(text: str, key: str) -> int | None:
    """The line of a top-level ``key`` of a TOML text (before any table header)."""
    for n, line in enumerate(text.splitlines(), start=1):
        if re.match(r"^\s*\[", line):
            return None
        if re.match(rf"^\s*{re.escape(key)}\s*=", line):
            return n
    return None


class Merged:
    """The design tables of one section as TOML text, with where each of its lines came from."""

    def __init__(self) -> None:
        self.tables: dict[str, dict[str, Any]] = {}
        self.origin: dict[tuple[str, str | None], Origin] = {}

    def set(self, table: str, key: str | None, value: Any, origin: Origin) -> None:
        if key is None:
            self.tables.setdefault(table, {})
            self.origin.setdefault((table, None), origin)
            return
        self.tables.setdefault(table, {})[key] = value
        self.origin[(table, key)] = origin
        self.origin.setdefault((table, None), origin)

    def copy(self) -> Merged:
        """A copy whose tables can be changed without changing this one's."""
        out = Merged()
        out.tables = {t: dict(v) for t, v in self.tables.items()}
        out.origin = dict(self.origin)
        return out

    def text(self) -> tuple[str, dict[int, Origin]]:
        lines: list[str] = []
        where: dict[int, Origin] = {}
        for table in (*DESIGN_TABLES, *(t for t in self.tables if t not in DESIGN_TABLES)):
            if table not in self.tables:
                continue
            body = self.tables[table]
            lines.append(f"[{table}]")
            where[len(lines)] = self.origin[(table, None)]
            subs = []
            for name, value in body.items():
                if isinstance(value, dict) and name in ("errors", "record"):
                    subs.append((name, value))
                    continue
                lines.append(f"{name} = {toml_value(value)}")
                where[len(lines)] = self.origin[(table, name)]
            for name, value in subs:
                lines.append(f"[{table}.{name}]")
                where[len(lines)] = self.origin[(table, name)]
                for k, x in value.items():
                    lines.append(f"{json.dumps(str(k)) if not re.match(r'^[A-Za-z0-9_-]+$', k) else k} = "
                                 f"{toml_value(x)}")
                    where[len(lines)] = self.origin.get((f"{table}.{name}", str(k)),
                                                        self.origin[(table, name)])
        return "\n".join(lines) + "\n", where


def section_key(where: Where, index: int, key: str) -> tuple[str, str]:
    """The design table of a section's flat key (``depth`` -> ``site``); refused when unknown."""
    tables = [t for t in OVERRIDABLE if key in _KEYS[t]]
    line = where.item("section", index, key)
    if not tables:
        known = {**SECTION_KEYS, **{k: 0 for t in ("site", "caisson") for k in DESIGN_KEYS[t]},
                 **{k: 0 for k in LIFETIME_KEYS}}
        raise where.fail_at(line, f"[[section]] {key}: unknown key{did_you_mean(key, known)}; accepted: "
                            f"{', '.join(SECTION_KEYS)}, or a key of [site], [caisson] or [lifetime]")
    if len(tables) > 1:
        both = " and ".join(f"[{t}]" for t in tables)
        raise where.fail_at(line, f"[[section]] {key}: a key of both {both}; "
                            f"accepted: write {tables[0]}.{key} or {tables[1]}.{key}")
    return tables[0], key


def check_override(where: Where, index: int, table: str, key: str, written: str | None = None) -> None:
    keys = _KEYS[table]
    line = where.item("section", index, written or f"{table}.{key}")
    if key not in keys:
        raise where.fail_at(line, f"[[section]] {table}.{key}: unknown key{did_you_mean(key, keys)}; "
                            f"accepted keys of [{table}]: {', '.join(keys)}")
    if table == "lifetime" and key in STUDY_WIDE:
        place = "seed and trials at the top of the study" if key in ("seed", "trials") else "in [lifetime]"
        raise where.fail_at(line, f"[[section]] lifetime.{key}: the same for every section; "
                            f"accepted: {place}")


def section_widths(where: Where, index: int, sec: Mapping[str, Any]
                   ) -> tuple[tuple[float, ...] | None, float | None, float]:
    """A section's ``width`` or ``widths`` (None: neither), ``target`` and ``tolerance``, checked."""

    def line(key: str) -> int | None:
        return where.item("section", index, key)

    if "width" in sec and "widths" in sec:
        raise where.fail_at(line("widths"), "[[section]] widths together with width; accepted: one of them")
    widths: tuple[float, ...] | None = None
    spec = DESIGN_KEYS["caisson"]["width"]  # the design file's range of a width, and its words
    if "width" in sec:
        w = number_of(sec["width"])
        if w is None or not math.isfinite(w):
            raise where.fail_at(line("width"), f"[[section]] width = {sec['width']!r}: accepted: "
                                f"{SECTION_KEYS['width'].accepted}, {spec.accepted}")
        if not spec.check(w):
            raise where.fail_at(line("width"), f"[[section]] width = {sec['width']!r}: "
                                f"{spec.reason(w)}; accepted: {spec.accepted}")
        widths = (w,)
    if "widths" in sec:
        v = sec["widths"]
        ws = [number_of(x) for x in v] if isinstance(v, list) else [None]
        if not ws or any(x is None or not math.isfinite(x) for x in ws):
            raise where.fail_at(line("widths"), f"[[section]] widths = {v!r}: accepted: "
                                f"{SECTION_KEYS['widths'].accepted}, each {spec.accepted}")
        bad = [x for x in ws if x is not None and not spec.check(x)]
        if bad:
            raise where.fail_at(line("widths"), f"[[section]] widths = {v!r}: {bad[0]:g} m is "
                                f"{spec.reason(bad[0])}; accepted: each {spec.accepted}")
        got = [float(x) for x in ws if x is not None]
        if any(b <= a for a, b in zip(got, got[1:])):
            raise where.fail_at(line("widths"), f"[[section]] widths = {v!r}: not increasing; accepted: "
                                f"{SECTION_KEYS['widths'].accepted}")
        widths = tuple(got)
    target = None
    if "target" in sec:
        target = number_of(sec["target"])
        if target is None or not (math.isfinite(target) and SECTION_KEYS["target"].check(target)):
            raise where.fail_at(line("target"), f"[[section]] target = {sec['target']!r}: accepted: "
                                f"{SECTION_KEYS['target'].accepted}")
        if widths is None or len(widths) < 2:
            raise where.fail_at(line("target"), "[[section]] target needs widths = [..] (at least two, the "
                                "bracket of the width for the target)")
    tolerance: float = default_of(SectionKeys, "tolerance")
    if "tolerance" in sec:
        tolerance = _tolerance(where, line("tolerance"), sec["tolerance"], target, widths)
    return widths, target, tolerance


def _tolerance(where: Where, at: int | None, value: Any, target: float | None,
               widths: tuple[float, ...] | None) -> float:
    """A section's ``tolerance``: > 0, with a target, and below the bracket of its widths."""
    t = number_of(value)
    if target is None or t is None or not (math.isfinite(t) and SECTION_KEYS["tolerance"].check(t)):
        raise where.fail_at(at, f"[[section]] tolerance = {value!r}: accepted: "
                            f"{SECTION_KEYS['tolerance'].accepted}, with target")
    assert widths is not None  # a target has its bracket
    span = widths[-1] - widths[0]
    if t >= span:
        raise where.fail_at(at, f"[[section]] tolerance = {value!r}: not below the bracket of widths "
                            f"({widths[0]:g} to {widths[-1]:g} m, {span:g} m wide): the search would stop "
                            "at its first step")
    return t


def year_table(where: Where, index: int, key: str, value: Any, years: int, factor: bool
                ) -> tuple[float, ...]:
    """A table ``{year = value}`` as one value per service year 1..years, linear between the years
    given, from today's value (0 m, or a factor 1) at year 0, constant after the last."""
    line = where.item("scenario", index, key)
    if not isinstance(value, dict) or not value:
        raise where.fail_at(line, f"[[scenario]] {key} = {value!r}: accepted: "
                            f"{SCENARIO_KEYS[key].accepted}")
    points: dict[int, float] = {}
    for name, x in value.items():
        if isinstance(x, dict) or not re.fullmatch(r"\d+", str(name)):
            raise where.fail_at(line, f"[[scenario]] {key}: the year {name!r} is not a whole number; "
                                f"accepted: service years 1 to {years}")
        year = int(name)
        if not 1 <= year <= years:
            raise where.fail_at(line, f"[[scenario]] {key}: the year {year} is outside the design life; "
                                f"accepted: service years 1 to {years}")
        v = number_of(x)
        if v is None or not math.isfinite(v) or (factor and not v > 0.0):
            need = "a factor > 0" if factor else "a finite rise in metres"
            raise where.fail_at(line, f"[[scenario]] {key}: year {year} = {x!r}; accepted: {need}")
        points[year] = v
    xs = [0, *sorted(points)]
    ys = [1.0 if factor else 0.0, *(points[y] for y in sorted(points))]
    out = []
    for y in range(1, years + 1):
        if y >= xs[-1]:
            out.append(ys[-1])
            continue
        k = next(i for i in range(1, len(xs)) if xs[i] >= y)
        t = (y - xs[k - 1]) / (xs[k] - xs[k - 1])
        out.append(ys[k - 1] + t * (ys[k] - ys[k - 1]))
    return tuple(out)


def scenario_values(where: Where, index: int, sc: Mapping[str, Any], years: int
                    ) -> tuple[str, tuple[float, ...], tuple[float, ...], tuple[float, ...], bool]:
    """A ``[[scenario]]``: its name; per service year, the rise [m] and the two factors; and whether
    it gives none of them (today's climate)."""
    for given in sc:
        if given not in SCENARIO_KEYS:
            raise where.fail_at(where.item("scenario", index, given), f"[[scenario]] {given}: unknown key"
                                f"{did_you_mean(given, SCENARIO_KEYS)}; accepted: {', '.join(SCENARIO_KEYS)}")
    name = sc["name"]
    if "sea_level_rise" in sc and ("rate" in sc or "acceleration" in sc):
        raise where.fail_at(where.item("scenario", index, "rate" if "rate" in sc else "acceleration"),
                            "[[scenario]] rate/acceleration together with sea_level_rise; accepted: one of "
                            "them")
    if "sea_level_rise" in sc:
        sea = year_table(where, index, "sea_level_rise", sc["sea_level_rise"], years, False)
    else:
        coef = []
        for term in ("rate", "acceleration"):
            v = number_of(sc.get(term, 0.0))
            if v is None or not math.isfinite(v):
                raise where.fail_at(where.item("scenario", index, term),
                                    f"[[scenario]] {term} = {sc[term]!r}: accepted: "
                                    f"{SCENARIO_KEYS[term].accepted}, a finite number")
            coef.append(v)
        sea = tuple(coef[0] * y + 0.5 * coef[1] * y * y for y in range(1, years + 1))
    ones = (1.0,) * years
    height = (year_table(where, index, "wave_height_factor", sc["wave_height_factor"], years, True)
              if "wave_height_factor" in sc else ones)
    rate = (year_table(where, index, "storm_rate_factor", sc["storm_rate_factor"], years, True)
            if "storm_rate_factor" in sc else ones)
    today = not any(k in sc for k in SCENARIO_KEYS if k != "name")
    return name, sea, height, rate, today


def check_names(where: Where, array: str, items: list[Any]) -> list[str]:
    seen: dict[str, int] = {}
    for i, item in enumerate(items):
        if not isinstance(item, dict):
            raise where.fail_at(None, f"{array} must be [[{array}]] tables")
        name = item.get("name")
        line = where.item(array, i, "name")
        if not isinstance(name, str) or not name.strip():
            raise where.fail_at(line, f"[[{array}]] {i + 1} has no name; accepted: name = \"...\", unique")
        if name in seen:
            raise where.fail_at(line, f"[[{array}]] name = {name!r}: a duplicate of the {array} at line "
                                f"{where.item(array, seen[name], 'name')}; accepted: unique names")
        seen[name] = i
    return list(seen)


def design_of(merged: Merged, study_source: str, section: str, index: int, where: Where) -> Design:
    """Read the merged tables with the design reader; its messages name the key's own file and line."""
    from ..caisson.file import parse_design

    text, origin = merged.text()
    try:
        return parse_design(text, source=study_source)
    except DesignFileError as exc:
        msg = str(exc)
        m = re.match(rf"^{re.escape(study_source)}, line (\d+): ", msg)
        if m:
            o = origin.get(int(m.group(1)))
            place = study_source if o is None else (o.file if o.line is None else f"{o.file}, line {o.line}")
            msg = f"{place}: section {section!r}: {msg[m.end():]}"
        elif msg.startswith(f"{study_source}: "):
            head = where.at(where.item("section", index))
            msg = f"{head}: section {section!r}: {msg[len(study_source) + 2:]}"
        raise StudyFileError(msg) from None
