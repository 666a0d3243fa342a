"""Margins of a point: the smallest change of k or mu that changes the mode (exact).

How the margin is found (exact)
-------------------------------
Along a line of constant mu the rule of :func:`regimemap.classify` can only
change where mu equals one of its thresholds or where one of its conditions
flips, and each of these is the root of a *linear* equation in k:

=========================  ==================================================
OA, mu = k                  k = mu                                (3.4), (4.7)
AB/AE, k = k_A              k = 1/(gamma (1+k'))            (3.5), (4.10)
CD/AB, mu = 1/g - k k'      k = (1/g - mu)/k'            Section III.2, (4.21)
DC, mu = -1/g - k k'        k = (-1/g - mu)/k'                         (4.20)
mu = mu*(k), f_x >= 0       k = (mu d - b)/(a - mu c)           (3.24), (4.40)
mu = mu*(k), f_x <= 0       k = -(mu d + b)/(a + mu c)          (3.24), (3.45)
f_x = 0 (ak + b = 0)        k = -b/a                           cases 2/3
=========================  ==================================================

Along a line of constant k the thresholds are the values k, 1/g - k k',
-1/g - k k' and mu*(k) themselves.  Between two consecutive roots the mode is
constant, so :func:`margin` evaluates :func:`~regimemap.classify` at each root
and in the middle of each gap, walking away from the point, and stops at the
first place whose mode differs; it then bisects on ``classify`` between the
last probe with the point's mode and the first without, down to adjacent
floating-point numbers.  The reported boundary ``at`` is the first value
found with another mode, so ``classify`` gives the point's mode everywhere
strictly between the point and ``at`` and another mode at ``at``.

With loads
----------
The rule's conditions (:func:`regimemap.mechanics.regions.column_intervals`)
are all sign conditions on expressions that are affine in k at fixed mu
(:func:`regimemap.mechanics.regions.affine_terms`) and affine in mu at fixed k,
so the list of roots stays complete: along k the root of every such expression
(each from its values at k = 0 and k = 1), along mu the ends of every
hypothesis's interval.  The walk and the bisection are the same.

Search range and special values
-------------------------------
The search covers the whole half-line: k (or mu) from the point's value up
to infinity, and down to 0 inclusive.  Because the list of roots is complete,
"no change" is exact: a direction whose mode never changes (for instance mu
going up inside RE or RO) is reported as ``None``.  Going down from a value of
0 is impossible and is reported as ``None`` too.  The relative change is
``|at - x|/x``; when the point's own value x is 0 it is undefined and reported
as ``None`` (the absolute change ``delta`` is always given).  A point exactly
on a boundary has a margin of 0 in the direction that leaves its region.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..mechanics import constants as C
from ..mechanics.loads import BlockConstants, block_constants
from ..mechanics.modes import Mode
from ..mechanics.regions import affine_terms, column_intervals, rule_expressions
from ..mechanics.validation import MAX_VALUE, check_gamma, check_kprime, check_loads, check_nonnegative_array
from .classify import classify

__all__ = [
    "BOUNDARY_ULPS",
    "Crossing",
    "Margin",
    "carries_loads",
    "checked_loads",
    "crossing",
    "finite_or_none",
    "loads_constants",
    "margin",
    "margin_arrays",
    "margin_at",
    "negligible",
]

#: Largest number of bisection steps (enough to reach adjacent doubles).
_BISECT_STEPS = 1100
#: A change of at most this many units in the last place of the value is no change:
#: the point is on the boundary.
BOUNDARY_ULPS = 4.0


def negligible(delta: float, value: float) -> bool:
    """True when a change ``delta`` of ``value`` is within :data:`BOUNDARY_ULPS` of rounding."""
    return bool(delta <= BOUNDARY_ULPS * np.spacing(max(abs(value), 1e-300)))


def finite_or_none(v: float | None) -> float | None:
    """A float for JSON: non-finite numbers become None."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


