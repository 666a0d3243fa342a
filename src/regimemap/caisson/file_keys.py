"""The keys of a design file's ``[site]``, ``[wave]`` and ``[caisson]`` tables and their reader.

:data:`DESIGN_KEYS` says what each key accepts (the words of the error messages, and
of the documentation's table of the keys); :class:`DesignReader` reads a value and checks
it against them.  :func:`regimemap.caisson.file.parse_design` uses both.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from ..io.toml_errors import DesignFileError, did_you_mean
from ..io.toml_lines import key_line, key_text

__all__ = ["DEPTH_RANGE", "DESIGN_KEYS", "MAX_BERM", "MAX_CREST", "MAX_HEIGHT", "MAX_WEIGHT", "MIN_LENGTH",
           "PERIOD_RANGE", "WIDTH_RANGE", "DesignReader", "KeySpec"]


# -- the accepted keys ----------------------------------------------------------------------------

@dataclass(frozen=True)
class KeySpec:
    """One key of a table: what it accepts in words, its range test, whether it is required, and
    why a value out of range is refused (``why(value)``: the physics, and the likely slip)."""

    accepted: str                      # what is accepted, in words
    check: Callable[[float], bool]     # range test of a number
    required: bool = True
    boolean: bool = False
    why: Callable[[float], str] | None = None


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


def _length(lo: float, hi: float) -> Callable[[float], bool]:
    return lambda x: lo <= x <= hi


def _beyond(lo: float, hi: float, unit: str, what: str) -> Callable[[float], str]:
    """The reason of a length or weight outside ``[lo, hi]``: ``what`` it would be."""
    def why(x: float) -> str:
        side = f"below {lo:g} {unit}" if x < lo else f"above {hi:g} {unit}"
        return f"{side}, {what}"
    return why


def _slip(x: float, scale: float, hi: float, unit: str, what: str) -> str:
    """``"; 6.3 m in centimetres for metres?"`` when ``x / scale`` would be in range, else ``""``."""
    return f"; {x / scale:.4g} {unit} in {what}?" if x / scale <= hi else ""


def _height_why(x: float) -> str:
    if x < MIN_LENGTH:
        return f"below {MIN_LENGTH:g} m, less than any wave of a laboratory flume"
    return (f"above {MAX_HEIGHT:g} m: the largest significant heights measured at sea are about 20 m"
            + _slip(x, 100.0, MAX_HEIGHT, "m", "centimetres for metres"))


def _hmax_why(x: float) -> str:
    if x < MIN_LENGTH:
        return f"below {MIN_LENGTH:g} m, less than any wave of a laboratory flume"
    return (f"above {2 * MAX_HEIGHT:g} m, twice the largest significant height accepted "
            f"({MAX_HEIGHT:g} m)" + _slip(x, 100.0, 2 * MAX_HEIGHT, "m", "centimetres for metres"))


def _period_why(x: float) -> str:
    lo, hi = PERIOD_RANGE
    if x > hi:
        return (f"longer than {hi:g} s: sea waves (wind waves and swell) last {lo:g}-{hi:g} s, longer is "
                "a tide or a tsunami, outside Goda's formulas"
                + _slip(x, 10.0, hi, "s", "tenths of a second"))
    return (f"shorter than {lo:g} s: ripples, not sea waves; a frequency (1/s) or an angular "
            "frequency for a period?")


def _depth_why(x: float) -> str:
    lo, hi = DEPTH_RANGE
    if x > hi:
        return (f"deeper than {hi:g} m: no caisson breakwater stands there (the deepest, Kamaishi's, "
                "in 63 m)" + _slip(x, 100.0, hi, "m", "centimetres for metres"))
    return f"shallower than {lo:g} m, less than a laboratory model's flume; metres expected"


#: The keys of the tables ``[site]``, ``[wave]`` and ``[caisson]`` (``[lifetime]`` is
#: :mod:`regimemap.lifetime.file`'s).
DESIGN_KEYS: dict[str, dict[str, KeySpec]] = {
    "site": {
        "depth": KeySpec(f"a water depth {DEPTH_RANGE[0]:g} <= h <= {DEPTH_RANGE[1]:g} in metres",
                         lambda x: DEPTH_RANGE[0] <= x <= DEPTH_RANGE[1], why=_depth_why),
        "armour_depth": KeySpec(f"a depth d >= {MIN_LENGTH:g} in metres above the armour layer of the "
                                "mound", lambda x: x >= MIN_LENGTH,
                                why=_beyond(MIN_LENGTH, math.inf, "m", "less than a laboratory model's")),
        "seabed_slope": KeySpec("tan(theta) of the sea bed, 0 <= seabed_slope <= 1",
                             lambda x: 0.0 <= x <= 1.0),
        "water_density": KeySpec("a density 900 <= water_density <= 1100 kg/m^3",
                              lambda x: 900.0 <= x <= 1100.0, required=False),
    },
    "wave": {
        "H0": KeySpec(f"an equivalent deep-water significant height {MIN_LENGTH:g} <= H0 <= "
                      f"{MAX_HEIGHT:g} in metres", _length(MIN_LENGTH, MAX_HEIGHT), required=False,
                      why=_height_why),
        "H13": KeySpec(f"a significant height {MIN_LENGTH:g} <= H13 <= {MAX_HEIGHT:g} in metres at the "
                       "wall", _length(MIN_LENGTH, MAX_HEIGHT), required=False, why=_height_why),
        "Hmax": KeySpec(f"a maximum height H13 <= Hmax <= {2 * MAX_HEIGHT:g} in metres at the wall",
                        _length(MIN_LENGTH, 2 * MAX_HEIGHT), required=False, why=_hmax_why),
        "period": KeySpec(f"a significant period {PERIOD_RANGE[0]:g} <= T1/3 <= {PERIOD_RANGE[1]:g} "
                          "in seconds", lambda x: PERIOD_RANGE[0] <= x <= PERIOD_RANGE[1],
                          why=_period_why),
        "angle": KeySpec("an angle -90 < angle < 90 degrees from the normal to the wall",
                      lambda x: -90.0 < x < 90.0, required=False),
        "rotation": KeySpec("a rotation toward the normal 0 <= rotation <= 15 degrees (Goda 2000)",
                         lambda x: 0.0 <= x <= 15.0, required=False),
    },
    "caisson": {
        "width": KeySpec(f"a full width {WIDTH_RANGE[0]:g} <= width <= {WIDTH_RANGE[1]:g} in metres",
                         _length(*WIDTH_RANGE),
                         why=_beyond(*WIDTH_RANGE, "m", "no caisson (models in a flume to breakwaters "
                                     "are 0.1-100 m wide); metres expected")),
        "base_depth": KeySpec(f"a depth h' >= {MIN_LENGTH:g} in metres of the base below still water",
                              lambda x: x >= MIN_LENGTH,
                              why=_beyond(MIN_LENGTH, math.inf, "m", "less than a laboratory model's")),
        "crest": KeySpec(f"a crest height 0 <= hc <= {MAX_CREST:g} in metres above still water (not below "
                         "the water)", _length(0.0, MAX_CREST),
                         why=_beyond(0.0, MAX_CREST, "m", "no breakwater's crest; metres expected")),
        "berm_width": KeySpec(f"a berm width 0 <= BM <= {MAX_BERM:g} in metres", _length(0.0, MAX_BERM),
                              required=False, why=_beyond(0.0, MAX_BERM, "m", "metres expected")),
        "friction": KeySpec("a friction coefficient 0 < friction <= 2", lambda x: 0.0 < x <= 2.0),
        "buoyant_weight": KeySpec(f"a buoyant weight 0 < W' <= {MAX_WEIGHT:g} in kN per metre",
                                  lambda x: 0.0 < x <= MAX_WEIGHT, required=False,
                                  why=_beyond(0.0, MAX_WEIGHT, "kN/m", "more than forty times a 100 m "
                                              "square block of concrete; kN/m expected")),
        "concrete_fraction": KeySpec("an area fraction 0 <= concrete_fraction <= 1",
                                  lambda x: 0.0 <= x <= 1.0, required=False),
        "concrete_density": KeySpec("a density concrete_density > 0 in kg/m^3", _positive,
                                 required=False),
        "fill_density": KeySpec("a density fill_density > 0 in kg/m^3 (fill below still water)",
                             _positive, required=False),
        "fill_density_above": KeySpec("a density fill_density_above > 0 in kg/m^3", _positive,
                                   required=False),
        "required_sliding": KeySpec("a required sliding safety factor 1 <= required_sliding <= 3 "
                                 "(default 1.2, Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0,
                                 required=False),
        "required_overturning": KeySpec("a required overturning safety factor 1 <= required_overturning "
                                     "<= 3 (default 1.2, Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0,
                                     required=False),
        "impulsive": KeySpec("true or false (Takahashi's impulsive coefficient)", lambda x: True,
                          required=False, boolean=True),
    },
}


class DesignReader:
    """Reads the values of a parsed design file, checked against :data:`DESIGN_KEYS`; every
    error is a :class:`DesignFileError` that names the file, the line of the key (found in
    ``text``, :func:`~regimemap.io.toml_lines.key_line`), the key and what is accepted."""

    def __init__(self, source: str, text: str = "") -> None:
        self.source = source
        self.text = text

    def where(self, section: str | None = None, key: str | None = None) -> str:
        """``source, line N`` of ``[section] key`` (of the table's header without ``key``)."""
        line = None if section is None else key_line(self.text, section, key)
        return self.source if line is None else f"{self.source}, line {line}"

    def fail(self, what: str, section: str | None = None, key: str | None = None) -> DesignFileError:
        return DesignFileError(f"{self.where(section, key)}: {what}")

    def written(self, section: str, key: str, value: object) -> str:
        """``value`` as the file writes it (``10.10``, ``1e300``), else its repr."""
        return key_text(self.text, section, key) or repr(value)

    def key_error(self, section: str, key: str, value: object, why: str) -> DesignFileError:
        accepted = DESIGN_KEYS[section][key].accepted
        return self.fail(f"[{section}] {key} = {self.written(section, key, value)}: {why}; "
                         f"accepted: {accepted}", section, key)

    def check_names(self, data: Mapping[str, Any]) -> None:
        tables = [*DESIGN_KEYS, "lifetime"]
        for section, table in data.items():
            if section not in tables:
                raise self.fail(f"unknown table [{section}]{did_you_mean(section, dict.fromkeys(tables))}; "
                                f"accepted tables: {', '.join(f'[{s}]' for s in tables)}", section)
            if not isinstance(table, dict):
                raise self.fail(f"[{section}] must be a table, found {table!r}", section)
            if section == "lifetime":  # its keys are checked with their lines (_LifetimeReader)
                continue
            keys = DESIGN_KEYS[section]
            for key in table:
                if key not in keys:
                    raise self.fail(f"unknown key [{section}] {key}{did_you_mean(key, keys)}; "
                                    f"accepted keys in [{section}]: {', '.join(keys)}", section, key)
        for section in DESIGN_KEYS:
            if section not in data:
                raise self.fail(f"missing table [{section}]; required keys: "
                                + ", ".join(k for k, v in DESIGN_KEYS[section].items() if v.required))

    def number(self, data: Mapping[str, Any], section: str, key: str) -> float | None:
        spec = DESIGN_KEYS[section][key]
        table = data[section]
        if key not in table:
            if spec.required:
                raise self.fail(f"[{section}] {key} is missing; accepted: {spec.accepted}", section)
            return None
        value = table[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.key_error(section, key, value, f"expected a number, found {type(value).__name__}")
        x = float(value)
        if not math.isfinite(x):
            raise self.key_error(section, key, value, "not a finite number")
        if not spec.check(x):
            raise self.key_error(section, key, value, "out of range" if spec.why is None
                                 else f"out of range, {spec.why(x)}")
        return x

    def required(self, data: Mapping[str, Any], section: str, key: str) -> float:
        x = self.number(data, section, key)
        assert x is not None
        return x

    def boolean(self, data: Mapping[str, Any], section: str, key: str, default: bool) -> bool:
        table = data[section]
        if key not in table:
            return default
        value = table[key]
        if not isinstance(value, bool):
            raise self.key_error(section, key, value, f"expected true or false, found {type(value).__name__}")
        return value
