"""Where labels go: inside regions, beside curves, or outside with a leader (no matplotlib).

The one label-placement model of the drawings: every function works in
fractions of the view (``[0, 1] x [0, 1]``), with text boxes measured by the
caller, so the map (:mod:`regimemap.drawing.text.labels`), its tidy pass
(:mod:`regimemap.drawing.text.tidy`), the ambiguity overlay, the atlas and the
animation place their labels by the same rules.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Box",
    "band_columns",
    "box_hits",
    "column_intervals",
    "curve_label_anchor",
    "interior_point",
    "label_anchor",
    "leader_label_anchor",
    "overlaps",
    "point_along",
    "view_points",
]

# -- labels ----------------------------------------------------------------------------------


Box = tuple[float, float, float, float]


def _overlaps(box: Box, others: Sequence[Box]) -> bool:
    x0, y0, x1, y1 = box
    return any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in others)


def overlaps(box: Box, others: Sequence[Box]) -> bool:
    """Whether ``box`` overlaps any of ``others`` (boxes in view fractions)."""
    return _overlaps(box, others)


def _polygon_columns(polygon: np.ndarray, k_max: float, mu_max: float, columns: int
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Column centres x and the polygon's interval [lo, hi] on each, in view fractions."""
    poly = np.asarray(polygon, dtype=np.float64)
    x = poly[:, 0] / k_max
    y = np.clip(poly[:, 1] / mu_max, 0.0, 1.0)
    xs = (np.arange(columns) + 0.5) / columns
    lo, hi = _column_intervals(x, y, xs)
    return xs, lo, hi


def label_anchor(polygon: np.ndarray, k_max: float, mu_max: float, box: tuple[float, float],
                 columns: int = 400, obstacles: Sequence[Box] = (),
                 lines: Sequence[np.ndarray] = ()) -> tuple[float, float] | None:
    """A point well inside a region polygon, clipped to the view, where a label fits.

    Parameters
    ----------
    polygon : ndarray, shape (n, 2)
        A polygon of :func:`regimemap.geometry.region_polygons` (one interval
        of mu per k, as every region of the report is).
    k_max, mu_max : float
        The view.
    box : (float, float)
        Width and height of the label, as fractions of the view.
    columns : int
        Resolution of the search along k.
    obstacles : sequence of (x0, y0, x1, y1)
        Boxes (fractions of the view) the label must not overlap, e.g. the
        names of points.
    lines : sequence of ndarray
        Dense polylines (view fractions, :func:`view_points`) the label should
        not cover; ignored if that leaves no room.

    Returns
    -------
    (k, mu) or None
        The centre of the label: among the windows of columns 1.5 label
        widths wide (then 1 width), the one with the tallest common interval
        of mu, moved up or down to clear the obstacles; None when the label
        does not fit.
    """
    if len(polygon) < 3:
        return None
    if len(lines):
        dense = np.concatenate(list(lines))
        found = _label_anchor(polygon, k_max, mu_max, box, columns, obstacles, dense)
        if found is not None:
            return found
    return _label_anchor(polygon, k_max, mu_max, box, columns, obstacles, np.empty((0, 2)))


