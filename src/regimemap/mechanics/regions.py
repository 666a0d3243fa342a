"""The report's region of every mode, as it derives them (before Section 4.7).

Each predicate takes :class:`~regimemap.mechanics.block.Parameters` and arrays of k and
mu (broadcast together) and returns a boolean array; boundaries are included,
as the report writes them (<=, >=).  These are the *raw* regions shown by the
single-mode figures (3.1-3.8 and 4.2-4.6).  Below C they overlap; Section 4.7
of the report (and :func:`regimemap.classify`) gives each point one mode.

Every predicate is cross-checked against the independent solver
(:mod:`regimemap.mechanics.solver`) in ``tests/test_regions.py``.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from . import constants as C
from .block import Parameters
from .curves import dotted_line_344, lower_line, mu_star, mu_star_signed, mu_star_star, upper_line
from .modes import Mode

__all__ = [
    "rest_region",
    "slide_region",
    "rock_region",
    "slide_rock_minus_region",
    "slide_rock_plus_region",
    "slide_rock_prime_minus_region",
    "RAW_REGIONS",
    "raw_region",
]


def _km(k: ArrayLike, mu: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    k, mu = np.broadcast_arrays(np.asarray(k, dtype=np.float64), np.asarray(mu, dtype=np.float64))
    return k, mu


def rest_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """RE: mu >= k (3.4), (4.7) and k <= 1/(gamma(1+k')) (3.5), (4.10)."""
    k, mu = _km(k, mu)
    return (mu >= k) & C.rest_possible(k, p.gamma, p.kprime)


def slide_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """SL: mu <= k (3.6), (4.23) and |xi| <= B.

    Above C, |xi| <= B is mu <= 1/gamma - k k' (line CD, Section III.2); below C
    it is -1/gamma + k|k'| <= mu <= 1/gamma + k|k'| (4.18)-(4.21), lines DC and AB.
    """
    k, mu = _km(k, mu)
    return (mu <= k) & (mu <= upper_line(p, k)) & (mu >= lower_line(p, k))


def rock_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """RO (about O): theta'' >= 0, k >= k_A (3.17), (4.37), and mu >= mu*(k) (3.24), (4.40)."""
    k, mu = _km(k, mu)
    return C.rock_possible(k, p.gamma, p.kprime) & (mu >= mu_star(p, k))


def slide_rock_minus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """SRO-: slide-rock about O with x_O'' <= 0.

    theta'' >= 0 from (3.30)/(4.64) and x_O'' <= 0 from (3.37)/(4.76), each a
    sign condition on a ratio with denominator 4 + g^2 - 3 mu g:

    * mu <= mu_B' = (4+g^2)/(3g): mu >= 1/gamma - k k' and mu <= (ak+b)/(ck+d),
      i.e. (3.42) above C and (4.67), (4.68), (4.77), (4.78) below C;
    * mu >= mu_B': mu <= 1/gamma - k k' and mu >= (ak+b)/(ck+d), (4.69), (4.70),
      (4.80), (4.81); empty above C (3.36), and below C deleted by Section 4.7
      (the solver finds another mode admissible at each of its points).
    """
    k, mu = _km(k, mu)
    up = upper_line(p, k)
    ms = mu_star_signed(p, k)
    mu_b = p.mu_Bprime
    branch_low = (mu <= mu_b) & (mu >= up) & (mu <= ms)
    branch_high = (mu >= mu_b) & (mu <= up) & (mu >= ms)
    return branch_low | branch_high


def slide_rock_plus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """SRO+: slide-rock about O with x_O'' >= 0 (Section III.4, case 3, Fig 3.8).

    theta'' >= 0 needs mu <= -1/gamma + k k' (3.44); x_O'' >= 0 from (3.45)
    needs ak + b <= 0 (f_x <= 0, k >= b/|a|) and mu <= mu*(k).  Empty below C,
    where a > 0.
    """
    k, mu = _km(k, mu)
    f = p.a * k + p.b
    return (f <= 0.0) & (mu <= mu_star(p, k)) & (mu <= dotted_line_344(p, k))


def slide_rock_prime_minus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """SRO'-: slide-rock about O' with x_O''' <= 0 (Section IV.6, Fig 4.6).

    theta'' <= 0 gives mu <= -1/gamma + k|k'| (4.92), below DC.  x_O''' <= 0
    from (4.95) gives mu <= mu**(k) (4.96) for k < d/c, and holds for every mu
    when k >= d/c (the report omits this; see docs/errata.md).  Empty above C.
    """
    k, mu = _km(k, mu)
    beyond_pole = p.c * k >= p.d
    below_mss = mu <= mu_star_star(p, k)
    return (mu <= lower_line(p, k)) & (beyond_pole | below_mss)


def _never(p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """RO' (4.57) and SRO'+: never admissible for -1 <= k' <= 1."""
    k, mu = _km(k, mu)
    return np.zeros(k.shape, dtype=bool)


RAW_REGIONS: dict[Mode, Callable[[Parameters, ArrayLike, ArrayLike], np.ndarray]] = {
    Mode.RE: rest_region,
    Mode.SL: slide_region,
    Mode.RO: rock_region,
    Mode.SRO_MINUS: slide_rock_minus_region,
    Mode.SRO_PLUS: slide_rock_plus_region,
    Mode.SRO_PRIME_MINUS: slide_rock_prime_minus_region,
    Mode.RO_PRIME: _never,
    Mode.SRO_PRIME_PLUS: _never,
}


def raw_region(mode: Mode, p: Parameters, k: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """The report's region of ``mode`` (before Section 4.7's deletions)."""
    return RAW_REGIONS[Mode(mode)](p, k, mu)
