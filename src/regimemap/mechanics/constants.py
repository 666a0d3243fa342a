"""The closed forms of the map: the only place where each is written (the report's and the loaded block's).

Every function takes floats or numpy arrays (broadcast together) and is written
with the same operations, in the same order, wherever it is used, so that the
map (:mod:`regimemap.maps.classify`), the curves, the raw regions, the polygons
and the point queries compare against identical floats.  Every closed form in one module,
hence its length.

One sign convention serves both chapters: ``kprime`` is signed, ``h = kprime*H``,
positive above the centre of mass C (Chapter III) and negative below it
(Chapter IV, where the report writes ``|k'| = -kprime``).  Then (4.42)-(4.45)
are (3.18)-(3.21)::

    a = 4 + gamma**2 - 3*gamma**2*kprime      (3.18), (4.42)
    b = 3*gamma                               (3.19), (4.43)
    c = 3*gamma*(1 + kprime)                  (3.20), (4.44)
    d = 1 + 4*gamma**2                        (3.21), (4.45)

With loads (:mod:`regimemap.mechanics.loads`: buoyancy, uplift, inertia) every
form below is generalised; it takes a :class:`~regimemap.mechanics.loads.BlockConstants`
``cst`` and, at zero loads, is the report's form evaluated with the same
floating-point operations, bit for bit (``tests/mechanics/test_loaded_zero.py``).  With
``W = 1 - beta - u - nu k`` and ``s = k k' + e_u U/gamma`` (S/gamma) the lines
of the k-mu plane are (zero loads: W = 1, s = k k')::

    mu = k/W                     OA, the limit of rest by friction      (3.4), (4.7)
    k  = Q/P                     k_A: AB above C, AE below C             (3.5), (3.17), (4.10), (4.37)
    mu = 1/gamma - s/W           the upper line: CD above C, AB below    Section III.2, (4.21)
    mu = -1/gamma - s/W          the lower line: DC                      (4.20)
    mu = -s/W                    the dotted line below C (k|k'|)         (4.22)
    mu = s/W - 1/gamma           the dotted line of case 3               (3.44)
    mu = |a_O k + b_O|/(c_O k + d_O)     mu*(k)                          (3.24), (4.40)
    mu = (a_O' k - b_O')/(d_O' - c_O' k) mu**(k)                         (4.96)-(4.97)
    W i^2 + |S| <= 0             lift-off (whole columns, from the point L)
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .loads import BlockConstants, coefficients, net_load, uplift_load

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
    "lift_off_range",
    "lower_line",
    "mu_A",
    "mu_Bprime",
    "mu_star",
    "mu_star_signed",
    "mu_star_star",
    "rest_line",
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



# -- thresholds of k' (the report's cases, zero loads) --------------------------------------


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


# -- named abscissae and ordinates (scalars) -------------------------------------------------


def _w(cst: BlockConstants, k: float) -> float:
    return float(net_load(k, cst.buoyancy, cst.uplift, cst.uplift_ratio))


def _on_map(cst: BlockConstants, k: float) -> bool:
    """k is a finite abscissa >= 0 where the block presses on the base (W > 0)."""
    return math.isfinite(k) and k >= 0.0 and _w(cst, k) > 0.0


def k_A(cst: BlockConstants) -> float:
    """k_A = Q/P: rest about O ends (3.5), (3.17), (4.10), (4.37); 1/(gamma(1+k')) at zero loads.

    inf where P = 0 (k' = -1 at zero loads) and Q >= 0, -inf where Q < 0.
    """
    if cst.P == 0.0:
        return math.inf if cst.Q >= 0.0 else -math.inf
    return float(cst.Q / cst.P)


def mu_A(cst: BlockConstants) -> float:
    """mu at A: k_A/W(k_A) on OA (k_A at zero loads, (4.46)); inf where the block does not press there."""
    kA = k_A(cst)
    if not math.isfinite(kA):
        return kA
    w = _w(cst, kA)
    return float(kA / w) if w > 0.0 else math.inf


def mu_Bprime(cst: BlockConstants) -> float:
    """mu_B' = A0/(3 gamma) = (i^2+1)/gamma, (4.49) (4+g^2)/(3g): slide-rock about O is singular there."""
    return float(cst.A0 / (3.0 * cst.gamma))


def k_Bprime(cst: BlockConstants) -> float:
    """k_B': W i^2 + S = 0, where mu* meets the upper line at mu_B' again (4.48); inf if none.

    ``(W0 (3 i^2) + 3 e_u u)/(nu (3 i^2 - 3 e_u) - 3 gamma k')`` with 3 i^2 = 1 + g^2 + extra:
    (1+g^2)/(3 gamma |k'|) at zero loads, below C only.
    """
    three_i2 = (1.0 + cst.gamma**2) + cst.extra
    den = cst.uplift_ratio * (three_i2 - 3.0 * cst.uplift_arm) - 3.0 * cst.gamma * cst.kprime
    if not den > 0.0:
        return math.inf
    kb = float((cst.w0 * three_i2 + 3.0 * cst.uplift_arm * cst.uplift) / den)
    return kb if _on_map(cst, kb) else math.inf


def b_over_abs_a(a: float, b: float) -> float:
    """b/|a| (point G): where f_x of rocking changes sign when a < 0 (cases 2/3); inf if a >= 0.

    With loads: b_O/|a_O|.
    """
    if a >= 0.0:
        return math.inf
    return float(b / abs(a))


def k_D(cst: BlockConstants) -> float:
    """k where the upper line (k' >= 0) or the lower line (k' < 0) meets mu = 0; inf if nowhere.

    Q/(gamma k' + nu(1+e_u)) above C, Q'/(nu(1-e_u) - gamma k') below; 1/(gamma|k'|) at zero loads.
    """
    g, kp, nu, eu = cst.gamma, cst.kprime, cst.uplift_ratio, cst.uplift_arm
    if kp >= 0.0:
        num, den = cst.Q, g * kp + nu * (1.0 + eu)
    else:
        num, den = cst.Qp, nu * (1.0 - eu) - g * kp
    if den == 0.0:
        return math.inf
    k = float(num / den)
    return k if _on_map(cst, k) else math.inf


def k_F(a: float, b: float) -> float:
    """k_F = b/a, where mu** = 0 (Section IV.6); inf when a <= 0.  With loads: b_O'/a_O'."""
    return math.inf if a <= 0.0 else float(b / a)


def k_pole(c: float, d: float) -> float:
    """d/c, the pole of mu**(k) (4.97); inf at k' = -1.  With loads: d_O'/c_O'."""
    return math.inf if c == 0.0 else float(d / c)


def crossing_mu_star_lower(cst: BlockConstants) -> float | None:
    """C': the largest k where mu*(k) meets the lower line with mu >= 0 (a quadratic in k), or None.

    ``(a_O k + b_O) W = -(W/gamma + s)(c_O k + d_O)`` with ``W = W0 - nu k`` and
    ``W/gamma + s = (p0 + q k)/gamma``, ``p0 = W0 + e_u u``, ``q = gamma k' + nu(e_u - 1)``;
    at zero loads ``c|k'| k^2 + (d|k'| - c/g - a) k - (d/g + b) = 0``, the report's C'.
    """
    g, nu = cst.gamma, cst.uplift_ratio
    w0 = cst.w0
    p0 = w0 + cst.uplift_arm * cst.uplift
    mq = -cst.kprime - nu * (cst.uplift_arm - 1.0) / g  # -q/gamma: |k'| at zero loads
    aO, bO, cO, dO = cst.aO, cst.bO, cst.cO, cst.dO
    A2 = cO * mq + nu * aO
    A1 = dO * mq - (cO * p0) / g - aO * w0 + nu * bO
    A0 = -((dO * p0) / g + bO * w0)
    roots: list[float] = []
    if A2 != 0.0:
        disc = A1 * A1 - 4.0 * A2 * A0
        if disc >= 0.0:
            r = math.sqrt(disc)
            roots = [(-A1 + r) / (2.0 * A2), (-A1 - r) / (2.0 * A2)]
    elif A1 != 0.0:
        roots = [-A0 / A1]
    good = [float(x) for x in roots if x > 0.0 and _on_map(cst, x) and lower_line(x, cst) >= 0.0]
    return max(good) if good else None


def lift_off_range(cst: BlockConstants) -> tuple[float, float] | None:
    """[k1, k2] (k >= 0) where lift-off is consistent, W i^2 + |S| <= 0, or None (always at zero loads).

    Both ``W i^2 + S`` and ``W i^2 - S`` are linear in k: ``h0 + h1 k <= 0``.
    """
    g, eu, u, nu, i2 = cst.gamma, cst.uplift_arm, cst.uplift, cst.uplift_ratio, cst.i2
    w0 = cst.w0
    lo, hi = 0.0, math.inf
    for sgn in (1.0, -1.0):
        h0 = w0 * i2 + sgn * eu * u
        h1 = -nu * i2 + sgn * (g * cst.kprime + eu * nu)
        if h1 == 0.0:
            if h0 > 0.0:
                return None
        elif h1 > 0.0:
            hi = min(hi, -h0 / h1)
        else:
            lo = max(lo, -h0 / h1)
    return (float(lo), float(hi)) if lo <= hi else None


# -- the lines and curves of the k-mu plane (vectorised in k) ------------------------------


def _ws(k: Num, cst: BlockConstants) -> tuple[Num, Num]:
    """W and s = S/gamma = k k' + e_u U/gamma at k (W = 1.0, s = k k' exactly at zero loads)."""
    W = net_load(k, cst.buoyancy, cst.uplift, cst.uplift_ratio)
    s = k * cst.kprime + cst.uplift_arm * uplift_load(k, cst.uplift, cst.uplift_ratio) * (1.0 / cst.gamma)
    return W, s


def rest_line(k: Num, cst: BlockConstants) -> Num:
    """mu = k/W: OA, the limit of rest by friction (3.4), (4.7) (mu = k at zero loads)."""
    W, _ = _ws(k, cst)
    with np.errstate(divide="ignore", invalid="ignore"):
        return k / W


def rest_possible(k: Num, cst: BlockConstants) -> NDArray[np.bool_]:
    """k P <= Q and Q' + k P' >= 0 and W > 0: the reaction of rest inside the base (3.5), (4.10)."""
    W, _ = _ws(k, cst)
    return np.asarray((k * cst.P <= cst.Q) & (cst.Qp + k * cst.Pp >= 0.0) & (W > 0.0))


def rock_possible(k: Num, cst: BlockConstants) -> NDArray[np.bool_]:
    """k P >= Q (k >= k_A at zero loads): theta'' >= 0 in rocking about O, (3.17), (4.37)."""
    return np.asarray(k * cst.P >= cst.Q)


def upper_line(k: Num, cst: BlockConstants) -> Num:
    """mu = 1/gamma - s/W: CD above C (Section III.2), AB below C (4.21); xi = -B on it."""
    W, s = _ws(k, cst)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 1.0 / cst.gamma - s / W


def lower_line(k: Num, cst: BlockConstants) -> Num:
    """mu = -1/gamma - s/W (-1/gamma + k|k'| at zero loads): DC (4.20); xi = +B (at O') on it."""
    W, s = _ws(k, cst)
    with np.errstate(divide="ignore", invalid="ignore"):
        return -(1.0 / cst.gamma) - s / W


def dotted_line(k: Num, cst: BlockConstants) -> Num:
    """mu = -s/W (k|k'| below C at zero loads) (4.22): in sliding xi <= 0 above it, xi >= 0 below."""
    W, s = _ws(k, cst)
    with np.errstate(divide="ignore", invalid="ignore"):
        return -s / W


def dotted_line_344(k: Num, cst: BlockConstants) -> Num:
    """mu = s/W - 1/gamma (3.44): theta'' = 0 in slide-rock about O slipping right (case 3)."""
    return -upper_line(k, cst)


def mu_star_signed(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """(ak+b)/(ck+d) = f_x/f_y of rocking about O, (3.22)-(3.23), (4.38)-(4.39); mu* where >= 0.

    With loads the constants are a_O, b_O, c_O, d_O.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return (a * k + b) / (c * k + d)


def mu_star(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """mu*(k) = |ak+b|/(ck+d), (3.24) and (4.40)-(4.41): the friction rocking about O needs.

    With loads the constants are a_O, b_O, c_O, d_O.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(a * k + b) / (c * k + d)


def mu_star_star(k: Num, a: Num, b: Num, c: Num, d: Num) -> Num:
    """mu**(k) = (ak-b)/(d-ck), (4.96)-(4.97) with a from (4.42) (docs/errata.md E3).

    With loads the constants are a_O', b_O', c_O', d_O'.  Infinite at the pole
    k = d/c (+-inf) and negative beyond it; no warnings.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return (a * k - b) / (d - c * k)


class Thresholds(NamedTuple):
    """The per-k quantities the final map compares mu with (:func:`thresholds`)."""

    #: the net downward load W = 1 - beta - u - nu k (1.0 at zero loads)
    W: FloatArray
    #: the applied moment about C over gamma, s = k k' + e_u U/gamma
    s: FloatArray
    #: lift-off is consistent: W i^2 + |S| <= 0 (never at zero loads)
    lift_off: NDArray[np.bool_]
    #: rest is possible at some mu: k P <= Q, Q' + k P' >= 0, W > 0 (k <= k_A at zero loads)
    rest_ok: NDArray[np.bool_]
    #: OA: mu above which rest holds, k/W
    mu_rest: FloatArray
    #: the upper line CD/AB, 1/gamma - s/W
    upper: FloatArray
    #: the lower line DC, -1/gamma - s/W
    lower: FloatArray
    #: mu*(k) = |a_O k + b_O|/(c_O k + d_O)
    mu_star: FloatArray
    #: a_O k + b_O >= 0 (f_x of rocking >= 0): slide-rock about O slips left (SRO-) rather than right
    f_pos: NDArray[np.bool_]
    #: a regular column (every column at zero loads): W > 0, f_y of rocking about O > 0 and
    #: rest never failing about O'; there the report's rule holds with these thresholds
    regular: NDArray[np.bool_]


def thresholds(k: ArrayLike, cst: BlockConstants) -> Thresholds:
    """The thresholds of the final map at each k (see :mod:`regimemap.maps.classify`).

    Written with the operations of :func:`upper_line`, :func:`lower_line`,
    :func:`rest_line`, :func:`mu_star` and :func:`rest_possible`, sharing W and s.
    """
    k = np.asarray(k, dtype=np.float64)
    if _unloaded(cst):
        return _thresholds_unloaded(k, cst)
    W, s = _ws(k, cst)
    with np.errstate(divide="ignore", invalid="ignore"):
        sw = s / W
        inv_g = 1.0 / cst.gamma
        upper = inv_g - sw
        lower = -inv_g - sw
        mu_rest = k / W
        f = cst.aO * k + cst.bO
        den = cst.cO * k + cst.dO
        mu_s = np.abs(f) / den
    S = cst.gamma * s
    lift_off = W * cst.i2 + np.abs(S) <= 0.0
    rest_op = cst.Qp + k * cst.Pp >= 0.0
    rest_ok = (k * cst.P <= cst.Q) & rest_op & (W > 0.0)
    regular = (W > 0.0) & (den > 0.0) & rest_op
    return Thresholds(np.asarray(W), np.asarray(s), np.asarray(lift_off), np.asarray(rest_ok),
                      np.asarray(mu_rest), np.asarray(upper), np.asarray(lower), np.asarray(mu_s),
                      np.asarray(f >= 0.0), np.asarray(regular))


def _unloaded(cst: BlockConstants) -> bool:
    """True when no vertical load acts (scalar zeros): W = 1 and s = k k' exactly."""
    loads = (cst.buoyancy, cst.uplift, cst.uplift_ratio)
    return all(isinstance(v, float) and v == 0.0 for v in loads)


def _thresholds_unloaded(k: FloatArray, cst: BlockConstants) -> Thresholds:
    """:func:`thresholds` with no vertical load, with the operations that are identities dropped.

    With ``W = (1 - 0 - 0) - 0 k = 1`` and ``s = k k' + 0``: ``s/W``, ``k/W`` are
    ``k k'`` and ``k`` exactly; lift-off never happens (``W i^2 > 0``), ``Q' + k P' =
    1 + k gamma (1+k') > 0`` and ``c_O k + d_O = c k + d0 > 0`` for k >= 0, so every
    column is regular.  The same floats as the general path, half the work
    (this is what makes :func:`regimemap.classify` fast for the report's block).
    """
    kk = k * cst.kprime
    with np.errstate(divide="ignore", invalid="ignore"):
        inv_g = 1.0 / cst.gamma
        upper = inv_g - kk
        lower = -inv_g - kk
        f = cst.aO * k + cst.bO
        mu_s = np.abs(f) / (cst.cO * k + cst.dO)
    shape = np.shape(kk)
    return Thresholds(np.broadcast_to(1.0, shape), np.asarray(kk), np.broadcast_to(False, shape),
                      np.asarray(k * cst.P <= cst.Q), k, np.asarray(upper), np.asarray(lower),
                      np.asarray(mu_s), np.asarray(f >= 0.0), np.broadcast_to(True, shape))


def k_roots_at_mu(mu: FloatArray, gamma: FloatArray, kprime: FloatArray) -> FloatArray:
    """Every k where a threshold of the report's map (zero loads) equals mu; shape (n, 7).

    Columns: OA (k = mu), k_A, the upper line, the lower line, mu* with f_x >= 0
    (``k = (mu d - b)/(a - mu c)``), mu* with f_x <= 0 (``k = -(mu d + b)/(a + mu c)``)
    and f_x = 0 (``k = -b/a``).  Non-finite or negative entries are no roots.
    With loads every condition is affine in k at fixed mu: see
    :func:`regimemap.mechanics.regions.affine_terms`.
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