@dataclass(frozen=True)
class Crossing:
    """The nearest change of mode in one direction along k or along mu.

    Attributes
    ----------
    direction : {"up", "down"}
        Whether the value increases or decreases.
    at : float
        The first value (of k or of mu) where the mode differs from the point's.
    delta : float
        ``|at - x|``, the absolute change (x is the point's value).
    relative : float or None
        ``delta / x``; None when x is 0.
    to : Mode
        The mode just beyond the boundary (the mode at ``at`` if the region
        beyond is the point's own mode again, i.e. an isolated boundary point).
    """

    direction: str
    at: float
    delta: float
    relative: float | None
    to: Mode

    def as_dict(self) -> dict[str, Any]:
        return {
            "direction": self.direction,
            "at": finite_or_none(self.at),
            "delta": finite_or_none(self.delta),
            "relative": finite_or_none(self.relative),
            "to": self.to.label,
        }


    @property
    def on_boundary(self) -> bool:
        """True when the crossing is at the point itself (a change of a few ulps)."""
        return negligible(self.delta, self.at)


@dataclass(frozen=True)
class Margin:
    """The smallest change of one variable (k or mu), the other held fixed, that changes the mode.

    Attributes
    ----------
    variable : {"k", "mu"}
    value : float
        The point's value of the variable.
    up, down : Crossing or None
        The nearest change when the variable increases / decreases; None when
        the mode never changes in that direction (or the value is 0 and
        cannot decrease).
    """

    variable: str
    value: float
    up: Crossing | None
    down: Crossing | None

    @property
    def nearest(self) -> Crossing | None:
        """The smaller of :attr:`up` and :attr:`down` (by absolute change; down on a tie)."""
        options = [c for c in (self.down, self.up) if c is not None]
        return min(options, key=lambda c: c.delta) if options else None

    @property
    def relative(self) -> float | None:
        """Relative change of the nearest crossing (None if none, or if the value is 0)."""
        n = self.nearest
        return None if n is None else n.relative

    def as_dict(self) -> dict[str, Any]:
        n = self.nearest
        near = {} if n is None else n.as_dict()
        return {
            "variable": self.variable,
            "value": finite_or_none(self.value),
            **{key: near.get(key) for key in ("relative", "delta", "direction", "at", "to")},
            "up": None if self.up is None else self.up.as_dict(),
            "down": None if self.down is None else self.down.as_dict(),
        }


def loads_constants(g: Any, kp: Any, loads: dict[str, Any]) -> BlockConstants:
    """The block constants of ``g``, ``kp`` (numbers or arrays) and the load keywords ``loads``
    (those absent: the report's block)."""
    return block_constants(g, kp, loads.get("buoyancy", 0.0), loads.get("uplift", 0.0),
                           loads.get("uplift_ratio", 0.0), loads.get("uplift_arm", 1.0 / 3.0),
                           loads.get("gyration"))


def carries_loads(loads: dict[str, Any]) -> bool:
    """True when the keywords describe a loaded block (not the report's)."""
    return any(loads.get(key, 0.0) != 0.0 for key in ("buoyancy", "uplift", "uplift_ratio")) \
        or loads.get("gyration") is not None


