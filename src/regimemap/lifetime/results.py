"""The result of a lifetime simulation: every trial's sliding and the statistics of it.

numpy only.  A :class:`LifetimeResult` holds plain arrays (the lifetime
sliding of every trial, the largest single-storm slide of every trial, the
number of storms) and computes the expected sliding distance with its
standard error, quantiles and exceedance probabilities from them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..mechanics.checks import Check

__all__ = ["Failure", "LifetimeResult", "year_passing"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]


@dataclass(frozen=True)
class Failure:
    """The probability that the lifetime sliding passes the limit where the caisson is off its mound.

    Attributes
    ----------
    sliding_limit : float
        The sliding at which the caisson fails [m] (the harbour-side crest
        width of the mound).
    probability : float
        ``P(S > sliding_limit)`` over the design life: the share of lifetimes
        that slide farther.
    std_error : float
        Its binomial standard error ``sqrt(p (1 - p) / n)``.
    """

    sliding_limit: float
    probability: float
    std_error: float

    @classmethod
    def of(cls, sliding: FloatArray, limit: float) -> Failure:
        """From the lifetime slides ``sliding`` [m] and the limit [m]."""
        n = int(np.size(sliding))
        p = float(np.mean(np.asarray(sliding) > limit)) if n else math.nan
        return cls(float(limit), p, math.sqrt(p * (1.0 - p) / n) if n else math.nan)


@dataclass(frozen=True)
class LifetimeResult:
    """Sliding over the design life, trial by trial.

    Attributes
    ----------
    sliding : ndarray
        Total sliding of each simulated lifetime [m].
    max_storm : ndarray
        The largest sliding of a single storm in each lifetime [m].
    storms : ndarray of int
        Number of storms in each lifetime.
    seed : int
        The root seed: the same seed gives the same arrays, bit for bit on one machine (to a
        relative 1e-12 or better on another CPU).
    years : int
        Design life.
    thresholds : tuple of float
        Lifetime slides whose exceedance is reported by :meth:`summary` [m].
    width : float
        Full width of the caisson [m].
    sliding_waves : int
        Waves whose sliding was computed (those above their storm's threshold).
    checks : tuple of Check
        The requirements and their verdicts (empty until
        :func:`regimemap.lifetime.requirements.judge_lifetime`).
    failure : Failure or None
        The probability of sliding off the mound, when a limit is given.
    impulsive : bool
        Whether the waves' forces took Takahashi's impulsive coefficient (the
        model's choice, named in every report).
    by_year : ndarray, shape (years,)
        Expected cumulative sliding at the end of each service year [m]
        (``by_year[-1]`` is the ESD up to rounding); empty when not recorded.
    by_year_error : ndarray, shape (years,)
        Its standard error [m]; empty when not recorded.
    """

    sliding: FloatArray
    max_storm: FloatArray
    storms: IntArray
    seed: int
    years: int
    thresholds: tuple[float, ...]
    width: float
    sliding_waves: int = 0
    checks: tuple[Check, ...] = ()
    failure: Failure | None = None
    impulsive: bool = False
    by_year: FloatArray = field(default_factory=lambda: np.zeros(0))
    by_year_error: FloatArray = field(default_factory=lambda: np.zeros(0))

    @property
    def trials(self) -> int:
        """Number of simulated lifetimes."""
        return int(self.sliding.size)

    @property
    def expected_sliding(self) -> float:
        """The expected sliding distance (ESD): the mean lifetime sliding [m]."""
        return float(np.mean(self.sliding))

    @property
    def std_error(self) -> float:
        """Standard error of the ESD: the sample standard deviation over sqrt(trials) [m]."""
        n = self.trials
        if n < 2:
            return math.nan
        return float(np.std(self.sliding, ddof=1) / math.sqrt(n))

    @property
    def std(self) -> float:
        """Standard deviation of the lifetime sliding [m]."""
        return float(np.std(self.sliding, ddof=1)) if self.trials > 1 else math.nan

    def quantile(self, q: float) -> float:
        """The ``q`` quantile of the lifetime sliding [m] (linear interpolation)."""
        return float(np.quantile(self.sliding, q))

    @property
    def median(self) -> float:
        """Median lifetime sliding [m]."""
        return self.quantile(0.5)

    def exceedance(self, x: float) -> float:
        """``P(S > x)``: the share of lifetimes that slide more than ``x`` metres."""
        return float(np.mean(self.sliding > x))

    def storm_exceedance(self, x: float) -> float:
        """The share of lifetimes in which one storm alone slides the caisson more than ``x`` m.

        Kim & Suh's (2013) first-passage probability of a single-storm limit
        (0.03 m repairable, 0.1 m ultimate).
        """
        return float(np.mean(self.max_storm > x))

    @property
    def never_slides(self) -> float:
        """The share of lifetimes with no sliding at all."""
        return float(np.mean(self.sliding == 0.0))

    def exceedance_curve(self) -> tuple[FloatArray, FloatArray]:
        """``(x, P(S > x))`` at every distinct positive lifetime sliding (for a plot)."""
        s = np.sort(self.sliding)
        x = np.unique(s)
        p = 1.0 - np.searchsorted(s, x, side="right") / s.size
        keep = x > 0.0
        return x[keep], p[keep]

    def summary(self) -> dict[str, object]:
        """The statistics as a plain dict (metres, probabilities)."""
        return {
            "expected_sliding": self.expected_sliding,
            "std_error": self.std_error,
            "std": self.std,
            "median": self.median,
            "quantile_90": self.quantile(0.9),
            "quantile_99": self.quantile(0.99),
            "exceedance": {_key(x): self.exceedance(x) for x in self.thresholds},
            "storm_exceedance": {_key(x): self.storm_exceedance(x) for x in self.thresholds},
            "never_slides": self.never_slides,
            "trials": self.trials,
            "years": self.years,
            "seed": self.seed,
            "width": self.width,
            "mean_storms": float(np.mean(self.storms)),
        }

    def __repr__(self) -> str:
        return (f"LifetimeResult(ESD={self.expected_sliding:.4g} m ± {self.std_error:.2g} m, "
                f"trials={self.trials}, years={self.years}, width={self.width:g} m, seed={self.seed})")

    def _repr_html_(self) -> str:
        """The statistics of :meth:`summary` as a small table (Jupyter's rich display)."""
        from ..mechanics.htmltable import html_table, number

        rows: list[tuple[object, ...]] = [
            ("expected sliding (ESD)", f"{number(self.expected_sliding)} m",
             f"± {number(self.std_error, 2)} m (standard error)"),
            ("standard deviation", f"{number(self.std)} m", ""),
            ("median", f"{number(self.median)} m", ""),
            ("90 % / 99 % quantile", f"{number(self.quantile(0.9))} m / "
             f"{number(self.quantile(0.99))} m", ""),
            ("never slides", f"{100.0 * self.never_slides:.3g} %", "of the lifetimes"),
        ]
        for x in self.thresholds:
            rows.append((f"P(S > {x:g} m)", f"{100.0 * self.exceedance(x):.3g} %",
                         f"one storm alone: {100.0 * self.storm_exceedance(x):.3g} %"))
        rows += [
            ("trials", self.trials, f"lifetimes of {self.years} years, seed {self.seed}"),
            ("storms", number(float(np.mean(self.storms))), "per lifetime, on average"),
            ("width", f"{self.width:g} m", "of the caisson"),
        ]
        return html_table(rows, caption=f"Lifetime sliding: ESD = {number(self.expected_sliding)} m "
                          f"over {self.years} years", header=("", "value", ""))

    def year_passing(self, limit: float) -> int | None:
        """The first service year whose expected cumulative sliding exceeds ``limit`` [m]; None if none.

        Raises ValueError when the result holds no :attr:`by_year`.
        """
        return year_passing(self.by_year, limit)


def year_passing(by_year: FloatArray, limit: float) -> int | None:
    """The first service year (from 1) with ``by_year > limit``; None if none.

    Examples
    --------
    >>> year_passing(np.array([0.02, 0.05, 0.12, 0.2]), 0.1)
    3
    >>> year_passing(np.array([0.02, 0.05]), 0.1) is None
    True
    """
    values = np.asarray(by_year, dtype=np.float64)
    if values.size == 0:
        raise ValueError("no expected sliding by service year was recorded")
    over = np.flatnonzero(values > limit)
    return int(over[0]) + 1 if over.size else None


def _key(x: float) -> str:
    """A threshold as a JSON key: ``0.1`` -> ``"0.1"`` (shortest repr)."""
    return repr(float(x)) if float(x) != int(x) else f"{int(x)}"
