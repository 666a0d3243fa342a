"""Labels placed once a figure is laid out: each at the first free one of its candidate places.

:class:`LabelPlacer` measures the texts of a figure (:func:`figure_texts`) with
the renderer, at :data:`regimemap.drawing.text.tidy.MEASURE_DPI` (so an SVG or PDF
does not depend on the resolution of a PNG), and moves each annotation made by
:func:`make_label` to the first of its :class:`Candidate` places that is inside
its axes, clear of every other text and clear of the curves.  Used by the
lifetime figures, the study's and the design sheet.  It is the one placer,
:class:`regimemap.drawing.text.placer.Placer`, measured on a whole figure, with the
candidates given with each label; the maps' tidy pass (:mod:`regimemap.drawing.text.tidy`)
uses the same placer with the candidates of each kind of map label
(:mod:`regimemap.drawing.text.relabel`).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from .placer import Placer, clear_of
from .textboxes import GAP, Box, box_of
from .tidy import MEASURE_DPI

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure
    from matplotlib.text import Text

__all__ = ["Candidate", "LabelPlacer", "Placed", "corner_candidates", "figure_texts",
           "hline_candidates", "hline_label", "make_label", "vline_candidates", "vline_label"]

FloatArray = NDArray[np.float64]
#: Font size (points) of a label by default.
_FS = 8.0


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
    add(getattr(fig, "_suptitle", None))
    for leg in fig.legends:
        if leg.get_visible():
            for t in leg.get_texts():
                add(t)
    for ax in fig.axes:
        if ax.get_visible():
            for t in _axes_texts(ax):
                add(t)
    return out


def _axes_texts(ax: Axes) -> Iterator[Any]:
    """The texts of one axes, in drawing order: tick labels in view and axis labels (when the
    axis is on), titles, free texts, legend (None where a title is missing)."""
    if ax.axison:
        yield from _tick_labels_in_view(ax)
        yield ax.xaxis.label
        yield ax.yaxis.label
    for name in ("title", "_left_title", "_right_title"):
        yield getattr(ax, name, None)
    yield from ax.texts
    ax_leg = ax.get_legend()
    if ax_leg is not None and ax_leg.get_visible():
        yield from ax_leg.get_texts()


def _tick_labels_in_view(ax: Axes) -> Iterator[Any]:
    """The labels of the major and minor ticks of both axes that lie within the limits."""
    for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        lo, hi = min(lim), max(lim)
        tol = 1e-9 * (hi - lo)
        for tick in axis.get_major_ticks() + axis.get_minor_ticks():
            loc: float | None = tick.get_loc()  # None on a tick not yet placed
            if loc is None or not (lo - tol <= loc <= hi + tol):
                continue
            if axis.get_scale() == "log" and not lo * (1 - 1e-9) <= loc <= hi * (1 + 1e-9):
                continue
            yield tick.label1
            yield tick.label2


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
class Candidate:
    """A place of a label: the point ``xy`` (in the label's coordinates), an offset from it
    (points) and the alignment of the text there."""

    xy: tuple[float, float]
    offset: tuple[float, float]
    ha: str
    va: str


class LabelPlacer(Placer):
    """Put labels where they meet no other text and no curve, inside their axes.

    The free space and the search are the one :class:`~regimemap.drawing.text.placer.Placer`
    (the boxes taken and the figure's frame); the candidates are given with each label.  Create it once
    the figure's axes, curves and fixed texts are drawn; the texts already in the figure
    (:func:`figure_texts`) are taken.  :meth:`avoid_line` and :meth:`avoid_lines_of` add
    curves; :meth:`place` moves an annotation (offset in points from a point ``xy``) to the
    first free one of its candidates.  Measured at
    :data:`~regimemap.drawing.text.tidy.MEASURE_DPI`: call :meth:`close` (or use it as a
    context manager) to restore the figure's resolution.
    """

    def __init__(self, fig: Figure) -> None:
        self._dpi = fig.dpi
        fig.set_dpi(MEASURE_DPI)
        renderer: RendererBase = fig.canvas.get_renderer()  # type: ignore[attr-defined]
        fig.draw_without_rendering()
        super().__init__(fig, renderer, [box_of(t, renderer, GAP / 2) for t in figure_texts(fig)])
        self.points: list[FloatArray] = []

    def close(self) -> None:
        self.fig.set_dpi(self._dpi)

    def __enter__(self) -> LabelPlacer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def place_all(self, ax: Axes, labels: Placed) -> None:
        """:meth:`place` each label of ``labels`` (label, candidates, shorter texts) in order."""
        for t, cands, texts in labels:
            self.place(ax, t, cands, texts=texts)

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

    def place(self, ax: Axes, t: Any, candidates: Iterable[Candidate], *,
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

        def places() -> Iterator[Any]:
            for text in variants:
                t.set_text(text)
                for c in cands:
                    t.xy = c.xy
                    t.xyann = c.offset
                    t.set_ha(c.ha)
                    t.set_va(c.va)
                    yield t

        for need_clear in ((True, False) if lines else (False,)):
            _, ok = self.first_free(places(), within, clear_of(self.points) if need_clear else None)
            if ok:
                self.take(t)
                patch = t.get_bbox_patch()
                if need_clear and patch is not None and t.get_gid() != "boxed":
                    patch.set_visible(False)
                return True
        t.set_text(variants[0])
        t.set_visible(False)
        return False


def vline_candidates(x: float, side_first: int = 1) -> list[Candidate]:
    """Places of the rotated label of a vertical line at ``x``: beside it, from the bottom or
    the top of the axes inwards, on either side."""
    sides = (side_first, -side_first)
    order: list[tuple[float, str]] = [(0.03, "bottom"), (0.97, "top")]
    for k in range(1, 10):
        order += [(0.03 + 0.05 * k, "bottom"), (0.97 - 0.05 * k, "top")]
    return [Candidate((x, y), (2.5 * side, 0.0), "left" if side > 0 else "right", va)
            for y, va in order for side in sides]


def hline_candidates(y: float, xs: Sequence[float] = (0.98, 0.02, 0.75, 0.5, 0.25)
                      ) -> list[Candidate]:
    """Places of the label of a horizontal line at ``y``: above or below it, at ``xs`` (axes)."""
    out = []
    for sy in (1, -1):
        for x in xs:
            ha = "right" if x > 0.6 else ("left" if x < 0.4 else "center")
            out.append(Candidate((x, y), (0.0, 1.5 * sy), ha, "bottom" if sy > 0 else "top"))
    return out


def corner_candidates(inset: float = 0.03) -> list[Candidate]:
    """The four corners of the axes, then the middles of the top and bottom edges."""
    lo, hi = inset, 1.0 - inset
    return [Candidate((x, y), (0.0, 0.0), ha, va)
            for (y, va) in ((hi, "top"), (lo, "bottom"))
            for (x, ha) in ((hi, "right"), (lo, "left"), (0.5, "center"))]


def make_label(ax: Axes, text: str, *, xycoords: Any = "data", rotation: float = 0.0,
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
Placed = list[tuple[Any, list[Candidate], list[str]]]


def vline_label(ax: Axes, x: float, text: str, *, fontsize: float, color: str = "black",
                side_first: int = 1, texts: Sequence[str] = ()) -> tuple[Any, list[Candidate], list[str]]:
    """The turned label of a vertical line at ``x`` (data), its places
    (:func:`vline_candidates`) and its other wordings ``texts``: an item of :data:`Placed`."""
    t = make_label(ax, text, xycoords=ax.get_xaxis_transform(), rotation=90.0, fontsize=fontsize,
                   color=color)
    return t, vline_candidates(x, side_first=side_first), list(texts)


def hline_label(ax: Axes, y: float, text: str, *, fontsize: float, color: str = "black"
                ) -> tuple[Any, list[Candidate], list[str]]:
    """The label of a horizontal line at ``y`` (data) and its places (:func:`hline_candidates`):
    an item of :data:`Placed`."""
    t = make_label(ax, text, xycoords=ax.get_yaxis_transform(), fontsize=fontsize, color=color)
    return t, hline_candidates(y), []
