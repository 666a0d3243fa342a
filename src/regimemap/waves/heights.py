"""Design wave heights at the wall: nonlinear shoaling and Goda's surf-zone formulas.

Sources
-------
* Goda, Y. (1975). Irregular wave deformation in the surf zone. *Coastal
  Engineering in Japan* 18, 13-26 -- the approximate formulas for
  ``H1/3`` and ``Hmax`` inside the surf zone, reproduced in
* Goda, Y. (2000). *Random Seas and Design of Maritime Structures*, 2nd ed.,
  World Scientific, Sect. 3.6 (wave breaking; the beta coefficients) and
  Sect. 4.2 (design wave for an upright breakwater: ``Hmax = 1.8 Ks H0'``
  outside the surf zone, ``h_b`` five ``H1/3`` seaward of the wall).
* Kweon, H.-M. & Goda, Y. (1996). A parametric model for random wave
  deformation by breaking on arbitrary beach profiles. *Proc. 25th ICCE*,
  ASCE, 261-274 -- the explicit approximation of Shuto's (1974) nonlinear
  shoaling coefficient used here.
* The linear shoaling coefficient is Green's law generalised by energy-flux
  conservation (e.g. Dean & Dalrymple 1991, *Water Wave Mechanics for Engineers
  and Scientists*, Ch. 4).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._types import FloatArray, G, as_float
from .dispersion import deep_water_wavelength, wavenumber

__all__ = ["DesignHeights", "breaker_height", "design_heights", "given_heights",
           "linear_shoaling_coefficient", "shoaling_coefficient"]

HMAX_FACTOR = 1.8
"""Goda's (2000, Sect. 4.2) ratio ``Hmax / H1/3`` outside the surf zone."""


def linear_shoaling_coefficient(period: npt.ArrayLike, depth: npt.ArrayLike,
                                g: float = G) -> FloatArray:
    """Linear shoaling coefficient ``Ksi = (tanh(kh) 2n)^(-1/2)``.

    Parameters
    ----------
    period : array_like
        Wave period [s].
    depth : array_like
        Water depth [m].
    g : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    ndarray
        :math:`K_{si} = \\sqrt{C_{g0} / C_g}` with :math:`n = (1 + 2kh/\\sinh 2kh) / 2`
        (energy-flux conservation, Dean & Dalrymple 1991, Ch. 4).
    """
    t, h = np.broadcast_arrays(as_float(period), as_float(depth))
    kh = wavenumber(t, h, g) * h
    with np.errstate(over="ignore", invalid="ignore"):
        two_kh = 2.0 * kh
        ratio = np.where(two_kh < 700.0, two_kh / np.sinh(np.minimum(two_kh, 700.0)), 0.0)
    n = 0.5 * (1.0 + ratio)
    return np.asarray(1.0 / np.sqrt(np.tanh(kh) * 2.0 * n), dtype=np.float64)


def shoaling_coefficient(H0: npt.ArrayLike, period: npt.ArrayLike, depth: npt.ArrayLike,
                         g: float = G) -> FloatArray:
    """Nonlinear shoaling coefficient ``Ks`` (Shuto 1974, after Kweon & Goda 1996).

    Parameters
    ----------
    H0 : array_like
        Equivalent deep-water significant wave height ``H0'`` [m].
    period : array_like
        Significant wave period ``T1/3`` [s].
    depth : array_like
        Water depth ``h`` [m].
    g : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    ndarray
        ``Ks = Ksi + 0.0015 (h/L0)^-2.87 (H0'/L0)^1.27``, the explicit fit of
        Kweon & Goda (1996) to Shuto's (1974) nonlinear shoaling diagram (the
        diagram of Goda 2000, Sect. 3.5); ``Ksi`` is
        :func:`linear_shoaling_coefficient`.
    """
    h0, t, h = np.broadcast_arrays(as_float(H0), as_float(period), as_float(depth))
    L0 = deep_water_wavelength(t, g)
    ksi = linear_shoaling_coefficient(t, h, g)
    return np.asarray(ksi + 0.0015 * (h / L0) ** -2.87 * (h0 / L0) ** 1.27, dtype=np.float64)