def _roots_along_k(mu: np.ndarray, g: np.ndarray, kp: np.ndarray,
                   loads: dict[str, Any] | None = None) -> np.ndarray:
    """Every k where the rule of classify may change along the line of constant mu; shape (n, m)."""
    if not loads or not carries_loads(loads):
        return C.k_roots_at_mu(mu, g, kp)
    cst = loads_constants(g, kp, loads)
    e0 = rule_expressions(affine_terms(np.zeros_like(mu), cst), mu, g, cst.i2, 0.0)
    e1 = rule_expressions(affine_terms(np.ones_like(mu), cst), mu, g, cst.i2, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        roots = [np.broadcast_to(-a / (b - a), mu.shape) for a, b in zip(e0, e1)]
    return np.stack(roots, axis=1)


def _roots_along_mu(k: np.ndarray, g: np.ndarray, kp: np.ndarray,
                    loads: dict[str, Any] | None = None) -> np.ndarray:
    """Every mu where the rule of classify may change along the line of constant k; shape (n, m)."""
    cst = loads_constants(g, kp, loads or {})
    t = C.thresholds(k, cst)
    cols = [t.mu_rest, t.upper, t.lower, t.mu_star]
    if loads and carries_loads(loads):
        cols.append(np.broadcast_to(cst.A0 / (3.0 * cst.gamma), k.shape))
        for _, lo, hi in column_intervals(k, cst):
            cols += [lo, hi]
    return np.stack([np.broadcast_to(c, k.shape) for c in cols], axis=1)


def _classify_along(var: str, values: np.ndarray, other: np.ndarray, g: np.ndarray,
                    kp: np.ndarray, loads: dict[str, Any]) -> np.ndarray:
    """classify with ``var`` = values (n, m) and the other variable fixed per row."""
    o, gg, kk = (np.broadcast_to(v[:, None], values.shape) for v in (other, g, kp))
    if var == "k":
        return classify(values, o, gg, kk, **loads)
    return classify(o, values, gg, kk, **loads)


def _walk(var: str, x: np.ndarray, other: np.ndarray, g: np.ndarray, kp: np.ndarray,
          m0: np.ndarray, roots: np.ndarray, up: bool, loads: dict[str, Any]
          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nearest change of mode from x in one direction; returns (found, at, to)."""
    n = x.size
    xc = x[:, None]
    ok = np.isfinite(roots) & (roots >= 0.0) & (roots <= MAX_VALUE)  # a probe stays a valid k or mu
    if up:
        ok &= roots > xc
        cand = np.sort(np.where(ok, roots, np.inf), axis=1)
    else:
        ok &= roots < xc
        cand = np.where(ok, roots, -np.inf)
        # 0 ends the search downward; it is a probe of its own
        cand = np.concatenate([cand, np.where(xc > 0.0, 0.0, -np.inf)], axis=1)
        cand = -np.sort(-cand, axis=1)
        # drop duplicated zeros (a root at 0 and the end point)
        dup = np.zeros_like(cand, dtype=bool)
        dup[:, 1:] = cand[:, 1:] == cand[:, :-1]
        cand = np.where(dup, -np.inf, cand)
        cand = -np.sort(-cand, axis=1)
    valid = np.isfinite(cand)
    m = cand.shape[1]
    # probes: mid(x, c0), c0, mid(c0, c1), c1, ..., c_{m-1}, beyond c_{m-1}
    probes = np.empty((n, 2 * m + 1))
    pvalid = np.zeros((n, 2 * m + 1), dtype=bool)
    prev = x.copy()
    prev_valid = np.ones(n, dtype=bool)
    for i in range(m):
        ci, vi = cand[:, i], valid[:, i]
        mid = np.where(vi, prev + 0.5 * (ci - prev), np.nan)
        probes[:, 2 * i] = mid
        pvalid[:, 2 * i] = vi & prev_valid
        probes[:, 2 * i + 1] = ci
        pvalid[:, 2 * i + 1] = vi & prev_valid
        prev = np.where(vi, ci, prev)
        prev_valid &= vi
    if up:
        # the open half-line beyond the last root: one probe suffices (no root there)
        beyond = np.minimum(2.0 * prev + 1.0, MAX_VALUE)
        probes[:, 2 * m] = beyond
        pvalid[:, 2 * m] = beyond > prev  # nothing beyond the largest k or mu accepted
    else:
        pvalid[:, 2 * m] = False  # nothing below 0
        probes[:, 2 * m] = np.nan
    # a gap of zero width between equal roots has no interior
    pvalid &= np.isfinite(probes)
    safe = np.where(pvalid, probes, xc)
    modes = _classify_along(var, safe, other, g, kp, loads)
    differs = pvalid & (modes != m0[:, None])
    found = differs.any(axis=1)
    j = np.argmax(differs, axis=1)
    rows = np.arange(n)
    hi = safe[rows, j]
    lo = np.where(j > 0, safe[rows, np.maximum(j - 1, 0)], x)
    # walk back past invalid probes so that lo is a probe with the point's mode
    # (all valid probes before j have mode m0 by construction; invalid ones were set to x)
    to = modes[rows, j]
    # a root probe (odd index) followed by a gap whose mode also differs: report the gap's mode
    nxt = np.minimum(j + 1, 2 * m)
    gap_diff = pvalid[rows, nxt] & (modes[rows, nxt] != m0)
    to = np.where((j % 2 == 1) & gap_diff, modes[rows, nxt], to)
    # bisection on classify between lo (mode m0) and hi (another mode)
    lo = np.where(found, lo, x)
    hi = np.where(found, hi, x)
    active = found.copy()
    for _ in range(_BISECT_STEPS):
        if not active.any():
            break
        idx = np.flatnonzero(active)
        lo_i, hi_i = lo[idx], hi[idx]
        mid = lo_i + 0.5 * (hi_i - lo_i)
        stuck = (mid == lo_i) | (mid == hi_i)
        go = ~stuck
        if go.any():
            ii = idx[go]
            mm = mid[go]
            mk = _classify_along(var, mm[:, None], other[ii], g[ii], kp[ii], loads)[:, 0]
            same = mk == m0[ii]
            lo[ii[same]] = mm[same]
            hi[ii[~same]] = mm[~same]
        active[idx[stuck]] = False
    return found, hi, to


def margin_arrays(var: str, k: np.ndarray, mu: np.ndarray, g: np.ndarray, kp: np.ndarray,
                  m0: np.ndarray, loads: dict[str, Any] | None = None
                  ) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The nearest change of mode up and down along ``var`` for arrays of points.

    ``loads`` are the (checked) keywords of :func:`regimemap.classify`.
    Returns ``{"up": (found, at, to), "down": (found, at, to)}``, each an array per point.
    """
    loads = dict(loads or {})
    if var == "k":
        x, other, roots = k, mu, _roots_along_k(mu, g, kp, loads)
    else:
        x, other, roots = mu, k, _roots_along_mu(k, g, kp, loads)
    return {
        "up": _walk(var, x, other, g, kp, m0, roots, True, loads),
        "down": _walk(var, x, other, g, kp, m0, roots, False, loads),
    }


def checked_loads(buoyancy: Any = 0.0, uplift: Any = 0.0, uplift_ratio: Any = 0.0,
                  uplift_arm: Any = 1.0 / 3.0, gyration: Any = None, crest: Any = 1.0) -> dict[str, Any]:
    """The loads as checked keyword arguments of :func:`regimemap.classify`."""
    names = ("buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration", "crest")
    return dict(zip(names, check_loads(buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest)))


def crossing(direction: str, x: float, found: bool, at: float, to: int) -> Crossing | None:
    if not found:
        return None
    delta = abs(float(at) - x)
    rel = delta / x if x > 0.0 else None
    return Crossing(direction, float(at), delta, rel, Mode(int(to)))


def margin_at(var: str, x: float, arrays: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]],
              i: int) -> Margin:
    """The margin of point ``i`` along ``var`` (its value ``x``) from its :func:`margin_arrays`."""
    up, down = (crossing(d, x, bool(arrays[d][0][i]), arrays[d][1][i], arrays[d][2][i])
                for d in ("up", "down"))
    return Margin(var, x, up, down)


