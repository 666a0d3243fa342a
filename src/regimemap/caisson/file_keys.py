"""The keys of a design file's ``[site]``, ``[wave]`` and ``[caisson]`` tables, declared once; their reader.

Each key is one field of its table's dataclass (:class:`SiteSpec`, :class:`WaveSpec`,
:class:`CaissonSpec`), declared with :func:`~regimemap.io.toml_keys.key`: its name and type, its
default (none: required), what it accepts in words, its range test, why a value out of range is refused, and
its lines in the commented example.  From those fields come :data:`DESIGN_KEYS` (the words of
the error messages, the "did you mean" of an unknown key, the documentation's table of the
keys, the study file's overrides), the reading and checking of a table
(:meth:`~regimemap.io.toml_keys.KeyReader.table`, :func:`design_reader`) and the example's tables
(:func:`example_tables`).
:func:`regimemap.caisson.file.parse_design` reads a file with them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ..io.toml_keys import Key, KeyReader, example_table, key, keys_of

__all__ = ["DEPTH_RANGE", "DESIGN_KEYS", "DESIGN_TABLES", "MAX_BERM", "MAX_CREST", "MAX_HEIGHT", "MAX_WEIGHT",
           "MIN_LENGTH", "PERIOD_RANGE", "WIDTH_RANGE", "CaissonSpec", "SiteSpec", "WaveSpec",
           "design_reader", "example_tables"]


def _positive(x: float) -> bool:
    return x > 0.0


#: Hard limits set by the physics of sea waves and the reach of Goda's method (errors, not
#: warnings; :mod:`regimemap.caisson.file_plausibility` warns about the merely unusual):
#: significant heights up to 30 m (the largest measured at sea are about 20 m), periods of
#: 1-30 s (wind waves and swell; longer is a tide or a tsunami, outside Goda's formulas) and
#: water depths of 0.5-100 m (from a laboratory flume's model to beyond the deepest caisson
#: breakwater built, Kamaishi's in 63 m).
MAX_HEIGHT = 30.0
PERIOD_RANGE = (1.0, 30.0)
DEPTH_RANGE = (0.5, 100.0)
#: The least length a design file may give [m] (a wave height, a depth above the mound or below
#: the base): a centimetre, less than the smallest model in a laboratory flume.
MIN_LENGTH = 0.01
#: The section's limits: a width of 0.05-500 m (a flume's model to five times the widest
#: caissons), a crest up to 100 m and a berm up to 1000 m above and beside the water, a buoyant
#: weight up to 10^7 kN/m (forty times a 100 m square block of concrete: room for a weight in N/m,
#: a unit slip the warnings name).
WIDTH_RANGE = (0.05, 500.0)
MAX_CREST = 100.0
MAX_BERM = 1000.0
MAX_WEIGHT = 1e7
# the least buoyant weight, kN/m (1 N/m): below it W'/(m g) rounds away beside the buoyancy
# of any section in range, and the block would float (buoyancy = 1)
MIN_WEIGHT = 1e-3


def _length(lo: float, hi: float) -> Callable[[float], bool]:
    return lambda x: lo <= x <= hi


def _out_of_range(why: Callable[[float], str]) -> Callable[[float], str]:
    """The reason of a refused value as the design file's messages give it: ``out of range, WHY``."""
    return lambda x: f"out of range, {why(x)}"


def _beyond(lo: float, hi: float, unit: str, what: str) -> Callable[[float], str]:
    """The reason of a length or weight outside ``[lo, hi]``: ``what`` it would be."""
    def why(x: float) -> str:
        side = f"below {lo:g} {unit}" if x < lo else f"above {hi:g} {unit}"
        return f"{side}, {what}"
    return _out_of_range(why)


def _slip(x: float, scale: float, hi: float, unit: str, what: str) -> str:
    """``"; 6.3 m in centimetres for metres?"`` when ``x / scale`` would be in range, else ``""``."""
    return f"; {x / scale:.4g} {unit} in {what}?" if x / scale <= hi else ""


@_out_of_range
def _height_why(x: float) -> str:
    if x < MIN_LENGTH:
        return f"below {MIN_LENGTH:g} m, less than any wave of a laboratory flume"
    return (f"above {MAX_HEIGHT:g} m: the largest significant heights measured at sea are about 20 m"
            + _slip(x, 100.0, MAX_HEIGHT, "m", "centimetres for metres"))


@_out_of_range
def _hmax_why(x: float) -> str:
    if x < MIN_LENGTH:
        return f"below {MIN_LENGTH:g} m, less than any wave of a laboratory flume"
    return (f"above {2 * MAX_HEIGHT:g} m, twice the largest significant height accepted "
            f"({MAX_HEIGHT:g} m)" + _slip(x, 100.0, 2 * MAX_HEIGHT, "m", "centimetres for metres"))


