"""The view of a map: its automatic extent, and polyline simplification (no matplotlib).

:func:`auto_extent` chooses ``[0, k_max] x [0, mu_max]`` so that the map's
characteristic points are in view; :func:`nice_ceil` rounds limits up to a
nice number and :func:`simplify` thins polylines to what a figure can show.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.curves import mu_star, named_points
from ..mechanics.modes import Mode

__all__ = ["auto_extent", "nice_ceil", "simplify"]

#: lie and still be pulled into the automatic view.
_CAP = 12.0
#: With loads, mu*(k) over the view is followed up to this many times the highest
#: characteristic mu (it may have a pole, c_O k + d_O = 0, inside the view).
_POLE_CAP = 3.0
#: Relative margin added around the characteristic points.
_MARGIN = 0.15


# -- small numeric helpers ----------------------------------------------------------


def nice_ceil(x: float, divisions: int = 8) -> float:
    """Round ``x > 0`` up to a multiple of a 'nice' step (1, 2, 2.5 or 5 x 10^n).

    The step is the smallest nice number >= ``x / divisions``, so an axis that
    ends at the result ends on a tick.

    Examples
    --------
    >>> nice_ceil(2.13), nice_ceil(0.53), nice_ceil(6.4)
    (2.5, 0.6, 7.0)
    """
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"nice_ceil needs a finite number > 0, got {x!r}")
    raw = x / divisions
    exp = math.floor(math.log10(raw))
    step = None
    for mant in (1.0, 2.0, 2.5, 5.0, 10.0):
        step = mant * 10.0**exp
        if step >= raw * (1.0 - 1e-12):
            break
    assert step is not None
    n = math.ceil(x / step - 1e-9)
    return float(round(n * step, 12))


def simplify(points: np.ndarray, tol: float, scale: tuple[float, float] = (1.0, 1.0)) -> np.ndarray:
    """Ramer-Douglas-Peucker simplification of a polyline.

    Parameters
    ----------
    points : ndarray, shape (n, 2)
        Vertices (k, mu).
    tol : float
        Largest allowed distance of a removed vertex from the simplified line,
        measured after dividing k and mu by ``scale``.
    scale : (float, float)
        Units of the two coordinates (the view extent), so that ``tol`` is a
        fraction of the view.

    Returns
    -------
    ndarray, shape (m, 2), m <= n
        A subset of the vertices, first and last kept.
    """
    pts = np.asarray(points, dtype=np.float64)
    n = len(pts)
    if n <= 2:
        return np.array(pts)
    q = pts / np.asarray(scale, dtype=np.float64)
    keep = np.zeros(n, dtype=bool)
    keep[0] = keep[-1] = True
    stack = [(0, n - 1)]
    while stack:
        i, j = stack.pop()
        if j <= i + 1:
            continue
        seg = q[i + 1:j]
        a, b = q[i], q[j]
        d = b - a
        norm = math.hypot(d[0], d[1])
        if norm == 0.0:
            dist = np.hypot(seg[:, 0] - a[0], seg[:, 1] - a[1])
        else:
            dist = np.abs(d[0] * (seg[:, 1] - a[1]) - d[1] * (seg[:, 0] - a[0])) / norm
        m = int(np.argmax(dist))
        if dist[m] > tol:
            idx = i + 1 + m
            keep[idx] = True
            stack.append((i, idx))
            stack.append((idx, j))
    return pts[keep]


# -- extent ------------------------------------------------------------------------------


def _reference_scale(p: Parameters) -> float:
    """k_A when it is finite (and > 0), else the abscissa of D (k' = -1), else of L."""
    if math.isfinite(p.k_A) and p.k_A > 0.0:
        return p.k_A
    if math.isfinite(p.k_D):
        return p.k_D
    return p.k_L if math.isfinite(p.k_L) and p.k_L > 0.0 else 1.0 / p.gamma


def _mu_on_view(p: Parameters, k_max: float) -> float:
    """The largest mu* (from A on, where it is drawn) within [0, k_max]."""
    if not math.isfinite(p.k_A):
        return 0.0  # k' = -1: no rocking, mu* is not drawn
    k0 = min(max(p.k_A, 0.0), k_max)
    if k0 >= k_max:
        return 0.0
    k = np.linspace(k0, k_max, 64)
    ms = mu_star(p, k)
    ms = ms[np.isfinite(ms) & (ms >= 0.0)] if p.loaded else ms
    return float(np.max(ms)) if ms.size else 0.0


def auto_extent(params: Parameters, raw_mode: Mode | None = None, *,
                include: Iterable[tuple[float, float]] = (),
                k_max: float | None = None, mu_max: float | None = None) -> tuple[float, float]:
    """A view ``[0, k_max] x [0, mu_max]`` that shows the map's characteristic points.

    Parameters
    ----------
    params : Parameters
    raw_mode : Mode, optional
        For a single-mode figure of the report's raw region: also show what
        bounds that region (C' for RO and SRO- below C; the range beyond G for
        SRO+).
    include : iterable of (k, mu)
        Extra points to keep in view (design points).
    k_max, mu_max : float, optional
        User choices; the other limit is computed to fit.

    Returns
    -------
    (k_max, mu_max) : tuple of float
        Both finite and > 0, rounded up to a nice number.

    Notes
    -----
    Shown: A (and E), C above C, D, with loads every named point and L
    (where lift-off starts) with some room beyond it, the point G = b/|a| and some of the range
    beyond it (cases 2/3, SRO+), B' with mu_B' when Delta >= 0, room right of D
    for SRO'- below C, and mu*(k) over the view (for the raw rest region, only
    the strip around A: Figs 3.1 and 4.2).  Points farther than 12 k_A
    (k' near 0 puts D and B' far away; k' = -1 puts A at infinity) are left out,
    so the neighbourhood of A never shrinks to a corner.
    """
    p = params
    ref = _reference_scale(p)
    cap = _CAP * ref
    ks, mus = _view_points(p, raw_mode, cap)
    if p.loaded:
        _add_loaded_points(p, cap, ref, ks, mus)
    for k, mu in include:
        if math.isfinite(k) and math.isfinite(mu):
            ks.append(float(k))
            mus.append(float(mu))
    if not ks:
        ks.append(ref)
    if k_max is None:
        k_max = nice_ceil((1.0 + _MARGIN) * max(max(ks), 1e-12))
    if mu_max is None:
        mu_max = _fit_mu_max(p, raw_mode, k_max, mus)
    return float(k_max), float(mu_max)


def _view_points(p: Parameters, raw_mode: Mode | None, cap: float) -> tuple[list[float], list[float]]:
    """The k and the mu to show: A (and E), 1/gamma, then by the side of C (see :func:`auto_extent`)."""
    ks: list[float] = []
    mus: list[float] = [1.0 / p.gamma]
    kA = p.k_A
    if math.isfinite(kA) and kA >= 0.0:
        ks += [kA, 1.6 * kA]
        if math.isfinite(p.mu_A):
            mus.append(p.mu_A)
    if raw_mode is not None and Mode(raw_mode) is Mode.RE:
        # Figs 3.1 and 4.2: the rest region is the strip left of A, above OA
        ks = [2.2 * kA if math.isfinite(kA) else 2.0 / p.gamma]
        mus = [1.6 * kA if math.isfinite(kA) else 2.0 / p.gamma]
    elif p.above:
        ks += _points_above(p, raw_mode, cap)
    else:
        _add_points_below(p, raw_mode, cap, ks, mus)
    return ks, mus


def _points_above(p: Parameters, raw_mode: Mode | None, cap: float) -> list[float]:
    """Above C: D, and G = b/|a| with some of the range beyond it (cases 2/3, SRO+)."""
    ks: list[float] = []
    if p.kprime > 0.0 and p.k_D <= cap:
        ks.append(p.k_D)
    G = p.b_over_abs_a
    if math.isfinite(G) and G <= cap:
        ks.append(G)
        if raw_mode is None or Mode(raw_mode) is Mode.SRO_PLUS:
            ks.append(min(3.0 * G, cap))
    return ks


def _add_points_below(p: Parameters, raw_mode: Mode | None, cap: float, ks: list[float],
                      mus: list[float]) -> None:
    """Below C: D with room right of it (SRO'-), B' with mu_B', and C' for the raw RO, SRO-."""
    kA = p.k_A
    if math.isfinite(p.k_D) and p.k_D <= cap:
        ks += [p.k_D, 2.0 * p.k_D]
    kB = p.k_Bprime
    if math.isfinite(kB) and (not math.isfinite(kA) or kB >= kA) and kB <= cap:
        ks.append(kB)
        mus.append(p.mu_Bprime)
    if raw_mode is not None and Mode(raw_mode) in (Mode.RO, Mode.SRO_MINUS):
        # the raw regions reach below DC beyond C' (the report's sector CC'C'')
        cp = named_points(p).get("C'")
        if cp is not None and cp.k <= max(cap, 2.5 * max(ks, default=0.0)):
            ks.append(cp.k)
            mus.append(cp.mu)


def _add_loaded_points(p: Parameters, cap: float, ref: float, ks: list[float], mus: list[float]) -> None:
    """The loaded map's characteristic points, lift-off's start L among them."""
    for pt in named_points(p).values():
        if math.isfinite(pt.k) and math.isfinite(pt.mu) and 0.0 < pt.k <= cap:
            ks.append(pt.k)
            if pt.mu <= _CAP * max(1.0 / p.gamma, p.mu_Bprime):
                mus.append(pt.mu)
    if math.isfinite(p.k_L):  # lift-off is shown wherever it starts
        ks.append(1.3 * p.k_L if p.k_L > 0.0 else 0.3 * ref)


def _fit_mu_max(p: Parameters, raw_mode: Mode | None, k_max: float, mus: list[float]) -> float:
    """mu_max that shows ``mus`` and mu* over [0, k_max] (OA to mid height where A is at infinity)."""
    if raw_mode is None or Mode(raw_mode) is not Mode.RE:
        on_view = _mu_on_view(p, k_max)
        if p.loaded:  # mu* of a loaded block may have a pole in view: show its rise, not all of it
            on_view = min(on_view, _POLE_CAP * max(mus))
        mus.append(on_view)
    if not math.isfinite(p.k_A):  # rest up to mu = k everywhere: show OA to mid height
        mus.append(0.5 * k_max)
    return nice_ceil((1.0 + _MARGIN) * max(max(mus), 1e-12))