def margin(k: float, mu: float, gamma: float, kprime: float, *, buoyancy: float = 0.0,
           uplift: float = 0.0, uplift_ratio: float = 0.0, uplift_arm: float = 1.0 / 3.0,
           gyration: float | None = None, crest: float = 1.0) -> tuple[Margin, Margin]:
    """The margins of one point along k (mu fixed) and along mu (k fixed).

    Parameters
    ----------
    k, mu : float
        The point: force F/(mg) >= 0 and friction coefficient >= 0.
    gamma, kprime : float
        Aspect ratio H/B > 0 and force height h/H in [-1, crest].
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest : float, keyword-only
        The loads, as in :func:`regimemap.classify`.

    Returns
    -------
    (Margin, Margin)
        Along k and along mu.  See the module docstring for the method, the
        search range and the special values (None).

    Examples
    --------
    >>> mk, mm = margin(0.3, 0.2, 3.0, 0.4)
    >>> mk.nearest.to.label, round(mk.nearest.at, 6)
    ('SRO-', 0.333333)
    """
    k_arr = check_nonnegative_array("k", k).reshape(-1)
    mu_arr = check_nonnegative_array("mu", mu).reshape(-1)
    if k_arr.size != 1 or mu_arr.size != 1:
        raise ValueError("margin() takes one point; use query_points for many")
    loads = checked_loads(buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest)
    g = np.array([check_gamma(gamma)])
    kp = np.array([check_kprime(kprime, loads["crest"])])
    m0 = classify(k_arr, mu_arr, g, kp, **loads)
    return (margin_at("k", float(k_arr[0]), margin_arrays("k", k_arr, mu_arr, g, kp, m0, loads), 0),
            margin_at("mu", float(mu_arr[0]), margin_arrays("mu", k_arr, mu_arr, g, kp, m0, loads), 0))
