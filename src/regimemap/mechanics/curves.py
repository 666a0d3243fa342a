"""The catalogue of curves and named points of the k-mu plane (vectorised in k).

Each curve of the map is described once here, with its equation, where it
comes from in the report, its kind (boundary, construction or dotted) and the
function that evaluates it; drawing (:mod:`regimemap.maps.view`) and export
(:mod:`regimemap.maps.record_export`) sample the same entries.  The formulas themselves
are written once, in :mod:`regimemap.mechanics.constants`.

Lines are named as in the report: above C (Chapter III) OA is mu = k, AB the
vertical k = k_A and CD the line mu = 1/gamma - k k'; below C (Chapter IV) AB
is mu = 1/gamma + k|k'| (4.21), DC is mu = -1/gamma + k|k'| (4.20), AE the
vertical k = k_A and the dotted line mu = k|k'| (4.22).  With the signed k'
used here, CD (above) and AB (below) are the same expression, the *upper
line* ``1/gamma - k k'``; DC is the *lower line* ``-1/gamma - k k'``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import constants as C
from .block import Parameters

__all__ = [
    "Curve",
    "CurveKind",
    "NamedPoint",
    "dotted_line",
    "dotted_line_344",
    "line_OA",
    "lower_line",
    "map_curves",
    "mu_star",
    "mu_star_signed",
    "mu_star_star",
    "named_points",
    "upper_line",
]

FloatArray = NDArray[np.float64]


def _k(k: ArrayLike) -> FloatArray:
    return np.asarray(k, dtype=np.float64)


def mu_star_signed(p: Parameters, k: ArrayLike) -> FloatArray:
    """(a_O k + b_O)/(c_O k + d_O): f_x/f_y of rocking about O, (3.22)-(3.23), (4.38)-(4.39).

    Its sign is that of f_x; it is mu* where f_x >= 0.
    """
    c = p.constants
    return np.asarray(C.mu_star_signed(_k(k), c.aO, c.bO, c.cO, c.dO))


def mu_star(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu*(k) = |a_O k + b_O|/(c_O k + d_O), (3.24) and (4.40)-(4.41).

    Rocking about O needs mu >= mu*(k): the friction needed to stop the
    pivot O slipping.  In case 3 (a < 0, k > b/|a|) it is -(ak+b)/(ck+d).
    """
    c = p.constants
    return np.asarray(C.mu_star(_k(k), c.aO, c.bO, c.cO, c.dO))


