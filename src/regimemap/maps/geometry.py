"""Regions of the k-mu plane as vector polygons (for crisp SVG/PDF fills).

The column rule and the polygons it labels are one argument, kept in one module of some
length (the bisection of the edges is :mod:`regimemap.maps.bisection`'s).

Along any vertical line (fixed k) every region of the report is one interval
of mu, so a region is exactly described by its lower and upper edges as
functions of k.  The polygons below sample those edges on a fine k grid that
contains every characteristic abscissa of the map (k_A, k_B', b/|a|, k_D,
the pole d/c, the crossing C' ...), and locate the ends of each run of
non-empty columns by bisection, so the fills meet the boundary curves without
a staircase.  With loads a mode may hold several intervals of a column (lift-off
holds whole columns), so each column is cut at every threshold and interval end
of the column rule (:func:`final_pieces`), the pieces are labelled by the rule,
and the polygons follow each mode's pieces across the columns.  Nothing here
imports matplotlib.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import NamedTuple

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.constants import dotted_line_344, mu_star_signed, mu_star_star, rock_possible, thresholds
from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES, Mode
from ..mechanics.regions import affine_terms, column_intervals
from .bisection import bisect_edge, bisect_edges
from .classify import classify_constants

__all__ = [
    "DEFAULT_SAMPLES",
    "Interval",
    "sample_k",
    "final_intervals",
    "final_pieces",
    "raw_pieces",
    "raw_intervals",
    "breakpoints",
    "bisect_edge",
    "bisect_edges",
    "region_polygons",
    "area_in_view",
    "extend_run",
    "run_outline",
]

#: Samples of k across the view for polygons and curves (breakpoints are added).
DEFAULT_SAMPLES = 801

#: (lo, hi) arrays of mu per k; the interval is empty where lo >= hi (NaN-free).
Interval = tuple[np.ndarray, np.ndarray]


def final_intervals(p: Parameters, k: np.ndarray, mu_cap: float) -> dict[Mode, Interval]:
    """The interval of mu of each mode of the final map (:func:`regimemap.classify`) at each k.

    Intervals are clipped to [0, mu_cap]; a mode absent from a column has lo == hi.
    """
    k = np.asarray(k, dtype=np.float64)
    t = thresholds(k, p.constants)
    lower, upper, mu_s, f_pos = t.lower, t.upper, t.mu_star, t.f_pos
    e4 = np.where(t.rest_ok, t.mu_rest, np.inf)
    e1 = np.minimum(np.maximum(lower, 0.0), e4)
    e2 = np.minimum(np.maximum(upper, e1), e4)
    e3 = np.minimum(np.maximum(mu_s, e2), e4)
    e1, e2, e3, e4c = (np.clip(v, 0.0, mu_cap) for v in (e1, e2, e3, e4))
    return {
        Mode.SRO_PRIME_MINUS: (np.zeros_like(k), e1),
        Mode.SL: (e1, e2),
        # the slide-rock run (e2, e3) is SRO- where f_x >= 0 and SRO+ elsewhere
        Mode.SRO_MINUS: (np.where(f_pos, e2, e3), e3),
        Mode.SRO_PLUS: (np.where(f_pos, e3, e2), e3),
        Mode.RO: (e3, e4c),
        Mode.RE: (e4c, np.full_like(k, mu_cap)),
    }


def raw_intervals(mode: Mode, p: Parameters, k: np.ndarray, mu_cap: float) -> Interval:
    """The interval of mu of the report's raw region of ``mode`` (:mod:`regimemap.mechanics.regions`).

    For the report's block (regular columns); a loaded block's raw regions are
    :func:`raw_pieces`.
    """
    k = np.asarray(k, dtype=np.float64)
    cst = p.constants
    t = thresholds(k, cst)
    rest_ok, lower, upper, mu_s, f_pos = t.rest_ok, t.lower, t.upper, t.mu_star, t.f_pos
    zero = np.zeros_like(k)
    top = np.full_like(k, mu_cap)
    mode = Mode(mode)
    if mode is Mode.RE:
        lo, hi = np.where(rest_ok, k, top), top
    elif mode is Mode.SL:
        lo, hi = np.maximum(lower, 0.0), np.minimum(k, upper)
    elif mode is Mode.RO:
        rock_ok = rock_possible(k, cst)
        lo, hi = np.where(rock_ok, mu_s, top), top
    elif mode is Mode.SRO_MINUS:
        ms = mu_star_signed(k, cst.aO, cst.bO, cst.cO, cst.dO)
        mb = p.mu_Bprime
        lo1, hi1 = np.maximum(upper, 0.0), np.minimum(ms, mb)
        lo2, hi2 = np.maximum(np.maximum(ms, mb), 0.0), upper
        use2 = (hi2 - lo2) > (hi1 - lo1)
        lo, hi = np.where(use2, lo2, lo1), np.where(use2, hi2, hi1)
    elif mode is Mode.SRO_PLUS:
        lo = zero
        hi = np.where(~f_pos, np.minimum(mu_s, dotted_line_344(k, cst)), zero)
    elif mode is Mode.SRO_PRIME_MINUS:
        mss = mu_star_star(k, cst.aP, cst.bP, cst.cP, cst.dP)
        bound = np.where(cst.cP * k >= cst.dP, lower, np.minimum(lower, mss))
        lo, hi = zero, bound
    else:
        lo, hi = zero, zero
    lo = np.clip(lo, 0.0, mu_cap)
    hi = np.clip(hi, 0.0, mu_cap)
    return lo, np.maximum(hi, lo)


def breakpoints(p: Parameters) -> list[float]:
    """Abscissae where a region may start or end or a boundary has a corner."""
    pts = [0.0, p.k_A, p.k_Bprime, p.b_over_abs_a, p.k_D, p.k_pole, p.k_F, p.mu_A]
    kc = p.k_Cprime if p.kprime < 0 else None
    if kc is not None:
        pts.append(kc)
    # where the upper line crosses mu = 0 (above C) and mu_B' (below C)
    if p.kprime != 0.0:
        pts.append((1.0 / p.gamma - p.mu_Bprime) / p.kprime)
    if p.loaded:
        # where a condition on k alone changes: W = 0, f_y of rocking about O = 0,
        # rest about O' fails, lift-off starts or ends, and where the lines meet mu_B'
        c = p.constants
        with np.errstate(divide="ignore", invalid="ignore"):
            t0, t1 = affine_terms(np.zeros(1), c), affine_terms(np.ones(1), c)
            for key in ("W", "fyO", "TP", "TO", "fxO", "fxP"):
                pts.append(float(-t0[key][0] / (t1[key][0] - t0[key][0])))
        lift = p.lift_off
        if lift is not None:
            pts += list(lift)
    return sorted({float(x) for x in pts if math.isfinite(x) and x >= 0.0})


def sample_k(p: Parameters, k_max: float, samples: int, more: Iterable[float] = ()) -> np.ndarray:
    """``samples`` values of k over [0, k_max] with every breakpoint (and ``more``) among them.

    Each breakpoint goes in with its two neighbours 1e-9 k_max away, so corners are exact.
    """
    k = np.linspace(0.0, k_max, samples)
    extra = [x for x in breakpoints(p) + list(more) if 0.0 <= x <= k_max]
    # put each breakpoint in with its two neighbours, so corners are exact
    eps = k_max * 1e-9
    extra += [x - eps for x in extra if x - eps > 0] + [x + eps for x in extra if x + eps < k_max]
    return np.unique(np.concatenate([k, extra]))


def region_polygons(p: Parameters, k_max: float, mu_max: float,
                    modes: Iterable[Mode] | None = None, raw: bool = False,
                    samples: int = DEFAULT_SAMPLES, overshoot: float = 1.5) -> dict[Mode, list[np.ndarray]]:
    """Polygons (arrays of (k, mu) vertices) of each mode's region within the view.

    Parameters
    ----------
    p : Parameters
    k_max, mu_max : float
        The view is [0, k_max] x [0, mu_max]; polygons extend a little beyond
        (``overshoot`` x mu_max) and are meant to be clipped by the axes.
    modes : iterable of Mode, optional
        Which modes (default: the six map modes).
    raw : bool
        The report's raw region of each mode (single-mode figures) instead of
        the final map.
    samples : int
        Number of k samples (breakpoints are added).

    Returns
    -------
    dict[Mode, list[ndarray of shape (n, 2)]]
        For each mode, one closed polygon per run of k where it is present.
    """
    modes = tuple((LOADED_MAP_MODES if p.loaded else MAP_MODES) if modes is None else modes)
    mu_cap = mu_max * overshoot
    k = sample_k(p, k_max, samples)
    if p.loaded:
        return _track_polygons(p, k, mu_cap, modes, raw)

    def intervals(kk: np.ndarray) -> dict[Mode, Interval]:
        if raw:
            return {m: raw_intervals(m, p, kk, mu_cap) for m in modes}
        return final_intervals(p, kk, mu_cap)

    cols = intervals(k)
    # the runs of columns where each mode is present, and their ends to find (all at once)
    runs: list[tuple[Mode, np.ndarray]] = []
    edges: list[tuple[int, int, int]] = []  # (index of the mode in ``modes``, inner, outer)
    for i, mode in enumerate(modes):
        lo, hi = cols[mode]
        idx = np.flatnonzero((hi - lo) > 0.0)
        if idx.size == 0:
            continue
        for run in np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1):
            runs.append((mode, run))
            for inner, outer in ((run[0], run[0] - 1), (run[-1], run[-1] + 1)):
                if 0 <= outer < k.size:
                    edges.append((i, int(inner), int(outer)))
    edge_mode = np.array([e[0] for e in edges], dtype=np.intp)

    def present(which: np.ndarray, kk: np.ndarray) -> np.ndarray:
        at = intervals(kk.ravel())
        width = np.stack([at[m][1] - at[m][0] for m in modes]).reshape((len(modes),) + kk.shape)
        return np.asarray(width[edge_mode[which], np.arange(kk.shape[0])] > 0.0)

    ends = bisect_edges(present, k[[e[1] for e in edges]], k[[e[2] for e in edges]])
    found = {edge: float(ke) for edge, ke in zip(edges, ends)}
    out: dict[Mode, list[np.ndarray]] = {mode: [] for mode in modes}
    for mode, run in runs:
        i, i0, i1 = modes.index(mode), int(run[0]), int(run[-1])
        ks = list(k[run])
        if i0 > 0:
            ks.insert(0, found[(i, i0, i0 - 1)])
        if i1 < k.size - 1:
            ks.append(found[(i, i1, i1 + 1)])
        kk = np.asarray(ks)
        out[mode].append(run_outline(kk, *intervals(kk)[mode]))
    return out


def extend_run(k: np.ndarray, lo: np.ndarray, hi: np.ndarray, front: tuple[float, float, float] | None,
               back: tuple[float, float, float] | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A run of columns ``(k, lo, hi)`` with the column ``front`` (a ``(k, lo, hi)``) before it and
    ``back`` after it, where they are not None (the ends found beyond its first and last column)."""
    if front is not None:
        k, lo, hi = (np.concatenate([[v], arr]) for v, arr in zip(front, (k, lo, hi)))
    if back is not None:
        k, lo, hi = (np.concatenate([arr, [v]]) for v, arr in zip(back, (k, lo, hi)))
    return k, lo, hi


