"""Moving one label of a map to a free place: the candidates of each kind of label.

:func:`regimemap.drawing.text.tidy.tidy_figure` keeps the boxes already taken in the one
placer, :class:`regimemap.drawing.text.placer.Placer`, and, for each label that meets another
text or leaves the figure, calls the mover of its kind.  A mover says only where its label may
go, in order; :meth:`~regimemap.drawing.text.placer.Placer.first_free` picks the first free place:

* a point's name (:func:`place_annotation`): around the point, then farther
  with a leader line;
* the text of an arrow to a point off view (:func:`place_off_view`): farther
  in, or along the edge;
* a line's name (:func:`place_curve_label`): beside the line
  (:func:`regimemap.drawing.text.placement.curve_label_anchor`), then away from it
  with a leader to it;
* a mode symbol (:func:`place_region_label`): inside its region
  (:func:`regimemap.drawing.text.placement.label_anchor`), then anywhere on the
  region (a thin band).

Each returns the label (a new artist when its kind of annotation changed) and
whether it found a free place; :func:`replace_label` puts a new artist in the
map's records.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from itertools import chain
from typing import TYPE_CHECKING, Any

import numpy as np

from ..artists import MapArtists
from .placement import (
    band_columns,
    curve_label_anchor,
    label_anchor,
    leader_label_anchor,
    point_along,
    view_points,
)
from .placer import Placer, clear_of
from .textboxes import Box

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes

__all__ = ["axes_bounds", "inside", "line_pixels", "off_lines", "place_annotation",
           "place_curve_label", "place_off_view", "place_region_label", "polygon_of",
           "replace_label"]

_RING = [(1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1), (0, -1), (1, 0), (-1, 0)]
_HA = {1: "left", 0: "center", -1: "right"}
_VA = {1: "bottom", 0: "center", -1: "top"}


def axes_bounds(ax: Axes) -> Box:
    bb = ax.bbox
    return (bb.x0 - 1.0, bb.y0 - 1.0, bb.x1 + 1.0, bb.y1 + 1.0)


def _fractions(ax: Axes, boxes: Iterable[Box]) -> list[Box]:
    """Pixel boxes as fractions of the axes (the units of :mod:`regimemap.drawing.text.placement`)."""
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


def line_pixels(ax: Axes, art: MapArtists) -> np.ndarray:
    """The map's lines in view as dense points (pixels): a point's name keeps off them."""
    k_max, mu_max = art.data.k_max, art.data.mu_max
    parts = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]
    parts = [q for q in parts if len(q)]
    if not parts:
        return np.empty((0, 2))
    return np.asarray(ax.transAxes.transform(np.concatenate(parts)))


def off_lines(b: Box, lines: np.ndarray) -> bool:
    """Does the box (pixels, less a pixel of margin) stay clear of every line?"""
    return clear_of([lines], 1.0)(b)


def place_annotation(ax: Axes, t: Any, placer: Placer, within: Box | None,
                      lines: np.ndarray | None = None) -> tuple[Any, bool]:
    """Move an offset annotation (a point's name) to a free place; (artist, placed).

    Its places: around the point, then farther with a leader line (:func:`_point_candidates`).
    With ``lines`` (pixels) the first place that is also clear of the lines wins; when every
    place meets a line, the first free one.
    """
    xy = t.xy
    label = [t]

    def places() -> Iterator[Any]:
        for offset, ha, va, leader in _point_candidates(t):
            cur = label[0]
            if leader != (cur.arrow_patch is not None):
                new = _annotation_like(ax, cur, xy, offset, "offset points", ha, va, leader)
                cur.remove()
                label[0] = cur = new
            else:
                cur.xyann = offset
                cur.set_ha(ha)
                cur.set_va(va)
            yield cur

    tests = [clear_of([lines], 1.0), None] if lines is not None and len(lines) else [None]
    for clear in tests:
        found, ok = placer.first_free(places(), within, clear)
        if ok:
            return found, True
    return label[0], False


def place_off_view(t: Any, placer: Placer, within: Box) -> bool:
    """Move the text of an arrow to a point off view: farther in, or along the edge."""
    x0, y0 = t.xyann
    n = math.hypot(x0, y0) or 1.0
    ux, uy = x0 / n, y0 / n  # from the edge inwards

    def places() -> Iterator[Any]:
        for k in range(0, 48):
            back = (k // 8) * 8.0
            side = ((k % 8 + 1) // 2) * (1 if k % 2 else -1) * 7.0
            t.xyann = (x0 + back * ux - side * uy, y0 + back * uy + side * ux)
            yield t

    _, ok = placer.first_free(places(), within)
    if not ok:
        t.xyann = (x0, y0)
    return ok


def place_curve_label(ax: Axes, art: MapArtists, name: str, t: Any, placer: Placer
                       ) -> tuple[Any, bool]:
    """Move a line's name beside its line, or away from it with a leader line.

    Beside the line (:func:`~regimemap.drawing.text.placement.curve_label_anchor`, up to three
    times, the label's size grown a tenth each time it was not free), then at 80, 60, 40, 20 and
    90 % along it with a leader (:func:`~regimemap.drawing.text.placement.leader_label_anchor`);
    each place computed from the space taken so far.
    """
    cd = art.data.curves.get(name)
    if cd is None:
        return t, False
    k_max, mu_max = art.data.k_max, art.data.mu_max
    size = _size_fraction(ax, placer.box(t))
    lines = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]
    label = [t]

    def redrawn(xy: tuple[float, float], xytext: tuple[float, float], leader: bool) -> Any:
        new = _annotation_like(ax, label[0], xy, xytext, "data", "center", "center", leader)
        label[0].remove()
        label[0] = new
        return new

    def beside() -> Iterator[Any]:
        nonlocal size
        for _attempt in range(3):
            at = curve_label_anchor(cd.points, k_max, mu_max, size, lines, _fractions(ax, placer.taken))
            if at is None:
                return
            yield redrawn(at, at, False)
            size = (size[0] * 1.1, size[1] * 1.1)

    def with_leader() -> Iterator[Any]:
        for frac in (0.8, 0.6, 0.4, 0.2, 0.9):
            target = point_along(cd.points, k_max, mu_max, frac)
            if target is None:
                return
            at = leader_label_anchor(target, k_max, mu_max, size, lines, _fractions(ax, placer.taken))
            if at is not None:
                yield redrawn(target, at, True)

    found, ok = placer.first_free(chain(beside(), with_leader()), axes_bounds(ax))
    return (found if ok else label[0]), ok


def inside(polygon: np.ndarray, xy: tuple[float, float]) -> bool:
    """Is the point ``xy`` (data) inside the polygon?"""
    from matplotlib.path import Path

    return bool(Path(np.asarray(polygon)).contains_point((float(xy[0]), float(xy[1]))))


def polygon_of(art: MapArtists, mode: Any, xy: tuple[float, float]) -> np.ndarray | None:
    """The polygon of ``mode`` that holds ``xy`` (else the largest one)."""
    from matplotlib.path import Path

    polys = [p for p in art.data.polygons.get(mode, []) if len(p) >= 3]
    for p in polys:
        if Path(p).contains_point(xy):
            return p
    return max(polys, key=len) if polys else None


def place_region_label(ax: Axes, art: MapArtists, mode: Any, t: Any, placer: Placer
                        ) -> tuple[Any, bool]:
    """Move a mode symbol to a free place inside its region (else on its thickest part)."""
    xy = t.xy if hasattr(t, "xy") else t.get_position()
    poly = polygon_of(art, mode, (float(xy[0]), float(xy[1])))
    if poly is None:
        return t, False
    k_max, mu_max = art.data.k_max, art.data.mu_max
    axes_box = axes_bounds(ax)
    if getattr(t, "arrow_patch", None) is not None:  # a leader label: make it a plain one
        new = _annotation_like(ax, t, (float(xy[0]), float(xy[1])), (float(xy[0]), float(xy[1])),
                               "data", "center", "center", False)
        t.remove()
        t = new
    size = _size_fraction(ax, placer.box(t))
    lines = [view_points(c.points, k_max, mu_max) for c in art.data.curves.values()]

    def places() -> Iterator[Any]:
        for grow in (1.0, 1.15):
            at = label_anchor(poly, k_max, mu_max, (size[0] * grow, size[1] * grow),
                              obstacles=_fractions(ax, placer.taken), lines=lines)
            if at is None:
                break
            _move_text(t, at)
            if inside(poly, at):
                yield t
        # a thin band: on the band, wherever it is free
        xs, lo, hi = band_columns(poly, k_max, mu_max, 200)
        room = hi - lo
        for c in np.argsort(-room, kind="stable")[:200]:
            if room[c] <= 0.0:
                break
            at = (float(xs[c] * k_max), float(0.5 * (lo[c] + hi[c]) * mu_max))
            _move_text(t, at)
            if inside(poly, at):
                yield t

    _, ok = placer.first_free(places(), axes_box)
    return t, ok


def _move_text(t: Any, at: tuple[float, float]) -> None:
    if hasattr(t, "xyann") and getattr(t, "anncoords", None) == "data":
        t.xy = at
        t.xyann = at
    else:
        t.set_position(at)


def replace_label(art: MapArtists, old: Any, new: Any) -> None:
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
