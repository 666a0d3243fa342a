"""Hourly wave records of a known extreme-value truth, to measure how often an interval covers it.

numpy only.  A synthetic record is a background sea state that never exceeds a base level
:math:`u_0`, and storms that rise above it: their number over the record's :math:`T` years is
:math:`N \\sim \\mathrm{Poisson}(\\lambda T)`, and each storm's peak is :math:`u_0` plus an
excess drawn from the generalised Pareto distribution GPD(:math:`\\sigma`, :math:`\\xi`),
independently.  The storms are placed uniformly in time at least ``separation_hours`` apart
(the sorted uniforms of ``N`` points on the record shortened by ``(N - 1) d``, each moved on by
``i d``: the count stays Poisson), and each is a smooth rise to its peak, an hour of the record,
and a fall of the same shape, above :math:`u_0` for exactly ``2 storm_hours + 1`` hours.  So
the storm peaks above :math:`u_0` are the marks of a Poisson process of rate :math:`\\lambda`
with GPD excesses, and the runs declustering of :func:`regimemap.climate.peaks.storms` at any
threshold :math:`u \\ge u_0` with a gap shorter than the storms' separation finds exactly the
storms that reach above :math:`u`, each at its peak.

By threshold stability (Coles 2001, Sect. 4.2 and 4.3) the excesses over any :math:`u \\ge u_0`
are GPD(:math:`\\sigma_u`, :math:`\\xi`), :math:`\\sigma_u = \\sigma + \\xi (u - u_0)`, at the rate
:math:`\\lambda_u = \\lambda (1 + \\xi (u - u_0)/\\sigma)^{-1/\\xi}`, and the :math:`R`-year
value, :math:`\\lambda R\\,P(\\text{peak} > H_R) = 1`, is the same from every such threshold:

.. math:: H_R = u_0 + \\frac{\\sigma}{\\xi}\\left((\\lambda R)^{\\xi} - 1\\right)
          = u + \\frac{\\sigma_u}{\\xi}\\left((\\lambda_u R)^{\\xi} - 1\\right)

(:math:`u_0 + \\sigma \\ln(\\lambda R)` at :math:`\\xi = 0`).  That is the truth an interval
computed from the record claims to cover.  Each record draws from its own
:class:`numpy.random.SeedSequence` (one child of a root's ``spawn`` per record): the same seed
gives the same record, bit for bit, in any order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .wave_record import Record, make_record

__all__ = ["DEFAULT_SEPARATION", "DEFAULT_STORM_HOURS", "HOURS_PER_YEAR", "SyntheticClimate",
           "record_seeds", "synthetic_hs", "synthetic_record"]

FloatArray = NDArray[np.float64]

#: Hours in a year of the records (365.25 days, as :attr:`regimemap.climate.wave_record.Record.years`).
HOURS_PER_YEAR = 24.0 * 365.25
#: A storm is above the base level for ``2 K + 1`` hours, ``K`` = this.
DEFAULT_STORM_HOURS = 6
#: Least time between two storm peaks [h]: well above the default declustering gap of 48 h plus
#: the storms' own length, so that no gap at or below 48 h joins two storms.
DEFAULT_SEPARATION = 120
#: Hours over which a storm's edge falls from the base level to the background.
_RAMP = 4
#: The record's first time.
_START = np.datetime64("2000-01-01T00:00:00", "s")


@dataclass(frozen=True)
class SyntheticClimate:
    """The truth of a synthetic record: storm peaks above ``base`` at ``rate`` a year, GPD excesses.

    Attributes
    ----------
    sigma : float
        GPD scale of the excesses over ``base`` [m], > 0.
    xi : float
        GPD shape (``xi < 0``: a bounded tail, upper end point ``base - sigma/xi``).
    rate : float
        ``lambda``, storms above ``base`` a year, > 0.
    base : float
        ``u0`` [m]: the background stays below it, every storm rises above it.
    """

    sigma: float
    xi: float
    rate: float
    base: float

    def __post_init__(self) -> None:
        for name in ("sigma", "rate", "base"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > 0.0):
                raise ValueError(f"{name} must be a finite number > 0, got {v!r}")
        if not math.isfinite(self.xi):
            raise ValueError(f"xi must be finite, got {self.xi!r}")

    def at_threshold(self, u: float) -> tuple[float, float]:
        """``(sigma_u, lambda_u)`` of the storm peaks above ``u >= base`` (threshold stability,
        Coles 2001, Eq. 4.9 and Sect. 4.3.3): ``sigma_u = sigma + xi (u - u0)`` and
        ``lambda_u = lambda (1 + xi (u - u0)/sigma)^(-1/xi)`` (``lambda exp(-(u - u0)/sigma)`` at
        ``xi = 0``).

        Raises
        ------
        ValueError
            ``u`` below ``base``, or at or above the upper end point of a bounded tail.
        """
        d = float(u) - self.base
        if d < 0.0:
            raise ValueError(f"threshold {u:g} m is below the base level {self.base:g} m")
        z = 1.0 + self.xi * d / self.sigma
        if not z > 0.0:
            raise ValueError(f"threshold {u:g} m is at or above the upper end point "
                             f"{self.base - self.sigma / self.xi:g} m")
        if self.xi == 0.0:
            return self.sigma, self.rate * math.exp(-d / self.sigma)
        return self.sigma + self.xi * d, self.rate * z ** (-1.0 / self.xi)

    def return_value(self, years: float) -> float:
        """``H_R`` [m]: ``lambda R P(peak > H_R) = 1``, ``u0 + sigma/xi ((lambda R)^xi - 1)``
        (``u0 + sigma ln(lambda R)`` at ``xi = 0``; Coles 2001, Eq. 4.13).

        Raises
        ------
        ValueError
            ``lambda R <= 1``: fewer than one storm above ``base`` in ``R`` years.

        Examples
        --------
        >>> c = SyntheticClimate(sigma=1.0, xi=0.0, rate=10.0, base=3.0)
        >>> round(c.return_value(100.0), 6) == round(3.0 + math.log(1000.0), 6)
        True
        """
        lr = self.rate * float(years)
        if not lr > 1.0:
            raise ValueError(f"no {years:g}-year value with {self.rate:g} storms a year")
        if self.xi == 0.0:
            return self.base + self.sigma * math.log(lr)
        return self.base + self.sigma / self.xi * math.expm1(self.xi * math.log(lr))

    def excesses(self, rng: np.random.Generator, n: int) -> FloatArray:
        """``n`` GPD excesses over ``base`` by the inverse distribution function,
        ``sigma/xi (V^-xi - 1)`` with ``V`` uniform on (0, 1] (``-sigma ln V`` at ``xi = 0``)."""
        v = 1.0 - rng.random(n)
        if self.xi == 0.0:
            return np.asarray(-self.sigma * np.log(v), dtype=np.float64)
        return np.asarray(self.sigma / self.xi * np.expm1(-self.xi * np.log(v)), dtype=np.float64)


def record_seeds(seed: int, n: int) -> list[np.random.SeedSequence]:
    """One :class:`numpy.random.SeedSequence` per record: ``SeedSequence(seed).spawn(n)``."""
    return list(np.random.SeedSequence(seed).spawn(n))


def _background(rng: np.random.Generator, n: int, base: float) -> FloatArray:
    """A slowly varying sea state below ``base``: an hourly AR(1) (lag-one correlation 0.97,
    unit variance), mapped by a logistic onto 15 % to 80 % of ``base``."""
    phi = 0.97
    w = rng.standard_normal(n) * math.sqrt(1.0 - phi * phi)
    # the AR(1) x_t = phi x_(t-1) + w_t as a cumulative sum: x_t = phi^t sum_(s <= t) w_s phi^-s,
    # in blocks short enough that phi^-s stays far from overflow
    x = np.empty(n)
    last = float(rng.standard_normal())
    block = 2000
    powers = phi ** np.arange(1, block + 1)
    for a in range(0, n, block):
        m = min(block, n - a)
        p = powers[:m]
        x[a:a + m] = p * (last + np.cumsum(w[a:a + m] / p))
        last = float(x[a + m - 1])
    return np.asarray(base * (0.15 + 0.65 / (1.0 + np.exp(-1.5 * x))), dtype=np.float64)


def synthetic_hs(climate: SyntheticClimate, years: float, seed: np.random.SeedSequence | int,
                 storm_hours: int = DEFAULT_STORM_HOURS,
                 separation_hours: int = DEFAULT_SEPARATION) -> tuple[FloatArray, FloatArray]:
    """An hourly significant-wave-height series of ``years`` years and its storm peaks.

    Parameters
    ----------
    climate : SyntheticClimate
        The truth.
    years : float
        Record length [years] (``round(years * 8766)`` hourly samples), > 0.
    seed : SeedSequence or int
        The record's own seed (a child of :func:`record_seeds`).
    storm_hours : int, optional
        ``K``: a storm is above ``base`` for ``2 K + 1`` hours, its peak in the middle, the excess
        falling as ``cos^2(pi k / (2 (K + 1)))`` at ``k`` hours from the peak.
    separation_hours : int, optional
        Least time between two peaks [h]; more than ``2 (K + 4) + 1`` (the storms do not overlap)
        and more than the declustering gap plus ``2 K`` (the declustering does not join them).

    Returns
    -------
    hs : ndarray
        The hourly heights [m].
    peaks : ndarray
        The storm peaks [m] in time order (``base`` + GPD excesses; their number is Poisson).

    Raises
    ------
    ValueError
        A separation too short for the storms, or more storms drawn than the record holds at that
        separation (lower the rate or the separation).
    """
    k, d = int(storm_hours), int(separation_hours)
    if k < 1:
        raise ValueError(f"storm_hours must be an integer >= 1, got {storm_hours!r}")
    half = k + _RAMP
    if d <= 2 * half + 1:
        raise ValueError(f"separation_hours must exceed {2 * half + 1} h (twice a storm's "
                         f"{half} h half-length, plus one), got {separation_hours!r}")
    n = round(float(years) * HOURS_PER_YEAR)
    if not n > 2 * half + 1:
        raise ValueError(f"years must be long enough for a storm, got {years!r}")
    rng = np.random.default_rng(seed)
    hs = _background(rng, n, climate.base)
    count = int(rng.poisson(climate.rate * n / HOURS_PER_YEAR))
    slack = (n - 2 * half - 1) - (count - 1) * d
    if count and slack < 0:
        raise ValueError(f"{count} storms do not fit in {years:g} years {d} h apart")
    start = np.sort(np.floor(rng.uniform(0.0, slack, count)).astype(np.int64))
    at = half + start + d * np.arange(count, dtype=np.int64)
    peaks = climate.base + climate.excesses(rng, count)
    offsets = np.arange(-half, half + 1)
    shape = np.cos(0.5 * np.pi * np.abs(offsets) / (k + 1.0)) ** 2  # > 0 for |k| <= K
    inside = np.abs(offsets) <= k
    fall = (np.abs(offsets) - k) / (_RAMP + 1.0)  # beyond K: from base down to the background
    rows = at[:, None] + offsets[None, :]
    bg = hs[rows]
    storm = np.where(inside[None, :], climate.base + (peaks - climate.base)[:, None] * shape[None, :],
                     climate.base + (bg - climate.base) * np.clip(fall, 0.0, 1.0)[None, :])
    hs[rows] = storm
    return hs, peaks


def synthetic_record(climate: SyntheticClimate, years: float, seed: np.random.SeedSequence | int,
                     storm_hours: int = DEFAULT_STORM_HOURS,
                     separation_hours: int = DEFAULT_SEPARATION) -> Record:
    """The :class:`~regimemap.climate.wave_record.Record` of :func:`synthetic_hs` (hourly from
    2000-01-01T00Z, no period), with its quality control, as a reader would make it.

    Examples
    --------
    >>> c = SyntheticClimate(sigma=0.8, xi=-0.1, rate=8.0, base=3.0)
    >>> r = synthetic_record(c, 2.0, seed=1)
    >>> r.step_hours, round(r.years, 6), bool(r.hs.max() > c.base > r.hs.min())
    (1.0, 2.0, True)
    """
    hs, _ = synthetic_hs(climate, years, seed, storm_hours, separation_hours)
    time = np.asarray(_START + np.arange(hs.size) * np.timedelta64(3600, "s"), dtype="datetime64[s]")
    return make_record("synthetic", time, hs)
