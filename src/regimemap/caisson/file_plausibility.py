"""Values of a design file that are valid but implausible for a breakwater: likely unit slips.

A design file can pass every range check and still describe no breakwater:
``depth = 1010`` (centimetres for metres) draws a 1000-m mound, and
``buoyant_weight = 2312000`` (N/m for kN/m) a section as dense as lead. Each
check below names the key, the value, the range that real vertical
breakwaters fall in, and the slip that most likely explains the value; as
warnings of a workflow they are :class:`~regimemap.records.notices.Notice`
data (:func:`implausible_notices`). The commands print them on standard error;
``--strict`` makes them errors. Valid inputs are never refused without ``--strict``.

Values beyond what physics allows are errors of the reader instead
(:mod:`regimemap.caisson.file_keys`: a significant height over 30 m, a period
outside 1-30 s, a depth outside 0.5-100 m); the warnings here are for the
merely unusual.  The ranges are generous on purpose (a warning that fires on
real designs is noise): sea water depth at a breakwater up to 70 m (the
deepest caisson breakwater, Kamaishi's, stands in 63 m), significant periods 2-30 s, an
implied unit weight of the whole section 5-30 kN/m^3 (water is 10, concrete
24, a sand-filled caisson 19-21), heel pressure up to 5 MPa (Goda 2000,
Sect. 4.2: about 400-500 kPa is allowed on a rubble mound), a section
narrower or wider than 1-100 m and wave heights below 30 m.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..records.notices import Notice

if TYPE_CHECKING:  # pragma: no cover
    from regimemap.waves import CaissonAnalysis

    from .file import Design

__all__ = ["IMPLAUSIBLE", "Implausible", "implausible_notices", "implausible_values"]

#: The code of an implausible value's :class:`~regimemap.records.notices.Notice`.
IMPLAUSIBLE = "implausible-value"

#: Plausible ranges: (low, high) and the unit they are in.
RANGES: dict[str, tuple[float, float, str]] = {
    "depth": (0.5, 70.0, "m"),
    "period": (2.0, 30.0, "s"),
    "unit_weight": (5.0, 30.0, "kN/m^3"),
    "heel_pressure": (0.0, 5000.0, "kPa"),
    "width": (1.0, 100.0, "m"),
    "height": (0.0, 30.0, "m"),
}


@dataclass(frozen=True)
class Implausible:
    """One implausible value: where, what, and the likely slip."""

    key: str       # "[site] depth"
    value: float
    message: str   # the whole sentence, naming the key

    def __str__(self) -> str:
        return self.message

    def notice(self) -> Notice:
        """The finding as a warning of a workflow: code :data:`IMPLAUSIBLE`, the key dotted
        (``"caisson.buoyant_weight"``, ``"heel_pressure"``) as its quantity."""
        quantity = self.key.replace("[", "").replace("] ", ".").replace(" ", "_")
        return Notice(IMPLAUSIBLE, self.message, quantity=quantity, value=self.value)


def _num(x: float) -> str:
    """A number as a person writes it: ``2312000``, ``10.1``, ``0.035`` (no exponent below 1e15)."""
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return f"{x:.6g}" if 1e-4 <= abs(x) < 1e15 else f"{x:.4g}"


def implausible_values(design: Design, analysis: CaissonAnalysis | None = None) -> list[Implausible]:
    """The implausible values of a design file (empty when all are plausible).

    Parameters
    ----------
    design : Design
        A parsed and checked design file.
    analysis : CaissonAnalysis, optional
        Its Goda analysis, for the checks on computed values (heel pressure).

    Returns
    -------
    list of Implausible
        In file order: ``[site]``, ``[wave]``, ``[caisson]``, ``[lifetime]``,
        then computed values.

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> implausible_values(parse_design(example_design_text()))
    []
    >>> text = example_design_text().replace("buoyant_weight = 2312", "buoyant_weight = 2312000")
    >>> print(implausible_values(parse_design(text))[0])  # doctest: +ELLIPSIS
    [caisson] buoyant_weight = 2312000: implies a unit weight of ... N/m for kN/m?
    """
    w, c = design.wave, design.caisson
    heights: tuple[tuple[str, float | None], ...] = (
        ("[wave] H0", w.H0), ("[wave] H13", w.H13), ("[wave] Hmax", w.Hmax), ("[caisson] crest", c.crest))
    return [*_depths(design), *_period("[wave] period", w.period), *_heights(heights),
            *_width(c.width), *_unit_weight(design), *_densities(design), *_lifetime(design),
            *_heel_pressure(analysis)]


def implausible_notices(design: Design, analysis: CaissonAnalysis | None = None
                        ) -> tuple[Notice, ...]:
    """:func:`implausible_values` as the warnings of a workflow, one
    :class:`~regimemap.records.notices.Notice` each (:meth:`Implausible.notice`).

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> text = example_design_text().replace("depth = 10.1", "depth = 80")
    >>> n = implausible_notices(parse_design(text))[0]
    >>> n.code, n.quantity, n.value
    ('implausible-value', 'site.depth', 80.0)
    """
    return tuple(item.notice() for item in implausible_values(design, analysis))


def _item(key: str, value: float, text: str) -> Implausible:
    """One finding: ``key = value: text``."""
    return Implausible(key, value, f"{key} = {_num(value)}: {text}")


def _depths(design: Design) -> list[Implausible]:
    """Depths over 70 m: deeper than any caisson breakwater built."""
    s, c = design.site, design.caisson
    hi = RANGES["depth"][1]
    return [_item(key, depth, f"deeper than {hi:g} m, deeper than any caisson breakwater built "
                              "(Kamaishi's stands in 63 m)")
            for key, depth in (("[site] depth", s.depth), ("[site] armour_depth", s.armour_depth),
                               ("[caisson] base_depth", c.base_depth))
            if depth > hi]


def _period(key: str, period: float | None, slips: bool = True) -> list[Implausible]:
    """A period outside 2-30 s: tenths of a second, or a frequency (``slips``: say which)."""
    lo, hi, _ = RANGES["period"]
    if period is None or lo <= period <= hi:
        return []
    text = f"outside the {lo:g}-{hi:g} s of sea waves"
    if slips:
        text += "; " + (f"{period / 10:.3g} s in tenths of a second?" if period > hi else
                        "a laboratory model's wave, or a frequency (1/s) for a period?")
    return [_item(key, period, text)]


def _heights(heights: tuple[tuple[str, float | None], ...]) -> list[Implausible]:
    """Wave heights (and the crest) over 30 m: centimetres for metres."""
    hi = RANGES["height"][1]
    return [_item(key, h, f"over {hi:g} m; {h / 100:.4g} m in centimetres for metres?")
            for key, h in heights if h is not None and h > hi]


def _width(width: float) -> list[Implausible]:
    """A caisson narrower than 1 m or wider than 100 m."""
    lo, hi, _ = RANGES["width"]
    if lo <= width <= hi:
        return []
    slip = (f"{width / 100:.4g} m in centimetres for metres?" if width > hi
            else "the half width B for the full width, or metres for decimetres?")
    return [_item("[caisson] width", width, f"outside the {lo:g}-{hi:g} m of caisson widths; {slip}")]


def _unit_weight(design: Design) -> list[Implausible]:
    """The section's implied unit weight (dry weight over its area, kN/m^3) outside 5-30."""
    s, c = design.site, design.caisson
    if c.buoyant_weight is None:
        return []
    g = 9.81
    dry = c.buoyant_weight + s.water_density * g * c.width * c.base_depth / 1e3
    area = c.width * (c.base_depth + c.crest)
    unit = dry / area if area > 0 else math.inf
    lo, hi, _ = RANGES["unit_weight"]
    if lo <= unit <= hi:
        return []
    slip = ("N/m for kN/m?" if unit > 1000 * lo and unit / 1000 <= hi * 1.5 else
            "kN/m expected: N/m or tonnes per metre?" if unit > hi else
            "tonnes per metre for kN/m, or the weight of a smaller section?")
    return [_item("[caisson] buoyant_weight", c.buoyant_weight,
                  f"implies a unit weight of {_num(round(unit, 1))} kN/m^3 for the section "
                  f"{_num(c.width)} m wide and {_num(c.base_depth + c.crest)} m high "
                  f"(real caissons: {lo:g}-{hi:g}); {slip}")]


