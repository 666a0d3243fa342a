"""The result of a lifetime simulation: every trial's sliding and the statistics of it.

numpy only.  A :class:`LifetimeResult` holds plain arrays (the lifetime
sliding of every trial, the largest single-storm slide of every trial, the
number of storms) and computes the expected sliding distance with its
standard error, quantiles and exceedance probabilities from them.  One table,
:data:`STATISTICS`, names the statistics a person reads: the result's dict
(:meth:`LifetimeResult.summary`), its JSON (:func:`regimemap.lifetime.record.lifetime_json`)
and its notebook table read it.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..records.checks import Check

__all__ = ["STATISTICS", "Failure", "LifetimeResult", "Statistic", "threshold_key", "year_passing"]

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

    @property
    def quantile_90(self) -> float:
        """The 90 % quantile of the lifetime sliding [m]."""
        return self.quantile(0.9)

    @property
    def quantile_99(self) -> float:
        """The 99 % quantile of the lifetime sliding [m]."""
        return self.quantile(0.99)

    @property
    def mean_storms(self) -> float:
        """The mean number of storms in a lifetime."""
        return float(np.mean(self.storms))

    def summary(self) -> dict[str, object]:
        """The statistics of :data:`STATISTICS` as a plain dict, in its order.

        Lengths in metres, probabilities in [0, 1]; ``exceedance`` and
        ``storm_exceedance`` map each threshold (:func:`threshold_key`) to its
        probability; ``failure`` is ``{sliding_limit, probability, std_error}`` or None.
        """
        return {s.key: s.of(self) for s in STATISTICS}

    def __repr__(self) -> str:
        return (f"LifetimeResult(ESD={self.expected_sliding:.4g} m ± {self.std_error:.2g} m, "
                f"trials={self.trials}, years={self.years}, width={self.width:g} m, seed={self.seed})")

    def _repr_html_(self) -> str:
        """The statistics of :data:`STATISTICS` as a small table (Jupyter's rich display)."""
        from ..records.htmltable import html_table
        from ..records.numbers import number

        aside = {s.beside for s in STATISTICS}
        rows: list[tuple[object, ...]] = []
        for s in STATISTICS:
            if s.key not in aside:
                rows += s.html_rows(self)
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


def threshold_key(x: float) -> str:
    """A threshold in metres as a key: ``0.1`` -> ``"0.1"``, ``1.0`` -> ``"1"`` (the shortest repr)."""
    v = float(x)
    return f"{int(v)}" if v == int(v) else repr(v)


def _percent(p: float) -> str:
    return f"{100.0 * p:.3g} %"


@dataclass(frozen=True)
class Statistic:
    """One statistic of a :class:`LifetimeResult`: the row that its dict, its JSON and its table read.

    Attributes
    ----------
    key : str
        The attribute of :class:`LifetimeResult` (a method of the threshold when
        ``per_threshold``), and the key of :meth:`LifetimeResult.summary` and of the JSON.
    label : str
        Its name for people (``{x}`` stands for the threshold when ``per_threshold``).
    unit : str
        ``"m"``, ``"probability"``, ``"year"`` or ``""``.
    description : str
        What it is, in a few words.
    count : bool
        A whole number (kept as an int); the others are floats.
    per_threshold : bool
        One value per threshold of the result (``{threshold_key(x): value}``).
    digits : int
        Significant digits in the table.
    beside : str
        The key of the statistic the table shows in this one's row (``""``: its description).
    aside : str
        How this statistic reads beside another (``{}`` its value), when one shows it.
    """

    key: str
    label: str
    unit: str = ""
    description: str = ""
    count: bool = False
    per_threshold: bool = False
    digits: int = 4
    beside: str = ""
    aside: str = ""

    def of(self, result: LifetimeResult) -> object:
        """The value in ``result``: an int, a float, a dict by threshold, or the failure as a dict."""
        value = getattr(result, self.key)
        if self.per_threshold:
            return {threshold_key(x): float(value(x)) for x in result.thresholds}
        if isinstance(value, Failure):
            return asdict(value)
        if value is None:
            return None
        return int(value) if self.count else float(value)

    def cell(self, result: LifetimeResult, x: float | None = None) -> str:
        """Its value in ``result`` for people, with its unit (at the threshold ``x`` when
        ``per_threshold``): ``0.32 m``, ``40 %``, ``5``."""
        from ..records.numbers import number

        value = getattr(result, self.key)
        if self.per_threshold:
            value = value(x)
        if self.unit == "probability":
            return _percent(float(value))
        if self.count:
            return str(int(value))
        return number(float(value), self.digits) + (f" {self.unit}" if self.unit else "")

    def html_rows(self, result: LifetimeResult) -> list[tuple[object, ...]]:
        """Its rows of the table: ``(label, value with its unit, note)``, one per threshold when
        ``per_threshold``, none for an absent value; the note is the statistic ``beside`` when
        there is one, its ``description`` otherwise."""
        other = _BY_KEY[self.beside] if self.beside else None
        if self.per_threshold:
            return [(self.label.format(x=f"{x:g}"), self.cell(result, x),
                     self.description if other is None else other.aside.format(other.cell(result, x)))
                    for x in result.thresholds]
        value = getattr(result, self.key)
        if value is None:
            return []
        if isinstance(value, Failure):
            return [(self.label, _percent(value.probability),
                     f"{self.description} (S > {value.sliding_limit:g} m), ± {_percent(value.std_error)}")]
        note = self.description if other is None else other.aside.format(other.cell(result))
        return [(self.label, self.cell(result), note)]


#: The statistics of a lifetime result, in the order of its dict, its JSON and its table.
STATISTICS: tuple[Statistic, ...] = (
    Statistic("expected_sliding", "expected sliding (ESD)", "m", "the mean lifetime sliding",
              beside="std_error"),
    Statistic("std_error", "standard error", "m", "of the ESD", digits=2, aside="± {} (standard error)"),
    Statistic("std", "standard deviation", "m", "of the lifetime sliding"),
    Statistic("median", "median", "m", "of the lifetime sliding"),
    Statistic("quantile_90", "90 % quantile", "m", "of the lifetime sliding"),
    Statistic("quantile_99", "99 % quantile", "m", "of the lifetime sliding"),
    Statistic("exceedance", "P(S > {x} m)", "probability", "over the life", per_threshold=True,
              beside="storm_exceedance"),
    Statistic("storm_exceedance", "P(one storm > {x} m)", "probability",
              "one storm alone (Kim & Suh 2013)", per_threshold=True, aside="one storm alone: {}"),
    Statistic("never_slides", "never slides", "probability", "of the lifetimes"),
    Statistic("failure", "probability of failure", "", "sliding off the mound"),
    Statistic("mean_storms", "storms", "", "per lifetime, on average"),
    Statistic("trials", "trials", "", "lifetimes simulated", count=True),
    Statistic("seed", "seed", "", "the root seed", count=True),
    Statistic("years", "design life", "year", "years", count=True),
    Statistic("width", "width", "m", "of the caisson"),
)
_BY_KEY = {s.key: s for s in STATISTICS}
