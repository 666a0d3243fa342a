"""The design chart of :mod:`regimemap.lifetime`: expected sliding distance against width.

:func:`chart_figure` draws a :class:`~regimemap.lifetime.DesignChart`: the ESD of each
width with a band of two standard errors, the tolerable limits and the target, the width
meeting the target and the width of Goda's deterministic design (SF = 1.2 under the 50-year
wave).  Labels are placed once the figure is laid out
(:class:`~regimemap.drawing.text.labelplacer.LabelPlacer`); colours, limits and numbers are
:mod:`regimemap.lifetime.figures.style`'s, shared with :mod:`regimemap.lifetime.figures.exceedance`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ...drawing.save import DEFAULT_DPI
from ...drawing.style import agg_figure, key_below, label_axes, style_context
from ...drawing.text.labelplacer import (
    LabelPlacer,
    Placed,
    corner_candidates,
    hline_label,
    make_label,
    vline_label,
)
from ...drawing.verdict import draw_verdict_badge, verdict_colour
from ..chart import DesignChart
from .style import (
    ESD_LINE,
    FILL,
    FS,
    LIMIT,
    LIMIT_DASHES,
    SF_DASHES,
    TARGET,
    TARGET_TEXT,
    TOLERABLE,
    decade_range,
    draw_title_block,
    format_log_axis,
    impulsive_words,
    limit_text,
    metres,
    title_height,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from numpy.typing import NDArray

    from ..replicates import ChartBand

    FloatArray = NDArray[np.float64]

__all__ = ["CHART_FIGSIZE", "chart_figure", "chart_title"]

#: Dashes of the design's own width (dotted).
DESIGN_DASHES = (1.2, 1.6)
#: The climate band's upper curve and its width: Paul Tol's green, long dashes.
BAND_LINE = "#228833"
BAND_DASHES = (6.0, 2.0)

#: Size of :func:`chart_figure` in inches (a page wide, as the lifetime figure; the height
#: without a title and with a key of three rows, as the figure grows with them).
CHART_FIGSIZE: tuple[float, float] = (7.0, 4.14)


def _chart_range(chart: DesignChart) -> tuple[float, float]:
    esd = np.asarray(chart.expected_sliding, dtype=np.float64)
    se = np.asarray(chart.std_error, dtype=np.float64)
    pos = esd > 0.0
    marks = [lim for lim, _ in TOLERABLE] + [chart.target]
    if not np.any(pos):
        return decade_range(min(marks) / 10.0, max(marks) * 3.0)
    upper = esd + 2.0 * np.where(np.isfinite(se), se, 0.0)
    lo = min(float(np.min(esd[pos])), *marks)
    hi = max(float(np.max(upper[pos])), *marks)
    return decade_range(lo / 1.5, hi * 1.5)


def chart_title(section: str, chart: DesignChart) -> str:
    """The title of :func:`chart_figure`: the section and the target, then the run's facts."""
    design = "" if chart.design_width is None else f" (design $b$ = {chart.design_width:g} m)"
    return (f"{section}: width for ESD \u2264 {chart.target:g} m{design}\n"
            f"{chart.widths.size} widths \u00d7 {chart.trials} lifetimes, seed {chart.seed}, "
            f"{impulsive_words(chart.impulsive)}")


