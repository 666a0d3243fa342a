"""Keep every text of a map figure legible: nothing overlaps, nothing leaves the figure.

:func:`regimemap.drawing.mapplot.draw_map` places its labels with a size
model of the text (:func:`regimemap.drawing.style.text_size`) and knows
nothing of the tick labels, the title, the key or the design points drawn
after it.  :func:`tidy_figure` runs once the figure is laid out: it measures
every text with the renderer (window extents, in pixels), fits the titles
to the figure (wrapped at commas, then smaller), and moves each label that
meets another text or leaves the figure, in order of importance — the names
of the report's points, the names of design points, the arrows to points
outside the view, the names of the lines, the mode symbols — to the first
free place among its candidates:

* a point's name: around the point, then farther with a leader line;
* a line's name: beside the line (:func:`regimemap.drawing.placement.curve_label_anchor`),
  then away from it with a leader to it;
* a mode symbol: inside its region (:func:`regimemap.drawing.placement.label_anchor`),
  then anywhere on the region (a thin band), framed.

A label with no free place is hidden (and listed in the report); none is
left overlapping.  :func:`text_boxes` lists the boxes that the tests check.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .placement import (
    box_hits,
    column_intervals,
    curve_label_anchor,
    label_anchor,
    leader_label_anchor,
    view_points,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure
    from matplotlib.text import Text

    from .mapplot import MapArtists

__all__ = ["MEASURE_DPI", "TidyReport", "band_columns", "fit_title", "inside", "text_boxes",
           "tidy_figure"]

Box = tuple[float, float, float, float]

#: Gap (pixels) kept between two texts, and between a text and the figure's edge.
_GAP = 2.0
#: Resolution at which the texts are measured and placed (dots per inch): a map is laid
#: out the same way whatever the resolution of its file (an SVG does not depend on --dpi).
MEASURE_DPI = 150.0
#: Smallest font size (points) a title is shrunk to.
_MIN_TITLE_FS = 6.0


@dataclass
class TidyReport:
    """What :func:`tidy_figure` did: the labels it moved and those it had to hide."""

    moved: list[str] = field(default_factory=list)
    hidden: list[str] = field(default_factory=list)


# -- boxes -------------------------------------------------------------------------------------


def _box(artist: Artist, renderer: RendererBase, pad: float = 0.0) -> Box:
    bb = artist.get_window_extent(renderer)
    return (bb.x0 - pad, bb.y0 - pad, bb.x1 + pad, bb.y1 + pad)


def _hit(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _inside(a: Box, b: Box) -> bool:
    return a[0] >= b[0] and a[1] >= b[1] and a[2] <= b[2] and a[3] <= b[3]


def _visible_text(t: Any) -> bool:
    return bool(t is not None and t.get_visible() and t.get_text().strip()
                and t.figure is not None)


def _tick_labels(ax: Axes) -> list[Text]:
    """The tick labels that are drawn (in view, visible, not empty)."""
    out = []
    for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        lo, hi = min(lo, hi), max(lo, hi)
        eps = 1e-9 * (hi - lo)
        for tick in axis.get_major_ticks():
            if not (lo - eps <= tick.get_loc() <= hi + eps):
                continue
            for lab in (tick.label1, tick.label2):
                if _visible_text(lab):
                    out.append(lab)
    return out


def _marker_boxes(ax: Axes, line: Any, renderer: RendererBase) -> list[Box]:
    """Boxes of the markers of a Line2D (one per point), in pixels."""
    if line is None or not line.get_visible() or line.axes is None:
        return []
    r = 0.5 * line.get_markersize() * ax.figure.dpi / 72.0 + 0.5 * line.get_markeredgewidth()
    xy = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
    return [(x - r, y - r, x + r, y + r) for x, y in xy]


def text_boxes(fig: Figure, maps: Sequence[MapArtists], extra: Iterable[Artist] = ()
               ) -> dict[str, list[tuple[str, Box]]]:
    """Every text and marker of a figure of maps, by kind, as drawn (pixels).

    Kinds: ``fixed`` (tick and axis labels, titles, keys, the suptitle and
    ``extra``), ``markers`` (the report's points and design points) and
    ``labels`` (point names, design-point names, arrows to points off view,
    line names, mode symbols).  Call after :func:`tidy_figure` (or a draw).
    """
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fixed: list[tuple[str, Box]] = []
    markers: list[tuple[str, Box]] = []
    labels: list[tuple[str, Box]] = []
    seen_axes = []
    for art in maps:
        ax = _axes_of(art)
        if ax is None or ax in seen_axes:
            continue
        seen_axes.append(ax)
        for t in _tick_labels(ax):
            fixed.append((f"tick {t.get_text()}", _box(t, renderer)))
        titles = [getattr(ax, name, None) for name in ("title", "_left_title", "_right_title")]
        for t in [ax.xaxis.label, ax.yaxis.label, *titles]:
            if _visible_text(t):
                fixed.append((f"axis text {t.get_text()!r}", _box(t, renderer)))
        leg = ax.get_legend()
        if leg is not None and leg.get_visible():
            fixed.append(("key", _box(leg, renderer)))
        for name, m in art.point_markers.items():
            markers.extend((f"point {name}", b) for b in _marker_boxes(ax, m, renderer))
        for a in art.extra:
            if a.get_gid() == "design-dots":
                markers.extend(("design point", b) for b in _marker_boxes(ax, a, renderer))
        for kind, t in _movable(art):
            if _visible_text(t):
                labels.append((f"{kind} {t.get_text()!r}", _box(t, renderer)))
    for leg in fig.legends:
        if leg.get_visible():
            fixed.append(("key", _box(leg, renderer)))
    sup: Any = getattr(fig, "_suptitle", None)
    if _visible_text(sup):
        fixed.append(("suptitle", _box(sup, renderer)))
    for a in extra:
        if a.get_visible():
            fixed.append((f"extra {a.get_gid() or type(a).__name__}", _box(a, renderer)))
    return {"fixed": fixed, "markers": markers, "labels": labels}


def _axes_of(art: MapArtists) -> Any:
    """The Axes a map was drawn on (None if it drew nothing)."""
    artists: list[Any] = [a for lst in art.fills.values() for a in lst]
    artists += [a for lst in art.curves.values() for a in lst]
    artists += list(art.point_labels.values()) + [art.title]
    for a in artists:
        if a is not None and a.axes is not None:
            return a.axes
    return None


def _movable(art: MapArtists) -> list[tuple[str, Any]]:
    """The labels of a map that may move, most important first."""
    named = set(art.data.points)
    out: list[tuple[str, Any]] = [("point", t) for n, t in art.point_labels.items() if n in named]
    seen: list[Any] = []
    for t in art.off_view.values():
        if not any(t is s for s in seen):
            seen.append(t)
            out.append(("off-view", t))
    out += [("point", t) for n, t in art.point_labels.items() if n not in named]  # line ends
    out += [("design", a) for a in art.extra if a.get_gid() == "design-name"]
    out += [("curve", t) for t in art.curve_labels.values()]
    out += [("region", t) for lst in art.region_labels.values() for t in lst]
    return out


# -- titles ----------------------------------------------------------------------------------


def _split_outside_math(line: str, sep: str = ", ") -> list[str]:
    """``line`` cut after each ``sep`` that is not inside ``$...$``."""
    parts, cur, in_math, i = [], "", False, 0
    while i < len(line):
        if line[i] == "$":
            in_math = not in_math
        if not in_math and line.startswith(sep, i):
            parts.append(cur + sep.rstrip())
            cur, i = "", i + len(sep)
            continue
        cur += line[i]
        i += 1
    if cur:
        parts.append(cur)
    return parts


def fit_title(t: Text, renderer: RendererBase, right: float, top: float) -> bool:
    """Fit a title between its anchor and ``right``, below ``top`` (pixels): wrap, then shrink.

    Lines too long are wrapped at their commas (never inside mathtext); if a
    line is still too long, or the title rises above ``top``, the font gets
    smaller, down to 6 points.  Returns True when the title was changed.
    """
    if not _visible_text(t):
        return False

    def fits() -> bool:
        b = _box(t, renderer)
        return b[2] <= right and b[3] <= top

    if fits():
        return False
    original = t.get_text()
    lines: list[str] = []
    for line in original.split("\n"):
        t.set_text(line)
        if _box(t, renderer)[2] <= right:
            lines.append(line)
            continue
        cur = ""
        for piece in _split_outside_math(line):
            trial = (cur + " " + piece) if cur else piece
            t.set_text(trial)
            if cur and _box(t, renderer)[2] > right:
                lines.append(cur)
                cur = piece
            else:
                cur = trial
        if cur:
            lines.append(cur)
    t.set_text("\n".join(lines))
    size = float(t.get_fontsize())
    while not fits() and size > _MIN_TITLE_FS:
        size = max(_MIN_TITLE_FS, size - 0.5)
        t.set_fontsize(size)
    return True


# -- moving labels ---------------------------------------------------------------------------

_RING = [(1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1), (0, -1), (1, 0), (-1, 0)]
_HA = {1: "left", 0: "center", -1: "right"}
_VA = {1: "bottom", 0: "center", -1: "top"}


class _Placer:
    """The free space of a figure: boxes already taken, and the figure's frame."""

    def __init__(self, fig: Figure, renderer: RendererBase, taken: list[Box]):
        self.fig = fig
        self.renderer = renderer
        self.taken = list(taken)
        fb = fig.bbox
        self.frame = (fb.x0 + _GAP, fb.y0 + _GAP, fb.x1 - _GAP, fb.y1 - _GAP)

    def box(self, t: Any) -> Box:
        return _box(t, self.renderer, _GAP / 2)

    def free(self, b: Box, within: Box | None = None) -> bool:
        if not _inside(b, self.frame) or (within is not None and not _inside(b, within)):
            return False
        return not any(_hit(b, o) for o in self.taken)

    def take(self, t: Any) -> None:
        self.taken.append(self.box(t))


def _axes_box(ax: Axes) -> Box:
    bb = ax.bbox
    return (bb.x0 - 1.0, bb.y0 - 1.0, bb.x1 + 1.0, bb.y1 + 1.0)


def _fractions(ax: Axes, boxes: Iterable[Box]) -> list[Box]:
    """Pixel boxes as fractions of the axes (the units of :mod:`regimemap.drawing.placement`)."""
    inv = ax.transAxes.inverted()
    out = []
    for b in boxes:
        (x0, y0), (x1, y1) = inv.transform([(b[0], b[1]), (b[2], b[3])])
        out.append((float(x0), float(y0), float(x1), float(y1)))
    return out


def _size_fraction(ax: Axes, b: Box) -> tuple[float, float]:
    return ((b[2] - b[0]) / ax.bbox.width, (b[3] - b[1]) / ax.bbox.height)


def _annotation_like(ax: Axes, old: Any, xy: tuple[float, float], xytext: tuple[float, float],
                     textcoords: str, ha: str, va: str, leader: bool) -> Any:
    """A new annotation with the text and style of ``old`` (optionally with a leader line)."""
    patch = old.get_bbox_patch()
    bbox = None
    if patch is not None:
        bbox = {"boxstyle": patch.get_boxstyle(), "fc": patch.get_facecolor(),
                "ec": patch.get_edgecolor(), "lw": patch.get_linewidth()}
    arrow = None
    if leader:
        arrow = {"arrowstyle": "-", "color": "0.2", "lw": 0.6, "shrinkA": 0.0, "shrinkB": 2.0}
    new = ax.annotate(old.get_text(), xy, xytext=xytext, textcoords=textcoords, ha=ha, va=va,
                      fontsize=old.get_fontsize(), fontstyle=old.get_fontstyle(),
                      color=old.get_color(), zorder=old.get_zorder(), annotation_clip=False,
                      bbox=bbox, arrowprops=arrow)
    new.set_gid(old.get_gid())
    return new


def _point_candidates(t: Any) -> list[tuple[tuple[float, float], str, str, bool]]:
    """Offsets (points), alignments and leader flag to try for a point's name."""
    out = []
    for dist, leader in ((3.5, False), (9.0, False), (18.0, True), (30.0, True)):
        for sx, sy in _RING:
            out.append(((sx * dist, sy * dist), _HA[sx], _VA[sy], leader))
    return out


def _line_pixels(ax: Axes, art: MapArtists) -> np.ndarray:
    """The map's lines in view as dense points (pixels): a point's name keeps off them."""
    k_max, mu_max = art.data.k_max, art.data.mu_max
    parts = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]
    parts = [q for q in parts if len(q)]
    if not parts:
        return np.empty((0, 2))
    return np.asarray(ax.transAxes.transform(np.concatenate(parts)))


