"""Figures of :mod:`regimemap.lifetime`: the sliding of a caisson over its design life.

* :func:`lifetime_figure` -- one :class:`~regimemap.lifetime.LifetimeResult`: (a) the
  exceedance curve ``P(S > x)`` of the lifetime sliding, with Kim & Suh's single-storm curve,
  the expected sliding distance (ESD) with its standard error and the tolerable limits -- and,
  with a wave record's climate band (:class:`~regimemap.lifetime.replicates.ClimateBand`), the
  band of ``P(S > x)`` over the replicate climates (hatched green), its mean and the ESD
  including the climate's uncertainty (green) -- and
  (b) the histogram of the lifetimes that slid (log-spaced bins; those that did not are counted
  in words);
* :func:`draw_exceedance` -- the exceedance panel on any axes (the design sheet uses it).

The design chart, ESD against width, is :mod:`regimemap.lifetime.figures.chart`.

``make figures`` draws Goda's caisson with ``regimemap lifetime`` into
``figures/lifetime-goda.*`` and ``figures/lifetime-chart-goda.*``.

Most lifetimes do not slide at all and those that do spread over several decades, so the
sliding is drawn on logarithmic axes.  Labels are placed once the figure is laid out
(:class:`~regimemap.drawing.text.labelplacer.LabelPlacer`); colours, limits and numbers are
:mod:`regimemap.lifetime.figures.style`'s.  Nothing is computed here beyond the empirical
curves of the arrays.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ...drawing.save import DEFAULT_DPI
from ...drawing.style import agg_figure, key_below, label_axes, style_context
from ...drawing.text.labelplacer import (
    Candidate,
    LabelPlacer,
    Placed,
    corner_candidates,
    make_label,
    vline_label,
)
from ...drawing.verdict import draw_verdict_badge, verdict_colour
from ...records.checks import Check
from ..results import LifetimeResult
from .style import (
    BAND,
    BAR_EDGE,
    CLIMATE_DASHES,
    CLIMATE_FILL,
    CLIMATE_HATCH,
    CLIMATE_LINE,
    FILL,
    FS,
    LIFE,
    LIFE_LW,
    LIMIT,
    LIMIT_DASHES,
    OFF_MOUND,
    OFF_MOUND_HATCH,
    STORM,
    STORM_DASHES,
    STORM_LW,
    TOLERABLE,
    decade_range,
    draw_title_block,
    format_log_axis,
    impulsive_words,
    limit_text,
    metres,
    percent,
    title_height,
    value_pm,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..replicates import ClimateBand

__all__ = ["LIFETIME_FIGSIZE", "TOLERABLE", "draw_exceedance", "lifetime_figure",
           "lifetime_title", "sliding_range"]

#: Size of :func:`lifetime_figure` in inches (width: a page, two columns; height: without a
#: title and with a key of three rows, as the figure grows with them).
LIFETIME_FIGSIZE: tuple[float, float] = (7.0, 3.59)

FloatArray = NDArray[np.float64]


# -- the exceedance curve --------------------------------------------------------------------


def _steps(values: FloatArray, x_left: float) -> tuple[FloatArray, FloatArray] | None:
    """The empirical ``P(V > x)`` of ``values`` as a step line from ``x_left``, zeros left out.

    Returns None when no value is positive.  The curve starts at ``x_left`` (or at the smallest
    value, if smaller) at ``P(V > 0)``, drops at every distinct positive value and ends at the
    largest, at 1/n (that ``P(V > x)`` is 0 beyond it cannot be drawn on a log axis).
    Draw it with ``drawstyle="steps-post"``.
    """
    v = np.sort(np.asarray(values, dtype=np.float64))
    n = v.size
    pos = v[v > 0.0]
    if n == 0 or pos.size == 0:
        return None
    x = np.unique(pos)
    p = 1.0 - np.searchsorted(v, x, side="right") / n
    xs = np.concatenate([[min(x_left, float(x[0]))], x])
    ps = np.concatenate([[pos.size / n], p])
    ps[-1] = ps[-2]  # P = 1/n up to the largest value, where the line ends
    return xs, ps




#: The sliding axis spans at most this many decades (below it: "slid less than ...").
_DECADES = 6


def sliding_range(result: LifetimeResult) -> tuple[float, float]:
    """The sliding axis of a result: whole decades around the slides, the limits and the ESD.

    At most six decades, counted down from the largest slide; without any slide, 0.001-10 m.
    """
    marks = [lim for lim, _ in TOLERABLE]
    vals = np.concatenate([result.sliding, result.max_storm])
    vals = vals[vals > 0.0]
    if vals.size == 0:
        return 1e-3, 10.0
    lo = min(float(np.min(vals)), *marks)
    hi = max(float(np.max(vals)), result.expected_sliding, *marks)
    lo, hi = decade_range(lo, hi)
    return max(lo, hi / 10.0**_DECADES), hi


def _esd_text(result: LifetimeResult) -> str:
    return f"ESD = {value_pm(result.expected_sliding, result.std_error)} m"


def _esd_check(result: LifetimeResult) -> Check | None:
    """The requirement on the ESD, if the result was judged on it (not on a climate band)."""
    return next((c for c in result.checks if c.name == "expected sliding distance"), None)


def _band_check(result: LifetimeResult) -> Check | None:
    """The requirement on the ESD including the climate's uncertainty, if judged on it."""
    return next((c for c in result.checks if c.name == "ESD including the climate's uncertainty"), None)


