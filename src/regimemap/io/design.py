"""Reader of the TOML design file of a caisson breakwater (site, design wave, caisson, life).

The file has three tables, and an optional fourth, in SI units (metres,
seconds, degrees, kg/m^3; weights in kN per metre of breakwater)::

    [site]      depth, armour_depth, seabed_slope, water_density (optional)
    [wave]      H0 -- or H13 and Hmax --, period, angle (optional),
                rotation (optional)
    [caisson]   width, base_depth, crest, berm_width (optional), friction,
                buoyant_weight -- or concrete_fraction, concrete_density,
                fill_density, fill_density_above (optional) --,
                impulsive (optional)
    [lifetime]  (optional; ``regimemap lifetime``) the climate -- H0_10 and
                H0_50, or annual_maxima --, distribution, shape,
                storms_per_year; years, trials, seed, storm_hours, period or
                steepness, tide_range, thresholds, truncate, impulsive; and
                [lifetime.errors] deepwater, transformation, force, friction,
                each [ratio, cov] -- every key but the climate optional

:func:`example_design_text` returns a commented example (Goda's worked
upright breakwater, with a life of 50 years). Every error in a file raises
:class:`DesignFileError`, whose message names the file, the key with its
table (``[caisson] base_depth``), the value found and what is accepted; for
``[lifetime]`` and ``[lifetime.errors]`` also the line of the key
(``goda.toml, line 45: [lifetime] shape = -1.0: out of range; ...``).  A
parsed file is a :class:`Design`; :meth:`Design.analysis_inputs` gives the
inputs of Goda's procedure, :meth:`Design.lifetime_caisson` and
:meth:`Design.lifetime_model` those of
:func:`regimemap.lifetime.lifetime_sliding`.
"""

from __future__ import annotations

import difflib
import math
import re
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel
    from regimemap.waves import CaissonAnalysis

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "MAX_TRIALS", "MAX_YEARS", "CaissonSpec", "Design",
           "DesignFileError", "LifetimeSpec", "SiteSpec", "WaveSpec", "check_lifetime_option",
           "example_design_text", "key_line", "parse_design", "read_design"]

#: Most lifetimes a run may simulate (its arrays take ~24 bytes a lifetime).
MAX_TRIALS = 10_000_000
#: Longest design life [years].
MAX_YEARS = 1000


class DesignFileError(ValueError):
    """A design file that cannot be read, parsed or accepted."""


@dataclass(frozen=True)
class SiteSpec:
    """``[site]``: depth ``h``, armour depth ``d`` [m], ``tan theta``, water density [kg/m^3]."""

    depth: float
    armour_depth: float
    seabed_slope: float
    water_density: float = 1030.0


@dataclass(frozen=True)
class WaveSpec:
    """``[wave]``: ``H0'`` or (``H1/3``, ``Hmax``) [m], ``T1/3`` [s], angle and rotation [deg]."""

    period: float
    H0: float | None = None
    H13: float | None = None
    Hmax: float | None = None
    angle: float = 0.0
    rotation: float = 0.0


@dataclass(frozen=True)
class CaissonSpec:
    """``[caisson]``: geometry [m], friction, and ``W'`` [kN/m] or densities [kg/m^3]."""

    width: float
    base_depth: float
    crest: float
    friction: float
    berm_width: float = 0.0
    buoyant_weight: float | None = None
    concrete_fraction: float | None = None
    concrete_density: float | None = None
    fill_density: float | None = None
    fill_density_above: float | None = None
    impulsive: bool = True


@dataclass(frozen=True)
class LifetimeSpec:
    """``[lifetime]``: the climate and the options of a lifetime simulation, as the file gives them.

    The climate is ``H0_10`` and ``H0_50`` [m], or ``annual_maxima`` [m];
    ``errors`` holds the factors ``[lifetime.errors]`` names, as ``(ratio,
    cov)``: the others take :data:`regimemap.lifetime.DEFAULT_ERRORS`.
    ``thresholds`` None means :data:`regimemap.lifetime.DEFAULT_THRESHOLDS`,
    ``seed`` None a fresh seed for every run.
    """

    years: int = 50
    trials: int = 5000
    seed: int | None = None
    distribution: str = "weibull"
    shape: float = 2.0
    H0_10: float | None = None
    H0_50: float | None = None
    annual_maxima: tuple[float, ...] | None = None
    storms_per_year: float | None = None
    storm_hours: float = 2.0
    period: float | None = None
    steepness: float | None = None
    tide_range: float = 0.0
    thresholds: tuple[float, ...] | None = None
    truncate: float | None = None
    impulsive: bool = False
    errors: Mapping[str, tuple[float, float]] = field(default_factory=dict)


