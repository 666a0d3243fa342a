"""The mechanics core (numpy only): modes, the block and its loads, the closed forms,
the curves, the raw regions and the independent equations-of-motion solver.

Nothing here draws, reads or writes files, or imports another part of regimemap:
every other layer builds on this one.  The report's closed forms are written
once, in :mod:`regimemap.mechanics.constants`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .block import Case, Parameters, case_of
    from .curves import Curve, NamedPoint, map_curves, named_points
    from .modes import LOADED_MAP_MODES, MAP_MODES, PRIORITY, SELECTION_ORDER, Mode
    from .regions import RAW_REGIONS, raw_region
    from .solver import (
        TOLERANCE,
        Hypothesis,
        Response,
        admissible,
        admissible_hypotheses,
        choose,
        least_constraint,
        solve,
    )

__all__ = [
    "Case",
    "Curve",
    "Hypothesis",
    "LOADED_MAP_MODES",
    "MAP_MODES",
    "Mode",
    "NamedPoint",
    "PRIORITY",
    "Parameters",
    "RAW_REGIONS",
    "Response",
    "SELECTION_ORDER",
    "TOLERANCE",
    "admissible",
    "admissible_hypotheses",
    "case_of",
    "choose",
    "least_constraint",
    "map_curves",
    "named_points",
    "raw_region",
    "solve",
]


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