def chart_figure(chart: DesignChart, title: str | None = None, *, dpi: float = DEFAULT_DPI,
                 band: ChartBand | None = None) -> Figure:
    """The design chart: expected sliding distance against the caisson's width.

    The ESD of each width (log axis) with a band of two standard errors; the tolerable limits
    of :data:`TOLERABLE` and the target as horizontal lines; the narrowest width meeting the
    target (solid) and the width of Goda's deterministic design, SF = ``required_sf`` under the
    50-year wave (dash-dot-dotted), as vertical lines labelled with their widths.  Widths whose
    ESD is 0 (no lifetime slid) cannot be drawn on a log axis: the curve stops there and they
    are marked with open triangles along the bottom of the axes.  The key, below the axes,
    names every line and the sources; what is not on the chart (no width meets the target, the
    SF width outside the widths) is said in a note in the axes.

    Parameters
    ----------
    chart : DesignChart
        From :func:`regimemap.lifetime.design_chart`.
    title : str, optional
        Written at the top left; its first line larger, the others (:func:`chart_title`: the
        run's facts) below it.
    dpi : float
        Resolution of PNG output.
    band : ChartBand, optional
        The chart under a record's replicate climates
        (:func:`regimemap.lifetime.replicates.climate_band_chart`): its upper curve is drawn
        dashed, with the width for the target at that level as a vertical line.

    Returns
    -------
    Figure
        One axes labelled ``chart`` (Agg canvas, no pyplot).

    Notes
    -----
    The width's Monte Carlo interval is drawn as a bar with end caps on the target line.  A
    judged chart (:func:`regimemap.lifetime.judge_chart`) shows the design's width as a dotted
    vertical line labelled in the fail colour when it is narrower than the width for the
    target, and a PASS or FAIL badge at the top right.
    """

    widths = np.asarray(chart.widths, dtype=np.float64)
    esd = np.asarray(chart.expected_sliding, dtype=np.float64)
    se = np.asarray(chart.std_error, dtype=np.float64)
    se0 = np.where(np.isfinite(se), se, 0.0)
    pos = esd > 0.0
    y0, y1 = _chart_range(chart)
    lo_w, hi_w = float(widths[0]), float(widths[-1])
    pad = 0.02 * (hi_w - lo_w)
    on_limit = [math.isclose(lim, chart.target, rel_tol=1e-9) for lim, _ in TOLERABLE]
    key = _chart_key(chart, bool(np.all(pos)), on_limit) + _band_key(band)
    rows = (len(key) + 1) // 2
    w = CHART_FIGSIZE[0]
    top = 0.15 + max(title_height(title) + 0.05 if title else 0.0, 0.32 if chart.checks else 0.0)
    left, right, ah = 0.66, 0.2, 2.9
    bottom = 0.5 + 0.08 + 0.17 * rows
    h = top + ah + bottom
    with style_context():
        fig = agg_figure(figsize=(w, h), dpi=dpi)
        ax = fig.add_axes((left / w, bottom / h, (w - left - right) / w, ah / h), label="chart")
        ax.set_yscale("log")
        ax.set_xlim(lo_w - pad, hi_w + pad)
        ax.set_ylim(y0, y1)
        # the band of +-2 SE; where its lower edge reaches 0 it runs out of the axes
        lower = np.where(esd - 2.0 * se0 > 0.0, esd - 2.0 * se0, y0 * 1e-3)
        ax.fill_between(widths, lower, esd + 2.0 * se0, where=pos, facecolor=FILL,
                        edgecolor="none", zorder=1)
        ax.plot(widths, np.where(pos, esd, np.nan), color=ESD_LINE, lw=1.4, marker="o",
                markersize=2.6, zorder=4)
        if not np.all(pos):
            zw = widths[~pos]
            ax.plot(zw, np.full(zw.shape, 0.035), transform=ax.get_xaxis_transform(), ls="none",
                    marker="v", markersize=4.5, markerfacecolor="white", markeredgecolor=ESD_LINE,
                    markeredgewidth=1.0, zorder=5)
        horizontal = _draw_limits(ax, chart, on_limit)
        vertical, notes = _draw_widths(ax, chart, lo_w, hi_w)
        vertical += _draw_band(ax, band)
        format_log_axis(ax, "y")
        label_axes(ax, "caisson width $b$ (m)", "expected sliding distance (m)", FS)
        if title:
            draw_title_block(fig, title, h)
        draw_verdict_badge(fig, chart.checks, x=1.0 - 0.1 / w, y=1.0 - 0.1 / h, fontsize=FS + 1.0)
        key_below(fig, key, 0.06 / h, FS - 0.5)
        note = None
        if notes:
            note = make_label(ax, "\n".join(notes), xycoords="axes fraction", fontsize=FS - 0.5)
        se_band = (np.where(pos, np.maximum(lower, y0), np.nan), np.where(pos, esd + 2.0 * se0, np.nan))
        _place_labels(fig, ax, widths, se_band, note, vertical + horizontal)
    return fig