def run_outline(k: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The closed polygon of a run of columns ``lo <= mu <= hi`` at ``k``: its lower edge left to
    right, then its upper edge right to left."""
    return np.concatenate([np.column_stack([k, lo]), np.column_stack([k[::-1], hi[::-1]])])


# -- loaded blocks: several pieces of a mode per column --------------------------------------

Pieces = list[list[tuple[Mode, float, float]]]

#: The label of a piece of a column that no hypothesis holds: a single float where strict
#: ends meet (mu = mu_B' at a corner), left out of the pieces.
_NO_MODE = 255
#: Mode codes are 0 .. _CODES - 1.
_CODES = max(int(m) for m in Mode) + 1


def _merge(column: list[tuple[Mode, float, float]]) -> list[tuple[Mode, float, float]]:
    """Sort pieces by lo and join touching pieces of the same mode."""
    out: list[tuple[Mode, float, float]] = []
    for m, lo, hi in sorted(column, key=lambda x: (x[1], x[2])):
        if out and out[-1][0] == m and out[-1][2] >= lo:
            out[-1] = (m, out[-1][1], max(out[-1][2], hi))
        else:
            out.append((m, lo, hi))
    return out


def _final_table(p: Parameters, k: np.ndarray, mu_cap: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every column cut at all its ends: (lo, hi, label) of each cut, arrays of shape (len(k), m).

    The cuts of a column are sorted bottom up and tile [0, mu_cap]; empty cuts
    have lo == hi; the label is the rule's mode at the middle (``_NO_MODE``
    where no hypothesis holds).
    """
    cst = p.constants
    t = thresholds(k, cst)
    ends = [np.zeros_like(k), np.full_like(k, mu_cap), t.mu_rest, t.upper, t.lower, t.mu_star]
    for _, lo, hi in column_intervals(k, cst):
        ends += [lo, hi]
    E = np.stack([np.broadcast_to(e, k.shape) for e in ends], axis=1)
    E = np.sort(np.clip(np.where(np.isfinite(E), E, np.where(E > 0, mu_cap, 0.0)), 0.0, mu_cap), axis=1)
    a, b = E[:, :-1], E[:, 1:]
    # only the non-empty cuts are labelled (most are empty: ends meet or are clipped)
    full = b > a
    lab = np.full(a.shape, _NO_MODE, dtype=np.uint8)
    rows = np.broadcast_to(k[:, None], a.shape)
    lab[full] = classify_constants(rows[full], 0.5 * (a[full] + b[full]), cst)
    return a, b, lab


def final_pieces(p: Parameters, k: np.ndarray, mu_cap: float) -> Pieces:
    """The final map along each column as pieces ``(mode, lo, hi)`` of mu in [0, mu_cap], bottom up.

    Each column is cut at the thresholds of the rule and at the ends of every
    hypothesis's interval (:func:`~regimemap.mechanics.regions.column_intervals`),
    so the mode is constant on each piece; it is labelled by the rule itself
    (:func:`~regimemap.maps.classify.classify_constants`) at its middle.  A
    piece that no hypothesis holds (one float wide, where strict ends meet) is
    left out.
    """
    k = np.asarray(k, dtype=np.float64)
    a, b, lab = _final_table(p, k, mu_cap)
    keep = (b > a) & (lab != _NO_MODE)
    out: Pieces = []
    for j in range(k.size):
        col = [(Mode(int(lab[j, s])), float(a[j, s]), float(b[j, s]))
               for s in np.flatnonzero(keep[j])]
        out.append(_merge(col))
    return out


def raw_pieces(p: Parameters, k: np.ndarray, mu_cap: float, modes: Iterable[Mode]) -> Pieces:
    """The raw regions of ``modes`` along each column as pieces ``(mode, lo, hi)`` (they may overlap)."""
    k = np.asarray(k, dtype=np.float64)
    wanted = set(modes)
    out: Pieces = [[] for _ in range(k.size)]
    for m, lo, hi in column_intervals(k, p.constants):
        if m not in wanted:
            continue
        lo_c, hi_c = np.clip(lo, 0.0, mu_cap), np.clip(hi, 0.0, mu_cap)
        for j in np.flatnonzero(hi_c > lo_c):
            out[j].append((m, float(lo_c[j]), float(hi_c[j])))
    return [_merge(col) for col in out]


class _Tracks(NamedTuple):
    """The pieces of every column by mode code and rank: the t-th piece of mode m, bottom up."""

    counts: np.ndarray  #: (columns, codes): how many pieces of each mode a column has
    lo: np.ndarray  #: (codes, ranks, columns): lo of the t-th piece of mode m (NaN: none)
    hi: np.ndarray  #: (codes, ranks, columns)


def _table_tracks(a: np.ndarray, b: np.ndarray, lab: np.ndarray) -> _Tracks:
    """:func:`final_pieces` (:func:`_merge` of the labelled cuts) as :class:`_Tracks`, all columns at once.

    The cuts of :func:`_final_table` are visited bottom up, one cut of every
    column per step: a non-empty labelled cut of the mode of the column's last
    piece that touches it extends that piece; any other starts the next piece
    of its mode.
    """
    n, cuts = a.shape
    count = np.zeros((n, _CODES), dtype=np.intp)
    lo = np.full((_CODES, cuts, n), np.nan)
    hi = np.full((_CODES, cuts, n), np.nan)
    cur = np.full(n, -1, dtype=np.intp)  # mode of the last piece of each column
    cur_t = np.zeros(n, dtype=np.intp)  # and its rank
    cur_hi = np.full(n, -np.inf)
    labels = lab.astype(np.intp)
    for s in range(cuts):
        a_s, b_s, m_s = a[:, s], b[:, s], labels[:, s]
        valid = (b_s > a_s) & (m_s != _NO_MODE)
        if not valid.any():
            continue
        cont = valid & (m_s == cur) & (cur_hi >= a_s)
        new = valid & ~cont
        j = np.flatnonzero(new)
        m = m_s[j]
        t = count[j, m]
        count[j, m] = t + 1
        lo[m, t, j] = a_s[j]
        cur[j], cur_t[j], cur_hi[j] = m, t, b_s[j]
        c = np.flatnonzero(cont)
        cur_hi[c] = np.maximum(cur_hi[c], b_s[c])
        v = np.flatnonzero(valid)
        hi[cur[v], cur_t[v], v] = cur_hi[v]
    return _Tracks(count, lo, hi)


def _table_counts(a: np.ndarray, b: np.ndarray, lab: np.ndarray) -> np.ndarray:
    """``_table_tracks(a, b, lab).counts`` without the pieces' ends: (columns, codes), all at once.

    A non-empty labelled cut starts a piece unless the column's previous such
    cut has its mode and touches it (their ends are sorted, so the run's top
    is that cut's top).
    """
    n, cuts = a.shape
    labels = lab.astype(np.intp)
    valid = (b > a) & (labels != _NO_MODE)
    last = np.maximum.accumulate(np.where(valid, np.arange(cuts), -1), axis=1)
    prev = np.concatenate([np.full((n, 1), -1), last[:, :-1]], axis=1)
    rows = np.arange(n)[:, None]
    at = np.maximum(prev, 0)
    joined = (prev >= 0) & (labels[rows, at] == labels) & (b[rows, at] >= a)
    starts = valid & ~joined
    codes = (rows * _CODES + labels)[starts]
    return np.bincount(codes, minlength=n * _CODES).reshape(n, _CODES)


def _list_tracks(cols: Pieces) -> _Tracks:
    """Pieces as lists per column (:func:`raw_pieces`) as :class:`_Tracks`."""
    n = len(cols)
    ranks = max([len(col) for col in cols] + [1])
    count = np.zeros((n, _CODES), dtype=np.intp)
    lo = np.full((_CODES, ranks, n), np.nan)
    hi = np.full((_CODES, ranks, n), np.nan)
    for j, pieces in enumerate(cols):
        for m, a, b in pieces:
            t = count[j, int(m)]
            count[j, int(m)] = t + 1
            lo[int(m), t, j] = a
            hi[int(m), t, j] = b
    return _Tracks(count, lo, hi)


def _track_polygons(p: Parameters, k: np.ndarray, mu_cap: float, modes: tuple[Mode, ...],
                    raw: bool) -> dict[Mode, list[np.ndarray]]:
    """The polygons of a loaded block: each mode's t-th piece followed across the columns.

    The ends of each run of columns are found by :func:`bisect_edges`, all at
    once (the same k as :func:`bisect_edge` one by one).
    """
    def tracks(kk: np.ndarray) -> _Tracks:
        kk = np.asarray(kk, dtype=np.float64)
        if raw:
            return _list_tracks(raw_pieces(p, kk, mu_cap, modes))
        return _table_tracks(*_final_table(p, kk, mu_cap))

    tr = tracks(k)
    out: dict[Mode, list[np.ndarray]] = {m: [] for m in modes}
    # every run of columns of every (mode, rank), and its ends to find: (mode, t, inner, outer)
    runs: list[tuple[int, int, np.ndarray]] = []
    edges: list[tuple[int, int, int, int]] = []
    for m in sorted(int(mode) for mode in out):
        for t in range(tr.lo.shape[1]):
            idx = np.flatnonzero(np.isfinite(tr.lo[m, t]))
            if idx.size == 0:
                continue
            for run in np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1):
                runs.append((m, t, run))
                for inner, outer in ((run[0], run[0] - 1), (run[-1], run[-1] + 1)):
                    if 0 <= outer < k.size:
                        edges.append((m, t, int(inner), int(outer)))
    edge_m = np.array([e[0] for e in edges], dtype=np.intp)
    edge_t = np.array([e[1] for e in edges], dtype=np.intp)

    def present(which: np.ndarray, kk: np.ndarray) -> np.ndarray:
        flat = kk.ravel()
        counts = (_list_tracks(raw_pieces(p, flat, mu_cap, modes)).counts if raw
                  else _table_counts(*_final_table(p, flat, mu_cap)))
        count = counts.reshape(kk.shape + (_CODES,))
        rows = np.arange(kk.shape[0])[:, None]
        cols = np.arange(kk.shape[1])[None, :]
        return np.asarray(count[rows, cols, edge_m[which][:, None]] > edge_t[which][:, None])

    ke = bisect_edges(present, k[[e[2] for e in edges]], k[[e[3] for e in edges]])
    at_edge = tracks(ke)
    found = {edge: (float(ke[i]), at_edge.lo[edge[0], edge[1], i], at_edge.hi[edge[0], edge[1], i])
             for i, edge in enumerate(edges)
             if np.isfinite(at_edge.lo[edge[0], edge[1], i]) and ke[i] != k[edge[2]]}
    for m, t, run in runs:
        i0, i1 = int(run[0]), int(run[-1])
        out[Mode(m)].append(run_outline(*extend_run(k[run], tr.lo[m, t, run], tr.hi[m, t, run],
                                                    found.get((m, t, i0, i0 - 1)),
                                                    found.get((m, t, i1, i1 + 1)))))
    return out


