"""Force pulses k(t) (in units of g), vectorised over runs.

Every shape starts at t = 0 and lasts ``duration`` seconds (the whole pulse),
with peak ``k_peak`` (the largest value; positive pushes towards O).  Each run
may have its own ``k_peak`` and ``duration``.  Outside [0, duration) k = 0.

============  ================================================================
shape         k(t) for 0 <= tau = t/duration < 1
============  ================================================================
rectangular   k_peak
triangular    k_peak tau/c for tau < c, k_peak (1-tau)/(1-c) after (c = ``peak_at``,
              default 1/2: a symmetric triangle; c = 0 is a blast-type decaying pulse)
half-sine     k_peak sin(pi tau)              (omega_p = pi/duration)
one-sine      k_peak sin(2 pi tau)            (omega_p = 2 pi/duration; Zhang & Makris
              2001 type A acceleration with phase 0)
one-cosine    k_peak cos(2 pi tau)            (omega_p = 2 pi/duration; Zhang & Makris
              2001 type B)
breaking      k_peak max(tri(tau/f), r sin(pi tau)): a short impulsive triangle of
              duration f * duration (rising to k_peak at f/2, back to 0 at f) on a
              half-sine of peak r k_peak spanning the whole pulse.  ``peak_ratio`` r
              (default 0.4) is the quasi-static (standing-wave) peak over the impulsive
              peak, ``impulsive_fraction`` f (default 0.1) the impulsive duration over
              the whole pulse.  This is the triangular-impulse-on-standing-wave shape of
              the breaking-wave force model for caissons of Tanimoto et al. (1996) and
              Shimosako & Takahashi (1999); the defaults are illustrative, not their
              design formulas (which set the impulsive duration and peak from the wave
              and mound geometry).
arrays        linear interpolation of given samples (t, k[, k']), see
              :meth:`Pulse.from_arrays`; duration is the last sample time.
============  ================================================================

References
----------
Housner, G. W. (1963). Bull. Seismol. Soc. Am. 53(2), 403-417 (rectangular and
half-sine pulses).

Makris, N. & Roussos, Y. (2000). Geotechnique 50(3), 243-262 (half-sine pulses).

Zhang, J. & Makris, N. (2001). J. Eng. Mech. 127(5), 473-483 (one-sine and
one-cosine cycloidal pulses).

Tanimoto, K., Takahashi, S., Kaneko, T. & Shiota, K. (1996). Investigations of
breaking wave forces and sliding of caissons. Proc. 25th ICCE.

Shimosako, K. & Takahashi, S. (1999). Application of deformation-based
reliability design for coastal structures. Proc. Coastal Structures '99.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Pulse", "SHAPES"]

FloatArray = NDArray[np.float64]

#: The analytic shapes (plus ``"arrays"`` for sampled histories).
SHAPES: tuple[str, ...] = ("rectangular", "triangular", "half-sine", "one-sine", "one-cosine", "breaking")


@dataclass(frozen=True)
class Pulse:
    """A force history k(t) (units of g), one per run.

    Build with the class methods (:meth:`rectangular`, :meth:`half_sine`, ...).

    Attributes
    ----------
    shape : str
        One of :data:`SHAPES` or ``"arrays"``.
    k_peak, duration : ndarray
        Peak (units of g) and whole duration (s), scalars or one per run.
    peak_at : float
        Triangular pulse: time of the peak as a fraction of the duration.
    peak_ratio, impulsive_fraction : float
        Breaking-wave pulse parameters (see the module docstring).
    t_samples, k_samples, kprime_samples : ndarray or None
        Sampled history of :meth:`from_arrays`.
    """

    shape: str
    k_peak: FloatArray
    duration: FloatArray
    peak_at: float = 0.5
    peak_ratio: float = 0.4
    impulsive_fraction: float = 0.1
    t_samples: FloatArray | None = None
    k_samples: FloatArray | None = None
    kprime_samples: FloatArray | None = None

    def __post_init__(self) -> None:
        if self.shape not in SHAPES + ("arrays",):
            raise ValueError(f"unknown pulse shape {self.shape!r}; known: {', '.join(SHAPES)}, arrays")
        if np.any(np.asarray(self.duration) <= 0):
            raise ValueError("pulse duration must be positive")
        if not 0.0 <= self.peak_at <= 1.0:
            raise ValueError("peak_at must lie in [0, 1]")
        if not 0.0 < self.impulsive_fraction <= 1.0:
            raise ValueError("impulsive_fraction must lie in (0, 1]")

    # -- constructors ---------------------------------------------------------------------------
    @classmethod
    def make(cls, shape: str, k_peak: ArrayLike, duration: ArrayLike, **params: float) -> Pulse:
        """A pulse of a named shape (see :data:`SHAPES`); ``params``: peak_at, peak_ratio,
        impulsive_fraction."""
        unknown = set(params) - {"peak_at", "peak_ratio", "impulsive_fraction"}
        if unknown:
            raise ValueError(f"unknown pulse parameters: {', '.join(sorted(unknown))}")
        return cls(shape=shape, k_peak=np.asarray(k_peak, dtype=np.float64),
                   duration=np.asarray(duration, dtype=np.float64),
                   peak_at=float(params.get("peak_at", 0.5)), peak_ratio=float(params.get("peak_ratio", 0.4)),
                   impulsive_fraction=float(params.get("impulsive_fraction", 0.1)))

    @classmethod
    def rectangular(cls, k_peak: ArrayLike, duration: ArrayLike) -> Pulse:
        """Constant k_peak during ``duration`` (Housner 1963)."""
        return cls.make("rectangular", k_peak, duration)

    @classmethod
    def triangular(cls, k_peak: ArrayLike, duration: ArrayLike, peak_at: float = 0.5) -> Pulse:
        """Linear rise to k_peak at ``peak_at * duration``, linear fall to 0 at ``duration``."""
        return cls.make("triangular", k_peak, duration, peak_at=peak_at)

    @classmethod
    def half_sine(cls, k_peak: ArrayLike, duration: ArrayLike) -> Pulse:
        """k_peak sin(omega_p t), omega_p = pi/duration (Makris & Roussos 2000)."""
        return cls.make("half-sine", k_peak, duration)

    @classmethod
    def one_sine(cls, k_peak: ArrayLike, duration: ArrayLike) -> Pulse:
        """k_peak sin(omega_p t), omega_p = 2 pi/duration (Zhang & Makris 2001, type A, no phase)."""
        return cls.make("one-sine", k_peak, duration)

    @classmethod
    def one_cosine(cls, k_peak: ArrayLike, duration: ArrayLike) -> Pulse:
        """k_peak cos(omega_p t), omega_p = 2 pi/duration (Zhang & Makris 2001, type B)."""
        return cls.make("one-cosine", k_peak, duration)

    @classmethod
    def breaking(cls, k_peak: ArrayLike, duration: ArrayLike, peak_ratio: float = 0.4,
                 impulsive_fraction: float = 0.1) -> Pulse:
        """Breaking-wave impact: impulsive triangle on a half-sine (Tanimoto et al. 1996)."""
        return cls.make("breaking", k_peak, duration, peak_ratio=peak_ratio,
                        impulsive_fraction=impulsive_fraction)

    @classmethod
    def from_frequency(cls, shape: str, k_peak: ArrayLike, omega_p: ArrayLike, **params: float) -> Pulse:
        """A pulse given its circular frequency: duration pi/omega_p (rectangular, triangular,
        half-sine, breaking) or 2 pi/omega_p (one-sine, one-cosine)."""
        w = np.asarray(omega_p, dtype=np.float64)
        cycles = 2.0 if shape in ("one-sine", "one-cosine") else 1.0
        return cls.make(shape, k_peak, cycles * np.pi / w, **params)

    @classmethod
    def from_arrays(cls, t: ArrayLike, k: ArrayLike, kprime: ArrayLike | None = None) -> Pulse:
        """A sampled history, linearly interpolated; zero outside [t[0], t[-1]].

        Parameters
        ----------
        t : array_like
            Increasing sample times (s), t[-1] > 0.
        k : array_like
            Force over m g at those times.
        kprime : array_like, optional
            Height of the force over H_C at those times (overrides the block's).
        """
        ts = np.asarray(t, dtype=np.float64)
        ks = np.asarray(k, dtype=np.float64)
        if ts.ndim != 1 or ts.shape != ks.shape or ts.size < 2:
            raise ValueError("t and k must be 1-d arrays of the same length (at least 2)")
        if np.any(np.diff(ts) <= 0):
            raise ValueError("sample times must increase")
        kps = None
        if kprime is not None:
            kps = np.asarray(kprime, dtype=np.float64)
            if kps.shape != ts.shape:
                raise ValueError("kprime must have the shape of t")
        return cls(shape="arrays", k_peak=np.asarray(np.max(np.abs(ks))), duration=np.asarray(ts[-1]),
                   t_samples=ts, k_samples=ks, kprime_samples=kps)

    # -- properties -----------------------------------------------------------------------------
    @property
    def omega_p(self) -> FloatArray:
        """Circular frequency: pi/duration, or 2 pi/duration for one-sine and one-cosine."""
        cycles = 2.0 if self.shape in ("one-sine", "one-cosine") else 1.0
        return cycles * np.pi / self.duration

    @property
    def has_kprime(self) -> bool:
        """Whether the pulse carries its own k'(t)."""
        return self.kprime_samples is not None

    # -- evaluation -----------------------------------------------------------------------------
    def k(self, t: ArrayLike, k_peak: ArrayLike | None = None,
          duration: ArrayLike | None = None) -> FloatArray:
        """k at times ``t`` (broadcast with the per-run ``k_peak`` and ``duration``).

        ``k_peak`` and ``duration`` default to the pulse's own; the time stepper
        passes the parameters of its active runs.
        """
        tt = np.asarray(t, dtype=np.float64)
        kp = self.k_peak if k_peak is None else np.asarray(k_peak, dtype=np.float64)
        T = self.duration if duration is None else np.asarray(duration, dtype=np.float64)
        if self.shape == "arrays":
            assert self.t_samples is not None and self.k_samples is not None
            return np.interp(tt, self.t_samples, self.k_samples, left=0.0, right=0.0)
        tau = tt / T
        inside = (tau >= 0.0) & (tau < 1.0)
        if self.shape == "rectangular":
            shape = np.ones_like(tau)
        elif self.shape == "triangular":
            c = self.peak_at
            rise = tau / c if c > 0 else np.ones_like(tau)
            fall = (1.0 - tau) / (1.0 - c) if c < 1 else np.ones_like(tau)
            shape = np.where(tau < c, rise, fall)
        elif self.shape == "half-sine":
            shape = np.sin(np.pi * tau)
        elif self.shape == "one-sine":
            shape = np.sin(2.0 * np.pi * tau)
        elif self.shape == "one-cosine":
            shape = np.cos(2.0 * np.pi * tau)
        else:  # breaking
            f = self.impulsive_fraction
            s = tau / f
            tri = np.where(s < 0.5, 2.0 * s, np.maximum(2.0 - 2.0 * s, 0.0))
            shape = np.maximum(tri, self.peak_ratio * np.sin(np.pi * tau))
        return np.where(inside, kp * shape, 0.0)

    def breakpoints(self, duration: ArrayLike | None = None) -> FloatArray:
        """The breakpoints of the pulse, per run: the times between which k(t) is smooth and monotone.

        Start, peak(s) and trough, kinks and end of an analytic shape (for ``breaking``: the
        impulsive triangle's peak and end, the half-sine's peak and the kinks where the two meet),
        or every sample of a sampled history.  The time stepper lands a step on each
        (:mod:`regimemap.dynamics.events`).

        Parameters
        ----------
        duration : array_like, optional
            Per-run durations (s); default the pulse's own.

        Returns
        -------
        ndarray, shape (n, m)
            Increasing times (s) in [0, duration] per run (n the number of durations; the
            samples' times, shape (1, m), for a sampled history).
        """
        if self.shape == "arrays":
            assert self.t_samples is not None
            samples: FloatArray = np.array(self.t_samples, dtype=np.float64)[None, :]
            return samples
        T = np.atleast_1d(np.asarray(self.duration if duration is None else duration, dtype=np.float64))
        return T.reshape(-1)[:, None] * self._tau_breakpoints()[None, :]

    def _tau_breakpoints(self) -> FloatArray:
        """:meth:`breakpoints` in units of the duration (the same for every run of a shape)."""
        taus: list[float] = [0.0, 1.0]
        if self.shape == "triangular":
            taus.append(self.peak_at)
        elif self.shape in ("half-sine", "one-cosine"):
            taus.append(0.5)
        elif self.shape == "one-sine":
            taus += [0.25, 0.75]
        elif self.shape == "breaking":
            taus += self._breaking_kinks()
        return np.unique(np.clip(np.asarray(taus, dtype=np.float64), 0.0, 1.0))

    def _breaking_kinks(self) -> list[float]:
        """Breakpoints of the breaking shape max(tri(tau/f), r sin(pi tau)) in (0, 1), in tau.

        The triangle's peak f/2 and end f, the half-sine's peak 1/2 and every tau where the two
        meet.  On each linear piece of the triangle the difference tri - r sin(pi tau) is convex
        (sin is concave on [0, 1]): its minimum is in closed form, and each side of it holds at
        most one root, found by bisection.
        """
        f, r = self.impulsive_fraction, self.peak_ratio
        out = [0.5 * f, f, 0.5]
        if r <= 0.0:
            return out
        for a, b, slope, c0 in ((0.0, 0.5 * f, 2.0 / f, 0.0), (0.5 * f, f, -2.0 / f, 2.0)):

            def d(tau: float, slope: float = slope, c0: float = c0) -> float:
                return c0 + slope * tau - r * float(np.sin(np.pi * tau))

            # d'(tau) = slope - r pi cos(pi tau) = 0 at the minimum
            cosv = slope / (r * np.pi)
            tmin = float(np.arccos(cosv)) / np.pi if -1.0 <= cosv <= 1.0 else (a if cosv > 1.0 else b)
            tmin = min(max(tmin, a), b)
            if d(tmin) >= 0.0:
                continue
            for lo, hi in ((tmin, a), (tmin, b)):  # d(lo) < 0; a root where d(hi) > 0
                if d(hi) <= 0.0:
                    continue
                for _ in range(100):
                    mid = 0.5 * (lo + hi)
                    if mid in (lo, hi):
                        break
                    if d(mid) < 0.0:
                        lo = mid
                    else:
                        hi = mid
                out.append(hi)
        return out

    def kprime(self, t: ArrayLike) -> FloatArray | None:
        """k'(t) of a sampled history, None when the pulse has none (the block's k' holds)."""
        if self.kprime_samples is None:
            return None
        assert self.t_samples is not None
        tt = np.asarray(t, dtype=np.float64)
        return np.interp(tt, self.t_samples, self.kprime_samples)

    def arrays(self, n: int) -> tuple[FloatArray, FloatArray]:
        """``k_peak`` and ``duration`` broadcast to ``n`` runs."""
        return (np.broadcast_to(self.k_peak, (n,)).astype(np.float64),
                np.broadcast_to(self.duration, (n,)).astype(np.float64))
