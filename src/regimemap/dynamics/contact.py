"""The contact problem of one time step: two unilateral frictional corners, solved exactly.

One step of the time stepper (:mod:`regimemap.dynamics.stepper`) leaves, per unit mass and with
generalised velocity v = (x_dot, y_dot, theta_dot) of C and mass matrix M = diag(1, 1, J), a
*free* velocity v_f = v_k + h f (the forces over the step, no reaction) and asks for the
velocity v_{k+1} = v_f + M^-1 sum_j (W_N,j P_N,j + W_T,j P_T,j) that meets, at every active
corner j (O, O'), the velocity-level Signorini-Coulomb conditions (normal restitution 0)::

    0 <= u_N,j ⊥ P_N,j >= 0
    stick: u_T,j = 0, |P_T,j| <= mu P_N,j ;  slip: P_T,j = -mu P_N,j sign(u_T,j)

where u_N,j = y_dot + theta_dot r_x,j and u_T,j = x_dot - theta_dot r_y,j are the corner
velocities and r_j the vector from C to corner j (:class:`Arms`).

The problem (two corners, three degrees of freedom) is solved *exactly* by enumerating its ten
contact states -- both corners stuck (rest), both slipping left or right (slide), one corner
stuck or slipping left/right with the other free (rock, slide-rock about O or O'), and flight --
each a linear system of at most 3 unknowns in closed form, and taking the first state whose
sign conditions hold, in the order of Section 4.7 of the report (:data:`regimemap.PRIORITY`):
RE, SL, SRO'-, RO, SRO-, SRO+, RO', SRO'+, then FLIGHT.  Where the Coulomb problem has several
solutions (Painleve-type configurations) this order picks one, as :func:`regimemap.classify`
does at the onset.  Rest is exact: when both corners can stick, v_{k+1} = 0 is set exactly.

From rest (v_k = 0) the velocity problem is the acceleration problem of the onset times h, so
each state's velocity over h is the acceleration of :func:`regimemap.mechanics.solver.solve`
for that hypothesis (``tests/dynamics/test_contact.py`` checks the states one by one).

:func:`corner_impact` is the corner impact map of a restitution other than Housner's (see the
stepper's docstring): the same problem without forces, scaled when it is a rotation about the
impacting corner.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import IntEnum
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..mechanics.modes import Mode

__all__ = [
    "Phase",
    "Arms",
    "Contact",
    "ContactState",
    "corner_impact",
    "SLIDES",
    "ROCKS",
    "PIVOT_O",
    "PIVOT_P",
]

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
CodeArray = NDArray[np.int8]


class Phase(IntEnum):
    """A contact state of one step, coded as the :class:`~regimemap.mechanics.modes.Mode` it is.

    Codes 0-7 are the modes of contact; ``FLIGHT`` (no corner in contact) is
    :attr:`Mode.LO <regimemap.mechanics.modes.Mode.LO>`, the map's lift-off,
    seen from the motion: ``Phase(c)`` and ``Mode(c)`` name the same state.
    """

    RE = Mode.RE.value
    SL = Mode.SL.value
    RO = Mode.RO.value
    SRO_MINUS = Mode.SRO_MINUS.value
    SRO_PLUS = Mode.SRO_PLUS.value
    SRO_PRIME_MINUS = Mode.SRO_PRIME_MINUS.value
    RO_PRIME = Mode.RO_PRIME.value
    SRO_PRIME_PLUS = Mode.SRO_PRIME_PLUS.value
    FLIGHT = Mode.LO.value

    @property
    def label(self) -> str:
        """The report's symbol: RE, SL, RO, SRO-, SRO+, SRO'-, RO', SRO'+ or FLIGHT."""
        return _PHASE_LABELS[self]


_PHASE_LABELS = {
    Phase.RE: "RE", Phase.SL: "SL", Phase.RO: "RO", Phase.SRO_MINUS: "SRO-", Phase.SRO_PLUS: "SRO+",
    Phase.SRO_PRIME_MINUS: "SRO'-", Phase.RO_PRIME: "RO'", Phase.SRO_PRIME_PLUS: "SRO'+",
    Phase.FLIGHT: "FLIGHT",
}

# What a state does, indexed by its Phase code.
#                   RE     SL     RO     SRO-   SRO+   SRO'-  RO'    SRO'+  FLIGHT
#: Whether the base slips in the state.
SLIDES = np.array([False, True, False, True, True, True, False, True, False])
#: Whether a corner is off the base in the state.
ROCKS = np.array([False, False, True, True, True, True, True, True, True])
#: Whether the block turns about O alone (RO, SRO-, SRO+).
PIVOT_O = np.array([False, False, True, True, True, False, False, False, False])
#: Whether the block turns about O' alone (SRO'-, RO', SRO'+).
PIVOT_P = np.array([False, False, False, False, False, True, True, True, False])


class Arms(NamedTuple):
    """The vectors from C to the corners O and O' (m), one value per run."""

    xO: FloatArray
    yO: FloatArray
    xP: FloatArray
    yP: FloatArray

    @classmethod
    def at(cls, theta: FloatArray, B: FloatArray, H: FloatArray) -> Arms:
        """The arms of a block of half width ``B`` and height ``H`` of C, turned by ``theta`` (rad).

        The same arithmetic as the stepper's (bit for bit).
        """
        c = np.cos(theta)
        s = np.sin(theta)
        Bc, Bs, Hc, Hs = B * c, B * s, H * c, H * s
        return cls(Hs - Bc, -Bs - Hc, Bc + Hs, Bs - Hc)


