"""The one-page design sheet of a caisson (A4 portrait): its layout.

The title block carries the verdict of the design check (:mod:`regimemap.drawing.verdict`):
a PASS or FAIL badge, and each failing number of (f) and (g) in the fail colour.

Panels: (a) the cross-section to scale (still-water level, mound and berm,
caisson, crest, the forces on the equivalent block); (b) Goda's pressure
diagram on the wall (``p1``, ``p3``, ``p4``, ``eta*``) and (c) the uplift
triangle (``pu``); (d) the loaded regime map of the design wave -- its exact
region polygons and boundary curves, as ``regimemap plot`` draws them -- with the
design point and the path it follows as the wave grows (0.5 to 1.5 times the
design heights); (e) the safety factors along that path with the mode of
each point on its own map; (f) the numbers; and, when a lifetime simulation is
given, (g) the exceedance curve of the caisson's sliding over its design life
(:func:`regimemap.lifetime.figures.exceedance.draw_exceedance`), under (e) -- with a wave
record's climate, the band over its replicate climates and the ESD including the climate's
uncertainty, and the note under it names the record, its fit and the band.

This module places the panels on the page and writes the notes; the panels are
drawn by :mod:`regimemap.caisson.figures.panels` ((a), (b), (c), (e), (f)) and
:mod:`regimemap.caisson.figures.map_panel` ((d)).  Everything drawn is computed beforehand,
by :func:`regimemap.caisson.run.run_caisson` with ``sheet=True`` (the report, the
checks, panel (d)'s map and panel (g)'s lifetime): :func:`caisson_sheet` draws its
record; these modules only draw.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ...drawing.save import DEFAULT_DPI, figure_version
from ...drawing.style import agg_figure, label_axes, style_context
from ...drawing.verdict import draw_verdict_badge, verdict_colour
from ...maps.mapdata import MapData
from ...records.checks import Check
from ...records.numbers import significant
from ..report import CaissonReport, MapView
from .map_panel import draw_map_panel, map_legend, tidy_map_panel
from .panels import FS, draw_path, draw_pressure, draw_section, draw_table, draw_uplift, num

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ...drawing.text.labelplacer import Placed
    from ...lifetime.replicates import ClimateBand
    from ...lifetime.results import LifetimeResult
    from ..run import CaissonRecord

__all__ = ["SHEET_SIZE", "PANELS", "LIFETIME_PANEL", "caisson_sheet", "sheet_figure"]

#: Size of the sheet in inches: A4 portrait.
SHEET_SIZE: tuple[float, float] = (8.27, 11.69)
#: The panels' axes, by label (``ax.get_label()``), in drawing order.
PANELS: tuple[str, ...] = ("section", "pressure", "uplift", "map", "path", "table")
#: The label of the lifetime panel (g), drawn after :data:`PANELS` when a lifetime is given.
LIFETIME_PANEL = "lifetime"
_BLOCK_NOTE = (
    "The equivalent loaded block (docs/waves.md, Sect. 7): half width B, centre of mass C at H_C "
    "above the base, \u03b3 = H_C/B; m g is the dry weight W\u2032 + \u03c1w g V (V the submerged "
    "volume); the wave force P = k m g acts k\u2032H_C above C; the buoyancy \u03c1w g V acts up "
    "through C; the uplift U = (U/P) P acts up, (uplift arm) \u00d7 B from C toward the seaward "
    "corner (1/3 for Goda's triangle).  Goda's SF_sliding \u2265 1 and SF_overturning \u2265 1 "
    "hold exactly when the map says rest (RE).")


# -- (g) the lifetime ------------------------------------------------------------------------

def _record_note(record: str, fit: str, band: ClimateBand | None) -> str:
    """The note of (g) on a wave record's climate: the record, its fit, the band (instead of the
    tolerable limits' sources, which the lifetime figure's key gives)."""
    name = Path(record).name
    if band is None:
        return (f"(g): ESD \u00b1 1 standard error (grey) under the {fit} fit of the record {name}, its "
                "uncertainty not counted (climate_replicates = 0).")
    return (f"(g): ESD \u00b1 1 s.e. (grey) under the {fit} fit of the record {name}; green: over "
            f"{band.replicates} climates of the fit, the {100 * band.level:g} % band of P(S > x) and the ESD "
            f"including the climate's uncertainty, {band.expected_sliding:.3g} m ({band.lower:.3g}\u2013"
            f"{band.upper:.3g} m).")


def _path_note(r: CaissonReport, short: bool,
               record: tuple[str, str, ClimateBand | None] | None = None) -> str:
    """The note under (e) (``short``: under (g), in fewer words; with a wave ``record`` -- its path,
    its fit in words and its band -- (g)'s sentence names them)."""
    p = r.path
    kp = f"{significant(float(p.kprime[0]), 3)} \u2026 {significant(float(p.kprime[-1]), 3)}"
    up = f"{significant(float(p.uplift_ratio[0]), 3)} \u2026 {significant(float(p.uplift_ratio[-1]), 3)}"
    if short:
        return (f"(d): the regions of the design wave; along the path k\u2032 ({kp}) and U/P ({up}) "
                "change: each marker and (e)'s band has the colour of the mode on its own map.  "
                "SF \u2265 1 (both) \u21d4 rest.  " + (
                    "(g): ESD \u00b1 1 standard error (grey); tolerable ESD 0.1 m (Goda & Takagi 2000), "
                    "0.3 m (Shimosako & Takahashi 1999)." if record is None else _record_note(*record)))
    return (f"The regions are those of the design wave.  Along the path k\u2032 ({kp}) and U/P "
            f"({up}) change with the wave, so each marker (and the band along the bottom of (e)) "
            "has the colour of the mode on its own map.  SF \u2265 1 (both) \u21d4 rest on the map.")


def _impulsive_words(on: bool | None) -> str:
    return "" if on is None else (", with \u03b1$_I$" if on else ", without \u03b1$_I$")


def _lifetime_panels(fig: Figure, r: CaissonReport, lifetime: LifetimeResult,
                     rect: Callable[[float, float, float, float], tuple[float, float, float, float]],
                     required: tuple[float, float], esd: Check | None,
                     impulsive: bool | None, band: ClimateBand | None = None,
                     record: tuple[str, str] | None = None) -> tuple[Axes, Placed]:
    """(e) shorter, (g) the exceedance curve of the lifetime under it, and the note, shorter.

    (g)'s title names the lifetime's impulsive setting (``impulsive``, the file's ``[lifetime]
    impulsive``); its ESD label is in the fail colour when ``esd`` fails.  With a wave record
    (``record``: its path and its fit in words) (g) draws the climate ``band`` and the note names
    the record, its fit and the band.  Returns (g)'s axes and its labels, to place once the rest
    of the sheet is drawn.
    """
    from ...lifetime.figures.exceedance import draw_exceedance

    ax_path = fig.add_axes(rect(5.55, 5.1, 2.35, 1.35), label="path")
    draw_path(ax_path, r, required)
    # with a record (g) is a little shorter and higher: its note names the record and the band
    ax_l = fig.add_axes(rect(5.55, 3.33, 2.35, 1.05) if record is None else rect(5.55, 3.55, 2.35, 0.93),
                        label=LIFETIME_PANEL)
    placed = draw_exceedance(ax_l, lifetime, storm=False, fontsize=FS, band=band)
    label_axes(ax_l, f"$x$ (m); $S$ = sliding in {lifetime.years} years", "$P(S > x)$", FS,
               f"(g) {lifetime.trials} lifetimes{_impulsive_words(impulsive)}")
    if esd is not None:  # the ESD's label: the failing number in the fail colour
        for t, _, _ in placed:
            if t.get_text().startswith("ESD"):
                t.set_color(verdict_colour(esd))
    note = _path_note(r, True, None if record is None else (*record, band))
    fig.text(5.4 / SHEET_SIZE[0], (2.86 if record is None else 3.08) / SHEET_SIZE[1],
             "\n".join(textwrap.wrap(note, 54)), fontsize=FS - 1.0, va="top",
             ha="left", color="0.15", linespacing=1.3, gid="lifetime-note")
    return ax_l, placed


def _place_lifetime_labels(fig: Figure, ax: Axes, placed: Placed) -> None:
    """Place the labels of (g) clear of every text of the sheet and of (g)'s lines."""
    from ...drawing.text.labelplacer import LabelPlacer

    with LabelPlacer(fig) as placer:
        placer.avoid_lines_of(ax)
        placer.place_all(ax, placed)

# -- the sheet -----------------------------------------------------------------------------

def caisson_sheet(record: CaissonRecord, *, title: str | None = None, dpi: float = DEFAULT_DPI
                  ) -> Figure:
    """The design sheet of a caisson record: :func:`sheet_figure` of its fields.

    Parameters
    ----------
    record : CaissonRecord
        From :func:`regimemap.caisson.run.run_caisson` with ``sheet=True`` (panel
        (d)'s view and map; panel (g) when it holds a lifetime).
    title : str, optional
        Shown after "caisson design sheet"; default the design file's name.
    dpi : float
        Resolution of PNG output.

    Raises
    ------
    ValueError
        If the record holds no map for panel (d) (computed without ``sheet=True``).
    """
    if record.view is None or record.map_data is None:
        raise ValueError("the record holds no map for the sheet: run_caisson(..., sheet=True)")
    run = record.lifetime_run
    wave_record = None
    if run is not None and run.wave_record is not None:
        c = run.model.climate
        shape = f" (\u03be = {c.shape:.3g})" if c.distribution in ("gpd", "gev") else ""
        wave_record = (run.wave_record.path, f"{c.distribution.upper()}{shape}")
    return sheet_figure(record.report, view=record.view, data=record.map_data, checks=record.checks,
                        title=Path(record.design.source).name if title is None else title, dpi=dpi,
                        lifetime=record.lifetime, required=record.required,
                        lifetime_impulsive=record.lifetime_impulsive, written=record.design.written,
                        band=record.band, wave_record=wave_record)


def sheet_figure(report: CaissonReport, *, view: MapView, data: MapData, checks: Sequence[Check],
                 title: str | None = None, dpi: float = DEFAULT_DPI,
                 lifetime: LifetimeResult | None = None, required: tuple[float, float] = (1.2, 1.2),
                 lifetime_impulsive: bool | None = None,
                 written: Mapping[str, str] | None = None, band: ClimateBand | None = None,
                 wave_record: tuple[str, str] | None = None) -> Figure:
    """The one-page design sheet of a caisson (A4 portrait, no pyplot).

    Parameters
    ----------
    report : CaissonReport
        From :func:`regimemap.caisson.report.caisson_report`.
    view : MapView
        The map's view, and
    data : MapData
        the design wave's loaded map in it, drawn in (d): both from
        :func:`regimemap.caisson.report.sheet_map` (its exact region polygons and boundary curves).
    checks : sequence of Check
        The requirements of the design check, whose verdict the title block's badge
        shows (PASS, or FAIL and how many); a failing safety factor of (f) and a failing
        expected sliding distance of (g) are written in the fail colour:
        :func:`regimemap.caisson.report.caisson_checks` of ``required``, and the checks of
        ``lifetime`` (:func:`regimemap.lifetime.judge_lifetime`) when it is drawn.
    title : str, optional
        Shown after "caisson design sheet" (e.g. the design file's name).
    dpi : float
        Resolution of PNG output.
    lifetime : LifetimeResult, optional
        The caisson's sliding over its design life
        (:func:`regimemap.lifetime.lifetime_sliding`): adds panel (g), its exceedance
        curve with the ESD and the tolerable limits, under (e) (which gets shorter, and its
        note too).
    required : tuple of float, optional
        The safety factors the design must reach (sliding, overturning; 1.2 and 1.2 by
        default, the design file's ``[caisson] required_*``), drawn in (e) beside SF = 1.
    lifetime_impulsive : bool, optional
        Whether the lifetime simulation included Takahashi's impulsive coefficient (the
        design file's ``[lifetime] impulsive``), named in (g)'s title.
    written : mapping, optional
        The design file's values as it writes them (``{"wave.H0": "6.3"}``,
        :attr:`regimemap.caisson.file.Design.written`): the header echoes H0', T1/3, tan theta
        and mu so.
    band : ClimateBand, optional
        The lifetimes under a wave record's replicate climates, drawn in (g).
    wave_record : (str, str), optional
        The wave record whose fit is the lifetime's climate: its path and its fit in words,
        named in (g)'s note (with the band).

    Returns
    -------
    Figure
        Axes labelled as :data:`PANELS`, then :data:`LIFETIME_PANEL` when ``lifetime`` is given.
    """

    W, H = SHEET_SIZE
    by_name = {c.name: c for c in checks}

    def rect(x: float, y: float, w: float, h: float) -> tuple[float, float, float, float]:
        return (x / W, y / H, w / W, h / H)

    with style_context():
        fig = agg_figure(figsize=SHEET_SIZE, dpi=dpi)
        head = "caisson design sheet" + (f": {title}" if title else "")
        fig.text(0.6 / W, 1.0 - 0.38 / H, head, fontsize=13, fontweight="bold", va="top")
        draw_verdict_badge(fig, checks, x=1.0 - 0.37 / W, y=1.0 - 0.36 / H, fontsize=12.0)
        a = report.analysis
        inp = report.inputs
        shown = {} if written is None else written

        def value(key: str, name: str) -> str:  # as the design file writes it, else the number
            return shown.get(key) or f"{num(report, name):g}"

        wave = (f"H\u2080\u2032 = {value('wave.H0', 'H0')} m" if inp.get("H0") is not None
                else "H\u2081/\u2083, H$_{max}$ given at the wall")
        fig.text(0.6 / W, 1.0 - 0.68 / H,
                 f"{wave}, T\u2081/\u2083 = {value('wave.period', 'period')} s, "
                 f"\u03b2 = {float(a.pressures.beta):g}\u00b0, "
                 f"tan \u03b8 = {value('site.seabed_slope', 'seabed_slope')}, "
                 f"\u03bc = {shown.get('caisson.friction') or format(report.mu, 'g')}, "
                 f"W\u2032 = {significant(float(a.section.buoyant_weight) / 1e3)} kN/m.\n"
                 + ("Goda (2000) with Takahashi's \u03b1$_I$ (impulsive = true)"
                    if inp.get("impulsive", True) else
                    "Goda (2000) without Takahashi's \u03b1$_I$ (impulsive = false)")
                 + ("" if lifetime is None or lifetime_impulsive is None else
                    f"; (g) {'with' if lifetime_impulsive else 'without'} it "
                    f"([lifetime] impulsive = {str(lifetime_impulsive).lower()})")
                 + f"; regimemap {figure_version()}",
                 fontsize=FS + 0.5, va="top", color="0.2", linespacing=1.4)

        ax_sec = fig.add_axes(rect(0.75, 8.55, 4.6, 1.85), label="section")
        draw_section(ax_sec, report)
        fig.text(0.6 / W, 7.95 / H, "\n".join(textwrap.wrap(_BLOCK_NOTE, 86)), fontsize=FS - 0.5,
                 va="top", ha="left", color="0.15", linespacing=1.35)
        ax_p = fig.add_axes(rect(5.95, 8.75, 1.95, 1.65), label="pressure")
        draw_pressure(ax_p, report)
        ax_u = fig.add_axes(rect(5.95, 7.35, 1.95, 0.72), label="uplift")
        draw_uplift(ax_u, report)

        ax_map = fig.add_axes(rect(0.75, 3.6, 4.1, 2.9), label="map")
        modes, map_art = draw_map_panel(ax_map, report, view, data)
        map_legend(ax_map, modes, map_art.data)  # what was drawn (no line hidden under another)
        lifetime_labels = None
        if lifetime is None:
            ax_path = fig.add_axes(rect(5.55, 4.5, 2.35, 1.95), label="path")
            draw_path(ax_path, report, required)
            fig.text(5.4 / W, 3.95 / H, "\n".join(textwrap.wrap(_path_note(report, False), 47)),
                     fontsize=FS - 0.5, va="top", ha="left", color="0.15", linespacing=1.35)
        else:
            lifetime_labels = _lifetime_panels(fig, report, lifetime, rect, required,
                                               by_name.get("expected sliding distance"),
                                               lifetime_impulsive, band, wave_record)

        ax_t = fig.add_axes(rect(0.6, 0.3, 7.2, 1.95), label="table")
        draw_table(ax_t, report, {"sliding": by_name.get("sliding safety factor"),
                                  "overturning": by_name.get("overturning safety factor")})
        tidy_map_panel(fig, ax_map, map_art)  # the map's texts clear of the sheet's
        if lifetime_labels is not None:  # once every other text is on the sheet
            _place_lifetime_labels(fig, *lifetime_labels)
    return fig
