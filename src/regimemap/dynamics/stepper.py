"""Moreau-Jean time stepping of a rigid block with two unilateral frictional corners.

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
(normal restitution 0).  The per-step contact problem is solved *exactly* by
enumerating its ten contact states (:mod:`regimemap.dynamics.contact`), in the
order of Section 4.7 of the report (:data:`regimemap.PRIORITY`): RE, SL, SRO'-,
RO, SRO-, SRO+, RO', SRO'+, then FLIGHT.  The state never needs hand-written
transition logic, and impacts, chattering rest and lift-off all come out of the
same step.

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
with speed above ``g h``, a *corner impact map* is applied before the step
(:func:`regimemap.dynamics.contact.corner_impact`): the same contact problem is
solved without forces (the plastic impact), and if its result is rotation about
the impacting corner (state RO or RO') the post-impact velocity is that result
times r/eta_H (eta_H the Housner ratio above), capped so that kinetic energy
never grows; other impacts (flat landings, slipping impacts) stay plastic.  The
step then proceeds from the mapped velocity.

Events
------
The force is taken at the mid-point, so a peak or a short excursion past a threshold is seen
only where a mid-point falls.  At every *event* of a run -- its pulse's breakpoints and its
crossings of the initiation map of :func:`regimemap.classify` -- the regular step that holds
it is cut and a step of EVENT_STEP h is taken with the force at the event
(:mod:`regimemap.dynamics.events`); from rest (or sliding flat) the contact problem is
homogeneous in h, so that step starts the onset mode at k(t_e) for any duration and any step.
``events=False`` is the regular schedule alone.

Outcome
-------
A run leaves the batch when it has come to rest after the pulse (state RE with
the pulse over), when it has overturned -- |theta| > pi/2, or, once the pulse
is over, |theta| >= alpha with outward angular velocity and the constant loads
turning it outward about the pivot (then nothing can bring it back) -- or at
``t_max`` (still moving: category STILL_MOVING).  The runs still moving are a
:class:`_Batch`, a struct of arrays that loses the runs that leave.

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
from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .block import Block
from .contact import PIVOT_O, PIVOT_P, ROCKS, SLIDES, Arms, Contact, Phase, corner_impact
from .events import event_times, schedule
from .pulses import Pulse
from .recording import RunLog
from .results import (
    CATEGORY_LABELS,
    OVERTURN,
    REST,
    ROCK,
    SLIDE,
    SLIDE_ROCK,
    STILL_MOVING,
    History,
    Simulation,
)

__all__ = ["Phase", "History", "Simulation", "simulate", "default_steps", "PULSE_STEPS", "FREE_STEP",
           "CATEGORY_LABELS", "REST", "SLIDE", "ROCK", "SLIDE_ROCK", "OVERTURN",
           "STILL_MOVING"]

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
IntArray = NDArray[np.int64]
CodeArray = NDArray[np.int8]

#: Default number of steps over a pulse (the step is at most duration / PULSE_STEPS).
PULSE_STEPS = 400
#: Default step outside the pulse, in units of 1/p (the step is FREE_STEP / p).
FREE_STEP = 0.004
#: Default time after the pulse, in units of 1/p, before a moving run is given up.
FREE_TIME = 60.0

_HALF_PI = 0.5 * math.pi


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


def _as_runs(value: ArrayLike, n: int) -> FloatArray:
    return np.broadcast_to(np.asarray(value, dtype=np.float64), (n,)).astype(np.float64)


def _gaps(B: FloatArray, H: FloatArray, y: FloatArray, c0: FloatArray,
          s0: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The heights of O and O' above the base (m), for C at height H + y and rotation theta
    (``c0``, ``s0``: its cosine and sine)."""
    return H + y - B * s0 - H * c0, H + y + B * s0 - H * c0


# -- the batch: the runs still moving, as a struct of arrays ----------------------------------------


@dataclass
class _Outcome:
    """The outcome of every run (length n), filled as the runs leave the batch."""

    overturned: BoolArray
    max_rotation: FloatArray
    residual_rotation: FloatArray
    residual_slide: FloatArray
    impacts: IntArray
    initial_mode: CodeArray
    slid: BoolArray
    rocked: BoolArray
    settled: BoolArray
    end_time: FloatArray
    steps: IntArray

    @classmethod
    def empty(cls, n: int) -> _Outcome:
        """Room for ``n`` runs."""
        return cls(overturned=np.zeros(n, dtype=bool), max_rotation=np.zeros(n),
                   residual_rotation=np.zeros(n), residual_slide=np.zeros(n),
                   impacts=np.zeros(n, dtype=np.int64), initial_mode=np.full(n, -1, dtype=np.int8),
                   slid=np.zeros(n, dtype=bool), rocked=np.zeros(n, dtype=bool),
                   settled=np.zeros(n, dtype=bool), end_time=np.zeros(n),
                   steps=np.zeros(n, dtype=np.int64))