class ContactState(NamedTuple):
    """The solution of the contact problem, per run.

    Attributes
    ----------
    vx, vy, om : ndarray
        The velocity after the step (m/s, m/s, rad/s).
    code : ndarray of int8
        The :class:`Phase` code of the state taken.
    unresolved : ndarray of bool
        Runs where no state was admissible (a stuck-corner fallback was used).
    """

    vx: FloatArray
    vy: FloatArray
    om: FloatArray
    code: CodeArray
    unresolved: BoolArray


class _Corner(NamedTuple):
    """One corner of the problem seen from itself: its arm, normal velocity, activity and the
    other corner's arm and activity."""

    rx: FloatArray
    ry: FloatArray
    uN: FloatArray
    act: BoolArray
    rx_other: FloatArray
    act_other: BoolArray


_Velocity = tuple[FloatArray, FloatArray, FloatArray]
_Candidate = tuple[int, BoolArray, "FloatArray | float", "FloatArray | float", "FloatArray | float"]


@dataclass(frozen=True)
class Contact:
    """The contact problem of one step for a batch of runs (arrays of one length).

    Attributes
    ----------
    arms : Arms
        Vectors from C to O and O' (at the step's mid-point).
    act_O, act_P : ndarray of bool
        Whether corner O, O' is active (closed on the base, or about to).
    mu : ndarray
        Friction coefficient.
    J : ndarray
        Moment of inertia about C per unit mass (m^2).
    tol : ndarray
        Tolerance of the sign conditions (a velocity, m/s).
    """

    arms: Arms
    act_O: BoolArray
    act_P: BoolArray
    mu: FloatArray
    J: FloatArray
    tol: FloatArray

    def take(self, sel: NDArray[np.intp]) -> Contact:
        """The problem of the runs ``sel`` (indices) only."""
        return Contact(Arms(*(a[sel] for a in self.arms)), self.act_O[sel], self.act_P[sel],
                       self.mu[sel], self.J[sel], self.tol[sel])

    def solve(self, vxf: FloatArray, vyf: FloatArray, omf: FloatArray) -> ContactState:
        """The velocity after the step from the free velocity (vxf, vyf, omf), and its state.

        The states are tried in the priority order of the module docstring, each run taking the
        first that is admissible for it; states that no run can be in (no run with that corner
        active) are skipped, and so are the states after the point where every run has found
        one (the result is the same: a later state never overrides an earlier one).
        """
        a = self.arms
        uNO = vyf + a.xO * omf
        uNP = vyf + a.xP * omf
        act_O, act_P = self.act_O, self.act_P
        any_O, any_P = bool(act_O.any()), bool(act_P.any())
        both = act_O & act_P
        at_O = _Corner(a.xO, a.yO, uNO, act_O, a.xP, act_P)
        at_P = _Corner(a.xP, a.yP, uNP, act_P, a.xO, act_O)
        v = (vxf, vyf, omf)
        stick: dict[int, tuple[BoolArray, FloatArray, FloatArray, FloatArray]] = {}

        def stick_at(c_: int) -> tuple[BoolArray, FloatArray, FloatArray, FloatArray]:
            if c_ not in stick:
                stick[c_] = self._stick(v, at_O if c_ == Phase.RO else at_P)
            return stick[c_]

        # the candidate states in priority order, computed when needed: (code, admissible, vx, vy, om)
        cands: list[Callable[[], list[_Candidate]]] = []
        if both.any():
            cands.append(lambda: [self._rest(v, both), *self._slides(v, both)])
        if any_P:
            cands.append(lambda: [(Phase.SRO_PRIME_MINUS, *self._slip(v, -1.0, at_P))])
        if any_O:
            cands.append(lambda: [(Phase.RO, *stick_at(Phase.RO))])
            cands.append(lambda: [(Phase.SRO_MINUS, *self._slip(v, -1.0, at_O)),
                                  (Phase.SRO_PLUS, *self._slip(v, 1.0, at_O))])
        if any_P:
            cands.append(lambda: [(Phase.RO_PRIME, *stick_at(Phase.RO_PRIME)),
                                  (Phase.SRO_PRIME_PLUS, *self._slip(v, 1.0, at_P))])

        vx1, vy1, om1 = v
        code = np.full(vxf.shape, Phase.FLIGHT, dtype=np.int8)
        found = np.zeros(vxf.shape, dtype=bool)
        for make in cands:
            for c_, okk, cvx, cvy, com in make():
                take = okk & ~found
                vx1 = np.where(take, cvx, vx1)
                vy1 = np.where(take, cvy, vy1)
                om1 = np.where(take, com, om1)
                code[take] = c_
                found |= okk
            if found.all():
                return ContactState(vx1, vy1, om1, code, ~found)
        # flight, where no contact state is admissible
        tol = self.tol
        found |= (~act_O | (uNO >= -tol)) & (~act_P | (uNP >= -tol))
        none = ~found
        if none.any():
            # nothing admissible (never met in our runs): stop, or stick on the active corner
            for act, c_ in ((act_P, Phase.RO_PRIME), (act_O, Phase.RO)):
                m = none & act
                if m.any():
                    st_ = stick_at(c_)
                    vx1 = np.where(m, st_[1], vx1)
                    vy1 = np.where(m, st_[2], vy1)
                    om1 = np.where(m, st_[3], om1)
                    code[m] = c_
            m = none & both
            vx1 = np.where(m, 0.0, vx1)
            vy1 = np.where(m, 0.0, vy1)
            om1 = np.where(m, 0.0, om1)
            code[m] = Phase.RE
        return ContactState(vx1, vy1, om1, code, none)

    # -- the states ------------------------------------------------------------------------------

    def _rest(self, v: _Velocity, both: BoolArray) -> _Candidate:
        """RE: both corners stick, v = 0.

        The impulse (Rx, Ry, Rm) = -M v_f is shared by the corners: T_O = t, T_P = Rx - t,
        N_O = a + b t, N_P = Ry - N_O; the feasible t by interval intersection.
        """
        vxf, vyf, omf = v
        a_ = self.arms
        mu, tol = self.mu, self.tol
        Rx = -vxf
        Ry = -vyf
        d = a_.xO - a_.xP
        a = (-self.J * omf - a_.xP * Ry + a_.yP * Rx) / d
        b = (a_.yO - a_.yP) / d
        mub = mu * b
        ok = both.copy()
        # N_O >= 0 and N_P >= 0: -b t <= a, b t <= Ry - a
        bz = np.abs(b) <= 1e-14
        bs = np.where(bz, 1.0, b)
        r1 = -(a + tol) / bs
        r2 = (Ry - a + tol) / bs
        ok &= ~bz | ((a >= -tol) & (Ry - a >= -tol))
        bpos = b > 1e-14
        bneg = b < -1e-14
        inf = np.inf
        hi = np.where(bpos, r2, np.where(bneg, r1, inf))
        lo = np.where(bpos, r1, np.where(bneg, r2, -inf))
        # Coulomb at both corners: c t <= d with c = +-1 -+ mu b (never 0 for |mu b| < 1)
        for ci, di in ((1.0 - mub, mu * a), (-1.0 - mub, mu * a),
                       (-1.0 + mub, mu * (Ry - a) - Rx), (1.0 + mub, mu * (Ry - a) + Rx)):
            r = (di + tol) / np.where(np.abs(ci) > 1e-14, ci, 1e-14)
            pos = ci > 0.0
            hi = np.where(pos, np.minimum(hi, r), hi)
            lo = np.where(pos, lo, np.maximum(lo, r))
        ok &= lo <= hi
        return (Phase.RE, ok, 0.0, 0.0, 0.0)

    def _slides(self, v: _Velocity, both: BoolArray) -> list[_Candidate]:
        """SL: both corners slip with the sign s of x_dot (s = -1, then +1); y_dot = theta_dot = 0."""
        vxf, vyf, omf = v
        a_ = self.arms
        mu, tol = self.mu, self.tol
        out: list[_Candidate] = []
        for sgn in (-1.0, 1.0):
            cO = a_.xO + sgn * mu * a_.yO
            cP = a_.xP + sgn * mu * a_.yP
            NO = (-self.J * omf + cP * vyf) / (cO - cP)
            NP = -vyf - NO
            vx = vxf + sgn * mu * vyf
            out.append((Phase.SL, both & (NO >= -tol) & (NP >= -tol) & (sgn * vx >= -tol), vx, 0.0, 0.0))
        return out

    def _stick(self, v: _Velocity, k: _Corner) -> tuple[BoolArray, FloatArray, FloatArray, FloatArray]:
        """One corner stuck, the other free (RO about O, RO' about O'): admissible, vx, vy, om."""
        vxf, vyf, omf = v
        J, mu, tol = self.J, self.mu, self.tol
        uT = vxf - k.ry * omf
        ax = k.rx / J
        ay = k.ry / J
        det = 1.0 + k.rx * ax + k.ry * ay
        N = -((1.0 + k.ry * ay) * k.uN + k.rx * ay * uT) / det
        T = -(k.rx * ay * k.uN + (1.0 + k.rx * ax) * uT) / det
        vx = vxf + T
        vy = vyf + N
        om = omf + ax * N - ay * T
        okk = (k.act & (N >= -tol) & (np.abs(T) <= mu * N + tol)
               & (~k.act_other | (vy + k.rx_other * om >= -tol)))
        return okk, vx, vy, om

    def _slip(self, v: _Velocity, sgn: float,
              k: _Corner) -> tuple[BoolArray, FloatArray, FloatArray, FloatArray]:
        """One corner slipping with the sign ``sgn`` of its velocity, the other free (SRO-, SRO+
        about O, SRO'-, SRO'+ about O'): admissible, vx, vy, om."""
        vxf, vyf, omf = v
        mu, tol = self.mu, self.tol
        c = (k.rx + sgn * mu * k.ry) / self.J
        den = 1.0 + k.rx * c
        N = -k.uN / np.where(den > 0.0, den, 1.0)
        vx = vxf - sgn * mu * N
        vy = vyf + N
        om = omf + c * N
        okk = (k.act & (den > 0.0) & (N >= -tol) & (sgn * (vx - k.ry * om) >= -tol)
               & (~k.act_other | (vy + k.rx_other * om >= -tol)))
        return okk, vx, vy, om


