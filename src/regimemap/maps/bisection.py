"""The ends of runs of columns, found by bisection: one edge at a time or every edge at once.

A region of a map holds on a run of k columns; where the run ends between two samples,
the end is the last k where the region is present, found by bisection to a relative width
of 1e-13 (:func:`bisect_edge`).  :func:`bisect_edges` does the same for many edges in a few
vectorised calls, with the same floats as :func:`bisect_edge` edge by edge.  Used by the
exact polygons (:mod:`regimemap.maps.geometry`) and the ambiguity overlay
(:mod:`regimemap.maps.ambiguity`); it knows nothing of the physics.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

__all__ = ["bisect_edge", "bisect_edges"]


def bisect_edge(present: Callable[[float], bool], k_in: float, k_out: float,
                iterations: int = 60) -> float:
    """The last k where ``present`` holds, between k_in (it holds) and k_out (it does not).

    Bisection to a relative width of 1e-13 (or adjacent floats).
    """
    for _ in range(iterations):
        mid = 0.5 * (k_in + k_out)
        if mid in (k_in, k_out):
            break
        if present(mid):
            k_in = mid
        else:
            k_out = mid
        if abs(k_out - k_in) <= 1e-13 * max(1.0, abs(k_in)):
            break
    return k_in


def bisect_edges(present: Callable[[np.ndarray, np.ndarray], np.ndarray], k_in: np.ndarray,
                 k_out: np.ndarray, iterations: int = 60, columns: int = 256) -> np.ndarray:
    """:func:`bisect_edge` for many edges at once: for each, the same k.

    Parameters
    ----------
    present : callable
        ``present(which, k)``: for the edges ``which`` (indices, shape (m,)) and
        abscissae ``k`` of shape (m, j) (row i for edge ``which[i]``), whether
        each edge's condition holds, a boolean array of shape (m, j).
    k_in, k_out : array_like
        For each edge, a k where its condition holds and one where it does not.
    iterations : int
        As :func:`bisect_edge`.
    columns : int
        About how many abscissae to ask ``present`` at a time.  Each call asks,
        for every edge not yet done, the ``2**d - 1`` midpoints that the next
        ``d`` steps of bisection may visit (either answer at each step; ``d``
        as large as ``columns`` allows, at least 1); then each edge walks down
        its answers exactly as :func:`bisect_edge` does.  ``present`` is
        vectorised: a call costs little more for a few hundred columns than
        for one, so the edges are found in a few calls instead of ~40 each.

    Returns
    -------
    ndarray
        For each edge, the last k where its condition holds.
    """
    k_in = np.array(k_in, dtype=np.float64).ravel()
    k_out = np.array(k_out, dtype=np.float64).ravel()
    steps = np.zeros(k_in.size, dtype=np.intp)
    todo = np.arange(k_in.size) if iterations > 0 else np.zeros(0, dtype=np.intp)
    while todo.size:
        depth = min(max(int(math.log2(columns / todo.size + 1.0)), 1), 12)
        nodes = 2 ** depth - 1
        # the bisection tree of each edge, level by level, stored as a heap: node i has
        # children 2i + 1 (the condition holds at i's middle) and 2i + 2 (it does not)
        lo, hi = k_in[todo, None], k_out[todo, None]
        levels = []
        for _ in range(depth):
            middle = 0.5 * (lo + hi)
            levels.append(middle)
            lo = np.stack([middle, lo], axis=2).reshape(todo.size, -1)
            hi = np.stack([hi, middle], axis=2).reshape(todo.size, -1)
        mid = np.concatenate(levels, axis=1)
        holds = np.asarray(present(todo, mid), dtype=bool)
        left: list[int] = []
        for row, e in enumerate(todo):
            a, b, i, done = float(k_in[e]), float(k_out[e]), 0, False
            while i < nodes and not done:
                m = float(mid[row, i])
                steps[e] += 1
                if m in (a, b):
                    done = True
                    break
                if holds[row, i]:
                    a, i = m, 2 * i + 1
                else:
                    b, i = m, 2 * i + 2
                done = abs(b - a) <= 1e-13 * max(1.0, abs(a)) or steps[e] >= iterations
            k_in[e], k_out[e] = a, b
            if not done:
                left.append(int(e))
        todo = np.array(left, dtype=np.intp)
    return k_in
