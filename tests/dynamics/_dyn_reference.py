"""Independent event-driven reference for pure rocking (scipy solve_ivp with events).

Housner (1963) / Zhang & Makris (2001, eq. 12) in *their* convention::

    phi'' = -p^2 [sin(alpha sgn(phi) - phi) + (a_g/g) cos(alpha sgn(phi) - phi)]

Mapping to regimemap's: a ground acceleration a_g (to the right) is an inertial
force -m a_g at C, i.e. our push to the left with k = a_g/g at k' = 0; it tips
the block about O, theta > 0 in our convention, phi < 0 in theirs.  So theta =
-phi and::

    theta'' = -p^2 [sin(alpha s - theta) - k cos(alpha s - theta)],  s = sgn(theta)

(linearised: theta'' = -p^2 [alpha s - theta - k]).  The block stays at rest
until |k| > tan(alpha) (linearised: alpha); an impact at theta = 0 multiplies
theta_dot by eta; the block is at rest again when an impact leaves
|theta_dot| < 1e-7 p alpha and |k| <= tan(alpha).  It has overturned when
|theta| reaches pi/2, or once the pulse is over when |theta| >= alpha moving
outwards (nothing can then bring it back).  Friction is infinite, no sliding, no
flight.  This file is independent of regimemap.dynamics.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq


@dataclass
class RefResult:
    overturned: bool
    max_rotation: float
    impacts: int
    impact_times: list[float] = field(default_factory=list)
    impact_peaks: list[float] = field(default_factory=list)  # |theta| maxima between impacts
    t: list[np.ndarray] = field(default_factory=list)
    theta: list[np.ndarray] = field(default_factory=list)


def _first_exceed(kfun: Callable[[float], float], thr: float, t0: float, t1: float,
                  n: int = 4000) -> tuple[float, float] | None:
    """First time in [t0, t1] where |k| > thr, and the sign of k there."""
    if t1 <= t0:
        return None
    ts = np.linspace(t0, t1, n + 1)
    ks = np.array([kfun(t) for t in ts])
    over = np.abs(ks) > thr
    if not over.any():
        return None
    i = int(np.argmax(over))
    sgn = float(np.sign(ks[i]))
    if i == 0:
        return ts[0], sgn
    f = lambda t: sgn * kfun(t) - thr  # noqa: E731
    if f(ts[i - 1]) >= 0:
        return ts[i - 1], sgn
    return brentq(f, ts[i - 1], ts[i], xtol=1e-14), sgn


def rocking(p: float, alpha: float, kfun: Callable[[float], float], t_pulse: float, *, eta: float,
            t_end: float, linear: bool = False, theta0: float = 0.0, omega0: float = 0.0,
            keep: bool = False, rtol: float = 1e-10, atol: float = 1e-12) -> RefResult:
    """Event-driven rocking response to k(t) (k(t) = 0 after t_pulse)."""
    thr = alpha if linear else np.tan(alpha)
    p2 = p * p

    def k_of(t: float) -> float:
        return kfun(t) if t < t_pulse else 0.0

    def rhs(s: float):
        def f(t: float, z: np.ndarray) -> list[float]:
            th, om = z
            if linear:
                acc = -p2 * (alpha * s - th - k_of(t))
            else:
                a = alpha * s - th
                acc = -p2 * (np.sin(a) - k_of(t) * np.cos(a))
            return [om, acc]
        return f

    res = RefResult(False, abs(theta0), 0)
    t = 0.0
    th, om = theta0, omega0
    resting = theta0 == 0.0 and omega0 == 0.0
    s = float(np.sign(theta0)) if theta0 != 0.0 else 0.0
    peak = abs(theta0)
    while t < t_end:
        if resting:
            hit = _first_exceed(k_of, thr, t, min(t_pulse, t_end))
            if hit is None:
                return res
            t, s = hit
            th, om = 0.0, 0.0
            resting = False
        seg_end = t_pulse if t < t_pulse else t_end
        seg_end = min(seg_end, t_end)
        s_now = s

        def ev_zero(t_: float, z: np.ndarray) -> float:
            return z[0]
        ev_zero.terminal = True  # type: ignore[attr-defined]
        ev_zero.direction = -s_now  # type: ignore[attr-defined]

        def ev_over(t_: float, z: np.ndarray) -> float:
            return abs(z[0]) - np.pi / 2
        ev_over.terminal = True  # type: ignore[attr-defined]
        ev_over.direction = 1  # type: ignore[attr-defined]
        def ev_peak(t_: float, z: np.ndarray) -> float:
            return z[1]
        events = [ev_zero, ev_over, ev_peak]
        if t >= t_pulse:
            def ev_away(t_: float, z: np.ndarray, s_now: float = s_now) -> float:
                return s_now * z[0] - alpha if s_now * z[1] > 0 else -1.0
            ev_away.terminal = True  # type: ignore[attr-defined]
            ev_away.direction = 1  # type: ignore[attr-defined]
            events.append(ev_away)
            if s * th >= alpha and s * om > 0:
                res.overturned = True
                return res
        sol = solve_ivp(rhs(s), (t, seg_end), [th, om], method="DOP853", rtol=rtol, atol=atol,
                        events=events, dense_output=False, max_step=max(seg_end - t, 1e-9) / 40)
        peak = max(peak, float(np.max(np.abs(sol.y[0]))))
        if sol.y_events[2].size:  # turning points: the exact peaks
            peak = max(peak, float(np.max(np.abs(sol.y_events[2][:, 0]))))
        res.max_rotation = max(res.max_rotation, peak)
        if keep:
            res.t.append(sol.t)
            res.theta.append(sol.y[0])
        if sol.status == 1:
            if sol.t_events[1].size:
                res.overturned = True
                return res
            if len(events) > 3 and sol.t_events[3].size:
                res.overturned = True
                return res
            # impact at theta = 0
            t = float(sol.t_events[0][0])
            om = float(sol.y_events[0][0][1]) * eta
            th = 0.0
            res.impacts += 1
            res.impact_times.append(t)
            res.impact_peaks.append(peak)
            peak = 0.0
            s = -s
            if abs(om) < 1e-7 * p * alpha:
                if abs(k_of(t)) <= thr:
                    resting = True
                else:
                    om = 0.0
                    s = float(np.sign(k_of(t)))
            continue
        t = seg_end
        th, om = float(sol.y[0][-1]), float(sol.y[1][-1])
        if t >= t_pulse and s * th >= alpha and s * om > 0:
            res.overturned = True
            return res
    return res


def half_sine(kp: float, T: float) -> Callable[[float], float]:
    return lambda t: kp * np.sin(np.pi * t / T) if 0 <= t < T else 0.0


def one_sine(kp: float, T: float) -> Callable[[float], float]:
    return lambda t: kp * np.sin(2 * np.pi * t / T) if 0 <= t < T else 0.0


def rectangular(kp: float, T: float) -> Callable[[float], float]:
    return lambda t: kp if 0 <= t < T else 0.0


def threshold(overturns: Callable[[float], bool], lo: float, hi: float, tol: float = 1e-5) -> float:
    """Bisection for the smallest overturning value in [lo, hi] (lo safe, hi overturning)."""
    assert not overturns(lo) and overturns(hi)
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        if overturns(mid):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)
