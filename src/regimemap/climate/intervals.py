"""Return-value intervals: a grid posterior, the profile likelihood, the non-parametric bootstrap.

numpy and scipy.  Three ways to say how uncertain a record's ``R``-year value is; every one
includes the uncertainty of the storm rate (how many storms ten years hold is itself uncertain).

``posterior``
    The default: its coverage is the nearest to nominal, measured on records of known truth
    (docs/guide/calibration.md).
    A Bayesian posterior computed on a grid, exact to the grid's resolution (no Markov chain).
    The prior is flat in the location, the logarithm of the scale and the shape:
    :math:`\\pi(\\sigma, \\xi) \\propto 1/\\sigma` with :math:`\\xi` uniform on
    :data:`XI_PRIOR` (the "flat" prior of revdbayes, ``gp_flat``; a lower bound on :math:`\\xi`
    is what makes the posterior proper, Northrop & Attalides 2016, Statistica Sinica 26,
    721-743).  Peaks over a threshold are a Poisson process: the rate has Jeffreys' prior
    :math:`\\pi(\\lambda) \\propto \\lambda^{-1/2}`, so that with :math:`N` storms in :math:`T`
    years :math:`\\lambda \\mid N \\sim \\mathrm{Gamma}(N + 1/2, \\text{rate} = T)`, independent of
    the peaks' parameters.  The interval is the equal-tailed quantiles of :math:`H_R` over the
    posterior draws, and the replicate fits (:attr:`Band.fits`) are the first of those draws.
``profile``
    The profile-likelihood interval (Coles 2001, Sect. 2.6.5 and 4.3.3): the values of
    :math:`H_R` inside the joint likelihood region
    :math:`\\{\\ell(\\lambda, \\theta) \\ge \\hat\\ell - \\chi^2_{1}(c)/2\\}` of the Poisson count
    and the peaks -- the image of that region under :math:`H_R`, which is the set where
    :math:`H_R`'s profile likelihood is above the cut.  The rate is profiled with the peaks'
    parameters: at each parameter point the rate spans the interval its own Poisson likelihood
    leaves inside the cut.  Its replicate fits are draws from the likelihood normalised over the
    same grid (the posterior's, as the prior is flat in the grid's coordinates).
``bootstrap``
    The non-parametric percentile bootstrap (:func:`bootstrap`): honest
    about what it is, and known to cover less than it claims on short records (it cannot resample
    a storm larger than the record's largest).

The grid: the coordinates are the location, the logarithm of the scale and the shape (GPD:
``ln sigma``, ``xi``; Weibull with ``k`` fixed: ``ln A``; Gumbel: ``B``, ``ln A``; GEV: ``mu``,
``ln sigma``, ``xi``), in which the prior is flat.  A coarse grid around the maximum-likelihood
fit is widened until the log-likelihood has fallen :data:`DROP` below its maximum at every open
edge, then a fine grid covers the box where it has not.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import stats

from .fits import AM_DISTRIBUTIONS, GEV_XI, POT_DISTRIBUTIONS, Fit, fit, return_levels

__all__ = ["DEFAULT_INTERVAL", "INTERVALS", "POSTERIOR_DRAWS", "XI_PRIOR", "Band", "Grid", "bootstrap",
           "bootstrap_minimum", "grid_quantiles", "interval_band", "likelihood_grid", "profile_interval",
           "return_values"]

FloatArray = NDArray[np.float64]

#: The interval methods (``ClimateOptions.interval``, ``climate --interval``).
INTERVALS = ("posterior", "profile", "bootstrap")
#: The default, chosen by measured coverage.
DEFAULT_INTERVAL = "posterior"
#: The GPD shape's prior range (uniform; the likelihood is unbounded below -1).
XI_PRIOR = (-1.0, 1.5)
#: Posterior draws behind an interval (at least; the replicate fits are the first of them).
POSTERIOR_DRAWS = 20_000
#: Replicates in each tail beyond a percentile bootstrap interval, at least (:func:`bootstrap_minimum`).
TAIL_REPLICATES = 2


def bootstrap_minimum(confidence: float) -> int:
    """The fewest bootstrap replicates for a ``confidence`` percentile interval: each tail beyond it,
    a share (1 - confidence)/2 of them, holds at least :data:`TAIL_REPLICATES` (two: a bound is
    then not one replicate's value), so 4/(1 - confidence): 40 at 0.9, 400 at 0.99.

    Examples
    --------
    >>> bootstrap_minimum(0.9), bootstrap_minimum(0.95), bootstrap_minimum(0.999)
    (40, 80, 4000)
    """
    return math.ceil(round(2 * TAIL_REPLICATES / (1.0 - confidence), 6))


#: Log-likelihood drop [nepers] below its maximum that bounds the grid (e^-16: nothing left).
DROP = 16.0
#: Points per axis of the coarse and of the fine grid, by number of parameters.
_COARSE = {1: 81, 2: 41, 3: 17}
_FINE = {1: 801, 2: 161, 3: 41}


@dataclass(frozen=True)
class Grid:
    """The likelihood of a fit's parameters on a grid (flat-prior coordinates).

    Attributes
    ----------
    distribution : str
    threshold : float or None
    parameters : dict of ndarray
        The parameters at each grid point (``sigma``, ``xi``, ... as in :class:`Fit`).
    loglik : ndarray
        The log-likelihood there, relative to its maximum (<= 0; -inf outside the support).
    cell : ndarray
        The grid step of each coordinate.
    coordinates : ndarray
        The grid points in the flat-prior coordinates, one row per point.
    names : tuple of str
        The coordinates' names (``ln_sigma``, ``xi``, ...).
    low, high : ndarray
        The coordinates' hard bounds (``-inf``/``inf`` where open).
    count : int
        ``N``, storms (peaks over a threshold) or annual maxima.
    years : float or None
        ``T``, the record's years (peaks over a threshold; None for annual maxima: rate 1).
    """

    distribution: str
    threshold: float | None
    parameters: dict[str, FloatArray] = field(repr=False)
    loglik: FloatArray = field(repr=False)
    cell: FloatArray
    coordinates: FloatArray = field(repr=False)
    names: tuple[str, ...]
    low: FloatArray
    high: FloatArray
    count: int
    years: float | None


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
    grid : Grid or None
        The likelihood grid (``posterior``, ``profile``).
    distribution, threshold : str or None, float or None
        The fit's distribution and threshold (the draws' return values).
    """

    fits: list[Fit] = field(repr=False)
    requested: int
    seed: int
    method: str = "bootstrap"
    draws: dict[str, FloatArray] = field(default_factory=dict, repr=False)
    grid: Grid | None = field(default=None, repr=False)
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
    """Non-parametric bootstrap of a fit: each replicate resamples the values with replacement --
    their number drawn from a Poisson distribution with the observed count as its mean for peaks
    over a threshold (the storms of a record are a Poisson process, and ``lambda = N/years`` varies
    with their number), the number of years fixed for annual maxima -- and refits (Efron &
    Tibshirani 1993, Ch. 13, percentile intervals).

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


def _parameters(distribution: str, c: FloatArray, shape: float) -> dict[str, FloatArray]:
    """The parameters of :class:`Fit` from the coordinates ``c`` (one row per point)."""
    if distribution == "gpd":
        return {"sigma": np.exp(c[:, 0]), "xi": c[:, 1]}
    if distribution == "weibull":
        return {"A": np.exp(c[:, 0]), "k": np.full(c.shape[0], float(shape))}
    if distribution == "gumbel":
        return {"A": np.exp(c[:, 1]), "B": c[:, 0]}
    return {"mu": c[:, 0], "sigma": np.exp(c[:, 1]), "xi": c[:, 2]}


def _coordinates(estimate: Fit) -> tuple[tuple[str, ...], FloatArray, FloatArray, FloatArray]:
    """Names, the fit's point, and the hard lower and upper bounds of the coordinates."""
    p, inf = estimate.parameters, math.inf
    if estimate.distribution == "gpd":
        return (("ln_sigma", "xi"), np.array([math.log(p["sigma"]), p["xi"]]),
                np.array([-inf, XI_PRIOR[0]]), np.array([inf, XI_PRIOR[1]]))
    if estimate.distribution == "weibull":
        return ("ln_A",), np.array([math.log(p["A"])]), np.array([-inf]), np.array([inf])
    if estimate.distribution == "gumbel":
        return (("B", "ln_A"), np.array([p["B"], math.log(p["A"])]), np.array([-inf, -inf]),
                np.array([inf, inf]))
    return (("mu", "ln_sigma", "xi"), np.array([p["mu"], math.log(p["sigma"]), p["xi"]]),
            np.array([-inf, -inf, GEV_XI[0]]), np.array([inf, inf, GEV_XI[1]]))


def _loglik(distribution: str, x: FloatArray, threshold: float | None, c: FloatArray,
            shape: float) -> FloatArray:
    """Log-likelihood of the values ``x`` at each row of coordinates ``c`` (-inf outside the support),
    in chunks of points."""
    out = np.empty(c.shape[0])
    step = max(1, 2_000_000 // max(x.size, 1))
    for a in range(0, c.shape[0], step):
        out[a:a + step] = _loglik_chunk(distribution, x, threshold, c[a:a + step], shape)
    return out


def _loglik_chunk(distribution: str, x: FloatArray, threshold: float | None, c: FloatArray,
                  shape: float) -> FloatArray:
    n = x.size
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        if distribution in ("gpd", "weibull"):
            assert threshold is not None
            y = x - threshold
            if distribution == "weibull":
                k, ln_a = float(shape), c[:, 0]
                z = y[None, :] / np.exp(ln_a)[:, None]
                return np.asarray(n * math.log(k) - n * k * ln_a + (k - 1.0) * float(np.sum(np.log(y)))
                                  - np.sum(z ** k, axis=1), dtype=np.float64)
            ln_s, xi = c[:, 0], c[:, 1]
            sigma = np.exp(ln_s)
            t = 1.0 + (xi / sigma)[:, None] * y[None, :]
            ok = np.all(t > 0.0, axis=1)
            small = np.abs(xi) < 1e-9
            lt = np.log(np.where(t > 0.0, t, 1.0))
            safe = np.where(small, 1.0, xi)
            ll = np.where(small, -n * ln_s - float(y.sum()) / sigma,
                          -n * ln_s - (1.0 + 1.0 / safe) * np.sum(lt, axis=1))
            return np.where(ok, ll, -np.inf)
        if distribution == "gumbel":
            b, ln_a = c[:, 0], c[:, 1]
            z = (x[None, :] - b[:, None]) / np.exp(ln_a)[:, None]
            return np.asarray(-n * ln_a - np.sum(z, axis=1) - np.sum(np.exp(-z), axis=1), dtype=np.float64)
        mu, ln_s, xi = c[:, 0], c[:, 1], c[:, 2]
        z = (x[None, :] - mu[:, None]) / np.exp(ln_s)[:, None]
        t = 1.0 + xi[:, None] * z
        ok = np.all(t > 0.0, axis=1)
        small = np.abs(xi) < 1e-9
        safe = np.where(small, 1.0, xi)
        lt = np.log(np.where(t > 0.0, t, 1.0))
        gen = (-n * ln_s - (1.0 + 1.0 / safe) * np.sum(lt, axis=1)
               - np.sum(np.exp(-lt / safe[:, None]), axis=1))
        gum = -n * ln_s - np.sum(z, axis=1) - np.sum(np.exp(-z), axis=1)
        return np.where(ok, np.where(small, gum, gen), -np.inf)


def _mesh(lo: FloatArray, hi: FloatArray, points: int) -> tuple[FloatArray, FloatArray]:
    axes = [np.linspace(a, b, points) for a, b in zip(lo, hi)]
    mesh = np.meshgrid(*axes, indexing="ij")
    cell = np.array([(b - a) / (points - 1) for a, b in zip(lo, hi)])
    return np.stack([m.ravel() for m in mesh], axis=1), cell


def likelihood_grid(values: ArrayLike, estimate: Fit, years: float | None = None,
                    shape: float = 2.0) -> Grid:
    """The fit's log-likelihood on a grid covering all but ``e^-DROP`` of it (the module says how).

    Parameters
    ----------
    values : array_like
        The values fitted.
    estimate : Fit
        Their maximum-likelihood fit (the grid's first centre).
    years : float, optional
        The record's years (peaks over a threshold: the rate's Poisson likelihood).
    shape : float, optional
        Weibull ``k``.

    Returns
    -------
    Grid
    """
    x = np.asarray(values, dtype=np.float64).ravel()
    d = estimate.distribution
    names, centre, low, high = _coordinates(estimate)
    dim = centre.size
    # first half-widths: a few standard errors (scale ~ 1/sqrt(n) in ln, shape ~ 1/sqrt(n),
    # location ~ scale/sqrt(n))
    n = max(x.size, 1)
    scale = float(np.exp(centre[names.index("ln_sigma")] if "ln_sigma" in names else
                         centre[names.index("ln_A")]))
    half = np.array([5.0 * scale / math.sqrt(n) if nm in ("mu", "B") else 6.0 / math.sqrt(n) for nm in names])
    lo = np.maximum(centre - half, low)
    hi = np.minimum(centre + half, high)
    for _ in range(12):
        pts, _cell = _mesh(lo, hi, _COARSE[dim])
        ll = _loglik(d, x, estimate.threshold, pts, shape)
        top = float(np.max(ll))
        keep = ll > top - DROP
        grown = False
        for j in range(dim):
            inside = pts[keep, j]
            width = hi[j] - lo[j]
            if inside.min() <= lo[j] + 1e-12 * max(1.0, abs(lo[j])) and lo[j] > low[j]:
                lo[j] = max(lo[j] - width, low[j])
                grown = True
            if inside.max() >= hi[j] - 1e-12 * max(1.0, abs(hi[j])) and hi[j] < high[j]:
                hi[j] = min(hi[j] + width, high[j])
                grown = True
        if not grown:
            break
    # the fine grid: the box of what is kept, one coarse cell wider (inside the hard bounds)
    pts, cell = _mesh(lo, hi, _COARSE[dim])
    inside = pts[keep]
    flo = np.maximum(inside.min(axis=0) - cell, low)
    fhi = np.minimum(inside.max(axis=0) + cell, high)
    fhi = np.where(fhi > flo, fhi, flo + cell)
    pts, cell = _mesh(flo, fhi, _FINE[dim])
    ll = _loglik(d, x, estimate.threshold, pts, shape)
    best = _loglik(d, x, estimate.threshold, centre[None, :], shape)[0]
    top = max(float(np.max(ll)), float(best))
    return Grid(distribution=d, threshold=estimate.threshold, parameters=_parameters(d, pts, shape),
                loglik=ll - top, cell=cell, coordinates=pts, names=names, low=low, high=high,
                count=int(x.size), years=None if d in AM_DISTRIBUTIONS else years)


def _rate_bounds(count: int, slack: FloatArray) -> tuple[FloatArray, FloatArray]:
    """``lambda/lambda_hat`` where the Poisson log-likelihood of ``count`` storms has fallen by
    ``slack``: ``N (r - 1 - ln r) = slack``, below and above 1 (NaN where ``slack < 0``)."""
    n = float(count)
    r_lo = np.concatenate([np.geomspace(1e-6, 0.5, 400), np.linspace(0.5, 1.0, 400)[1:]])
    r_hi = np.concatenate([np.linspace(1.0, 2.0, 400), np.geomspace(2.0, 1e3, 400)[1:]])
    g_lo = n * (r_lo - 1.0 - np.log(r_lo))
    g_hi = n * (r_hi - 1.0 - np.log(r_hi))
    s = np.where(slack >= 0.0, slack, np.nan)
    lo = np.interp(s, g_lo[::-1], r_lo[::-1])
    hi = np.interp(s, g_hi, r_hi)
    return np.where(np.isfinite(s), lo, np.nan), np.where(np.isfinite(s), hi, np.nan)


def profile_interval(grid: Grid, years: float, confidence: float) -> tuple[float, float]:
    """The profile-likelihood interval of ``H_R`` (the module says how the rate is profiled)."""
    cut = 0.5 * float(stats.chi2.ppf(confidence, 1))
    slack = cut + grid.loglik
    ok = slack >= 0.0
    params = {k: v[ok] for k, v in grid.parameters.items()}
    if grid.years is None:
        h = return_levels(grid.distribution, params, grid.threshold, np.ones(int(ok.sum())), years)
        h = h[np.isfinite(h)]
        return (float(h.min()), float(h.max())) if h.size else (math.nan, math.nan)
    rate = grid.count / grid.years
    r_lo, r_hi = _rate_bounds(grid.count, slack[ok])
    low = return_levels(grid.distribution, params, grid.threshold, rate * r_lo, years)
    high = return_levels(grid.distribution, params, grid.threshold, rate * r_hi, years)
    low, high = low[np.isfinite(low)], high[np.isfinite(high)]
    if low.size == 0 or high.size == 0:
        return math.nan, math.nan
    return float(low.min()), float(high.max())


def grid_quantiles(grid: Grid, values: FloatArray, probabilities: ArrayLike) -> FloatArray:
    """Posterior quantiles of ``values`` (one per grid point, e.g. ``xi`` or ``sigma - xi u``) with
    the grid's normalised likelihood as weights (the cells' jitter ignored: to a cell's width)."""
    w = np.exp(grid.loglik - np.max(grid.loglik))
    order = np.argsort(values, kind="stable")
    cum = np.cumsum(w[order])
    cum /= cum[-1]
    at = np.searchsorted(cum, np.asarray(probabilities, dtype=np.float64), side="left")
    return np.asarray(values[order][np.minimum(at, values.size - 1)], dtype=np.float64)


def _draw(grid: Grid, n: int, rng: np.random.Generator) -> tuple[dict[str, FloatArray], FloatArray]:
    """``n`` draws from the grid's normalised likelihood (a cell by its weight, then uniform in it;
    flat prior in the coordinates) and the rates from their Gamma posterior."""
    w = np.exp(grid.loglik - np.max(grid.loglik))
    w /= w.sum()
    cells = rng.choice(w.size, size=n, p=w)
    jitter = (rng.random((n, grid.coordinates.shape[1])) - 0.5) * grid.cell
    c = np.clip(grid.coordinates[cells] + jitter, grid.low, grid.high)
    k = float(grid.parameters["k"][0]) if "k" in grid.parameters else 2.0
    params = _parameters(grid.distribution, c, k)
    if grid.years is None:
        rate = np.ones(n)
    else:
        rate = rng.gamma(grid.count + 0.5, 1.0 / grid.years, size=n)
    return params, rate


def interval_band(values: ArrayLike, estimate: Fit, method: str, n: int, seed: int,
                  years: float | None = None, shape: float = 2.0) -> Band:
    """The band of a fit by ``method`` (:data:`INTERVALS`) with ``n`` replicate fits.

    Parameters
    ----------
    values : array_like
        The values fitted.
    estimate : Fit
        Their fit.
    method : str
        ``posterior``, ``profile`` or ``bootstrap``.
    n : int
        Replicate fits (>= 1).
    seed : int
        Root seed: the draws come from ``SeedSequence(seed).spawn(1)[0]`` (``bootstrap``: replicate
        ``i`` from ``spawn(n)[i]``), the same for the same seed.
    years : float, optional
        The record's years (peaks over a threshold).
    shape : float, optional
        Weibull ``k``.

    Returns
    -------
    Band
    """
    if method not in INTERVALS:
        raise ValueError(f"interval must be one of {', '.join(INTERVALS)}, got {method!r}")
    if method == "bootstrap":
        return bootstrap(values, estimate, n, seed, years, shape)
    grid = likelihood_grid(values, estimate, years, shape)
    rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(seed).spawn(1)[0]))
    params, rate = _draw(grid, max(n, POSTERIOR_DRAWS), rng)
    fits = [Fit(estimate.distribution, {k: float(v[i]) for k, v in params.items()}, estimate.threshold,
                float(rate[i]), estimate.n) for i in range(n)]
    return Band(fits=fits, requested=n, seed=seed, method=method, draws={**params, "rate": rate}, grid=grid,
                distribution=estimate.distribution, threshold=estimate.threshold)
