"""Parameters of a map (gamma, kprime), the report's derived constants and cases.

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

from dataclasses import dataclass, field
from enum import Enum

from . import constants as C
from .validation import check_gamma, check_kprime

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


@dataclass(frozen=True)
class Parameters:
    """The block and its loading: validated map parameters and the report's derived quantities.

    This is the one parameter object that every layer passes around (maps,
    drawing, export, the command line).  Its derived quantities are computed
    by :mod:`regimemap.mechanics.constants`, the single home of the closed forms.

    Parameters
    ----------
    gamma : float
        Aspect (slenderness) ratio ``gamma = H/B > 0`` (B, H: half width and half height).
    kprime : float
        Height of the force above the centre of mass as a fraction of H,
        ``h = kprime*H``, in [-1, 1]; negative below C (Chapter IV).

    Raises
    ------
    ValueError
        If gamma is not finite and > 0 or kprime is not in [-1, 1].

    Examples
    --------
    >>> p = Parameters(gamma=3.0, kprime=0.4)
    >>> round(p.k_A, 4), p.case.value
    (0.2381, '1b')
    """

    gamma: float
    kprime: float
    a: float = field(init=False)
    b: float = field(init=False)
    c: float = field(init=False)
    d: float = field(init=False)

    def __post_init__(self) -> None:
        g = check_gamma(self.gamma)
        kp = check_kprime(self.kprime)
        object.__setattr__(self, "gamma", g)
        object.__setattr__(self, "kprime", kp)
        a, b, c, d = C.coefficients(g, kp)  # (3.18)-(3.21), (4.42)-(4.45)
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)
        object.__setattr__(self, "c", c)
        object.__setattr__(self, "d", d)

    def __repr__(self) -> str:
        """The inputs as given, the derived a, b, c, d without float noise (12 digits)."""
        def num(v: float) -> str:
            return repr(float(f"{v:.12g}") + 0.0)

        return (f"Parameters(gamma={self.gamma!r}, kprime={self.kprime!r}, a={num(self.a)}, "
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
        """The report's case (see :class:`Case`)."""
        return case_of(self.gamma, self.kprime)

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
        """k_A = 1/(gamma(1+k')) = 3/c, (3.5), (3.17), (4.10), (4.37); inf at k' = -1."""
        return C.k_A(self.gamma, self.kprime)

    @property
    def mu_A(self) -> float:
        """mu_A = mu*(k_A) = k_A (Section III.3 case 1, (4.46))."""
        return self.k_A

    @property
    def k_Bprime(self) -> float:
        """k_B' = (1+g^2)/(3 gamma |k'|), (4.48); inf for k' >= 0 (no B' above C)."""
        return C.k_Bprime(self.gamma, self.kprime)

    @property
    def mu_Bprime(self) -> float:
        """mu_B' = (4+g^2)/(3 gamma), (4.49): where 4 + g^2 - 3 mu gamma = 0 in (3.30), (4.64)."""
        return C.mu_Bprime(self.gamma)

    @property
    def b_over_abs_a(self) -> float:
        """b/|a|: where f_x of rocking changes sign when a < 0 (cases 2/3); inf if a >= 0."""
        return C.b_over_abs_a(self.a, self.b)

    @property
    def slope_at_A(self) -> float:
        """d mu*/dk at A = (1+g^2-3g^2 k')/(4(1+g^2)) (Section III.3, case 1)."""
        return C.slope_at_A(self.gamma, self.kprime)

    @property
    def delta(self) -> float:
        """Delta = ((1+g^2) - (4+g^2)|k'|)/(4(1+g^2)) (Section IV.3): slope of mu* at A minus |k'|."""
        return C.delta(self.gamma, self.kprime)

    @property
    def k_D(self) -> float:
        """k where CD (above C, mu = 1/g - k k') or DC (below C, mu = -1/g + k|k'|) meets mu = 0."""
        return C.k_D(self.gamma, self.kprime)

    @property
    def k_F(self) -> float:
        """k_F = b/a where mu** = 0 (Section IV.6); defined below C (inf when a <= 0)."""
        return C.k_F(self.a, self.b)

    @property
    def k_pole(self) -> float:
        """d/c, the pole of mu**(k) (4.97); inf at k' = -1."""
        return C.k_pole(self.c, self.d)

    @property
    def k_Cprime(self) -> float | None:
        """C': where mu* meets the lower line DC below C (None when they do not meet)."""
        return C.crossing_mu_star_lower(self.gamma, self.kprime)

    def as_dict(self) -> dict[str, float | str]:
        """All parameters and derived quantities as plain numbers."""
        return {
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
