"""What a simulation returns: the outcome of a batch of runs, a run's time history, the categories.

Data only (numpy); :func:`regimemap.dynamics.simulate` fills them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "History",
    "Simulation",
    "CATEGORY_LABELS",
    "REST",
    "SLIDE",
    "ROCK",
    "SLIDE_ROCK",
    "OVERTURN",
    "STILL_MOVING",
]

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
IntArray = NDArray[np.int64]

# Outcome categories (integer codes).
REST, SLIDE, ROCK, SLIDE_ROCK, OVERTURN, STILL_MOVING = 0, 1, 2, 3, 4, 5
#: Labels of the outcome categories, by code.
CATEGORY_LABELS: tuple[str, ...] = ("rest", "slide only", "rock only", "slide-rock", "overturned",
                                    "still moving")


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
        Final theta (rad) (at t_max for a run still moving: not residual).
    residual_slide : ndarray
        Final horizontal displacement of the middle of the base (m), positive towards O.
    impacts : ndarray of int
        Number of corner impacts (a corner closing on the base faster than g h).
    initial_mode : ndarray of int8
        :class:`~regimemap.dynamics.Phase` code of the first step (the motion at t = 0+).
    slid, rocked : ndarray of bool
        Whether the base ever slipped / a corner ever lifted.
    settled : ndarray of bool
        Came to rest after the pulse (False when overturned or stopped at t_max; a run neither
        settled nor overturned is :attr:`still_moving`, its ``residual_*`` where t_max stopped it).
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
    def still_moving(self) -> BoolArray:
        """Runs that reached the time limit neither at rest nor overturned."""
        return ~(self.settled | self.overturned)

    @property
    def category(self) -> NDArray[np.int8]:
        """Outcome category code per run (see :data:`CATEGORY_LABELS`); ``categories(0.0)``."""
        return self.categories(0.0)

    def categories(self, min_rotation: float = 0.0) -> NDArray[np.int8]:
        """Outcome category code per run (see :data:`CATEGORY_LABELS`).

        A run rocked when a rocking phase occurred (a corner lifted in some step, as
        :attr:`phases` shows), slid when its base slipped in some step; there is no hidden
        floor.  A run that reached the time limit without coming to rest or overturning is
        :data:`STILL_MOVING`, whatever it did before.

        Parameters
        ----------
        min_rotation : float
            Rocking counts only if the largest |theta| exceeds this angle (rad); 0 counts
            every rocking phase.  A run that rocked less is "slide only" if it slid,
            otherwise "rest".

        Returns
        -------
        ndarray of int8
        """
        if not min_rotation >= 0.0:
            raise ValueError(f"min_rotation must be >= 0 (got {min_rotation})")
        rocked = self.rocked if min_rotation == 0.0 else self.rocked & (self.max_rotation > min_rotation)
        cat = np.full(self.overturned.shape, REST, dtype=np.int8)
        cat[self.slid] = SLIDE
        cat[rocked] = ROCK
        cat[self.slid & rocked] = SLIDE_ROCK
        cat[self.still_moving] = STILL_MOVING
        cat[self.overturned] = OVERTURN
        return cat
