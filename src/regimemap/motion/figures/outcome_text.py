"""The text of an outcome map, placed so that it fits: the title, the region names, the contour labels.

:func:`place_outcome_text` runs once the axes of an outcome map are drawn
(:func:`regimemap.motion.figures.outcome.draw_outcome_map` calls it) and measures every text with the
renderer (window extents, in pixels, at :data:`regimemap.drawing.text.tidy.MEASURE_DPI`, so that the
layout does not depend on the resolution of a file):

* the title is wrapped at its commas, then made smaller, until it fits the width of the axes
  and the top of the figure (:func:`regimemap.drawing.text.tidy.fit_title`): never clipped;
* the fixed texts -- tick and axis labels, the title, the key -- are taken first;
* a region's name goes where its box lies inside its region and inside the axes, clear of every
  text placed before: among those places, the one farthest from the lines (boundaries and
  contours), preferring places that no line crosses; a name with no such place is left out;
* each contour level gets one label on its line, turned with it, on a patch of the region's
  colour, at the first place from the middle of its longest visible stretch outwards where the
  stretch is straight, the label inside the region where the contour means something, clear of
  every text placed and of the other lines (then: of the other contours under its letters); a
  level with no such place is left out, line and all (crowded lines cannot be read).

:func:`outcome_text_boxes` lists the boxes that the tests check, as
:func:`regimemap.drawing.text.tidy.text_boxes` does for the regime maps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ...drawing.style import OUTCOME_STYLE
from ...drawing.text.textboxes import GAP, Box, box_of, box_within, boxes_hit, major_tick_labels, visible_text
from ...drawing.text.tidy import MEASURE_DPI, fit_title
from .outcome_artists import CategoryLookup, OutcomeArtists, TextReport

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure


__all__ = ["CategoryLookup", "TextReport", "outcome_text_boxes", "place_outcome_text"]

FloatArray = NDArray[np.float64]

#: Spacing (pixels) of the points along a line that a label must keep off.
_STEP = 2.0
#: Most places tried for a region's name (nodes of its region, evenly thinned).
_REGION_CANDIDATES = 1500
#: The patch behind a contour label (the region's colour), hiding the line under it.
_CONTOUR_PATCH: dict[str, Any] = {"boxstyle": "round,pad=0.3", "fc": "white", "ec": "none", "alpha": 0.9}
#: The codes where each contour means something (slide: slide only, slide-rock; rotation:
#: rock only, slide-rock).
_WHERE = {"residual_slide": (1, 3), "max_rotation": (2, 3)}


def _axes(art: OutcomeArtists) -> Axes | None:
    for a in [*art.regions.values(), *art.labels, art.title, art.legend]:
        ax = getattr(a, "axes", None) if a is not None else None
        if ax is not None:
            found: Axes = ax
            return found
    return None


def outcome_text_boxes(fig: Figure, art: OutcomeArtists) -> dict[str, list[tuple[str, Box]]]:
    """Every text of an outcome map as drawn (pixels), by kind.

    ``fixed``: tick and axis labels, the title and the key; ``labels``: the region names and the
    contour labels; ``markers``: none (the kinds of :func:`regimemap.drawing.text.tidy.text_boxes`).
    """
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fixed: list[tuple[str, Box]] = []
    labels: list[tuple[str, Box]] = []
    ax = _axes(art)
    if ax is not None:
        fixed += [(f"tick {t.get_text()}", box_of(t, renderer)) for t in major_tick_labels(ax)]
        for t in (ax.xaxis.label, ax.yaxis.label, ax.title):
            if visible_text(t):
                fixed.append((f"axis text {t.get_text()!r}", box_of(t, renderer)))
    if art.legend is not None and art.legend.get_visible():
        fixed.append(("key", box_of(art.legend, renderer)))
    for kind, texts in (("region", art.labels), ("contour", art.contour_labels)):
        labels += [(f"{kind} {t.get_text()!r}", box_of(t, renderer)) for t in texts if visible_text(t)]
    return {"fixed": fixed, "markers": [], "labels": labels}


def place_outcome_text(fig: Figure, ax: Axes, art: OutcomeArtists, category: NDArray[Any],
                       xs: FloatArray, ys: FloatArray) -> TextReport:
    """Fit the title and place the region names and contour labels of an outcome map.

    Parameters
    ----------
    fig, ax : Figure, Axes
        The figure, laid out (its size and the axes' position final), and the map's axes.
    art : OutcomeArtists
        What :func:`regimemap.motion.figures.outcome.draw_outcome_map` drew; its ``labels`` hold the
        region names (``gid`` ``region-<code>``) and get their places, ``contour_labels`` gets
        the contour labels.
    category, xs, ys : ndarray
        The map's grid with increasing axes (the nodes where a name may go).

    Returns
    -------
    TextReport
    """
    if not hasattr(fig.canvas, "get_renderer"):  # a bare Figure(): measure with Agg
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(fig)
    dpi = fig.dpi
    fig.set_dpi(MEASURE_DPI)  # the same decisions at every output resolution
    try:
        return _place(fig, ax, art, np.asarray(category), xs, ys)
    finally:
        fig.set_dpi(dpi)


def _dense(pixels: FloatArray, step: float = _STEP) -> FloatArray:
    """A polyline with vertices at most ``step`` apart."""
    if len(pixels) < 2:
        return pixels
    seg = np.hypot(*np.diff(pixels, axis=0).T)
    n = np.maximum(1, np.ceil(seg / step).astype(np.int64))
    t = np.concatenate([np.arange(k) / k for k in n.tolist()])
    start = np.repeat(pixels[:-1], n, axis=0)
    delta = np.repeat(np.diff(pixels, axis=0), n, axis=0)
    return np.vstack([start + t[:, None] * delta, pixels[-1:]])


def _place(fig: Figure, ax: Axes, art: OutcomeArtists, cat: NDArray[Any], xs: FloatArray,
           ys: FloatArray) -> TextReport:
    report = TextReport()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fig.draw_without_rendering()  # ticks, labels and key in their final places
    fb = fig.bbox
    # within the axes' width (a centred title then stays clear of the tick labels beside them)
    right = min(fb.x1 - GAP, ax.bbox.x1)
    if art.title is not None and fit_title(art.title, renderer, right, fb.y1 - GAP):
        report.placed.append(f"title {art.title.get_text()!r}")
    taken = [(b[0] - GAP / 2, b[1] - GAP / 2, b[2] + GAP / 2, b[3] + GAP / 2)
             for _, b in outcome_text_boxes(fig, _fixed_only(art))["fixed"]]
    bb = ax.bbox
    frame = (bb.x0 + GAP, bb.y0 + GAP, bb.x1 - GAP, bb.y1 - GAP)
    to_px = ax.transData.transform
    to_data = ax.transData.inverted().transform
    lookup = art.category_at
    boundary = [_dense(np.asarray(to_px(p))) for p in art.boundary_lines if len(p) > 1]
    contour_px: dict[tuple[str, int], FloatArray] = {}
    for key, cs in art.contours.items():
        for li, segs in enumerate(cs.allsegs):
            parts = [_dense(np.asarray(to_px(s))) for s in segs if len(s) > 1]
            pts = np.vstack(parts) if parts else np.zeros((0, 2))
            if len(pts) and lookup is not None:  # only where it is drawn (the lines are clipped)
                pts = pts[np.isin(lookup(to_data(pts)), _WHERE.get(key, ()))]
            contour_px[(key, li)] = pts
    lines = np.vstack([*boundary, *contour_px.values(), np.zeros((0, 2))])
    for t in list(art.labels):
        if _place_region(t, renderer, cat, xs, ys, frame, taken, lines, to_px, to_data, lookup):
            taken.append(box_of(t, renderer, _pad(t, fig)))
            report.placed.append(f"region {t.get_text()!r}")
        else:
            t.remove()
            art.labels.remove(t)
            report.hidden.append(f"region {t.get_text()!r}")
    for key, cs in art.contours.items():
        unit = art.contour_units.get(key, "")
        style: Any = cs.get_edgecolor()
        color = style[0] if len(style) else "black"
        for li, level in enumerate(cs.levels):
            text = f"{float(level):g}{unit}"
            others = np.vstack([p for k, p in contour_px.items() if k != (key, li)] + [np.zeros((0, 2))])
            t = ax.text(0.0, 0.0, text, fontsize=7.5, color=color, ha="center", va="center",
                        rotation_mode="anchor", zorder=5.5, clip_on=False, bbox=dict(_CONTOUR_PATCH))
            t.set_gid(f"contour-{key}")
            segs = [np.asarray(to_px(s)) for s in cs.allsegs[li] if len(s) > 1]
            if _place_contour(t, renderer, fig, segs, key, frame, taken, others, np.vstack([*boundary,
                              np.zeros((0, 2))]), to_data, lookup):
                taken.append(box_of(t, renderer, _pad(t, fig)))
                art.contour_labels.append(t)
                report.placed.append(f"contour {text!r}")
            else:  # a line that cannot be labelled is left out: it could not be read
                t.remove()
                _drop_level(cs, li)
                contour_px[(key, li)] = np.zeros((0, 2))
                report.hidden.append(f"contour {text!r}")
    return report


def _drop_level(cs: Any, index: int) -> None:
    """Leave out the line of one level of a contour set."""
    from matplotlib.path import Path

    paths = list(cs.get_paths())
    paths[index] = Path(np.zeros((0, 2)))
    cs.set_paths(paths)


def _fixed_only(art: OutcomeArtists) -> OutcomeArtists:
    from dataclasses import replace

    return replace(art, labels=[], contour_labels=[])


def _pad(t: Any, fig: Figure) -> float:
    """Pixels the patch behind a text reaches beyond its letters."""
    patch = t.get_bbox_patch()
    if patch is None:
        return GAP / 2
    pad = float(getattr(patch.get_boxstyle(), "pad", 0.0))
    return pad * float(t.get_fontsize()) * fig.dpi / 72.0 + GAP / 2


def _free(b: Box, frame: Box, taken: list[Box]) -> bool:
    return box_within(b, frame) and not any(boxes_hit(b, o) for o in taken)


def _place_region(t: Any, renderer: RendererBase, cat: NDArray[Any], xs: FloatArray, ys: FloatArray,
                  frame: Box, taken: list[Box], lines: FloatArray, to_px: Any, to_data: Any,
                  lookup: Any) -> bool:
    """Put a region's name at the free place inside its region farthest from the lines."""
    code = int(str(t.get_gid()).split("-")[1])
    ii, jj = np.nonzero(cat == code)
    if ii.size == 0 or lookup is None:
        return False
    if ii.size > _REGION_CANDIDATES:
        pick = np.linspace(0, ii.size - 1, _REGION_CANDIDATES).astype(np.int64)
        ii, jj = ii[pick], jj[pick]
    centre = np.asarray(to_px(np.column_stack([xs[jj], ys[ii]])))
    pad = _pad(t, t.figure)
    b0 = box_of(t, renderer, pad)
    w, h = b0[2] - b0[0], b0[3] - b0[1]
    x0, y0 = centre[:, 0] - w / 2, centre[:, 1] - h / 2
    ok = (x0 >= frame[0]) & (y0 >= frame[1]) & (x0 + w <= frame[2]) & (y0 + h <= frame[3])
    for o in taken:
        ok &= ~((x0 < o[2]) & (o[0] < x0 + w) & (y0 < o[3]) & (o[1] < y0 + h))
    # the box inside the region: its corners, the middles of its sides and its centre
    for fx in (0.0, 0.5, 1.0):
        for fy in (0.0, 0.5, 1.0):
            idx = np.flatnonzero(ok)
            if idx.size == 0:
                return False
            probe = np.column_stack([x0[idx] + fx * w, y0[idx] + fy * h])
            ok[idx] &= lookup(to_data(probe)) == code
    idx = np.flatnonzero(ok)
    if idx.size == 0:
        return False
    crossed = np.zeros(idx.size, dtype=bool)
    clearance = np.full(idx.size, np.inf)
    for chunk in range(0, len(lines), 4000):
        q = lines[chunk:chunk + 4000]
        dx = np.abs(q[None, :, 0] - centre[idx, 0:1])
        dy = np.abs(q[None, :, 1] - centre[idx, 1:2])
        crossed |= np.any((dx < w / 2) & (dy < h / 2), axis=1)
        gap = np.hypot(np.maximum(dx - w / 2, 0), np.maximum(dy - h / 2, 0))
        clearance = np.minimum(clearance, gap.min(axis=1))
    edge = np.minimum.reduce([centre[idx, 0] - w / 2 - frame[0], frame[2] - centre[idx, 0] - w / 2,
                              centre[idx, 1] - h / 2 - frame[1], frame[3] - centre[idx, 1] - h / 2])
    score = np.minimum(clearance, edge + 20.0) - np.where(crossed, 1e6, 0.0)
    for k in np.argsort(-score, kind="stable")[:20].tolist():
        t.set_position(tuple(to_data(centre[idx[k]][None, :])[0]))
        if _free(box_of(t, renderer, pad), frame, taken):
            return True
    return False


def _runs(px: FloatArray, visible: NDArray[np.bool_]) -> list[FloatArray]:
    """The stretches of consecutive visible points."""
    out = []
    edges = np.flatnonzero(np.diff(np.concatenate([[0], visible.astype(np.int8), [0]])))
    for a, b in zip(edges[0::2].tolist(), edges[1::2].tolist()):
        if b - a >= 2:
            out.append(px[a:b])
    return out


def _place_contour(t: Any, renderer: RendererBase, fig: Figure, segs: list[FloatArray], key: str,
                   frame: Box, taken: list[Box], others: FloatArray, boundary: FloatArray, to_data: Any,
                   lookup: Any) -> bool:
    """Put a contour label on its line: the first free, straight, visible place from the middle of
    its longest stretch outwards."""
    allowed = _WHERE.get(key, ())
    t.set_rotation(0.0)
    pad = _pad(t, fig)
    b0 = box_of(t, renderer)
    w, h = b0[2] - b0[0] + 2 * pad, b0[3] - b0[1] + 2 * pad
    stretches: list[FloatArray] = []
    for px in segs:
        d = _dense(px)
        inside = (d[:, 0] > frame[0]) & (d[:, 0] < frame[2]) & (d[:, 1] > frame[1]) & (d[:, 1] < frame[3])
        if lookup is not None:
            inside &= np.isin(lookup(to_data(d)), allowed)
        stretches += _runs(d, inside)
    stretches.sort(key=lambda r: -float(np.hypot(*np.diff(r, axis=0).T).sum()))
    text_h = b0[3] - b0[1]
    search = _ContourSearch(renderer, frame, taken, to_data, lookup, allowed, pad)
    # first clear of every line under the patch, then of the other contours under the letters
    for near, clear in ((np.vstack([others, boundary]), (w, h)), (others, (w - 2 * pad, text_h))):
        for r in stretches:
            s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(r, axis=0).T))])
            length = float(s[-1])
            if length < w + 2 * GAP:
                continue
            half = 0.5 * w
            step = max(half / 2, 6.0)
            mid = 0.5 * length
            offsets = sorted(np.arange(-mid + half + GAP, mid - half - GAP + 1e-9, step).tolist(), key=abs)
            for off in offsets:
                at = mid + off
                if _try_contour(t, search, r, s, at, (w, h), near, clear):
                    return True
    return False