def _label_anchor(polygon: np.ndarray, k_max: float, mu_max: float, box: tuple[float, float],
                  columns: int, obstacles: Sequence[Box], dense: np.ndarray
                  ) -> tuple[float, float] | None:
    xs, lo, hi = _polygon_columns(polygon, k_max, mu_max, columns)
    w, h = box
    win = np.lib.stride_tricks.sliding_window_view
    for factor in (1.5, 1.0):
        half = max(1, int(math.ceil(0.5 * factor * w * columns)))
        if 2 * half + 1 > columns:
            continue
        L = win(lo, 2 * half + 1).max(axis=1)
        U = win(hi, 2 * half + 1).min(axis=1)
        room = U - L
        ok = np.flatnonzero(room >= h * 1.15)
        if ok.size == 0:
            continue
        # best room first; among near-equal rooms, the middle of the run first
        mid = ok[len(ok) // 2]
        order = sorted(ok.tolist(), key=lambda c: (-round(float(room[c]) / 0.02), abs(c - mid)))
        for c in order[:200]:
            cx = float(xs[c + half])
            y_lo, y_hi = L[c] + 0.55 * h, U[c] - 0.55 * h
            centre = 0.5 * (L[c] + U[c])
            steps = [0.0] + [s * j * 0.25 * h for j in range(1, 40) for s in (1, -1)]
            for dy in steps:
                cy = centre + dy
                if cy < y_lo - 1e-12 or cy > y_hi + 1e-12:
                    continue
                b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                if not _overlaps(b, obstacles) and not box_hits(b, dense):
                    return cx * k_max, float(cy) * mu_max
    return None


def interior_point(polygon: np.ndarray, k_max: float, mu_max: float,
                   columns: int = 400) -> tuple[float, float] | None:
    """A point inside a (thin) polygon within the view, for the tip of a leader line.

    The middle of the median column among those at least 60 % as tall as the
    tallest; None if the polygon has no part in the view.
    """
    if len(polygon) < 3:
        return None
    xs, lo, hi = _polygon_columns(polygon, k_max, mu_max, columns)
    room = hi - lo
    if room.max() <= 0.0:
        return None
    good = np.flatnonzero(room >= 0.6 * room.max())
    c = int(good[len(good) // 2])
    return float(xs[c] * k_max), float(0.5 * (lo[c] + hi[c]) * mu_max)


def view_points(points: np.ndarray, k_max: float, mu_max: float, step: float = 0.003
                ) -> np.ndarray:
    """A polyline in view fractions, with vertices at most ``step`` apart (for hit tests)."""
    q = np.asarray(points, dtype=np.float64) / (k_max, mu_max)
    if len(q) < 2:
        return q
    seg = np.hypot(*np.diff(q, axis=0).T)
    n = np.maximum(1, np.ceil(seg / step).astype(int))
    parts = [q[:1]]
    for i, m in enumerate(n):
        t = (np.arange(1, m + 1) / m)[:, None]
        parts.append(q[i] + t * (q[i + 1] - q[i]))
    return np.concatenate(parts)


def box_hits(box: Box, dense: np.ndarray) -> bool:
    """Does any of the points ``dense`` (view fractions) fall inside ``box``?"""
    if dense.size == 0:
        return False
    x0, y0, x1, y1 = box
    return bool(np.any((dense[:, 0] > x0) & (dense[:, 0] < x1) & (dense[:, 1] > y0)
                       & (dense[:, 1] < y1)))


def curve_label_anchor(points: np.ndarray, k_max: float, mu_max: float,
                       box: tuple[float, float], lines: Sequence[np.ndarray] = (),
                       obstacles: Sequence[Box] = (), start: float = 0.2,
                       gap: float = 0.008, clearance: float = 0.025
                       ) -> tuple[float, float] | None:
    """Where to centre a curve's label: beside the curve, clear of lines and other labels.

    Candidates run along the visible part of the curve from near its end back
    to ``start`` of its length, on either side; the first whose box lies in
    the view, overlaps no obstacle, crosses no line (``lines``: dense
    polylines in view fractions, from :func:`view_points`) and has no other
    line within ``clearance`` (so that it cannot be read as another line's
    label) wins; if none has that clearance, the first without it.

    Returns
    -------
    (k, mu) or None
        Centre of the label in data coordinates.
    """
    q = view_points(points, k_max, mu_max, 0.003)
    inside = (q[:, 0] >= 0) & (q[:, 0] <= 1) & (q[:, 1] >= 0) & (q[:, 1] <= 1)
    q = q[inside]
    if len(q) < 2:
        return None
    w, h = box
    own = view_points(points, k_max, mu_max, 0.003)
    others = [ln for ln in lines if not (len(ln) == len(own) and np.array_equal(ln, own))]
    everything = np.concatenate(list(lines)) if len(lines) else np.empty((0, 2))
    other = np.concatenate(others) if others else np.empty((0, 2))
    for clear in (clearance, 0.0):
        found = _beside_curve(q, w, h, gap, start, obstacles, everything, other, clear)
        if found is not None:
            return float(found[0] * k_max), float(found[1] * mu_max)
    return None


def _beside_curve(q: np.ndarray, w: float, h: float, gap: float, start: float,
                  obstacles: Sequence[Box], everything: np.ndarray, other: np.ndarray,
                  clear: float) -> tuple[float, float] | None:
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(q, axis=0).T))])
    if s[-1] <= 0.0:
        return None
    for frac in np.arange(0.96, start - 1e-9, -0.02):
        i = int(np.searchsorted(s, frac * s[-1]))
        i = min(max(i, 1), len(q) - 1)
        t = q[i] - q[i - 1]
        norm = math.hypot(t[0], t[1])
        if norm == 0.0:
            continue
        n = np.array([-t[1], t[0]]) / norm
        if n[1] < 0:
            n = -n  # first try the side above the curve
        reach = 0.5 * (abs(w * n[0]) + abs(h * n[1])) + gap
        for side in (1.0, -1.0):
            cx, cy = q[i] + side * reach * n
            b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
            if b[0] < 0.005 or b[1] < 0.005 or b[2] > 0.995 or b[3] > 0.995:
                continue
            if _overlaps(b, obstacles) or box_hits(b, everything):
                continue
            if clear and box_hits((b[0] - clear, b[1] - clear, b[2] + clear, b[3] + clear),
                                  other):
                continue  # another line this close would make the label ambiguous
            return float(cx), float(cy)
    return None


