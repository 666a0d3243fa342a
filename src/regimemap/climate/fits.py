"""Extreme-value fits of storm peaks and annual maxima, by maximum likelihood.

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

The intervals of the return values (the grid posterior, the profile likelihood, the bootstrap)
are in :mod:`regimemap.climate.intervals`.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize, stats

__all__ = ["AM_DISTRIBUTIONS", "GEV_XI", "MIN_MAXIMA", "MIN_PEAKS", "POT_DISTRIBUTIONS", "Fit", "fit",
           "fit_gumbel", "fit_weibull", "return_levels"]

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


def fit_gumbel(x: FloatArray) -> tuple[float, float]:
    """Gumbel maximum likelihood (``scipy.stats.gumbel_r.fit``).

    Parameters
    ----------
    x : ndarray
        The annual maxima [m].

    Returns
    -------
    tuple of float
        ``(A, B)``: the scale and the location [m].
    """
    B, A = stats.gumbel_r.fit(x)
    return float(A), float(B)


def _weibull_profile(x: FloatArray, k: float, B: float) -> float:
    d = x - B
    return float(-x.size * math.log(float(np.mean(d**k))) + (k - 1.0) * float(np.log(d).sum()))


def fit_weibull(x: FloatArray, k: float, location: float | None = None) -> tuple[float, float]:
    """Weibull maximum likelihood with the shape ``k`` given.

    For a location ``B`` the likelihood's maximum is in closed form, ``A^k = mean((x - B)^k)``
    (``scipy.stats.weibull_min.fit(x, fc=k, floc=B)`` finds it numerically).  Without
    ``location``, ``B`` maximises the profile log-likelihood
    ``-n ln mean((x - B)^k) + (k - 1) sum ln(x - B)`` over ``B < min(x)`` (``k > 1``, where it
    has an interior maximum): on a grid, then Brent's bounded search
    (``scipy.optimize.minimize_scalar``) around its best point.

    Parameters
    ----------
    x : ndarray
        The values [m], not all equal (all above ``location``).
    k : float
        The shape.
    location : float, optional
        ``B`` [m] (the threshold of storm peaks); None: fitted.

    Returns
    -------
    tuple of float
        ``(A, B)``: the scale and the location [m].
    """
    if location is None:
        x0 = float(x.min())
        spread = float(x.max()) - x0
        # B = x0 - exp(t): t from a millionth of the spread to a hundred spreads below the minimum
        ts = np.linspace(math.log(1e-6 * spread), math.log(100.0 * spread), 400)
        vals = [_weibull_profile(x, k, x0 - math.exp(t)) for t in ts]
        i = int(np.argmax(vals))
        lo, hi = float(ts[max(i - 1, 0)]), float(ts[min(i + 1, ts.size - 1)])
        best = optimize.minimize_scalar(lambda t: -_weibull_profile(x, k, x0 - math.exp(t)),
                                        bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
        location = x0 - math.exp(float(best.x) if -best.fun >= vals[i] else float(ts[i]))
    return float(np.mean((x - location) ** k)) ** (1.0 / k), location


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
    scale, loc = fit_gumbel(x)
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
            return {"A": fit_weibull(x, shape, threshold)[0], "k": float(shape)}
        if distribution == "gumbel":
            A, B = fit_gumbel(x)
            return {"A": A, "B": B}
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
