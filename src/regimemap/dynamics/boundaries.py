"""Where the boundaries between the categories of an outcome map cross the grid, by bisection.

numpy only.  An outcome map knows the category of each node of its grid; a boundary between two
categories crosses every grid edge whose two nodes differ.  :func:`refine_crossings` finds each
crossing along its edge -- along the swept input that varies on that edge, the other one fixed
-- by bisection, to a tolerance of 10^-3 of that input's range, for all the edges of the grid at
once: each step simulates the probes of every open bracket in one batch (the ``evaluate``
callable), so the cost is a few batches, not one per edge.

* A step probes each bracket at ``2^b - 1`` evenly spaced points (``b = 1``: plain bisection).
  A batch costs about as much as its longest run whatever its size, so for few brackets
  (small maps) a step probes more points and fewer batches are run (:func:`plan_refinement`
  picks ``b``, the same for every step).
* A probe whose category is neither end's splits its bracket in two: an edge between ``a`` and
  ``c`` that a thin band of ``b`` crosses gets two crossings, ``a|b`` and ``b|c``; any change of
  category between neighbouring probes is a bracket of its own.  So that chaotic stretches
  (outcomes that flip from probe to probe) cannot swell the batches, a step falls back to one
  probe per bracket when the brackets have multiplied, and an edge with more than
  :data:`MAX_CROSSINGS` crossings is refined no further.
* A cell whose corners alternate between two categories (a saddle) is probed at its centre, in
  the first batch, so that the assembly (:mod:`regimemap.dynamics.regions`) knows which
  diagonal joins.

The result, :class:`Crossings`, gives every crossing as its edge, the fraction of the edge from
its first node, and the categories on either side; the positions in the swept inputs' units
follow by linear interpolation between the edge's nodes.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Crossings", "Evaluate", "RefinePlan", "TOLERANCE", "crossing_points", "plan_refinement",
           "refinable", "refine_crossings", "saddle_cells"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
CodeArray = NDArray[np.int8]
#: ``evaluate(first, second)``: the categories of the runs at these values of the two swept
#: inputs (1-D arrays of one length), simulated as one batch.
Evaluate = Callable[[FloatArray, FloatArray], ArrayLike]

#: Default tolerance of a crossing, as a fraction of the range of the swept input along its edge.
TOLERANCE = 1e-3
#: A batch costs about as much as this many runs besides its runs: the stepper's overhead per
#: step (~170 us, against ~0.17 us per run and step) over the steps of its longest run, which
#: near a boundary is two to three times the mean run (Makris-Roussos map, 200 x 200: one batch
#: of 3899 probes took about half as long as three of 557).  Used to choose the probes per bracket.
BATCH_OVERHEAD_RUNS = 2000
#: Most probes per bracket and step (2^MAX_BITS - 1).
MAX_BITS = 6
#: Crossings of one edge beyond which its brackets are left as they are (a chaotic stretch).
MAX_CROSSINGS = 8
#: Smallest batch allowed before the probes per bracket fall back to one.
MIN_BUDGET = 5000


@dataclass(frozen=True)
class Crossings:
    """The crossings of the category boundaries with the grid of an outcome map.

    Edges are named by their first node (row ``i``, column ``j``) and ``axis``: 0 for the edge
    from (i, j) to (i, j + 1) (along the first swept input, on row i), 1 for the edge from
    (i, j) to (i + 1, j) (along the second one, on column j).

    Attributes
    ----------
    axis : ndarray of int8
    i, j : ndarray of int
        The edge of each crossing.
    fraction : ndarray
        Where it crosses, from 0 at node (i, j) to 1 at the other node.
    before, after : ndarray of int8
        The categories on the side of node (i, j) and on the other side.
    centre_i, centre_j : ndarray of int
        Cells (by their first node) whose centre was probed.
    centre : ndarray of int8
        The category at their centres.
    runs, batches : int
        Runs simulated and batches run to find them.
    """

    axis: CodeArray
    i: IntArray
    j: IntArray
    fraction: FloatArray
    before: CodeArray
    after: CodeArray
    centre_i: IntArray
    centre_j: IntArray
    centre: CodeArray
    runs: int = 0
    batches: int = 0

    @staticmethod
    def empty() -> Crossings:
        """No crossing (a map of one category)."""
        z = np.zeros(0, dtype=np.int64)
        c = np.zeros(0, dtype=np.int8)
        return Crossings(c, z, z, np.zeros(0), c, c, z, z, c)

    def __len__(self) -> int:
        return int(self.fraction.size)

    def arrays(self) -> dict[str, NDArray[Any]]:
        """Every field as an array (``runs`` and ``batches`` 0-d), for an ``.npz`` file."""
        return {f.name: np.asarray(getattr(self, f.name)) for f in fields(self)}

    @staticmethod
    def from_arrays(arrays: Mapping[str, Any]) -> Crossings:
        """The inverse of :meth:`arrays`.

        Raises
        ------
        KeyError
            If a field is missing.
        """
        kinds: dict[str, Any] = {"axis": np.int8, "before": np.int8, "after": np.int8, "centre": np.int8,
                                 "i": np.int64, "j": np.int64, "centre_i": np.int64,
                                 "centre_j": np.int64, "fraction": np.float64}
        kw: dict[str, Any] = {name: np.asarray(arrays[name], dtype=kind).ravel()
                              for name, kind in kinds.items()}
        return Crossings(**kw, runs=int(arrays["runs"]), batches=int(arrays["batches"]))


@dataclass(frozen=True)
class RefinePlan:
    """What :func:`refine_crossings` will simulate when no probe finds a third category.

    Attributes
    ----------
    brackets : int
        Grid edges between two categories.
    bits : int
        Halvings of each bracket per batch (``2^bits - 1`` probes per bracket).
    batches : int
        Batches of probes (the saddles' centres ride in the first).
    runs : int
        Runs in all the batches.
    saddles : int
        Cells probed at their centre.
    """

    brackets: int
    bits: int
    batches: int
    runs: int
    saddles: int


def _strictly_monotonic(v: FloatArray) -> bool:
    d = np.diff(v)
    return bool(v.size >= 2 and np.all(np.isfinite(v)) and (np.all(d > 0) or np.all(d < 0)))


def refinable(x: ArrayLike, y: ArrayLike) -> bool:
    """Can a map on these axes be refined: at least two values on each, strictly monotonic?"""
    return (_strictly_monotonic(np.asarray(x, dtype=np.float64))
            and _strictly_monotonic(np.asarray(y, dtype=np.float64)))


def _brackets(x: FloatArray, y: FloatArray, cat: NDArray[Any], tol: float
              ) -> tuple[CodeArray, IntArray, IntArray, CodeArray, CodeArray, FloatArray]:
    """The grid edges between two categories: axis, i, j, the end categories and the width in
    fractions of the edge below which a bracket is closed."""
    hi_, hj = np.nonzero(cat[:, :-1] != cat[:, 1:])
    vi, vj = np.nonzero(cat[:-1, :] != cat[1:, :])
    axis = np.concatenate([np.zeros(hi_.size, np.int8), np.ones(vi.size, np.int8)])
    i = np.concatenate([hi_, vi]).astype(np.int64)
    j = np.concatenate([hj, vj]).astype(np.int64)
    c0 = np.concatenate([cat[hi_, hj], cat[vi, vj]]).astype(np.int8)
    c1 = np.concatenate([cat[hi_, hj + 1], cat[vi + 1, vj]]).astype(np.int8)
    span_x = tol * float(np.ptp(x))
    span_y = tol * float(np.ptp(y))
    pitch = np.concatenate([np.abs(x[hj + 1] - x[hj]), np.abs(y[vi + 1] - y[vi])])
    limit = np.concatenate([np.full(hi_.size, span_x), np.full(vi.size, span_y)]) / pitch
    return axis, i, j, c0, c1, limit


def saddle_cells(category: ArrayLike) -> tuple[IntArray, IntArray]:
    """Cells (first node i, j) whose corners alternate between two categories."""
    c = np.asarray(category)
    a, b, cc, d = c[:-1, :-1], c[:-1, 1:], c[1:, 1:], c[1:, :-1]
    i, j = np.nonzero((a == cc) & (b == d) & (a != b))
    return i.astype(np.int64), j.astype(np.int64)


def _halvings(limit: FloatArray) -> IntArray:
    """Halvings of a unit bracket until it is at most ``limit`` wide."""
    with np.errstate(divide="ignore"):
        need = np.ceil(np.log2(1.0 / limit) - 1e-12)
    return np.maximum(need, 0).astype(np.int64)


def plan_refinement(x: ArrayLike, y: ArrayLike, category: ArrayLike, tol: float = TOLERANCE) -> RefinePlan:
    """How :func:`refine_crossings` will work on this map: brackets, probes, batches and runs.

    The halvings per batch ``b`` minimise the estimated cost, the runs plus
    :data:`BATCH_OVERHEAD_RUNS` per batch: plain bisection for many brackets, more probes per
    bracket (and fewer batches) for few.
    """
    xs = np.asarray(x, dtype=np.float64)
    ys = np.asarray(y, dtype=np.float64)
    cat = np.asarray(category)
    if not refinable(xs, ys) or cat.shape != (ys.size, xs.size):
        return RefinePlan(0, 1, 0, 0, 0)
    limit = _brackets(xs, ys, cat, tol)[5]
    need = _halvings(limit)
    saddles = int(saddle_cells(cat)[0].size)
    if need.size == 0 or int(need.max()) == 0:
        return RefinePlan(int(need.size), 1, int(saddles > 0), saddles, saddles)
    best: tuple[float, int, int, int] | None = None
    for bits in range(1, min(MAX_BITS, int(need.max())) + 1):
        steps = -(-need // bits)  # per bracket
        batches = int(steps.max())
        runs = int(steps.sum()) * (2 ** bits - 1) + saddles
        cost = runs + BATCH_OVERHEAD_RUNS * batches
        if best is None or cost < best[0]:
            best = (cost, bits, batches, runs)
    assert best is not None
    return RefinePlan(int(need.size), best[1], best[2], best[3], saddles)


def _points(axis: CodeArray, i: IntArray, j: IntArray, frac: FloatArray, x: FloatArray, y: FloatArray
            ) -> tuple[FloatArray, FloatArray]:
    """The swept values at fractions ``frac`` (shape (n, m)) of the edges (n)."""
    on_row = (axis == 0)[:, None]
    jn = np.minimum(j + 1, x.size - 1)[:, None]
    inext = np.minimum(i + 1, y.size - 1)[:, None]
    xa, ya = x[j][:, None], y[i][:, None]
    px = np.where(on_row, xa + frac * (x[jn] - xa), xa)
    py = np.where(on_row, ya, ya + frac * (y[inext] - ya))
    return px, py


def refine_crossings(x: ArrayLike, y: ArrayLike, category: ArrayLike, evaluate: Evaluate, *,
                     tol: float = TOLERANCE, progress: Callable[[int], None] | None = None) -> Crossings:
    """Find where the category boundaries cross the grid's edges, by vectorised bisection.

    Parameters
    ----------
    x, y : array_like
        The values of the first swept input (columns) and of the second (rows), each strictly
        monotonic, at least two (:func:`refinable`).
    category : array_like of int, shape (len(y), len(x))
        The category of every node.
    evaluate : callable
        ``evaluate(first, second)`` -> the categories of runs at those values, one batch.
    tol : float
        Width of a closed bracket, as a fraction of the range of the swept input along it; the
        crossing is the middle of its bracket.
    progress : callable, optional
        Called with the number of runs of each batch once it is done (when ``evaluate`` does
        not report them itself, pass None).

    Returns
    -------
    Crossings
        Sorted by edge (axis, i, j) and fraction.

    Raises
    ------
    ValueError
        For axes that cannot be refined or a category array of the wrong shape.
    """
    xs = np.asarray(x, dtype=np.float64)
    ys = np.asarray(y, dtype=np.float64)
    cat = np.asarray(category).astype(np.int8)
    if not refinable(xs, ys):
        raise ValueError("refining needs two strictly monotonic axes of at least two values each")
    if cat.shape != (ys.size, xs.size):
        raise ValueError(f"category has shape {cat.shape}, the axes {ys.size} x {xs.size}")
    plan = plan_refinement(xs, ys, cat, tol)
    axis, i, j, c0, c1, limit = _brackets(xs, ys, cat, tol)
    f0 = np.zeros(axis.size)
    f1 = np.ones(axis.size)
    si, sj = saddle_cells(cat)
    centre = np.zeros(si.size, dtype=np.int8)
    planned = 2 ** plan.bits - 1
    budget = max(2 * plan.runs // max(plan.batches, 1), MIN_BUDGET)
    runs = batches = 0
    first = True
    while True:
        active = (f1 - f0) > limit
        if not active.any() and not (first and si.size):
            break
        a = np.flatnonzero(active)
        # plain bisection when split brackets have made the batch too big
        probes = planned if a.size * planned <= budget else 1
        inner = np.arange(1, probes + 1) / (probes + 1.0)
        frac = f0[a, None] + (f1 - f0)[a, None] * inner[None, :]
        px, py = _points(axis[a], i[a], j[a], frac, xs, ys)
        qx, qy = px.ravel(), py.ravel()
        if first and si.size:  # the saddles' centres ride in the first batch
            qx = np.concatenate([qx, 0.5 * (xs[sj] + xs[sj + 1])])
            qy = np.concatenate([qy, 0.5 * (ys[si] + ys[si + 1])])
        got = np.asarray(evaluate(qx, qy)).astype(np.int8).ravel()
        runs += got.size
        batches += 1
        if progress is not None:
            progress(int(got.size))
        if first and si.size:
            centre = got[a.size * probes:]
            got = got[:a.size * probes]
        first = False
        if a.size == 0:
            continue
        seq_c = np.concatenate([c0[a, None], got.reshape(a.size, probes), c1[a, None]], axis=1)
        seq_f = np.concatenate([f0[a, None], frac, f1[a, None]], axis=1)
        r, k = np.nonzero(seq_c[:, 1:] != seq_c[:, :-1])  # every change of category: a bracket
        keep = ~active
        axis = np.concatenate([axis[keep], axis[a][r]])
        i = np.concatenate([i[keep], i[a][r]])
        j = np.concatenate([j[keep], j[a][r]])
        limit = np.concatenate([limit[keep], limit[a][r]])
        f0, f1 = (np.concatenate([f0[keep], seq_f[r, k]]), np.concatenate([f1[keep], seq_f[r, k + 1]]))
        c0, c1 = (np.concatenate([c0[keep], seq_c[r, k]]), np.concatenate([c1[keep], seq_c[r, k + 1]]))
        # an edge crossed many times (a chaotic stretch of the map) is not refined further
        _, edge, count = np.unique(np.column_stack([axis, i, j]), axis=0, return_inverse=True,
                                   return_counts=True)
        limit = np.where(count[edge.ravel()] > MAX_CROSSINGS, np.inf, limit)
    mid = 0.5 * (f0 + f1)
    order = np.lexsort((mid, j, i, axis))
    return Crossings(axis=axis[order], i=i[order], j=j[order], fraction=mid[order], before=c0[order],
                     after=c1[order], centre_i=si, centre_j=sj, centre=centre, runs=runs,
                     batches=batches)


def crossing_points(c: Crossings, x: ArrayLike, y: ArrayLike) -> FloatArray:
    """The crossings in the swept inputs' units, shape (n, 2): (first, second)."""
    xs = np.asarray(x, dtype=np.float64)
    ys = np.asarray(y, dtype=np.float64)
    px, py = _points(c.axis, c.i, c.j, c.fraction[:, None], xs, ys)
    return np.column_stack([px.ravel(), py.ravel()])