@_out_of_range
def _period_why(x: float) -> str:
    lo, hi = PERIOD_RANGE
    if x > hi:
        return (f"longer than {hi:g} s: sea waves (wind waves and swell) last {lo:g}-{hi:g} s, longer is "
                "a tide or a tsunami, outside Goda's formulas"
                + _slip(x, 10.0, hi, "s", "tenths of a second"))
    return (f"shorter than {lo:g} s: ripples, not sea waves; a frequency (1/s) or an angular "
            "frequency for a period?")


@_out_of_range
def _depth_why(x: float) -> str:
    lo, hi = DEPTH_RANGE
    if x > hi:
        return (f"deeper than {hi:g} m: no caisson breakwater stands there (the deepest, Kamaishi's, "
                "in 63 m)" + _slip(x, 100.0, hi, "m", "centimetres for metres"))
    return f"shallower than {lo:g} m, less than a laboratory model's flume; metres expected"


@dataclass(frozen=True, kw_only=True)
class SiteSpec:
    """``[site]``: depth ``h``, armour depth ``d`` [m], ``tan theta``, water density [kg/m^3]."""

    depth: float = key(f"a water depth {DEPTH_RANGE[0]:g} <= h <= {DEPTH_RANGE[1]:g} in metres",
                       lambda x: DEPTH_RANGE[0] <= x <= DEPTH_RANGE[1], why=_depth_why,
                       example="depth = 10.1          # h, water depth at the wall")
    armour_depth: float = key(f"a depth d >= {MIN_LENGTH:g} in metres above the armour layer of the mound",
                              lambda x: x >= MIN_LENGTH,
                              why=_beyond(MIN_LENGTH, math.inf, "m", "less than a laboratory model's"),
                              example="armour_depth = 5.6    # d, depth above the armour layer of the mound")
    seabed_slope: float = key("tan(theta) of the sea bed, 0 <= seabed_slope <= 1", lambda x: 0.0 <= x <= 1.0,
                              example="seabed_slope = 0.01   # tan(theta) of the sea bed in front (1/100)")
    water_density: float = key("a density 900 <= water_density <= 1100 kg/m^3",
                               lambda x: 900.0 <= x <= 1100.0, default=1030.0,
                               example="water_density = 1030  # optional, default 1030")


@dataclass(frozen=True, kw_only=True)
class WaveSpec:
    """``[wave]``: ``H0'`` or (``H1/3``, ``Hmax``) [m], ``T1/3`` [s], angle and rotation [deg]."""

    H0: float | None = key(f"an equivalent deep-water significant height {MIN_LENGTH:g} <= H0 <= "
                           f"{MAX_HEIGHT:g} in metres", _length(MIN_LENGTH, MAX_HEIGHT), default=None,
                           why=_height_why,
                           example="H0 = 6.3              # equivalent deep-water significant height H0'\n"
                                   "                      # (or give H13 and Hmax at the wall instead)")
    H13: float | None = key(f"a significant height {MIN_LENGTH:g} <= H13 <= {MAX_HEIGHT:g} in metres at the "
                            "wall", _length(MIN_LENGTH, MAX_HEIGHT), default=None, why=_height_why)
    Hmax: float | None = key(f"a maximum height H13 <= Hmax <= {2 * MAX_HEIGHT:g} in metres at the wall",
                             _length(MIN_LENGTH, 2 * MAX_HEIGHT), default=None, why=_hmax_why)
    period: float = key(f"a significant period {PERIOD_RANGE[0]:g} <= T1/3 <= {PERIOD_RANGE[1]:g} in seconds",
                        lambda x: PERIOD_RANGE[0] <= x <= PERIOD_RANGE[1], why=_period_why,
                        example="period = 11.4         # T1/3, significant period")
    angle: float = key("an angle -90 < angle < 90 degrees from the normal to the wall",
                       lambda x: -90.0 < x < 90.0, default=0.0,
                       example="angle = 15            # beta, degrees from the normal to the wall")
    rotation: float = key("a rotation toward the normal 0 <= rotation <= 15 degrees (Goda 2000)",
                          lambda x: 0.0 <= x <= 15.0, default=0.0,
                          example="rotation = 0          # optional: rotate beta toward the normal by up "
                                  "to 15 degrees\n"
                                  "                      # (Goda's recommendation for uncertain directions); "
                                  "default 0")


