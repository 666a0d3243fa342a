"""Figures of :mod:`regimemap.lifetime`: the sliding of a caisson over its design life.

* :func:`lifetime_figure` -- one :class:`~regimemap.lifetime.LifetimeResult`: (a) the
  exceedance curve ``P(S > x)`` of the lifetime sliding, with Kim & Suh's single-storm curve,
  the expected sliding distance (ESD) with its standard error and the tolerable limits, and
  (b) the histogram of the lifetimes that slid (log-spaced bins; those that did not are counted
  in words);
* :func:`chart_figure` -- a :class:`~regimemap.lifetime.DesignChart`: ESD against width with
  a band of two standard errors, the tolerable limits and the target, the width meeting the
  target and the width of Goda's deterministic design (SF = 1.2 under the 50-year wave);
* :func:`draw_exceedance` -- the exceedance panel on any axes (the design sheet uses it).

``make figures`` draws Goda's caisson with ``regimemap lifetime`` into
``figures/lifetime-goda.*`` and ``figures/lifetime-chart-goda.*``.

Most lifetimes do not slide at all and those that do spread over several decades, so the
sliding is drawn on logarithmic axes.  Labels are placed once the figure is laid out
(:class:`LabelPlacer`): each goes to the first of its candidate places that is inside its
axes, clear of every other text and clear of the curves; the texts are measured at
:data:`regimemap.drawing.tidy.MEASURE_DPI`, so an SVG or PDF does not depend on the
resolution of a PNG.  Nothing is computed here beyond the empirical curves of the arrays.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..lifetime.chart import DesignChart
from ..lifetime.results import LifetimeResult
from ..maps.describe import format_significant
from .save import DEFAULT_DPI
from .style import style_context
from .tidy import MEASURE_DPI

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure
    from matplotlib.text import Text

__all__ = [
    "CHART_FIGSIZE", "LIFETIME_FIGSIZE", "TOLERABLE", "LabelPlacer", "Placed",
    "chart_figure", "draw_exceedance", "figure_texts", "lifetime_figure",
    "sliding_range",
]

#: Size of :func:`lifetime_figure` in inches (width: a page, two columns; height: without a
#: title and with a key of three rows, as the figure grows with them).
LIFETIME_FIGSIZE: tuple[float, float] = (7.0, 3.59)
#: Size of :func:`chart_figure` in inches (the same width; the same rule for the height).
CHART_FIGSIZE: tuple[float, float] = (7.0, 4.14)
#: The tolerable expected sliding distances [m] drawn on every figure, with their source.
TOLERABLE: tuple[tuple[float, str], ...] = (
    (0.1, "Goda & Takagi 2000"),
    (0.3, "Shimosako & Takahashi 1999"),
)

# Paul Tol's colour-blind-safe schemes: the lifetime curve a wide light blue (*medium
# contrast*), the single-storm curve dark red dashes on top of it (visible where the two
# coincide: one storm often makes the whole of a lifetime's slide), the ESD black; the light
# blue of his *light* scheme for fills.
_LIFE = "#6699CC"
_LIFE_LW = 2.2
_STORM = "#994455"
_STORM_LW = 1.0
_STORM_DASHES = (3.0, 1.8)
_FILL = "#BBCCEE"
_BAR_EDGE = "#2F5F8F"
_BAND = "0.86"  # one standard error about the ESD
_TARGET = "#BB5566"  # the target ESD and the width meeting it
_TARGET_TEXT = "#993344"  # the same, dark enough for text
_LIMIT = "0.25"
_ESD_LINE = "#004488"  # the chart's ESD: Tol's high-contrast dark blue
#: Dashes of the width of Goda's deterministic design (dash-dot-dot).
_SF_DASHES = (6.0, 1.8, 1.2, 1.8, 1.2, 1.8)
#: Line styles of the tolerable limits (0.1 m, 0.3 m): dashed and dash-dotted.
_LIMIT_DASHES: tuple[tuple[float, ...], ...] = ((5.0, 2.5), (6.0, 2.0, 1.2, 2.0))
_FS = 8.0  # axis labels; tick labels and the lines' labels half a point smaller
#: Gap (pixels at MEASURE_DPI) kept between two texts and between a text and a curve.
_GAP = 2.0

Box = tuple[float, float, float, float]
FloatArray = NDArray[np.float64]


# -- numbers ---------------------------------------------------------------------------------


def _g(x: float, digits: int = 3) -> str:
    return format_significant(x, digits).replace("-", "\u2212")


def _metres(x: float) -> str:
    """A length for a label: ``1.14``, ``0.0305``, ``284`` (three significant digits)."""
    return _g(x, 3)


def _value_pm(value: float, se: float) -> str:
    """``value ± se``, the standard error to two significant digits and the value to match."""
    if not math.isfinite(se) or se <= 0.0 or value <= 0.0:
        return _metres(value)
    decimals = max(0, 1 - int(math.floor(math.log10(se))))
    if decimals > 6:  # a tiny error: write both in three significant digits
        return f"{_metres(value)} \u00b1 {_g(se, 2)}"
    return f"{value:.{decimals}f} \u00b1 {se:.{decimals}f}"


def _percent(p: float) -> str:
    """A share in per cent for a label: ``89.6 %``, ``0.04 %``, ``100 %``."""
    v = 100.0 * p
    if v == 0.0 or v == 100.0:
        return f"{v:.0f} %"
    if v >= 10.0:
        return f"{v:.1f} %"
    return f"{format_significant(v, 2)} %"


# -- the texts of a figure and a placer for labels ----------------------------------------


def figure_texts(fig: Figure) -> list[Text]:
    """Every text a figure draws: tick labels in view, axis labels, titles, legends, free texts.

    The texts that :class:`LabelPlacer` keeps apart and the tests measure.
    """
    out: list[Any] = []

    def add(t: Any) -> None:
        if (t is not None and t.get_visible() and t.get_text().strip()
                and not any(t is s for s in out)):
            out.append(t)

    for t in fig.texts:
        add(t)
    sup = getattr(fig, "_suptitle", None)
    add(sup)
    for leg in fig.legends:
        if leg.get_visible():
            for t in leg.get_texts():
                add(t)
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        if ax.axison:
            for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
                lo, hi = min(lim), max(lim)
                tol = 1e-9 * (hi - lo)
                for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                    loc = tick.get_loc()
                    if loc is None or not (lo - tol <= loc <= hi + tol):
                        continue
                    if axis.get_scale() == "log" and not lo * (1 - 1e-9) <= loc <= hi * (1 + 1e-9):
                        continue
                    add(tick.label1)
                    add(tick.label2)
            add(ax.xaxis.label)
            add(ax.yaxis.label)
        for name in ("title", "_left_title", "_right_title"):
            add(getattr(ax, name, None))
        for t in ax.texts:
            add(t)
        ax_leg = ax.get_legend()
        if ax_leg is not None and ax_leg.get_visible():
            for t in ax_leg.get_texts():
                add(t)
    return out


def _box(t: Any, renderer: RendererBase, pad: float = 0.0) -> Box:
    bb = t.get_window_extent(renderer)
    return (bb.x0 - pad, bb.y0 - pad, bb.x1 + pad, bb.y1 + pad)


def _hit(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _inside(a: Box, b: Box) -> bool:
    return a[0] >= b[0] and a[1] >= b[1] and a[2] <= b[2] and a[3] <= b[3]


def _dense(xy: FloatArray, step: float = 1.0) -> FloatArray:
    """A polyline (pixels) with vertices at most ``step`` apart; NaN vertices break it."""
    parts = []
    for a, b in zip(xy[:-1], xy[1:]):
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            continue
        n = max(1, int(math.ceil(float(np.hypot(*(b - a))) / step)))
        parts.append(a + (np.arange(0, n + 1) / n)[:, None] * (b - a))
    if not parts:
        finite = xy[np.all(np.isfinite(xy), axis=1)]
        return np.asarray(finite, dtype=np.float64).reshape(-1, 2)
    return np.concatenate(parts)


@dataclass
class _Candidate:
    xy: tuple[float, float]
    offset: tuple[float, float]
    ha: str
    va: str


class LabelPlacer:
    """Put labels where they meet no other text and no curve, inside their axes.

    Create it once the figure's axes, curves and fixed texts are drawn; the texts already in the
    figure (:func:`figure_texts`) are taken.  :meth:`avoid` adds curves (lines and the outlines
    of bars); :meth:`place` moves an annotation (offset in points from a point ``xy``) to the first
    free one of its candidates.  Measured at :data:`~regimemap.drawing.tidy.MEASURE_DPI`: call
    :meth:`close` to restore the figure's resolution.
    """

    def __init__(self, fig: Figure) -> None:
        self.fig = fig
        self._dpi = fig.dpi
        fig.set_dpi(MEASURE_DPI)
        self.renderer: RendererBase = fig.canvas.get_renderer()  # type: ignore[attr-defined]
        fig.draw_without_rendering()
        self.taken: list[Box] = [_box(t, self.renderer, _GAP / 2) for t in figure_texts(fig)]
        self.points: list[FloatArray] = []
        fb = fig.bbox
        self.frame: Box = (fb.x0 + _GAP, fb.y0 + _GAP, fb.x1 - _GAP, fb.y1 - _GAP)

    def close(self) -> None:
        self.fig.set_dpi(self._dpi)

    def avoid_line(self, ax: Axes, x: Sequence[float] | FloatArray, y: Sequence[float] | FloatArray,
                   transform: Any = None) -> None:
        """A curve (data coordinates, or ``transform``'s) that labels keep clear of."""
        tr = ax.transData if transform is None else transform
        xy = np.column_stack([np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)])
        with np.errstate(divide="ignore", invalid="ignore"):
            pix = np.asarray(tr.transform(xy), dtype=np.float64)
        bb = ax.bbox
        dense = _dense(pix)
        keep = ((dense[:, 0] >= bb.x0 - 1) & (dense[:, 0] <= bb.x1 + 1)
                & (dense[:, 1] >= bb.y0 - 1) & (dense[:, 1] <= bb.y1 + 1))
        self.points.append(dense[keep])

    def avoid_lines_of(self, ax: Axes) -> None:
        """Every line of ``ax`` (curves, reference lines, markers) is an obstacle for labels."""
        for ln in ax.get_lines():
            if not ln.get_visible():
                continue
            x = np.asarray(ln.get_xdata(), dtype=np.float64)
            y = np.asarray(ln.get_ydata(), dtype=np.float64)
            tr = ln.get_transform()
            if ln.get_linestyle() in ("None", "none", "", " "):  # markers only
                r = 0.5 * ln.get_markersize() * self.fig.dpi / 72.0 + 1.0
                with np.errstate(divide="ignore", invalid="ignore"):
                    pix = tr.transform(np.column_stack([x, y]))
                for px, py in pix:
                    if np.isfinite(px) and np.isfinite(py):
                        self.avoid_box((px - r, py - r, px + r, py + r))
                continue
            if ln.get_drawstyle() == "steps-post" and x.size > 1:  # the steps as drawn
                x, y = np.repeat(x, 2)[1:], np.repeat(y, 2)[:-1]
            self.avoid_line(ax, x, y, transform=tr)

    def avoid_box(self, box: Box) -> None:
        """A box (pixels at the placer's resolution) that labels keep clear of."""
        self.taken.append(box)

    def _clear_of_lines(self, b: Box) -> bool:
        x0, y0, x1, y1 = b
        for p in self.points:
            if p.size and bool(np.any((p[:, 0] > x0) & (p[:, 0] < x1) & (p[:, 1] > y0)
                                      & (p[:, 1] < y1))):
                return False
        return True

    def place(self, ax: Axes, t: Any, candidates: Iterable[_Candidate], *,
              texts: Sequence[str] = (), lines: bool = True) -> bool:
        """Move the annotation ``t`` to its first free candidate; hide it if none is free.

        A candidate is free when the label is inside the axes (and the figure), meets no text
        taken so far and (with ``lines``) no curve.  ``texts`` are other wordings of the label
        (e.g. narrower), tried in turn at every candidate.  When every candidate meets a curve,
        the first one clear of texts is used, on its white box; a label clear of every curve
        loses its box (unless its gid is ``"boxed"``).  Returns False when the label was hidden.
        """
        bb = ax.bbox
        within: Box = (bb.x0 + 1.0, bb.y0 + 1.0, bb.x1 - 1.0, bb.y1 - 1.0)
        cands = list(candidates)
        variants = [t.get_text(), *texts]
        for need_clear in ((True, False) if lines else (False,)):
            for text in variants:
                t.set_text(text)
                for c in cands:
                    t.xy = c.xy
                    t.xyann = c.offset
                    t.set_ha(c.ha)
                    t.set_va(c.va)
                    b = _box(t, self.renderer, _GAP / 2)
                    if not (_inside(b, within) and _inside(b, self.frame)):
                        continue
                    if any(_hit(b, o) for o in self.taken):
                        continue
                    if need_clear and not self._clear_of_lines(b):
                        continue
                    self.taken.append(b)
                    patch = t.get_bbox_patch()
                    if need_clear and patch is not None and t.get_gid() != "boxed":
                        patch.set_visible(False)
                    return True
        t.set_text(variants[0])
        t.set_visible(False)
        return False

    def place_legend(self, ax: Axes, leg: Any, locs: Sequence[str]) -> bool:
        """Put an axes' legend at the first of ``locs`` clear of texts and curves (else the first)."""
        for loc in locs:
            leg.set_loc(loc)
            b = _box(leg, self.renderer, _GAP / 2)
            if any(_hit(b, o) for o in self.taken) or not self._clear_of_lines(b):
                continue
            self.taken.append(b)
            return True
        leg.set_loc(locs[0])
        self.taken.append(_box(leg, self.renderer, _GAP / 2))
        return False