@dataclass
class _Batch:
    """The runs still moving: entry i of every array belongs to the same run.

    Per run: its index in the batch as given (``idx``), its constants (block, pulse, steps, time
    limit), its state at the start of the step and what it has done so far.  :meth:`compress`
    keeps some runs in every array at once; :meth:`retire` writes the outcome of the runs that
    leave and drops them.
    """

    idx: IntArray
    # constants: the block, the pulse, the steps, the time limit
    B: FloatArray
    H: FloatArray
    J: FloatArray
    mu: FloatArray
    kpr: FloatArray
    beta: FloatArray
    u: FloatArray
    nu: FloatArray
    eu: FloatArray
    kp: FloatArray
    T: FloatArray
    hp: FloatArray
    hf: FloatArray
    tmax: FloatArray
    eta: FloatArray
    alpha: FloatArray
    # derived constants: 1e-6 B (the gap tolerance's floor), B + H, g/J
    gtol0: FloatArray
    BH: FloatArray
    gJ: FloatArray
    # the events: the times (inf padding, sorted, a last column of inf), the next one's index and
    # time (``evn`` = ev[i, iev[i]])
    ev: FloatArray
    iev: IntArray
    evn: FloatArray
    # the state at the start of the step (``cth``, ``sth``: the cosine and sine of ``th``); ``mid``:
    # inside a regular step cut by an event, which ends at ``tgt``
    mid: BoolArray
    tgt: FloatArray
    x: FloatArray
    y: FloatArray
    th: FloatArray
    cth: FloatArray
    sth: FloatArray
    vx: FloatArray
    vy: FloatArray
    om: FloatArray
    t: FloatArray
    nleft: IntArray
    prevO: BoolArray
    prevP: BoolArray
    prev_code: CodeArray
    # so far
    maxrot: FloatArray
    imp: IntArray
    slid: BoolArray
    rocked: BoolArray
    nsteps: IntArray

    @classmethod
    def start(cls, block: Block, pulse: Pulse, n: int, dt: float | None, t_max: ArrayLike | None,
              theta0: ArrayLike, omega0: ArrayLike, events: bool = True) -> _Batch:
        """The ``n`` runs at t = 0 (see :func:`simulate` for the arguments)."""
        par = block.arrays(n)
        kp, T = pulse.arrays(n)
        ev = event_times(block, pulse, n, kp, T) if events else np.full((n, 1), np.inf)
        hp, hf = default_steps(block, pulse, n, dt)
        p = _as_runs(block.p, n)
        tmax = T + FREE_TIME / p if t_max is None else _as_runs(t_max, n)
        B = par["B"]
        H = B * par["gamma"]
        J = par["i2"] * B * B
        th0 = _as_runs(theta0, n)
        om0 = _as_runs(omega0, n)
        # standing on the lower corner: y such that that corner touches the base
        y0 = B * np.abs(np.sin(th0)) + H * np.cos(th0) - H
        # velocity of C when rotating at om0 about the touching corner r (from C): v = om z x (-r)
        c0 = np.cos(th0)
        s0 = np.sin(th0)
        r_x = np.where(th0 > 0, H * s0 - B * c0, B * c0 + H * s0)
        r_y = np.where(th0 > 0, -B * s0 - H * c0, B * s0 - H * c0)
        return cls(
            idx=np.arange(n), B=B, H=H, J=J, mu=par["mu"], kpr=par["kprime"], beta=par["beta"],
            u=par["u"], nu=par["nu"], eu=par["e_u"], kp=kp, T=T, hp=hp, hf=hf, tmax=tmax,
            eta=(J + H * H - B * B) / (J + H * H + B * B), alpha=np.arctan2(B, H),
            gtol0=1e-6 * B, BH=B + H, gJ=float(block.g) / J,
            ev=ev, iev=np.zeros(n, dtype=np.int64), evn=ev[:, 0].copy(), mid=np.zeros(n, dtype=bool),
            tgt=np.zeros(n), x=np.zeros(n), y=y0.copy(), th=th0.copy(), cth=c0, sth=s0,
            vx=np.where(th0 != 0, om0 * r_y, 0.0),
            vy=np.where(th0 != 0, -om0 * r_x, 0.0), om=np.where(th0 != 0, om0, 0.0), t=np.zeros(n),
            nleft=np.rint(T / hp).astype(np.int64), prevO=np.zeros(n, dtype=bool),
            prevP=np.zeros(n, dtype=bool), prev_code=np.full(n, -1, dtype=np.int8),
            maxrot=np.abs(th0), imp=np.zeros(n, dtype=np.int64), slid=np.zeros(n, dtype=bool),
            rocked=np.zeros(n, dtype=bool), nsteps=np.zeros(n, dtype=np.int64))

    @property
    def size(self) -> int:
        """The number of runs in the batch."""
        return int(self.idx.size)

    def compress(self, keep: BoolArray) -> None:
        """Keep only the runs where ``keep`` holds, in every array."""
        for f in fields(self):
            setattr(self, f.name, getattr(self, f.name)[keep])

    def retire(self, done: BoolArray, over: BoolArray, rest: BoolArray, out: _Outcome) -> None:
        """Write the outcome of the runs in ``done`` (overturned: ``over``, at rest: ``rest``) into
        ``out`` and drop them from the batch."""
        d = np.flatnonzero(done)
        ids = self.idx[d]
        out.overturned[ids] = over[d]
        out.settled[ids] = rest[d] & ~over[d]
        out.max_rotation[ids] = self.maxrot[d]
        out.residual_rotation[ids] = self.th[d]
        out.residual_slide[ids] = -(self.x[d] + self.H[d] * np.sin(self.th[d]))
        out.impacts[ids] = self.imp[d]
        out.slid[ids] = self.slid[d]
        out.rocked[ids] = self.rocked[d]
        out.end_time[ids] = self.t[d]
        out.steps[ids] = self.nsteps[d]
        self.compress(~done)


