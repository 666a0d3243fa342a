"""regimemap: regime maps of a freestanding rigid block pushed by a horizontal force.

For a rigid block of aspect ratio ``gamma = H/B`` on a rigid base with Coulomb
friction ``mu``, pushed by a horizontal force ``F = m g k`` at height
``h = kprime*H`` above its centre of mass, regimemap tells which motion starts
(rest, slide, rock, slide-rock) at every point of the k-mu plane; with
buoyancy, uplift or another inertia (keyword-only arguments everywhere a block
is described) also rock about O' and lift-off.

The library imports numpy only; matplotlib is imported by the drawing modules
when they are used.
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

# first: in the regimemap command's own process (only), Ctrl-C while it starts is one line
from .process import is_console  # noqa: F401 - imported for its effect (regimemap.process)

# isort: split
from ._lazy import attach
from ._version import __version__
from .maps.classify import PRIORITY, classify, label_grid
from .mechanics.block import Case, Parameters
from .mechanics.modes import LOADED_MAP_MODES, MAP_MODES, SELECTION_ORDER, Mode
from .mechanics.solver import Hypothesis, admissible

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .maps.query import PointResult, margin, query_point, query_points

__all__ = [
    "Case",
    "Hypothesis",
    "LOADED_MAP_MODES",
    "MAP_MODES",
    "Mode",
    "PRIORITY",
    "Parameters",
    "PointResult",
    "SELECTION_ORDER",
    "admissible",
    "classify",
    "label_grid",
    "margin",
    "query_point",
    "query_points",
    "__version__",
]

# Diagnostics go to logging.getLogger("regimemap") and its children (one per module), never to
# print: silent unless the application shows them (``regimemap -v``, or logging.basicConfig).
logging.getLogger(__name__).addHandler(logging.NullHandler())


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
