"""From a record to return values with their intervals: the steps of ``regimemap climate``.

numpy and scipy: threshold, storms (or annual maxima), fit, interval
(:mod:`regimemap.climate.intervals`), the fit's guards (:mod:`regimemap.climate.guards`), return
values; the curves the figures draw, the threshold diagnostics and the threshold sensitivity.
"""

from __future__ import annotations

from dataclasses import InitVar, dataclass, field, replace

import numpy as np

from ..records.notices import Notice
from .fits import AM_DISTRIBUTIONS, POT_DISTRIBUTIONS, Fit, fit
from .guards import endpoint, fit_notices, limit_notices
from .intervals import (
    DEFAULT_INTERVAL,
    INTERVALS,
    Band,
    bootstrap_minimum,
    grid_quantiles,
    interval_band,
    likelihood_grid,
    return_values,
)
from .peaks import (
    DEFAULT_COVERAGE,
    DEFAULT_GAP,
    DEFAULT_QUANTILE,
    AnnualMaxima,
    Storms,
    annual_maxima,
    resolve_threshold,
    storms,
)
from .wave_record import HS_MAX, Record

__all__ = ["METHODS", "MIN_YEARS", "SENSITIVITY_QUANTILES", "ClimateOptions", "ClimateResult", "Curves",
           "Diagnostics", "Sensitivity", "analyse", "curves", "diagnostics", "sensitivity"]

#: The ways to take extremes from a record.
METHODS = ("pot", "annual-maxima")
#: Shortest record [years] for an extreme-value analysis.
MIN_YEARS = 1.0
#: Fewest storms above a threshold of the diagnostics.
DIAGNOSTIC_STORMS = 20
#: The thresholds of the threshold sensitivity: these quantiles of the heights.
SENSITIVITY_QUANTILES = (0.98, 0.985, 0.99, 0.993, 0.995, 0.997)


@dataclass(frozen=True)
class ClimateOptions:
    """How to analyse a record (the options of ``regimemap climate`` and of ``[lifetime.record]``).

    Attributes
    ----------
    method : str
        ``pot`` (peaks over a threshold) or ``annual-maxima``.
    threshold : tuple of (str, float)
        ``("quantile", q)`` or ``("value", metres)`` (peaks over a threshold).
    gap_hours : float
        Declustering gap [h], > 0.
    distribution : str or None
        ``gpd`` or ``weibull`` (pot), ``gumbel`` or ``gev`` (annual maxima); None: ``gpd`` or ``gumbel``.
    shape : float
        Weibull ``k`` (fixed).
    coverage : float
        Least share of a year's hours observed for its annual maximum.
    return_periods : tuple of float
        Return periods [years].
    confidence : float
        Level of the intervals, in (0, 1).
    replicates : int
        Replicate fits (0: no interval): the posterior draws, likelihood draws or bootstrap refits
        the lifetime's climate replicates are drawn from (``bootstrap``: the draws of the interval
        too; the others draw at least :data:`~regimemap.climate.intervals.POSTERIOR_DRAWS` for it).
    seed : int
        Root seed of the draws.
    interval : str
        ``posterior`` (default), ``profile`` or ``bootstrap``
        (:mod:`regimemap.climate.intervals`).
    hs_limit : float or None
        A physical limit [m]: a return value or interval bound above it is flagged (None: the
        :data:`~regimemap.climate.wave_record.HS_MAX` the record reader refuses in a record).
    hs_limit_name : str
        What the limit is, for the notice.
    bootstrap : int, optional
        The old name of ``replicates`` (init only: ``ClimateOptions(bootstrap=200)`` still works).
    """

    method: str = "pot"
    threshold: tuple[str, float] = ("quantile", DEFAULT_QUANTILE)
    gap_hours: float = DEFAULT_GAP
    distribution: str | None = None
    shape: float = 2.0
    coverage: float = DEFAULT_COVERAGE
    return_periods: tuple[float, ...] = (10.0, 50.0, 100.0)
    confidence: float = 0.9
    replicates: int = 200
    seed: int = 0
    interval: str = DEFAULT_INTERVAL
    hs_limit: float | None = None
    hs_limit_name: str = "the largest height the record reader accepts"
    bootstrap: InitVar[int | None] = None

    def __post_init__(self, bootstrap: int | None) -> None:
        if bootstrap is not None:
            object.__setattr__(self, "replicates", int(bootstrap))

    @property
    def fitted(self) -> str:
        """The distribution fitted."""
        if self.distribution is not None:
            return self.distribution
        return "gpd" if self.method == "pot" else "gumbel"

    def check(self) -> None:
        """The combination is possible, else a ValueError naming the option."""
        if self.method not in METHODS:
            raise ValueError(f"method must be one of {', '.join(METHODS)}, got {self.method!r}")
        allowed = POT_DISTRIBUTIONS if self.method == "pot" else AM_DISTRIBUTIONS
        if self.fitted not in allowed:
            raise ValueError(f"distribution {self.fitted!r} does not fit {self.method}: "
                             f"accepted {', '.join(allowed)}")
        if not self.gap_hours > 0.0:
            raise ValueError(f"gap must be a number of hours > 0, got {self.gap_hours!r}")
        if not 0.0 < self.confidence < 1.0:
            raise ValueError(f"confidence must be in (0, 1), got {self.confidence!r}")
        if not 0.0 < self.coverage <= 1.0:
            raise ValueError(f"coverage must be in (0, 1], got {self.coverage!r}")
        if not (np.isfinite(self.shape) and self.shape > 0.0):  # checked whatever the distribution
            raise ValueError(f"shape must be a Weibull k > 0, got {self.shape!r}")
        if self.interval not in INTERVALS:
            raise ValueError(f"interval must be one of {', '.join(INTERVALS)}, got {self.interval!r}")
        if self.hs_limit is not None and not (self.hs_limit > 0.0 and np.isfinite(self.hs_limit)):
            raise ValueError(f"hs_limit must be a height in metres > 0, got {self.hs_limit!r}")
        if not self.replicates >= 0:
            raise ValueError(f"replicates must be a number >= 0, got {self.replicates!r}")
        fewest = bootstrap_minimum(self.confidence)
        if self.interval == "bootstrap" and 0 < self.replicates < fewest:
            raise ValueError(f"replicates must be 0 (no interval) or at least {fewest} for a "
                             f"{100 * self.confidence:g} % bootstrap interval (4/(1 - confidence): each "
                             f"tail beyond it holds two replicates or more), got {self.replicates!r}")