class _Step(NamedTuple):
    """What a step did: the state taken, the force k, the start time, the unresolved runs."""

    code: CodeArray
    k: FloatArray
    t_start: FloatArray
    unresolved: int


def _step(b: _Batch, pulse: Pulse, g: float, restitution: float | None, loaded: bool) -> _Step:
    """Advance every run of the batch by one step of the scheme (in place)."""
    h, tm, h_reg, t_new = schedule(b)
    hh = 0.5 * h
    # after every run's pulse, k = 0 (what Pulse.k gives there, without evaluating the shape)
    past = tm >= b.T if pulse.t_samples is None else tm > pulse.t_samples[-1]
    k = np.zeros(b.size) if past.all() else pulse.k(tm, b.kp, b.T)
    thm = b.th + hh * b.om
    c, s = np.cos(thm), np.sin(thm)
    Bc, Bs, Hc, Hs = b.B * c, b.B * s, b.H * c, b.H * s
    arms = Arms(Hs - Bc, -Bs - Hc, Bc + Hs, Bs - Hc)
    # activation on the linearised gap at the mid-point, g(q_k) + (h/2) u_N (Moreau 1988)
    gO, gP = _gaps(b.B, b.H, b.y, b.cth, b.sth)
    # tolerance: v_k met the constraint with the previous step's arms, an O(h^2 om^2 R) mismatch
    gtol = b.gtol0 + (h_reg * b.om) ** 2 * b.BH
    actO = gO + hh * (b.vy + arms.xO * b.om) <= gtol
    actP = gP + hh * (b.vy + arms.xP * b.om) <= gtol
    contact = Contact(arms, actO, actP, b.mu, b.J, 1e-10 * g * h)
    _impacts(b, contact, g * h_reg, restitution)
    # forces per unit mass at (t_m, q_m)
    kpr_t = pulse.kprime(tm) if pulse.has_kprime else None
    kpr = b.kpr if kpr_t is None else kpr_t
    fx = -g * k
    tau = b.gJ * k * kpr * Hc
    fy: FloatArray | float
    if loaded:
        lift = b.u + b.nu * k
        fy = g * (b.beta + lift - 1.0)
        tau = tau + b.gJ * (b.eu * Bc + Hs) * lift
    else:
        fy = -g
    new = contact.solve(b.vx + h * fx, b.vy + h * fy, b.om + h * tau)
    b.x += hh * (b.vx + new.vx)
    b.y += hh * (b.vy + new.vy)
    b.th += hh * (b.om + new.om)
    b.cth = np.cos(b.th)
    b.sth = np.sin(b.th)
    # no drift of a single pivot: the position update of a rotation drifts the pivot's gap by
    # O(h^3) per step; move C vertically so that the pivot keeps its gap (or closes a positive one)
    pivO = PIVOT_O[new.code]
    pivP = PIVOT_P[new.code]
    if pivO.any() or pivP.any():
        gO1, gP1 = _gaps(b.B, b.H, b.y, b.cth, b.sth)  # a run turns about one corner at most
        b.y -= np.where(pivO, gO1 - np.minimum(gO, 0.0), 0.0)
        b.y -= np.where(pivP, gP1 - np.minimum(gP, 0.0), 0.0)
    t_start = b.t
    b.vx, b.vy, b.om = new.vx, new.vy, new.om
    b.t = t_new
    b.nsteps += 1
    b.prevO, b.prevP = actO, actP
    np.maximum(b.maxrot, np.abs(b.th), out=b.maxrot)
    b.slid |= SLIDES[new.code]
    b.rocked |= ROCKS[new.code]
    return _Step(new.code, k, t_start, int(new.unresolved.sum()) if new.unresolved.any() else 0)


