"""A study's scenarios against the limits of a design file, before any task runs.

A scenario's sea level moves every section's still water: the depth ``h``, the
depth ``d`` above the armour and ``h'`` below the base rise by it, the crest
``hc`` falls by it (:class:`regimemap.lifetime.YearTrend`).  Each service year of
each scenario is checked for each section with the design file's own declarations
(:data:`regimemap.caisson.file_keys.DESIGN_KEYS`: their range tests and the words of
what they accept) and the lifetime model's rule that the crest stays above the still
water (``hc - rise > 0``, :meth:`regimemap.lifetime.YearTrend.check_site`): a
scenario that puts a crest under water, leaves a mound dry or a depth out of range is
refused, naming the file, the scenario's line, the service year and the section, with
a hint when the values read in millimetres (or centimetres) would pass.  A sea level
that falls is unusual, not impossible: a :class:`~regimemap.records.notices.Notice`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..caisson.file_keys import DESIGN_KEYS
from ..lifetime.file_keys import LIFETIME_KEYS
from ..records.notices import Notice
from .file_sections import Where

if TYPE_CHECKING:
    from ..caisson.file import Design

__all__ = ["SEA_LEVEL_LIMITS", "check_scenario_limits", "check_wave_heights", "falling_sea_level"]

#: What a rise does to a design's lengths: (table, key, symbol, sign of the rise, what a failure does
#: to the section ``{}``); each risen length is checked against the design file's declaration of its
#: key (:data:`~regimemap.caisson.file_keys.DESIGN_KEYS`), and the crest must stay above the water.
SEA_LEVEL_LIMITS = (("caisson", "crest", "hc", -1.0, "puts the crest of section {} under water"),
                    ("site", "armour_depth", "d", 1.0, "leaves the mound of section {} dry"),
                    ("caisson", "base_depth", "h'", 1.0, "lifts the base of section {} out of the water"),
                    ("site", "depth", "h", 1.0, "takes the water depth of section {} out of range"))
#: A rise of this many metres or more is no projection of the sea level (about 1 m by 2100, a few
#: metres in the worst cases): a value that passes once divided by 1000 or 100 was typed in mm or cm.
_SLIP_RISE = 10.0


def _key(sc: Mapping[str, Any]) -> str:
    """The scenario's key that gives its sea level (for the line of the message)."""
    if "sea_level_rise" in sc:
        return "sea_level_rise"
    return "rate" if "rate" in sc else "acceleration"


def _value(design: Design, table: str, key: str) -> float:
    value: float = getattr(design.caisson if table == "caisson" else design.site, key)
    return value


def _problem(design: Design, rise: float) -> tuple[str, str, float, float, str] | None:
    """The first of the design's lengths the sea-level ``rise`` puts out of range: (symbol, what it
    does, today's value, the value risen, what is accepted); None when all stay in range."""
    for table, key, symbol, sign, what in SEA_LEVEL_LIMITS:
        spec = DESIGN_KEYS[table][key]
        today = _value(design, table, key)
        moved = today + sign * rise
        # the crest must stay above the still water (the lifetime model's rule), not only >= 0
        if not spec.check(moved) or (key == "crest" and not moved > 0.0):
            return symbol, what, today, moved, spec.accepted
    return None


def _passes(designs: Sequence[Design], sea: Sequence[float]) -> bool:
    return all(_problem(d, eta) is None for eta in sea if eta != 0.0 for d in designs)