def _old_bootstrap(self: ClimateOptions) -> int:
    """The old name of ``replicates``, read-only."""
    return self.replicates


# ``bootstrap`` is an init-only argument; read back, it is ``replicates`` (not the InitVar's default)
ClimateOptions.bootstrap = property(_old_bootstrap)  # type: ignore[attr-defined]


@dataclass(frozen=True)
class ClimateResult:
    """The analysis of a record.

    Attributes
    ----------
    record : Record
    options : ClimateOptions
    storms : Storms or None
        The storms (pot).
    maxima : AnnualMaxima or None
        The annual maxima (annual-maxima).
    fit : Fit
    band : Band or None
        The interval's draws and replicate fits (None without replicates).
    return_values : list of dict
        ``{period, value, lower, upper}``.
    notes : list of str
        Warnings about the fit (``--strict`` makes them errors): the messages of ``notices``.
    notices : list of Notice
        The same warnings as data (code ``fit``, the quantity and its value:
        :mod:`regimemap.climate.guards`).
    """

    record: Record
    options: ClimateOptions
    storms: Storms | None
    maxima: AnnualMaxima | None
    fit: Fit
    band: Band | None
    return_values: list[dict[str, float | None]]
    notes: list[str] = field(default_factory=list)
    notices: list[Notice] = field(default_factory=list)

    @property
    def endpoint(self) -> float | None:
        """The fitted upper end point [m] of a bounded tail (``xi < 0``), else None."""
        return endpoint(self.fit)

    def warnings(self) -> list[str]:
        """The quality control's warnings and the fit's notes (``--strict`` makes them errors)."""
        am = self.options.method == "annual-maxima"
        return self.record.quality.warnings(self.options.coverage if am else None) + self.notes

    @property
    def sample(self) -> np.ndarray:
        """The values fitted (storm peaks or annual maxima)."""
        if self.storms is not None:
            return self.storms.peak
        assert self.maxima is not None
        return self.maxima.maxima


def analyse(record: Record, options: ClimateOptions) -> ClimateResult:
    """Threshold, storms or annual maxima, fit, interval, guards and return values.

    Raises
    ------
    ValueError
        A record shorter than :data:`MIN_YEARS`, a threshold above every height, too few storms
        or years for a fit, or an impossible option (the message names it).
    """
    options.check()
    if record.years < MIN_YEARS:
        raise ValueError(f"{record.source}: {record.years:.2f} years observed; an extreme-value "
                         f"analysis needs at least {MIN_YEARS:g} year")
    notices: list[Notice] = []
    st: Storms | None = None
    am: AnnualMaxima | None = None
    if options.method == "pot":
        u = resolve_threshold(record, *options.threshold)
        st = storms(record, u, options.gap_hours)
        estimate = fit(st.peak, options.fitted, u, st.rate, options.shape)
        sample, years = st.peak, record.years
    else:
        am = annual_maxima(record, options.coverage)
        estimate = fit(am.maxima, options.fitted)
        sample, years = am.maxima, None
    notices += fit_notices(estimate, sample, record.years, max(options.return_periods))
    band = (interval_band(sample, estimate, options.interval, options.replicates, options.seed, years,
                          options.shape)
            if options.replicates > 0 else None)
    if band is not None and band.failed > 0.05 * band.requested:
        notices.append(Notice("fit", f"{band.failed} of {band.requested} bootstrap replicates had too few "
                                     "values to fit and were left out: the band is too narrow (lower the "
                                     "threshold)", "replicates", float(band.failed)))
    for R in options.return_periods:
        if estimate.rate * R <= 1.0:
            raise ValueError(f"return period {R:g} years is shorter than the mean time between "
                             f"storms ({1.0 / estimate.rate:.3g} years)")
    values = return_values(estimate, band, list(options.return_periods), options.confidence)
    limit = HS_MAX if options.hs_limit is None else options.hs_limit
    notices += limit_notices(values, limit, options.hs_limit_name)
    return ClimateResult(record=record, options=options, storms=st, maxima=am, fit=estimate, band=band,
                         return_values=values, notes=[n.message for n in notices], notices=notices)


