"""The study file of ``regimemap study``: a breakwater's sections and the climate scenarios they meet.

A study file (TOML) holds the tables of a design file (``[site]``, ``[wave]``,
``[caisson]``, ``[lifetime]``) inline, or ``base = "design.toml"`` (relative to
the study file; inline tables then change the base's keys), and::

    seed, trials        the root seed (or [lifetime] seed) and lifetimes per task
    [[section]]         name, chainage [m]; width, widths or target (+ widths, the
                        chart's bracket, and tolerance); overrides of the design's
                        [site], [caisson] and [lifetime] keys (depth = 8.0, or
                        caisson.impulsive = false for a key two tables share)
    [[scenario]]        name; sea_level_rise = {year = metres} (linear between the
                        years, from 0 m today, constant after the last) or rate [m/yr]
                        and acceleration [m/yr^2] (rise = rate y + acceleration y^2 / 2);
                        wave_height_factor and storm_rate_factor = {year = factor}
                        (from 1 today); none of them: today's climate

Each section's design is its overrides merged into the base's tables and read by
:func:`regimemap.io.design.parse_design`, so every check of a design file applies;
its messages name the study file (or the base) and the line where the key was
written.  Every refusal is a :class:`StudyFileError` naming the file, the line and
the key.  A study's hash (:attr:`Study.study_hash`) is the sha256 of its canonical
content: the parsed tables, the base file's text and the wave record's bytes.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

from .design_errors import DesignFileError, did_you_mean
from .design_keys import DESIGN_KEYS
from .design_lifetime_keys import LIFETIME_KEYS, MAX_TRIALS
from .inputs import read_design_text
from .toml_lines import key_line

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel, YearTrend

    from .design import Design

__all__ = ["SECTION_KEYS", "SCENARIO_KEYS", "STUDY_KEYS", "ScenarioSpec", "SectionSpec", "Study",
           "StudyFileError", "parse_study", "read_study"]


class StudyFileError(DesignFileError):
    """A study file that cannot be read or accepted (file, line and key named)."""


#: The study's own keys at the top level (besides the design file's tables).
STUDY_KEYS = {"base": 'a design file, relative to the study file (default: the tables inline)',
              "seed": "a whole number >= 0, the root seed of every task (default: [lifetime] seed)",
              "trials": f"lifetimes per task, 1 to {MAX_TRIALS} (default: [lifetime] trials)",
              "section": "the [[section]] tables", "scenario": "the [[scenario]] tables"}
#: The keys of a ``[[section]]`` besides the design's keys it overrides.
SECTION_KEYS = {"name": "a name, unique among the sections",
                "chainage": "the position along the breakwater in metres, never below the section before",
                "width": "the one width simulated, in metres (W' in proportion to the design's width)",
                "widths": "a list of widths in metres, increasing (with target: at least two, the "
                          "bracket of the width for the target)",
                "target": "the tolerable ESD in metres, > 0: the width for it is searched",
                "tolerance": "the width for the target to this many metres, > 0 (default 0.05)"}
#: The keys of a ``[[scenario]]``.
SCENARIO_KEYS = {"name": "a name, unique among the scenarios",
                 "sea_level_rise": "a table {year = metres} of the rise above today's mean sea level",
                 "rate": "a rate of sea-level rise in m/yr (with acceleration, instead of sea_level_rise)",
                 "acceleration": "an acceleration of sea-level rise in m/yr^2 (with rate)",
                 "wave_height_factor": "a table {year = factor > 0} on the storm peaks H0'",
                 "storm_rate_factor": "a table {year = factor > 0} on the number of storms"}
#: The design's tables a section may override, and the ``[lifetime]`` keys the study fixes for all.
OVERRIDABLE = ("site", "caisson", "lifetime")
STUDY_WIDE = ("years", "trials", "seed", "record", "climate_replicates")
_DESIGN_TABLES = ("site", "wave", "caisson", "lifetime")


@dataclass(frozen=True)
class SectionSpec:
    """One ``[[section]]``: its name, chainage, design and widths or target.

    Attributes
    ----------
    name : str
    chainage : float
        Position along the breakwater [m].
    design : Design
        The base design with the section's overrides, checked.
    widths : tuple of float
        The widths simulated [m] (with ``target``: the chart's bracket).
    target : float or None
        The tolerable ESD [m]; None: fixed widths.
    tolerance : float
        The bisection's tolerance of the width for the target [m].
    """

    name: str
    chainage: float
    design: Design
    widths: tuple[float, ...]
    target: float | None = None
    tolerance: float = 0.05

    def caisson(self) -> Caisson:
        """The section's caisson at its site (:meth:`Design.lifetime_caisson`)."""
        return self.design.lifetime_caisson()


@dataclass(frozen=True)
class ScenarioSpec:
    """One ``[[scenario]]``: its climate over the service years 1..L.

    Attributes
    ----------
    name : str
    sea_level : tuple of float
        Rise above today's mean sea level in each service year [m].
    wave_height, storm_rate : tuple of float
        Factors on the storm peaks and on the number of storms in each year.
    """

    name: str
    sea_level: tuple[float, ...]
    wave_height: tuple[float, ...]
    storm_rate: tuple[float, ...]

    @property
    def stationary(self) -> bool:
        """Today's climate: no rise and every factor 1 (the scenario gave none)."""
        return (all(x == 0.0 for x in self.sea_level) and all(x == 1.0 for x in self.wave_height)
                and all(x == 1.0 for x in self.storm_rate))

    def trend(self) -> YearTrend:
        """The scenario as a :class:`regimemap.lifetime.YearTrend`."""
        from regimemap.lifetime import YearTrend

        return YearTrend(self.sea_level, self.wave_height, self.storm_rate)


@dataclass(frozen=True)
class Study:
    """A parsed and checked study file.

    Attributes
    ----------
    source : str
        The study file.
    seed, trials, years : int
        Root seed, lifetimes per task, design life.
    sections : tuple of SectionSpec
        In file order (chainage never decreasing).
    scenarios : tuple of ScenarioSpec
        In file order.
    study_hash : str
        sha256 of the study's canonical content.
    """

    source: str
    seed: int
    trials: int
    years: int
    sections: tuple[SectionSpec, ...]
    scenarios: tuple[ScenarioSpec, ...]
    study_hash: str

    @property
    def replicates(self) -> int:
        """Bootstrap climates of the record (0: the climate alone)."""
        spec = self.sections[0].design.lifetime_spec()
        return spec.climate_replicates if spec.record is not None else 0

    def model(self, section: SectionSpec, scenario: ScenarioSpec) -> LifetimeModel:
        """The section's lifetime model under the scenario (today's climate: no trend)."""
        model = section.design.lifetime_model(self.years)
        return model if scenario.stationary else model.with_(trend=scenario.trend())


class _Where:
    """Lines of the study file's keys, also inside the n-th ``[[section]]`` or ``[[scenario]]``."""

    def __init__(self, text: str, source: str) -> None:
        self.text = text
        self.source = source
        self.lines = text.splitlines()

    def at(self, line: int | None) -> str:
        return self.source if line is None else f"{self.source}, line {line}"

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

    def fail(self, line: int | None, what: str) -> StudyFileError:
        return StudyFileError(f"{self.at(line)}: {what}")


def _number(v: Any) -> float | None:
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _load(text: str, source: str) -> dict[str, Any]:
    try:
        data: dict[str, Any] = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\s*\(at line (\d+), column (\d+)\)", msg)
        where = source
        if m:
            where = f"{source}, line {m.group(1)}"
            msg = msg[:m.start()] + msg[m.end():]
        raise StudyFileError(f"{where}: TOML syntax error: {msg}") from None
    return data


def _toml_value(v: Any) -> str:
    """A parsed TOML value written back as TOML."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")  # pragma: no cover - tomllib's types only


@dataclass
class _Origin:
    """Where a key of the merged design was written: a file and its line."""

    file: str
    line: int | None


class _Merged:
    """The design tables of one section as TOML text, with where each of its lines came from."""

    def __init__(self) -> None:
        self.tables: dict[str, dict[str, Any]] = {}
        self.origin: dict[tuple[str, str | None], _Origin] = {}

    def set(self, table: str, key: str | None, value: Any, origin: _Origin) -> None:
        if key is None:
            self.tables.setdefault(table, {})
            self.origin.setdefault((table, None), origin)
            return
        self.tables.setdefault(table, {})[key] = value
        self.origin[(table, key)] = origin
        self.origin.setdefault((table, None), origin)

    def text(self) -> tuple[str, dict[int, _Origin]]:
        lines: list[str] = []
        where: dict[int, _Origin] = {}
        for table in _DESIGN_TABLES:
            if table not in self.tables:
                continue
            body = self.tables[table]
            lines.append(f"[{table}]")
            where[len(lines)] = self.origin[(table, None)]
            subs = []
            for key, value in body.items():
                if isinstance(value, dict) and key in ("errors", "record"):
                    subs.append((key, value))
                    continue
                lines.append(f"{key} = {_toml_value(value)}")
                where[len(lines)] = self.origin[(table, key)]
            for key, value in subs:
                lines.append(f"[{table}.{key}]")
                where[len(lines)] = self.origin[(table, key)]
                for k, x in value.items():
                    lines.append(f"{json.dumps(str(k)) if not re.match(r'^[A-Za-z0-9_-]+$', k) else k} = "
                                 f"{_toml_value(x)}")
                    where[len(lines)] = self.origin[(table, key)]
        return "\n".join(lines) + "\n", where


def _section_key(where: _Where, index: int, key: str) -> tuple[str, str]:
    """The design table of a section's flat key (``depth`` -> ``site``); refused when unknown."""
    tables = [t for t in OVERRIDABLE if key in (LIFETIME_KEYS if t == "lifetime" else DESIGN_KEYS[t])]
    line = where.item("section", index, key)
    if not tables:
        known = {**SECTION_KEYS, **{k: 0 for t in ("site", "caisson") for k in DESIGN_KEYS[t]},
                 **{k: 0 for k in LIFETIME_KEYS}}
        raise where.fail(line, f"[[section]] {key}: unknown key{did_you_mean(key, known)}; accepted: "
                         f"{', '.join(SECTION_KEYS)}, or a key of [site], [caisson] or [lifetime]")
    if len(tables) > 1:
        raise where.fail(line, f"[[section]] {key}: a key of both {' and '.join(f'[{t}]' for t in tables)}; "
                         f"accepted: write {tables[0]}.{key} or {tables[1]}.{key}")
    return tables[0], key


def _check_override(where: _Where, index: int, table: str, key: str) -> None:
    keys = LIFETIME_KEYS if table == "lifetime" else DESIGN_KEYS[table]
    line = where.item("section", index, f"{table}.{key}")
    if key not in keys:
        raise where.fail(line, f"[[section]] {table}.{key}: unknown key{did_you_mean(key, keys)}; accepted "
                         f"keys of [{table}]: {', '.join(keys)}")
    if table == "lifetime" and key in STUDY_WIDE:
        raise where.fail(line, f"[[section]] lifetime.{key}: the same for every section; accepted: "
                         f"{'seed and trials at the top of the study' if key in ('seed', 'trials') else 'in [lifetime]'}")


def _widths(where: _Where, index: int, sec: Mapping[str, Any]) -> tuple[tuple[float, ...] | None, float | None,
                                                                     float]:
    line = lambda key: where.item("section", index, key)  # noqa: E731
    if "width" in sec and "widths" in sec:
        raise where.fail(line("widths"), "[[section]] widths together with width; accepted: one of them")
    widths: tuple[float, ...] | None = None
    if "width" in sec:
        w = _number(sec["width"])
        if w is None or not (math.isfinite(w) and w > 0.0):
            raise where.fail(line("width"), f"[[section]] width = {sec['width']!r}: accepted: "
                             f"{SECTION_KEYS['width']}, > 0")
        widths = (w,)
    if "widths" in sec:
        v = sec["widths"]
        ws = [_number(x) for x in v] if isinstance(v, list) else [None]
        if not ws or any(x is None or not (math.isfinite(x) and x > 0.0) for x in ws):
            raise where.fail(line("widths"), f"[[section]] widths = {v!r}: accepted: {SECTION_KEYS['widths']}")
        got = [float(x) for x in ws if x is not None]
        if any(b <= a for a, b in zip(got, got[1:])):
            raise where.fail(line("widths"), f"[[section]] widths = {v!r}: not increasing; accepted: "
                             f"{SECTION_KEYS['widths']}")
        widths = tuple(got)
    target = None
    if "target" in sec:
        target = _number(sec["target"])
        if target is None or not (math.isfinite(target) and target > 0.0):
            raise where.fail(line("target"), f"[[section]] target = {sec['target']!r}: accepted: "
                             f"{SECTION_KEYS['target']}")
        if widths is None or len(widths) < 2:
            raise where.fail(line("target"), "[[section]] target needs widths = [..] (at least two, the "
                             "bracket of the width for the target)")
    tolerance = 0.05
    if "tolerance" in sec:
        t = _number(sec["tolerance"])
        if target is None or t is None or not (math.isfinite(t) and t > 0.0):
            raise where.fail(line("tolerance"), f"[[section]] tolerance = {sec['tolerance']!r}: accepted: "
                             f"{SECTION_KEYS['tolerance']}, with target")
        tolerance = t
    return widths, target, tolerance


def _year_table(where: _Where, index: int, key: str, value: Any, years: int, factor: bool
                ) -> tuple[float, ...]:
    """A table ``{year = value}`` as one value per service year 1..years, linear between the years
    given, from today's value (0 m, or a factor 1) at year 0, constant after the last."""
    line = where.item("scenario", index, key)
    if not isinstance(value, dict) or not value:
        raise where.fail(line, f"[[scenario]] {key} = {value!r}: accepted: {SCENARIO_KEYS[key]}")
    points: dict[int, float] = {}
    for name, x in value.items():
        if isinstance(x, dict) or not re.fullmatch(r"\d+", str(name)):
            raise where.fail(line, f"[[scenario]] {key}: the year {name!r} is not a whole number; "
                             f"accepted: service years 1 to {years}")
        year = int(name)
        if not 1 <= year <= years:
            raise where.fail(line, f"[[scenario]] {key}: the year {year} is outside the design life; "
                             f"accepted: service years 1 to {years}")
        v = _number(x)
        if v is None or not math.isfinite(v) or (factor and not v > 0.0):
            need = "a factor > 0" if factor else "a finite rise in metres"
            raise where.fail(line, f"[[scenario]] {key}: year {year} = {x!r}; accepted: {need}")
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


def _scenario(where: _Where, index: int, sc: Mapping[str, Any], years: int) -> ScenarioSpec:
    for key in sc:
        if key not in SCENARIO_KEYS:
            raise where.fail(where.item("scenario", index, key), f"[[scenario]] {key}: unknown key"
                             f"{did_you_mean(key, SCENARIO_KEYS)}; accepted: {', '.join(SCENARIO_KEYS)}")
    name = sc["name"]
    if "sea_level_rise" in sc and ("rate" in sc or "acceleration" in sc):
        raise where.fail(where.item("scenario", index, "rate" if "rate" in sc else "acceleration"),
                         "[[scenario]] rate/acceleration together with sea_level_rise; accepted: one of them")
    if "sea_level_rise" in sc:
        sea = _year_table(where, index, "sea_level_rise", sc["sea_level_rise"], years, False)
    else:
        coef = []
        for key in ("rate", "acceleration"):
            v = _number(sc.get(key, 0.0))
            if v is None or not math.isfinite(v):
                raise where.fail(where.item("scenario", index, key), f"[[scenario]] {key} = {sc[key]!r}: "
                                 f"accepted: {SCENARIO_KEYS[key]}, a finite number")
            coef.append(v)
        sea = tuple(coef[0] * y + 0.5 * coef[1] * y * y for y in range(1, years + 1))
    ones = (1.0,) * years
    height = (_year_table(where, index, "wave_height_factor", sc["wave_height_factor"], years, True)
              if "wave_height_factor" in sc else ones)
    rate = (_year_table(where, index, "storm_rate_factor", sc["storm_rate_factor"], years, True)
            if "storm_rate_factor" in sc else ones)
    return ScenarioSpec(name=name, sea_level=sea, wave_height=height, storm_rate=rate)


def _names(where: _Where, array: str, items: list[Any]) -> list[str]:
    seen: dict[str, int] = {}
    for i, item in enumerate(items):
        if not isinstance(item, dict):
            raise where.fail(None, f"{array} must be [[{array}]] tables")
        name = item.get("name")
        line = where.item(array, i, "name")
        if not isinstance(name, str) or not name.strip():
            raise where.fail(line, f"[[{array}]] {i + 1} has no name; accepted: name = \"...\", unique")
        if name in seen:
            raise where.fail(line, f"[[{array}]] name = {name!r}: a duplicate of the {array} at line "
                             f"{where.item(array, seen[name], 'name')}; accepted: unique names")
        seen[name] = i
    return list(seen)


def _design_of(merged: _Merged, study_source: str, section: str, index: int, where: _Where) -> Design:
    """Read the merged tables with the design reader; its messages name the key's own file and line."""
    from .design import parse_design

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
            msg = f"{where.at(where.item('section', index))}: section {section!r}: {msg[len(study_source) + 2:]}"
        raise StudyFileError(msg) from None


def _fingerprint(data: Mapping[str, Any], base_text: str | None, record_path: str | None) -> str:
    h = hashlib.sha256()
    h.update(json.dumps(data, sort_keys=True, default=str).encode())
    h.update(b"\0base\0" + (base_text or "").encode())
    if record_path is not None:
        try:
            h.update(b"\0record\0" + Path(record_path).read_bytes())
        except OSError:
            h.update(b"\0record?\0" + record_path.encode())
    return h.hexdigest()


def parse_study(text: str, source: str = "<study>") -> Study:
    """Parse and check the text of a study file.

    Parameters
    ----------
    text : str
        TOML text.
    source : str, optional
        The study file's name (its folder resolves ``base`` and a record's path).

    Returns
    -------
    Study

    Raises
    ------
    StudyFileError
        Naming the file, the line and the key: a TOML error, an unknown key,
        duplicate names, a chainage that goes back, a scenario year outside
        the design life, a factor <= 0, a section's design refused by the
        design file's checks.
    """
    where = _Where(text, source)
    data = _load(text, source)
    folder = Path(source).parent
    for key in data:
        if key not in STUDY_KEYS and key not in _DESIGN_TABLES:
            raise where.fail(key_line(text, key) if isinstance(data[key], dict) else _top_line(text, key),
                             f"unknown key {key}{did_you_mean(key, {**STUDY_KEYS, **dict.fromkeys(_DESIGN_TABLES)})}; "
                             f"accepted: {', '.join(STUDY_KEYS)} and the tables {', '.join(_DESIGN_TABLES)}")
    merged_base = _Merged()
    base_text = None
    if "base" in data:
        if not isinstance(data["base"], str) or not data["base"].strip():
            raise where.fail(_top_line(text, "base"), f"base = {data['base']!r}: accepted: {STUDY_KEYS['base']}")
        base_path = folder / data["base"]
        try:
            base_text = read_design_text(base_path)
        except (OSError, UnicodeDecodeError, ValueError) as exc:
            raise where.fail(_top_line(text, "base"), f"base = {data['base']!r}: cannot read the design file: "
                             f"{exc}") from None
        base_data = _load(base_text, str(base_path))
        for table in _DESIGN_TABLES:
            if isinstance(base_data.get(table), dict):
                merged_base.set(table, None, None, _Origin(str(base_path), key_line(base_text, table)))
                for key, value in base_data[table].items():
                    if table == "lifetime" and key == "record" and isinstance(value, dict) and "path" in value:
                        value = {**value, "path": str(base_path.parent / str(value["path"]))}
                    merged_base.set(table, key, value,
                                    _Origin(str(base_path), key_line(base_text, table, key)))
        for key in base_data:
            if key not in _DESIGN_TABLES:
                merged_base.set(key, None, None, _Origin(str(base_path), key_line(base_text, key)))
                merged_base.tables[key] = base_data[key] if isinstance(base_data[key], dict) else {}
    for table in _DESIGN_TABLES:
        if table in data:
            if not isinstance(data[table], dict):
                raise where.fail(_top_line(text, table), f"{table} must be a table [{table}]")
            merged_base.set(table, None, None, _Origin(source, key_line(text, table)))
            for key, value in data[table].items():
                merged_base.set(table, key, value, _Origin(source, key_line(text, table, key)))
    if "lifetime" not in merged_base.tables:
        raise where.fail(None, "no [lifetime] table (the wave climate and the options of the lifetime "
                         "simulation), inline or in the base design file")
    life = merged_base.tables["lifetime"]

    sections_raw = data.get("section", [])
    scenarios_raw = data.get("scenario", [])
    if not isinstance(sections_raw, list) or not sections_raw:
        raise where.fail(None, "no [[section]]; accepted: at least one [[section]] with name and chainage")
    if not isinstance(scenarios_raw, list) or not scenarios_raw:
        raise where.fail(None, "no [[scenario]]; accepted: at least one [[scenario]] (name = \"today\" "
                         "alone is today's climate)")
    _names(where, "section", sections_raw)
    _names(where, "scenario", scenarios_raw)

    seed = data.get("seed", life.get("seed"))
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise where.fail(_top_line(text, "seed"), f"seed = {seed!r}: accepted: {STUDY_KEYS['seed']}; a "
                         "study needs one (its tasks are resumed on the same random numbers)")
    trials = data.get("trials", life.get("trials", 5000))
    if isinstance(trials, bool) or not isinstance(trials, int) or not 1 <= trials <= MAX_TRIALS:
        raise where.fail(_top_line(text, "trials"), f"trials = {trials!r}: accepted: {STUDY_KEYS['trials']}")
    years = life.get("years", 50)

    sections = []
    last: tuple[str, float] | None = None
    for i, sec in enumerate(sections_raw):
        name = sec["name"]
        chain = _number(sec.get("chainage"))
        if chain is None or not math.isfinite(chain):
            raise where.fail(where.item("section", i, "chainage"), f"[[section]] {name!r}: chainage = "
                             f"{sec.get('chainage')!r}; accepted: {SECTION_KEYS['chainage']}")
        if last is not None and chain < last[1]:
            raise where.fail(where.item("section", i, "chainage"), f"[[section]] {name!r}: chainage = "
                             f"{sec['chainage']!r} goes back (section {last[0]!r} is at {last[1]:g} m); "
                             f"accepted: {SECTION_KEYS['chainage']}")
        last = (name, chain)
        merged = _Merged()
        merged.tables = {t: dict(v) for t, v in merged_base.tables.items()}
        merged.origin = dict(merged_base.origin)
        for key, value in sec.items():
            if key in SECTION_KEYS:
                continue
            if key in OVERRIDABLE and isinstance(value, dict):
                for sub, x in value.items():
                    _check_override(where, i, key, sub)
                    merged.set(key, sub, x, _Origin(source, where.item("section", i, f"{key}.{sub}")))
                continue
            table, k = _section_key(where, i, key)
            _check_override(where, i, table, k)
            merged.set(table, k, value, _Origin(source, where.item("section", i, key)))
        widths, target, tolerance = _widths(where, i, sec)
        design = _design_of(merged, source, name, i, where)
        sections.append(SectionSpec(name=name, chainage=chain, design=design,
                                    widths=widths if widths is not None else (design.caisson.width,),
                                    target=target, tolerance=tolerance))
    scenarios = tuple(_scenario(where, j, sc, years) for j, sc in enumerate(scenarios_raw))
    record = sections[0].design.lifetime_spec().record
    digest = _fingerprint(data, base_text, None if record is None else record.path)
    return Study(source=source, seed=int(seed), trials=int(trials), years=int(years), sections=tuple(sections),
                 scenarios=scenarios, study_hash=digest)


def _top_line(text: str, key: str) -> int | None:
    """The line of a top-level ``key`` of a TOML text (before any table header)."""
    for n, line in enumerate(text.splitlines(), start=1):
        if re.match(r"^\s*\[", line):
            return None
        if re.match(rf"^\s*{re.escape(key)}\s*=", line):
            return n
    return None


def read_study(path: str | Path) -> Study:
    """Read and check a study file (:func:`parse_study`).

    Raises
    ------
    StudyFileError
        See :func:`parse_study`; also when the file cannot be read.
    """
    p = Path(path)
    try:
        text = read_design_text(p)
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise StudyFileError(f"{p}: cannot read the study file: {exc}") from None
    return parse_study(text, source=str(p))
