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

from typing import Any

from ._version import __version__
from .maps.classify import PRIORITY, classify, label_grid
from .mechanics.block import Case, Parameters
from .mechanics.modes import LOADED_MAP_MODES, MAP_MODES, SELECTION_ORDER, Mode
from .mechanics.solver import Hypothesis, admissible

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

_LAZY = {"PointResult", "margin", "query_point", "query_points"}


def __getattr__(name: str) -> Any:  # PEP 562: the point query is imported on first use
    if name in _LAZY:
        from .maps import query

        return getattr(query, name)
    raise AttributeError(f"module 'regimemap' has no attribute {name!r}")