def mu_star_star(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu**(k) = (a_O' k - b_O')/(d_O' - c_O' k), (4.96)-(4.97) with a from (4.42) (see docs/errata.md).

    Infinite at the pole k = d/c (returned as +-inf); negative beyond it.
    """
    c = p.constants
    return np.asarray(C.mu_star_star(_k(k), c.aP, c.bP, c.cP, c.dP))


def line_OA(p: Parameters, k: ArrayLike) -> FloatArray:
    """OA: mu = k/W (mu = k at zero loads), the limit of rest by friction, (3.4) and (4.7)."""
    if not p.loaded:
        return np.array(_k(k))
    return np.asarray(C.rest_line(_k(k), p.constants))


def upper_line(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu = 1/gamma - s/W: CD of Section III.2 (k' >= 0), AB (4.21) of Section IV.2 (k' <= 0).

    On it the normal reaction of sliding acts at O (xi = -B).
    """
    return np.asarray(C.upper_line(_k(k), p.constants))


def lower_line(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu = -1/gamma - s/W (-1/gamma + k|k'| at zero loads): DC (4.20); on it xi = +B (at O')."""
    return np.asarray(C.lower_line(_k(k), p.constants))


def dotted_line(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu = -s/W (k|k'| at zero loads), (4.22): the slide region has xi <= 0 above it and xi >= 0 below it."""
    return np.asarray(C.dotted_line(_k(k), p.constants))


def dotted_line_344(p: Parameters, k: ArrayLike) -> FloatArray:
    """mu = s/W - 1/gamma (k k' - 1/gamma), (3.44): theta'' = 0 in slide-rock about O slipping right."""
    return np.asarray(C.dotted_line_344(_k(k), p.constants))


# -- the catalogue --------------------------------------------------------------------------

#: What a curve is on a map: it may bound regions, or only help to construct them
#: (the report draws those dashed), or be one of the report's dotted lines.
CurveKind = Literal["boundary", "construction", "dotted"]


@dataclass(frozen=True)
class Curve:
    """One curve of the map of given parameters, as the report defines it.

    Attributes
    ----------
    name : str
        ``OA``, ``AB``, ``CD``, ``DC``, ``AE``, ``dotted``, ``mu_star`` or ``mu_star_star``.
    equation : str
        The equation in plain text.
    report : str
        Where the report writes it.
    role : str
        What it separates, in words.
    kind : CurveKind
        ``boundary`` (can bound regions), ``dotted`` (the report's dotted lines).
    tex : str
        The mathtext label drawn next to it ("" for lines named by their end points).
    spec : dict
        The curve as numbers (JSON export): a line ``mu = c0 + c1 k``, a vertical
        ``k = k``, or a rational ``mu = (p k + q)/(r k + t)`` (``abs`` for mu*).
    k_from, k_to : float
        Where the curve belongs to the map (``inf`` for no end).
    func : callable or None
        ``mu = func(k)`` (vectorised); None for a vertical line.
    vertical_k : float or None
        The abscissa of a vertical line.
    """

    name: str
    equation: str
    report: str
    role: str
    kind: CurveKind
    tex: str
    spec: dict[str, Any]
    k_from: float
    k_to: float
    func: Callable[[FloatArray], FloatArray] | None = field(default=None, compare=False)
    vertical_k: float | None = None

    @property
    def vertical(self) -> bool:
        """True for the vertical line k = k_A."""
        return self.vertical_k is not None

    @property
    def dotted(self) -> bool:
        """True for the report's dotted lines (3.44) and (4.22)."""
        return self.kind == "dotted"


def _line(c0: float, c1: float) -> dict[str, Any]:
    return {"type": "line", "c0": c0, "c1": c1, "text": "mu = c0 + c1*k"}


def _rational(p_: float, q: float, r: float, t: float, absolute: bool = False) -> dict[str, Any]:
    text = "mu = |p*k + q|/(r*k + t)" if absolute else "mu = (p*k + q)/(r*k + t)"
    return {"type": "rational", "abs": absolute, "p": p_, "q": q, "r": r, "t": t, "text": text}


def _over_w(p: Parameters, q0: float, q1: float) -> dict[str, Any]:
    """The curve mu = (q0 + q1 k)/W as a spec: a line while W does not depend on k."""
    c = p.constants
    w0 = c.w0
    if c.uplift_ratio == 0.0:
        return _line(q0 / w0, q1 / w0)
    return _rational(q1, q0, -c.uplift_ratio, w0)


def map_curves(p: Parameters) -> dict[str, Curve]:
    """The curves of the map of ``p``, in drawing order, keyed by name.

    Above C: ``OA``, ``AB`` (vertical k = k_A), ``CD`` (upper line), ``mu_star``
    and, in cases 2/3 (a < 0), ``dotted`` (3.44).  Below C: ``OA``, ``AE``
    (vertical k = k_A), ``AB`` (upper line), ``DC`` (lower line), ``dotted``
    (4.22), ``mu_star`` and ``mu_star_star`` (from F to its pole d/c).  With
    loads the same curves with the generalised forms (OA is mu = k/W, the lines
    1/gamma - s/W and -1/gamma - s/W, rational when the uplift grows with the
    push), and the verticals ``LO`` (k = k_L, where lift-off starts: the point L)
    and ``LO_end`` (where it ends, if it does).  Curves that do not exist for
    ``p`` (k_A infinite at k' = -1, ...) are left out.
    """
    g, kp = p.gamma, p.kprime
    cst = p.constants
    loaded = p.loaded
    eu_u = cst.uplift_arm * cst.uplift
    kA = p.k_A
    finite_A = math.isfinite(kA) and kA >= 0.0
    out: dict[str, Curve] = {}
    out["OA"] = Curve("OA", "mu = k/W" if loaded else "mu = k", "(3.4), (4.7)",
                      "rest | slide (up to A)", "boundary", "",
                      _over_w(p, 0.0, 1.0), 0.0, kA, lambda k: line_OA(p, k))
    vertical = "AB" if p.above else "AE"
    if finite_A:
        out[vertical] = Curve(
            vertical, "k = k_A = Q/P" if loaded else "k = k_A = 1/(gamma (1 + k'))",
            "(3.5), (3.17)" if p.above else "(4.10), (4.37)", "rest | rock (vertical)", "boundary", "",
            {"type": "vertical", "k": kA}, kA, kA, None, vertical_k=kA)
    upper = "CD" if p.above else "AB"
    out[upper] = Curve(
        upper, "mu = 1/gamma - s/W" if loaded else
        "mu = 1/gamma - k k'" + ("" if p.above else " = 1/gamma + k|k'|"),
        "Section III.2" if p.above else "(4.21)", "xi = -B: the reaction of sliding reaches O",
        "boundary", "",
        _over_w(p, cst.w0 * (1.0 / g) - eu_u / g, -kp - cst.uplift_ratio * (1.0 + cst.uplift_arm) / g)
        if loaded else _line(1.0 / g, -kp), 0.0, p.k_D if p.above else math.inf,
        lambda k: upper_line(p, k))
    if not p.above:
        out["DC"] = Curve("DC", "mu = -1/gamma - s/W" if loaded else "mu = -1/gamma + k|k'|", "(4.20)",
                          "xi = +B: the reaction of sliding reaches O'", "boundary", "",
                          _over_w(p, -cst.w0 * (1.0 / g) - eu_u / g,
                                  -kp + cst.uplift_ratio * (1.0 - cst.uplift_arm) / g)
                          if loaded else _line(-1.0 / g, -kp), p.k_D, math.inf, lambda k: lower_line(p, k))
        out["dotted"] = Curve("dotted", "mu = -s/W" if loaded else "mu = k|k'|", "(4.22)",
                              "xi = 0 in sliding (construction line)",
                              "dotted", r"$\xi = 0$" if loaded else r"$\mu = k|k'|$",
                              _over_w(p, -eu_u / g, -kp - cst.uplift_ratio * cst.uplift_arm / g)
                              if loaded else _line(0.0, abs(kp)), 0.0, math.inf,
                              lambda k: dotted_line(p, k))
    if finite_A:
        out["mu_star"] = Curve(
            "mu_star", "mu* = |a k + b|/(c k + d)", "(3.24), (4.40)",
            "rock about O needs mu >= mu* (from A on)", "boundary", r"$\mu^*(k)$",
            _rational(cst.aO, cst.bO, cst.cO, cst.dO, absolute=True), kA, math.inf,
            lambda k: mu_star(p, k))
    if p.above and cst.aO < 0.0:
        out["dotted"] = Curve("dotted", "mu = s/W - 1/gamma" if loaded else "mu = k k' - 1/gamma", "(3.44)",
                              "theta'' = 0 in slide-rock about O (SRO+)", "dotted",
                              r"$\ddot{\theta} = 0$" if loaded else r"$\mu = kk' - 1/\gamma$",
                              _over_w(p, -(cst.w0 * (1.0 / g) - eu_u / g),
                                      kp + cst.uplift_ratio * (1.0 + cst.uplift_arm) / g)
                              if loaded else _line(-1.0 / g, kp), p.k_D, math.inf,
                              lambda k: dotted_line_344(p, k))
    if not p.above:
        out["mu_star_star"] = Curve(
            "mu_star_star", "mu** = (a k - b)/(d - c k)", "(4.96)-(4.97)",
            "slide-rock about O' needs mu <= mu** (left of the pole d/c)", "boundary",
            r"$\mu^{**}(k)$", _rational(cst.aP, -cst.bP, -cst.cP, cst.dP), p.k_F, p.k_pole,
            lambda k: mu_star_star(p, k))
    lift = p.lift_off
    if lift is not None:
        for name, kl, role in (("LO", lift[0], "lift-off starts (W i^2 + |S| = 0)"),
                               ("LO_end", lift[1], "lift-off ends (W i^2 + |S| = 0)")):
            if math.isfinite(kl) and (name == "LO" or lift[1] > lift[0]):
                out[name] = Curve(name, "k = k_L: W i^2 + |S| = 0", "docs/derivation.md 3.7", role,
                                  "boundary", "", {"type": "vertical", "k": kl}, kl, kl, None,
                                  vertical_k=kl)
    return out


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
    """The named points that exist (finite, k >= 0, the block pressing on the base) for ``p``.

    Above C (Chapter III): O, A (k_A, k_A) where OA, mu* and AB meet, C (0, 1/gamma)
    where CD meets the mu axis, D (1/(gamma k'), 0) where CD meets the k axis
    (k' > 0), and in cases 2/3 the point G (b/|a|, 0) where mu* = 0 (not named in
    the report).  Below C (Chapter IV): O, A, E (k_A, 0) the foot of AE, B'
    (4.48)-(4.49) when k' < 0, D (1/(gamma|k'|), 0) where DC meets the k axis,
    F (b/a, 0) where mu** = 0, and C' where mu* crosses DC.  With loads the
    generalised points (``docs/derivation.md`` Section 6) and L (k_L, 0), where
    lift-off starts.
    """
    pts: dict[str, NamedPoint] = {"O": NamedPoint("O", 0.0, 0.0, "origin")}
    kA = p.k_A
    onA = _finite(kA) and kA >= 0.0
    if onA:
        pts["A"] = NamedPoint("A", kA, p.mu_A, "OA, mu*, AB meet: k_A = 1/(gamma(1+k'))")
    if p.above:
        c_mu = float(upper_line(p, 0.0))
        if not p.loaded or (p.constants.w0 > 0.0 and c_mu >= 0.0):
            pts["C"] = NamedPoint("C", 0.0, c_mu if p.loaded else 1.0 / p.gamma,
                                  "line CD meets the mu axis")
        if _finite(p.k_D) and (p.kprime > 0.0 or p.loaded):
            pts["D"] = NamedPoint("D", p.k_D, 0.0, "line CD meets the k axis")
        if p.constants.aO < 0.0 and _finite(p.b_over_abs_a):
            pts["G"] = NamedPoint("G", p.b_over_abs_a, 0.0, "mu* = 0, f_x = 0 (k = b/|a|)")
    else:
        if onA:
            pts["E"] = NamedPoint("E", kA, 0.0, "foot of the vertical AE through A")
        if _finite(p.k_Bprime):
            pts["B'"] = NamedPoint("B'", p.k_Bprime, p.mu_Bprime,
                                    "mu* meets AB again (4.48)-(4.49)")
        if _finite(p.k_D):
            pts["D"] = NamedPoint("D", p.k_D, 0.0, "line DC meets the k axis")
            if _finite(p.k_F) and p.k_F >= 0.0:
                pts["F"] = NamedPoint("F", p.k_F, 0.0, "mu** = 0 (k = b/a)")
            kc = p.k_Cprime
            if kc is not None:
                pts["C'"] = NamedPoint("C'", kc, float(lower_line(p, kc)), "mu* meets DC")
        if p.loaded and p.constants.aO < 0.0 and _finite(p.b_over_abs_a):
            pts["G"] = NamedPoint("G", p.b_over_abs_a, 0.0, "mu* = 0, f_x = 0 (k = b_O/|a_O|)")
    if _finite(p.k_L):
        pts["L"] = NamedPoint("L", p.k_L, 0.0, "lift-off starts (W i^2 + |S| = 0)")
    if p.loaded:  # only the points of the map: k >= 0, mu >= 0, both finite
        pts = {n: q for n, q in pts.items() if _finite(q.k, q.mu) and q.k >= 0.0 and q.mu >= 0.0}
    return pts