@dataclass(frozen=True)
class Curves:
    """What the return-level and QQ plots draw (computed here, drawn by :mod:`regimemap.climate.figures`).

    Attributes
    ----------
    periods : ndarray
        Return periods of the fitted curve [years].
    level : ndarray
        The fit's return values there [m].
    lower, upper : ndarray or None
        The interval's bounds there (None without replicates): quantiles of the same draws, or
        the profile over the same grid, at every period (no refit).
    observed : ndarray
        The values fitted, ascending [m].
    observed_periods : ndarray
        Their return periods at Weibull plotting positions: ``p_i = i/(n + 1)``,
        ``R_i = 1/(lambda (1 - p_i))``.
    model_quantiles : ndarray
        The fit's quantiles at ``p_i`` (the QQ plot's x).
    """

    periods: np.ndarray
    level: np.ndarray
    lower: np.ndarray | None
    upper: np.ndarray | None
    observed: np.ndarray
    observed_periods: np.ndarray
    model_quantiles: np.ndarray


def curves(result: ClimateResult, points: int = 60) -> Curves:
    """The return-level curve with its band, and the observations at their plotting positions."""
    f = result.fit
    x = np.sort(result.sample)
    p = np.arange(1, x.size + 1) / (x.size + 1.0)
    obs_periods = 1.0 / (f.rate * (1.0 - p))
    first = 1.05 / f.rate if f.rate > 1.0 else 1.1
    last = max(2.0 * float(obs_periods.max()), 2.0 * max(result.options.return_periods), 200.0)
    periods = np.geomspace(first, last, points)
    level = np.array([f.return_value(R) for R in periods])
    lower = upper = None
    if result.band is not None and result.band.fits:
        bounds = np.array([result.band.interval(R, result.options.confidence) for R in periods])
        lower, upper = bounds[:, 0], bounds[:, 1]
    return Curves(periods=periods, level=level, lower=lower, upper=upper, observed=x,
                  observed_periods=obs_periods, model_quantiles=np.asarray(f.frozen().ppf(p), dtype=float))


@dataclass(frozen=True)
class Diagnostics:
    """Threshold diagnostics over a range of thresholds (Coles 2001, Sect. 4.3.1).

    Attributes
    ----------
    thresholds : ndarray
        ``u`` [m].
    storms : ndarray of int
        Storms above each ``u`` (declustered with the analysis' gap).
    mean_excess : ndarray
        Mean residual life: the mean of ``peak - u`` [m]; for a GPD linear in ``u``.
    mean_excess_ci : ndarray
        Its 90 % normal half-width, ``1.645 sd/sqrt(n)``.
    xi : ndarray
        The GPD shape fitted above each ``u`` (NaN where too few storms); constant above a valid
        threshold.
    sigma_star : ndarray
        The modified scale ``sigma - xi u``, constant likewise.
    xi_interval, sigma_star_interval : ndarray
        Their equal-tailed posterior intervals at ``confidence``, shape ``(points, 2)`` (the grid
        posterior of :mod:`regimemap.climate.intervals`; NaN where too few storms).
    confidence : float
        The intervals' level.
    """

    thresholds: np.ndarray
    storms: np.ndarray
    mean_excess: np.ndarray
    mean_excess_ci: np.ndarray
    xi: np.ndarray
    sigma_star: np.ndarray
    xi_interval: np.ndarray
    sigma_star_interval: np.ndarray
    confidence: float = 0.9


