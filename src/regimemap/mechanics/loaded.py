"""Closed forms of the loaded block (issue 10): constants, raw regions, the column rule.

The block of the report (Chapters III-IV) with, besides gravity and the push
F = m g k (to the left, at height ``kprime*H_C`` above the centre of mass C):

* buoyancy ``beta m g`` upward through C's vertical;
* uplift ``U = (u + nu k) m g`` upward at ``e_u B`` from C towards O' (the
  seaward corner; ``e_u = 1/3`` is Goda's triangle, zero under O);
* any inertia ``I = m B^2 i^2`` (``gyration = i``; None is the uniform block,
  ``i^2 = (1 + gamma^2)/3``), ``gamma = H_C/B`` the height of C over the half width.

Per unit m g and B, the net downward load is ``W = 1 - beta - u - nu k`` and the
applied moment about C (counter-clockwise, i.e. lifting O') is
``S = gamma k k' + e_u U``.  The derivation of every formula below is in
``docs/derivation.md``; at zero loads and uniform inertia each one is the
report's expression evaluated with the same floating-point operations as
:mod:`regimemap.classify` / :class:`regimemap.params.Parameters`, so
:func:`classify_loaded` is bit-for-bit :func:`regimemap.classify.classify` there.

Generalised constants (``extra = 3 i^2 - (1 + gamma^2)``, 0.0 for the uniform
block; ``A0 = 4 + gamma^2 + extra = 3(i^2 + 1)``; ``d0 = d + extra = 3(i^2 + gamma^2)``)::

    P  = gamma(1+k') + nu(1+e_u)       Q  = 1 - beta - u(1+e_u)     (rest about O: k P <= Q)
    P' = gamma(1+k') - nu(1-e_u)       Q' = 1 - beta - u(1-e_u)     (rest about O': Q' + k P' >= 0)
    a_O = a + (extra - 3 gamma nu (1+e_u))   b_O = b Q               (3 D f_x of rocking about O)
    c_O = c - nu (d0 - 3 e_u)                d_O = d0 (1-beta-u) + 3 e_u u   (3 D f_y)
    a_O' = a + (extra + 3 gamma nu (1-e_u))  b_O' = b Q'             (3 D f_x of rocking about O')
    c_O' = c + nu (d0 + 3 e_u)               d_O' = d0 (1-beta-u) - 3 e_u u  (3 D f_y = d_O' - c_O' k)

with ``D = i^2 + 1 + gamma^2``.  Lines: ``upper = 1/gamma - (k k' + e_u U/gamma)/W`` (xi = -B,
CD/AB), ``lower = -1/gamma - (k k' + e_u U/gamma)/W`` (xi = +B, DC); ``mu* = |a_O k + b_O|/(c_O k + d_O)``,
``mu** = (a_O' k - b_O')/(d_O' - c_O' k)``, ``mu_B' = A0/(3 gamma)``.

Mode codes are :class:`~regimemap.modes.Mode` values, and :data:`LO` (8) for lift-off.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .modes import Mode

__all__ = [
    "LO",
    "LoadedConstants",
    "Thresholds",
    "loaded_constants",
    "thresholds",
    "classify_loaded",
    "column_segments_loaded",
    "label_grid_loaded",
    "RAW_REGIONS_LOADED",
    "raw_region_loaded",
    "named_points_loaded",
    "mu_star_signed_loaded",
    "mu_star_star_loaded",
    "LoadedPoint",
]

#: Mode code of lift-off (no contact force): the codes 0..7 are :class:`Mode`.
LO: int = 8

Float = NDArray[np.float64]
Bool = NDArray[np.bool_]
U8 = NDArray[np.uint8]

_RE, _SL, _RO, _SM, _SP, _SPM, _ROP, _SPP = (np.uint8(m) for m in (
    Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS, Mode.SRO_PRIME_MINUS,
    Mode.RO_PRIME, Mode.SRO_PRIME_PLUS))
_LO = np.uint8(LO)


@dataclass(frozen=True)
class LoadedConstants:
    """Validated parameters of a loaded map and their derived constants (floats).

    Parameters are those of :func:`classify_loaded`; the derived constants are
    listed in the module docstring.  Build with :func:`loaded_constants`.
    """

    gamma: float
    kprime: float
    buoyancy: float
    uplift: float
    uplift_ratio: float
    uplift_arm: float
    gyration: float | None
    crest: float
    i2: float
    extra: float
    a: float
    b: float
    c: float
    d: float
    A0: float
    d0: float
    P: float
    Q: float
    Pp: float
    Qp: float
    aO: float
    bO: float
    cO: float
    dO: float
    aP: float
    bP: float
    cP: float
    dP: float

    @property
    def mu_Bprime(self) -> float:
        """A0/(3 gamma) = (i^2 + 1)/gamma: slide-rock about O slipping left is singular there (4.49)."""
        return self.A0 / (3.0 * self.gamma)

    @property
    def k_A(self) -> float:
        """Q/P: rest about O ends (the vertical through A), (3.5)/(4.10) generalised; inf if P = 0."""
        if self.P == 0.0:
            return math.inf if self.Q >= 0.0 else -math.inf
        return self.Q / self.P

    @property
    def k_LO(self) -> float:
        """k where W = 0 (the net vertical load vanishes); inf without nu or when W never vanishes."""
        w0 = 1.0 - self.buoyancy - self.uplift
        if self.uplift_ratio == 0.0:
            return math.inf if w0 > 0.0 else 0.0
        return max(w0 / self.uplift_ratio, 0.0)


def _check(name: str, value: Any, lo: float, hi: float, lo_open: bool = False, hi_open: bool = False
           ) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    bad = (not math.isfinite(v)) or v < lo or v > hi or (lo_open and v == lo) or (hi_open and v == hi)
    if bad:
        left = "(" if lo_open else "["
        right = ")" if hi_open else "]"
        raise ValueError(f"{name} must be in {left}{lo}, {hi}{right}, got {value!r}")
    return v


def loaded_constants(gamma: float, kprime: float, *, buoyancy: float = 0.0, uplift: float = 0.0,
                     uplift_ratio: float = 0.0, uplift_arm: float = 1.0 / 3.0,
                     gyration: float | None = None, crest: float = 1.0) -> LoadedConstants:
    """Validate the parameters and compute the generalised constants.

    Raises
    ------
    ValueError
        gamma not > 0, crest not > 0, kprime not in [-1, crest], buoyancy not in
        [0, 1), uplift or uplift_ratio < 0, uplift_arm not in [-1, 1], gyration not > 0.
    """
    g = _check("gamma", gamma, 0.0, math.inf, lo_open=True)
    cr = _check("crest", crest, 0.0, math.inf, lo_open=True)
    kp = _check("kprime", kprime, -1.0, cr) + 0.0  # fold -0.0
    beta = _check("buoyancy", buoyancy, 0.0, 1.0, hi_open=True)
    u = _check("uplift", uplift, 0.0, math.inf)
    nu = _check("uplift_ratio", uplift_ratio, 0.0, math.inf)
    eu = _check("uplift_arm", uplift_arm, -1.0, 1.0)
    g2 = g * g
    if gyration is None:
        gy: float | None = None
        i2 = (1.0 + g2) / 3.0
        extra = 0.0
    else:
        gy = _check("gyration", gyration, 0.0, math.inf, lo_open=True)
        i2 = gy * gy
        extra = 3.0 * i2 - (1.0 + g2)
    # the report's constants exactly as regimemap.classify._constants computes them
    a = 4.0 + g2 - 3.0 * g2 * kp
    b = 3.0 * g
    c = 3.0 * g * (1.0 + kp)
    d = 1.0 + 4.0 * g2
    A0 = (4.0 + g2) + extra
    d0 = d + extra
    w0 = 1.0 - beta - u
    return LoadedConstants(
        gamma=g, kprime=kp, buoyancy=beta, uplift=u, uplift_ratio=nu, uplift_arm=eu, gyration=gy,
        crest=cr, i2=i2, extra=extra, a=a, b=b, c=c, d=d, A0=A0, d0=d0,
        P=g * (1.0 + kp) + nu * (1.0 + eu), Q=1.0 - beta - u * (1.0 + eu),
        Pp=g * (1.0 + kp) - nu * (1.0 - eu), Qp=1.0 - beta - u * (1.0 - eu),
        aO=a + (extra - 3.0 * g * nu * (1.0 + eu)), bO=b * (1.0 - beta - u * (1.0 + eu)),
        cO=c - nu * (d0 - 3.0 * eu), dO=d0 * w0 + 3.0 * eu * u,
        aP=a + (extra + 3.0 * g * nu * (1.0 - eu)), bP=b * (1.0 - beta - u * (1.0 - eu)),
        cP=c + nu * (d0 + 3.0 * eu), dP=d0 * w0 - 3.0 * eu * u,
    )


class Thresholds(NamedTuple):
    """Per-k quantities of the column rule (arrays of k's shape)."""

    #: net downward load W = 1 - beta - u - nu k
    W: Float
    #: applied moment about C over gamma, S/gamma = k k' + e_u U/gamma
    s: Float
    #: lift-off: no contact force can be consistent (W i^2 + |S| <= 0)
    lift_off: Bool
    #: rest possible at some mu (k P <= Q, Q' + k P' >= 0, W > 0)
    rest_ok: Bool
    #: mu above which rest holds: k/W
    mu_rest: Float
    #: upper line (xi = -B): 1/gamma - s/W
    upper: Float
    #: lower line (xi = +B): -1/gamma - s/W
    lower: Float
    #: mu* = |a_O k + b_O|/(c_O k + d_O)
    mu_star: Float
    #: a_O k + b_O >= 0 (f_x of rocking about O to the right)
    f_pos: Bool
    #: regular column: W > 0, rocking about O has f_y > 0 and rest never fails about O'
    regular: Bool


def thresholds(k: ArrayLike, cst: LoadedConstants) -> Thresholds:
    """The per-k thresholds of the column rule (see :func:`classify_loaded`)."""
    k = np.asarray(k, dtype=np.float64)
    g, kp, eu = cst.gamma, cst.kprime, cst.uplift_arm
    inv_g = 1.0 / g
    W = (1.0 - cst.buoyancy - cst.uplift) - cst.uplift_ratio * k
    up = cst.uplift + cst.uplift_ratio * k
    s = k * kp + eu * up * inv_g
    with np.errstate(divide="ignore", invalid="ignore"):
        sw = s / W
        upper = inv_g - sw
        lower = -inv_g - sw
        mu_rest = k / W
        f = cst.aO * k + cst.bO
        den = cst.cO * k + cst.dO
        mu_s = np.abs(f) / den
    S = g * s
    lift_off = W * cst.i2 + np.abs(S) <= 0.0
    rest_o = k * cst.P <= cst.Q
    rest_op = cst.Qp + k * cst.Pp >= 0.0
    rest_ok = rest_o & rest_op & (W > 0.0)
    regular = (W > 0.0) & (den > 0.0) & rest_op
    return Thresholds(W, s, lift_off, rest_ok, mu_rest, upper, lower, mu_s, f >= 0.0, regular)


def mu_star_signed_loaded(k: ArrayLike, cst: LoadedConstants) -> Float:
    """(a_O k + b_O)/(c_O k + d_O): f_x/f_y of rocking about O ((3.22)-(3.23) generalised)."""
    k = np.asarray(k, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        out: Float = (cst.aO * k + cst.bO) / (cst.cO * k + cst.dO)
    return out


def mu_star_star_loaded(k: ArrayLike, cst: LoadedConstants) -> Float:
    """mu**(k) = (a_O' k - b_O')/(d_O' - c_O' k), where the slip of O' in SRO'- vanishes ((4.96)-(4.97))."""
    k = np.asarray(k, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        out: Float = (cst.aP * k - cst.bP) / (cst.dP - cst.cP * k)
    return out


def _validate_km(k: ArrayLike, mu: ArrayLike) -> tuple[Float, Float]:
    k_arr = np.asarray(k, dtype=np.float64)
    mu_arr = np.asarray(mu, dtype=np.float64)
    for name, v in (("k", k_arr), ("mu", mu_arr)):
        if v.size and not (np.isfinite(v).all() and (v >= 0.0).all()):
            raise ValueError(f"{name} must be finite and >= 0")
    kb, mb = np.broadcast_arrays(k_arr, mu_arr)
    return kb, mb


# -- raw regions (each hypothesis's admissible set, closed form) ----------------------------------------

def _pivot_terms(k: Float, cst: LoadedConstants) -> dict[str, Float]:
    """Numerators of the pivot hypotheses (signs only matter; see docs/derivation.md)."""
    g = cst.gamma
    W = (1.0 - cst.buoyancy - cst.uplift) - cst.uplift_ratio * k
    S = g * k * cst.kprime + cst.uplift_arm * (cst.uplift + cst.uplift_ratio * k)
    return {
        "W": W, "S": S,
        "fxO": cst.aO * k + cst.bO, "fyO": cst.cO * k + cst.dO,  # 3 D f_x, 3 D f_y of RO
        "fxP": cst.aP * k - cst.bP, "fyP": cst.dP - cst.cP * k,  # of RO'
        "TO": g * k + S - W,  # D theta'' of RO
        "TP": g * k + S + W,  # D theta'' of RO'
    }


def _rest(k: Float, mu: Float, cst: LoadedConstants) -> Bool:
    t = _pivot_terms(k, cst)
    W = t["W"]
    return (mu * W >= k) & (k * cst.P <= cst.Q) & (cst.Qp + k * cst.Pp >= 0.0)


def _slide(k: Float, mu: Float, cst: LoadedConstants) -> Bool:
    """Slide in either direction (fx = +-mu W, fy = W, |xi| <= 1, slip against friction)."""
    t = _pivot_terms(k, cst)
    W, S, g = t["W"], t["S"], cst.gamma
    out = np.zeros(k.shape, dtype=bool)
    for sigma in (1.0, -1.0):
        m = g * sigma * mu * W + S  # -M, the moment of the reaction's point about C
        out |= (W >= 0.0) & (sigma * (sigma * mu * W - k) <= 0.0) & (m <= W) & (m >= -W)
    return out


def _rock(k: Float, mu: Float, cst: LoadedConstants, corner: str) -> Bool:
    t = _pivot_terms(k, cst)
    if corner == "O":
        return (t["TO"] >= 0.0) & (t["fyO"] >= 0.0) & (np.abs(t["fxO"]) <= mu * t["fyO"])
    return (t["TP"] <= 0.0) & (t["fyP"] >= 0.0) & (np.abs(t["fxP"]) <= mu * t["fyP"])


def _slide_rock(k: Float, mu: Float, cst: LoadedConstants, corner: str, sigma: float) -> Bool:
    """Slide-rock about a corner slipping left (sigma = +1) or right (sigma = -1)."""
    t = _pivot_terms(k, cst)
    W, S, g, i2 = t["W"], t["S"], cst.gamma, cst.i2
    if corner == "O":
        den = cst.A0 - 3.0 * sigma * mu * g  # 3 (i^2 + 1 - sigma mu gamma)
        T = W * (sigma * mu * g - 1.0) + S  # theta'' >= 0
        fy = W * i2 + S
        xo = sigma * mu * t["fyO"] - t["fxO"]  # 3 den x_O''
        sd = np.sign(den)
        out: Bool = (den != 0.0) & (T * sd >= 0.0) & (fy * sd >= 0.0) & (sigma * xo * sd <= 0.0)
        return out
    den = cst.A0 + 3.0 * sigma * mu * g  # 3 (i^2 + 1 + sigma mu gamma)
    T = W * (sigma * mu * g + 1.0) + S  # theta'' <= 0
    fy = W * i2 - S
    xo = sigma * mu * t["fyP"] - t["fxP"]
    sd = np.sign(den)
    res: Bool = (den != 0.0) & (T * sd <= 0.0) & (fy * sd >= 0.0) & (sigma * xo * sd <= 0.0)
    return res


def _lift_off(k: Float, mu: Float, cst: LoadedConstants) -> Bool:
    t = _pivot_terms(k, cst)
    return (t["W"] * cst.i2 + np.abs(t["S"]) <= 0.0) & (mu >= 0.0)


def _region(fn: Callable[..., Bool], *args: Any) -> Callable[[LoadedConstants, ArrayLike, ArrayLike], Bool]:
    def region(cst: LoadedConstants, k: ArrayLike, mu: ArrayLike) -> Bool:
        kb, mb = np.broadcast_arrays(np.asarray(k, dtype=np.float64), np.asarray(mu, dtype=np.float64))
        return fn(kb, mb, cst, *args)
    region.__doc__ = fn.__doc__
    return region


#: The raw region (admissible set of the hypotheses of that mode) of every mode code,
#: as predicates ``region(cst, k, mu) -> bool array``; boundaries included.
RAW_REGIONS_LOADED: dict[int, Callable[[LoadedConstants, ArrayLike, ArrayLike], Bool]] = {
    int(Mode.RE): _region(_rest),
    int(Mode.SL): _region(_slide),
    int(Mode.RO): _region(_rock, "O"),
    int(Mode.SRO_MINUS): _region(_slide_rock, "O", 1.0),
    int(Mode.SRO_PLUS): _region(_slide_rock, "O", -1.0),
    int(Mode.SRO_PRIME_MINUS): _region(_slide_rock, "O'", 1.0),
    int(Mode.RO_PRIME): _region(_rock, "O'"),
    int(Mode.SRO_PRIME_PLUS): _region(_slide_rock, "O'", -1.0),
    LO: _region(_lift_off),
}


def raw_region_loaded(code: int, cst: LoadedConstants, k: ArrayLike, mu: ArrayLike) -> Bool:
    """The raw region of mode ``code`` (a :class:`Mode` value or :data:`LO`)."""
    return RAW_REGIONS_LOADED[int(code)](cst, k, mu)


# -- the final rule -------------------------------------------------------------------------------------

def classify_loaded(k: ArrayLike, mu: ArrayLike, gamma: float, kprime: float, *, buoyancy: float = 0.0,
                    uplift: float = 0.0, uplift_ratio: float = 0.0, uplift_arm: float = 1.0 / 3.0,
                    gyration: float | None = None, crest: float = 1.0) -> U8:
    """Mode code (uint8) at each point (k, mu) of the loaded block.

    Parameters
    ----------
    k, mu : array_like
        Force F/(mg) >= 0 and friction coefficient >= 0 (broadcast together).
    gamma : float
        H_C/B > 0 (height of C over the half width).
    kprime : float
        Height of the push above C over H_C, in [-1, crest].
    buoyancy : float
        beta in [0, 1), upward through C.
    uplift, uplift_ratio : float
        Uplift U = (uplift + uplift_ratio k) m g >= 0.
    uplift_arm : float
        e_u in [-1, 1]: the uplift acts at e_u B from C towards O'.
    gyration : float or None
        Radius of gyration about C over B (None: uniform block).
    crest : float
        Height of the crest above C over H_C (upper end of kprime).

    Returns
    -------
    ndarray of uint8
        :class:`Mode` codes, :data:`LO` for lift-off.  At zero loads and uniform
        inertia this is :func:`regimemap.classify.classify` bit for bit.

    Raises
    ------
    ValueError
        For parameters out of range (see :func:`loaded_constants`) or k, mu
        negative or not finite.

    Notes
    -----
    The label is the first admissible mode in the selection order LO, RE, SL,
    SRO'-, RO, SRO-, SRO+, RO', SRO'+ (Gauss's least constraint, measured).
    In a *regular* column (``Thresholds.regular``: W > 0, f_y of rocking about
    O > 0, rest not failing about O') this is the report's rule with the
    generalised thresholds, from mu = 0 up::

        SRO'-  mu < lower;  SL  lower <= mu <= upper;  SRO-/SRO+ (sign of a_O k + b_O);
        RO  mu >= mu*;  RE  mu >= k/W where k P <= Q (overrides)

    Lift-off (W i^2 + |S| <= 0) is a whole column.  Other columns take the
    first of the per-k mu-intervals of every hypothesis.  Derivation:
    ``docs/derivation.md``.
    """
    cst = loaded_constants(gamma, kprime, buoyancy=buoyancy, uplift=uplift, uplift_ratio=uplift_ratio,
                           uplift_arm=uplift_arm, gyration=gyration, crest=crest)
    kb, mb = _validate_km(k, mu)
    return _classify(kb, mb, cst)


def _structured(k: Float, mu: Float, t: Thresholds) -> U8:
    """The rule of :func:`regimemap.classify.classify` with the generalised thresholds (regular columns)."""
    out = np.where(t.f_pos, _SM, _SP)
    np.copyto(out, _RO, where=mu >= t.mu_star)
    np.copyto(out, _SL, where=mu <= t.upper)
    np.copyto(out, _SPM, where=mu < t.lower)
    np.copyto(out, _RE, where=(mu >= t.mu_rest) & t.rest_ok)
    return np.asarray(out, dtype=np.uint8)


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

    def below(self, t: float) -> _Box:
        """Keep mu < t (mu <= the float just below t)."""
        self.hi = np.minimum(self.hi, np.nextafter(t, -np.inf))
        return self

    def above(self, t: float) -> _Box:
        """Keep mu > t."""
        self.lo = np.maximum(self.lo, np.nextafter(t, np.inf))
        return self


def _intervals(k: Float, cst: LoadedConstants) -> list[tuple[np.uint8, Float, Float]]:
    """Every hypothesis's admissible set at fixed k as closed mu-intervals, in selection order.

    The selection order (lift-off, RE, SL, SRO'-, RO, SRO-, SRO+, RO', SRO'+) is
    the order of least constraint wherever several modes are admissible (see
    docs/derivation.md and the tests); the first interval holding mu wins.
    """
    t = _pivot_terms(k, cst)
    W, S, g, i2 = t["W"], t["S"], cst.gamma, cst.i2
    shape = k.shape
    mb = cst.mu_Bprime
    out: list[tuple[np.uint8, Float, Float]] = []

    def add(code: np.uint8, box: _Box) -> None:
        out.append((code, box.lo, box.hi))

    add(_LO, _Box(shape).when(W * i2 + np.abs(S) <= 0.0))
    add(_RE, _Box(shape).linear(-k, W).when((k * cst.P <= cst.Q) & (cst.Qp + k * cst.Pp >= 0.0)))
    for sigma in (1.0, -1.0):  # slide left, right: slip against friction, xi in [-1, 1]
        add(_SL, _Box(shape).linear(sigma * k, -W).linear(W - S, -sigma * g * W)
            .linear(W + S, sigma * g * W).when(W >= 0.0))
    # slide-rock about O' slipping left: den = A0 + 3 mu gamma > 0
    add(_SPM, _Box(shape).linear(-(W + S), -g * W).when(W * i2 - S >= 0.0).linear(t["fxP"], -t["fyP"]))
    add(_RO, _Box(shape).linear(-np.abs(t["fxO"]), t["fyO"]).when((t["TO"] >= 0.0) & (t["fyO"] >= 0.0)))
    # slide-rock about O slipping left: den = A0 - 3 mu gamma, two branches about mu_B'
    add(_SM, _Box(shape).below(mb).linear(S - W, g * W).when(W * i2 + S >= 0.0).linear(t["fxO"], -t["fyO"]))
    add(_SM, _Box(shape).above(mb).linear(W - S, -g * W).when(W * i2 + S <= 0.0)
        .linear(-t["fxO"], t["fyO"]))
    # slide-rock about O slipping right: den = A0 + 3 mu gamma > 0
    add(_SP, _Box(shape).linear(S - W, -g * W).when(W * i2 + S >= 0.0).linear(-t["fxO"], -t["fyO"]))
    add(_ROP, _Box(shape).linear(-np.abs(t["fxP"]), t["fyP"]).when((t["TP"] <= 0.0) & (t["fyP"] >= 0.0)))
    # slide-rock about O' slipping right: den = A0 - 3 mu gamma, two branches
    add(_SPP, _Box(shape).below(mb).linear(-(W + S), g * W).when(W * i2 - S >= 0.0)
        .linear(-t["fxP"], -t["fyP"]))
    add(_SPP, _Box(shape).above(mb).linear(W + S, -g * W).when(W * i2 - S <= 0.0)
        .linear(t["fxP"], t["fyP"]))
    return out


def _generic(k: Float, mu: Float, cst: LoadedConstants) -> U8:
    """First interval of :func:`_intervals` holding mu (255 if none)."""
    out = np.full(np.broadcast(k, mu).shape, 255, dtype=np.uint8)
    for code, lo, hi in reversed(_intervals(k, cst)):
        np.copyto(out, code, where=(mu >= lo) & (mu <= hi))
    return out


def _classify(k: Float, mu: Float, cst: LoadedConstants) -> U8:
    t = thresholds(k, cst)
    out = _structured(k, mu, t)
    odd = ~t.regular
    if odd.any():
        np.copyto(out, _generic(k, mu, cst), where=odd)
    return out


# -- grids ----------------------------------------------------------------------------------------------

def column_segments_loaded(k: Float, mu_sorted: Float, cst: LoadedConstants) -> tuple[U8, NDArray[np.intp]]:
    """Labels and run lengths along each column of a grid whose mu axis is sorted increasingly.

    Regular columns (``Thresholds.regular``): at most five runs from mu = 0 up,
    SRO'-, SL, SRO-/SRO+, RO, RE, cut by ``searchsorted`` at lower, upper, mu*
    and k/W exactly as :func:`classify_loaded` compares.  Other columns (W <= 0,
    lift-off, f_y of rocking about O <= 0, rest failing about O'): the
    breakpoints of every interval of :func:`_intervals` cut the column and each
    piece takes the first interval (selection order) that holds it.

    Returns
    -------
    labels, counts : ndarray, shape (len(k), m)
        Mode codes and run lengths (each row of counts sums to len(mu_sorted)).
    """
    n = mu_sorted.size
    t = thresholds(k, cst)
    n_k = np.where(t.rest_ok, np.searchsorted(mu_sorted, t.mu_rest, side="left"), n)
    c1 = np.minimum(np.searchsorted(mu_sorted, t.lower, side="left"), n_k)
    c2 = np.minimum(np.searchsorted(mu_sorted, t.upper, side="right"), n_k)
    c3 = np.minimum(np.maximum(np.searchsorted(mu_sorted, t.mu_star, side="left"), c2), n_k)
    counts5 = np.stack([c1, c2 - c1, c3 - c2, n_k - c3, n - n_k], axis=1)
    labels5 = np.empty((k.size, 5), dtype=np.uint8)
    labels5[:, 0] = _SPM
    labels5[:, 1] = _SL
    labels5[:, 2] = np.where(t.f_pos, _SM, _SP)
    labels5[:, 3] = _RO
    labels5[:, 4] = _RE
    odd = np.flatnonzero(~t.regular)
    if odd.size == 0:
        return labels5, counts5
    ivs = _intervals(k[odd], cst)
    starts = np.stack([np.searchsorted(mu_sorted, lo, side="left") for _, lo, _ in ivs], axis=1)
    ends = np.stack([np.searchsorted(mu_sorted, hi, side="right") for _, _, hi in ivs], axis=1)
    ends = np.maximum(ends, starts)
    codes = np.array([c for c, _, _ in ivs], dtype=np.uint8)
    cuts = np.sort(np.concatenate([starts, ends, np.zeros((odd.size, 1), np.intp),
                                   np.full((odd.size, 1), n, np.intp)], axis=1), axis=1)
    left = cuts[:, :-1]
    cnt = np.diff(cuts, axis=1)
    # piece [left, left + cnt) lies in interval j iff starts_j <= left < ends_j (cuts include all ends)
    inside = (starts[:, None, :] <= left[:, :, None]) & (left[:, :, None] < ends[:, None, :])
    first = np.argmax(inside, axis=2)
    lab = np.where(inside.any(axis=2), codes[first], np.uint8(255)).astype(np.uint8)
    m = max(5, cnt.shape[1])
    labels = np.zeros((k.size, m), dtype=np.uint8)
    counts = np.zeros((k.size, m), dtype=np.intp)
    labels[:, :5] = labels5
    counts[:, :5] = counts5
    labels[odd] = 0
    counts[odd] = 0
    labels[odd, : cnt.shape[1]] = lab
    counts[odd, : cnt.shape[1]] = cnt
    return labels, counts


def label_grid_loaded(k_axis: ArrayLike, mu_axis: ArrayLike, gamma: float, kprime: float, *,
                      buoyancy: float = 0.0, uplift: float = 0.0, uplift_ratio: float = 0.0,
                      uplift_arm: float = 1.0 / 3.0, gyration: float | None = None, crest: float = 1.0
                      ) -> U8:
    """Mode codes on the grid ``k_axis x mu_axis``, shape (len(mu_axis), len(k_axis)).

    ``out[i, j] == classify_loaded(k_axis[j], mu_axis[i], ...)`` exactly; each
    column is cut into runs by :func:`column_segments_loaded` and filled with
    ``numpy.repeat``.  Axes: 1-D, finite, >= 0, any order.
    """
    cst = loaded_constants(gamma, kprime, buoyancy=buoyancy, uplift=uplift, uplift_ratio=uplift_ratio,
                           uplift_arm=uplift_arm, gyration=gyration, crest=crest)
    k_ax = np.asarray(k_axis, dtype=np.float64)
    mu_ax = np.asarray(mu_axis, dtype=np.float64)
    if k_ax.ndim != 1 or mu_ax.ndim != 1:
        raise ValueError("k_axis and mu_axis must be 1-D")
    _validate_km(k_ax, np.zeros(1))
    _validate_km(np.zeros(1), mu_ax)
    if mu_ax.size == 0 or k_ax.size == 0:
        return np.empty((mu_ax.size, k_ax.size), dtype=np.uint8)
    increasing = bool(np.all(np.diff(mu_ax) >= 0.0))
    order = None if increasing else np.argsort(mu_ax, kind="stable")
    mu_sorted = mu_ax if order is None else mu_ax[order]
    labels, counts = column_segments_loaded(k_ax, mu_sorted, cst)
    cols = np.repeat(labels.ravel(), counts.ravel()).reshape(k_ax.size, mu_sorted.size)
    grid = np.ascontiguousarray(cols.T)
    if order is None:
        return grid
    out = np.empty_like(grid)
    out[order] = grid
    return out


# -- named points ---------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LoadedPoint:
    """A named point of the loaded map: coordinates and meaning."""

    name: str
    k: float
    mu: float
    meaning: str


def _w(cst: LoadedConstants, k: float) -> float:
    return (1.0 - cst.buoyancy - cst.uplift) - cst.uplift_ratio * k


def _lower_at(cst: LoadedConstants, k: float) -> float:
    s = k * cst.kprime + cst.uplift_arm * (cst.uplift + cst.uplift_ratio * k) / cst.gamma
    return -1.0 / cst.gamma - s / _w(cst, k)


def _lift_off_range(cst: LoadedConstants) -> tuple[float, float] | None:
    """[k1, k2] (k >= 0) where W i^2 + |S| <= 0, or None."""
    g, eu, u, nu, i2 = cst.gamma, cst.uplift_arm, cst.uplift, cst.uplift_ratio, cst.i2
    w0 = 1.0 - cst.buoyancy - u
    lo, hi = 0.0, math.inf
    for sgn in (1.0, -1.0):  # W i2 + sgn S <= 0: h0 + h1 k <= 0
        h0 = w0 * i2 + sgn * eu * u
        h1 = -nu * i2 + sgn * (g * cst.kprime + eu * nu)
        if h1 == 0.0:
            if h0 > 0.0:
                return None
        elif h1 > 0.0:
            hi = min(hi, -h0 / h1)
        else:
            lo = max(lo, -h0 / h1)
    return (lo, hi) if lo <= hi else None


def named_points_loaded(cst: LoadedConstants) -> dict[str, LoadedPoint]:
    """The report's named points, generalised, where they exist (finite, k >= 0, W > 0).

    A (k_A = Q/P, on mu = k/W), C (0, upper(0)), D (upper line on mu = 0 above C,
    lower line below C), E (k_A, 0), B' (f_y of slide-rock about O vanishes on
    the upper line, at mu_B'), F (mu** = 0: b_O'/a_O'), G (mu* = 0: b_O/|a_O|),
    C' (mu* meets the lower line beyond D), and L (k where lift-off starts).
    At zero loads they are the points of :func:`regimemap.curves.named_points`
    (to rounding).
    """
    g, kp, eu, u, nu, i2 = cst.gamma, cst.kprime, cst.uplift_arm, cst.uplift, cst.uplift_ratio, cst.i2
    w0 = 1.0 - cst.buoyancy - u
    pts: dict[str, LoadedPoint] = {"O": LoadedPoint("O", 0.0, 0.0, "origin")}

    def ok(k: float) -> bool:
        return math.isfinite(k) and k >= 0.0 and _w(cst, k) > 0.0

    kA = cst.k_A
    if ok(kA):
        pts["A"] = LoadedPoint("A", kA, kA / _w(cst, kA), "rest about O ends: k_A = Q/P; mu = k/W")
        if kp < 0.0:
            pts["E"] = LoadedPoint("E", kA, 0.0, "foot of the vertical through A")
    if w0 > 0.0:
        c_mu = 1.0 / g - eu * u / (g * w0)
        if kp >= 0.0 and c_mu >= 0.0:
            pts["C"] = LoadedPoint("C", 0.0, c_mu, "upper line (xi = -B) meets the mu axis")
    den_up = g * kp + nu * (1.0 + eu)
    den_lo = nu * (1.0 - eu) - g * kp
    if kp > 0.0 and den_up > 0.0 and ok(cst.Q / den_up):
        pts["D"] = LoadedPoint("D", cst.Q / den_up, 0.0, "upper line meets the k axis")
    if kp < 0.0 and den_lo > 0.0 and ok(cst.Qp / den_lo):
        pts["D"] = LoadedPoint("D", cst.Qp / den_lo, 0.0, "lower line (xi = +B) meets the k axis")
    den_b = nu * i2 - g * kp - eu * nu
    if den_b > 0.0:
        kb = (w0 * i2 + eu * u) / den_b
        if ok(kb):
            pts["B'"] = LoadedPoint("B'", kb, cst.mu_Bprime,
                                    "f_y of slide-rock about O vanishes on the upper line")
    if cst.aP > 0.0 and ok(cst.bP / cst.aP) and kp < 0.0:
        pts["F"] = LoadedPoint("F", cst.bP / cst.aP, 0.0, "mu** = 0")
    if cst.aO < 0.0 and ok(cst.bO / abs(cst.aO)):
        pts["G"] = LoadedPoint("G", cst.bO / abs(cst.aO), 0.0, "mu* = 0 (f_x of rocking about O = 0)")
    if kp < 0.0:
        w1 = -nu
        p0, p1 = w0 + eu * u, -nu + g * kp + eu * nu
        A2 = g * cst.aO * w1 + cst.cO * p1
        A1 = g * (cst.aO * w0 + cst.bO * w1) + cst.cO * p0 + cst.dO * p1
        A0 = g * cst.bO * w0 + cst.dO * p0
        roots: list[float] = []
        if A2 != 0.0:
            disc = A1 * A1 - 4.0 * A2 * A0
            if disc >= 0.0:
                r = math.sqrt(disc)
                roots = [(-A1 + r) / (2.0 * A2), (-A1 - r) / (2.0 * A2)]
        elif A1 != 0.0:
            roots = [-A0 / A1]
        good = [x for x in roots if ok(x) and _lower_at(cst, x) >= 0.0]
        if good:
            kc = max(good)
            pts["C'"] = LoadedPoint("C'", kc, _lower_at(cst, kc), "mu* meets the lower line")
    lo_range = _lift_off_range(cst)
    if lo_range is not None and math.isfinite(lo_range[0]):
        pts["L"] = LoadedPoint("L", lo_range[0], 0.0, "lift-off starts (W i^2 + |S| = 0)")
    return pts
