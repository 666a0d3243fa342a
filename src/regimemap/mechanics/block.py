"""Parameters of a map (gamma, kprime and the loads), the derived constants and the report's cases.

One sign convention serves both chapters: ``kprime`` is signed, ``h = kprime*H``,
positive above the centre of mass C (Chapter III, 0 <= k' <= 1) and negative
below it (Chapter IV, -1 <= k' <= 0, where the report writes ``|k'|``).  With
``|k'| = -kprime`` below C, the constants (4.42)-(4.45) are (3.18)-(3.21)::

    a = 4 + gamma**2 - 3*gamma**2*kprime      (3.18), (4.42)
    b = 3*gamma                               (3.19), (4.43)
    c = 3*gamma*(1 + kprime)                  (3.20), (4.44)
    d = 1 + 4*gamma**2                        (3.21), (4.45)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from . import constants as C
from .loads import BlockConstants, block_constants
from .validation import check_gamma, check_kprime, check_loads, check_weight

__all__ = ["Case", "Parameters", "case_of"]


class Case(Enum):
    """The case of the report that a pair (gamma, kprime) falls in.

    At a threshold the lower case is chosen: ``kprime == (1+g^2)/(3g^2)`` is
    ``ABOVE_1A``, ``kprime == (4+g^2)/(3g^2)`` is ``ABOVE_1B``, ``|kprime| ==
    (1+g^2)/(4+g^2)`` is ``BELOW_DELTA_POS`` and ``kprime == 0`` is ``ABOVE_1A``
    (at k' = 0 both chapters give the same map).
    """

    #: Chapter III case 1, 0 <= k' <= (1+g^2)/(3g^2): slope of mu* at A >= 0 (Figs 3.3a, 3.6a, 3.9a).
    ABOVE_1A = "1a"
    #: Chapter III case 1, (1+g^2)/(3g^2) <= k' <= (4+g^2)/(3g^2): slope at A <= 0 (Figs 3.3b, 3.6b, 3.9b).
    ABOVE_1B = "1b"
    #: Chapter III cases 2 and 3, a <= 0, k' >= (4+g^2)/(3g^2), gamma > sqrt(2)
    #: (Figs 3.4, 3.5, 3.7, 3.8, 3.10, 3.11): f_x >= 0 for k <= b/|a| (case 2), f_x <= 0 beyond (case 3).
    ABOVE_2_3 = "2/3"
    #: Chapter IV, Delta >= 0, |k'| <= (1+g^2)/(4+g^2) (Figs 4.4a, 4.5a, 4.6a, 4.7a).
    BELOW_DELTA_POS = "delta>=0"
    #: Chapter IV, Delta <= 0, |k'| >= (1+g^2)/(4+g^2) (Figs 4.4b, 4.5b, 4.6b, 4.7b).
    BELOW_DELTA_NEG = "delta<=0"

    @property
    def above(self) -> bool:
        """True for the cases of Chapter III (force at or above C)."""
        return self in (Case.ABOVE_1A, Case.ABOVE_1B, Case.ABOVE_2_3)

    @property
    def description(self) -> str:
        """The case as the report's captions state it (plain text)."""
        return _CASE_TEXT[self][0]

    @property
    def tex(self) -> str:
        """The case as matplotlib mathtext, for figure titles."""
        return _CASE_TEXT[self][1]


_CASE_TEXT = {
    Case.ABOVE_1A: (
        "case 1, 0 <= k' <= (1+g^2)/(3g^2), a >= 0",
        r"case 1, $0 \leq k' \leq (1+\gamma^2)/(3\gamma^2)$, $a \geq 0$",
    ),
    Case.ABOVE_1B: (
        "case 1, (1+g^2)/(3g^2) <= k' <= (4+g^2)/(3g^2), a >= 0",
        r"case 1, $(1+\gamma^2)/(3\gamma^2) \leq k' \leq (4+\gamma^2)/(3\gamma^2)$, $a \geq 0$",
    ),
    Case.ABOVE_2_3: (
        "cases 2/3, (4+g^2)/(3g^2) <= k' <= 1, a <= 0",
        r"cases 2/3, $(4+\gamma^2)/(3\gamma^2) \leq k' \leq 1$, $a \leq 0$",
    ),
    Case.BELOW_DELTA_POS: (
        "force below C, Delta >= 0, |k'| <= (1+g^2)/(4+g^2)",
        r"$\Delta \geq 0$, $|k'| \leq (1+\gamma^2)/(4+\gamma^2)$",
    ),
    Case.BELOW_DELTA_NEG: (
        "force below C, Delta <= 0, |k'| >= (1+g^2)/(4+g^2)",
        r"$\Delta \leq 0$, $|k'| \geq (1+\gamma^2)/(4+\gamma^2)$",
    ),
}


def case_of(gamma: float, kprime: float) -> Case:
    """Return the :class:`Case` of ``(gamma, kprime)``; see :class:`Case` for ties."""
    if kprime >= 0.0:
        if kprime <= C.kprime_1(gamma):
            return Case.ABOVE_1A
        # a >= 0 (3.18); the second test keeps the tie k' = (4+g^2)/(3g^2) in
        # case 1 when rounding makes a a hair negative there
        if C.coefficients(gamma, kprime)[0] >= 0.0 or kprime <= C.kprime_2(gamma):
            return Case.ABOVE_1B
        return Case.ABOVE_2_3
    if -kprime <= C.kprime_delta(gamma):
        return Case.BELOW_DELTA_POS
    return Case.BELOW_DELTA_NEG


#: The loads of a block and their defaults (the report's block carries none).
LOAD_DEFAULTS: dict[str, Any] = {
    "buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0, "uplift_arm": 1.0 / 3.0,
    "gyration": None, "crest": 1.0,
}


@dataclass(frozen=True, repr=False)
class Parameters:
    """The block and its loading: validated map parameters and their derived quantities.

    This is the one parameter object that every layer passes around (maps,
    drawing, export, the command line).  Its derived quantities are computed
    by :mod:`regimemap.mechanics.constants`, the single home of the closed forms;
    at zero loads (the defaults) they are the report's, bit for bit.

    Parameters
    ----------
    gamma : float
        Aspect (slenderness) ratio ``gamma = H/B > 0`` (B, H: half width and half height).
    kprime : float
        Height of the force above the centre of mass as a fraction of H,
        ``h = kprime*H``, in [-1, crest]; negative below C (Chapter IV).
    buoyancy : float, keyword-only
        beta in [0, 1): buoyancy beta m g, upward through C.
    uplift : float, keyword-only
        u >= 0: the part of the uplift that does not grow with the push, u m g.
    uplift_ratio : float, keyword-only
        nu >= 0: the uplift grows by nu F with the push (U = (u + nu k) m g).
    uplift_arm : float, keyword-only
        e_u in [-1, 1]: the uplift acts at e_u B from C towards O' (1/3: Goda's triangle).
    gyration : float or None, keyword-only
        i > 0: the radius of gyration about C over B (I = m B^2 i^2); None is the
        uniform block, i^2 = (1 + gamma^2)/3.
    crest : float, keyword-only
        The top of the block over H (> 0); the force may act up to it, kprime <= crest.

    Raises
    ------
    ValueError
        If a value is outside its range; the message names the parameter, the
        value and the allowed range (:mod:`regimemap.mechanics.validation`).

    Examples
    --------
    >>> p = Parameters(gamma=3.0, kprime=0.4)
    >>> round(p.k_A, 4), p.case.value, p.loaded
    (0.2381, '1b', False)
    >>> Parameters(3.0, 0.4, buoyancy=0.3).loaded
    True
    """

    gamma: float
    kprime: float
    buoyancy: float = field(default=0.0, kw_only=True)
    uplift: float = field(default=0.0, kw_only=True)
    uplift_ratio: float = field(default=0.0, kw_only=True)
    uplift_arm: float = field(default=1.0 / 3.0, kw_only=True)
    gyration: float | None = field(default=None, kw_only=True)
    crest: float = field(default=1.0, kw_only=True)
    a: float = field(init=False)
    b: float = field(init=False)
    c: float = field(init=False)
    d: float = field(init=False)
    constants: BlockConstants = field(init=False, compare=False)

    def __post_init__(self) -> None:
        beta, u, nu, eu, gy, crest = check_loads(self.buoyancy, self.uplift, self.uplift_ratio,
                                                  self.uplift_arm, self.gyration, self.crest)
        check_weight(beta, u, nu)
        g = check_gamma(self.gamma)
        kp = check_kprime(self.kprime, crest)
        for name, value in (("gamma", g), ("kprime", kp), ("buoyancy", beta), ("uplift", u),
                            ("uplift_ratio", nu), ("uplift_arm", eu), ("gyration", gy),
                            ("crest", crest)):
            object.__setattr__(self, name, value)
        cst = block_constants(g, kp, beta, u, nu, eu, gy)
        object.__setattr__(self, "constants", cst)
        for name in ("a", "b", "c", "d"):  # (3.18)-(3.21), (4.42)-(4.45)
            object.__setattr__(self, name, getattr(cst, name))

    # -- the loads -------------------------------------------------------------------
    @property
    def loads(self) -> dict[str, Any]:
        """The loads as keyword arguments (``buoyancy`` ... ``crest``) of :func:`regimemap.classify`."""
        return {k: getattr(self, k) for k in LOAD_DEFAULTS}

    @property
    def loaded(self) -> bool:
        """True when the block carries a load or an inertia of its own (not the report's block)."""
        return (self.buoyancy != 0.0 or self.uplift != 0.0 or self.uplift_ratio != 0.0
                or self.gyration is not None)

    def __repr__(self) -> str:
        """The inputs as given (the loads other than their defaults), the derived a, b, c, d
        without float noise (12 digits)."""
        def num(v: float) -> str:
            return repr(float(f"{v:.12g}") + 0.0)

        extra = "".join(f", {k}={v!r}" for k, v in self.loads.items() if v != LOAD_DEFAULTS[k])
        return (f"Parameters(gamma={self.gamma!r}, kprime={self.kprime!r}{extra}, a={num(self.a)}, "
                f"b={num(self.b)}, c={num(self.c)}, d={num(self.d)})")

    # -- the chapter and the case -------------------------------------------------
    @property
    def above(self) -> bool:
        """True when the force acts at or above C (Chapter III)."""
        return self.kprime >= 0.0

    @property
    def abs_kprime(self) -> float:
        """``|k'|``, as Chapter IV writes it."""
        return abs(self.kprime)

    @property
    def case(self) -> Case:
        """The report's case of (gamma, kprime) (see :class:`Case`; the loads do not enter)."""
        return case_of(self.gamma, min(self.kprime, 1.0))

    # -- thresholds of k' ---------------------------------------------------------
    @property
    def kprime_1(self) -> float:
        """(1+g^2)/(3g^2): the slope of mu* at A changes sign (Chapter III, case 1)."""
        return C.kprime_1(self.gamma)

    @property
    def kprime_2(self) -> float:
        """(4+g^2)/(3g^2): a = 0 (3.18); above it cases 2/3 (only for gamma > sqrt 2)."""
        return C.kprime_2(self.gamma)

    @property
    def kprime_delta(self) -> float:
        """(1+g^2)/(4+g^2): Delta = 0 (Chapter IV, Section IV.3)."""
        return C.kprime_delta(self.gamma)

    # -- points and constants -----------------------------------------------------
    @property
    def k_A(self) -> float:
        """k_A = Q/P (1/(gamma(1+k')) at zero loads), (3.5), (3.17), (4.10), (4.37); inf at k' = -1."""
        return C.k_A(self.constants)

    @property
    def mu_A(self) -> float:
        """mu_A = k_A/W(k_A) (= k_A at zero loads, Section III.3 case 1, (4.46))."""
        return C.mu_A(self.constants)

    @property
    def k_Bprime(self) -> float:
        """k_B' ((1+g^2)/(3 gamma |k'|) at zero loads, (4.48)); inf where there is no B'."""
        return C.k_Bprime(self.constants)

    @property
    def mu_Bprime(self) -> float:
        """mu_B' = (i^2+1)/gamma ((4+g^2)/(3 gamma), (4.49)): slide-rock about O is singular there."""
        return C.mu_Bprime(self.constants)

    @property
    def b_over_abs_a(self) -> float:
        """b_O/|a_O| (G): where f_x of rocking changes sign when a_O < 0 (cases 2/3); inf if a_O >= 0."""
        return C.b_over_abs_a(self.constants.aO, self.constants.bO)

    @property
    def slope_at_A(self) -> float:
        """d mu*/dk at A = (1+g^2-3g^2 k')/(4(1+g^2)) (Section III.3, case 1; zero loads)."""
        return C.slope_at_A(self.gamma, self.kprime)

    @property
    def delta(self) -> float:
        """Delta = ((1+g^2) - (4+g^2)|k'|)/(4(1+g^2)) (Section IV.3; zero loads)."""
        return C.delta(self.gamma, self.kprime)

    @property
    def k_D(self) -> float:
        """k where CD (above C) or DC (below C) meets mu = 0 (1/(gamma|k'|) at zero loads)."""
        return C.k_D(self.constants)

    @property
    def k_F(self) -> float:
        """k_F = b_O'/a_O' where mu** = 0 (b/a, Section IV.6); inf when a_O' <= 0."""
        return C.k_F(self.constants.aP, self.constants.bP)

    @property
    def k_pole(self) -> float:
        """d_O'/c_O', the pole of mu**(k) (d/c, (4.97)); inf at k' = -1."""
        return C.k_pole(self.constants.cP, self.constants.dP)

    @property
    def k_Cprime(self) -> float | None:
        """C': where mu* meets the lower line DC (None when they do not meet at mu >= 0)."""
        return C.crossing_mu_star_lower(self.constants)

    @property
    def lift_off(self) -> tuple[float, float] | None:
        """The range [k1, k2] of k where the block lifts off (None at zero loads)."""
        return C.lift_off_range(self.constants)

    @property
    def k_L(self) -> float:
        """L: the k where lift-off starts (inf when it never does)."""
        r = self.lift_off
        return math.inf if r is None else r[0]

    def as_dict(self) -> dict[str, float | str | None]:
        """All parameters and derived quantities as plain numbers (the loads only when loaded)."""
        out: dict[str, float | str | None] = {
            "gamma": self.gamma,
            "kprime": self.kprime,
            "case": self.case.value,
            "a": self.a,
            "b": self.b,
            "c": self.c,
            "d": self.d,
            "k_A": self.k_A,
            "mu_A": self.mu_A,
            "k_Bprime": self.k_Bprime,
            "mu_Bprime": self.mu_Bprime,
            "b_over_abs_a": self.b_over_abs_a,
            "delta": self.delta,
            "slope_at_A": self.slope_at_A,
        }
        if self.loaded or self.crest != 1.0:
            out.update(self.loads)
            out["k_L"] = self.k_L
        return out
