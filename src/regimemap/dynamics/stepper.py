"""Moreau-Jean time stepping of a rigid block with two unilateral frictional corners.

Size: over 500 lines on purpose: the scheme, the closed forms of the ten contact states
and the bookkeeping of a batch belong to one time step.

The scheme
----------
Velocity-level time stepping of Moreau (1988) and Jean (1999), theta-method with
theta = 1/2, vectorised over a batch of runs.  Per unit mass, with generalised
velocity v = (x_dot, y_dot, theta_dot) of C, mass matrix M = diag(1, 1, J),
J = i2 B^2, and step h::

    t_m = t_k + h/2,   q_m = q_k + (h/2) v_k                  (mid-point)
    active contacts:   g_j(q_m) <= eps_g                      (j = O, O')
    M (v_{k+1} - v_k) = h f(t_m, q_m) + sum_j (W_N,j P_N,j + W_T,j P_T,j)
    q_{k+1} = q_k + (h/2) (v_k + v_{k+1})

with, at every active corner, the velocity-level Signorini-Coulomb conditions
(normal restitution 0)::

    0 <= u_N,j ⊥ P_N,j >= 0
    stick: u_T,j = 0, |P_T,j| <= mu P_N,j ;  slip: P_T,j = -mu P_N,j sign(u_T,j)

where u_N,j = y_dot + theta_dot r_x,j and u_T,j = x_dot - theta_dot r_y,j are
the corner velocities and r_j the vector from C to corner j (at q_m).

The per-step contact problem (two corners, three degrees of freedom) is solved
*exactly* by enumerating its ten contact states -- both corners stuck (rest),
both slipping left or right (slide), one corner stuck or slipping left/right
with the other free (rock, slide-rock about O or O'), and flight -- each a
linear system of at most 3 unknowns in closed form, and taking the first state
whose sign conditions hold, in the order of Section 4.7 of the report
(:data:`regimemap.PRIORITY`): RE, SL, SRO'-, RO, SRO-, SRO+, RO', SRO'+, then
FLIGHT.  Where the Coulomb problem has several solutions (Painleve-type
configurations) this order picks one, as :func:`regimemap.classify` does at the
onset; the state never needs hand-written transition logic, and impacts,
chattering rest and lift-off all come out of the same step.

Rest is exact: when both corners can stick, v_{k+1} = 0 is set exactly, so a
block below every threshold never drifts (x = theta = 0 to the last bit).

Impacts
-------
With restitution 0 the step makes a corner that closes on the base stop
(plastic impact).  If friction holds the impacting corner, the impulse acts
there only, angular momentum about it is conserved, and for a block rocking
about the other corner the ratio is Housner's (1963)::

    theta_dot+/theta_dot- = (I + m (H^2 - B^2)) / (I + m (H^2 + B^2))
                          = 1 - (3/2) sin^2(alpha)   (uniform block)

``restitution=r`` replaces this ratio by r (experiments often give less than
Housner's value): when a corner that was not in contact closes on the base
with speed above ``g h``, a *corner impact map* is applied before the step:
the same contact problem is solved without forces (the plastic impact), and if
its result is rotation about the impacting corner (state RO or RO') the
post-impact velocity is that result times r/eta_H (eta_H the Housner ratio
above), capped so that kinetic energy never grows; other impacts (flat
landings, slipping impacts) stay plastic.  The step then proceeds from the
mapped velocity.

Outcome
-------
A run leaves the batch when it has come to rest after the pulse (state RE with
the pulse over), when it has overturned -- |theta| > pi/2, or, once the pulse
is over, |theta| >= alpha with outward angular velocity and the constant loads
turning it outward about the pivot (then nothing can bring it back) -- or at
``t_max``.

References
----------
Moreau, J. J. (1988). Unilateral contact and dry friction in finite freedom
dynamics. In Nonsmooth Mechanics and Applications, CISM 302, Springer, 1-82.

Jean, M. (1999). The non-smooth contact dynamics method. Comput. Methods Appl.
Mech. Eng. 177, 235-257.

Housner, G. W. (1963). Bull. Seismol. Soc. Am. 53(2), 403-417.

Makris, N. & Roussos, Y. (2000). Geotechnique 50(3), 243-262.

Zhang, J. & Makris, N. (2001). J. Eng. Mech. 127(5), 473-483.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import IntEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mechanics.modes import Mode
from .block import Block
from .pulses import Pulse

__all__ = [
    "Phase",
    "History",
    "Simulation",
    "simulate",
    "default_steps",
    "PULSE_STEPS",
    "FREE_STEP",
    "CATEGORY_LABELS",
    "REST",
    "SLIDE",
    "ROCK",
    "SLIDE_ROCK",
    "OVERTURN",
]

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
IntArray = NDArray[np.int64]

#: Default number of steps over a pulse (the step is at most duration / PULSE_STEPS).
PULSE_STEPS = 400
#: Default step outside the pulse, in units of 1/p (the step is FREE_STEP / p).
FREE_STEP = 0.004
#: Default time after the pulse, in units of 1/p, before a moving run is given up.
FREE_TIME = 60.0


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

# Outcome categories (integer codes).
REST, SLIDE, ROCK, SLIDE_ROCK, OVERTURN = 0, 1, 2, 3, 4
#: Labels of the outcome categories, by code.
CATEGORY_LABELS: tuple[str, ...] = ("rest", "slide only", "rock only", "slide-rock", "overturned")

#                          RE     SL     RO     SRO-   SRO+   SRO'-  RO'    SRO'+  FLIGHT
_SLIDES = np.array([False, True, False, True, True, True, False, True, False])
_ROCKS = np.array([False, False, True, True, True, True, True, True, True])
_PIVOT_O = np.array([False, False, True, True, True, False, False, False, False])
_PIVOT_P = np.array([False, False, False, False, False, True, True, True, False])


@dataclass(frozen=True)
class History:
    """Time history of one run (values at the step ends; ``phase``/``k`` of the step ending there)."""

    t: FloatArray
    x: FloatArray
    y: FloatArray
    theta: FloatArray
    vx: FloatArray
    vy: FloatArray
    omega: FloatArray
    k: FloatArray
    phase: NDArray[np.int8]

    def base_slide(self, H: float) -> FloatArray:
        """Horizontal displacement of the middle of the base (m), positive towards O, for a
        block whose C is ``H`` (m) above the base: -(x + H sin(theta))."""
        return -(self.x + H * np.sin(self.theta))


@dataclass(frozen=True)
class Simulation:
    """Outcome of a batch of runs (arrays of length n_runs).

    Attributes
    ----------
    overturned : ndarray of bool
    max_rotation : ndarray
        Largest |theta| (rad).
    residual_rotation : ndarray
        Final theta (rad).
    residual_slide : ndarray
        Final horizontal displacement of the middle of the base (m), positive towards O.
    impacts : ndarray of int
        Number of corner impacts (a corner closing on the base faster than g h).
    initial_mode : ndarray of int8
        :class:`Phase` code of the first step (the motion at t = 0+).
    slid, rocked : ndarray of bool
        Whether the base ever slipped / a corner ever lifted.
    settled : ndarray of bool
        Came to rest after the pulse (False when overturned or stopped at t_max).
    end_time : ndarray
        Time at which the run left the batch (s).
    steps : ndarray of int
        Number of steps taken.
    unresolved : int
        Steps where no contact state was admissible (a stuck-corner fallback was used);
        0 in every case we ran.
    phases : list of list of (str, float) or None
        Per run, the sequence of (phase label, start time).
    history : History or None
        Histories of the run requested with ``history=``.
    """

    overturned: BoolArray
    max_rotation: FloatArray
    residual_rotation: FloatArray
    residual_slide: FloatArray
    impacts: IntArray
    initial_mode: NDArray[np.int8]
    slid: BoolArray
    rocked: BoolArray
    settled: BoolArray
    end_time: FloatArray
    steps: IntArray
    unresolved: int
    phases: list[list[tuple[str, float]]] | None
    history: History | None

    @property
    def category(self) -> NDArray[np.int8]:
        """Outcome category code per run (see :data:`CATEGORY_LABELS`)."""
        cat = np.full(self.overturned.shape, REST, dtype=np.int8)
        cat[self.slid] = SLIDE
        cat[self.rocked] = ROCK
        cat[self.slid & self.rocked] = SLIDE_ROCK
        cat[self.overturned] = OVERTURN
        return cat


def default_steps(block: Block, pulse: Pulse, n: int | None = None,
                  dt: float | None = None) -> tuple[FloatArray, FloatArray]:
    """Per-run time steps (h_pulse, h_free) (s).

    By default h_free = FREE_STEP/p and h_pulse = duration/N with N the smallest
    integer such that h_pulse <= min(duration/PULSE_STEPS, h_free): the pulse
    end falls on a step end.  ``dt`` (s) replaces both bounds.
    """
    if n is None:
        n = int(np.broadcast(np.asarray(block.B), np.asarray(block.gamma), pulse.duration).size)
    T = np.broadcast_to(pulse.duration, (n,)).astype(np.float64)
    if dt is None:
        h_free = np.broadcast_to(FREE_STEP / block.p, (n,)).astype(np.float64)
        bound = np.minimum(T / PULSE_STEPS, h_free)
    else:
        h_free = np.full(n, float(dt))
        bound = h_free
    n_pulse = np.ceil(T / bound - 1e-9)
    return T / n_pulse, h_free


_Solved = tuple[FloatArray, FloatArray, FloatArray, NDArray[np.int8], BoolArray]

# -- the per-step contact problem -------------------------------------------------------------------


def _contact(vxf: FloatArray, vyf: FloatArray, omf: FloatArray,
             rxO: FloatArray, ryO: FloatArray, rxP: FloatArray, ryP: FloatArray,
             actO: BoolArray, actP: BoolArray, mu: FloatArray, J: FloatArray,
             tol: FloatArray) -> _Solved:
    """Solve the two-corner contact problem of one step, for every run.

    States that no run can be in (no run with that corner active) are skipped.  Returns the new
    velocities, the :class:`Phase` code of the chosen state and a mask of the
    runs where no state was admissible (a fallback was used).
    """
    return _contact_states(vxf, vyf, omf, rxO, ryO, rxP, ryP, actO, actP, mu, J, tol)


def _contact_states(vxf: FloatArray, vyf: FloatArray, omf: FloatArray,
                    rxO: FloatArray, ryO: FloatArray, rxP: FloatArray, ryP: FloatArray,
                    actO: BoolArray, actP: BoolArray, mu: FloatArray, J: FloatArray,
                    tol: FloatArray) -> _Solved:
    """Enumerate the contact states of the runs given (see :func:`_contact`)."""
    uNO = vyf + rxO * omf
    uNP = vyf + rxP * omf
    both = actO & actP
    any_both = bool(both.any())
    any_O = bool(actO.any())
    any_P = bool(actP.any())
    # candidate states in priority order: (code, admissible, vx, vy, om)
    cands: list[tuple[int, BoolArray, FloatArray | float, FloatArray | float, FloatArray | float]] = []

    if any_both:
        # RE: both corners stick, v = 0.  Impulse (Rx, Ry, Rm) = -M vf shared by the corners:
        # T_O = t, T_P = Rx - t, N_O = a + b t, N_P = Ry - N_O; feasible t by interval intersection.
        Rx = -vxf
        Ry = -vyf
        d = rxO - rxP
        a = (-J * omf - rxP * Ry + ryP * Rx) / d
        b = (ryO - ryP) / d
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
        cands.append((Phase.RE, ok, 0.0, 0.0, 0.0))
        # SL: both corners slip with sign s of x_dot; y_dot = theta_dot = 0.
        for sgn in (-1.0, 1.0):
            cO = rxO + sgn * mu * ryO
            cP = rxP + sgn * mu * ryP
            NO = (-J * omf + cP * vyf) / (cO - cP)
            NP = -vyf - NO
            vx = vxf + sgn * mu * vyf
            cands.append((Phase.SL, both & (NO >= -tol) & (NP >= -tol) & (sgn * vx >= -tol), vx, 0.0, 0.0))

    def stick(rx: FloatArray, ry: FloatArray, uN: FloatArray, act: BoolArray,
              rxo: FloatArray, acto: BoolArray) -> tuple[BoolArray, FloatArray, FloatArray, FloatArray]:
        uT = vxf - ry * omf
        ax = rx / J
        ay = ry / J
        det = 1.0 + rx * ax + ry * ay
        N = -((1.0 + ry * ay) * uN + rx * ay * uT) / det
        T = -(rx * ay * uN + (1.0 + rx * ax) * uT) / det
        vx = vxf + T
        vy = vyf + N
        om = omf + ax * N - ay * T
        okk = act & (N >= -tol) & (np.abs(T) <= mu * N + tol) & (~acto | (vy + rxo * om >= -tol))
        return okk, vx, vy, om

    def slip(sgn: float, rx: FloatArray, ry: FloatArray, uN: FloatArray, act: BoolArray,
             rxo: FloatArray, acto: BoolArray) -> tuple[BoolArray, FloatArray, FloatArray, FloatArray]:
        c = (rx + sgn * mu * ry) / J
        den = 1.0 + rx * c
        N = -uN / np.where(den > 0.0, den, 1.0)
        vx = vxf - sgn * mu * N
        vy = vyf + N
        om = omf + c * N
        okk = (act & (den > 0.0) & (N >= -tol) & (sgn * (vx - ry * om) >= -tol)
               & (~acto | (vy + rxo * om >= -tol)))
        return okk, vx, vy, om

    stickO = stickP = None
    if any_P:
        cands.append((Phase.SRO_PRIME_MINUS, *slip(-1.0, rxP, ryP, uNP, actP, rxO, actO)))
    if any_O:
        stickO = stick(rxO, ryO, uNO, actO, rxP, actP)
        cands.append((Phase.RO, *stickO))
        cands.append((Phase.SRO_MINUS, *slip(-1.0, rxO, ryO, uNO, actO, rxP, actP)))
        cands.append((Phase.SRO_PLUS, *slip(1.0, rxO, ryO, uNO, actO, rxP, actP)))
    if any_P:
        stickP = stick(rxP, ryP, uNP, actP, rxO, actO)
        cands.append((Phase.RO_PRIME, *stickP))
        cands.append((Phase.SRO_PRIME_PLUS, *slip(1.0, rxP, ryP, uNP, actP, rxO, actO)))

    # flight, then overwrite by the states from the lowest to the highest priority
    flight = (~actO | (uNO >= -tol)) & (~actP | (uNP >= -tol))
    vx1 = vxf
    vy1 = vyf
    om1 = omf
    code = np.full(vxf.shape, Phase.FLIGHT, dtype=np.int8)
    found = flight
    for c_, okk, cvx, cvy, com in reversed(cands):
        vx1 = np.where(okk, cvx, vx1)
        vy1 = np.where(okk, cvy, vy1)
        om1 = np.where(okk, com, om1)
        code[okk] = c_
        found = found | okk
    none = ~found
    if none.any():
        # nothing admissible (never met in our runs): stop, or stick on the active corner
        for act, st_, c_ in ((actP, stickP, Phase.RO_PRIME), (actO, stickO, Phase.RO)):
            if st_ is not None:
                m = none & act
                vx1 = np.where(m, st_[1], vx1)
                vy1 = np.where(m, st_[2], vy1)
                om1 = np.where(m, st_[3], om1)
                code[m] = c_
        m = none & both
        vx1 = np.where(m, 0.0, vx1)
        vy1 = np.where(m, 0.0, vy1)
        om1 = np.where(m, 0.0, om1)
        code[m] = Phase.RE
    return vx1, vy1, om1, code, none


# -- the batch time stepper --------------------------------------------------------------------------


def _as_runs(value: ArrayLike, n: int) -> FloatArray:
    return np.broadcast_to(np.asarray(value, dtype=np.float64), (n,)).astype(np.float64)


def simulate(block: Block, pulse: Pulse, *, dt: float | None = None, t_max: ArrayLike | None = None,
             restitution: float | None = None, theta0: ArrayLike = 0.0, omega0: ArrayLike = 0.0,
             history: int | None = None, record_phases: bool = True) -> Simulation:
    """Simulate a batch of runs of a block under force pulses, from rest.

    Parameters
    ----------
    block : Block
        The block(s); array fields give one value per run.
    pulse : Pulse
        The pulse(s); ``k_peak`` and ``duration`` may be arrays (one per run).
    dt : float, optional
        Time step (s); by default :func:`default_steps` (duration/400 over the
        pulse, at most 0.004/p; 0.004/p after it).  Chosen so that overturning
        thresholds are within 1 % of the event-driven reference (docs/dynamics.md).
    t_max : array_like, optional
        Time (s) after which a still-moving run is given up (default
        duration + 60/p).
    restitution : float, optional
        Ratio theta_dot+/theta_dot- of a rocking impact (the corner impact map
        of the module docstring); None is the plastic impact of the scheme,
        which is Housner's ratio.
    theta0, omega0 : array_like
        Initial rotation (rad; the block then stands on its lower corner) and
        angular velocity (rad/s) about that corner (only when theta0 != 0).
    history : int, optional
        Index of a run whose time history is returned.
    record_phases : bool
        Whether to return the list of phases per run.

    Returns
    -------
    Simulation
    """
    if restitution is not None and not 0.0 <= restitution <= 1.0:
        raise ValueError("restitution must lie in [0, 1]")
    n = int(np.broadcast(np.asarray(block.B), np.asarray(block.gamma), np.asarray(block.mu),
                         np.asarray(block.kprime), np.asarray(block.beta), np.asarray(block.u),
                         np.asarray(block.nu), np.asarray(block.e_u),
                         np.asarray(block.gamma if block.i2 is None else block.i2),
                         pulse.k_peak, pulse.duration, np.asarray(theta0), np.asarray(omega0)).size)
    g = float(block.g)
    par = block.arrays(n)
    kp_all, T_all = pulse.arrays(n)
    hp_all, hf_all = default_steps(block, pulse, n, dt)
    p_all = _as_runs(block.p, n)
    tmax_all = T_all + FREE_TIME / p_all if t_max is None else _as_runs(t_max, n)
    loaded = block.loaded

    B = par["B"]
    H = B * par["gamma"]
    J = par["i2"] * B * B
    eta_h = (J + H * H - B * B) / (J + H * H + B * B)
    alpha = np.arctan2(B, H)
    th0 = _as_runs(theta0, n)
    om0 = _as_runs(omega0, n)
    # standing on the lower corner: y such that that corner touches the base
    y0 = B * np.abs(np.sin(th0)) + H * np.cos(th0) - H
    # velocity of C when rotating at om0 about the touching corner r (from C): v = om z x (-r)
    c0 = np.cos(th0)
    s0 = np.sin(th0)
    r_x = np.where(th0 > 0, H * s0 - B * c0, B * c0 + H * s0)
    r_y = np.where(th0 > 0, -B * s0 - H * c0, B * s0 - H * c0)
    vxi = np.where(th0 != 0, om0 * r_y, 0.0)
    vyi = np.where(th0 != 0, -om0 * r_x, 0.0)
    omi = np.where(th0 != 0, om0, 0.0)

    # active (compacted) state
    idx = np.arange(n)
    x = np.zeros(n)
    y = y0.copy()
    th = th0.copy()
    vx = vxi.copy()
    vy = vyi.copy()
    om = omi.copy()
    t = np.zeros(n)
    nleft = np.rint(T_all / hp_all).astype(np.int64)
    A = {"B": B, "H": H, "J": J, "mu": par["mu"], "kpr": par["kprime"], "beta": par["beta"],
         "u": par["u"], "nu": par["nu"], "eu": par["e_u"], "kp": kp_all, "T": T_all, "hp": hp_all,
         "hf": hf_all, "tmax": tmax_all, "eta": eta_h, "alpha": alpha}
    prevO = np.zeros(n, dtype=bool)
    prevP = np.zeros(n, dtype=bool)
    prev_code = np.full(n, -1, dtype=np.int8)
    maxrot = np.abs(th0)
    imp = np.zeros(n, dtype=np.int64)
    slid = np.zeros(n, dtype=bool)
    rocked = np.zeros(n, dtype=bool)
    nsteps = np.zeros(n, dtype=np.int64)

    # outputs
    o_over = np.zeros(n, dtype=bool)
    o_max = np.zeros(n)
    o_res = np.zeros(n)
    o_slide = np.zeros(n)
    o_imp = np.zeros(n, dtype=np.int64)
    o_init = np.full(n, -1, dtype=np.int8)
    o_slid = np.zeros(n, dtype=bool)
    o_rock = np.zeros(n, dtype=bool)
    o_set = np.zeros(n, dtype=bool)
    o_end = np.zeros(n)
    o_steps = np.zeros(n, dtype=np.int64)
    unresolved = 0
    ph_run: list[IntArray] = []
    ph_code: list[NDArray[np.int8]] = []
    ph_t: list[FloatArray] = []
    hist: dict[str, list[float]] | None = None
    if history is not None:
        if not 0 <= history < n:
            raise IndexError(f"history run {history} out of range (n = {n})")
        hist = {key: [] for key in ("t", "x", "y", "theta", "vx", "vy", "omega", "k", "phase")}
        hist["t"].append(0.0)
        for key, arr in (("x", x), ("y", y), ("theta", th), ("vx", vx), ("vy", vy), ("omega", om)):
            hist[key].append(float(arr[history]))
        hist["k"].append(0.0)
        hist["phase"].append(-1.0)
    first = True
    pulse_kprime = pulse.has_kprime
    half_pi = 0.5 * math.pi

    while idx.size:
        Bv, Hv, Jv, mu = A["B"], A["H"], A["J"], A["mu"]
        in_pulse = nleft > 0
        h = np.where(in_pulse, A["hp"], A["hf"])
        hh = 0.5 * h
        tm = t + hh
        k = pulse.k(tm, A["kp"], A["T"])
        thm = th + hh * om
        c = np.cos(thm)
        s = np.sin(thm)
        Bc = Bv * c
        Bs = Bv * s
        Hc = Hv * c
        Hs = Hv * s
        rxO = Hs - Bc
        ryO = -Bs - Hc
        rxP = Bc + Hs
        ryP = Bs - Hc
        # activation on the linearised gap at the mid-point, g(q_k) + (h/2) u_N (Moreau 1988)
        c0 = np.cos(th)
        s0 = np.sin(th)
        gO = Hv + y - Bv * s0 - Hv * c0
        gP = Hv + y + Bv * s0 - Hv * c0
        # tolerance: v_k met the constraint with the previous step's arms, an O(h^2 om^2 R) mismatch
        gtol = 1e-6 * Bv + (h * om) ** 2 * (Bv + Hv)
        actO = gO + hh * (vy + rxO * om) <= gtol
        actP = gP + hh * (vy + rxP * om) <= gtol
        tol = 1e-10 * g * h
        # impacts: a corner closing on the base that was not in contact
        newO = actO & ~prevO & (vy + rxO * om < -g * h)
        newP = actP & ~prevP & (vy + rxP * om < -g * h)
        hit = newO | newP
        if restitution is not None and hit.any():
            sel = np.flatnonzero(hit)
            z = np.zeros(sel.size, dtype=bool)
            pvx, pvy, pom, pcode, _ = _contact(
                vx[sel], vy[sel], om[sel], rxO[sel], ryO[sel], rxP[sel], ryP[sel],
                actO[sel] | z, actP[sel] | z, mu[sel], Jv[sel], tol[sel])
            rock = ((pcode == Phase.RO) & newO[sel]) | ((pcode == Phase.RO_PRIME) & newP[sel])
            ke0 = vx[sel] ** 2 + vy[sel] ** 2 + Jv[sel] * om[sel] ** 2
            ke1 = pvx ** 2 + pvy ** 2 + Jv[sel] * pom ** 2
            fac = restitution / A["eta"][sel]
            fac = np.minimum(fac, np.sqrt(ke0 / np.where(ke1 > 0, ke1, 1.0)))
            fac = np.where(rock, fac, 1.0)
            vx[sel] = fac * pvx
            vy[sel] = fac * pvy
            om[sel] = fac * pom
        imp += hit
        # forces per unit mass at (t_m, q_m)
        kpr_t = pulse.kprime(tm) if pulse_kprime else None
        kpr = A["kpr"] if kpr_t is None else kpr_t
        fx = -g * k
        tau = (g / Jv) * k * kpr * Hc
        fy: FloatArray | float
        if loaded:
            lift = A["u"] + A["nu"] * k
            fy = g * (A["beta"] + lift - 1.0)
            tau = tau + (g / Jv) * (A["eu"] * Bc + Hs) * lift
        else:
            fy = -g
        vxf = vx + h * fx
        vyf = vy + h * fy
        omf = om + h * tau
        vx1, vy1, om1, code, none = _contact(vxf, vyf, omf, rxO, ryO, rxP, ryP, actO, actP, mu, Jv, tol)
        if none.any():
            unresolved += int(none.sum())
        x += hh * (vx + vx1)
        y += hh * (vy + vy1)
        th += hh * (om + om1)
        # no drift of a single pivot: the position update of a rotation drifts the pivot's gap by
        # O(h^3) per step; move C vertically so that the pivot keeps its gap (or closes a positive one)
        pivO = _PIVOT_O[code]
        pivP = _PIVOT_P[code]
        if pivO.any() or pivP.any():
            c0 = np.cos(th)
            s0 = np.sin(th)
            y -= np.where(pivO, (Hv + y - Bv * s0 - Hv * c0) - np.minimum(gO, 0.0), 0.0)
            y -= np.where(pivP, (Hv + y + Bv * s0 - Hv * c0) - np.minimum(gP, 0.0), 0.0)
        vx, vy, om = vx1, vy1, om1
        t_old = t
        t = t + h
        nleft = np.maximum(nleft - 1, 0)
        nsteps += 1
        prevO, prevP = actO, actP
        at = np.abs(th)
        np.maximum(maxrot, at, out=maxrot)
        slid |= _SLIDES[code]
        rocked |= _ROCKS[code]
        if first:
            o_init[idx] = code
            first = False
        if record_phases:
            changed = code != prev_code
            if changed.any():
                ph_run.append(idx[changed])
                ph_code.append(code[changed])
                ph_t.append(t_old[changed])
        prev_code = code
        if hist is not None:
            where = np.flatnonzero(idx == history)
            if where.size:
                j = int(where[0])
                for key, arr in (("t", t), ("x", x), ("y", y), ("theta", th), ("vx", vx), ("vy", vy),
                                 ("omega", om), ("k", k)):
                    hist[key].append(float(arr[j]))
                hist["phase"].append(float(code[j]))

        # leaving the batch
        after = nleft == 0
        over = at > half_pi
        if after.any():
            c1 = np.cos(th)
            s1 = np.sin(th)
            rO = Hv * s1 - Bv * c1
            rP = Bv * c1 + Hv * s1
            if loaded:
                ur = A["eu"] * Bv * c1 + Hv * s1
                wt = 1.0 - A["beta"]
                mO = rO * wt + (ur - rO) * A["u"]
                mP = rP * wt + (ur - rP) * A["u"]
            else:
                mO, mP = rO, rP
            away = ((th >= A["alpha"]) & (om > 0) & (mO >= 0)) | ((th <= -A["alpha"]) & (om < 0) & (mP <= 0))
            over |= after & away
        rest = after & (code == Phase.RE)
        done = over | rest | (t >= A["tmax"])
        if done.any():
            d_ = np.flatnonzero(done)
            ids = idx[d_]
            o_over[ids] = over[d_]
            o_set[ids] = rest[d_] & ~over[d_]
            o_max[ids] = maxrot[d_]
            o_res[ids] = th[d_]
            o_slide[ids] = -(x[d_] + Hv[d_] * np.sin(th[d_]))
            o_imp[ids] = imp[d_]
            o_slid[ids] = slid[d_]
            o_rock[ids] = rocked[d_]
            o_end[ids] = t[d_]
            o_steps[ids] = nsteps[d_]
            keep = ~done
            idx = idx[keep]
            x, y, th, vx, vy, om, t = x[keep], y[keep], th[keep], vx[keep], vy[keep], om[keep], t[keep]
            nleft = nleft[keep]
            prevO, prevP, prev_code = prevO[keep], prevP[keep], prev_code[keep]
            maxrot, imp, nsteps = maxrot[keep], imp[keep], nsteps[keep]
            slid, rocked = slid[keep], rocked[keep]
            A = {key: val[keep] for key, val in A.items()}

    phases: list[list[tuple[str, float]]] | None = None
    if record_phases:
        phases = [[] for _ in range(n)]
        if ph_run:
            runs = np.concatenate(ph_run)
            pcs = np.concatenate(ph_code)
            pts = np.concatenate(ph_t)
            for r_, c_, t_ in zip(runs.tolist(), pcs.tolist(), pts.tolist(), strict=True):
                phases[r_].append((_PHASE_LABELS[Phase(c_)], t_))
    hist_out = None
    if hist is not None:
        hist_out = History(**{key: np.asarray(val) for key, val in hist.items() if key != "phase"},
                           phase=np.asarray(hist["phase"]).astype(np.int8))
    return Simulation(overturned=o_over, max_rotation=o_max, residual_rotation=o_res,
                      residual_slide=o_slide, impacts=o_imp, initial_mode=o_init, slid=o_slid,
                      rocked=o_rock, settled=o_set, end_time=o_end, steps=o_steps,
                      unresolved=unresolved, phases=phases, history=hist_out)