def check_scenario_limits(where: Where, index: int, sc: Mapping[str, Any], sea: Sequence[float],
                          sections: Sequence[tuple[str, Design]]) -> None:
    """Refuse the ``index``-th ``[[scenario]]`` when its sea level of a service year takes a section
    out of the design file's limits; the earliest year first, then the sections in order.

    Parameters
    ----------
    where : Where
        The study file's lines.
    index : int
        The scenario's place among the ``[[scenario]]`` tables.
    sc : mapping
        The scenario's table as parsed.
    sea : sequence of float
        Its rise above today's mean sea level in service years 1..L [m].
    sections : sequence of (str, Design)
        The sections' names and checked designs.

    Raises
    ------
    regimemap.study.file_sections.StudyFileError
        ``"FILE, line N: [[scenario]] 'NAME' sea_level_rise: service year Y = R m puts the crest
        of section 'S' under water (hc = 3.4 - R = ... m; accepted in every service year: ...)"``.
    """
    key = _key(sc)
    designs = [d for _, d in sections]
    for year, eta in enumerate(sea, start=1):
        if eta == 0.0:  # today's site, checked with the section's design
            continue
        for name, design in sections:
            found = _problem(design, eta)
            if found is None:
                continue
            symbol, what, today, moved, accepted = found
            op = "+" if (-1.0 if symbol == "hc" else 1.0) * eta >= 0.0 else "-"
            hint = ""
            if max(abs(x) for x in sea) >= _SLIP_RISE:
                for scale, unit in ((1000.0, "millimetres"), (100.0, "centimetres")):
                    if _passes(designs, [x / scale for x in sea]):
                        hint = f"; {unit} for metres?"
                        break
            rule = "hc - rise > 0, " if symbol == "hc" else ""
            raise where.fail_at(where.item("scenario", index, key),
                                f"[[scenario]] {sc['name']!r} {key}: service year {year} = {eta:g} m "
                                f"{what.format(repr(name))} ({symbol} = {today:g} {op} {abs(eta):g} = "
                                f"{round(moved, 9) + 0.0:g} m; accepted in every service year: "
                                f"{rule}{accepted}){hint}")


def falling_sea_level(where: Where, index: int, sc: Mapping[str, Any], sea: Sequence[float]) -> Notice | None:
    """A notice when the scenario's sea level falls from one service year to a later one (from
    today's, 0 m, to year 1 included); None when it never falls."""
    before, last_year = 0.0, 0
    for year, eta in enumerate(sea, start=1):
        if eta < before:
            low = min(sea[year - 1:])
            low_year = year + list(sea[year - 1:]).index(low)
            key = _key(sc)
            start = "today" if last_year == 0 else f"service year {last_year}"
            return Notice("falling-sea-level",
                          f"{where.at(where.item('scenario', index, key))}: [[scenario]] {sc['name']!r} "
                          f"{key}: the sea level falls, from {before:g} m ({start}) to {low:g} m in service "
                          f"year {low_year}; {key} is the level above today's mean sea level in each year "
                          "(a year or a sign typed wrong?); run as given",
                          quantity=key, value=float(low))
        before, last_year = eta, year
    return None


def _largest_height(design: Design) -> float | None:
    """The section's 50-year ``H0'`` as its file gives it (``H0_50``, or the largest of its
    ``annual_maxima``, a lower bound); None for a record's climate (fitted when the study runs)."""
    spec = design.lifetime_spec()
    if spec.H0_50 is not None:
        return float(spec.H0_50)
    if spec.annual_maxima:
        return float(max(spec.annual_maxima))
    return None


def check_wave_heights(where: Where, index: int, sc: Mapping[str, Any], factors: Sequence[float],
                       sections: Sequence[tuple[str, Design]]) -> None:
    """Refuse the ``index``-th ``[[scenario]]`` when its ``wave_height_factor`` of a service year
    lifts a section's 50-year ``H0'`` out of the design file's range of ``[lifetime] H0_50``
    (:data:`~regimemap.lifetime.file_keys.LIFETIME_KEYS`): a factor of 10 for 10 %.

    Raises
    ------
    regimemap.study.file_sections.StudyFileError
        Naming the file, the line of ``wave_height_factor``, the service year and the section.
    """
    spec = LIFETIME_KEYS["H0_50"]
    for year, f in enumerate(factors, start=1):
        if f == 1.0:
            continue
        for name, design in sections:
            h = _largest_height(design)
            if h is None or spec.check(h * f):
                continue
            hint = "; a per cent for a factor (1.1 for 10 % higher)?" if f >= 2.0 else ""
            line = where.item("scenario", index, "wave_height_factor")
            raise where.fail_at(line, f"[[scenario]] {sc['name']!r} wave_height_factor: service year "
                                f"{year} = {f:g} makes the 50-year H0' of section {name!r} {h * f:.4g} m "
                                f"({h:g} m x {f:g}; accepted in every service year: {spec.accepted}){hint}")
