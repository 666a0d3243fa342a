"""The inputs of a simulation, their ranges and checks, and the work limits (no matplotlib).

Every check raises :class:`ValueError` naming the input, the allowed range and
the value received, e.g. ``half_width must be a finite number in [0.001, 1000], got -1.0``;
the command line (``regimemap simulate``, ``regimemap outcome``) and the pulse
file reader use the same ranges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..mechanics.validation import GAMMA_MAX, GAMMA_MIN, check_gamma, check_kprime

if TYPE_CHECKING:  # pragma: no cover
    from .block import Block

__all__ = [
    "Limit",
    "INPUT_LIMITS",
    "MAX_STEPS",
    "MAX_MAP_RUNS",
    "MAX_AXIS_VALUES",
    "check_input",
    "check_net_weight",
    "check_gyration",
    "estimated_steps",
    "check_run_steps",
    "check_map_steps",
]


@dataclass(frozen=True)
class Limit:
    """The range of one input: ``lo`` to ``hi``, each end included unless ``open_lo``/``open_hi``."""

    lo: float
    hi: float
    open_lo: bool = False
    open_hi: bool = False
    unit: str = ""

    @property
    def text(self) -> str:
        """``a finite number in (0, 1000]`` and the like."""
        left = "(" if self.open_lo else "["
        right = ")" if self.open_hi else "]"
        return f"a finite number in {left}{self.lo:g}, {self.hi:g}{right}"

    def contains(self, v: float) -> bool:
        """Whether ``v`` is finite and inside the range."""
        if not math.isfinite(v):
            return False
        above = v > self.lo if self.open_lo else v >= self.lo
        below = v < self.hi if self.open_hi else v <= self.hi
        return above and below


#: The range of every input of a simulation, by name (the command line's option without
#: ``--``, with ``_`` for ``-``).  gamma and kprime are those of the regime maps.
INPUT_LIMITS: dict[str, Limit] = {
    "gamma": Limit(GAMMA_MIN, GAMMA_MAX),
    "kprime": Limit(-1.0, 1.0),
    # a millimetre: below it p (about 1/sqrt(B)) and the step count grow without bound
    "half_width": Limit(1e-3, 1000.0, unit="m"),
    "mu": Limit(0.0, 100.0),
    "k_peak": Limit(0.0, 100.0),
    "duration": Limit(1e-4, 100.0, unit="s"),
    "omega_p": Limit(0.01, 1e5, unit="rad/s"),
    "restitution": Limit(0.0, 1.0),
    "buoyancy": Limit(0.0, 1.0, open_hi=True),
    "uplift": Limit(0.0, 1.0, open_hi=True),
    "uplift_ratio": Limit(0.0, 10.0),
    "uplift_arm": Limit(-1.0, 1.0),
    # below about 1e-8 the rotational inertia m (i B)^2 is too small for the contact solve in
    # floats (no admissible state, then overflow); every real block has i > 0.3
    "gyration": Limit(1e-3, 1000.0),
    # the smallest largest rotation that counts as rocking (--min-rotation), in degrees
    "min_rotation": Limit(0.0, 90.0, unit="deg"),
    # a sampled pulse (pulse file): force and its height at each sample time
    "k": Limit(-100.0, 100.0),
    "t": Limit(0.0, 1e4, unit="s"),
}

#: Largest number of time steps of one run (over the pulse and after it), estimated before
#: running by :func:`estimated_steps`: about a minute of one run on one core.
MAX_STEPS = 200_000
#: Largest number of runs (cells) of an outcome map from the command line.
MAX_MAP_RUNS = 250_000
#: Largest number of values along one axis of an outcome map.
MAX_AXIS_VALUES = 1000


def check_input(name: str, value: Any) -> float:
    """``value`` as a float if it lies in the range of input ``name``, else ValueError."""
    if name == "gamma":
        return check_gamma(value)
    if name == "kprime":
        return check_kprime(value)
    lim = INPUT_LIMITS[name]
    try:
        if isinstance(value, (bool, np.bool_, str, bytes)):
            raise TypeError
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be {lim.text}, got {value!r} (not a number)") from None
    if not lim.contains(v):
        raise ValueError(f"{name} must be {lim.text}, got {v!r}")
    return v + 0.0  # fold -0.0


def check_net_weight(buoyancy: float, uplift: float) -> None:
    """The block must keep some weight: buoyancy + uplift < 1 (units of m g)."""
    if buoyancy + uplift >= 1.0:
        raise ValueError(f"buoyancy + uplift must be < 1 (the block keeps some weight), got "
                         f"{buoyancy:g} + {uplift:g} = {buoyancy + uplift:g}")


def check_gyration(gyration: float, gamma: float) -> float:
    """The radius of gyration about C over B: at most the half diagonal sqrt(1 + gamma^2).

    (A mass inside the rectangle has I <= m R^2 about C; the lower end is that of
    :data:`INPUT_LIMITS`.)  Returns i2 = gyration^2.
    """
    top = math.hypot(1.0, gamma)
    lo = INPUT_LIMITS["gyration"].lo
    if not lo <= gyration <= top * (1.0 + 1e-12):
        raise ValueError(f"gyration must be a finite number in [{lo:g}, sqrt(1 + gamma^2)] = "
                         f"[{lo:g}, {top:.6g}] for gamma = {gamma:g}, got {gyration:g}")
    return gyration * gyration


def estimated_steps(block: Block, duration: float, dt: float | None = None) -> int:
    """Time steps of the longest run of ``block`` under a pulse of ``duration`` (s), an upper bound.

    The default step (:func:`regimemap.dynamics.default_steps`) is at most duration/400 over the
    pulse and 0.004/p after it, and a run is given up 60/p after the pulse.
    """
    from .batch import FREE_STEP, FREE_TIME, PULSE_STEPS

    p = float(np.min(np.asarray(block.p, dtype=np.float64)))
    h_free = FREE_STEP / p if dt is None else dt
    bound = min(duration / PULSE_STEPS, h_free) if dt is None else dt
    return int(math.ceil(duration / bound) + math.ceil(FREE_TIME / p / h_free))


def check_run_steps(block: Block, duration: float) -> int:
    """The time steps of one run of ``block`` under a pulse of ``duration`` (s) (:func:`estimated_steps`).

    Raises
    ------
    ValueError
        When they exceed :data:`MAX_STEPS`; the message says where they come from.
    """
    from .batch import FREE_STEP, FREE_TIME

    steps = estimated_steps(block, duration)
    if steps > MAX_STEPS:
        raise ValueError(
            f"the run needs up to {steps} time steps (the pulse of {duration:g} s at a step of at most "
            f"{FREE_STEP:g}/p = {FREE_STEP / float(block.p):.3g} s, then {FREE_TIME:g}/p s of free motion), "
            f"more than the limit of {MAX_STEPS}; give a shorter pulse (or a larger block: p grows as the "
            f"half-width shrinks)")
    return steps


def check_map_steps(blocks: Block, longest: float) -> int:
    """The time steps of the longest run of an outcome map (:func:`estimated_steps`).

    Parameters
    ----------
    blocks : Block
        Every block of the map (the smallest p gives the longest run).
    longest : float
        The longest pulse (s).

    Raises
    ------
    ValueError
        When they exceed :data:`MAX_STEPS`.
    """
    steps = estimated_steps(blocks, longest)
    if steps > MAX_STEPS:
        raise ValueError(f"the longest run needs up to {steps} time steps, more than the limit of "
                         f"{MAX_STEPS}; give shorter pulses")
    return steps