def _densities(design: Design) -> list[Implausible]:
    """Densities outside 800-3500 kg/m^3: t/m^3 (or g/cm^3), or a unit weight in N/m^3."""
    c = design.caisson
    densities: tuple[tuple[str, float | None], ...] = (
        ("[caisson] concrete_density", c.concrete_density), ("[caisson] fill_density", c.fill_density),
        ("[caisson] fill_density_above", c.fill_density_above))
    return [_item(key, rho, "outside 800-3500 kg/m^3; " + (
                "t/m^3 or g/cm^3 for kg/m^3?" if rho < 800.0 else "a unit weight in N/m^3 for a density?"))
            for key, rho in densities if rho is not None and not 800.0 <= rho <= 3500.0]


def _lifetime(design: Design) -> list[Implausible]:
    """The ``[lifetime]`` table's return heights and period."""
    life = design.lifetime
    if life is None:
        return []
    returns: tuple[tuple[str, float | None], ...] = (
        ("[lifetime] H0_10", life.H0_10), ("[lifetime] H0_50", life.H0_50))
    return [*_heights(returns), *_period("[lifetime] period", life.period, slips=False)]


def _heel_pressure(analysis: CaissonAnalysis | None) -> list[Implausible]:
    """A heel pressure over 5 MPa (computed: needs the analysis)."""
    if analysis is None:
        return []
    import numpy as np

    pe = float(np.asarray(analysis.stability.heel_pressure)) / 1e3
    hi = RANGES["heel_pressure"][1]
    if not (math.isfinite(pe) and pe > hi):
        return []
    return [Implausible(
        "heel pressure", pe,
        f"heel pressure {_num(round(pe))} kPa: over {hi / 1e3:g} MPa, far beyond what a rubble "
        "mound bears (Goda 2000 allows about 500 kPa); check the units of [caisson] "
        "buoyant_weight (kN/m) and the geometry")]