def _band_key(band: ChartBand | None) -> list[tuple[Any, str]]:
    """The key of the climate band's upper curve and its width, when drawn."""
    if band is None:
        return []
    from matplotlib.lines import Line2D

    key: list[tuple[Any, str]] = [(Line2D([], [], color=BAND_LINE, lw=1.2, dashes=BAND_DASHES),
                                   f"ESD, upper end of the {100 * band.level:g} % climate band "
                                   f"({band.replicates} climates)")]
    if band.width_for_target is not None:
        key.append((Line2D([], [], color=BAND_LINE, lw=1.0),
                    f"narrowest width with that ESD \u2264 {band.target:g} m"))
    return key


def _draw_band(ax: Axes, band: ChartBand | None) -> Placed:
    """The climate band's upper curve and the width where it meets the target; its label."""
    if band is None:
        return []
    upper = np.asarray(band.upper, dtype=np.float64)
    ax.plot(band.widths, np.where(upper > 0.0, upper, np.nan), color=BAND_LINE, lw=1.2,
            dashes=BAND_DASHES, zorder=3.8)
    wb = band.width_for_target
    if wb is None:
        return []
    ax.axvline(wb, color=BAND_LINE, lw=1.0, zorder=3)
    return [vline_label(ax, wb, f"b = {metres(wb)} m (band)", fontsize=FS - 0.5, color=BAND_LINE)]