@dataclass(frozen=True)
class DesignHeights:
    """Design wave heights at the wall (arrays broadcast over the conditions).

    Attributes
    ----------
    H13 : ndarray
        Significant wave height ``H1/3`` at the wall [m].
    Hmax : ndarray
        Maximum (design) wave height ``Hmax`` [m].
    hb : ndarray
        Water depth ``h_b = h + 5 H1/3 tan(theta)`` five ``H1/3`` seaward of the
        wall [m] (Goda 2000, Sect. 4.2); used for ``Hmax`` and ``alpha2``.
    Ks : ndarray
        Nonlinear shoaling coefficient at the wall (nan when the heights were
        given directly).
    L0 : ndarray
        Deep-water wave length of ``T1/3`` [m] (nan when given directly).
    surf_zone : ndarray of bool
        ``h / L0 < 0.2``: the surf-zone formulas were used.
    """

    H13: FloatArray
    Hmax: FloatArray
    hb: FloatArray
    Ks: FloatArray
    L0: FloatArray
    surf_zone: npt.NDArray[np.bool_]


def design_heights(H0: npt.ArrayLike, period: npt.ArrayLike, depth: npt.ArrayLike,
                   seabed_slope: npt.ArrayLike, g: float = G,
                   hmax_factor: float = HMAX_FACTOR) -> DesignHeights:
    """Goda's design wave heights ``H1/3`` and ``Hmax`` at the wall.

    Parameters
    ----------
    H0 : array_like
        Equivalent deep-water significant wave height ``H0'`` [m].
    period : array_like
        Significant wave period ``T1/3`` [s].
    depth : array_like
        Water depth at the wall ``h`` [m].
    seabed_slope : array_like
        ``tan(theta)`` of the sea bed in front of the wall [-].
    g : float, optional
        Gravitational acceleration [m/s^2].
    hmax_factor : float, optional
        ``Hmax / (Ks H0')`` outside the surf zone; Goda (2000, Sect. 4.2)
        recommends 1.8.

    Returns
    -------
    DesignHeights

    Notes
    -----
    Goda (1975), reproduced in Goda (2000, Sect. 3.6), with
    ``s = H0'/L0``:

    * for ``h / L0 >= 0.2`` (outside the surf zone):
      ``H1/3 = Ks H0'``, ``Hmax = 1.8 Ks H0'``;
    * for ``h / L0 < 0.2``:
      ``H1/3 = min(beta0 H0' + beta1 h, betamax H0', Ks H0')`` and
      ``Hmax = min(beta0* H0' + beta1* h_b, betamax* H0', 1.8 Ks H0')`` with

      - ``beta0 = 0.028 s^-0.38 exp(20 tan^1.5 theta)``,
        ``beta1 = 0.52 exp(4.2 tan theta)``,
        ``betamax = max(0.92, 0.32 s^-0.29 exp(2.4 tan theta))``,
      - ``beta0* = 0.052 s^-0.38 exp(20 tan^1.5 theta)``,
        ``beta1* = 0.63 exp(3.8 tan theta)``,
        ``betamax* = max(1.65, 0.53 s^-0.29 exp(2.4 tan theta))``;

    * ``h_b = h + 5 H1/3 tan theta``: for the pressure formulas Goda (2000,
      Sect. 4.2) takes ``Hmax`` at the depth ``h_b`` a distance ``5 H1/3``
      seaward of the wall, so ``beta1*`` multiplies ``h_b`` (his worked
      upright breakwater, ``Hmax = 8.05 m``, confirms it: with ``h`` it would
      be 7.86 m).
    """
    h0, t, h, tan = np.broadcast_arrays(as_float(H0), as_float(period), as_float(depth),
                                        as_float(seabed_slope))
    L0 = deep_water_wavelength(t, g)
    s = h0 / L0
    ks = shoaling_coefficient(h0, t, h, g)
    ks_h0 = ks * h0
    surf = h / L0 < 0.2

    beta0 = 0.028 * s**-0.38 * np.exp(20.0 * tan**1.5)
    beta1 = 0.52 * np.exp(4.2 * tan)
    betamax = np.maximum(0.92, 0.32 * s**-0.29 * np.exp(2.4 * tan))
    beta0s = 0.052 * s**-0.38 * np.exp(20.0 * tan**1.5)
    beta1s = 0.63 * np.exp(3.8 * tan)
    betamaxs = np.maximum(1.65, 0.53 * s**-0.29 * np.exp(2.4 * tan))

    h13_surf = np.minimum(np.minimum(beta0 * h0 + beta1 * h, betamax * h0), ks_h0)
    h13 = np.where(surf, h13_surf, ks_h0)
    hb = h + 5.0 * h13 * tan
    hmax_surf = np.minimum(np.minimum(beta0s * h0 + beta1s * hb, betamaxs * h0),
                           hmax_factor * ks_h0)
    hmax = np.where(surf, hmax_surf, hmax_factor * ks_h0)
    return DesignHeights(H13=np.asarray(h13, dtype=np.float64),
                         Hmax=np.asarray(hmax, dtype=np.float64),
                         hb=np.asarray(hb, dtype=np.float64), Ks=ks, L0=L0,
                         surf_zone=np.asarray(surf, dtype=np.bool_))