def area_in_view(polygon: np.ndarray, k_max: float, mu_max: float) -> float:
    """The area of ``polygon`` (an (n, 2) array of (k, mu)) inside the view ``[0, k_max] x [0, mu_max]``.

    The polygon is clipped to the view's rectangle (Sutherland-Hodgman; the
    regions of a map are simple polygons) and the shoelace formula gives the
    area.  A key names a mode only where this is positive: the polygons reach
    beyond the view so that the fills meet its edges.
    """
    pts = [(float(x), float(y)) for x, y in np.asarray(polygon, dtype=float)]
    # each edge of the view as (inside test, crossing) on one coordinate
    for axis, bound, keep_below in ((0, 0.0, False), (0, k_max, True), (1, 0.0, False),
                                    (1, mu_max, True)):
        if not pts:
            return 0.0

        def inside(q: tuple[float, float], axis: int = axis, bound: float = bound,
                   keep_below: bool = keep_below) -> bool:
            return q[axis] <= bound if keep_below else q[axis] >= bound

        out: list[tuple[float, float]] = []
        for i, cur in enumerate(pts):
            prev = pts[i - 1]
            if inside(cur) != inside(prev):
                t = (bound - prev[axis]) / (cur[axis] - prev[axis])
                cut = (prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1]))
                out.append((bound, cut[1]) if axis == 0 else (cut[0], bound))
            if inside(cur):
                out.append(cur)
        pts = out
    if len(pts) < 3:
        return 0.0
    x = np.array([q[0] for q in pts])
    y = np.array([q[1] for q in pts])
    return float(0.5 * abs(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1))))
