"""The raw region of every mode: the set where its contact hypotheses are admissible.

Each predicate takes :class:`~regimemap.mechanics.block.Parameters` (with its
loads) and arrays of k and mu (broadcast together) and returns a boolean array;
boundaries are included (<=, >=).  On the report's block these are the report's
regions before Section 4.7, the single-mode figures (3.1-3.8 and 4.2-4.6); they
overlap below C, and Section 4.7 (:func:`regimemap.classify`) gives each point
one mode.  With loads the same conditions hold with the generalised constants
of :mod:`regimemap.mechanics.loads` (derivation: ``docs/derivation.md`` Section 3).

Along a column (fixed k) every condition is a sign condition on an expression
that is linear in mu (the slide-rock hypotheses split at mu_B', where their
denominator changes sign), so each raw region is at most two intervals of mu:
:func:`column_intervals` lists them in :data:`~regimemap.mechanics.modes.SELECTION_ORDER`,
the order of least constraint.  Every expression is moreover affine in k at
fixed mu (:func:`affine_terms`), which gives the exact margins along k.

Every predicate is cross-checked against the independent solver
(:mod:`regimemap.mechanics.solver`) in ``tests/mechanics/test_regions.py`` (zero loads)
and ``tests/mechanics/test_loaded_regions.py`` (loads).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .block import Parameters
from .loads import BlockConstants, applied_moment, net_load, uplift_load
from .modes import Mode

__all__ = [
    "RAW_REGIONS",
    "affine_terms",
    "column_intervals",
    "raw_region",
    "rule_expressions",
    "rest_region",
    "slide_region",
    "rock_region",
    "rock_prime_region",
    "slide_rock_minus_region",
    "slide_rock_plus_region",
    "slide_rock_prime_minus_region",
    "slide_rock_prime_plus_region",
    "lift_off_region",
]

Float = NDArray[np.float64]
Bool = NDArray[np.bool_]


def _km(k: ArrayLike, mu: ArrayLike) -> tuple[Float, Float]:
    kb, mb = np.broadcast_arrays(np.asarray(k, dtype=np.float64), np.asarray(mu, dtype=np.float64))
    return kb, mb


def affine_terms(k: ArrayLike, cst: BlockConstants) -> dict[str, Float]:
    """The expressions of k behind every condition (each affine in k), at each k.

    ``W``, ``S``; ``fxO``, ``fyO`` (3D f_x, 3D f_y of rocking about O: a_O k + b_O,
    c_O k + d_O); ``fxP``, ``fyP`` (of rocking about O': a_O' k - b_O', d_O' - c_O' k);
    ``TO`` = kP - Q = gamma k + S - W (D theta'' of RO; written as rest's
    condition kP <= Q is) and ``TP`` = Q' + kP' = gamma k + S + W (D theta'' of RO').
    """
    k = np.asarray(k, dtype=np.float64)
    g = cst.gamma
    W = net_load(k, cst.buoyancy, cst.uplift, cst.uplift_ratio)
    S = applied_moment(k, g, cst.kprime, cst.uplift_arm, uplift_load(k, cst.uplift, cst.uplift_ratio))
    return {
        "W": W, "S": S,
        "fxO": cst.aO * k + cst.bO, "fyO": cst.cO * k + cst.dO,
        "fxP": cst.aP * k - cst.bP, "fyP": cst.dP - cst.cP * k,
        "TO": k * cst.P - cst.Q, "TP": cst.Qp + k * cst.Pp,
    }


def rule_expressions(t: dict[str, Float], mu: Float, g: Float, i2: Float | float, k: float) -> list[Float]:
    """Every expression whose sign a condition of the classification rule tests, at one k.

    ``t`` is :func:`affine_terms` at that ``k`` (each expression is affine in k, so its root in
    k follows from its values at two k): the margins along k (:mod:`regimemap.maps.margins`)
    and the dynamics' events (:mod:`regimemap.dynamics.events`) find where the rule may change
    from them.
    """
    W, S = t["W"], t["S"]
    out = [W, S, t["TO"], t["TP"], t["fxO"], t["fyO"], t["fxP"], t["fyP"], W * i2 + S, W * i2 - S,
           mu * W - k]
    for sg in (1.0, -1.0):
        out += [W - S - sg * g * mu * W, W + S - sg * g * mu * W, S - W - sg * g * mu * W,
                mu * t["fyO"] - sg * t["fxO"], mu * t["fyP"] - sg * t["fxP"]]
    return out


# -- the predicates ---------------------------------------------------------------------------


def rest_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """RE: mu W >= k (3.4), (4.7) and the reaction inside the base, kP <= Q (3.5), (4.10), Q' + kP' >= 0."""
    k, mu = _km(k, mu)
    cst = p.constants
    W = net_load(k, cst.buoyancy, cst.uplift, cst.uplift_ratio)
    return np.asarray((mu * W >= k) & (k * cst.P <= cst.Q) & (cst.Qp + k * cst.Pp >= 0.0))


def slide_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """SL: f_y = W >= 0, slip against friction (mu W <= k to the left) and |xi| <= B.

    |xi| <= B is lower <= mu <= upper: below the line CD above C (Section III.2),
    between DC and AB below C (4.18)-(4.21).
    """
    k, mu = _km(k, mu)
    t = affine_terms(k, p.constants)
    W, S, g = t["W"], t["S"], p.gamma
    out = np.zeros(k.shape, dtype=bool)
    for sigma in (1.0, -1.0):
        m = g * sigma * mu * W + S  # minus the moment of the reaction about C
        out |= (W >= 0.0) & (sigma * (sigma * mu * W - k) <= 0.0) & (m <= W) & (m >= -W)
    return out


def _rock(p: Parameters, k: ArrayLike, mu: ArrayLike, corner: str) -> Bool:
    k, mu = _km(k, mu)
    t = affine_terms(k, p.constants)
    if corner == "O":
        return np.asarray((t["TO"] >= 0.0) & (t["fyO"] >= 0.0) & (np.abs(t["fxO"]) <= mu * t["fyO"]))
    return np.asarray((t["TP"] <= 0.0) & (t["fyP"] >= 0.0) & (np.abs(t["fxP"]) <= mu * t["fyP"]))


def rock_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """RO (about O): theta'' >= 0, k >= k_A (3.17), (4.37), f_y >= 0 and mu >= mu*(k) (3.24), (4.40)."""
    return _rock(p, k, mu, "O")


def rock_prime_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """RO' (about O'): O lifts, Q' + kP' <= 0 (never on the report's block, (4.57)), f_y >= 0, mu >= mu*'."""
    return _rock(p, k, mu, "O'")


def _slide_rock(p: Parameters, k: ArrayLike, mu: ArrayLike, corner: str, sigma: float) -> Bool:
    """Slide-rock about a corner slipping left (sigma = +1) or right (sigma = -1)."""
    k, mu = _km(k, mu)
    cst = p.constants
    t = affine_terms(k, cst)
    W, S, g, i2 = t["W"], t["S"], cst.gamma, cst.i2
    if corner == "O":
        den = cst.A0 - 3.0 * sigma * mu * g  # 3 (i^2 + 1 - sigma mu gamma)
        T = W * (sigma * mu * g - 1.0) + S  # theta'' >= 0
        fy = W * i2 + S
        xo = sigma * mu * t["fyO"] - t["fxO"]  # 3 den x_O''
        sd = np.sign(den)
        return np.asarray((den != 0.0) & (T * sd >= 0.0) & (fy * sd >= 0.0) & (sigma * xo * sd <= 0.0))
    den = cst.A0 + 3.0 * sigma * mu * g  # 3 (i^2 + 1 + sigma mu gamma)
    T = W * (sigma * mu * g + 1.0) + S  # theta'' <= 0
    fy = W * i2 - S
    xo = sigma * mu * t["fyP"] - t["fxP"]
    sd = np.sign(den)
    return np.asarray((den != 0.0) & (T * sd <= 0.0) & (fy * sd >= 0.0) & (sigma * xo * sd <= 0.0))


def slide_rock_minus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """SRO-: slide-rock about O with x_O'' <= 0.

    theta'' >= 0 from (3.30)/(4.64) and x_O'' <= 0 from (3.37)/(4.76), each a
    sign condition on a ratio with denominator 3(i^2 + 1 - mu gamma) (4 + g^2 - 3 mu g):

    * mu < mu_B': mu >= upper line and mu <= (a_O k + b_O)/(c_O k + d_O),
      i.e. (3.42) above C and (4.67), (4.68), (4.77), (4.78) below C;
    * mu > mu_B': mu <= upper line and mu >= that ratio, (4.69), (4.70),
      (4.80), (4.81); empty above C (3.36), and below C deleted by Section 4.7
      (the solver finds another mode admissible at each of its points).
    """
    return _slide_rock(p, k, mu, "O", 1.0)


def slide_rock_plus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """SRO+: slide-rock about O with x_O'' >= 0 (Section III.4, case 3, Fig 3.8).

    theta'' >= 0 needs mu <= -1/gamma + k k' (3.44); x_O'' >= 0 from (3.45)
    needs a_O k + b_O <= 0 (f_x <= 0, k >= b/|a|) and mu <= mu*(k).  Empty below
    C on the report's block, where a > 0.
    """
    return _slide_rock(p, k, mu, "O", -1.0)


def slide_rock_prime_minus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """SRO'-: slide-rock about O' with x_O''' <= 0 (Section IV.6, Fig 4.6).

    theta'' <= 0 gives mu <= lower line (4.92), below DC.  x_O''' <= 0 from
    (4.95) gives mu <= mu**(k) (4.96) for k < d/c, and holds for every mu when
    k >= d/c (the report omits this; see docs/errata.md).  Empty above C on the
    report's block.
    """
    return _slide_rock(p, k, mu, "O'", 1.0)


def slide_rock_prime_plus_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """SRO'+: slide-rock about O' slipping right (never on the report's block)."""
    return _slide_rock(p, k, mu, "O'", -1.0)


def lift_off_region(p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """LO: no contact force is consistent, W i^2 + |S| <= 0 (whole columns; never at zero loads)."""
    k, mu = _km(k, mu)
    t = affine_terms(k, p.constants)
    return np.asarray((t["W"] * p.constants.i2 + np.abs(t["S"]) <= 0.0) & (mu >= 0.0))


RAW_REGIONS: dict[Mode, Callable[[Parameters, ArrayLike, ArrayLike], Bool]] = {
    Mode.RE: rest_region,
    Mode.SL: slide_region,
    Mode.RO: rock_region,
    Mode.SRO_MINUS: slide_rock_minus_region,
    Mode.SRO_PLUS: slide_rock_plus_region,
    Mode.SRO_PRIME_MINUS: slide_rock_prime_minus_region,
    Mode.RO_PRIME: rock_prime_region,
    Mode.SRO_PRIME_PLUS: slide_rock_prime_plus_region,
    Mode.LO: lift_off_region,
}


def raw_region(mode: Mode, p: Parameters, k: ArrayLike, mu: ArrayLike) -> Bool:
    """The raw region of ``mode`` (before Section 4.7 or least constraint choose one mode)."""
    return RAW_REGIONS[Mode(mode)](p, k, mu)


# -- the same regions as intervals of mu per column ------------------------------------------


def _halfline(alpha: Float, beta: Float) -> tuple[Float, Float]:
    """{mu : alpha + beta mu >= 0} as a closed interval [lo, hi] (empty: lo = inf, hi = -inf)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -alpha / beta
    never = (beta == 0.0) & (alpha < 0.0)
    lo = np.where(beta > 0.0, t, np.where(never, np.inf, -np.inf))
    hi = np.where(beta < 0.0, t, np.where(never, -np.inf, np.inf))
    return lo, hi


class _Box:
    """An interval [lo, hi] of mu per k, built by intersecting half-lines and k-only conditions."""

    def __init__(self, shape: tuple[int, ...]) -> None:
        self.lo = np.full(shape, -np.inf)
        self.hi = np.full(shape, np.inf)

    def linear(self, alpha: Any, beta: Any) -> _Box:
        """Keep mu with alpha + beta mu >= 0."""
        lo, hi = _halfline(np.broadcast_to(np.asarray(alpha, dtype=np.float64), self.lo.shape),
                           np.broadcast_to(np.asarray(beta, dtype=np.float64), self.lo.shape))
        self.lo = np.maximum(self.lo, lo)
        self.hi = np.minimum(self.hi, hi)
        return self

    def when(self, cond: Any) -> _Box:
        """Keep the interval only where the k-only condition holds."""
        cond = np.broadcast_to(np.asarray(cond, dtype=bool), self.lo.shape)
        self.lo = np.where(cond, self.lo, np.inf)
        self.hi = np.where(cond, self.hi, -np.inf)
        return self

    def below(self, t: Any) -> _Box:
        """Keep mu < t (mu <= the float just below t)."""
        self.hi = np.minimum(self.hi, np.nextafter(t, -np.inf))
        return self

    def above(self, t: Any) -> _Box:
        """Keep mu > t."""
        self.lo = np.maximum(self.lo, np.nextafter(t, np.inf))
        return self


def column_intervals(k: ArrayLike, cst: BlockConstants) -> list[tuple[Mode, Float, Float]]:
    """Every hypothesis's admissible set at each k as closed intervals [lo, hi] of mu.

    In :data:`~regimemap.mechanics.modes.SELECTION_ORDER` (lift-off, RE, SL
    (left, right), SRO'-, RO, SRO- (two branches about mu_B'), SRO+, RO', SRO'+
    (two branches)); empty intervals have lo > hi.  Strict ends (mu != mu_B')
    use the neighbouring float, so every test is ``lo <= mu <= hi``.  The
    conditions are those of the predicates above; their derivation is in
    ``docs/derivation.md`` Section 5.
    """
    k = np.asarray(k, dtype=np.float64)
    t = affine_terms(k, cst)
    W, S, g, i2 = t["W"], t["S"], cst.gamma, cst.i2
    shape = k.shape
    mb = cst.A0 / (3.0 * g)  # mu_B'
    out: list[tuple[Mode, Float, Float]] = []

    def add(mode: Mode, box: _Box) -> None:
        out.append((mode, box.lo, box.hi))

    add(Mode.LO, _Box(shape).when(W * i2 + np.abs(S) <= 0.0))
    add(Mode.RE, _Box(shape).linear(-k, W).when((k * cst.P <= cst.Q) & (cst.Qp + k * cst.Pp >= 0.0)))
    for sigma in (1.0, -1.0):  # slide left, right: slip against friction, xi in [-1, 1]
        add(Mode.SL, _Box(shape).linear(sigma * k, -W).linear(W - S, -sigma * g * W)
            .linear(W + S, sigma * g * W).when(W >= 0.0))
    # slide-rock about O' slipping left: den = A0 + 3 mu gamma > 0
    add(Mode.SRO_PRIME_MINUS, _Box(shape).linear(-(W + S), -g * W).when(W * i2 - S >= 0.0)
        .linear(t["fxP"], -t["fyP"]))
    add(Mode.RO, _Box(shape).linear(-np.abs(t["fxO"]), t["fyO"]).when((t["TO"] >= 0.0) & (t["fyO"] >= 0.0)))
    # slide-rock about O slipping left: den = A0 - 3 mu gamma, two branches about mu_B'
    add(Mode.SRO_MINUS, _Box(shape).below(mb).linear(S - W, g * W).when(W * i2 + S >= 0.0)
        .linear(t["fxO"], -t["fyO"]))
    add(Mode.SRO_MINUS, _Box(shape).above(mb).linear(W - S, -g * W).when(W * i2 + S <= 0.0)
        .linear(-t["fxO"], t["fyO"]))
    # slide-rock about O slipping right: den = A0 + 3 mu gamma > 0
    add(Mode.SRO_PLUS, _Box(shape).linear(S - W, -g * W).when(W * i2 + S >= 0.0)
        .linear(-t["fxO"], -t["fyO"]))
    add(Mode.RO_PRIME, _Box(shape).linear(-np.abs(t["fxP"]), t["fyP"])
        .when((t["TP"] <= 0.0) & (t["fyP"] >= 0.0)))
    # slide-rock about O' slipping right: den = A0 - 3 mu gamma, two branches
    add(Mode.SRO_PRIME_PLUS, _Box(shape).below(mb).linear(-(W + S), g * W).when(W * i2 - S >= 0.0)
        .linear(-t["fxP"], -t["fyP"]))
    add(Mode.SRO_PRIME_PLUS, _Box(shape).above(mb).linear(W + S, -g * W).when(W * i2 - S <= 0.0)
        .linear(t["fxP"], t["fyP"]))
    return out