def _band_esd_text(band: ClimateBand) -> str:
    return f"with the climate: ESD = {value_pm(band.expected_sliding, band.std_error)} m"


def _draw_climate_band(ax: Axes, band: ClimateBand, y0: float) -> None:
    """The band of ``P(S > x)`` over the replicate climates (its lower end clipped to the axis's
    bottom ``y0``), hatched, under the curves; their mean, dashed, over them; the ESD including
    the climate's uncertainty, a vertical line."""
    x, lo, mean, hi = band.curve_band()
    x0, x1 = ax.get_xlim()
    keep = (x >= x0 / 1.2) & (x <= x1 * 1.2) & (hi > 0.0)
    if np.any(keep):
        ax.fill_between(x[keep], np.maximum(lo[keep], y0), hi[keep], facecolor=CLIMATE_FILL,
                        edgecolor=CLIMATE_LINE, hatch=CLIMATE_HATCH, lw=0.0, zorder=0.8, gid="climate-band")
        m = np.where(mean[keep] > 0.0, mean[keep], np.nan)
        ax.plot(x[keep], m, color=CLIMATE_LINE, lw=1.1, dashes=CLIMATE_DASHES, zorder=4.8,
                gid="climate-mean")
    if band.expected_sliding > 0.0:
        ax.axvline(band.expected_sliding, color=CLIMATE_LINE, lw=1.1, zorder=2.6, gid="climate-esd")


def lifetime_title(section: str, result: LifetimeResult) -> str:
    """The title of :func:`lifetime_figure`: the section and its width, then the run's facts."""
    return (f"{section}: caisson $b$ = {result.width:g} m, {result.years}-year life\n"
            f"{result.trials} lifetimes, seed {result.seed}, {impulsive_words(result.impulsive)}")




def _reference_lines(ax: Axes, result: LifetimeResult, zorder: float = 2.0) -> None:
    """The tolerable limits and the ESD (with its band of one standard error), vertical; the zone
    off the mound (beyond the sliding limit) shaded and hatched when a lifetime slid into it."""
    f = result.failure
    if f is not None and f.probability > 0.0 and f.sliding_limit < ax.get_xlim()[1]:
        ax.axvspan(f.sliding_limit, ax.get_xlim()[1], facecolor=OFF_MOUND, edgecolor="#999933",
                   hatch=OFF_MOUND_HATCH, lw=0.0, zorder=0.3)
        ax.axvline(f.sliding_limit, color="#999933", lw=0.9, zorder=zorder)
    for (lim, _), dashes in zip(TOLERABLE, LIMIT_DASHES):
        ax.axvline(lim, color=LIMIT, lw=0.8, dashes=dashes, zorder=zorder)
    esd, se = result.expected_sliding, result.std_error
    if esd > 0.0:
        if math.isfinite(se) and se > 0.0:
            x0 = ax.get_xlim()[0]
            ax.axvspan(max(esd - se, 1e-3 * x0), esd + se, facecolor=BAND, edgecolor="none",
                       zorder=0.5)
        ax.axvline(esd, color="black", lw=1.1, zorder=zorder + 0.5)


