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

import math
import re
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

# the [lifetime] table (its own module) and the line finder, re-exported: one front door
from .design_errors import DesignFileError, did_you_mean
from .design_lifetime import (
    ERROR_FACTORS,
    LIFETIME_KEYS,
    LIFETIME_TABLES,
    MAX_TRIALS,
    MAX_YEARS,
    LifetimeSpec,
    check_lifetime_option,
    read_lifetime,
)
from .design_lifetime import lifetime_model as _lifetime_model
from .toml_lines import key_line

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel
    from regimemap.waves import CaissonAnalysis

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "MAX_TRIALS", "MAX_YEARS", "CaissonSpec", "Design",
           "DesignFileError", "LifetimeSpec", "SiteSpec", "WaveSpec", "check_lifetime_option",
           "example_design_text", "key_line", "parse_design", "read_design"]

#: The key tables of ``[lifetime]`` (read by the documentation's table of the keys).
_TABLE_KEYS = LIFETIME_TABLES


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
    required_sliding: float = 1.2
    required_overturning: float = 1.2


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
        "required_sliding": _Key("a required sliding safety factor 1 <= required_sliding <= 3 "
                                 "(default 1.2, Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0,
                                 required=False),
        "required_overturning": _Key("a required overturning safety factor 1 <= required_overturning "
                                     "<= 3 (default 1.2, Goda 2000, Sect. 4.2)", lambda x: 1.0 <= x <= 3.0,
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
                raise self.fail(f"unknown table [{section}]{did_you_mean(section, dict.fromkeys(tables))}; "
                                f"accepted tables: {', '.join(f'[{s}]' for s in tables)}")
            if not isinstance(table, dict):
                raise self.fail(f"[{section}] must be a table, found {table!r}")
            if section == "lifetime":  # its keys are checked with their lines (_LifetimeReader)
                continue
            for key in table:
                if key not in _SPEC[section]:
                    raise self.fail(f"unknown key [{section}] {key}{did_you_mean(key, _SPEC[section])}; "
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
                          impulsive=r.boolean(data, c, "impulsive", True),
                          required_sliding=r.number(data, c, "required_sliding") or 1.2,
                          required_overturning=r.number(data, c, "required_overturning") or 1.2)

    if caisson.base_depth > site.depth:
        raise r.fail(f"[caisson] base_depth = {caisson.base_depth!r}: the base of the caisson would be "
                     f"deeper than the water ([site] depth = {site.depth!r}); accepted: "
                     f"0 < base_depth <= [site] depth = {site.depth!r} (metres)")
    if site.armour_depth > caisson.base_depth:
        raise r.fail(f"[site] armour_depth = {site.armour_depth!r}: the top of the armour layer would be "
                     f"below the base of the caisson ([caisson] base_depth = {caisson.base_depth!r}); "
                     f"accepted: 0 < armour_depth <= [caisson] base_depth = {caisson.base_depth!r} (metres)")
    lifetime = read_lifetime(text, source, data["lifetime"]) if "lifetime" in data else None
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
# required_sliding = 1.2     # optional: the safety factors the design must reach (default 1.2
# required_overturning = 1.2 #   for both, Goda 2000); `regimemap caisson` says when one fails

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
