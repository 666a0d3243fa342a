"""The standard normal distribution's quantile function, and normal factors from uniforms.

numpy and scipy.special.  Every normal variate of :mod:`regimemap.lifetime` is drawn as a
uniform ``u`` and mapped through the inverse distribution function, so that a
truncation at ``±n`` standard deviations is an exact truncated distribution
(not a clip) and changes no other random number of the run.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import special

__all__ = ["normal_cdf", "normal_quantile", "truncated_normal"]

FloatArray = NDArray[np.float64]


def normal_quantile(u: ArrayLike) -> FloatArray:
    """Quantile function ``Phi^-1(u)`` of the standard normal distribution.

    Parameters
    ----------
    u : array_like
        Probabilities in ``[0, 1]``.

    Returns
    -------
    ndarray
        ``z`` with ``Phi(z) = u`` (``-inf`` at 0, ``inf`` at 1): ``scipy.special.ndtri``.

    Examples
    --------
    >>> float(normal_quantile(0.975).round(6))
    1.959964
    """
    return np.asarray(special.ndtri(np.asarray(u, dtype=np.float64)), dtype=np.float64)


def normal_cdf(z: float) -> float:
    """``Phi(z)`` of the standard normal distribution (a scalar; ``scipy.special.ndtr``)."""
    return float(special.ndtr(z))


def truncated_normal(u: ArrayLike, truncate: float | None = None) -> FloatArray:
    """Standard normal variates from uniforms, optionally truncated at ``±truncate``.

    Parameters
    ----------
    u : array_like
        Uniform variates on ``[0, 1)``.
    truncate : float or None
        ``n``: the distribution is the standard normal conditioned on
        ``|z| <= n`` (Kim & Takayama 2003 cut their error factors so), drawn
        exactly by ``z = Phi^-1(Phi(-n) + u (Phi(n) - Phi(-n)))``; None: no
        truncation.

    Returns
    -------
    ndarray
        ``z``, monotone in ``u`` (the same ``u`` gives the same rank at any
        ``n``: common random numbers across truncations).
    """
    uu = np.asarray(u, dtype=np.float64)
    if truncate is None:
        # keep away from 0: a uniform of exactly 0 would give -inf
        return normal_quantile(np.where(uu > 0.0, uu, np.nextafter(0.0, 1.0)))
    lo = normal_cdf(-truncate)
    hi = normal_cdf(truncate)
    return np.clip(normal_quantile(lo + uu * (hi - lo)), -truncate, truncate)
