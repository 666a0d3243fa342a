"""Regions of the k-mu plane as vector polygons (for crisp SVG/PDF fills).

Along any vertical line (fixed k) every region of the report is one interval
of mu, so a region is exactly described by its lower and upper edges as
functions of k.  The polygons below sample those edges on a fine k grid that
contains every characteristic abscissa of the map (k_A, k_B', b/|a|, k_D,
the pole d/c, the crossing C' ...), and locate the ends of each run of
non-empty columns by bisection, so the fills meet the boundary curves without
a staircase.  Nothing here imports matplotlib.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.constants import mu_star_signed, mu_star_star, thresholds
from ..mechanics.modes import MAP_MODES, Mode

__all__ = [
    "DEFAULT_SAMPLES",
    "Interval",
    "sample_k",
    "final_intervals",
    "raw_intervals",
    "breakpoints",
    "bisect_edge",
    "region_polygons",
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
    rest_ok, lower, upper, mu_s, f_pos = thresholds(k, p.gamma, p.kprime)
    e4 = np.where(rest_ok, k, np.inf)
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
    """The interval of mu of the report's raw region of ``mode`` (:mod:`regimemap.mechanics.regions`)."""
    k = np.asarray(k, dtype=np.float64)
    rest_ok, lower, upper, mu_s, f_pos = thresholds(k, p.gamma, p.kprime)
    zero = np.zeros_like(k)
    top = np.full_like(k, mu_cap)
    mode = Mode(mode)
    if mode is Mode.RE:
        lo, hi = np.where(rest_ok, k, top), top
    elif mode is Mode.SL:
        lo, hi = np.maximum(lower, 0.0), np.minimum(k, upper)
    elif mode is Mode.RO:
        rock_ok = k * (p.gamma * (1.0 + p.kprime)) >= 1.0
        lo, hi = np.where(rock_ok, mu_s, top), top
    elif mode is Mode.SRO_MINUS:
        ms = mu_star_signed(k, p.a, p.b, p.c, p.d)
        mb = p.mu_Bprime
        lo1, hi1 = np.maximum(upper, 0.0), np.minimum(ms, mb)
        lo2, hi2 = np.maximum(np.maximum(ms, mb), 0.0), upper
        use2 = (hi2 - lo2) > (hi1 - lo1)
        lo, hi = np.where(use2, lo2, lo1), np.where(use2, hi2, hi1)
    elif mode is Mode.SRO_PLUS:
        lo = zero
        hi = np.where(~f_pos, np.minimum(mu_s, k * p.kprime - 1.0 / p.gamma), zero)
    elif mode is Mode.SRO_PRIME_MINUS:
        mss = mu_star_star(k, p.a, p.b, p.c, p.d)
        bound = np.where(p.c * k >= p.d, lower, np.minimum(lower, mss))
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
    modes = tuple(MAP_MODES if modes is None else modes)
    mu_cap = mu_max * overshoot
    k = sample_k(p, k_max, samples)

    def intervals(kk: np.ndarray) -> dict[Mode, Interval]:
        if raw:
            return {m: raw_intervals(m, p, kk, mu_cap) for m in modes}
        return final_intervals(p, kk, mu_cap)

    cols = intervals(k)
    out: dict[Mode, list[np.ndarray]] = {}
    for mode in modes:
        lo, hi = cols[mode]
        columns = (hi - lo) > 0.0
        polys: list[np.ndarray] = []
        if columns.any():
            idx = np.flatnonzero(columns)
            runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)

            def present(kk: float, mode: Mode = mode) -> bool:
                lo1, hi1 = intervals(np.array([kk]))[mode]
                return bool(hi1[0] - lo1[0] > 0.0)

            for run in runs:
                ks = list(k[run])
                i0, i1 = run[0], run[-1]
                if i0 > 0:
                    ks.insert(0, bisect_edge(present, k[i0], k[i0 - 1]))
                if i1 < k.size - 1:
                    ks.append(bisect_edge(present, k[i1], k[i1 + 1]))
                kk = np.asarray(ks)
                lo_k, hi_k = intervals(kk)[mode]
                poly = np.concatenate([np.column_stack([kk, lo_k]), np.column_stack([kk[::-1], hi_k[::-1]])])
                polys.append(poly)
        out[mode] = polys
    return out
