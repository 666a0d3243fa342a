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
:func:`regimemap.caisson.file.parse_design`, so every check of a design file applies;
its messages name the study file (or the base) and the line where the key was
written.  Every refusal is a :class:`StudyFileError` naming the file, the line and
the key.  A study's hash (:attr:`Study.study_hash`) is the sha256 of its canonical
content: the parsed tables, the base file's text and the wave record's bytes.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..io.inputs import InputFileError, read_design_text
from ..io.toml_errors import did_you_mean
from ..io.toml_keys import number_of
from ..io.toml_lines import key_line
from ..records.notices import Notice
from .file_limits import check_scenario_limits, check_wave_heights, falling_sea_level
from .file_sections import (
    DESIGN_TABLES,
    OVERRIDABLE,
    SCENARIO_KEYS,
    SECTION_KEYS,
    STUDY_KEYS,
    Merged,
    Origin,
    StudyFileError,
    Where,
    check_names,
    check_override,
    design_of,
    load_toml,
    scenario_values,
    section_key,
    section_widths,
    top_line,
)

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel, YearTrend

    from ..caisson.file import Design

__all__ = ["SECTION_KEYS", "SCENARIO_KEYS", "STUDY_KEYS", "ScenarioSpec", "SectionSpec", "Study",
           "StudyFileError", "parse_study", "read_study"]


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
    today : bool
        The scenario gives none of them: today's climate, run without a trend.
    """

    name: str
    sea_level: tuple[float, ...]
    wave_height: tuple[float, ...]
    storm_rate: tuple[float, ...]
    today: bool = False

    @property
    def stationary(self) -> bool:
        """No rise and every factor 1 in every year (today's climate, given or written out)."""
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
    notices : tuple of Notice
        The warnings of the file (a falling sea level, ``falling-sea-level``).
    """

    source: str
    seed: int
    trials: int
    years: int
    sections: tuple[SectionSpec, ...]
    scenarios: tuple[ScenarioSpec, ...]
    study_hash: str
    notices: tuple[Notice, ...] = ()

    @property
    def replicates(self) -> int:
        """Bootstrap climates of the record (0: the climate alone)."""
        spec = self.sections[0].design.lifetime_spec()
        return spec.climate_replicates if spec.record is not None else 0

    def model(self, section: SectionSpec, scenario: ScenarioSpec) -> LifetimeModel:
        """The section's lifetime model under the scenario (a scenario that gives no change: no trend)."""
        model = section.design.lifetime_model(self.years)
        return model if scenario.today else model.with_(trend=scenario.trend())


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
        design file's checks, a width outside the design file's range, a
        scenario whose sea level of a service year takes a section out of the
        design file's limits (:func:`regimemap.study.file_limits.check_scenario_limits`).
    """
    where = Where(text, source)
    data = load_toml(text, source)
    known = {**STUDY_KEYS, **dict.fromkeys(DESIGN_TABLES)}
    for key in data:
        if key not in known:
            raise where.fail_at(key_line(text, key) if isinstance(data[key], dict) else top_line(text, key),
                                f"unknown key {key}{did_you_mean(key, known)}; accepted: "
                                f"{', '.join(STUDY_KEYS)} and the tables {', '.join(DESIGN_TABLES)}")
    base, base_text = _base_tables(data, text, source, where)
    life = base.tables["lifetime"]
    sections_raw, scenarios_raw = data.get("section", []), data.get("scenario", [])
    if not isinstance(sections_raw, list) or not sections_raw:
        raise where.fail_at(None, "no [[section]]; accepted: at least one [[section]] with name and chainage")
    if not isinstance(scenarios_raw, list) or not scenarios_raw:
        raise where.fail_at(None, "no [[scenario]]; accepted: at least one [[scenario]] (name = \"today\" "
                            "alone is today's climate)")
    check_names(where, "section", sections_raw)
    check_names(where, "scenario", scenarios_raw)
    seed = data.get("seed", life.get("seed"))
    if isinstance(seed, bool) or not isinstance(seed, int) or not STUDY_KEYS["seed"].check(seed):
        raise where.fail_at(top_line(text, "seed"), f"seed = {seed!r}: accepted: "
                            f"{STUDY_KEYS['seed'].accepted}; a study needs one (its tasks are resumed on the "
                            "same random numbers)")
    trials = data.get("trials", life.get("trials", 5000))
    if isinstance(trials, bool) or not isinstance(trials, int) or not STUDY_KEYS["trials"].check(trials):
        raise where.fail_at(top_line(text, "trials"),
                            f"trials = {trials!r}: accepted: {STUDY_KEYS['trials'].accepted}")
    sections: list[SectionSpec] = []
    for i, sec in enumerate(sections_raw):
        sections.append(_section(where, i, sec, base, sections[-1] if sections else None))
    years = sections[0].design.lifetime_spec().years
    scenarios = tuple(ScenarioSpec(*scenario_values(where, j, sc, years))
                      for j, sc in enumerate(scenarios_raw))
    notices = []
    named = [(sec.name, sec.design) for sec in sections]
    for j, (sc, spec) in enumerate(zip(scenarios_raw, scenarios)):
        check_scenario_limits(where, j, sc, spec.sea_level, named)
        check_wave_heights(where, j, sc, spec.wave_height, named)
        falling = falling_sea_level(where, j, sc, spec.sea_level)
        if falling is not None:
            notices.append(falling)
    record = sections[0].design.lifetime_spec().record
    digest = _fingerprint(data, base_text, None if record is None else record.path)
    return Study(source=source, seed=int(seed), trials=int(trials), years=int(years),
                 sections=tuple(sections), scenarios=scenarios, study_hash=digest, notices=tuple(notices))


def _base_tables(data: Mapping[str, Any], text: str, source: str, where: Where) -> tuple[Merged, str | None]:
    """The base design's tables: the file of ``base`` (its record's path made absolute), then the
    study's inline tables over it; and the base file's text (None without one)."""
    merged = Merged()
    base_text = None
    if "base" in data:
        line = top_line(text, "base")
        if not isinstance(data["base"], str) or not data["base"].strip():
            raise where.fail_at(line, f"base = {data['base']!r}: accepted: {STUDY_KEYS['base'].accepted}")
        base_path = Path(source).parent / data["base"]
        try:
            base_text = read_design_text(base_path)
        except InputFileError as exc:
            raise where.fail_at(line, f"base = {data['base']!r}: cannot read the design file "
                                      f"{str(base_path)!r}: {exc.reason}") from None
        except (OSError, ValueError) as exc:
            raise where.fail_at(line,
                                f"base = {data['base']!r}: cannot read the design file: {exc}") from None
        base_data = load_toml(base_text, str(base_path))
        for table, body in base_data.items():
            merged.set(table, None, None, Origin(str(base_path), key_line(base_text, table)))
            for key, value in (body.items() if isinstance(body, dict) else ()):
                if table == "lifetime" and key == "record" and isinstance(value, dict) and "path" in value:
                    value = {**value, "path": str(base_path.parent / str(value["path"]))}
                merged.set(table, key, value, Origin(str(base_path), key_line(base_text, table, key)))
                _sub_origins(merged, table, key, value, str(base_path), base_text)
    for table in DESIGN_TABLES:
        if table in data:
            if not isinstance(data[table], dict):
                raise where.fail_at(top_line(text, table), f"{table} must be a table [{table}]")
            merged.set(table, None, None, Origin(source, key_line(text, table)))
            for key, value in data[table].items():
                merged.set(table, key, value, Origin(source, key_line(text, table, key)))
                _sub_origins(merged, table, key, value, source, text)
    if "lifetime" not in merged.tables:
        raise where.fail_at(None, "no [lifetime] table (the wave climate and the options of the lifetime "
                            "simulation), inline or in the base design file")
    return merged, base_text


def _sub_origins(merged: Merged, table: str, key: str, value: object, file: str, text: str) -> None:
    """The line of each key of a table within a table (``[lifetime.record] threshold``), so that the
    design reader's message about one of them names its own line, not the table's."""
    if isinstance(value, dict):
        inner = f"{table}.{key}"
        for sub in value:
            merged.origin[(inner, str(sub))] = Origin(file, key_line(text, inner, str(sub)))


def _section(where: Where, i: int, sec: Mapping[str, Any], base: Merged,
             before: SectionSpec | None) -> SectionSpec:
    """The ``i``-th ``[[section]]``: its chainage (not below ``before``'s), its overrides merged into
    ``base`` and read by the design reader, its widths or target."""
    name = sec["name"]
    chain = number_of(sec.get("chainage"))
    line = where.item("section", i, "chainage")
    if chain is None or not math.isfinite(chain):
        raise where.fail_at(line, f"[[section]] {name!r}: chainage = {sec.get('chainage')!r}; accepted: "
                            f"{SECTION_KEYS['chainage'].accepted}")
    if before is not None and chain < before.chainage:
        raise where.fail_at(line, f"[[section]] {name!r}: chainage = {sec['chainage']!r} goes back (section "
                            f"{before.name!r} is at {before.chainage:g} m); accepted: "
                            f"{SECTION_KEYS['chainage'].accepted}")
    merged = base.copy()
    for key, value in sec.items():
        if key in SECTION_KEYS:
            continue
        if key in OVERRIDABLE and isinstance(value, dict):
            for sub, x in value.items():
                check_override(where, i, key, sub)
                merged.set(key, sub, x, Origin(where.source, where.item("section", i, f"{key}.{sub}")))
            continue
        table, k = section_key(where, i, key)
        check_override(where, i, table, k, key)
        merged.set(table, k, value, Origin(where.source, where.item("section", i, key)))
    widths, target, tolerance = section_widths(where, i, sec)
    design = design_of(merged, where.source, name, i, where)
    return SectionSpec(name=name, chainage=chain, design=design,
                       widths=widths if widths is not None else (design.caisson.width,),
                       target=target, tolerance=tolerance)


def read_study(path: str | Path) -> Study:
    """Read and check a study file (:func:`parse_study`).

    Raises
    ------
    StudyFileError
        See :func:`parse_study`; also when the file cannot be read.
    """
    p = Path(path)
    try:
        text = read_design_text(p, "study file")
    except InputFileError as exc:
        raise StudyFileError(f"{p}: cannot read the study file: {exc.reason}") from None
    except (OSError, ValueError) as exc:
        raise StudyFileError(f"{p}: cannot read the study file: {exc}") from None
    return parse_study(text, source=str(p))