@dataclass(frozen=True)
class Design:
    """A parsed and checked design file."""

    site: SiteSpec
    wave: WaveSpec
    caisson: CaissonSpec
    source: str
    lifetime: LifetimeSpec | None = None

    def analysis_inputs(self, g: float = 9.81) -> dict[str, Any]:
        """The keyword arguments of :func:`regimemap.waves.analyse_caisson` for this design (SI: N, Pa)."""
        from regimemap.waves import Densities

        c = self.caisson
        densities = None
        weight = None
        if c.buoyant_weight is not None:
            weight = c.buoyant_weight * 1e3
        else:
            assert c.concrete_fraction is not None and c.concrete_density is not None
            assert c.fill_density is not None
            densities = Densities(c.concrete_fraction, c.concrete_density, c.fill_density,
                                  c.fill_density_above)
        return dict(
            depth=self.site.depth, armour_depth=self.site.armour_depth, slope=self.site.seabed_slope,
            period=self.wave.period, H0=self.wave.H0, H13=self.wave.H13, Hmax=self.wave.Hmax,
            angle_deg=self.wave.angle, rotation_deg=self.wave.rotation, width=c.width,
            base_depth=c.base_depth, crest=c.crest, berm_width=c.berm_width, friction=c.friction,
            buoyant_weight=weight, densities=densities, impulsive=c.impulsive,
            rho_w=self.site.water_density, g=g)

    def analyse(self, g: float = 9.81) -> CaissonAnalysis:
        """Run :func:`regimemap.waves.analyse_caisson` on this design (SI: N, Pa)."""
        from regimemap.waves import analyse_caisson

        return analyse_caisson(**self.analysis_inputs(g))

    def lifetime_caisson(self, g: float = 9.81) -> Caisson:
        """The caisson at its site for :mod:`regimemap.lifetime` (SI: ``W'`` in N/m).

        The section, the friction, the site (depths, slope, water density) and
        the wave's angle and rotation of the file; the design wave's heights and
        period are not used (the storms come from ``[lifetime]``'s climate).
        """
        from regimemap.lifetime import Caisson

        a = self.analysis_inputs(g)
        return Caisson(depth=a["depth"], armour_depth=a["armour_depth"], slope=a["slope"],
                       width=a["width"], base_depth=a["base_depth"], crest=a["crest"],
                       friction=a["friction"], buoyant_weight=a["buoyant_weight"],
                       densities=a["densities"], berm_width=a["berm_width"], angle_deg=a["angle_deg"],
                       rotation_deg=a["rotation_deg"], rho_w=a["rho_w"], g=g)

    def lifetime_spec(self) -> LifetimeSpec:
        """The ``[lifetime]`` table; :class:`DesignFileError` if the file has none."""
        if self.lifetime is None:
            raise DesignFileError(
                f"{self.source}: no [lifetime] table (the wave climate and the options of the "
                "lifetime simulation); `regimemap caisson --example` prints a design file with one")
        return self.lifetime

    def lifetime_model(self, years: int | None = None) -> LifetimeModel:
        """The climate and options of ``[lifetime]`` as a :class:`regimemap.lifetime.LifetimeModel`.

        Parameters
        ----------
        years : int, optional
            Design life instead of the file's ``years`` (checked as the file's).

        Raises
        ------
        DesignFileError
            If the file has no ``[lifetime]`` table.
        ValueError
            If ``years`` is out of range.
        """
        spec = self.lifetime_spec()
        if years is not None:
            years = check_lifetime_option("years", years)
        return _lifetime_model(spec, years)


# -- the accepted keys ----------------------------------------------------------------------------

@dataclass(frozen=True)
class _Key:
    accepted: str                      # what is accepted, in words
    check: Callable[[float], bool]     # range test of a number
    required: bool = True
    boolean: bool = False


def _positive(x: float) -> bool:
    return x > 0.0