def _vline_candidates(x: float, side_first: int = 1) -> list[_Candidate]:
    """Places of the rotated label of a vertical line at ``x``: beside it, from the bottom or
    the top of the axes inwards, on either side."""
    sides = (side_first, -side_first)
    order: list[tuple[float, str]] = [(0.03, "bottom"), (0.97, "top")]
    for k in range(1, 10):
        order += [(0.03 + 0.05 * k, "bottom"), (0.97 - 0.05 * k, "top")]
    return [_Candidate((x, y), (2.5 * side, 0.0), "left" if side > 0 else "right", va)
            for y, va in order for side in sides]


def _hline_candidates(y: float, xs: Sequence[float] = (0.98, 0.02, 0.75, 0.5, 0.25)
                      ) -> list[_Candidate]:
    """Places of the label of a horizontal line at ``y``: above or below it, at ``xs`` (axes)."""
    out = []
    for sy in (1, -1):
        for x in xs:
            ha = "right" if x > 0.6 else ("left" if x < 0.4 else "center")
            out.append(_Candidate((x, y), (0.0, 1.5 * sy), ha, "bottom" if sy > 0 else "top"))
    return out


def _corner_candidates(inset: float = 0.03) -> list[_Candidate]:
    """The four corners of the axes, then the middles of the top and bottom edges."""
    lo, hi = inset, 1.0 - inset
    return [_Candidate((x, y), (0.0, 0.0), ha, va)
            for (y, va) in ((hi, "top"), (lo, "bottom"))
            for (x, ha) in ((hi, "right"), (lo, "left"), (0.5, "center"))]


