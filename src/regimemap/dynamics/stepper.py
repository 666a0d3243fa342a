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
``Batch`` (:mod:`regimemap.dynamics.batch`), a struct of arrays that loses the runs that leave.

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
from dataclasses import fields

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .batch import FREE_STEP, PULSE_STEPS, Batch, Outcome, Step, default_steps, gaps
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

_HALF_PI = 0.5 * math.pi


def _step(b: Batch, pulse: Pulse, g: float, restitution: float | None, loaded: bool) -> Step:
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
    gO, gP = gaps(b.B, b.H, b.y, b.cth, b.sth)
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
        gO1, gP1 = gaps(b.B, b.H, b.y, b.cth, b.sth)  # a run turns about one corner at most
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
    return Step(new.code, k, t_start, int(new.unresolved.sum()) if new.unresolved.any() else 0)


def _impacts(b: Batch, contact: Contact, gh: FloatArray, restitution: float | None) -> None:
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


def _leaving(b: Batch, code: CodeArray, loaded: bool) -> tuple[BoolArray, BoolArray]:
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
        regular schedule alone.
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
                         np.asarray(block.kprime), np.asarray(block.buoyancy),
                         np.asarray(block.uplift), np.asarray(block.uplift_ratio),
                         np.asarray(block.uplift_arm),
                         np.asarray(block.gamma if block.i2 is None else block.i2),
                         pulse.k_peak, pulse.duration, np.asarray(theta0), np.asarray(omega0)).size)
    batch = Batch.start(block, pulse, n, dt, t_max, theta0, omega0,
                        event_times(block, pulse, n, *pulse.arrays(n)) if events
                        else np.full((n, 1), np.inf))
    log = RunLog(batch, record_phases, history)
    out = Outcome.empty(n)
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