def _chart_key(chart: DesignChart, all_slid: bool, on_limit: list[bool]) -> list[tuple[Any, str]]:
    """The key, (handle, text): the chart's own lines, then the limits and the target."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    sfw = chart.sf_width
    sf_in = math.isfinite(sfw) and float(chart.widths[0]) <= sfw <= float(chart.widths[-1])
    key: list[tuple[Any, str]] = [
        ((Patch(facecolor=FILL, edgecolor="none"),
          Line2D([], [], color=ESD_LINE, lw=1.4, marker="o", markersize=2.6)),
         f"ESD \u00b1 2 standard errors ({chart.trials} lifetimes per width)")]
    if not all_slid:
        key.append((Line2D([], [], ls="none", marker="v", markersize=4.5, markerfacecolor="white",
                           markeredgecolor=ESD_LINE, markeredgewidth=1.0),
                    "ESD = 0 (no lifetime slid)"))
    if chart.width_for_target is not None:
        key.append((Line2D([], [], color=TARGET, lw=1.0),
                    f"narrowest width with ESD \u2264 {chart.target:g} m (to {chart.tolerance:g} m)"))
    iv = chart.width_interval
    if iv is not None:
        key.append((Line2D([], [], color=TARGET, lw=2.2, marker="|", markersize=7),
                    f"its {100 * iv.level:g} % Monte Carlo interval (bootstrap)"))
    if chart.design_width is not None and chart.checks:
        key.append((Line2D([], [], color="black", lw=1.0, dashes=DESIGN_DASHES), "the design's width"))
    if sf_in:
        key.append((Line2D([], [], color="black", lw=1.0, dashes=SF_DASHES),
                    f"SF = {chart.required_sf:g} under the 50-year wave (Goda 2000)"))
    for (lim, source), dashes, is_target in zip(TOLERABLE, LIMIT_DASHES, on_limit):
        key.append((Line2D([], [], color=TARGET if is_target else LIMIT,
                           lw=1.0 if is_target else 0.8, dashes=dashes),
                    f"tolerable ESD {limit_text(lim, source)}" + (", the target" if is_target else "")))
    if not any(on_limit):
        key.append((Line2D([], [], color=TARGET, lw=1.0), f"target ESD {chart.target:g} m"))
    return key


def _draw_limits(ax: Axes, chart: DesignChart, on_limit: list[bool]) -> Placed:
    """The tolerable limits and the target as horizontal lines; their labels, to be placed."""
    horizontal: Placed = []
    for (lim, _), dashes, is_target in zip(TOLERABLE, LIMIT_DASHES, on_limit):
        ax.axhline(lim, color=TARGET if is_target else LIMIT, lw=1.0 if is_target else 0.8,
                   dashes=dashes, zorder=2)
        horizontal.append(hline_label(ax, lim, f"{lim:g} m" + (": target" if is_target else ""),
                                      fontsize=FS - 0.5, color=TARGET_TEXT if is_target else "0.15"))
    if not any(on_limit):
        ax.axhline(chart.target, color=TARGET, lw=1.0, zorder=2)
        horizontal.append(hline_label(ax, chart.target, f"target {chart.target:g} m", fontsize=FS - 0.5,
                                      color=TARGET_TEXT))
    return horizontal


def _draw_widths(ax: Axes, chart: DesignChart, lo_w: float, hi_w: float) -> tuple[Placed, list[str]]:
    """The width meeting the target and the width of Goda's SF as vertical lines, their labels
    to be placed; the notes on what is not on the chart."""
    wt, sfw = chart.width_for_target, chart.sf_width
    sf = f"SF = {chart.required_sf:g}"
    vertical: Placed = []
    notes: list[str] = []
    if wt is not None:
        ax.axvline(wt, color=TARGET, lw=1.0, zorder=3)
        every = (math.isclose(wt, lo_w, rel_tol=1e-12)
                 and bool(np.asarray(chart.expected_sliding, dtype=np.float64)[0] <= chart.target))
        text = (f"b = {metres(wt)} m: every width meets it" if every
                else f"b = {metres(wt)} m")
        vertical.append(vline_label(ax, wt, text, fontsize=FS - 0.5, color=TARGET_TEXT,
                                    texts=[text.replace(": ", ":\n")] if every else []))
        iv = chart.width_interval
        if iv is not None:
            ax.plot([iv.lower, iv.upper], [chart.target, chart.target], color=TARGET, lw=2.2,
                    marker="|", markersize=7, solid_capstyle="butt", zorder=3.5)
    else:
        notes.append(f"no width of {lo_w:.4g}\u2013{hi_w:.4g} m\n"
                     f"has ESD \u2264 {chart.target:g} m")
    dw = chart.design_width
    if dw is not None and chart.checks and lo_w <= dw <= hi_w:
        ax.axvline(dw, color="black", lw=1.0, dashes=DESIGN_DASHES, zorder=3)
        vertical.append(vline_label(ax, dw, f"design b = {metres(dw)} m", fontsize=FS - 0.5,
                                    color=verdict_colour(chart.checks[0]), side_first=-1))
    if math.isfinite(sfw) and lo_w <= sfw <= hi_w:
        ax.axvline(sfw, color="black", lw=1.0, dashes=SF_DASHES, zorder=3)
        vertical.append(vline_label(ax, sfw, f"b = {metres(sfw)} m", fontsize=FS - 0.5, side_first=-1))
    elif math.isfinite(sfw):
        notes.append(f"{sf} under the 50-year wave:\nb = {metres(sfw)} m, off the chart")
    else:
        notes.append(f"{sf} under the 50-year wave:\nno width")
    return vertical, notes


def _place_labels(fig: Figure, ax: Axes, widths: FloatArray, band: tuple[FloatArray, FloatArray],
                  note: Any, labels: Placed) -> None:
    """Place the note (a corner first), then the lines' labels in order, clear of the lines and of
    the band (its lower and upper edges, NaN where not drawn)."""
    lb, ub = band
    with LabelPlacer(fig) as placer:
        placer.avoid_lines_of(ax)
        placer.avoid_line(ax, widths, ub)
        placer.avoid_line(ax, widths, lb)
        for x, a, b in zip(widths, lb, ub):  # the band between its edges
            if np.isfinite(a) and np.isfinite(b):
                placer.avoid_line(ax, [x, x], [a, b])
        if note is not None:  # a corner first; then the lines' labels, the vertical ones first
            placer.place(ax, note, corner_candidates())
        placer.place_all(ax, labels)