def _off_lines(b: Box, lines: np.ndarray) -> bool:
    """Does the box (pixels, less a pixel of margin) stay clear of every line?"""
    return not box_hits((b[0] + 1.0, b[1] + 1.0, b[2] - 1.0, b[3] - 1.0), lines)


def _place_annotation(ax: Axes, t: Any, placer: _Placer, within: Box | None,
                      lines: np.ndarray | None = None) -> tuple[Any, bool]:
    """Move an offset annotation (a point's name) to a free place; (artist, placed).

    With ``lines`` (pixels) the first place that is also clear of the lines
    wins; when every place meets a line, the first free one.
    """
    xy = t.xy
    if lines is None:
        lines = np.empty((0, 2))
    passes = (True, False) if len(lines) else (False,)
    for clear in passes:
        for offset, ha, va, leader in _point_candidates(t):
            has_arrow = t.arrow_patch is not None
            if leader != has_arrow:
                new = _annotation_like(ax, t, xy, offset, "offset points", ha, va, leader)
                t.remove()
                t = new
            else:
                t.xyann = offset
                t.set_ha(ha)
                t.set_va(va)
            b = placer.box(t)
            if placer.free(b, within) and (not clear or _off_lines(b, lines)):
                return t, True
    return t, False


def _place_off_view(t: Any, placer: _Placer, within: Box) -> bool:
    """Move the text of an arrow to a point off view: farther in, or along the edge."""
    x0, y0 = t.xyann
    n = math.hypot(x0, y0) or 1.0
    ux, uy = x0 / n, y0 / n  # from the edge inwards
    for k in range(0, 48):
        back = (k // 8) * 8.0
        side = ((k % 8 + 1) // 2) * (1 if k % 2 else -1) * 7.0
        t.xyann = (x0 + back * ux - side * uy, y0 + back * uy + side * ux)
        if placer.free(placer.box(t), within):
            return True
    t.xyann = (x0, y0)
    return False


def _place_curve_label(ax: Axes, art: MapArtists, name: str, t: Any, placer: _Placer
                       ) -> tuple[Any, bool]:
    """Move a line's name beside its line, or away from it with a leader line."""
    cd = art.data.curves.get(name)
    if cd is None:
        return t, False
    k_max, mu_max = art.data.k_max, art.data.mu_max
    size = _size_fraction(ax, placer.box(t))
    lines = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]
    axes_box = _axes_box(ax)
    for _attempt in range(3):
        obstacles = _fractions(ax, placer.taken)
        at = curve_label_anchor(cd.points, k_max, mu_max, size, lines, obstacles)
        if at is not None:
            new = _annotation_like(ax, t, at, at, "data", "center", "center", False)
            t.remove()
            t = new
            if placer.free(placer.box(t), axes_box):
                return t, True
            size = (size[0] * 1.1, size[1] * 1.1)
            continue
        break
    from .mapplot import point_along

    for frac in (0.8, 0.6, 0.4, 0.2, 0.9):
        target = point_along(cd.points, k_max, mu_max, frac)
        if target is None:
            break
        at = leader_label_anchor(target, k_max, mu_max, size, lines, _fractions(ax, placer.taken))
        if at is None:
            continue
        new = _annotation_like(ax, t, target, at, "data", "center", "center", True)
        t.remove()
        t = new
        if placer.free(placer.box(t), axes_box):
            return t, True
    return t, False


def band_columns(polygon: np.ndarray, k_max: float, mu_max: float, columns: int = 200
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Column centres and the polygon's interval on each, in view fractions, clipped to the view.

    Unlike the placement module's columns, the polygon itself is not clipped
    first (that bends its edges), only the intervals: their middles lie inside.
    """
    poly = np.asarray(polygon, dtype=np.float64)
    xs = (np.arange(columns) + 0.5) / columns
    lo, hi = column_intervals(poly[:, 0] / k_max, poly[:, 1] / mu_max, xs)
    empty = lo > hi
    lo, hi = np.clip(lo, 0.0, 1.0), np.clip(hi, 0.0, 1.0)
    lo[empty], hi[empty] = 1.0, 0.0
    return xs, lo, hi


def inside(polygon: np.ndarray, xy: tuple[float, float]) -> bool:
    """Is the point ``xy`` (data) inside the polygon?"""
    from matplotlib.path import Path

    return bool(Path(np.asarray(polygon)).contains_point((float(xy[0]), float(xy[1]))))


def _polygon_of(art: MapArtists, mode: Any, xy: tuple[float, float]) -> np.ndarray | None:
    """The polygon of ``mode`` that holds ``xy`` (else the largest one)."""
    from matplotlib.path import Path

    polys = [p for p in art.data.polygons.get(mode, []) if len(p) >= 3]
    for p in polys:
        if Path(p).contains_point(xy):
            return p
    return max(polys, key=len) if polys else None


def _place_region_label(ax: Axes, art: MapArtists, mode: Any, t: Any, placer: _Placer
                        ) -> tuple[Any, bool]:
    """Move a mode symbol to a free place inside its region (else on its thickest part)."""
    xy = t.xy if hasattr(t, "xy") else t.get_position()
    poly = _polygon_of(art, mode, (float(xy[0]), float(xy[1])))
    if poly is None:
        return t, False
    k_max, mu_max = art.data.k_max, art.data.mu_max
    axes_box = _axes_box(ax)
    if getattr(t, "arrow_patch", None) is not None:  # a leader label: make it a plain one
        new = _annotation_like(ax, t, (float(xy[0]), float(xy[1])), (float(xy[0]), float(xy[1])),
                               "data", "center", "center", False)
        t.remove()
        t = new
    size = _size_fraction(ax, placer.box(t))
    lines = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]
    for grow in (1.0, 1.15):
        at = label_anchor(poly, k_max, mu_max, (size[0] * grow, size[1] * grow),
                          obstacles=_fractions(ax, placer.taken), lines=lines)
        if at is None:
            break
        _move_text(t, at)
        if inside(poly, at) and placer.free(placer.box(t), axes_box):
            return t, True
    # a thin band: on the band, wherever it is free
    xs, lo, hi = band_columns(poly, k_max, mu_max, 200)
    room = hi - lo
    for c in np.argsort(-room, kind="stable")[:200]:
        if room[c] <= 0.0:
            break
        at = (float(xs[c] * k_max), float(0.5 * (lo[c] + hi[c]) * mu_max))
        _move_text(t, at)
        if inside(poly, at) and placer.free(placer.box(t), axes_box):
            return t, True
    return t, False


def _move_text(t: Any, at: tuple[float, float]) -> None:
    if hasattr(t, "xyann") and getattr(t, "anncoords", None) == "data":
        t.xy = at
        t.xyann = at
    else:
        t.set_position(at)


def _replace(art: MapArtists, old: Any, new: Any) -> None:
    """Put ``new`` where ``old`` was in the map's records."""
    if new is old:
        return
    for d in (art.point_labels, art.curve_labels, art.off_view):
        for key, v in list(d.items()):
            if v is old:
                d[key] = new
    for lst in art.region_labels.values():
        for i, v in enumerate(lst):
            if v is old:
                lst[i] = new
    extra: list[Any] = art.extra
    for i, v in enumerate(extra):
        if v is old:
            extra[i] = new


# -- the whole figure ------------------------------------------------------------------------


def tidy_figure(fig: Figure, maps: Sequence[MapArtists], *, fixed: Iterable[Artist] = (),
                fit_titles: bool = True) -> TidyReport:
    """Make the text of a laid-out figure of maps legible (see the module docstring).

    Parameters
    ----------
    fig : Figure
        With an Agg canvas; its size and the axes' positions are final.
    maps : sequence of MapArtists
        What :func:`regimemap.drawing.mapplot.draw_map` drew, one per map.
    fixed : iterable of Artist
        Other texts that must stay where they are (e.g. the k' of an animation frame).
    fit_titles : bool
        Wrap or shrink the titles (and the suptitle) to fit the figure.

    Returns
    -------
    TidyReport

    Notes
    -----
    The texts are measured with the figure at :data:`MEASURE_DPI` (and the
    figure's resolution restored afterwards), so the layout, and the bytes of
    an SVG or PDF, do not depend on the resolution asked for a PNG.
    """
    dpi = fig.dpi
    fig.set_dpi(MEASURE_DPI)  # the same decisions at every output resolution
    try:
        return _tidy(fig, maps, list(fixed), fit_titles)
    finally:
        fig.set_dpi(dpi)


def _tidy(fig: Figure, maps: Sequence[MapArtists], fixed: list[Artist], fit_titles: bool
          ) -> TidyReport:
    report = TidyReport()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fig.draw_without_rendering()  # the ticks, titles and keys in their final places
    if fit_titles:
        fb = fig.bbox
        for art in maps:
            if art.title is not None and fit_title(art.title, renderer, fb.x1 - _GAP, fb.y1 - _GAP):
                report.moved.append(f"title {art.title.get_text()!r}")
        sup = getattr(fig, "_suptitle", None)
        if sup is not None:
            fit_title(sup, renderer, fb.x1 - _GAP, fb.y1 - _GAP)
    boxes = text_boxes(fig, maps, fixed)
    placer = _Placer(fig, renderer, [b for _, b in boxes["fixed"]]
                     + [b for _, b in boxes["markers"]])
    for art in maps:
        ax = _axes_of(art)
        if ax is None:
            continue
        axes_box = _axes_box(ax)
        lines = _line_pixels(ax, art)
        for kind, t in _movable(art):
            if not _visible_text(t):
                continue
            within = axes_box if kind in ("curve", "region", "off-view") else None
            ok_here = True
            if kind == "region":
                mode = next((m for m, lst in art.region_labels.items()
                             if any(v is t for v in lst)), None)
                xy = t.get_position()
                poly = _polygon_of(art, mode, (float(xy[0]), float(xy[1])))
                ok_here = (getattr(t, "arrow_patch", None) is not None
                           or (poly is not None and inside(poly, xy)))
            if kind == "point" and getattr(t, "arrow_patch", None) is None:
                ok_here = _off_lines(placer.box(t), lines)  # a name written on a line reads badly
            if kind == "curve":
                ok_here = False  # placed again below with its measured size: closer to its line
            if ok_here and placer.free(placer.box(t), within):
                placer.take(t)
                continue
            if kind in ("point", "design"):
                new, ok = _place_annotation(ax, t, placer, None, lines if kind == "point" else None)
            elif kind == "off-view":
                new, ok = t, _place_off_view(t, placer, axes_box)
            elif kind == "curve":
                name = next((n for n, v in art.curve_labels.items() if v is t), "")
                new, ok = _place_curve_label(ax, art, name, t, placer)
            else:
                mode = next((m for m, lst in art.region_labels.items()
                             if any(v is t for v in lst)), None)
                new, ok = _place_region_label(ax, art, mode, t, placer)
            _replace(art, t, new)
            label = f"{kind} {new.get_text()!r}"
            if ok:
                placer.take(new)
                if kind != "curve":
                    report.moved.append(label)
            else:
                new.set_visible(False)
                report.hidden.append(label)
    return report
