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
table (``[caisson] base_depth``), the value found, what is accepted and the
line of the key (``goda.toml, line 45: [lifetime] shape = -1.0: out of range;
...``); a value beyond the limits physics sets (a significant height over 30
m, a period outside 1-30 s, a depth outside 0.5-100 m) is refused with the
reason.  A
parsed file is a :class:`Design`; :meth:`Design.analysis_inputs` gives the
inputs of Goda's procedure, :meth:`Design.lifetime_caisson` and
:meth:`Design.lifetime_model` those of
:func:`regimemap.lifetime.lifetime_sliding`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

# the keys, the example, the [lifetime] table (their own modules) and the line finder,
# re-exported: one front door
from ..io.inputs import read_design_text
from ..io.toml_errors import DesignFileError, did_you_mean
from ..io.toml_keys import KeyReader, load_toml
from ..io.toml_lines import key_line, key_text
from ..lifetime.file import LifetimeSpec, read_lifetime
from ..lifetime.file import lifetime_model as _lifetime_model
from ..lifetime.file_keys import ERROR_FACTORS, LIFETIME_KEYS, MAX_TRIALS, MAX_YEARS, check_lifetime_option
from .file_example import example_design_text
from .file_keys import DESIGN_KEYS, CaissonSpec, SiteSpec, WaveSpec, design_reader

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel
    from regimemap.waves import CaissonAnalysis

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "MAX_TRIALS", "MAX_YEARS", "Design",
           "DesignFileError", "LifetimeSpec", "check_lifetime_option",
           "example_design_text", "key_line", "parse_design", "read_design"]