def leader_label_anchor(target: tuple[float, float], k_max: float, mu_max: float,
                        box: tuple[float, float], lines: Sequence[np.ndarray] = (),
                        obstacles: Sequence[Box] = ()) -> tuple[float, float] | None:
    """Where to put the label of a region too thin to hold it, pointing at ``target``.

    Tries positions around the target at growing distances; the label's box
    must lie in the view, clear of lines and obstacles, and the leader line
    must not cross an obstacle.  Returns the label centre (data) or None.
    """
    x, y = target[0] / k_max, target[1] / mu_max
    w, h = box
    everything = np.concatenate(list(lines)) if len(lines) else np.empty((0, 2))
    # 16 directions, diagonals first (labels beside a thin band read best there)
    angles = [-45, 45, 135, -135, -90, 90, 0, 180, -22.5, 22.5, 157.5, -157.5, -67.5, 67.5,
              112.5, -112.5]
    directions = [(math.cos(math.radians(a)), math.sin(math.radians(a))) for a in angles]
    for strict_lines, strict_leader in ((True, True), (False, True), (False, False)):
        for dist in (0.1, 0.15, 0.22, 0.3, 0.4):
            for ux, uy in directions:
                cx, cy = x + ux * dist, y + uy * dist * 0.8
                b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                if b[0] < 0.01 or b[1] < 0.01 or b[2] > 0.99 or b[3] > 0.99:
                    continue
                if _overlaps(b, obstacles) or (strict_lines and box_hits(b, everything)):
                    continue
                if strict_leader:
                    t = np.linspace(0.0, 1.0, 40)[:, None]
                    leader = np.array([x, y]) + t * (np.array([cx, cy]) - np.array([x, y]))
                    if any(box_hits(o, leader) for o in obstacles):
                        continue
                return float(cx * k_max), float(cy * mu_max)
    return None


def _column_intervals(x: np.ndarray, y: np.ndarray, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """lo, hi of a closed polygon along the vertical lines x = xs (empty: lo = 1, hi = 0)."""
    x0, y0 = x, y
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    xa, xb = np.minimum(x0, x1), np.maximum(x0, x1)
    hit = (xa[:, None] <= xs[None, :]) & (xs[None, :] < xb[:, None])
    dx = np.where(x1 != x0, x1 - x0, 1.0)
    t = (xs[None, :] - x0[:, None]) / dx[:, None]
    yy = y0[:, None] + t * (y1 - y0)[:, None]
    lo = np.where(hit, yy, np.inf).min(axis=0)
    hi = np.where(hit, yy, -np.inf).max(axis=0)
    empty = ~hit.any(axis=0)
    lo[empty] = 1.0
    hi[empty] = 0.0
    return lo, hi


def column_intervals(x: np.ndarray, y: np.ndarray, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """lo, hi of the closed polygon (x, y) along the vertical lines x = xs (empty: lo > hi)."""
    return _column_intervals(x, y, xs)


def band_columns(polygon: np.ndarray, k_max: float, mu_max: float, columns: int = 200
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Column centres and the polygon's interval on each, in view fractions, clipped to the view.

    Unlike :func:`label_anchor`'s columns, the polygon itself is not clipped
    first (that bends its edges), only the intervals: their middles lie inside.

    Parameters
    ----------
    polygon : ndarray, shape (n, 2)
        A closed polygon (k, mu).
    k_max, mu_max : float
        The view.
    columns : int
        Number of columns across the view.

    Returns
    -------
    xs, lo, hi : ndarray
        Column centres and the bottom and top of the polygon on each (view
        fractions; an empty column has ``lo = 1 > hi = 0``).
    """
    poly = np.asarray(polygon, dtype=np.float64)
    xs = (np.arange(columns) + 0.5) / columns
    lo, hi = column_intervals(poly[:, 0] / k_max, poly[:, 1] / mu_max, xs)
    empty = lo > hi
    lo, hi = np.clip(lo, 0.0, 1.0), np.clip(hi, 0.0, 1.0)
    lo[empty], hi[empty] = 1.0, 0.0
    return xs, lo, hi


def point_along(pts: np.ndarray, k_max: float, mu_max: float, frac: float
                ) -> tuple[float, float] | None:
    """The point at ``frac`` of the visible length of a polyline (data coordinates).

    Parameters
    ----------
    pts : ndarray, shape (n, 2)
        The polyline (k, mu).
    k_max, mu_max : float
        The view.
    frac : float
        Fraction (0 to 1) of the length of the polyline inside the view.

    Returns
    -------
    (k, mu) or None
        None when less than two of its points are in view.
    """
    q = view_points(pts, k_max, mu_max, 0.003)
    q = q[(q[:, 0] >= 0) & (q[:, 0] <= 1) & (q[:, 1] >= 0) & (q[:, 1] <= 1)]
    if len(q) < 2:
        return None
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(q, axis=0).T))])
    i = int(np.clip(np.searchsorted(s, frac * s[-1]), 0, len(q) - 1))
    return float(q[i, 0] * k_max), float(q[i, 1] * mu_max)


def cell_edges(values: Sequence[float] | NDArray[np.float64]) -> NDArray[np.float64]:
    """Edges of the cells centred on increasing ``values``: half-way between samples, and half a
    spacing beyond the ends."""
    v = np.asarray(values, dtype=np.float64)
    if v.size == 1:
        half = 0.5 * max(abs(float(v[0])), 1.0)
        return np.array([v[0] - half, v[0] + half])
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate(([v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]))