@dataclass(frozen=True, kw_only=True)
class CaissonSpec:
    """``[caisson]``: geometry [m], friction, and ``W'`` [kN/m] or densities [kg/m^3]."""

    width: float = key(f"a full width {WIDTH_RANGE[0]:g} <= width <= {WIDTH_RANGE[1]:g} in metres",
                       _length(*WIDTH_RANGE),
                       why=_beyond(*WIDTH_RANGE, "m", "no caisson (models in a flume to breakwaters are "
                                   "0.1-100 m wide); metres expected"),
                       example="width = 15.0          # full width of the upright section")
    base_depth: float = key(f"a depth h' >= {MIN_LENGTH:g} in metres of the base below still water",
                            lambda x: x >= MIN_LENGTH,
                            why=_beyond(MIN_LENGTH, math.inf, "m", "less than a laboratory model's"),
                            example="base_depth = 7.1      # h', depth of its base below still water")
    crest: float = key(f"a crest height 0 <= hc <= {MAX_CREST:g} in metres above still water (not below the "
                       "water)", _length(0.0, MAX_CREST),
                       why=_beyond(0.0, MAX_CREST, "m", "no breakwater's crest; metres expected"),
                       example="crest = 3.4           # hc, crest height above still water")
    berm_width: float = key(f"a berm width 0 <= BM <= {MAX_BERM:g} in metres", _length(0.0, MAX_BERM),
                            default=0.0, why=_beyond(0.0, MAX_BERM, "m", "metres expected"),
                            example="berm_width = 8.0      # BM, berm width (Takahashi's impulsive "
                                    "coefficient)")
    friction: float = key("a friction coefficient 0.01 <= friction <= 2 (ice on steel is about 0.02)",
                          lambda x: 0.01 <= x <= 2.0,
                          example="friction = 0.6        # mu, caisson on rubble")
    buoyant_weight: float | None = key(f"a buoyant weight {MIN_WEIGHT:g} <= W' <= {MAX_WEIGHT:g} in kN per "
                                       "metre", lambda x: MIN_WEIGHT <= x <= MAX_WEIGHT, default=None,
                                       why=_out_of_range(lambda x: (
                                           f"below {MIN_WEIGHT:g} kN/m, a caisson that floats (its buoyancy "
                                           "is all its weight)" if x < MIN_WEIGHT else
                                           f"above {MAX_WEIGHT:g} kN/m, more than forty times a 100 m square "
                                           "block of concrete; kN/m expected")),
                                       example="buoyant_weight = 2312 # W', weight in still water, kN/m")
    concrete_fraction: float | None = key("an area fraction 0 <= concrete_fraction <= 1",
                                          lambda x: 0.0 <= x <= 1.0, default=None,
                                          example="# or, instead of buoyant_weight, the densities of a "
                                                  "filled caisson:\n"
                                                  "# concrete_fraction = 0.25   # area fraction of concrete "
                                                  "in the section")
    concrete_density: float | None = key("a density concrete_density > 0 in kg/m^3", _positive, default=None,
                                         example="# concrete_density = 2400    # kg/m^3")
    fill_density: float | None = key("a density fill_density > 0 in kg/m^3 (fill below still water)",
                                     _positive, default=None,
                                     example="# fill_density = 2000        # saturated fill below still "
                                             "water, kg/m^3")
    fill_density_above: float | None = key("a density fill_density_above > 0 in kg/m^3", _positive,
                                           default=None,
                                           example="# fill_density_above = 1800  # optional: fill above "
                                                   "still water, kg/m^3")
    required_sliding: float = key("a required sliding safety factor 1 <= required_sliding <= 3 (default 1.2, "
                                  "Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0, default=1.2,
                                  example="# required_sliding = 1.2     # optional: the safety factors the "
                                          "design must reach (default 1.2")
    required_overturning: float = key("a required overturning safety factor 1 <= required_overturning <= 3 "
                                      "(default 1.2, Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0,
                                      default=1.2,
                                      example="# required_overturning = 1.2 #   for both, Goda 2000); "
                                              "`regimemap caisson` says when one fails")
    impulsive: bool = key("true or false (Takahashi's impulsive coefficient)", kind="bool", default=True,
                          example="# impulsive = true           # optional: Takahashi's impulsive "
                                  "coefficient (default true)")


#: The tables ``[site]``, ``[wave]`` and ``[caisson]`` and the dataclass of each (``[lifetime]`` is
#: :mod:`regimemap.lifetime.file`'s).
DESIGN_TABLES: dict[str, type] = {"site": SiteSpec, "wave": WaveSpec, "caisson": CaissonSpec}
#: The keys of each table, as their fields declare them.
DESIGN_KEYS: dict[str, dict[str, Key]] = {table: keys_of(cls) for table, cls in DESIGN_TABLES.items()}


def example_tables() -> str:
    """The tables ``[site]``, ``[wave]`` and ``[caisson]`` of the commented example, from the keys' lines."""
    return "".join(example_table(table, cls) + "\n" for table, cls in DESIGN_TABLES.items())


def design_reader(source: str, text: str = "") -> KeyReader:
    """The reader of a design file's ``[site]``, ``[wave]`` and ``[caisson]``."""
    return KeyReader(source, text, DESIGN_KEYS)