_SPEC: dict[str, dict[str, _Key]] = {
    "site": {
        "depth": _Key("a water depth h > 0 in metres", _positive),
        "armour_depth": _Key("a depth d > 0 in metres above the armour layer of the mound", _positive),
        "seabed_slope": _Key("tan(theta) of the sea bed, 0 <= seabed_slope <= 1",
                             lambda x: 0.0 <= x <= 1.0),
        "water_density": _Key("a density 900 <= water_density <= 1100 kg/m^3",
                              lambda x: 900.0 <= x <= 1100.0, required=False),
    },
    "wave": {
        "H0": _Key("an equivalent deep-water significant height H0 > 0 in metres", _positive,
                   required=False),
        "H13": _Key("a significant height H13 > 0 in metres at the wall", _positive, required=False),
        "Hmax": _Key("a maximum height Hmax >= H13 in metres at the wall", _positive, required=False),
        "period": _Key("a significant period T1/3 > 0 in seconds", _positive),
        "angle": _Key("an angle -90 < angle < 90 degrees from the normal to the wall",
                      lambda x: -90.0 < x < 90.0, required=False),
        "rotation": _Key("a rotation toward the normal 0 <= rotation <= 15 degrees (Goda 2000)",
                         lambda x: 0.0 <= x <= 15.0, required=False),
    },
    "caisson": {
        "width": _Key("a full width > 0 in metres", _positive),
        "base_depth": _Key("a depth h' > 0 in metres of the base below still water", _positive),
        "crest": _Key("a crest height hc >= 0 in metres above still water (not below the water)",
                      lambda x: x >= 0.0),
        "berm_width": _Key("a berm width BM >= 0 in metres", lambda x: x >= 0.0, required=False),
        "friction": _Key("a friction coefficient 0 < friction <= 2", lambda x: 0.0 < x <= 2.0),
        "buoyant_weight": _Key("a buoyant weight W' > 0 in kN per metre", _positive, required=False),
        "concrete_fraction": _Key("an area fraction 0 <= concrete_fraction <= 1",
                                  lambda x: 0.0 <= x <= 1.0, required=False),
        "concrete_density": _Key("a density concrete_density > 0 in kg/m^3", _positive,
                                 required=False),
        "fill_density": _Key("a density fill_density > 0 in kg/m^3 (fill below still water)",
                             _positive, required=False),
        "fill_density_above": _Key("a density fill_density_above > 0 in kg/m^3", _positive,
                                   required=False),
        "impulsive": _Key("true or false (Takahashi's impulsive coefficient)", lambda x: True,
                          required=False, boolean=True),
    },
}


class _Reader:
    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, what: str) -> DesignFileError:
        return DesignFileError(f"{self.source}: {what}")

    def key_error(self, section: str, key: str, value: object, why: str) -> DesignFileError:
        accepted = _SPEC[section][key].accepted
        return self.fail(f"[{section}] {key} = {value!r}: {why}; accepted: {accepted}")

    def check_names(self, data: Mapping[str, Any]) -> None:
        tables = [*_SPEC, "lifetime"]
        for section, table in data.items():
            if section not in tables:
                raise self.fail(f"unknown table [{section}]{_did_you_mean(section, dict.fromkeys(tables))}; "
                                f"accepted tables: {', '.join(f'[{s}]' for s in tables)}")
            if not isinstance(table, dict):
                raise self.fail(f"[{section}] must be a table, found {table!r}")
            if section == "lifetime":  # its keys are checked with their lines (_LifetimeReader)
                continue
            for key in table:
                if key not in _SPEC[section]:
                    raise self.fail(f"unknown key [{section}] {key}{_did_you_mean(key, _SPEC[section])}; "
                                    f"accepted keys in [{section}]: {', '.join(_SPEC[section])}")
        for section in _SPEC:
            if section not in data:
                raise self.fail(f"missing table [{section}]; required keys: "
                                + ", ".join(k for k, v in _SPEC[section].items() if v.required))

    def number(self, data: Mapping[str, Any], section: str, key: str) -> float | None:
        spec = _SPEC[section][key]
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


def _did_you_mean(name: str, known: Mapping[str, object]) -> str:
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
    if not close:
        close = [k for k in known if k.lower() == name.lower()]
    return f" (did you mean {close[0]!r}?)" if close else ""


# -- [lifetime]: the climate and the options of the lifetime simulation ---------------------------

@dataclass(frozen=True)
class _LKey:
    accepted: str                      # what is accepted, in words
    kind: str                          # "int", "number", "text", "bool", "numbers", "pair", "table"
    check: Callable[[Any], bool] = lambda x: True


def _at_least(lo: float) -> Callable[[Any], bool]:
    return lambda x: x >= lo


