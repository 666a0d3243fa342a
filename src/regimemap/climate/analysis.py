"""From a record to return values with their confidence band: the steps of ``regimemap climate``.

numpy and scipy: threshold, storms (or annual maxima), fit, bootstrap, return values.
"""

from __future__ import annotations

from dataclasses import InitVar, dataclass, field

import numpy as np

from .fits import AM_DISTRIBUTIONS, GEV_XI, POT_DISTRIBUTIONS, Band, Fit, fit, return_values
from .intervals import DEFAULT_INTERVAL, INTERVALS, interval_band
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
from .record import Record

__all__ = ["METHODS", "MIN_YEARS", "ClimateOptions", "ClimateResult", "Curves", "Diagnostics", "analyse",
           "curves", "diagnostics"]

#: The ways to take extremes from a record.
METHODS = ("pot", "annual-maxima")
#: Shortest record [years] for an extreme-value analysis.
MIN_YEARS = 1.0
#: Fewest storms above a threshold of the diagnostics.
DIAGNOSTIC_STORMS = 20


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
        if self.interval not in INTERVALS:
            raise ValueError(f"interval must be one of {', '.join(INTERVALS)}, got {self.interval!r}")
        if not self.replicates >= 0:
            raise ValueError(f"replicates must be a number >= 0, got {self.replicates!r}")


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
        The bootstrap (None without replicates).
    return_values : list of dict
        ``{period, value, lower, upper}``.
    notes : list of str
        Warnings about the fit (``--strict`` makes them errors).
    """

    record: Record
    options: ClimateOptions
    storms: Storms | None
    maxima: AnnualMaxima | None
    fit: Fit
    band: Band | None
    return_values: list[dict[str, float | None]]
    notes: list[str] = field(default_factory=list)

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
    """Threshold, storms or annual maxima, fit, bootstrap and return values.

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
    notes: list[str] = []
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
    if estimate.distribution == "gev" and estimate.parameters["xi"] <= GEV_XI[0] + 1e-6:
        notes.append(f"the GEV shape reached its bound xi = {GEV_XI[0]:g} (too few or too even annual "
                     "maxima for three parameters): prefer gumbel or peaks over a threshold")
    band = (interval_band(sample, estimate, options.interval, options.replicates, options.seed, years,
                          options.shape)
            if options.replicates > 0 else None)
    if band is not None and band.failed > 0.05 * band.requested:
        notes.append(f"{band.failed} of {band.requested} bootstrap replicates had too few values to fit "
                     "and were left out: the band is too narrow (lower the threshold)")
    for R in options.return_periods:
        if estimate.rate * R <= 1.0:
            raise ValueError(f"return period {R:g} years is shorter than the mean time between "
                             f"storms ({1.0 / estimate.rate:.3g} years)")
    values = return_values(estimate, band, list(options.return_periods), options.confidence)
    return ClimateResult(record=record, options=options, storms=st, maxima=am, fit=estimate, band=band,
                         return_values=values, notes=notes)


@dataclass(frozen=True)
class Curves:
    """What the return-level and QQ plots draw (computed here, drawn by :mod:`regimemap.drawing.climate`).

    Attributes
    ----------
    periods : ndarray
        Return periods of the fitted curve [years].
    level : ndarray
        The fit's return values there [m].
    lower, upper : ndarray or None
        The band's bounds there (None without a bootstrap).
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
    """

    thresholds: np.ndarray
    storms: np.ndarray
    mean_excess: np.ndarray
    mean_excess_ci: np.ndarray
    xi: np.ndarray
    sigma_star: np.ndarray


def diagnostics(record: Record, gap_hours: float = DEFAULT_GAP, points: int = 30) -> Diagnostics:
    """Mean residual life and parameter stability at ``points`` thresholds evenly from the 90 %
    quantile of the heights to the height that leaves :data:`DIAGNOSTIC_STORMS` storms; the GPD
    is fitted only where at least that many storms remain."""
    hs = record.hs[np.isfinite(record.hs)]
    top = storms(record, float(np.quantile(hs, 0.90)), gap_hours).peak
    last = float(np.sort(top)[-DIAGNOSTIC_STORMS]) if top.size > DIAGNOSTIC_STORMS else float(top.max())
    us = np.linspace(float(np.quantile(hs, 0.90)), max(last - 1e-9, float(np.quantile(hs, 0.90))), points)
    n, me, ci, xi, ss = [], [], [], [], []
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
        except ValueError:
            xi.append(np.nan)
            ss.append(np.nan)
    return Diagnostics(thresholds=us, storms=np.array(n), mean_excess=np.array(me),
                       mean_excess_ci=np.array(ci), xi=np.array(xi), sigma_star=np.array(ss))