def draw_exceedance(ax: Axes, result: LifetimeResult, *, storm: bool = True,
                    fontsize: float = FS, labels: bool = True, band: ClimateBand | None = None) -> Placed:
    """Draw the exceedance curve of a lifetime result on ``ax``; return its labels to place.

    The step curve ``P(S > x)`` of the lifetime sliding (log-log), and with ``storm`` that of
    the largest single-storm slide of each lifetime (Kim & Suh 2013); the ESD as a vertical line
    over a band of one standard error, and the tolerable limits of :data:`TOLERABLE` as vertical
    lines; with a wave record's climate ``band``, the band of ``P(S > x)`` over its replicate
    climates (green, hatched, under the curves; artist gid ``climate-band``), their mean
    (``climate-mean``, green dashes) and the ESD including the climate's uncertainty
    (``climate-esd``, a green vertical line); with ``labels``, the lines' labels (``0.1 m``,
    ``ESD = 1.14 ± 0.14 m``), returned with their candidate places for :meth:`LabelPlacer.place`
    (the caller places them once the figure is laid out).  When no lifetime slid, the panel
    says so.
    """
    n = result.trials
    x0, x1 = sliding_range(result)
    if band is not None and band.expected_sliding > x1:  # the ESD with the climate in view
        x1 = 10.0 ** math.ceil(math.log10(band.expected_sliding))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(x0, x1)
    y0 = 10.0 ** math.floor(math.log10(0.5 / max(n, 1)))
    ax.set_ylim(y0, 1.0)
    placed: Placed = []
    if band is not None:
        _draw_climate_band(ax, band, y0)
    life = _steps(result.sliding, x0)
    if life is not None:
        ax.plot(*life, drawstyle="steps-post", color=LIFE, lw=LIFE_LW, zorder=4, label="lifetime")
    if storm:
        st = _steps(result.max_storm, x0)
        if st is not None:
            ax.plot(*st, drawstyle="steps-post", color=STORM, lw=STORM_LW, dashes=STORM_DASHES,
                    zorder=4.5, label="storm")
    _reference_lines(ax, result)
    if labels:  # the ESD's first: it has the most to say
        if result.expected_sliding > 0.0:
            text = ("fitted climate: " if band is not None else "") + _esd_text(result)
            check = _esd_check(result)
            placed.append(vline_label(
                ax, result.expected_sliding, text, fontsize=fontsize - 0.5,
                color="black" if check is None else verdict_colour(check),
                texts=[text.replace(" \u00b1", "\n\u00b1", 1)] if "\u00b1" in text else []))
        if band is not None and band.expected_sliding > 0.0:
            text = _band_esd_text(band)
            check = _band_check(result)
            placed.append(vline_label(
                ax, band.expected_sliding, text, fontsize=fontsize - 0.5,
                color=CLIMATE_LINE if check is None or check.passed else verdict_colour(check),
                texts=[text.replace(": ", ":\n", 1)]))
        placed += [vline_label(ax, lim, limit_text(lim), fontsize=fontsize - 0.5, color="0.15", side_first=-1)
                   for lim, _ in TOLERABLE]
    if life is None:
        t = make_label(ax, f"no lifetime slid\n(0 of {n}): ESD = 0 m", xycoords="axes fraction",
                   fontsize=fontsize)
        t.set_multialignment("center")
        t.get_bbox_patch().set(edgecolor="0.6", linewidth=0.6, alpha=1.0)
        t.set_gid("boxed")
        placed.insert(0, (t, [Candidate((0.5, 0.5), (0.0, 0.0), "center", "center"),
                              *corner_candidates()], []))
    format_log_axis(ax, "x")
    format_log_axis(ax, "y")
    label_axes(ax, "sliding $x$ (m)", f"$P(S > x)$ in {result.years} years", fontsize)
    return placed


# -- the histogram ---------------------------------------------------------------------------