#: The keys of ``[lifetime]``, in the order the messages list them.
LIFETIME_KEYS: dict[str, _LKey] = {
    "years": _LKey(f"a design life in whole years, 1 <= years <= {MAX_YEARS} (default 50)", "int",
                   lambda x: 1 <= x <= MAX_YEARS),
    "trials": _LKey(f"a number of simulated lifetimes, 1 <= trials <= {MAX_TRIALS} (default 5000)",
                    "int", lambda x: 1 <= x <= MAX_TRIALS),
    "seed": _LKey("a whole number >= 0, the root seed of the random numbers (default: a fresh one, "
                  "reported)", "int", _at_least(0)),
    "distribution": _LKey('"weibull" or "gumbel", the distribution of the storm peaks H0\' '
                          '(default "weibull")', "text", lambda x: x in ("weibull", "gumbel")),
    "shape": _LKey("a Weibull shape k > 0 (default 2; fitting annual_maxima needs k > 1)", "number",
                   _positive),
    "H0_10": _LKey("the 10-year return value of H0', > 0 in metres", "number", _positive),
    "H0_50": _LKey("the 50-year return value of H0' in metres, H0_50 > H0_10", "number", _positive),
    "annual_maxima": _LKey("a list of at least three annual maxima of H0', each > 0 in metres and not "
                           "all equal (instead of H0_10 and H0_50)", "numbers", _positive),
    "storms_per_year": _LKey("a mean number of storms a year, storms_per_year > 0.1 (a Poisson number "
                             "of storms, peaks over a threshold; not with annual_maxima; default: one "
                             "storm a year, its peak the annual maximum)", "number", lambda x: x > 0.1),
    "storm_hours": _LKey("a duration > 0 in hours of each storm's peak sea state (default 2)", "number",
                         _positive),
    "period": _LKey("a significant period T1/3 > 0 in seconds for every storm (default: Goda's "
                    "3.3 H0'^0.63); not with steepness", "number", _positive),
    "steepness": _LKey("a deep-water steepness 0 < H0'/L0 <= 0.142 for every storm; not with period",
                       "number", lambda x: 0.0 < x <= 0.142),
    "tide_range": _LKey("a tidal range >= 0 in metres (default 0)", "number", _at_least(0.0)),
    "thresholds": _LKey("a list of lifetime slides, each > 0 in metres, whose exceedance probability "
                        "is reported (default [0.03, 0.1, 0.3, 1, 3])", "numbers", _positive),
    "truncate": _LKey("a cut-off > 0 of the normal error factors, in standard deviations (default: "
                      "none)", "number", _positive),
    "impulsive": _LKey("true or false: Takahashi's impulsive coefficient in each wave's force "
                       "(default false)", "bool"),
    "errors": _LKey("the table [lifetime.errors] of the uncertainty factors (deepwater, "
                    "transformation, force, friction)", "table"),
}

_PAIR = "a pair [ratio, cov] with ratio > 0 and cov >= 0, the factor ratio (1 + cov z) "
_DEFAULT = "; absent: its default in regimemap.lifetime.DEFAULT_ERRORS"
#: The keys of ``[lifetime.errors]`` (the factors of :class:`regimemap.lifetime.Errors`).
ERROR_FACTORS: dict[str, _LKey] = {
    "deepwater": _LKey(_PAIR + "on the storm's H0' (once per lifetime)" + _DEFAULT, "pair"),
    "transformation": _LKey(_PAIR + "on H1/3 at the wall (once per storm)" + _DEFAULT, "pair"),
    "force": _LKey(_PAIR + "on the wave force P and the uplift U (once per storm)" + _DEFAULT, "pair"),
    "friction": _LKey(_PAIR + "on the friction coefficient (once per storm)" + _DEFAULT, "pair"),
}

_TABLE_KEYS = {"lifetime": LIFETIME_KEYS, "lifetime.errors": ERROR_FACTORS}
_CLIMATE = ("either H0_10 and H0_50 (the 10- and 50-year return values of H0', metres) or "
            "annual_maxima (a list of annual maxima of H0', metres)")


def check_lifetime_option(name: str, value: Any) -> Any:
    """One value of ``[lifetime]`` (``years``, ``trials``, ``seed`` ...), checked as the file's.

    Text (from the command line) is read as the key's kind: a whole number
    for ``years``, ``trials`` and ``seed``, a number for the others.

    Returns
    -------
    int or float
        The value.

    Raises
    ------
    ValueError
        ``"trials must be a number of simulated lifetimes, 1 <= trials <= ..., got '0'"``.
    """
    spec = LIFETIME_KEYS[name]
    if spec.kind not in ("int", "number"):
        raise ValueError(f"{name} is not a single number")
    got = value
    if isinstance(value, str):
        try:
            value = int(value.strip(), 10) if spec.kind == "int" else float(value.strip())
        except ValueError:
            kind = "a whole number" if spec.kind == "int" else "a number"
            raise ValueError(f"{name} must be {spec.accepted}, got {got!r} (not {kind})") from None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
            spec.kind == "int" and not isinstance(value, int)):
        raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    if spec.kind == "number":
        value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    if not spec.check(value):
        raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    return value