def _label(ax: Axes, text: str, *, xycoords: Any = "data", rotation: float = 0.0,
           fontsize: float = _FS, color: str = "black") -> Any:
    """An annotation to be placed by :class:`LabelPlacer` (at the origin until then).

    It has a white box, which :meth:`LabelPlacer.place` removes when the label is clear of
    every line.
    """
    bbox = {"boxstyle": "square,pad=0.12", "fc": "white", "ec": "none", "alpha": 0.85}
    t = ax.annotate(text, (0.0, 0.0), xycoords=xycoords, xytext=(0.0, 0.0),
                    textcoords="offset points", rotation=rotation, rotation_mode="default",
                    fontsize=fontsize, color=color, bbox=bbox, zorder=6, annotation_clip=False)
    t.set_multialignment("left" if rotation == 0.0 else "center")
    return t


#: Labels to place: (annotation, its candidate places, other wordings of it).
Placed = list[tuple[Any, list[_Candidate], list[str]]]


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


def _decade_range(lo: float, hi: float) -> tuple[float, float]:
    return 10.0 ** math.floor(math.log10(lo)), 10.0 ** math.ceil(math.log10(hi))


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
    lo, hi = _decade_range(lo, hi)
    return max(lo, hi / 10.0**_DECADES), hi


def _format_log_axis(ax: Axes, axis: str = "x") -> None:
    """Decades labelled as plain numbers where short (0.01 ... 1000), else as powers of ten."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    def fmt(v: float, _pos: int | None = None) -> str:
        if v <= 0:
            return ""
        e = int(round(math.log10(v)))
        if abs(math.log10(v) - e) > 1e-6:
            return ""
        if -2 <= e <= 3:
            return f"{v:g}"
        return f"$10^{{{e}}}$".replace("-", "\u2212")

    a = ax.xaxis if axis == "x" else ax.yaxis
    a.set_major_locator(LogLocator(base=10.0, numticks=12))
    a.set_major_formatter(FuncFormatter(fmt))
    a.set_minor_locator(LogLocator(base=10.0, subs=tuple(np.arange(2, 10) * 0.1), numticks=12))
    a.set_minor_formatter(NullFormatter())


def _esd_text(result: LifetimeResult) -> str:
    return f"ESD = {_value_pm(result.expected_sliding, result.std_error)} m"


def _limit_text(lim: float, source: str | None = None) -> str:
    return f"{lim:g} m" + (f" ({source})" if source else "")


def _reference_lines(ax: Axes, result: LifetimeResult, zorder: float = 2.0) -> None:
    """The tolerable limits and the ESD (with its band of one standard error), vertical."""
    for (lim, _), dashes in zip(TOLERABLE, _LIMIT_DASHES):
        ax.axvline(lim, color=_LIMIT, lw=0.8, dashes=dashes, zorder=zorder)
    esd, se = result.expected_sliding, result.std_error
    if esd > 0.0:
        if math.isfinite(se) and se > 0.0:
            x0 = ax.get_xlim()[0]
            ax.axvspan(max(esd - se, 1e-3 * x0), esd + se, facecolor=_BAND, edgecolor="none",
                       zorder=0.5)
        ax.axvline(esd, color="black", lw=1.1, zorder=zorder + 0.5)


def draw_exceedance(ax: Axes, result: LifetimeResult, *, storm: bool = True,
                    fontsize: float = _FS, labels: bool = True) -> Placed:
    """Draw the exceedance curve of a lifetime result on ``ax``; return its labels to place.

    The step curve ``P(S > x)`` of the lifetime sliding (log-log), and with ``storm`` that of
    the largest single-storm slide of each lifetime (Kim & Suh 2013); the ESD as a vertical line
    over a band of one standard error, and the tolerable limits of :data:`TOLERABLE` as vertical
    lines; with ``labels``, the lines' labels (``0.1 m``, ``ESD = 1.14 ± 0.14 m``), returned
    with their candidate places for :meth:`LabelPlacer.place` (the caller places them once the
    figure is laid out).  When no lifetime slid, the panel says so.
    """
    n = result.trials
    x0, x1 = sliding_range(result)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(x0, x1)
    ax.set_ylim(10.0 ** math.floor(math.log10(0.5 / max(n, 1))), 1.0)
    placed: Placed = []
    life = _steps(result.sliding, x0)
    if life is not None:
        ax.plot(*life, drawstyle="steps-post", color=_LIFE, lw=_LIFE_LW, zorder=4, label="lifetime")
    if storm:
        st = _steps(result.max_storm, x0)
        if st is not None:
            ax.plot(*st, drawstyle="steps-post", color=_STORM, lw=_STORM_LW, dashes=_STORM_DASHES,
                    zorder=4.5, label="storm")
    _reference_lines(ax, result)
    if labels:  # the ESD's first: it has the most to say
        if result.expected_sliding > 0.0:
            text = _esd_text(result)
            t = _label(ax, text, xycoords=ax.get_xaxis_transform(), rotation=90.0,
                       fontsize=fontsize - 0.5)
            placed.append((t, _vline_candidates(result.expected_sliding, side_first=1),
                           [text.replace(" \u00b1", "\n\u00b1", 1)] if "\u00b1" in text else []))
        for lim, _ in TOLERABLE:
            t = _label(ax, _limit_text(lim), xycoords=ax.get_xaxis_transform(), rotation=90.0,
                       fontsize=fontsize - 0.5, color="0.15")
            placed.append((t, _vline_candidates(lim, side_first=-1), []))
    if life is None:
        t = _label(ax, f"no lifetime slid\n(0 of {n}): ESD = 0 m", xycoords="axes fraction",
                   fontsize=fontsize)
        t.set_multialignment("center")
        t.get_bbox_patch().set(edgecolor="0.6", linewidth=0.6, alpha=1.0)
        t.set_gid("boxed")
        placed.insert(0, (t, [_Candidate((0.5, 0.5), (0.0, 0.0), "center", "center"),
                              *_corner_candidates()], []))
    _format_log_axis(ax, "x")
    _format_log_axis(ax, "y")
    ax.set_xlabel("sliding $x$ (m)", fontsize=fontsize)
    ax.set_ylabel(f"$P(S > x)$ in {result.years} years", fontsize=fontsize)
    ax.tick_params(labelsize=fontsize - 0.5)
    return placed


# -- the histogram ---------------------------------------------------------------------------


def _draw_histogram(ax: Axes, result: LifetimeResult, xlim: tuple[float, float],
                    fontsize: float = _FS) -> tuple[list[tuple[float, float, float]], int]:
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
        ax.stairs(counts, edges, fill=True, facecolor=_FILL, edgecolor="none", zorder=2)
        ax.stairs(counts, edges, fill=False, edgecolor=_BAR_EDGE, lw=0.8, zorder=3)
        bars = [(float(a), float(b), float(c)) for a, b, c in zip(edges[:-1], edges[1:], counts)]
        from matplotlib.ticker import MaxNLocator

        ax.yaxis.set_major_locator(MaxNLocator(nbins=5, integer=True))
        ax.set_ylim(0.0, float(np.max(counts)) * 1.8)  # room for the note above the bars
    else:
        ax.set_ylim(0.0, 1.0)
        ax.set_yticks([0.0])
    ax.set_xlim(*xlim)
    _reference_lines(ax, result, zorder=1.0)
    _format_log_axis(ax, "x")
    ax.set_xlabel("lifetime sliding $S$ (m)", fontsize=fontsize)
    ax.set_ylabel("lifetimes", fontsize=fontsize)
    ax.tick_params(labelsize=fontsize - 0.5)
    return bars, below


def _never_texts(result: LifetimeResult, below: int, x0: float) -> list[str]:
    """What the histogram leaves out, in words: a wide, a medium and a narrow wording."""
    n = result.trials
    still = int(np.count_nonzero(result.sliding == 0.0))
    if still == n:
        return [f"no lifetime slid:\nall {n} rest", f"no lifetime\nslid: all\n{n} rest"]
    share = _percent(still / n)
    wide = [f"{share} of {n} lifetimes", "did not slide (not drawn)"]
    medium = [f"{share} of {n}", "lifetimes did not", "slide (not drawn)"]
    narrow = [f"{share} of", f"{n} lifetimes", "did not slide", "(not drawn)"]
    if below:
        wide.append(f"{below} slid < {x0:g} m")
        medium.append(f"{below} slid < {x0:g} m")
        narrow += [f"{below} slid", f"< {x0:g} m"]
    return ["\n".join(wide), "\n".join(medium), "\n".join(narrow)]


# -- the figures -----------------------------------------------------------------------------


def _legend_handles(result: LifetimeResult, storm: bool = True) -> list[Any]:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    h: list[Any] = []
    if np.any(result.sliding > 0.0):
        h.append(Line2D([], [], color=_LIFE, lw=_LIFE_LW,
                        label=f"lifetime sliding $S$: $P(S > x)$ over {result.years} years"))
    if storm and np.any(result.max_storm > 0.0):
        h.append(Line2D([], [], color=_STORM, lw=_STORM_LW, dashes=_STORM_DASHES,
                        label="largest slide of one storm (Kim & Suh 2013)"))
    if result.expected_sliding > 0.0:
        esd = Line2D([], [], color="black", lw=1.1)
        if math.isfinite(result.std_error) and result.std_error > 0.0:
            band = Patch(facecolor=_BAND, edgecolor="none")
            h.append(((band, esd), "expected sliding distance (ESD) \u00b1 1 standard error"))
        else:
            h.append((esd, "expected sliding distance (ESD)"))
    for (lim, source), dashes in zip(TOLERABLE, _LIMIT_DASHES):
        h.append(Line2D([], [], color=_LIMIT, lw=0.8, dashes=dashes,
                        label=f"tolerable ESD {_limit_text(lim, source)}"))
    return h


def _add_legend(fig: Figure, handles: list[Any], y: float, fontsize: float) -> Any:
    arts, names = [], []
    for h in handles:
        if isinstance(h, tuple):
            arts.append(h[0])
            names.append(h[1])
        else:
            arts.append(h)
            names.append(h.get_label())
    return fig.legend(arts, names, loc="lower center", bbox_to_anchor=(0.5, y), ncols=2,
                      fontsize=fontsize, frameon=False, handlelength=2.6, columnspacing=1.6,
                      borderaxespad=0.0)


def lifetime_figure(result: LifetimeResult, title: str | None = None, *, dpi: float = DEFAULT_DPI
                    ) -> Figure:
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
        Written above the panels (none by default: a paper has a caption).
    dpi : float
        Resolution of PNG output.

    Returns
    -------
    Figure
        Axes labelled ``exceedance`` and ``histogram`` (Agg canvas, no pyplot).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    handles = _legend_handles(result)
    rows = (len(handles) + 1) // 2
    w = LIFETIME_FIGSIZE[0]
    key = 0.08 + 0.17 * rows
    top = 0.3 + (0.3 if title else 0.0)
    bottom, left, gap, right, ah = 0.45 + key, 0.62, 0.72, 0.25, 2.25
    h = top + ah + bottom
    with style_context():
        fig = Figure(figsize=(w, h), dpi=dpi)
        FigureCanvasAgg(fig)
        aw = (w - left - gap - right) / 2.0
        ax_a = fig.add_axes((left / w, bottom / h, aw / w, ah / h), label="exceedance")
        ax_b = fig.add_axes(((left + aw + gap) / w, bottom / h, aw / w, ah / h), label="histogram")
        placed = draw_exceedance(ax_a, result)
        ax_a.set_title("(a) probability of exceedance", fontsize=_FS + 0.5, loc="left")
        bars, below = _draw_histogram(ax_b, result, ax_a.get_xlim())
        ax_b.set_title("(b) the lifetimes that slid", fontsize=_FS + 0.5, loc="left")
        _add_legend(fig, handles, 0.06 / h, _FS - 0.5)
        if title:
            fig.text(0.5, 1.0 - 0.1 / h, title, fontsize=_FS + 1.5, ha="center", va="top")
        never_texts = _never_texts(result, below, ax_a.get_xlim()[0])
        never = _label(ax_b, never_texts[0], xycoords="axes fraction")
        never_at = _corner_candidates()
        if not bars:
            never.set_multialignment("center")
            never_at = [_Candidate((0.5, 0.5), (0.0, 0.0), "center", "center"), *never_at]
        placer = LabelPlacer(fig)
        try:
            for ax in (ax_a, ax_b):
                placer.avoid_lines_of(ax)
            for x_lo, x_hi, c in bars:  # the bars' outlines
                placer.avoid_line(ax_b, [x_lo, x_lo, x_hi, x_hi], [0.0, c, c, 0.0])
            placer.place(ax_b, never, never_at, texts=never_texts[1:])
            for t, cands, texts in placed:
                placer.place(ax_a, t, cands, texts=texts)
        finally:
            placer.close()
    return fig


def _chart_range(chart: DesignChart) -> tuple[float, float]:
    esd = np.asarray(chart.expected_sliding, dtype=np.float64)
    se = np.asarray(chart.std_error, dtype=np.float64)
    pos = esd > 0.0
    marks = [lim for lim, _ in TOLERABLE] + [chart.target]
    if not np.any(pos):
        return _decade_range(min(marks) / 10.0, max(marks) * 3.0)
    upper = esd + 2.0 * np.where(np.isfinite(se), se, 0.0)
    lo = min(float(np.min(esd[pos])), *marks)
    hi = max(float(np.max(upper[pos])), *marks)
    return _decade_range(lo / 1.5, hi * 1.5)


def chart_figure(chart: DesignChart, title: str | None = None, *, dpi: float = DEFAULT_DPI
                 ) -> Figure:
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
        Written above the axes.
    dpi : float
        Resolution of PNG output.

    Returns
    -------
    Figure
        One axes labelled ``chart`` (Agg canvas, no pyplot).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    widths = np.asarray(chart.widths, dtype=np.float64)
    esd = np.asarray(chart.expected_sliding, dtype=np.float64)
    se = np.asarray(chart.std_error, dtype=np.float64)
    se0 = np.where(np.isfinite(se), se, 0.0)
    pos = esd > 0.0
    y0, y1 = _chart_range(chart)
    lo_w, hi_w = float(widths[0]), float(widths[-1])
    pad = 0.02 * (hi_w - lo_w)
    wt, sfw = chart.width_for_target, chart.sf_width
    sf_in = math.isfinite(sfw) and lo_w <= sfw <= hi_w
    sf = f"SF = {chart.required_sf:g}"
    # the key, (handle, text): the chart's own lines, then the limits and the target
    key: list[tuple[Any, str]] = [
        ((Patch(facecolor=_FILL, edgecolor="none"),
          Line2D([], [], color=_ESD_LINE, lw=1.4, marker="o", markersize=2.6)),
         f"ESD \u00b1 2 standard errors ({chart.trials} lifetimes per width)")]
    if not np.all(pos):
        key.append((Line2D([], [], ls="none", marker="v", markersize=4.5, markerfacecolor="white",
                           markeredgecolor=_ESD_LINE, markeredgewidth=1.0),
                    "ESD = 0 (no lifetime slid)"))
    if wt is not None:
        key.append((Line2D([], [], color=_TARGET, lw=1.0),
                    f"narrowest width with ESD \u2264 {chart.target:g} m"))
    if sf_in:
        key.append((Line2D([], [], color="black", lw=1.0, dashes=_SF_DASHES),
                    f"{sf} under the 50-year wave (Goda 2000)"))
    on_limit = [math.isclose(lim, chart.target, rel_tol=1e-9) for lim, _ in TOLERABLE]
    for (lim, source), dashes, is_target in zip(TOLERABLE, _LIMIT_DASHES, on_limit):
        key.append((Line2D([], [], color=_TARGET if is_target else _LIMIT,
                           lw=1.0 if is_target else 0.8, dashes=dashes),
                    f"tolerable ESD {_limit_text(lim, source)}" + (", the target" if is_target else "")))
    if not any(on_limit):
        key.append((Line2D([], [], color=_TARGET, lw=1.0), f"target ESD {chart.target:g} m"))
    rows = (len(key) + 1) // 2
    w = CHART_FIGSIZE[0]
    top = 0.15 + (0.32 if title else 0.0)
    left, right, ah = 0.66, 0.2, 2.9
    bottom = 0.5 + 0.08 + 0.17 * rows
    h = top + ah + bottom
    with style_context():
        fig = Figure(figsize=(w, h), dpi=dpi)
        FigureCanvasAgg(fig)
        ax = fig.add_axes((left / w, bottom / h, (w - left - right) / w, ah / h), label="chart")
        ax.set_yscale("log")
        ax.set_xlim(lo_w - pad, hi_w + pad)
        ax.set_ylim(y0, y1)
        # the band of +-2 SE; where its lower edge reaches 0 it runs out of the axes
        lower = np.where(esd - 2.0 * se0 > 0.0, esd - 2.0 * se0, y0 * 1e-3)
        ax.fill_between(widths, lower, esd + 2.0 * se0, where=pos, facecolor=_FILL,
                        edgecolor="none", zorder=1)
        ax.plot(widths, np.where(pos, esd, np.nan), color=_ESD_LINE, lw=1.4, marker="o",
                markersize=2.6, zorder=4)
        if not np.all(pos):
            zw = widths[~pos]
            ax.plot(zw, np.full(zw.shape, 0.035), transform=ax.get_xaxis_transform(), ls="none",
                    marker="v", markersize=4.5, markerfacecolor="white", markeredgecolor=_ESD_LINE,
                    markeredgewidth=1.0, zorder=5)
        vertical: Placed = []
        horizontal: Placed = []
        for (lim, _), dashes, is_target in zip(TOLERABLE, _LIMIT_DASHES, on_limit):
            ax.axhline(lim, color=_TARGET if is_target else _LIMIT, lw=1.0 if is_target else 0.8,
                       dashes=dashes, zorder=2)
            t = _label(ax, f"{lim:g} m" + (": target" if is_target else ""),
                       xycoords=ax.get_yaxis_transform(), fontsize=_FS - 0.5,
                       color=_TARGET_TEXT if is_target else "0.15")
            horizontal.append((t, _hline_candidates(lim), []))
        if not any(on_limit):
            ax.axhline(chart.target, color=_TARGET, lw=1.0, zorder=2)
            t = _label(ax, f"target {chart.target:g} m", xycoords=ax.get_yaxis_transform(),
                       fontsize=_FS - 0.5, color=_TARGET_TEXT)
            horizontal.append((t, _hline_candidates(chart.target), []))
        notes: list[str] = []
        if wt is not None:
            ax.axvline(wt, color=_TARGET, lw=1.0, zorder=3)
            every = math.isclose(wt, lo_w, rel_tol=1e-12) and bool(esd[0] <= chart.target)
            text = (f"b = {_metres(wt)} m: every width meets it" if every
                    else f"b = {_metres(wt)} m")
            t = _label(ax, text, xycoords=ax.get_xaxis_transform(), rotation=90.0,
                       fontsize=_FS - 0.5, color=_TARGET_TEXT)
            vertical.append((t, _vline_candidates(wt, side_first=1),
                             [text.replace(": ", ":\n")] if every else []))
        else:
            notes.append(f"no width of {lo_w:.4g}\u2013{hi_w:.4g} m\n"
                         f"has ESD \u2264 {chart.target:g} m")
        if sf_in:
            ax.axvline(sfw, color="black", lw=1.0, dashes=_SF_DASHES, zorder=3)
            t = _label(ax, f"b = {_metres(sfw)} m", xycoords=ax.get_xaxis_transform(),
                       rotation=90.0, fontsize=_FS - 0.5)
            vertical.append((t, _vline_candidates(sfw, side_first=-1), []))
        elif math.isfinite(sfw):
            notes.append(f"{sf} under the 50-year wave:\nb = {_metres(sfw)} m, off the chart")
        else:
            notes.append(f"{sf} under the 50-year wave:\nno width")
        _format_log_axis(ax, "y")
        ax.set_xlabel("caisson width $b$ (m)", fontsize=_FS)
        ax.set_ylabel("expected sliding distance (m)", fontsize=_FS)
        ax.tick_params(labelsize=_FS - 0.5)
        if title:
            fig.text(0.5, 1.0 - 0.1 / h, title, fontsize=_FS + 1.5, ha="center", va="top")
        fig.legend([k for k, _ in key], [v for _, v in key], loc="lower center",
                   bbox_to_anchor=(0.5, 0.06 / h), ncols=2, fontsize=_FS - 0.5, frameon=False,
                   handlelength=2.6, columnspacing=1.2, borderaxespad=0.0)
        note = None
        if notes:
            note = _label(ax, "\n".join(notes), xycoords="axes fraction", fontsize=_FS - 0.5)
        placer = LabelPlacer(fig)
        try:
            placer.avoid_lines_of(ax)
            ub = np.where(pos, esd + 2.0 * se0, np.nan)
            lb = np.where(pos, np.maximum(lower, y0), np.nan)
            placer.avoid_line(ax, widths, ub)
            placer.avoid_line(ax, widths, lb)
            for x, a, b in zip(widths, lb, ub):  # the band between its edges
                if np.isfinite(a) and np.isfinite(b):
                    placer.avoid_line(ax, [x, x], [a, b])
            if note is not None:  # a corner first; then the lines' labels, the vertical ones first
                placer.place(ax, note, _corner_candidates())
            for t, cands, texts in vertical + horizontal:
                placer.place(ax, t, cands, texts=texts)
        finally:
            placer.close()
    return fig