def _draw_histogram(ax: Axes, result: LifetimeResult, xlim: tuple[float, float],
                    fontsize: float = FS) -> tuple[list[tuple[float, float, float]], int]:
    """Histogram of the lifetimes that slid, log-spaced bins, on the sliding axis ``xlim``.

    Returns the bars (left, right, count) and the number of lifetimes that slid less than the
    axis starts at (not drawn).
    """
    pos = result.sliding[result.sliding > 0.0]
    below = int(np.count_nonzero(pos < xlim[0]))
    shown = pos[pos >= xlim[0]]
    bars: list[tuple[float, float, float]] = []
    ax.set_xscale("log")
    if shown.size:
        lo, hi = float(np.min(shown)), float(np.max(shown))
        if hi <= lo * 1.01:
            lo, hi = lo / 1.5, hi * 1.5
        nbins = int(np.clip(round(4.0 * math.log10(hi / lo)), 6, 40))
        edges = np.geomspace(lo, hi, nbins + 1)
        counts, _ = np.histogram(shown, bins=edges)
        ax.stairs(counts, edges, fill=True, facecolor=FILL, edgecolor="none", zorder=2)
        ax.stairs(counts, edges, fill=False, edgecolor=BAR_EDGE, lw=0.8, zorder=3)
        bars = [(float(a), float(b), float(c)) for a, b, c in zip(edges[:-1], edges[1:], counts)]
        from matplotlib.ticker import MaxNLocator

        ax.yaxis.set_major_locator(MaxNLocator(nbins=5, integer=True))
        ax.set_ylim(0.0, float(np.max(counts)) * 1.8)  # room for the note above the bars
    else:
        ax.set_ylim(0.0, 1.0)
        ax.set_yticks([0.0])
    ax.set_xlim(*xlim)
    _reference_lines(ax, result, zorder=1.0)
    format_log_axis(ax, "x")
    label_axes(ax, "lifetime sliding $S$ (m)", "lifetimes", fontsize)
    return bars, below


def _never_texts(result: LifetimeResult, below: int, x0: float) -> list[str]:
    """What the histogram leaves out, in words: a wide, a medium and a narrow wording."""
    n = result.trials
    still = int(np.count_nonzero(result.sliding == 0.0))
    if still == n:
        return [f"no lifetime slid:\nall {n} rest", f"no lifetime\nslid: all\n{n} rest"]
    share = percent(still / n)
    wide = [f"{share} of {n} lifetimes", "did not slide (not drawn)"]
    medium = [f"{share} of {n}", "lifetimes did not", "slide (not drawn)"]
    narrow = [f"{share} of", f"{n} lifetimes", "did not slide", "(not drawn)"]
    if below:
        wide.append(f"{below} slid < {x0:g} m")
        medium.append(f"{below} slid < {x0:g} m")
        narrow += [f"{below} slid", f"< {x0:g} m"]
    return ["\n".join(wide), "\n".join(medium), "\n".join(narrow)]


# -- the figures -----------------------------------------------------------------------------


def _legend_handles(result: LifetimeResult, storm: bool = True, band: ClimateBand | None = None) -> list[Any]:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    h: list[Any] = []
    if np.any(result.sliding > 0.0):
        h.append(Line2D([], [], color=LIFE, lw=LIFE_LW,
                        label=f"lifetime sliding $S$: $P(S > x)$ over {result.years} years"))
    if storm and np.any(result.max_storm > 0.0):
        h.append(Line2D([], [], color=STORM, lw=STORM_LW, dashes=STORM_DASHES,
                        label="largest slide of one storm (Kim & Suh 2013)"))
    if result.expected_sliding > 0.0:
        esd = Line2D([], [], color="black", lw=1.1)
        if math.isfinite(result.std_error) and result.std_error > 0.0:
            se_patch = Patch(facecolor=BAND, edgecolor="none")
            h.append(((se_patch, esd), "expected sliding distance (ESD) \u00b1 1 standard error"))
        else:
            h.append((esd, "expected sliding distance (ESD)"))
    if band is not None:
        h.append((Patch(facecolor=CLIMATE_FILL, edgecolor=CLIMATE_LINE, hatch=CLIMATE_HATCH, lw=0.0),
                  f"{100 * band.level:g} % band over {band.replicates} climates of the record"))
        h.append(Line2D([], [], color=CLIMATE_LINE, lw=1.1, dashes=CLIMATE_DASHES,
                        label="including the climate's uncertainty (their mean)"))
        if band.expected_sliding > 0.0:
            h.append(Line2D([], [], color=CLIMATE_LINE, lw=1.1,
                            label=f"its ESD ({100 * band.level:g} % band {metres(band.lower)}\u2013"
                                  f"{metres(band.upper)} m)"))
    for (lim, source), dashes in zip(TOLERABLE, LIMIT_DASHES):
        h.append(Line2D([], [], color=LIMIT, lw=0.8, dashes=dashes,
                        label=f"tolerable ESD {limit_text(lim, source)}"))
    f = result.failure
    if f is not None and f.probability > 0.0:
        h.append((Patch(facecolor=OFF_MOUND, edgecolor="#999933", hatch=OFF_MOUND_HATCH, lw=0.0),
                  f"off the mound ($S$ > {f.sliding_limit:g} m): failure "
                  f"{percent(f.probability)} \u00b1 {percent(f.std_error)}"))
    elif f is not None:
        h.append((Patch(facecolor="none", edgecolor="none"),
                  f"no lifetime slid off the mound ($S$ > {f.sliding_limit:g} m)"))
    return h