def _impacts(b: _Batch, contact: Contact, gh: FloatArray, restitution: float | None) -> None:
    """Count the corner impacts of the step -- a corner closing on the base faster than g h that
    was not in contact -- and, with a restitution, apply the corner impact map (in place)."""
    a = contact.arms
    newO = contact.act_O & ~b.prevO & (b.vy + a.xO * b.om < -gh)
    newP = contact.act_P & ~b.prevP & (b.vy + a.xP * b.om < -gh)
    hit = newO | newP
    if restitution is not None and hit.any():
        sel = np.flatnonzero(hit)
        b.vx[sel], b.vy[sel], b.om[sel] = corner_impact(
            contact.take(sel), (b.vx[sel], b.vy[sel], b.om[sel]), newO[sel], newP[sel],
            restitution / b.eta[sel])
    b.imp += hit


def _leaving(b: _Batch, code: CodeArray, loaded: bool) -> tuple[BoolArray, BoolArray]:
    """Which runs have overturned, and which have come to rest after the pulse."""
    after = b.nleft == 0
    over = np.abs(b.th) > _HALF_PI
    if after.any():
        c1 = b.cth
        s1 = b.sth
        rO = b.H * s1 - b.B * c1
        rP = b.B * c1 + b.H * s1
        if loaded:  # the moment of the constant loads about the pivot
            ur = b.eu * b.B * c1 + b.H * s1
            wt = 1.0 - b.beta
            mO = rO * wt + (ur - rO) * b.u
            mP = rP * wt + (ur - rP) * b.u
        else:
            mO, mP = rO, rP
        away = (((b.th >= b.alpha) & (b.om > 0) & (mO >= 0))
                | ((b.th <= -b.alpha) & (b.om < 0) & (mP <= 0)))
        over |= after & away
    return over, after & (code == Phase.RE)


# -- the time stepper ----------------------------------------------------------------------------------


def simulate(block: Block, pulse: Pulse, *, dt: float | None = None, t_max: ArrayLike | None = None,
             restitution: float | None = None, theta0: ArrayLike = 0.0, omega0: ArrayLike = 0.0,
             history: int | None = None, record_phases: bool = True, events: bool = True,
             progress: Callable[[int], None] | None = None) -> Simulation:
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
    events : bool
        Whether to land a step on every event of a run -- the pulse's breakpoints and its
        crossings of the initiation map (:mod:`regimemap.dynamics.events`).  False is the
        regular schedule alone (the stepper before events, bit for bit).
    progress : callable, optional
        Called with the number of runs that have just left the batch (at rest, overturned
        or at ``t_max``), as they leave: a progress bar's ``step`` (``regimemap outcome``).

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
    batch = _Batch.start(block, pulse, n, dt, t_max, theta0, omega0, events)
    log = RunLog(batch, record_phases, history)
    out = _Outcome.empty(n)
    g, loaded = float(block.g), block.loaded
    unresolved = 0
    first = True
    while batch.size:
        step = _step(batch, pulse, g, restitution, loaded)
        unresolved += step.unresolved
        if first:
            out.initial_mode[batch.idx] = step.code
            first = False
        log.record(batch, step)
        batch.prev_code = step.code
        over, rest = _leaving(batch, step.code, loaded)
        done = over | rest | (batch.t >= batch.tmax)
        if done.any():
            batch.retire(done, over, rest, out)
            if progress is not None:
                progress(int(np.count_nonzero(done)))
    return Simulation(**{f.name: getattr(out, f.name) for f in fields(out)}, unresolved=unresolved,
                      phases=log.phases(), history=log.history())
