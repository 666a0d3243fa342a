"""Sliding of a caisson under one wave: the added mass and the closed-form distance.

numpy only, vectorised over waves.  Shimosako & Takahashi's (1999) equation of
motion of a sliding caisson per metre of breakwater is

    (W/g + M_a) x'' = P(t) - mu (W' - U(t))        while x' > 0,

with ``W`` the weight in air, ``W'`` the buoyant weight, ``M_a`` the added mass
of the water on both faces, and a wave whose force and uplift rise and fall
together as half a sine,

    P(t) = P sin(pi t / tau0),   U(t) = U sin(pi t / tau0),   0 <= t <= tau0,

(zero after ``tau0``).  With ``F = P + mu U``, ``R = mu W'``, ``M = W/g + M_a``,
``omega = pi/tau0`` and ``s = omega t`` the caisson starts at
``s1 = asin(R/F)`` when ``F > R``; in units of ``R/(M omega)`` its velocity is

    v(s) = (F/R)(cos s1 - cos s) - (s - s1)        (s <= pi),
    v(s) = v(pi) - (s - pi)                           (s >= pi),

it stops at the first root ``s2`` of ``v`` after ``s1``, and in units of
:math:`R/(M \\omega^2)` it has slid

    D(s) = (F/R)[cos s1 (s - s1) - (sin s - sin s1)] - (s - s1)^2/2,

``D(s2)`` when it stops within the wave, :math:`D(\\pi) + v(\\pi)^2/2` otherwise.  The
derivation is in :doc:`/lifetime`, Sect. 6.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from regimemap.waves import wave_duration

__all__ = ["ADDED_MASS_COEFFICIENT", "added_mass", "half_sine_slide", "wave_duration"]

FloatArray = NDArray[np.float64]

#: :math:`M_a / (\rho_w h'^2)` for both faces:
#: :math:`2 (16/\pi^3) \sum_{n\ \mathrm{odd}} 1/n^3 = (28/\pi^3) \zeta(3)`
#: (incompressible potential flow against a rigid vertical wall; :doc:`/lifetime`, Sect. 6.2).
ADDED_MASS_COEFFICIENT = 28.0 / math.pi**3 * 1.2020569031595942853997


def added_mass(base_depth: ArrayLike, rho_w: float) -> FloatArray:
    """Added mass of the water on both faces of a caisson, per metre [kg/m].

    Parameters
    ----------
    base_depth : array_like
        ``h'``, depth of the base below still water [m].
    rho_w : float
        Water density [kg/m^3].

    Returns
    -------
    ndarray
        :math:`M_a = 1.0855 \\rho_w h'^2` (Shimosako & Takahashi 1999): on each face
        :math:`(16/\\pi^3) \\rho_w h'^2 \\sum_{n\\ \\mathrm{odd}} 1/n^3 = 0.5428 \\rho_w h'^2`, the exact
        value of Westergaard's (1933) series for an incompressible fluid.

    Examples
    --------
    >>> round(ADDED_MASS_COEFFICIENT, 4)
    1.0855
    """
    hp = np.asarray(base_depth, dtype=np.float64)
    return np.asarray(ADDED_MASS_COEFFICIENT * rho_w * hp * hp, dtype=np.float64)


#: Most Newton (or bisection) steps for the stop within the wave.
_STOP_STEPS = 60


def _stop_within(ratio: FloatArray, s1: FloatArray, c1: FloatArray) -> FloatArray:
    """The root ``s2`` of the velocity on ``[max(s1, pi - s1), pi]`` of each wave (1-d arrays).

    Newton's method from ``pi``, safeguarded by the bracket; each wave runs
    its own steps until its iterate stops changing (from then on it never
    changes: the step and the bracket are functions of it), at most
    :data:`_STOP_STEPS`.  Settled waves leave the arrays, so the work follows
    the waves still iterating; each wave's iterates are the same whatever
    the other waves in the arrays.
    """
    lo = np.maximum(s1, np.pi - s1)
    hi = np.full_like(ratio, np.pi)
    s = hi.copy()
    out = np.empty_like(ratio)
    todo = np.arange(ratio.size)
    with np.errstate(divide="ignore", invalid="ignore"):
        for _ in range(_STOP_STEPS):
            # v = ratio (c1 - cos s) - (s - s1) and dv = ratio sin s - 1, written in place
            v = np.subtract(c1, np.cos(s))
            v *= ratio
            v -= s - s1
            dv = np.sin(s)
            dv *= ratio
            dv -= 1.0
            np.copyto(lo, s, where=v > 0.0)
            np.copyto(hi, s, where=v <= 0.0)
            step = np.divide(v, dv, out=v)
            np.subtract(s, step, out=step)
            bisect = np.add(lo, hi, out=dv)
            bisect *= 0.5
            # lo and hi are finite: the strict bounds also refuse an infinite or nan step
            s_new = np.where((step > lo) & (step < hi), step, bisect)
            going = s_new != s
            s = s_new
            n_going = int(np.count_nonzero(going))
            if n_going == 0:
                break
            if 8 * n_going < 7 * going.size:  # an eighth has settled: keep the others only
                settled = ~going
                out[todo[settled]] = s[settled]
                todo, ratio, s1, c1, lo, hi, s = (a[going] for a in (todo, ratio, s1, c1, lo, hi, s))
    out[todo] = s
    return out


def half_sine_slide(force: ArrayLike, resistance: ArrayLike, mass: ArrayLike,
                    duration: ArrayLike) -> FloatArray:
    """Distance slid under one half-sine push, in closed form [m].

    Parameters
    ----------
    force : array_like
        ``F = P + mu U``: the peak push plus the friction the peak uplift
        takes away [N/m].
    resistance : array_like
        ``R = mu W'``: the friction at rest [N/m].
    mass : array_like
        ``M = W/g + M_a`` [kg/m].
    duration : array_like
        ``tau0`` [s]; a wave with ``tau0 <= 0`` does not push.

    Returns
    -------
    ndarray
        The distance slid (0 where ``F <= R``; ``inf`` where ``R <= 0 < F``:
        nothing stops the caisson), broadcast over the inputs.

    Notes
    -----
    See the module docstring.  The stop ``s2`` within the wave is the root of
    the velocity on ``[max(s1, pi - s1), pi]``, where the velocity is
    decreasing and concave: Newton's method from ``pi`` converges to it
    monotonically, safeguarded by the bracket, to machine precision.

    Examples
    --------
    A push that barely exceeds friction slides almost nothing:

    >>> float(half_sine_slide(1.0001e6, 1e6, 2e5, 4.0)) < 1e-6
    True
    """
    F, R, M, tau = np.broadcast_arrays(*(np.asarray(a, dtype=np.float64)
                                         for a in (force, resistance, mass, duration)))
    out = np.zeros(F.shape, dtype=np.float64)
    F = np.where(tau > 0.0, F, 0.0)  # no push without a duration (H >= 4h, docs/lifetime.md, Sect. 5.2)
    endless = (R <= 0.0) & (F > R)
    out[endless] = np.inf
    moving = (F > R) & ~endless
    if not np.any(moving):
        return out
    ratio = F[moving] / R[moving]
    q = 1.0 / ratio
    s1 = np.arcsin(q)
    c1 = np.sqrt((1.0 - q) * (1.0 + q))  # cos s1, accurate when F is close to R
    v_pi = ratio * (c1 + 1.0) - (np.pi - s1)
    late = v_pi >= 0.0
    D = np.empty_like(ratio)
    # stops after the wave: D(pi) + v(pi)^2/2
    rl, s1l, c1l, vl = ratio[late], s1[late], c1[late], v_pi[late]
    D[late] = rl * (c1l * (np.pi - s1l) - (0.0 - q[late])) - 0.5 * (np.pi - s1l) ** 2 + 0.5 * vl * vl
    # stops within the wave: root of v on [max(s1, pi - s1), pi]
    early = ~late
    if np.any(early):
        re, s1e, c1e = ratio[early], s1[early], c1[early]
        s = _stop_within(re, s1e, c1e)
        D[early] = re * (c1e * (s - s1e) - (np.sin(s) - q[early])) - 0.5 * (s - s1e) ** 2
    omega = np.pi / tau[moving]
    out[moving] = np.maximum(D, 0.0) * R[moving] / (M[moving] * omega * omega)
    return out