def lifetime_figure(result: LifetimeResult, title: str | None = None, *, dpi: float = DEFAULT_DPI,
                    band: ClimateBand | None = None) -> Figure:
    """The sliding of one caisson over its design life: exceedance curve and histogram.

    (a) The exceedance probability ``P(S > x)`` of the lifetime sliding ``S`` (log-log) and of
    the largest slide of a single storm in a lifetime (Kim & Suh 2013), the ESD with its
    standard error and the tolerable limits of :data:`TOLERABLE`; (b) the histogram of the
    lifetimes that slid (log-spaced bins) on the same sliding axis, with the share that did not
    slide written in the panel.  The key, below the panels, names the sources.

    Parameters
    ----------
    result : LifetimeResult
        From :func:`regimemap.lifetime.lifetime_sliding`.
    title : str, optional
        Written at the top left (none by default: a paper has a caption); its first line
        larger, the others (:func:`lifetime_title`: the run's facts) below it.
    dpi : float
        Resolution of PNG output.
    band : ClimateBand, optional
        The lifetimes under a wave record's replicate climates: (a) draws the band of
        ``P(S > x)`` over them, its mean and the ESD including the climate's uncertainty
        (:func:`draw_exceedance`), and the key gives the ESD's band.

    Returns
    -------
    Figure
        Axes labelled ``exceedance`` and ``histogram`` (Agg canvas, no pyplot).

    Notes
    -----
    A judged result (:func:`regimemap.lifetime.judge_lifetime`) has a PASS or FAIL badge at
    the top right and its ESD label in the fail colour when the ESD fails its target; with a
    sliding limit, the zone off the mound is shaded and hatched and the key gives the
    probability of failure.
    """

    handles = _legend_handles(result, band=band)
    rows = (len(handles) + 1) // 2
    w = LIFETIME_FIGSIZE[0]
    key = 0.08 + 0.17 * rows
    top = 0.3 + max(title_height(title), 0.32 if result.checks else 0.0)
    bottom, left, gap, right, ah = 0.45 + key, 0.62, 0.72, 0.25, 2.25
    h = top + ah + bottom
    with style_context():
        fig = agg_figure(figsize=(w, h), dpi=dpi)
        aw = (w - left - gap - right) / 2.0
        ax_a = fig.add_axes((left / w, bottom / h, aw / w, ah / h), label="exceedance")
        ax_b = fig.add_axes(((left + aw + gap) / w, bottom / h, aw / w, ah / h), label="histogram")
        placed = draw_exceedance(ax_a, result, band=band)
        ax_a.set_title("(a) probability of exceedance", fontsize=FS + 0.5, loc="left")
        bars, below = _draw_histogram(ax_b, result, ax_a.get_xlim())
        ax_b.set_title("(b) the lifetimes that slid", fontsize=FS + 0.5, loc="left")
        key_below(fig, [k if isinstance(k, tuple) else (k, k.get_label()) for k in handles], 0.06 / h,
                  FS - 0.5, columnspacing=1.6)
        if title:
            draw_title_block(fig, title, h)
        draw_verdict_badge(fig, result.checks, x=1.0 - 0.1 / w, y=1.0 - 0.1 / h, fontsize=FS + 1.0)
        never_texts = _never_texts(result, below, ax_a.get_xlim()[0])
        never = make_label(ax_b, never_texts[0], xycoords="axes fraction")
        never_at = corner_candidates()
        if not bars:
            never.set_multialignment("center")
            never_at = [Candidate((0.5, 0.5), (0.0, 0.0), "center", "center"), *never_at]
        with LabelPlacer(fig) as placer:
            for ax in (ax_a, ax_b):
                placer.avoid_lines_of(ax)
            for x_lo, x_hi, c in bars:  # the bars' outlines
                placer.avoid_line(ax_b, [x_lo, x_lo, x_hi, x_hi], [0.0, c, c, 0.0])
            placer.place(ax_b, never, never_at, texts=never_texts[1:])
            placer.place_all(ax_a, placed)
    return fig