_BARE_KEY = r"(?:[A-Za-z0-9_-]+|\"(?:[^\"\\]|\\.)*\"|'[^']*')"
_DOTTED = re.compile(rf"\s*({_BARE_KEY}(?:\s*\.\s*{_BARE_KEY})*)\s*")
_HEADER = re.compile(rf"^\s*\[\[?{_DOTTED.pattern}\]\]?")
_ASSIGN = re.compile(rf"^{_DOTTED.pattern}=")


def _key_path(dotted: str) -> tuple[str, ...]:
    parts = re.findall(_BARE_KEY, dotted)
    return tuple(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def key_line(text: str, table: str, key: str | None = None) -> int | None:
    """The line (from 1) where ``key`` of ``table`` (``"lifetime.errors"``) is set in TOML ``text``.

    tomllib gives no positions, so the text is scanned: table headers
    (``[lifetime.errors]``), keys (``shape = 3``) and dotted keys
    (``errors.force = [0.9, 0.1]`` under ``[lifetime]``).  A key set inside an
    inline table gives the line of that table; with ``key`` None, or a key not
    found, the line of the table's header (None if there is none).  Lines in
    multi-line strings are not told apart from keys.
    """
    want = (*_key_path(table), *(() if key is None else (key,)))
    head = _key_path(table)
    current: tuple[str, ...] = ()
    inline = header = None
    for n, line in enumerate(text.splitlines(), start=1):
        m = _HEADER.match(line)
        if m:
            current = _key_path(m.group(1))
            if current == want:  # [lifetime.errors] for the key "errors" of [lifetime]
                return n
            if current == head and header is None:
                header = n
            continue
        m = _ASSIGN.match(line)
        if not m:
            continue
        path = current + _key_path(m.group(1))
        if path == want:
            return n
        if inline is None and key is not None and want[:len(path)] == path:
            inline = n  # the key sits in an inline table, or in the table set by this dotted key
        if header is None and path[:len(head)] == head and len(path) > len(head):
            header = n  # a table made of dotted keys (lifetime.years = 50)
    return inline if inline is not None else header


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
        accepted = _TABLE_KEYS[table][key].accepted
        return self.fail(table, key, f"[{table}] {key} = {value!r}: {why}; accepted: {accepted}")

    def check_names(self, table: str, data: Mapping[str, Any]) -> None:
        known = _TABLE_KEYS[table]
        for key in data:
            if key not in known:
                raise self.fail(table, key, f"unknown key [{table}] {key}{_did_you_mean(key, known)}; "
                                f"accepted keys in [{table}]: {', '.join(known)}")

    def number(self, table: str, data: Mapping[str, Any], key: str, value: Any,
               item: bool = False) -> float:
        """``value`` (``data[key]``, or an item of that list) checked as a number of ``key``."""
        spec = _TABLE_KEYS[table][key]
        which = f"{value!r} in the list is " if item else ""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            found = f"{which}{_toml_type(value)}" if item else _toml_type(value)
            raise self.bad(table, key, data[key], f"expected {'numbers' if item else 'a number'}, "
                           f"found {found}")
        x = float(value)
        if not math.isfinite(x):
            raise self.bad(table, key, data[key], f"{which}not a finite number")
        if not spec.check(x):
            raise self.bad(table, key, data[key], f"{which}out of range")
        return x

    def value(self, table: str, data: Mapping[str, Any], key: str) -> Any:
        """The checked value of ``key`` (None when absent)."""
        if key not in data:
            return None
        spec = _TABLE_KEYS[table][key]
        v = data[key]
        if spec.kind == "int":
            if isinstance(v, bool) or not isinstance(v, int):
                raise self.bad(table, key, v, f"expected a whole number, found {_toml_type(v)}")
            if not spec.check(v):
                raise self.bad(table, key, v, "out of range")
            return v
        if spec.kind == "number":
            return self.number(table, data, key, v)
        if spec.kind == "text":
            if not isinstance(v, str):
                raise self.bad(table, key, v, f"expected a string, found {_toml_type(v)}")
            if not spec.check(v):
                raise self.bad(table, key, v, "not one of the accepted values")
            return v
        if spec.kind == "bool":
            if not isinstance(v, bool):
                raise self.bad(table, key, v, f"expected true or false, found {_toml_type(v)}")
            return v
        if spec.kind == "numbers":
            if not isinstance(v, list):
                raise self.bad(table, key, v, f"expected a list of numbers, found {_toml_type(v)}")
            if not v:
                raise self.bad(table, key, v, "the list is empty")
            return tuple(self.number(table, data, key, x, item=True) for x in v)
        if spec.kind == "pair":
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
        if not isinstance(v, dict):  # "table"
            raise self.bad(table, key, v, f"expected a table, found {_toml_type(v)}")
        return v

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
        if got["period"] is not None and got["steepness"] is not None:
            raise self.fail(t, "steepness", f"[lifetime] steepness = {data['steepness']!r} together with "
                            f"[lifetime] period = {data['period']!r}; accepted: one of them, or neither "
                            "(Goda's T1/3 = 3.3 H0'^0.63)")
        spec = LifetimeSpec(
            years=50 if got["years"] is None else got["years"],
            trials=5000 if got["trials"] is None else got["trials"],
            seed=got["seed"], distribution=got["distribution"] or "weibull",
            shape=2.0 if got["shape"] is None else got["shape"],
            H0_10=h10, H0_50=h50, annual_maxima=maxima, storms_per_year=got["storms_per_year"],
            storm_hours=2.0 if got["storm_hours"] is None else got["storm_hours"],
            period=got["period"], steepness=got["steepness"],
            tide_range=0.0 if got["tide_range"] is None else got["tide_range"],
            thresholds=None if got["thresholds"] is None else tuple(sorted(set(got["thresholds"]))),
            truncate=got["truncate"], impulsive=bool(got["impulsive"]), errors=errors)
        try:  # anything the checks above missed, said the library's way
            _lifetime_model(spec)
        except ValueError as exc:
            raise self.fail(t, None, f"[lifetime]: {exc}") from None
        return spec


def _toml_type(v: Any) -> str:
    """The TOML name of a parsed value's type, for the messages."""
    names = {bool: "a boolean", int: "an integer", float: "a float", str: "a string", list: "an array",
             dict: "a table"}
    return names.get(type(v), type(v).__name__)


def _lifetime_model(spec: LifetimeSpec, years: int | None = None) -> LifetimeModel:
    from regimemap.lifetime import DEFAULT_ERRORS, DEFAULT_THRESHOLDS, Climate, ErrorFactor, LifetimeModel

    if spec.annual_maxima is not None:
        climate = Climate.fit_annual_maxima(spec.annual_maxima, spec.distribution, spec.shape)
    else:
        assert spec.H0_10 is not None and spec.H0_50 is not None
        climate = Climate.from_return_values(spec.H0_10, spec.H0_50, spec.distribution, spec.shape,
                                             spec.storms_per_year)
    errors = replace(DEFAULT_ERRORS, **{name: ErrorFactor(*pair) for name, pair in spec.errors.items()})
    return LifetimeModel(climate, years=spec.years if years is None else years,
                         storm_hours=spec.storm_hours, period=spec.period, steepness=spec.steepness,
                         tide_range=spec.tide_range, impulsive=spec.impulsive, truncate=spec.truncate,
                         errors=errors,
                         thresholds=DEFAULT_THRESHOLDS if spec.thresholds is None else spec.thresholds)


def parse_design(text: str, source: str = "<design>") -> Design:
    """Parse and check the text of a design file.

    Parameters
    ----------
    text : str
        TOML text.
    source : str, optional
        Name of the file, for the error messages.

    Returns
    -------
    Design

    Raises
    ------
    DesignFileError
        On a TOML syntax error (with its line number), an unknown table or key
        (with the closest known one), a missing key, a value of the wrong
        type or out of range, or inconsistent values; in ``[lifetime]`` also
        a missing or doubly given climate, and the message gives the line of
        the key (:func:`key_line`).
    """
    r = _Reader(source)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\s*\(at line (\d+), column (\d+)\)", msg)
        where = ""
        if m:
            where = f" at line {m.group(1)}, column {m.group(2)}"
            msg = msg[:m.start()] + msg[m.end():]
        raise r.fail(f"TOML syntax error{where}: {msg}") from None
    r.check_names(data)

    site = SiteSpec(depth=r.required(data, "site", "depth"),
                    armour_depth=r.required(data, "site", "armour_depth"),
                    seabed_slope=r.required(data, "site", "seabed_slope"),
                    water_density=r.number(data, "site", "water_density") or 1030.0)

    H0 = r.number(data, "wave", "H0")
    H13 = r.number(data, "wave", "H13")
    Hmax = r.number(data, "wave", "Hmax")
    if H0 is not None and (H13 is not None or Hmax is not None):
        raise r.fail(f"[wave] H0 = {H0!r} together with [wave] H13/Hmax; accepted: either H0 "
                     "(equivalent deep-water height) or both H13 and Hmax (heights at the wall)")
    if H0 is None:
        if H13 is None or Hmax is None:
            missing = "H13" if H13 is None and Hmax is not None else (
                "Hmax" if Hmax is None and H13 is not None else "H0")
            raise r.fail(f"[wave] {missing} is missing; accepted: either H0 (equivalent deep-water "
                         "height, m) or both H13 and Hmax (heights at the wall, m)")
        if Hmax < H13:
            raise r.key_error("wave", "Hmax", Hmax, f"smaller than [wave] H13 = {H13!r}")
    wave = WaveSpec(period=r.required(data, "wave", "period"), H0=H0, H13=H13, Hmax=Hmax,
                    angle=r.number(data, "wave", "angle") or 0.0,
                    rotation=r.number(data, "wave", "rotation") or 0.0)

    c = "caisson"
    weight = r.number(data, c, "buoyant_weight")
    dens = {k: r.number(data, c, k) for k in ("concrete_fraction", "concrete_density", "fill_density")}
    above = r.number(data, c, "fill_density_above")
    given = [k for k, v in dens.items() if v is not None]
    if weight is not None and (given or above is not None):
        raise r.fail(f"[caisson] buoyant_weight = {weight!r} together with densities "
                     f"({', '.join(given or ['fill_density_above'])}); accepted: either buoyant_weight "
                     "(kN/m) or concrete_fraction, concrete_density and fill_density")
    if weight is None and len(given) < 3:
        absent = [k for k, v in dens.items() if v is None]
        raise r.fail(f"[caisson] {' and '.join(absent)} missing; accepted: either buoyant_weight "
                     "(kN/m) or all of concrete_fraction, concrete_density, fill_density (kg/m^3)")
    caisson = CaissonSpec(width=r.required(data, c, "width"),
                          base_depth=r.required(data, c, "base_depth"),
                          crest=r.required(data, c, "crest"),
                          friction=r.required(data, c, "friction"),
                          berm_width=r.number(data, c, "berm_width") or 0.0,
                          buoyant_weight=weight, concrete_fraction=dens["concrete_fraction"],
                          concrete_density=dens["concrete_density"], fill_density=dens["fill_density"],
                          fill_density_above=above,
                          impulsive=r.boolean(data, c, "impulsive", True))

    if caisson.base_depth > site.depth:
        raise r.fail(f"[caisson] base_depth = {caisson.base_depth!r}: the base of the caisson would be "
                     f"deeper than the water ([site] depth = {site.depth!r}); accepted: "
                     f"0 < base_depth <= [site] depth = {site.depth!r} (metres)")
    if site.armour_depth > caisson.base_depth:
        raise r.fail(f"[site] armour_depth = {site.armour_depth!r}: the top of the armour layer would be "
                     f"below the base of the caisson ([caisson] base_depth = {caisson.base_depth!r}); "
                     f"accepted: 0 < armour_depth <= [caisson] base_depth = {caisson.base_depth!r} (metres)")
    lifetime = _LifetimeReader(text, source).read(data["lifetime"]) if "lifetime" in data else None
    return Design(site=site, wave=wave, caisson=caisson, source=source, lifetime=lifetime)


def read_design(path: str | Path) -> Design:
    """Read and check a design file.

    Parameters
    ----------
    path : str or Path
        The TOML file.

    Returns
    -------
    Design

    Raises
    ------
    DesignFileError
        See :func:`parse_design`; also when the file cannot be read.
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise DesignFileError(f"{p}: cannot read the design file: {exc}") from None
    return parse_design(text, source=str(p))


_EXAMPLE = """\
# regimemap design file: Goda's worked upright breakwater
# (Goda 2000, Random Seas and Design of Maritime Structures, Sect. 4.2).
# SI units: metres, seconds, degrees, kg/m^3; weights in kN per metre of breakwater.
# Expected: H1/3 = 5.80 m, Hmax = 8.05 m, p1 = 97.6 kPa, P = 941 kN/m,
#           U = 493 kN/m, SF sliding = 1.16, SF overturning = 2.56.

[site]
depth = 10.1          # h, water depth at the wall
armour_depth = 5.6    # d, depth above the armour layer of the mound
seabed_slope = 0.01   # tan(theta) of the sea bed in front (1/100)
water_density = 1030  # optional, default 1030

[wave]
H0 = 6.3              # equivalent deep-water significant height H0'
                      # (or give H13 and Hmax at the wall instead)
period = 11.4         # T1/3, significant period
angle = 15            # beta, degrees from the normal to the wall
rotation = 0          # optional: rotate beta toward the normal by up to 15 degrees
                      # (Goda's recommendation for uncertain directions); default 0

[caisson]
width = 15.0          # full width of the upright section
base_depth = 7.1      # h', depth of its base below still water
crest = 3.4           # hc, crest height above still water
berm_width = 8.0      # BM, berm width (Takahashi's impulsive coefficient)
friction = 0.6        # mu, caisson on rubble
buoyant_weight = 2312 # W', weight in still water, kN/m
# or, instead of buoyant_weight, the densities of a filled caisson:
# concrete_fraction = 0.25   # area fraction of concrete in the section
# concrete_density = 2400    # kg/m^3
# fill_density = 2000        # saturated fill below still water, kg/m^3
# fill_density_above = 1800  # optional: fill above still water, kg/m^3
# impulsive = true           # optional: Takahashi's impulsive coefficient (default true)

# Optional: the sliding of the caisson over its design life (`regimemap lifetime`), the
# expected sliding distance (ESD) of Shimosako & Takahashi (1999) by Monte Carlo: storms
# from the climate below, Rayleigh waves in each, the slide of every wave (docs/lifetime.md).
# The caisson, its site and the wave's angle are those above; the storms replace the design
# wave. Only the climate is required: H0_10 and H0_50, or annual_maxima.
[lifetime]
years = 50                # design life, years
trials = 5000             # lifetimes simulated (the ESD's standard error falls as 1/sqrt(trials))
seed = 2026               # root seed: the same seed, the same numbers (omit: a fresh seed, reported)
distribution = "weibull"  # storm peaks H0': "weibull" or "gumbel"
shape = 2.0               # Weibull shape k (> 0)
H0_10 = 5.0               # 10-year return value of H0', m
H0_50 = 6.3               # 50-year return value of H0', m (the design wave above)
# annual_maxima = [4.1, 3.6, 5.2, 4.4, 3.9]  # instead of H0_10 and H0_50: observed annual
                          # maxima of H0', m (at least three; Weibull needs shape > 1)
# storms_per_year = 4     # a Poisson number of storms a year (peaks over a threshold;
                          # not with annual_maxima); default: one storm a year, the annual maximum
storm_hours = 2.0         # duration of each storm's peak sea state, hours
# period = 11.4           # a fixed T1/3 for every storm, s (default: Goda's 3.3 H0'^0.63)
# steepness = 0.035       # or a fixed deep-water steepness H0'/L0 (not with period)
tide_range = 0.0          # tidal range, m: each storm's water level is (range/2) sin(2 pi phase)
thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]  # lifetime slides whose exceedance is reported, m
# truncate = 3.0          # cut the normal error factors at +-3 standard deviations (default: none)
impulsive = false         # Takahashi's impulsive coefficient in each wave's force (default false)

