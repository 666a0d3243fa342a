"""The event times of a run: the pulse's breakpoints and its crossings of the initiation map.

The Moreau-Jean step (:mod:`regimemap.dynamics.stepper`) evaluates the force at its mid-point,
so a pulse's peak, a kink or a short excursion of k(t) past a threshold of the initiation map is
"seen" only if a mid-point happens to fall near it.  The stepper therefore inserts, at each
*event* t_e of a run, a very short step (length ``EVENT_STEP`` times the regular step) whose
mid-point is t_e.  From rest the contact problem of a step is homogeneous in the step length
(v = 0, the free velocity is h f), so the state taken is the onset mode at k(t_e) for any step;
while moving, the short step adds a negligible impulse.  The events of a run are

* the **breakpoints** of its pulse (:meth:`regimemap.dynamics.Pulse.breakpoints`): start, peak,
  kinks and end of an analytic shape; of a sampled pulse, its first and last samples and every
  sample where k(t) turns (a local maximum or minimum, an end of a flat stretch).  The samples
  in between lie on monotone stretches, where the crossings below are the events that matter;
  landing on each of them would cost two steps a sample (a record sampled at 1 kHz is denser
  than the steps);
* its **crossings of the initiation map**: the times at which k(t) passes a boundary of
  :func:`regimemap.classify` for the block's gamma, k', mu and loads.  Along a line of constant
  mu every condition of ``classify``'s rule is affine in k, so the values of k where the mode may
  change are roots of closed forms (the list of :mod:`regimemap.maps.margins`); those where
  ``classify`` really changes (:func:`onset_boundaries`) are the boundaries.  Between two
  breakpoints k(t) is monotone, so each boundary it passes is found by bisection of the crossing
  time on k(t) -- no grid -- against a target just *past* the boundary (by ``BOUNDARY_MARGIN``
  relative, never past the middle of the next interval of the rule), so that k(t_e) lies strictly
  inside the next mode.  A push to the right (k < 0) is the mirror image: the boundaries of the
  block with the uplift arm and the uplift ratio of opposite signs.

A pulse that carries its own k'(t) has no single k': its events are its samples only.

:func:`schedule` cuts the regular step that holds an event (a step to t_e - delta, the event
step, the rest); only a run at rest or sliding flat (y' = theta' = 0) takes an event step, one
that turns or flies passes its events over (the map does not describe it, and a very short step
would see the mid-point arms' velocity mismatch without the forces that balance it).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:  # pragma: no cover
    from .batch import Batch
    from .block import Block
    from .pulses import Pulse

__all__ = ["EVENT_STEP", "BOUNDARY_MARGIN", "onset_boundaries", "crossing_times", "event_times",
           "Schedule", "schedule"]

FloatArray = NDArray[np.float64]

#: Length of the step inserted at an event, as a fraction of the regular step.
EVENT_STEP = 1e-6
#: How far past a boundary of the initiation map the crossing event lies: the target value of k is
#: the boundary plus BOUNDARY_MARGIN * max(|boundary|, 0.1) (the contact problem's tolerance is
#: 1e-10 of g h, so a smaller margin could leave the old mode admissible).
BOUNDARY_MARGIN = 1e-6
#: Bisection of a crossing time stops when the bracket is this fraction of the pulse's duration.
_TIME_TOL = 1e-13
_BISECT_STEPS = 80


def onset_boundaries(block: Block, n: int, mirror: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The values of k >= 0 where the mode of :func:`regimemap.classify` changes, per run.

    Parameters
    ----------
    block : Block
        The block(s); array fields give one value per run.
    n : int
        The number of runs.
    mirror : bool
        The mirror image (a push to the right, k < 0): the uplift arm and ratio change sign.

    Returns
    -------
    boundary, below, above : ndarray, shape (n, m)
        The boundaries in increasing order (NaN padding), and for each the nearest value of k
        below and above it where the rule may change (0 and inf at the ends): the interval of
        k on either side where the mode is that of the boundary's side.
    """
    from ..maps.classify import classify_constants
    from ..mechanics.loads import block_constants
    from ..mechanics.regions import affine_terms, rule_expressions

    par = block.arrays(n)
    col = {key: v[:, None] for key, v in par.items()}
    sign = -1.0 if mirror else 1.0
    gyr = None if block.i2 is None else np.sqrt(col["i2"])
    cst = block_constants(col["gamma"], col["kprime"], col["buoyancy"], col["uplift"],
                          sign * col["uplift_ratio"], sign * col["uplift_arm"], gyr)
    mu = col["mu"]
    with np.errstate(divide="ignore", invalid="ignore"):
        e0 = rule_expressions(affine_terms(np.zeros((n, 1)), cst), mu, cst.gamma, cst.i2, 0.0)
        e1 = rule_expressions(affine_terms(np.ones((n, 1)), cst), mu, cst.gamma, cst.i2, 1.0)
        roots = np.concatenate([np.broadcast_to(-a / (b - a), (n, 1)) for a, b in zip(e0, e1, strict=True)]
                               + [np.zeros((n, 1))], axis=1)
    roots = np.where(np.isfinite(roots) & (roots >= 0.0), roots, np.inf)
    roots = np.sort(roots, axis=1)
    dup = np.zeros(roots.shape, dtype=bool)
    dup[:, 1:] = roots[:, 1:] == roots[:, :-1]
    roots = np.sort(np.where(dup, np.inf, roots), axis=1)
    m = int(np.max(np.sum(np.isfinite(roots), axis=1)))
    roots = roots[:, :m]  # roots[:, 0] = 0
    finite = np.isfinite(roots)
    last = np.where(finite, roots, -np.inf).max(axis=1, keepdims=True)
    nxt = np.concatenate([roots[:, 1:], np.full((n, 1), np.inf)], axis=1)
    # the mode in the open interval after each root (beyond the last: 2 r + 1), and at k = 0
    probe = np.where(np.isfinite(nxt), 0.5 * (roots + nxt), 2.0 * last + 1.0)
    probe = np.where(finite, probe, 0.0)
    after = classify_constants(probe, np.broadcast_to(mu, probe.shape), cst)
    at0 = classify_constants(np.zeros((n, 1)), mu, cst)
    before = np.concatenate([at0, after[:, :-1]], axis=1)
    change = finite & (after != before)
    below = np.concatenate([np.zeros((n, 1)), roots[:, :-1]], axis=1)
    kb = np.where(change, roots, np.nan)
    order = np.argsort(np.where(change, roots, np.inf), axis=1, kind="stable")
    take = np.take_along_axis
    width = max(1, int(change.sum(axis=1).max(initial=0)))
    kb = take(kb, order, axis=1)[:, :width]
    lo = take(np.where(change, below, np.nan), order, axis=1)[:, :width]
    hi = take(np.where(change, nxt, np.nan), order, axis=1)[:, :width]
    return kb, lo, hi


