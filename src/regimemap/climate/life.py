"""A record's fit as the lifetime's climate, the climate of observed annual maxima, and the interval's
replicate fits as replicate climates.

numpy; builds :class:`regimemap.lifetime.Climate` objects (this package may import
:mod:`regimemap.lifetime`, never the reverse).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..lifetime.climate import DISTRIBUTIONS, Climate
from .analysis import ClimateResult
from .fits import Fit, fit_gumbel, fit_weibull
from .peaks import Storms

__all__ = ["MIN_PERIODS", "climate_of", "climate_of_maxima", "period_law", "replicate_climates"]

#: Fewest storm peaks with a period for :func:`period_law`.
MIN_PERIODS = 5


def climate_of(fit: Fit) -> Climate:
    """The lifetime's :class:`~regimemap.lifetime.Climate` of a fit.

    Storm peaks (``gpd``, ``weibull``) are a Poisson number of storms a year, ``lambda`` =
    the fit's rate, with their location at the threshold; annual maxima (``gumbel``, ``gev``)
    one storm a year whose peak is the annual maximum.

    Examples
    --------
    >>> from regimemap.climate.fits import Fit
    >>> c = climate_of(Fit("gpd", {"sigma": 1.3, "xi": -0.3}, threshold=4.0, rate=6.0, n=60))
    >>> round(c.return_value(50), 6) == round(Fit("gpd", {"sigma": 1.3, "xi": -0.3}, 4.0, 6.0, 60)
    ...                                         .return_value(50), 6)
    True
    """
    p = fit.parameters
    if fit.distribution == "gpd":
        assert fit.threshold is not None
        return Climate("gpd", scale=p["sigma"], location=fit.threshold, shape=p["xi"],
                       storms_per_year=fit.rate)
    if fit.distribution == "weibull":
        assert fit.threshold is not None
        return Climate("weibull", scale=p["A"], location=fit.threshold, shape=p["k"],
                       storms_per_year=fit.rate)
    if fit.distribution == "gumbel":
        return Climate("gumbel", scale=p["A"], location=p["B"])
    return Climate("gev", scale=p["sigma"], location=p["mu"], shape=p["xi"])


def climate_of_maxima(maxima: ArrayLike, distribution: str = "weibull", shape: float = 2.0) -> Climate:
    """The lifetime's :class:`~regimemap.lifetime.Climate` of observed annual maxima (one storm a
    year), by maximum likelihood (:func:`~regimemap.climate.fits.fit_gumbel`,
    :func:`~regimemap.climate.fits.fit_weibull` with its location fitted).

    Parameters
    ----------
    maxima : array_like
        At least three annual maxima of ``H0'`` [m], not all equal.
    distribution : str, optional
        ``"weibull"``: ``A`` and ``B`` for the given ``shape`` (> 1, where the likelihood has an
        interior maximum); ``"gumbel"``: ``A`` and ``B``.
    shape : float, optional
        Weibull shape ``k`` (default 2).

    Returns
    -------
    Climate

    Raises
    ------
    ValueError
        Fewer than three finite values, all equal, an unknown distribution or ``k <= 1``.
    """
    x = np.sort(np.asarray(maxima, dtype=np.float64).ravel())
    if x.size < 3 or not np.all(np.isfinite(x)):
        raise ValueError("annual maxima: need at least three finite values")
    if not float(x[-1] - x[0]) > 0.0:
        raise ValueError("annual maxima: the values are all equal")
    if distribution == "gumbel":
        A, B = fit_gumbel(x)
        return Climate(distribution="gumbel", scale=A, location=B, shape=shape)
    if distribution != "weibull":
        raise ValueError(f"distribution must be one of {', '.join(DISTRIBUTIONS)}")
    if not shape > 1.0:
        raise ValueError(f"fitting annual maxima needs a Weibull shape k > 1 (got {shape!r}): "
                         "for k <= 1 the likelihood grows without bound as B nears the "
                         "smallest value; give H0_10 and H0_50 instead")
    A, B = fit_weibull(x, shape)
    return Climate(distribution="weibull", scale=A, location=B, shape=shape)


def replicate_climates(result: ClimateResult) -> list[Climate]:
    """The climates of the band's replicate fits, in replicate order (each with its own storm rate):
    posterior draws under the default interval (:mod:`regimemap.climate.intervals`), so that the
    ESD's climate band carries the same uncertainty as the return values' interval."""
    if result.band is None:
        return []
    return [climate_of(f) for f in result.band.fits]


def period_law(storms: Storms) -> tuple[float, float] | None:
    """``(a, b)`` of ``T = a H^b`` fitted to the storm peaks and the periods at them (least squares of
    ``ln T`` on ``ln H``); None without periods or with fewer than :data:`MIN_PERIODS` of them.

    Examples
    --------
    >>> t = np.datetime64("2000-01-01", "s") + np.arange(6) * np.timedelta64(99 * 3600, "s")
    >>> h = np.array([4.0, 5.0, 6.0, 7.0, 4.5, 5.5])
    >>> s = Storms(3.0, 48.0, h, t, 3.3 * h**0.63, np.ones(6), 1.0)
    >>> tuple(round(v, 9) for v in period_law(s))
    (3.3, 0.63)
    """
    if storms.period is None:
        return None
    ok = np.isfinite(storms.period) & (storms.peak > 0.0)
    if np.count_nonzero(ok) < MIN_PERIODS:
        return None
    b, ln_a = np.polyfit(np.log(storms.peak[ok]), np.log(storms.period[ok]), 1)
    return float(np.exp(ln_a)), float(b)