@dataclass(frozen=True)
class _ContourSearch:
    """What stays the same while a contour label tries its places: the renderer, the figure's
    frame and the boxes taken (pixels), pixels -> data, the category lookup and the categories
    where the contour means something, the label's patch padding."""

    renderer: RendererBase
    frame: Box
    taken: list[Box]
    to_data: Any
    lookup: Any
    allowed: tuple[int, ...]
    pad: float


def _try_contour(t: Any, search: _ContourSearch, r: FloatArray, s: FloatArray, at: float,
                 size: tuple[float, float], near: FloatArray, clear: tuple[float, float]) -> bool:
    """Try a contour label of ``size`` (with its patch) centred at arc length ``at`` of stretch
    ``r``, no point of ``near`` within ``clear`` (a box along the line) of its centre."""
    renderer, frame, taken, pad = search.renderer, search.frame, search.taken, search.pad
    to_data, lookup, allowed = search.to_data, search.lookup, search.allowed
    w, h = size
    p = np.array([np.interp(at, s, r[:, 0]), np.interp(at, s, r[:, 1])])
    a = np.array([np.interp(at - w / 2, s, r[:, 0]), np.interp(at - w / 2, s, r[:, 1])])
    b = np.array([np.interp(at + w / 2, s, r[:, 0]), np.interp(at + w / 2, s, r[:, 1])])
    chord = b - a
    norm = float(np.hypot(*chord))
    if norm < 0.8 * w:
        return False  # too bent under the label
    u = chord / norm
    span = (s >= at - w / 2) & (s <= at + w / 2)
    off_line = np.abs((r[span] - a) @ np.array([-u[1], u[0]]))
    if off_line.size and float(off_line.max()) > 0.35 * h:
        return False
    n = np.array([-u[1], u[0]])
    corners = [p + sx * (w / 2) * u + sy * (h / 2) * n for sx in (-1, 1) for sy in (-1, 1)]
    if lookup is not None and not np.all(np.isin(lookup(to_data(np.vstack([p, a, b, *corners]))), allowed)):
        return False  # the label lies on the region where its contour means something
    if len(near):  # no other line under the (turned) label
        rel = near - p
        along = np.abs(rel @ u)
        across = np.abs(rel @ n)
        if np.any((along < clear[0] / 2) & (across < clear[1] / 2)):
            return False
    angle = math.degrees(math.atan2(u[1], u[0]))
    if angle > 90.0:
        angle -= 180.0
    elif angle <= -90.0:
        angle += 180.0
    t.set_rotation(angle)
    t.set_position(tuple(to_data(p[None, :])[0]))
    code = int(lookup(to_data(p[None, :]))[0]) if lookup is not None else -1
    colour = OUTCOME_STYLE[code].color if code in OUTCOME_STYLE else "white"
    t.set_bbox({**_CONTOUR_PATCH, "fc": colour})
    return _free(box_of(t, renderer, pad), frame, taken)
