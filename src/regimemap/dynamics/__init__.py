"""Dynamics of a rigid block under force pulses: rest, slide, rock, slide-rock, flight, impacts, overturning.

numpy only.  :func:`simulate` steps a batch of runs with a Moreau-Jean scheme
(:mod:`regimemap.dynamics.stepper`); :class:`Pulse` gives the force histories;
:func:`outcome_map` sweeps two inputs; :func:`design_wave_run` puts a caisson's equivalent block
under its design wave (:mod:`regimemap.dynamics.design_wave`).  See docs/dynamics.md.

Names are imported on first use (PEP 562), so that the command line can read
the input limits (:mod:`regimemap.dynamics.limits`) without importing the stepper.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .block import Block, G, frequency_parameter, size_R, slenderness
    from .design_wave import (
        DESIGN_INPUTS,
        DESIGN_UNITS,
        NO_ADDED_MASS,
        PROFILE,
        design_wave_inputs,
        design_wave_numbers,
        design_wave_run,
    )
    from .outcome import SWEEPABLE, OutcomeMap, from_dimensionless, outcome_map, to_dimensionless
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
        STILL_MOVING,
        History,
        Phase,
        Simulation,
        default_steps,
        simulate,
    )

__all__ = [
    "Block",
    "CATEGORY_LABELS",
    "DESIGN_INPUTS",
    "DESIGN_UNITS",
    "FREE_STEP",
    "G",
    "History",
    "NO_ADDED_MASS",
    "OVERTURN",
    "PROFILE",
    "PULSE_STEPS",
    "OutcomeMap",
    "Phase",
    "Pulse",
    "REST",
    "ROCK",
    "SHAPES",
    "SLIDE",
    "SLIDE_ROCK",
    "STILL_MOVING",
    "SWEEPABLE",
    "Simulation",
    "default_steps",
    "design_wave_inputs",
    "design_wave_numbers",
    "design_wave_run",
    "from_dimensionless",
    "frequency_parameter",
    "outcome_map",
    "simulate",
    "size_R",
    "slenderness",
    "to_dimensionless",
]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