@dataclass(frozen=True)
class Design:
    """A parsed and checked design file."""

    site: SiteSpec
    wave: WaveSpec
    caisson: CaissonSpec
    source: str
    lifetime: LifetimeSpec | None = None
    written: Mapping[str, str] = field(default_factory=dict)

    def as_written(self, section: str, key: str) -> str | None:
        """The value of ``[section] key`` as the file writes it (``"10.1"``); None when not set."""
        return self.written.get(f"{section}.{key}")

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
            depth=self.site.depth, armour_depth=self.site.armour_depth, seabed_slope=self.site.seabed_slope,
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
        return Caisson(depth=a["depth"], armour_depth=a["armour_depth"], seabed_slope=a["seabed_slope"],
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
        a missing or doubly given climate.  The message gives the line of
        the key (:func:`key_line`; of the table's header for a missing key)
        and the value as the file writes it.
    """
    r = design_reader(source, text)
    data = load_toml(text, lambda msg, line, column: r.fail(
        f"TOML syntax error{'' if line is None else f' at line {line}, column {column}'}: {msg}"))
    _check_tables(data, r)
    site = r.table("site", data["site"], SiteSpec)
    wave = _read_wave(data, r)
    caisson = _read_caisson(data, r)
    _check_depths(site, caisson, r)
    lifetime = read_lifetime(text, source, data["lifetime"]) if "lifetime" in data else None
    written = {f"{section}.{key}": key_text(text, section, key) or repr(data[section][key])
               for section in DESIGN_KEYS for key in DESIGN_KEYS[section] if key in data[section]}
    return Design(site=site, wave=wave, caisson=caisson, source=source, lifetime=lifetime,
                  written=written)


def _check_tables(data: Mapping[str, Any], r: KeyReader) -> None:
    """The tables ``[site]``, ``[wave]``, ``[caisson]`` (their keys known) and ``[lifetime]`` (its keys
    are checked with it, :func:`~regimemap.lifetime.file.read_lifetime`), none other."""
    tables = [*DESIGN_KEYS, "lifetime"]
    for section, table in data.items():
        if section not in tables and not isinstance(table, dict):  # a key above every table
            raise r.fail(f"unknown key {section} above the tables; a design file has only the "
                         f"tables {', '.join(f'[{s}]' for s in tables)}", section)
        if section not in tables:
            raise r.fail(f"unknown table [{section}]{did_you_mean(section, dict.fromkeys(tables))}; "
                         f"accepted tables: {', '.join(f'[{s}]' for s in tables)}", section)
        if not isinstance(table, dict):
            raise r.fail(f"[{section}] must be a table, found {table!r}", section)
        if section != "lifetime":
            r.check_keys(section, table)
    for section in DESIGN_KEYS:
        if section not in data:
            raise r.fail(f"missing table [{section}]; required keys: "
                         + ", ".join(k for k, v in DESIGN_KEYS[section].items() if v.required))


def _read_wave(data: Mapping[str, Any], r: KeyReader) -> WaveSpec:
    """``[wave]``: either ``H0`` or both ``H13`` and ``Hmax`` (``Hmax >= H13``)."""
    H0, H13, Hmax = (r.value("wave", data["wave"], k) for k in ("H0", "H13", "Hmax"))
    if H0 is not None and (H13 is not None or Hmax is not None):
        raise r.fail(f"[wave] H0 = {r.written('wave', 'H0', H0)} together with [wave] H13/Hmax; "
                     "accepted: either H0 (equivalent deep-water height) or both H13 and Hmax "
                     "(heights at the wall)", "wave", "H0")
    if H0 is None:
        if H13 is None or Hmax is None:
            missing = "H13" if H13 is None and Hmax is not None else (
                "Hmax" if Hmax is None and H13 is not None else "H0")
            raise r.fail(f"[wave] {missing} is missing; accepted: either H0 (equivalent deep-water "
                         "height, m) or both H13 and Hmax (heights at the wall, m)", "wave")
        if Hmax < H13:
            raise r.bad("wave", "Hmax", Hmax,
                        f"smaller than [wave] H13 = {r.written('wave', 'H13', H13)}")
    return r.table("wave", data["wave"], WaveSpec, H0=H0, H13=H13, Hmax=Hmax)


def _read_caisson(data: Mapping[str, Any], r: KeyReader) -> CaissonSpec:
    """``[caisson]``: either ``buoyant_weight`` or the three densities."""
    c = "caisson"
    weight = r.value(c, data[c], "buoyant_weight")
    dens = {k: r.value(c, data[c], k) for k in ("concrete_fraction", "concrete_density", "fill_density")}
    above = r.value(c, data[c], "fill_density_above")
    given = [k for k, v in dens.items() if v is not None]
    if weight is not None and (given or above is not None):
        raise r.fail(f"[caisson] buoyant_weight = {r.written(c, 'buoyant_weight', weight)} together with "
                     f"densities ({', '.join(given or ['fill_density_above'])}); accepted: either "
                     "buoyant_weight (kN/m) or concrete_fraction, concrete_density and fill_density",
                     c, "buoyant_weight")
    if weight is None and len(given) < 3:
        absent = [k for k, v in dens.items() if v is None]
        raise r.fail(f"[caisson] {' and '.join(absent)} missing; accepted: either buoyant_weight "
                     "(kN/m) or all of concrete_fraction, concrete_density, fill_density (kg/m^3)", c)
    return r.table(c, data[c], CaissonSpec, buoyant_weight=weight, fill_density_above=above, **dens)


def _check_depths(site: SiteSpec, caisson: CaissonSpec, r: KeyReader) -> None:
    """The armour layer no lower than the caisson's base, the base no deeper than the water."""
    depth = r.written("site", "depth", site.depth)
    base = r.written("caisson", "base_depth", caisson.base_depth)
    if caisson.base_depth > site.depth:
        raise r.fail(f"[caisson] base_depth = {base}: the base of the caisson would be deeper than the "
                     f"water ([site] depth = {depth}); accepted: 0 < base_depth <= [site] depth = "
                     f"{depth} (metres)", "caisson", "base_depth")
    if site.armour_depth > caisson.base_depth:
        raise r.fail(f"[site] armour_depth = {r.written('site', 'armour_depth', site.armour_depth)}: the "
                     "top of the armour layer would be below the base of the caisson ([caisson] "
                     f"base_depth = {base}); accepted: 0 < armour_depth <= [caisson] base_depth = "
                     f"{base} (metres)", "site", "armour_depth")


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
        text = read_design_text(p)
    except (OSError, UnicodeDecodeError) as exc:
        raise DesignFileError(f"{p}: cannot read the design file: {exc}") from None
    return parse_design(text, source=str(p))