def given_heights(H13: npt.ArrayLike, Hmax: npt.ArrayLike, depth: npt.ArrayLike,
                  seabed_slope: npt.ArrayLike) -> DesignHeights:
    """Design heights given directly (no shoaling, no surf-zone formula).

    Parameters
    ----------
    H13, Hmax : array_like
        Significant and maximum wave heights at the wall [m].
    depth : array_like
        Water depth at the wall ``h`` [m].
    seabed_slope : array_like
        ``tan(theta)`` of the sea bed, for ``h_b = h + 5 H1/3 tan theta``
        (Goda 2000, Sect. 4.2).

    Returns
    -------
    DesignHeights
        ``Ks`` and ``L0`` are nan, ``surf_zone`` is False.
    """
    h13, hmax, h, tan = np.broadcast_arrays(as_float(H13), as_float(Hmax), as_float(depth),
                                            as_float(seabed_slope))
    nan = np.full(h13.shape, np.nan)
    return DesignHeights(H13=h13.copy(), Hmax=hmax.copy(),
                         hb=np.asarray(h + 5.0 * h13 * tan, dtype=np.float64), Ks=nan,
                         L0=nan.copy(), surf_zone=np.zeros(h13.shape, dtype=np.bool_))


def breaker_height(L0: npt.ArrayLike, depth: npt.ArrayLike, seabed_slope: npt.ArrayLike) -> FloatArray:
    """Goda's breaker limit: the highest individual wave at a depth.

    Parameters
    ----------
    L0 : array_like
        Deep-water wave length ``L0`` [m] of the significant period.
    depth : array_like
        Water depth ``h_b`` at which the wave breaks [m] (for a wave at an
        upright wall, ``h_b = h + 5 H1/3 tan(theta)``, Goda 2000, Sect. 4.2).
    seabed_slope : array_like
        ``tan(theta)`` of the sea bed [-].

    Returns
    -------
    ndarray
        ``H_b = 0.17 L0 [1 - exp(-1.5 pi h_b/L0 (1 + 15 tan^(4/3) theta))]`` [m].

    Notes
    -----
    Goda's breaker index (Goda 1970; Goda 2000, Sect. 3.6, the formula of
    the breaking limit of regular waves), used as the limit of individual
    waves in the expected-sliding-distance model (Shimosako & Takahashi 1999;
    Goda & Takagi 2000).
    """
    l0, hb, tan = np.broadcast_arrays(as_float(L0), as_float(depth), as_float(seabed_slope))
    return np.asarray(0.17 * l0 * -np.expm1(-1.5 * np.pi * hb / l0 * (1.0 + 15.0 * tan ** (4.0 / 3.0))),
                      dtype=np.float64)