def _targets(kb: FloatArray, lo: FloatArray, hi: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The values of k just past each boundary going up and going down (NaN: none)."""
    margin = BOUNDARY_MARGIN * np.maximum(np.abs(kb), 0.1)
    up = np.minimum(kb + margin, np.where(np.isfinite(hi), 0.5 * (kb + hi), np.inf))
    down = np.maximum(kb - margin, 0.5 * (lo + kb))
    down = np.where(kb > 0.0, down, np.nan)  # nothing below k = 0 on this side
    return up, down


def crossing_times(pulse: Pulse, kp: FloatArray, T: FloatArray, breaks: FloatArray, up: FloatArray,
                   down: FloatArray) -> FloatArray:
    """The times at which k(t) first passes each target on each monotone piece of the pulse.

    Parameters
    ----------
    pulse : Pulse
    kp, T : ndarray, shape (n,)
        Each run's peak and duration.
    breaks : ndarray, shape (n, p)
        Each run's breakpoints, increasing (k is monotone between two of them).
    up, down : ndarray, shape (n, q)
        Signed values of k to pass going up (on increasing pieces) and going down; NaN: none.

    Returns
    -------
    ndarray, shape (n, r)
        The crossing times (NaN padding): the first time of the piece at which k >= an up
        target, or k <= a down target.
    """
    n = breaks.shape[0]
    ta, tb = breaks[:, :-1], breaks[:, 1:]
    piece = tb > ta
    ka = pulse.k(ta, kp[:, None], T[:, None])
    kb_ = pulse.k(np.nextafter(tb, -np.inf), kp[:, None], T[:, None])
    rising = piece & (kb_ > ka)
    falling = piece & (kb_ < ka)
    # candidates (run, piece, target): rising pieces with ka < K <= kb, falling with kb <= K < ka
    K = np.concatenate([up, down], axis=1)[:, None, :]
    is_up = np.concatenate([np.ones(up.shape, dtype=bool), np.zeros(down.shape, dtype=bool)],
                           axis=1)[:, None, :]
    a3, b3 = ka[:, :, None], kb_[:, :, None]
    ok = np.where(is_up, rising[:, :, None] & (a3 < K) & (K <= b3),
                  falling[:, :, None] & (b3 <= K) & (K < a3))
    r, j, q = np.nonzero(ok)
    if r.size == 0:
        return np.full((n, 0), np.nan)
    target = K[r, 0, q]
    ascending = is_up[0, 0, q]
    lo = ta[r, j].copy()
    hi = np.nextafter(tb[r, j], -np.inf)
    kpr, Tr = kp[r], T[r]
    tol = _TIME_TOL * Tr
    for _ in range(_BISECT_STEPS):
        active = (hi - lo) > tol
        if not active.any():
            break
        mid = lo + 0.5 * (hi - lo)
        km = pulse.k(mid, kpr, Tr)
        past = np.where(ascending, km >= target, km <= target)
        hi = np.where(active & past, mid, hi)
        lo = np.where(active & ~past, mid, lo)
    # per run, its crossings in a row
    counts = np.bincount(r, minlength=n)
    width = int(counts.max())
    out = np.full((n, width), np.nan)
    col = np.arange(r.size) - np.repeat(np.cumsum(counts) - counts, counts)
    out[r, col] = hi
    return out


def _turning_samples(pulse: Pulse) -> NDArray[np.bool_]:
    """The samples of a sampled pulse that are events: the first and the last, and those where
    k(t) turns (a local maximum or minimum, or an end of a flat stretch)."""
    assert pulse.k_samples is not None
    ks = pulse.k_samples
    keep = np.ones(ks.size, dtype=bool)
    before = ks[1:-1] - ks[:-2]
    after = ks[2:] - ks[1:-1]
    keep[1:-1] = (before * after <= 0.0) & ((before != 0.0) | (after != 0.0))
    return keep


def event_times(block: Block, pulse: Pulse, n: int, kp: FloatArray, T: FloatArray) -> FloatArray:
    """Every event time of each run (see the module docstring), sorted, inf padding; shape (n, m).

    Parameters
    ----------
    block : Block
    pulse : Pulse
    n : int
        The number of runs.
    kp, T : ndarray, shape (n,)
        Each run's peak and duration.
    """
    breaks = pulse.breakpoints(T)
    breaks = np.broadcast_to(breaks, (n, breaks.shape[1])).astype(np.float64)
    parts = [breaks if pulse.shape != "arrays" else breaks[:, _turning_samples(pulse)]]
    if not pulse.has_kprime:
        kb, lo, hi = onset_boundaries(block, n)
        up, down = _targets(kb, lo, hi)
        mkb, mlo, mhi = onset_boundaries(block, n, mirror=True)
        mup, mdown = _targets(mkb, mlo, mhi)
        # the mirror image: going down in k is going up in |k|
        parts.append(crossing_times(pulse, kp, T, breaks, np.concatenate([up, -mdown], axis=1),
                                    np.concatenate([down, -mup], axis=1)))
    ev = np.concatenate(parts, axis=1)
    ev = np.where(np.isfinite(ev) & (ev >= 0.0), ev, np.inf)
    ev = np.sort(ev, axis=1)
    dup = np.zeros(ev.shape, dtype=bool)
    dup[:, 1:] = ev[:, 1:] == ev[:, :-1]
    ev = np.sort(np.where(dup, np.inf, ev), axis=1)
    width = int(np.max(np.sum(np.isfinite(ev), axis=1), initial=0))
    return np.concatenate([ev[:, :width], np.full((n, 1), np.inf)], axis=1)


# -- the schedule of the steps -------------------------------------------------------------------


class Schedule(NamedTuple):
    """The step of every run: its length, the time of its force, the regular step, the new time."""

    h: FloatArray
    tm: FloatArray
    h_reg: FloatArray
    t_new: FloatArray


def schedule(b: Batch) -> Schedule:
    """The next step of every run, and the schedule's state after it (``b.nleft``, ``b.mid``,
    ``b.tgt``, ``b.iev``, updated in place).

    The regular step is h_pulse during the pulse and h_free after it.  At an event t_e (see
    :mod:`regimemap.dynamics.events`) the regular step that holds it is cut: a step to
    t_e - delta, a step of length 2 delta = EVENT_STEP h whose force is taken at t_e, and the rest
    of the regular step; the other steps are unchanged (without events, the regular schedule bit
    for bit).  An event step is taken only by a run at rest or sliding flat (y' = theta' = 0
    exactly): there its contact problem is the onset's, homogeneous in the step.  A run that turns
    or flies passes its events over -- the map does not describe its state, and a very short step
    would see the velocity mismatch of the mid-point arms (an O(h theta'^2 R) correction) without
    the forces that balance it over a regular step.
    """
    h_reg = np.where(b.nleft > 0, b.hp, b.hf)
    t_reg = b.t + h_reg
    tm = b.t + 0.5 * h_reg
    a = b.evn - (0.5 * EVENT_STEP) * h_reg
    due = b.mid | (a < t_reg)
    if not due.any():  # no event: the regular step
        b.nleft = np.maximum(b.nleft - 1, 0)
        return Schedule(h_reg, tm, h_reg, t_reg)
    d = np.flatnonzero(due)  # the runs with an event in this step, or inside a cut step
    t, hr, mid = b.t[d], h_reg[d], b.mid[d]
    delta = (0.5 * EVENT_STEP) * hr
    end = np.where(mid, b.tgt[d], t_reg[d])
    turning = (b.om[d] != 0.0) | (b.vy[d] != 0.0)
    iev = b.iev[d]
    e = b.ev[d, iev]
    while True:  # a run that turns or flies passes over the events of this step
        skip = turning & (e - delta < end)
        if not skip.any():
            break
        iev = iev + skip
        e = b.ev[d, iev]
    a = e - delta
    tiny = a <= t + delta
    cut = ~tiny & (a < end)
    te = np.maximum(e, t)
    t_new = np.where(tiny, te + delta, np.where(cut, a, end))
    h = np.where(mid | tiny | cut, t_new - t, hr)
    # the regular step is done when the step reaches its end (within delta of it)
    done = ~(tiny | cut) | (tiny & (t_new >= end - delta))
    nleft = np.where(done, np.maximum(b.nleft[d] - 1, 0), b.nleft[d])
    over = done & tiny  # an event step ends the regular step: the next one ends a step later
    b.tgt[d] = np.where(over, end + np.where(nleft > 0, b.hp[d], b.hf[d]), end)
    b.mid[d] = ~done | over
    b.iev[d] = iev + tiny
    b.evn[d] = b.ev[d, iev + tiny]
    b.nleft = np.maximum(b.nleft - 1, 0)
    b.nleft[d] = nleft
    h_all, tm_all, t_all = h_reg.copy(), tm.copy(), t_reg.copy()
    h_all[d] = h
    tm_all[d] = np.where(tiny, te, t + 0.5 * h)
    t_all[d] = t_new
    return Schedule(h_all, tm_all, h_reg, t_all)
