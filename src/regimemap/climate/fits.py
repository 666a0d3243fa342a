"""Extreme-value fits of storm peaks and annual maxima, their band of replicates, and the bootstrap.

numpy and scipy.stats, by maximum likelihood:

* ``gpd`` -- storm peaks over the threshold :math:`u`: the generalised Pareto distribution
  :math:`F(H) = 1 - (1 + \\xi (H - u)/\\sigma)^{-1/\\xi}` (``scipy.stats.genpareto``,
  :math:`c = \\xi`, location fixed at :math:`u`).  With :math:`\\lambda` storms a year the
  :math:`R`-year value is :math:`H_R = u + \\frac{\\sigma}{\\xi}((\\lambda R)^\\xi - 1)`
  (:math:`u + \\sigma \\ln(\\lambda R)` at :math:`\\xi = 0`; Coles 2001, Eq. 4.13);
* ``weibull`` -- storm peaks, :math:`F(H) = 1 - \\exp(-((H - u)/A)^k)` with the shape :math:`k`
  given and the location at :math:`u` (Goda 2000, Sect. 11.2: :math:`k` from 0.75 to 2 chosen,
  not fitted); :math:`H_R = u + A (\\ln \\lambda R)^{1/k}`,
  :math:`A^k = \\overline{(H - u)^k}` (``scipy.stats.weibull_min``);
* ``gumbel`` -- annual maxima, :math:`F(H) = \\exp(-\\exp(-(H - B)/A))` (``scipy.stats.gumbel_r``);
* ``gev`` -- annual maxima, :math:`F(H) = \\exp(-(1 + \\xi (H - \\mu)/\\sigma)^{-1/\\xi})`
  (``scipy.stats.genextreme``, whose shape is :math:`c = -\\xi`).

In every case :math:`F(H_R) = 1 - 1/(\\lambda R)` (:math:`\\lambda = 1` for annual maxima).

:class:`Band` holds an interval's draws and replicate fits, whichever the method
(:mod:`regimemap.climate.intervals`: the grid posterior, the default, and the profile likelihood).
:func:`bootstrap` is the third method, a non-parametric bootstrap with percentile intervals (Efron &
Tibshirani 1993, Ch. 13), which covers less than it claims on short records: each replicate
resamples the observed peaks with replacement -- their number drawn from a Poisson distribution
with the observed count as its mean for peaks over a threshold (the storms of a record are a
Poisson process: how many storms ten years hold is itself uncertain, and ``lambda = N/years``
varies with it), the number of years fixed for annual maxima -- and refits.  It does not assume
the fitted distribution is the true one, but it cannot resample a storm larger than the record's
largest, and its replicates reach shapes where the likelihood is unbounded.  Each replicate draws
from its own child of one :class:`numpy.random.SeedSequence` (``spawn``), so the band is the same
in any order or chunking.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize, stats

__all__ = ["AM_DISTRIBUTIONS", "GEV_XI", "MIN_MAXIMA", "MIN_PEAKS", "POT_DISTRIBUTIONS", "Band", "Fit",
           "bootstrap", "fit", "return_levels", "return_values"]

FloatArray = NDArray[np.float64]

#: Distributions of storm peaks (peaks over a threshold).
POT_DISTRIBUTIONS = ("gpd", "weibull")
#: Distributions of annual maxima.
AM_DISTRIBUTIONS = ("gumbel", "gev")
#: Fewest storm peaks for a fit.
MIN_PEAKS = 10
#: Fewest annual maxima for a fit.
MIN_MAXIMA = 5
#: The GEV shape's range searched (the likelihood is unbounded below -1).
GEV_XI = (-1.0, 1.5)


@dataclass(frozen=True)
class Fit:
    """A fitted distribution of storm peaks (``rate`` a year) or of annual maxima (``rate = 1``).

    Attributes
    ----------
    distribution : str
        ``gpd``, ``weibull``, ``gumbel`` or ``gev``.
    parameters : dict
        ``gpd``: ``sigma``, ``xi``; ``weibull``: ``A``, ``k``; ``gumbel``: ``A``, ``B``;
        ``gev``: ``mu``, ``sigma``, ``xi`` [m, or none for the shapes].
    threshold : float or None
        ``u`` [m] of the peaks over a threshold (the location of ``gpd`` and ``weibull``).
    rate : float
        ``lambda``, storms a year (1 for annual maxima).
    n : int
        Values fitted.
    """

    distribution: str
    parameters: dict[str, float]
    threshold: float | None
    rate: float
    n: int

    def frozen(self) -> Any:
        """The scipy.stats frozen distribution."""
        p, u = self.parameters, self.threshold
        if self.distribution == "gpd":
            return stats.genpareto(p["xi"], loc=u, scale=p["sigma"])
        if self.distribution == "weibull":
            return stats.weibull_min(p["k"], loc=u, scale=p["A"])
        if self.distribution == "gumbel":
            return stats.gumbel_r(loc=p["B"], scale=p["A"])
        return stats.genextreme(-p["xi"], loc=p["mu"], scale=p["sigma"])

    def return_value(self, years: float) -> float:
        """``H_R`` [m]: ``F(H_R) = 1 - 1/(lambda R)`` (:func:`return_levels`; equal to the frozen
        distribution's ``isf(1/(lambda R))``)."""
        if not self.rate * float(years) > 1.0:
            raise ValueError(f"no {years:g}-year return value with {self.rate:.3g} storms a year")
        p = self.parameters
        return float(return_levels(self.distribution, {k: np.array([v]) for k, v in p.items()},
                                   self.threshold, np.array([self.rate]), float(years))[0])


def return_levels(distribution: str, parameters: dict[str, FloatArray], threshold: float | None,
                  rate: FloatArray, years: float) -> FloatArray:
    """``H_R`` of many parameter sets at once, in closed form (NaN where ``lambda R <= 1``).

    ``gpd``: ``u + sigma/xi ((lambda R)^xi - 1)`` (``u + sigma ln(lambda R)`` at ``xi = 0``);
    ``weibull``: ``u + A (ln lambda R)^(1/k)``; ``gumbel``: ``B - A ln(-ln(1 - 1/R))``;
    ``gev``: ``mu + sigma/xi (y^-xi - 1)``, ``y = -ln(1 - 1/R)`` (``mu - sigma ln y`` at ``xi = 0``).
    """
    u = 0.0 if threshold is None else float(threshold)
    with np.errstate(invalid="ignore", divide="ignore"):
        lr = np.where(rate * years > 1.0, rate * years, np.nan)
        if distribution == "gpd":
            xi, sigma = parameters["xi"], parameters["sigma"]
            small = np.abs(xi) < 1e-12
            safe = np.where(small, 1.0, xi)
            out = np.where(small, sigma * np.log(lr), sigma / safe * np.expm1(safe * np.log(lr)))
            return np.asarray(u + out, dtype=np.float64)
        if distribution == "weibull":
            return np.asarray(u + parameters["A"] * np.log(lr) ** (1.0 / parameters["k"]),
                              dtype=np.float64)
        y = -math.log1p(-1.0 / years)
        if distribution == "gumbel":
            return np.asarray(parameters["B"] - parameters["A"] * math.log(y), dtype=np.float64)
        xi, mu, sigma = parameters["xi"], parameters["mu"], parameters["sigma"]
        small = np.abs(xi) < 1e-12
        safe = np.where(small, 1.0, xi)
        ly = math.log(y)
        return np.asarray(np.where(small, mu - sigma * ly, mu + sigma / safe * np.expm1(-safe * ly)),
                          dtype=np.float64)


def _gpd_profile(y: FloatArray) -> tuple[float, float]:
    """GPD maximum likelihood of the excesses ``y > 0``: ``(xi, sigma)`` (Grimshaw 1993).

    With ``theta = xi/sigma`` the likelihood's maximum over ``xi`` for a given ``theta`` is at
    ``xi = mean(ln(1 + theta y))``, leaving the one-dimensional profile
    ``-n ln(xi/theta) - n (1 + xi)`` over ``theta > -1/max(y)`` (``theta -> 0``: the exponential,
    ``-n ln mean(y) - n``): a grid, then Brent's bounded search (``scipy.optimize``) around its
    best point.  It finds the likelihood ``scipy.stats.genpareto.fit`` finds, in a tenth of the time.
    """
    n, ymax, ymean = y.size, float(y.max()), float(y.mean())

    def negative(theta: float) -> float:
        if abs(theta) * ymean < 1e-10:
            return n * math.log(ymean) + n
        k = float(np.mean(np.log1p(theta * y)))
        s = k / theta
        return n * math.log(s) + n * (k + 1.0) if s > 0.0 else math.inf

    lowest = -(1.0 - 1e-9) / ymax
    grid = np.concatenate([np.linspace(lowest, 0.0, 60, endpoint=False),
                           np.geomspace(1e-3, 50.0, 60) / ymean])
    values = [negative(float(t)) for t in grid]
    i = int(np.argmin(values))
    a, b = float(grid[max(i - 1, 0)]), float(grid[min(i + 1, grid.size - 1)])
    best = optimize.minimize_scalar(negative, bounds=(a, b), method="bounded",
                                    options={"xatol": 1e-12 / ymean})
    theta = float(best.x) if best.fun <= values[i] else float(grid[i])
    if abs(theta) * ymean < 1e-10:
        return 0.0, ymean
    k = float(np.mean(np.log1p(theta * y)))
    return k, k / theta


def _gev_negative(p: FloatArray, x: FloatArray) -> float:
    """Negative GEV log-likelihood at ``(mu, ln sigma, xi)`` (Coles 2001, Eq. 3.7 and 3.9)."""
    mu, sigma, xi = float(p[0]), math.exp(float(p[1])), float(p[2])
    z = (x - mu) / sigma
    if abs(xi) < 1e-8:
        return float(x.size * math.log(sigma) + np.sum(z) + np.sum(np.exp(-z)))
    t = 1.0 + xi * z
    if np.any(t <= 0.0):
        return math.inf
    lt = np.log(t)
    return float(x.size * math.log(sigma) + (1.0 + 1.0 / xi) * np.sum(lt) + np.sum(np.exp(-lt / xi)))


def _gev(x: FloatArray, start: dict[str, float] | None) -> dict[str, float]:
    """GEV maximum likelihood with ``xi`` in :data:`GEV_XI`: Nelder-Mead (``scipy.optimize``) from the
    Gumbel fit and from ``start``, the best of them.

    Below ``xi = -1`` the likelihood grows without bound as the upper end point nears the largest
    value (Smith 1985): the search is kept to ``xi >= -1``; inside, it finds what
    ``scipy.stats.genextreme.fit`` finds, faster.
    """
    loc, scale = stats.gumbel_r.fit(x)
    starts = ([np.array([start["mu"], math.log(start["sigma"]), start["xi"]])] if start is not None
              else [np.array([loc, math.log(scale), 0.1]), np.array([loc, math.log(scale), -0.2])])
    bounds = [(None, None), (None, None), GEV_XI]
    best = None
    for s0 in starts:
        r = optimize.minimize(_gev_negative, s0, args=(x,), method="Nelder-Mead", bounds=bounds,
                              options={"xatol": 1e-8, "fatol": 1e-10, "maxiter": 2000})
        if best is None or r.fun < best.fun:
            best = r
    assert best is not None
    return {"mu": float(best.x[0]), "sigma": math.exp(float(best.x[1])), "xi": float(best.x[2])}


def _fit_values(x: FloatArray, distribution: str, threshold: float | None, shape: float,
                start: dict[str, float] | None) -> dict[str, float]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        if distribution == "gpd":
            assert threshold is not None
            xi, sigma = _gpd_profile(x - threshold)
            return {"sigma": sigma, "xi": xi}
        if distribution == "weibull":
            assert threshold is not None
            # the likelihood's maximum with k and u fixed, in closed form: A^k = mean((x - u)^k)
            # (scipy.stats.weibull_min.fit(x, fc=k, floc=u) finds it numerically)
            return {"A": float(np.mean((x - threshold) ** shape)) ** (1.0 / shape), "k": float(shape)}
        if distribution == "gumbel":
            loc, scale = stats.gumbel_r.fit(x)
            return {"A": float(scale), "B": float(loc)}
        return _gev(x, start)


def fit(values: ArrayLike, distribution: str, threshold: float | None = None, rate: float = 1.0,
        shape: float = 2.0, start: dict[str, float] | None = None) -> Fit:
    """Maximum-likelihood fit of storm peaks (``gpd``, ``weibull``) or annual maxima
    (``gumbel``, ``gev``).

    Parameters
    ----------
    values : array_like
        Storm peaks (all above ``threshold``) or annual maxima [m].
    distribution : str
        ``gpd``, ``weibull``, ``gumbel`` or ``gev``.
    threshold : float, optional
        ``u`` [m], needed by ``gpd`` and ``weibull``.
    rate : float, optional
        Storms a year (peaks over a threshold; 1 for annual maxima).
    shape : float, optional
        Weibull ``k`` (fixed, > 0; default 2).
    start : dict, optional
        Starting parameters (a fit's ``parameters``): the bootstrap starts each refit at the estimate.

    Returns
    -------
    Fit

    Raises
    ------
    ValueError
        Too few values (:data:`MIN_PEAKS`, :data:`MIN_MAXIMA`), all equal, or an unknown distribution.
    """
    x = np.asarray(values, dtype=np.float64).ravel()
    if distribution in POT_DISTRIBUTIONS:
        if threshold is None:
            raise ValueError(f"{distribution} fits peaks over a threshold: give the threshold")
        if x.size < MIN_PEAKS:
            raise ValueError(f"{x.size} storm(s) above the threshold {threshold:.3g} m: a fit needs at "
                             f"least {MIN_PEAKS} (lower the threshold or shorten the gap)")
        if distribution == "weibull" and not (shape > 0.0 and math.isfinite(shape)):
            raise ValueError(f"shape must be a Weibull k > 0, got {shape!r}")
    elif distribution in AM_DISTRIBUTIONS:
        if x.size < MIN_MAXIMA:
            raise ValueError(f"{x.size} annual maxima: a fit needs at least {MIN_MAXIMA} years "
                             "(lower --coverage, or use peaks over a threshold)")
    else:
        raise ValueError(f"distribution must be one of {', '.join(POT_DISTRIBUTIONS + AM_DISTRIBUTIONS)}, "
                         f"got {distribution!r}")
    if not float(np.ptp(x)) > 0.0:
        raise ValueError("the values to fit are all equal")
    params = _fit_values(x, distribution, threshold, shape, start)
    return Fit(distribution=distribution, parameters=params,
               threshold=None if distribution in AM_DISTRIBUTIONS else float(threshold),  # type: ignore[arg-type]
               rate=float(rate), n=int(x.size))


@dataclass(frozen=True)
class Band:
    """The uncertainty of a fit: its interval method, the draws behind it and the replicate fits.

    Attributes
    ----------
    fits : list of Fit
        The replicate fits (each with its own rate) the lifetime's climate replicates are drawn
        from: posterior draws (``posterior``), draws from the normalised likelihood (``profile``),
        the refits that could be fitted (``bootstrap``).
    requested : int
        Replicates asked for.
    seed : int
        The root seed.
    method : str
        ``posterior``, ``profile`` or ``bootstrap`` (:data:`INTERVALS`).
    draws : dict of ndarray
        The parameter draws behind a ``posterior`` or ``bootstrap`` interval (and the ``rate``).
    grid : regimemap.climate.intervals.Grid or None
        The likelihood grid (``posterior``, ``profile``).
    distribution, threshold : str or None, float or None
        The fit's distribution and threshold (the draws' return values).
    """

    fits: list[Fit] = field(repr=False)
    requested: int
    seed: int
    method: str = "bootstrap"
    draws: dict[str, FloatArray] = field(default_factory=dict, repr=False)
    grid: Any = field(default=None, repr=False)
    distribution: str | None = None
    threshold: float | None = None

    @property
    def failed(self) -> int:
        """Replicates that had too few values to fit (bootstrap; 0 for the other methods)."""
        return self.requested - len(self.fits) if self.method == "bootstrap" else 0

    def return_values(self, years: float) -> FloatArray:
        """Each draw's ``R``-year value (NaN where ``lambda R <= 1``)."""
        if self.draws:
            params = {k: v for k, v in self.draws.items() if k != "rate"}
            assert self.distribution is not None
            return return_levels(self.distribution, params, self.threshold, self.draws["rate"], years)
        if not self.fits:
            return np.zeros(0)
        first = self.fits[0]
        params = {k: np.array([f.parameters[k] for f in self.fits]) for k in first.parameters}
        rates = np.array([f.rate for f in self.fits])
        return return_levels(first.distribution, params, first.threshold, rates, years)

    def interval(self, years: float, confidence: float) -> tuple[float, float]:
        """The ``confidence`` interval of the ``R``-year value: equal-tailed quantiles of the draws
        (``posterior``, ``bootstrap``) or the profile-likelihood interval (``profile``)."""
        if self.method == "profile":
            from .intervals import profile_interval

            assert self.grid is not None
            return profile_interval(self.grid, years, confidence)
        v = self.return_values(years)
        v = v[np.isfinite(v)]
        if v.size == 0:
            return math.nan, math.nan
        a = 0.5 * (1.0 - confidence)
        lo, hi = np.quantile(v, [a, 1.0 - a])
        return float(lo), float(hi)

    def label(self, confidence: float) -> str:
        """``90 % posterior interval`` (the figures' and the report's name of the band)."""
        name = {"posterior": "posterior interval", "profile": "profile-likelihood interval",
                "bootstrap": "bootstrap interval"}[self.method]
        return f"{100 * confidence:g} % {name}"



def bootstrap(values: ArrayLike, estimate: Fit, n: int, seed: int, years: float | None = None,
              shape: float = 2.0) -> Band:
    """Non-parametric bootstrap of a fit (the module's docstring says why and how).

    Parameters
    ----------
    values : array_like
        The values fitted.
    estimate : Fit
        The fit of ``values`` (its distribution, threshold; the start of every refit).
    n : int
        Replicates (>= 1).
    seed : int
        Root seed: replicate ``i`` draws from ``SeedSequence(seed).spawn(n)[i]``.
    years : float, optional
        Record length: for peaks over a threshold each replicate's rate is its count / ``years``.
    shape : float, optional
        Weibull ``k``.

    Returns
    -------
    Band
    """
    x = np.asarray(values, dtype=np.float64).ravel()
    pot = estimate.distribution in POT_DISTRIBUTIONS
    fits = []
    for child in np.random.SeedSequence(seed).spawn(n):
        rng = np.random.Generator(np.random.PCG64(child))
        m = int(rng.poisson(x.size)) if pot else x.size
        sample = x[rng.integers(0, x.size, m)]
        rate = m / years if (pot and years) else estimate.rate
        try:
            fits.append(fit(sample, estimate.distribution, estimate.threshold, rate, shape,
                            start=estimate.parameters))
        except ValueError:
            continue
    return Band(fits=fits, requested=n, seed=seed)


def return_values(estimate: Fit, band: Band | None, periods: list[float],
                  confidence: float) -> list[dict[str, float | None]]:
    """``[{period, value, lower, upper}]`` for each return period (bounds None without a band)."""
    out: list[dict[str, float | None]] = []
    for R in periods:
        lo, hi = band.interval(R, confidence) if band is not None else (None, None)
        out.append({"period": float(R), "value": estimate.return_value(R), "lower": lo, "upper": hi})
    return out
