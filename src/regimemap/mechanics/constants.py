"""The report's closed forms: the only place where each is written.

Every function takes floats or numpy arrays (broadcast together) and is written
with the same operations, in the same order, wherever it is used, so that the
map (:mod:`regimemap.maps.classify`), the curves, the raw regions, the polygons
and the point queries compare against identical floats.

One sign convention serves both chapters: ``kprime`` is signed, ``h = kprime*H``,
positive above the centre of mass C (Chapter III) and negative below it
(Chapter IV, where the report writes ``|k'| = -kprime``).  Then (4.42)-(4.45)
are (3.18)-(3.21)::

    a = 4 + gamma**2 - 3*gamma**2*kprime      (3.18), (4.42)
    b = 3*gamma                               (3.19), (4.43)
    c = 3*gamma*(1 + kprime)                  (3.20), (4.44)
    d = 1 + 4*gamma**2                        (3.21), (4.45)

and the lines of the k-mu plane are::

    mu = k                       OA, the limit of rest by friction      (3.4), (4.7)
    k  = 1/(gamma (1 + k'))      k_A: AB above C, AE below C             (3.5), (3.17), (4.10), (4.37)
    mu = 1/gamma - k k'          the upper line: CD above C, AB below    Section III.2, (4.21)
    mu = -1/gamma - k k'         the lower line: DC                      (4.20)
    mu = k |k'|                  the dotted line below C                 (4.22)
    mu = k k' - 1/gamma          the dotted line of case 3               (3.44)
    mu = |ak + b|/(ck + d)       mu*(k)                                  (3.24), (4.40)
    mu = (ak - b)/(d - ck)       mu**(k)                                 (4.96)-(4.97)
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "Thresholds",
    "b_over_abs_a",
    "coefficients",
    "crossing_mu_star_lower",
    "delta",
    "dotted_line",
    "dotted_line_344",
    "k_A",
    "k_Bprime",
    "k_D",
    "k_F",
    "k_pole",
    "k_roots_at_mu",
    "kprime_1",
    "kprime_2",
    "kprime_delta",
    "lower_line",
    "mu_Bprime",
    "mu_star",
    "mu_star_signed",
    "mu_star_star",
    "rest_possible",
    "rock_possible",
    "slope_at_A",
    "thresholds",
    "upper_line",
]

#: A float or an array of floats: the closed forms are written once for both
#: (numpy broadcasting), so their arguments and results are typed loosely.
Num = Any

FloatArray = NDArray[np.float64]


# -- the constants a, b, c, d --------------------------------------------------------------


def coefficients(gamma: Num, kprime: Num) -> tuple[Num, Num, Num, Num]:
    """a, b, c, d of (3.18)-(3.21) and (4.42)-(4.45) (k' signed).

    Parameters
    ----------
    gamma : float or ndarray
        Aspect ratio H/B.
    kprime : float or ndarray
        Force height h/H, signed.

    Returns
    -------
    (a, b, c, d)
        ``a = 4 + g^2 - 3 g^2 k'``, ``b = 3 g``, ``c = 3 g (1 + k')``, ``d = 1 + 4 g^2``.
    """
    g2 = gamma * gamma
    a = 4.0 + g2 - 3.0 * g2 * kprime
    b = 3.0 * gamma
    c = 3.0 * gamma * (1.0 + kprime)
    d = 1.0 + 4.0 * g2
    return a, b, c, d


# -- points and thresholds of k' (scalars) --------------------------------------------------


def k_A(gamma: float, kprime: float) -> float:
    """k_A = 1/(gamma(1+k')) = 3/c: the abscissa of A, (3.5), (3.17), (4.10), (4.37); inf at k' = -1."""
    den = gamma * (1.0 + kprime)
    return math.inf if den == 0.0 else 1.0 / den


def mu_Bprime(gamma: float) -> float:
    """mu_B' = (4+g^2)/(3 gamma), (4.49): where 4 + g^2 - 3 mu gamma = 0 in (3.30), (4.64)."""
    return (4.0 + gamma**2) / (3.0 * gamma)


def k_Bprime(gamma: float, kprime: float) -> float:
    """k_B' = (1+g^2)/(3 gamma |k'|), (4.48); inf for k' >= 0 (no B' above C)."""
    if kprime >= 0.0:
        return math.inf
    return (1.0 + gamma**2) / (3.0 * gamma * abs(kprime))


def kprime_1(gamma: float) -> float:
    """(1+g^2)/(3g^2): the slope of mu* at A changes sign (Chapter III, case 1)."""
    return (1.0 + gamma**2) / (3.0 * gamma**2)


def kprime_2(gamma: float) -> float:
    """(4+g^2)/(3g^2): a = 0 (3.18); above it cases 2/3 (only for gamma > sqrt 2)."""
    return (4.0 + gamma**2) / (3.0 * gamma**2)


def kprime_delta(gamma: float) -> float:
    """(1+g^2)/(4+g^2): Delta = 0 (Chapter IV, Section IV.3)."""
    return (1.0 + gamma**2) / (4.0 + gamma**2)


def slope_at_A(gamma: float, kprime: float) -> float:
    """d mu*/dk at A = (1+g^2-3g^2 k')/(4(1+g^2)) (Section III.3, case 1)."""
    g2 = gamma**2
    return (1.0 + g2 - 3.0 * g2 * kprime) / (4.0 * (1.0 + g2))


def delta(gamma: float, kprime: float) -> float:
    """Delta = ((1+g^2) - (4+g^2)|k'|)/(4(1+g^2)) (Section IV.3): slope of mu* at A minus |k'|."""
    g2 = gamma**2
    return ((1.0 + g2) - (4.0 + g2) * abs(kprime)) / (4.0 * (1.0 + g2))


def b_over_abs_a(a: float, b: float) -> float:
    """b/|a| (point G): where f_x of rocking changes sign when a < 0 (cases 2/3); inf if a >= 0."""
    if a >= 0.0:
        return math.inf
    return b / abs(a)


def k_D(gamma: float, kprime: float) -> float:
    """k where the upper line (above C) or the lower line (below C) meets mu = 0: 1/(gamma|k'|)."""
    if kprime == 0.0:
        return math.inf
    return 1.0 / (gamma * abs(kprime))


def k_F(a: float, b: float) -> float:
    """k_F = b/a, where mu** = 0 (Section IV.6); inf when a <= 0."""
    return math.inf if a <= 0.0 else b / a


def k_pole(c: float, d: float) -> float:
    """d/c, the pole of mu**(k) (4.97); inf at k' = -1."""
    return math.inf if c == 0.0 else d / c


def crossing_mu_star_lower(gamma: float, kprime: float) -> float | None:
    """C': the k > k_D where mu*(k) = -1/gamma + k|k'| below C (root of a quadratic), or None.

    ``(ak+b) = (q k - 1/g)(ck+d)`` with ``q = |k'|`` is
    ``c q k^2 + (d q - c/g - a) k - (d/g + b) = 0``.
    """
    a, b, c, d = coefficients(gamma, kprime)
    q = abs(kprime)
    if q == 0.0 or c == 0.0:
        return None
    A2 = c * q
    A1 = d * q - c / gamma - a
    A0 = -(d / gamma + b)
    disc = A1 * A1 - 4.0 * A2 * A0
    if disc < 0:
        return None
    root = (-A1 + math.sqrt(disc)) / (2.0 * A2)
    return root if root > 0 else None


# -- the lines and curves of the k-mu plane (vectorised in k) ------------------------------


def rest_possible(k: Num, gamma: Num, kprime: Num) -> NDArray[np.bool_]:
    """k <= k_A, written ``k gamma (1+k') <= 1``: the reaction of rest inside the base (3.5), (4.10)."""
    return np.asarray(k * (gamma * (1.0 + kprime)) <= 1.0)


def rock_possible(k: Num, gamma: Num, kprime: Num) -> NDArray[np.bool_]:
    """k >= k_A: theta'' >= 0 in rocking about O, (3.17), (4.37)."""
    return np.asarray(k * (gamma * (1.0 + kprime)) >= 1.0)


def upper_line(k: Num, gamma: Num, kprime: Num) -> Num:
    """mu = 1/gamma - k k': CD above C (Section III.2), AB below C (4.21); xi = -B on it."""
    return 1.0 / gamma - k * kprime


def lower_line(k: Num, gamma: Num, kprime: Num) -> Num:
    """mu = -1/gamma - k k' = -1/gamma + k|k'|: DC (4.20); xi = +B (at O') on it."""
    return -1.0 / gamma - k * kprime


def dotted_line(k: Num, kprime: float) -> Num:
    """mu = k|k'| (4.22): in sliding xi <= 0 above it and xi >= 0 below it."""
    return k * abs(kprime)


def dotted_line_344(k: Num, gamma: float, kprime: float) -> Num:
    """mu = k k' - 1/gamma (3.44): theta'' = 0 in slide-rock about O slipping right (case 3)."""
    return -upper_line(k, gamma, kprime)


def mu_star_signed(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """(ak+b)/(ck+d) = f_x/f_y of rocking about O, (3.22)-(3.23), (4.38)-(4.39); mu* where >= 0."""
    return (a * k + b) / (c * k + d)


def mu_star(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """mu*(k) = |ak+b|/(ck+d), (3.24) and (4.40)-(4.41): the friction rocking about O needs."""
    return np.abs(a * k + b) / (c * k + d)


def mu_star_star(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """mu**(k) = (ak-b)/(d-ck), (4.96)-(4.97) with a from (4.42) (docs/errata.md E3).

    Infinite at the pole k = d/c (+-inf) and negative beyond it; no warnings.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return (a * k - b) / (d - c * k)


class Thresholds(NamedTuple):
    """The per-k quantities the final map compares mu with (:func:`thresholds`)."""

    #: k <= k_A: rest is possible at all (3.5), (4.10).
    rest_ok: NDArray[np.bool_]
    #: the lower line DC, -1/gamma - k k'.
    lower: FloatArray
    #: the upper line CD/AB, 1/gamma - k k'.
    upper: FloatArray
    #: mu*(k) = |ak+b|/(ck+d).
    mu_star: FloatArray
    #: ak + b >= 0 (f_x of rocking >= 0): slide-rock about O slips left (SRO-) rather than right.
    f_pos: NDArray[np.bool_]


def thresholds(k: FloatArray, gamma: ArrayLike, kprime: ArrayLike) -> Thresholds:
    """The thresholds of the final map at each k (see :mod:`regimemap.maps.classify`).

    Parameters
    ----------
    k : ndarray
        Values of k.
    gamma, kprime : float or ndarray
        Broadcast with k.
    """
    g: Num = np.asarray(gamma, dtype=np.float64) if np.ndim(gamma) else float(gamma)  # type: ignore[arg-type]
    kp: Num = np.asarray(kprime, dtype=np.float64) if np.ndim(kprime) else float(kprime)  # type: ignore[arg-type]
    a, b, c, d = coefficients(g, kp)
    f = a * k + b
    return Thresholds(
        rest_ok=rest_possible(k, g, kp),
        lower=lower_line(k, g, kp),
        upper=upper_line(k, g, kp),
        mu_star=np.abs(f) / (c * k + d),
        f_pos=np.asarray(f >= 0.0),
    )


def k_roots_at_mu(mu: FloatArray, gamma: FloatArray, kprime: FloatArray) -> FloatArray:
    """Every k where a threshold of the map equals mu (the inverses of the lines above); shape (n, 7).

    Columns: OA (k = mu), k_A, the upper line, the lower line, mu* with f_x >= 0
    (``k = (mu d - b)/(a - mu c)``), mu* with f_x <= 0 (``k = -(mu d + b)/(a + mu c)``)
    and f_x = 0 (``k = -b/a``).  Non-finite or negative entries are no roots.
    """
    a, b, c, d = coefficients(gamma, kprime)
    with np.errstate(divide="ignore", invalid="ignore"):
        roots = [
            mu,
            1.0 / (gamma * (1.0 + kprime)),
            (1.0 / gamma - mu) / kprime,
            (-1.0 / gamma - mu) / kprime,
            (mu * d - b) / (a - mu * c),
            -(mu * d + b) / (a + mu * c),
            -b / a,
        ]
    return np.stack(roots, axis=1)