def corner_impact(contact: Contact, v: _Velocity, new_O: BoolArray, new_P: BoolArray,
                  ratio: FloatArray) -> _Velocity:
    """The corner impact map: the velocity just after corners close on the base.

    The contact problem is solved without forces (the plastic impact); where its result is a
    rotation about a corner that has just closed (``new_O`` with state RO, ``new_P`` with RO'),
    it is scaled by ``ratio`` (the restitution over Housner's ratio), capped so that the kinetic
    energy never grows; other impacts (flat landings, slipping impacts) stay plastic.

    Parameters
    ----------
    contact : Contact
        The problem of the impacting runs.
    v : tuple of ndarray
        Their velocity (vx, vy, om) just before the impact.
    new_O, new_P : ndarray of bool
        Whether O, O' has just closed on the base.
    ratio : ndarray
        The factor of a rocking impact over the plastic one.

    Returns
    -------
    tuple of ndarray
        The velocity (vx, vy, om) after the impact.
    """
    vx, vy, om = v
    J = contact.J
    plastic = contact.solve(vx, vy, om)
    rock = (((plastic.code == Phase.RO) & new_O) | ((plastic.code == Phase.RO_PRIME) & new_P))
    ke0 = vx ** 2 + vy ** 2 + J * om ** 2
    ke1 = plastic.vx ** 2 + plastic.vy ** 2 + J * plastic.om ** 2
    fac = np.minimum(ratio, np.sqrt(ke0 / np.where(ke1 > 0, ke1, 1.0)))
    fac = np.where(rock, fac, 1.0)
    return fac * plastic.vx, fac * plastic.vy, fac * plastic.om