# The uncertainty factors, each ratio (1 + cov z) with z standard normal: [ratio, cov] (the
# mean factor and its coefficient of variation; Takayama & Ikeda 1992 as cited by Shimosako &
# Takahashi 1999, docs/lifetime.md, Sect. 7). A factor left out takes this default.
[lifetime.errors]
{errors}"""

#: What each uncertainty factor multiplies, for the comments of the example.
_ERROR_COMMENTS = {
    "deepwater": "on the storm's H0' (drawn once per lifetime)",
    "transformation": "on H1/3 at the wall (once per storm)",
    "force": "on the wave force P and the uplift U (once per storm)",
    "friction": "on the friction coefficient (once per storm)",
}


def example_design_text() -> str:
    """The commented example design file (Goda's worked upright breakwater, with a life of 50 years).

    Its ``[lifetime.errors]`` are the defaults of :data:`regimemap.lifetime.DEFAULT_ERRORS`.
    """
    from regimemap.lifetime import DEFAULT_ERRORS

    lines = []
    for name, comment in _ERROR_COMMENTS.items():
        f = getattr(DEFAULT_ERRORS, name)
        lines.append(f"{f'{name} = [{f.ratio!r}, {f.cov!r}]':<30} # {comment}\n")
    return _EXAMPLE.replace("{errors}", "".join(lines))
