"""The keys of a design file's ``[site]``, ``[wave]`` and ``[caisson]`` tables and their reader.

:data:`DESIGN_KEYS` says what each key accepts (the words of the error messages, and
of the documentation's table of the keys); :class:`DesignReader` reads a value and checks
it against them.  :func:`regimemap.io.design.parse_design` uses both.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from .design_errors import DesignFileError, did_you_mean

__all__ = ["DESIGN_KEYS", "DesignReader", "KeySpec"]


# -- the accepted keys ----------------------------------------------------------------------------

@dataclass(frozen=True)
class KeySpec:
    """One key of a table: what it accepts in words, its range test, whether it is required."""

    accepted: str                      # what is accepted, in words
    check: Callable[[float], bool]     # range test of a number
    required: bool = True
    boolean: bool = False


def _positive(x: float) -> bool:
    return x > 0.0


#: The keys of the tables ``[site]``, ``[wave]`` and ``[caisson]`` (``[lifetime]`` is
#: :mod:`regimemap.io.design_lifetime`'s).
DESIGN_KEYS: dict[str, dict[str, KeySpec]] = {
    "site": {
        "depth": KeySpec("a water depth h > 0 in metres", _positive),
        "armour_depth": KeySpec("a depth d > 0 in metres above the armour layer of the mound", _positive),
        "seabed_slope": KeySpec("tan(theta) of the sea bed, 0 <= seabed_slope <= 1",
                             lambda x: 0.0 <= x <= 1.0),
        "water_density": KeySpec("a density 900 <= water_density <= 1100 kg/m^3",
                              lambda x: 900.0 <= x <= 1100.0, required=False),
    },
    "wave": {
        "H0": KeySpec("an equivalent deep-water significant height H0 > 0 in metres", _positive,
                   required=False),
        "H13": KeySpec("a significant height H13 > 0 in metres at the wall", _positive, required=False),
        "Hmax": KeySpec("a maximum height Hmax >= H13 in metres at the wall", _positive, required=False),
        "period": KeySpec("a significant period T1/3 > 0 in seconds", _positive),
        "angle": KeySpec("an angle -90 < angle < 90 degrees from the normal to the wall",
                      lambda x: -90.0 < x < 90.0, required=False),
        "rotation": KeySpec("a rotation toward the normal 0 <= rotation <= 15 degrees (Goda 2000)",
                         lambda x: 0.0 <= x <= 15.0, required=False),
    },
    "caisson": {
        "width": KeySpec("a full width > 0 in metres", _positive),
        "base_depth": KeySpec("a depth h' > 0 in metres of the base below still water", _positive),
        "crest": KeySpec("a crest height hc >= 0 in metres above still water (not below the water)",
                      lambda x: x >= 0.0),
        "berm_width": KeySpec("a berm width BM >= 0 in metres", lambda x: x >= 0.0, required=False),
        "friction": KeySpec("a friction coefficient 0 < friction <= 2", lambda x: 0.0 < x <= 2.0),
        "buoyant_weight": KeySpec("a buoyant weight W' > 0 in kN per metre", _positive, required=False),
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
    error is a :class:`DesignFileError` that names the file, the key and what is accepted."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, what: str) -> DesignFileError:
        return DesignFileError(f"{self.source}: {what}")

    def key_error(self, section: str, key: str, value: object, why: str) -> DesignFileError:
        accepted = DESIGN_KEYS[section][key].accepted
        return self.fail(f"[{section}] {key} = {value!r}: {why}; accepted: {accepted}")

    def check_names(self, data: Mapping[str, Any]) -> None:
        tables = [*DESIGN_KEYS, "lifetime"]
        for section, table in data.items():
            if section not in tables:
                raise self.fail(f"unknown table [{section}]{did_you_mean(section, dict.fromkeys(tables))}; "
                                f"accepted tables: {', '.join(f'[{s}]' for s in tables)}")
            if not isinstance(table, dict):
                raise self.fail(f"[{section}] must be a table, found {table!r}")
            if section == "lifetime":  # its keys are checked with their lines (_LifetimeReader)
                continue
            keys = DESIGN_KEYS[section]
            for key in table:
                if key not in keys:
                    raise self.fail(f"unknown key [{section}] {key}{did_you_mean(key, keys)}; "
                                    f"accepted keys in [{section}]: {', '.join(keys)}")
        for section in DESIGN_KEYS:
            if section not in data:
                raise self.fail(f"missing table [{section}]; required keys: "
                                + ", ".join(k for k, v in DESIGN_KEYS[section].items() if v.required))

    def number(self, data: Mapping[str, Any], section: str, key: str) -> float | None:
        spec = DESIGN_KEYS[section][key]
        table = data[section]
        if key not in table:
            if spec.required:
                raise self.fail(f"[{section}] {key} is missing; accepted: {spec.accepted}")
            return None
        value = table[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.key_error(section, key, value, f"expected a number, found {type(value).__name__}")
        x = float(value)
        if not math.isfinite(x):
            raise self.key_error(section, key, value, "not a finite number")
        if not spec.check(x):
            raise self.key_error(section, key, value, "out of range")
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