def diagnostics(record: Record, gap_hours: float = DEFAULT_GAP, points: int = 30,
                confidence: float = 0.9) -> Diagnostics:
    """Mean residual life and parameter stability at ``points`` thresholds evenly from the 90 %
    quantile of the heights to the height that leaves :data:`DIAGNOSTIC_STORMS` storms; the GPD
    is fitted only where at least that many storms remain, and the shape and modified scale get
    their ``confidence`` posterior intervals (flat prior, :mod:`regimemap.climate.intervals`)."""
    hs = record.hs[np.isfinite(record.hs)]
    q90 = float(np.quantile(hs, 0.90))
    top = storms(record, q90, gap_hours).peak
    last = float(np.sort(top)[-DIAGNOSTIC_STORMS]) if top.size > DIAGNOSTIC_STORMS else float(top.max())
    us = np.linspace(q90, max(last - 1e-9, q90), points)
    n, me, ci, xi, ss, xi_iv, ss_iv = [], [], [], [], [], [], []
    a = 0.5 * (1.0 - confidence)
    nan2 = [np.nan, np.nan]
    for u in us:
        s = storms(record, float(u), gap_hours)
        e = s.peak - u
        n.append(s.count)
        me.append(float(e.mean()) if e.size else np.nan)
        ci.append(1.645 * float(e.std(ddof=1)) / np.sqrt(e.size) if e.size > 1 else np.nan)
        try:
            if s.count < DIAGNOSTIC_STORMS:
                raise ValueError("too few storms")
            g = fit(s.peak, "gpd", float(u), s.rate)
            xi.append(g.parameters["xi"])
            ss.append(g.parameters["sigma"] - g.parameters["xi"] * float(u))
            grid = likelihood_grid(s.peak, g, s.years)
            gx, gs = grid.parameters["xi"], grid.parameters["sigma"]
            xi_iv.append(list(grid_quantiles(grid, gx, [a, 1.0 - a])))
            ss_iv.append(list(grid_quantiles(grid, gs - gx * float(u), [a, 1.0 - a])))
        except ValueError:
            xi.append(np.nan)
            ss.append(np.nan)
            xi_iv.append(nan2)
            ss_iv.append(nan2)
    return Diagnostics(thresholds=us, storms=np.array(n), mean_excess=np.array(me),
                       mean_excess_ci=np.array(ci), xi=np.array(xi), sigma_star=np.array(ss),
                       xi_interval=np.array(xi_iv, dtype=np.float64).reshape(-1, 2),
                       sigma_star_interval=np.array(ss_iv, dtype=np.float64).reshape(-1, 2),
                       confidence=float(confidence))


@dataclass(frozen=True)
class Sensitivity:
    """How a return value and its interval move with the threshold (peaks over a threshold).

    Attributes
    ----------
    period : float
        The return period [years] (50 when asked for, else the longest asked for).
    quantiles : ndarray
        The thresholds as quantiles of the heights (:data:`SENSITIVITY_QUANTILES`).
    thresholds : ndarray
        ``u`` [m].
    storms : ndarray of int
        Storms above each.
    value, lower, upper : ndarray
        The return value and its interval [m] (the analysis' method and level; NaN where too
        few storms to fit).
    confidence : float
    interval : str
        The interval method.
    """

    period: float
    quantiles: np.ndarray
    thresholds: np.ndarray
    storms: np.ndarray
    value: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    confidence: float
    interval: str


def sensitivity(record: Record, options: ClimateOptions,
                quantiles: tuple[float, ...] = SENSITIVITY_QUANTILES) -> Sensitivity | None:
    """The ``R``-year value and its interval refitted above each of ``quantiles`` of the heights
    (the same gap, distribution, method and seed; a posterior or profile with one replicate fit, the
    interval from its own draws); None for annual maxima or without an interval."""
    if options.method != "pot" or options.replicates <= 0:
        return None
    period = 50.0 if 50.0 in options.return_periods else max(options.return_periods)
    keep = options.replicates if options.interval == "bootstrap" else 1
    rows: list[tuple[float, int, float | None, float | None, float | None]] = []
    hs = record.hs[np.isfinite(record.hs)]
    for q in quantiles:
        u = float(np.quantile(hs, q))
        try:
            r = analyse(record, replace(options, threshold=("quantile", float(q)), replicates=keep,
                                        return_periods=(period,)))
        except ValueError:
            count = storms(record, u, options.gap_hours).count if u < float(hs.max()) else 0
            rows.append((u, count, np.nan, np.nan, np.nan))
            continue
        rv = r.return_values[0]
        assert r.storms is not None
        rows.append((u, r.storms.count, rv["value"], rv["lower"], rv["upper"]))
    a = np.array([[np.nan if v is None else float(v) for v in row] for row in rows], dtype=np.float64)
    return Sensitivity(period=period, quantiles=np.array(quantiles, dtype=np.float64), thresholds=a[:, 0],
                       storms=a[:, 1].astype(np.int64), value=a[:, 2], lower=a[:, 3], upper=a[:, 4],
                       confidence=options.confidence, interval=options.interval)
