"""Dynamics of a rigid block under force pulses: rest, slide, rock, slide-rock, flight, impacts, overturning.

numpy only.  :func:`simulate` steps a batch of runs with a Moreau-Jean scheme
(:mod:`regimemap.dynamics.stepper`); :class:`Pulse` gives the force histories;
:func:`outcome_map` sweeps two inputs.  See docs/dynamics.md.
"""

from __future__ import annotations

from .block import Block, G, frequency_parameter, size_R, slenderness
from .outcome import (
    SWEEPABLE,
    OutcomeMap,
    from_dimensionless,
    outcome_map,
    to_dimensionless,
)
from .pulses import SHAPES, Pulse
from .stepper import (
    CATEGORY_LABELS,
    FREE_STEP,
    OVERTURN,
    PULSE_STEPS,
    REST,
    ROCK,
    SLIDE,
    SLIDE_ROCK,
    History,
    Phase,
    Simulation,
    default_steps,
    simulate,
)

__all__ = [
    "Block",
    "CATEGORY_LABELS",
    "FREE_STEP",
    "G",
    "History",
    "OVERTURN",
    "PULSE_STEPS",
    "OutcomeMap",
    "Phase",
    "Pulse",
    "REST",
    "ROCK",
    "SHAPES",
    "SLIDE",
    "SLIDE_ROCK",
    "SWEEPABLE",
    "Simulation",
    "default_steps",
    "from_dimensionless",
    "frequency_parameter",
    "outcome_map",
    "simulate",
    "size_R",
    "slenderness",
    "to_dimensionless",
]
