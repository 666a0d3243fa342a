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

import math
from dataclasses import dataclass, field
from enum import Enum

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
    g2 = gamma * gamma
    if kprime >= 0.0:
        if kprime <= (1.0 + g2) / (3.0 * g2):
            return Case.ABOVE_1A
        # a >= 0 (3.18); the second test keeps the tie k' = (4+g^2)/(3g^2) in
        # case 1 when rounding makes a a hair negative there
        if 4.0 + g2 - 3.0 * g2 * kprime >= 0.0 or kprime <= (4.0 + g2) / (3.0 * g2):
            return Case.ABOVE_1B
        return Case.ABOVE_2_3
    if -kprime <= (1.0 + g2) / (4.0 + g2):
        return Case.BELOW_DELTA_POS
    return Case.BELOW_DELTA_NEG


@dataclass(frozen=True)
class Parameters:
    """Validated map parameters and the report's derived quantities.

    Parameters
    ----------
    gamma : float
        Aspect (slenderness) ratio ``gamma = H/B > 0``.
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
        g2 = g * g
        object.__setattr__(self, "a", 4.0 + g2 - 3.0 * g2 * kp)  # (3.18), (4.42)
        object.__setattr__(self, "b", 3.0 * g)  # (3.19), (4.43)
        object.__setattr__(self, "c", 3.0 * g * (1.0 + kp))  # (3.20), (4.44)
        object.__setattr__(self, "d", 1.0 + 4.0 * g2)  # (3.21), (4.45)

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
        return (1.0 + self.gamma**2) / (3.0 * self.gamma**2)

    @property
    def kprime_2(self) -> float:
        """(4+g^2)/(3g^2): a = 0 (3.18); above it cases 2/3 (only for gamma > sqrt 2)."""
        return (4.0 + self.gamma**2) / (3.0 * self.gamma**2)

    @property
    def kprime_delta(self) -> float:
        """(1+g^2)/(4+g^2): Delta = 0 (Chapter IV, Section IV.3)."""
        return (1.0 + self.gamma**2) / (4.0 + self.gamma**2)

    # -- points and constants -----------------------------------------------------
    @property
    def k_A(self) -> float:
        """k_A = 1/(gamma(1+k')) = 3/c, (3.5), (3.17), (4.10), (4.37); inf at k' = -1."""
        den = self.gamma * (1.0 + self.kprime)
        return math.inf if den == 0.0 else 1.0 / den

    @property
    def mu_A(self) -> float:
        """mu_A = mu*(k_A) = k_A (Section III.3 case 1, (4.46))."""
        return self.k_A

    @property
    def k_Bprime(self) -> float:
        """k_B' = (1+g^2)/(3 gamma |k'|), (4.48); inf for k' >= 0 (no B' above C)."""
        if self.kprime >= 0.0:
            return math.inf
        return (1.0 + self.gamma**2) / (3.0 * self.gamma * self.abs_kprime)

    @property
    def mu_Bprime(self) -> float:
        """mu_B' = (4+g^2)/(3 gamma), (4.49): where 4 + g^2 - 3 mu gamma = 0 in (3.30), (4.64)."""
        return (4.0 + self.gamma**2) / (3.0 * self.gamma)

    @property
    def b_over_abs_a(self) -> float:
        """b/|a|: where f_x of rocking changes sign when a < 0 (cases 2/3); inf if a >= 0."""
        if self.a >= 0.0:
            return math.inf
        return self.b / abs(self.a)

    @property
    def slope_at_A(self) -> float:
        """d mu*/dk at A = (1+g^2-3g^2 k')/(4(1+g^2)) (Section III.3, case 1)."""
        g2 = self.gamma**2
        return (1.0 + g2 - 3.0 * g2 * self.kprime) / (4.0 * (1.0 + g2))

    @property
    def delta(self) -> float:
        """Delta = ((1+g^2) - (4+g^2)|k'|)/(4(1+g^2)) (Section IV.3): slope of mu* at A minus |k'|."""
        g2 = self.gamma**2
        return ((1.0 + g2) - (4.0 + g2) * self.abs_kprime) / (4.0 * (1.0 + g2))

    @property
    def k_C_axis(self) -> float:
        """mu-intercept of the line CD (above C) or AB (below C): 1/gamma."""
        return 1.0 / self.gamma

    @property
    def k_D(self) -> float:
        """k where CD (above C, mu = 1/g - k k') or DC (below C, mu = -1/g + k|k'|) meets mu = 0."""
        if self.kprime == 0.0:
            return math.inf
        return 1.0 / (self.gamma * self.abs_kprime)

    @property
    def k_F(self) -> float:
        """k_F = b/a where mu** = 0 (Section IV.6); defined below C (inf when a <= 0)."""
        return math.inf if self.a <= 0.0 else self.b / self.a

    @property
    def k_pole(self) -> float:
        """d/c, the pole of mu**(k) (4.97); inf at k' = -1."""
        return math.inf if self.c == 0.0 else self.d / self.c

    def as_dict(self) -> dict[str, float | str]:
        """All parameters and derived quantities as plain numbers (inf as None-free floats)."""
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
