"""Linear dispersion relation: wave number and wave length at finite depth.

The relation of Airy (linear) wave theory,

.. math:: \\omega^2 = g k \\tanh(k h),

(e.g. Dean & Dalrymple 1991, *Water Wave Mechanics for Engineers and
Scientists*, Ch. 4) is solved for ``k`` by Newton's method in the
dimensionless unknown ``y = k h`` started from Guo's (2002) explicit
approximation, so that a handful of iterations reach machine precision.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ._types import FloatArray, G, as_float

__all__ = ["deep_water_wavelength", "wavelength", "wavenumber"]

_GUO_BETA = 2.4908
_NEWTON_ITERATIONS = 8


def deep_water_wavelength(period: npt.ArrayLike, g: float = G) -> FloatArray:
    """Deep-water wave length :math:`L_0 = g T^2 / (2 \\pi)`.

    Parameters
    ----------
    period : array_like
        Wave period ``T`` [s].
    g : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    ndarray
        ``L0`` [m].

    Notes
    -----
    Deep-water limit ``tanh(k h) -> 1`` of the linear dispersion relation
    (Dean & Dalrymple 1991, Ch. 4).
    """
    t = as_float(period)
    return np.asarray(g * t * t / (2.0 * np.pi), dtype=np.float64)


def wavenumber(period: npt.ArrayLike, depth: npt.ArrayLike, g: float = G) -> FloatArray:
    """Wave number ``k`` of the linear dispersion relation, to machine precision.

    Solves :math:`\\omega^2 = g k \\tanh(k h)` with :math:`\\omega = 2 \\pi / T`
    (Dean & Dalrymple 1991, Ch. 4), vectorised over broadcast ``period``
    and ``depth``.

    Parameters
    ----------
    period : array_like
        Wave period ``T`` [s], > 0.
    depth : array_like
        Water depth ``h`` [m], > 0; ``inf`` gives the deep-water value.
    g : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    ndarray
        ``k`` [rad/m], broadcast shape of the inputs.

    Notes
    -----
    With :math:`x_0 = \\omega^2 h / g` the unknown ``y = k h`` solves
    ``f(y) = y tanh(y) - x0 = 0``. The start is Guo's (2002) explicit
    approximation ``y = x0 (1 - exp(-x^beta))^(-1/beta)``,
    :math:`x = \\omega \\sqrt{h/g}`, ``beta = 2.4908`` (Guo, J. 2002, "Simple and
    explicit solution of wave dispersion equation", *Coastal Engineering* 45,
    71-74), within 0.76 % of the root (measured over ``h/L0`` from 1e-6
    to 60); Newton's method
    ``y <- y - f/f'``, :math:`f' = \\tanh y + y / \\cosh^2 y`, then converges
    quadratically (``f`` is increasing and convex in ``y > 0``), and a fixed
    number of iterations reaches a relative residual of a few ulp.
    """
    t, h = np.broadcast_arrays(as_float(period), as_float(depth))
    omega = 2.0 * np.pi / t
    k_deep = omega * omega / g
    finite = np.isfinite(h)
    h_f = np.where(finite, h, 1.0)
    x0 = k_deep * h_f
    x = omega * np.sqrt(h_f / g)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        y = x0 / (-np.expm1(-(x**_GUO_BETA))) ** (1.0 / _GUO_BETA)
        for _ in range(_NEWTON_ITERATIONS):
            th = np.tanh(y)
            # 1/cosh^2 y written as 1 - tanh^2 y underflows gracefully for large y
            dfdy = th + y * (1.0 - th * th)
            step = (y * th - x0) / dfdy
            y = np.where(np.isfinite(step), y - step, y)
    k = np.where(finite, y / h_f, k_deep)
    return np.asarray(k, dtype=np.float64)


def wavelength(period: npt.ArrayLike, depth: npt.ArrayLike, g: float = G) -> FloatArray:
    """Wave length ``L = 2 pi / k`` by the linear dispersion relation.

    Parameters
    ----------
    period : array_like
        Wave period ``T`` [s].
    depth : array_like
        Water depth ``h`` [m] (``inf`` allowed).
    g : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    ndarray
        ``L`` [m]; see :func:`wavenumber` for the method
        (Dean & Dalrymple 1991, Ch. 4).
    """
    return np.asarray(2.0 * np.pi / wavenumber(period, depth, g), dtype=np.float64)
