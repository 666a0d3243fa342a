"""The wave climate of a site: the distribution of storm peaks ``H0'``, fitted or given.

numpy (the fits are :mod:`regimemap.climate`'s: annual maxima by
:func:`regimemap.climate.life.climate_of_maxima`).  A storm's peak equivalent deep-water
significant height follows a Weibull distribution

    F(H) = 1 - exp(-((H - B)/A)^k),   H >= B,

or a Gumbel (Fisher-Tippett type I) distribution

    F(H) = exp(-exp(-(H - B)/A)),

with scale ``A``, location ``B`` and (Weibull) shape ``k``.  With one storm a
year (the default) ``F`` is the distribution of the annual maxima and the
``R``-year return value solves ``F(H_R) = 1 - 1/R``; with ``storms_per_year =
lambda`` the storms are a Poisson process and ``F`` is a peaks-over-threshold
distribution, ``F(H_R) = 1 - 1/(lambda R)`` (Goda 2000, Ch. 11), so that for
Weibull :math:`H_R = B + A (\\ln \\lambda R)^{1/k}`.  See docs/lifetime.md, Sect. 2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["DISTRIBUTIONS", "FITTED_DISTRIBUTIONS", "WEIBULL_SHAPE_RANGE", "Climate"]

FloatArray = NDArray[np.float64]

#: The storm-peak distributions of two return values or of annual maxima (the design file's).
DISTRIBUTIONS: tuple[str, ...] = ("weibull", "gumbel")
#: The Weibull shape k a storm climate may take, fixed or given: Goda's storm peaks take
#: 0.75 to 2 (Goda 2000, Sect. 11.2); far outside, the return values of H0_10 and H0_50
#: overflow or the climate is one height for every storm.
WEIBULL_SHAPE_RANGE: tuple[float, float] = (0.5, 5.0)
#: The distributions a record's fit gives too (:mod:`regimemap.climate`): the generalised Pareto
#: of storm peaks over the threshold ``B`` and the generalised extreme value of annual maxima;
#: for both ``shape`` is ``xi`` (any sign).
FITTED_DISTRIBUTIONS: tuple[str, ...] = ("gpd", "gev")


def _reduced(distribution: str, shape: float, p_exceed: float) -> float:
    """Reduced variate ``y = (H - B)/A`` of the non-exceedance ``1 - p_exceed``."""
    if distribution == "weibull":
        return float((-math.log(p_exceed)) ** (1.0 / shape))
    return float(-math.log(-math.log1p(-p_exceed)))


@dataclass(frozen=True)
class Climate:
    """Distribution of the storm peaks ``H0'`` at a site.

    Attributes
    ----------
    distribution : str
        ``"weibull"`` or ``"gumbel"``; ``"gpd"`` or ``"gev"`` from a record's fit.
    scale : float
        ``A`` [m], > 0.
    location : float
        ``B`` [m].
    shape : float
        Weibull ``k`` (> 0; unused by Gumbel); ``xi`` of ``gpd`` and ``gev``.
    storms_per_year : float or None
        ``lambda``: a Poisson number of storms a year with peaks from this
        distribution (peaks over a threshold); None: one storm a year whose
        peak is the annual maximum.

    Examples
    --------
    >>> c = Climate.from_return_values(5.0, 6.3)
    >>> round(c.return_value(10), 12), round(c.return_value(50), 12)
    (5.0, 6.3)
    """

    distribution: str
    scale: float
    location: float
    shape: float = 2.0
    storms_per_year: float | None = None

    def __post_init__(self) -> None:
        if self.distribution not in DISTRIBUTIONS + FITTED_DISTRIBUTIONS:
            known = ", ".join(DISTRIBUTIONS + FITTED_DISTRIBUTIONS)
            raise ValueError(f"distribution must be one of {known}, got {self.distribution!r}")
        if not (self.scale > 0.0 and math.isfinite(self.scale)):
            raise ValueError(f"scale A must be a finite number > 0, got {self.scale!r}")
        if not math.isfinite(self.location):
            raise ValueError(f"location B must be finite, got {self.location!r}")
        if self.distribution in FITTED_DISTRIBUTIONS:
            if not math.isfinite(self.shape):
                raise ValueError(f"shape xi must be finite, got {self.shape!r}")
        elif not self.shape > 0.0:
            raise ValueError(f"shape k must be > 0, got {self.shape!r}")
        if self.storms_per_year is not None and not self.storms_per_year > 0.0:
            raise ValueError(f"storms_per_year must be > 0, got {self.storms_per_year!r}")

    @property
    def rate(self) -> float:
        """Mean number of storms a year (1 for annual maxima)."""
        return 1.0 if self.storms_per_year is None else float(self.storms_per_year)

    @classmethod
    def from_return_values(cls, H0_10: float, H0_50: float, distribution: str = "weibull",
                           shape: float = 2.0, storms_per_year: float | None = None) -> Climate:
        """The distribution through two return values (10 and 50 years).

        Parameters
        ----------
        H0_10, H0_50 : float
            10- and 50-year return values of ``H0'`` [m], ``H0_50 > H0_10``.
        distribution : str, optional
            ``"weibull"`` (default) or ``"gumbel"``.
        shape : float, optional
            Weibull shape ``k`` (default 2).
        storms_per_year : float, optional
            ``lambda`` (None: annual maxima).

        Returns
        -------
        Climate
            ``A = (H0_50 - H0_10)/(y_50 - y_10)``, ``B = H0_10 - A y_10`` with
            the reduced variates ``y_R`` of ``F(H_R) = 1 - 1/(lambda R)``.
        """
        if not H0_50 > H0_10:
            raise ValueError(f"H0_50 = {H0_50!r} must exceed H0_10 = {H0_10!r}")
        lam = 1.0 if storms_per_year is None else float(storms_per_year)
        if distribution == "weibull" and not shape > 0.0:
            raise ValueError(f"shape k must be > 0, got {shape!r}")
        p10, p50 = 1.0 / (lam * 10.0), 1.0 / (lam * 50.0)
        if p10 >= 1.0:
            raise ValueError(f"storms_per_year = {lam!r} is too few for a 10-year return value "
                             "(need lambda * 10 > 1)")
        y10 = _reduced(distribution, shape, p10)
        y50 = _reduced(distribution, shape, p50)
        A = (H0_50 - H0_10) / (y50 - y10)
        return cls(distribution=distribution, scale=A, location=H0_10 - A * y10, shape=shape,
                   storms_per_year=storms_per_year)

    # -- the distribution ------------------------------------------------------------------------
    def cdf(self, H: ArrayLike) -> FloatArray:
        """``F(H)``, the non-exceedance probability of a storm peak."""
        y = (np.asarray(H, dtype=np.float64) - self.location) / self.scale
        if self.distribution in FITTED_DISTRIBUTIONS:
            return _fitted_cdf(self.distribution, self.shape, y)
        if self.distribution == "weibull":
            return np.asarray(-np.expm1(-np.maximum(y, 0.0) ** self.shape), dtype=np.float64)
        return np.asarray(np.exp(-np.exp(-y)), dtype=np.float64)

    def quantile(self, u: ArrayLike) -> FloatArray:
        """Storm peaks from uniforms: ``F^-1(u)`` [m]."""
        uu = np.asarray(u, dtype=np.float64)
        with np.errstate(divide="ignore"):
            if self.distribution in FITTED_DISTRIBUTIONS:
                y = _fitted_reduced(self.distribution, self.shape, 1.0 - uu)
            elif self.distribution == "weibull":
                y = (-np.log1p(-uu)) ** (1.0 / self.shape)
            else:
                y = -np.log(-np.log(uu))
        return np.asarray(self.location + self.scale * y, dtype=np.float64)

    def return_value(self, years: float) -> float:
        """The ``R``-year return value ``H_R`` [m]: ``F(H_R) = 1 - 1/(lambda R)``."""
        p = 1.0 / (self.rate * float(years))
        if not 0.0 < p < 1.0:
            raise ValueError(f"no {years!r}-year return value with {self.rate!r} storms a year")
        if self.distribution in FITTED_DISTRIBUTIONS:
            return float(self.location + self.scale * _fitted_reduced(self.distribution, self.shape,
                                                                      np.array(p)))
        return self.location + self.scale * _reduced(self.distribution, self.shape, p)

    def describe(self) -> str:
        """One line: the distribution, its parameters and its 10/50-year values."""
        k = (f", k = {self.shape:g}" if self.distribution == "weibull" else
             f", xi = {self.shape:.4g}" if self.distribution in FITTED_DISTRIBUTIONS else "")
        storms = ("one storm a year" if self.storms_per_year is None
                  else f"{self.storms_per_year:g} storms a year (Poisson)")
        name = self.distribution.upper() if self.distribution in FITTED_DISTRIBUTIONS else \
            self.distribution.capitalize()
        return (f"{name} A = {self.scale:.4g} m, B = {self.location:.4g} m{k}; "
                f"{storms}; H0'_10 = {self.return_value(10):.3f} m, "
                f"H0'_50 = {self.return_value(50):.3f} m")


def _fitted_reduced(distribution: str, xi: float, p_exceed: FloatArray) -> FloatArray:
    """``y = (H - B)/A`` exceeded with probability ``p_exceed``: generalised Pareto
    ``((p^-xi) - 1)/xi`` (``-ln p`` at ``xi = 0``), generalised extreme value
    ``((-ln(1 - p))^-xi - 1)/xi`` (``-ln(-ln(1 - p))`` at ``xi = 0``)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -np.log(p_exceed) if distribution == "gpd" else -np.log(-np.log1p(-p_exceed))
        if abs(xi) < 1e-12:
            return np.asarray(t, dtype=np.float64)
        return np.asarray(np.expm1(xi * t) / xi, dtype=np.float64)


def _fitted_cdf(distribution: str, xi: float, y: FloatArray) -> FloatArray:
    """``F`` of the reduced variate ``y`` of :func:`_fitted_reduced` (0 below, 1 above the support)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if abs(xi) < 1e-12:
            t = y
        else:
            z = 1.0 + xi * y
            t = np.where(z > 0.0, np.log(np.where(z > 0.0, z, 1.0)) / xi, np.inf if xi < 0 else -np.inf)
        if distribution == "gpd":
            return np.asarray(np.where(y < 0.0, 0.0, -np.expm1(-np.maximum(t, 0.0))), dtype=np.float64)
        return np.asarray(np.exp(-np.exp(-t)), dtype=np.float64)
