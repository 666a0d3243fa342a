"""The runs of :func:`regimemap.dynamics.simulate` still moving, as a struct of arrays.

A :class:`Batch` holds, per run, its constants (block, pulse, steps, time limit), its state at
the start of the step and what it has done so far; :meth:`Batch.compress` keeps some runs in
every array at once and :meth:`Batch.retire` writes the outcome of the runs that leave into an
:class:`Outcome`.  :class:`Step` is what one step of the scheme did.  The default time steps
(:func:`default_steps`) are here because a batch starts from them.  The time loop is
:mod:`regimemap.dynamics.stepper`; the events it lands on, :mod:`regimemap.dynamics.events`;
its records, :mod:`regimemap.dynamics.recording` -- each reads the batch, none is imported here.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .block import Block
from .pulses import Pulse

__all__ = ["Batch", "Outcome", "Step", "default_steps", "gaps", "as_runs", "PULSE_STEPS",
           "FREE_STEP", "FREE_TIME"]

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


def as_runs(value: ArrayLike, n: int) -> FloatArray:
    return np.broadcast_to(np.asarray(value, dtype=np.float64), (n,)).astype(np.float64)


def gaps(B: FloatArray, H: FloatArray, y: FloatArray, c0: FloatArray,
          s0: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The heights of O and O' above the base (m), for C at height H + y and rotation theta
    (``c0``, ``s0``: its cosine and sine)."""
    return H + y - B * s0 - H * c0, H + y + B * s0 - H * c0


# -- the batch: the runs still moving, as a struct of arrays ----------------------------------------


@dataclass
class Outcome:
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
    def empty(cls, n: int) -> Outcome:
        """Room for ``n`` runs."""
        return cls(overturned=np.zeros(n, dtype=bool), max_rotation=np.zeros(n),
                   residual_rotation=np.zeros(n), residual_slide=np.zeros(n),
                   impacts=np.zeros(n, dtype=np.int64), initial_mode=np.full(n, -1, dtype=np.int8),
                   slid=np.zeros(n, dtype=bool), rocked=np.zeros(n, dtype=bool),
                   settled=np.zeros(n, dtype=bool), end_time=np.zeros(n),
                   steps=np.zeros(n, dtype=np.int64))


@dataclass
class Batch:
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
              theta0: ArrayLike, omega0: ArrayLike, ev: FloatArray) -> Batch:
        """The ``n`` runs at t = 0 (see :func:`regimemap.dynamics.simulate` for the arguments;
        ``ev``: the events of every run, :func:`regimemap.dynamics.events.event_times`)."""
        par = block.arrays(n)
        kp, T = pulse.arrays(n)
        hp, hf = default_steps(block, pulse, n, dt)
        p = as_runs(block.p, n)
        tmax = T + FREE_TIME / p if t_max is None else as_runs(t_max, n)
        B = par["B"]
        H = B * par["gamma"]
        J = par["i2"] * B * B
        th0 = as_runs(theta0, n)
        om0 = as_runs(omega0, n)
        # standing on the lower corner: y such that that corner touches the base
        y0 = B * np.abs(np.sin(th0)) + H * np.cos(th0) - H
        # velocity of C when rotating at om0 about the touching corner r (from C): v = om z x (-r)
        c0 = np.cos(th0)
        s0 = np.sin(th0)
        r_x = np.where(th0 > 0, H * s0 - B * c0, B * c0 + H * s0)
        r_y = np.where(th0 > 0, -B * s0 - H * c0, B * s0 - H * c0)
        return cls(
            idx=np.arange(n), B=B, H=H, J=J, mu=par["mu"], kpr=par["kprime"], beta=par["buoyancy"],
            u=par["uplift"], nu=par["uplift_ratio"], eu=par["uplift_arm"], kp=kp, T=T, hp=hp, hf=hf,
            tmax=tmax,
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

    def retire(self, done: BoolArray, over: BoolArray, rest: BoolArray, out: Outcome) -> None:
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


class Step(NamedTuple):
    """What a step did: the state taken, the force k, the start time, the unresolved runs."""

    code: CodeArray
    k: FloatArray
    t_start: FloatArray
    unresolved: int
