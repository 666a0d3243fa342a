"""Boundary curves and named points of the k-mu plane (vectorised in k).

All functions take a :class:`~regimemap.params.Parameters` and an array of k.
Lines are named as in the report: above C (Chapter III) OA is mu = k, AB the
vertical k = k_A and CD the line mu = 1/gamma - k k'; below C (Chapter IV) AB
is mu = 1/gamma + k|k'| (4.21), DC is mu = -1/gamma + k|k'| (4.20), AE the
vertical k = k_A and the dotted line mu = k|k'| (4.22).  With the signed k'
used here, CD (above) and AB (below) are the same expression, the *upper
line* ``1/gamma - k k'``; DC is the *lower line* ``-1/gamma - k k'``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .block import Parameters

__all__ = [
    "mu_star",
    "mu_star_signed",
    "mu_star_star",
    "line_OA",
    "upper_line",
    "lower_line",
    "dotted_line",
    "line_CD",
    "line_AB",
    "line_DC",
    "NamedPoint",
    "named_points",
]


def _k(k: ArrayLike) -> np.ndarray:
    return np.asarray(k, dtype=np.float64)


def mu_star_signed(p: Parameters, k: ArrayLike) -> np.ndarray:
    """(ak+b)/(ck+d): f_x/f_y of rocking about O, (3.22)-(3.23), (4.38)-(4.39).

    Its sign is that of f_x; it is mu* where f_x >= 0.
    """
    k = _k(k)
    return (p.a * k + p.b) / (p.c * k + p.d)


def mu_star(p: Parameters, k: ArrayLike) -> np.ndarray:
    """mu*(k) = |ak+b|/(ck+d), (3.24) and (4.40)-(4.41).

    Rocking about O needs mu >= mu*(k): the friction needed to stop the
    pivot O slipping.  In case 3 (a < 0, k > b/|a|) it is -(ak+b)/(ck+d).
    """
    k = _k(k)
    return np.abs(p.a * k + p.b) / (p.c * k + p.d)


def mu_star_star(p: Parameters, k: ArrayLike) -> np.ndarray:
    """mu**(k) = (ak-b)/(d-ck), (4.96)-(4.97) with a from (4.42) (see docs/errata.md).

    Infinite at the pole k = d/c (returned as +-inf); negative beyond it.
    """
    k = _k(k)
    den = p.d - p.c * k
    with np.errstate(divide="ignore", invalid="ignore"):
        return (p.a * k - p.b) / den


def line_OA(p: Parameters, k: ArrayLike) -> np.ndarray:
    """OA: mu = k, the limit of rest by friction, (3.4) and (4.7)."""
    return _k(k).copy()


def upper_line(p: Parameters, k: ArrayLike) -> np.ndarray:
    """mu = 1/gamma - k k': CD of Section III.2 (k' >= 0), AB (4.21) of Section IV.2 (k' <= 0).

    On it the normal reaction of sliding acts at O (xi = -B).
    """
    return 1.0 / p.gamma - _k(k) * p.kprime


def lower_line(p: Parameters, k: ArrayLike) -> np.ndarray:
    """mu = -1/gamma - k k' = -1/gamma + k|k'|: DC (4.20); on it xi = +B (at O')."""
    return -1.0 / p.gamma - _k(k) * p.kprime


def dotted_line(p: Parameters, k: ArrayLike) -> np.ndarray:
    """mu = k|k'|, (4.22): the slide region has xi <= 0 above it and xi >= 0 below it."""
    return _k(k) * p.abs_kprime


line_CD = upper_line
line_AB = upper_line
line_DC = lower_line


@dataclass(frozen=True)
class NamedPoint:
    """A point of the report's figures with its coordinates and its meaning."""

    name: str
    k: float
    mu: float
    meaning: str

    def as_dict(self) -> dict[str, float | str]:
        return {"name": self.name, "k": self.k, "mu": self.mu, "meaning": self.meaning}


def _finite(*v: float) -> bool:
    return all(math.isfinite(x) for x in v)


def named_points(p: Parameters) -> dict[str, NamedPoint]:
    """The report's named points that exist (finite) for these parameters.

    Above C (Chapter III): O, A (k_A, k_A), C (0, 1/gamma) where CD meets the mu
    axis, D (1/(gamma k'), 0) where CD meets the k axis (k' > 0), and in cases
    2/3 the point G (b/|a|, 0) where mu* = 0 (not named in the report).
    Below C (Chapter IV): O, A, E (k_A, 0) the foot of AE, B' (4.48)-(4.49)
    when k' < 0, D (1/(gamma|k'|), 0) where DC meets the k axis, F (b/a, 0)
    where mu** = 0, and C' where mu* crosses DC.
    """
    pts: dict[str, NamedPoint] = {"O": NamedPoint("O", 0.0, 0.0, "origin")}
    kA = p.k_A
    if _finite(kA):
        pts["A"] = NamedPoint("A", kA, kA, "OA, mu*, AB meet: k_A = 1/(gamma(1+k'))")
    if p.above:
        pts["C"] = NamedPoint("C", 0.0, 1.0 / p.gamma, "line CD meets the mu axis")
        if p.kprime > 0.0:
            pts["D"] = NamedPoint("D", p.k_D, 0.0, "line CD meets the k axis")
        if p.a < 0.0:
            pts["G"] = NamedPoint("G", p.b_over_abs_a, 0.0, "mu* = 0, f_x = 0 (k = b/|a|)")
    else:
        if _finite(kA):
            pts["E"] = NamedPoint("E", kA, 0.0, "foot of the vertical AE through A")
        if _finite(p.k_Bprime):
            pts["B'"] = NamedPoint("B'", p.k_Bprime, p.mu_Bprime,
                                    "mu* meets AB again (4.48)-(4.49)")
        if _finite(p.k_D):
            pts["D"] = NamedPoint("D", p.k_D, 0.0, "line DC meets the k axis")
            pts["F"] = NamedPoint("F", p.k_F, 0.0, "mu** = 0 (k = b/a)")
            kc = _crossing_mu_star_lower(p)
            if kc is not None:
                pts["C'"] = NamedPoint("C'", kc, float(lower_line(p, kc)), "mu* meets DC")
    return pts


def _crossing_mu_star_lower(p: Parameters) -> float | None:
    """k > k_D where mu*(k) = -1/gamma + k|k'| (the root of a quadratic), or None."""
    # (ak+b) = (q k - 1/g)(ck+d) with q = |k'|  ->  c q k^2 + (d q - c/g - a) k - (d/g + b) = 0
    q = p.abs_kprime
    if q == 0.0 or p.c == 0.0:
        return None
    A2 = p.c * q
    A1 = p.d * q - p.c / p.gamma - p.a
    A0 = -(p.d / p.gamma + p.b)
    disc = A1 * A1 - 4.0 * A2 * A0
    if disc < 0:
        return None
    root = (-A1 + math.sqrt(disc)) / (2.0 * A2)
    return root if root > 0 else None
