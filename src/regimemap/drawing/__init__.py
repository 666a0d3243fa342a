"""The drawing layer: the only part of regimemap that imports matplotlib.

Styles (:mod:`.style`), label placement (:mod:`.placement`), the key
(:mod:`.key`), the map (:mod:`.mapplot`), the ambiguity overlay
(:mod:`.ambiguity`), atlas and animation (:mod:`.atlas`), the report's figure
presets (:mod:`.presets`), figure bytes (:mod:`.save`) and the figures of a
caisson's sliding over its design life (:mod:`.lifetime`).  Names are imported
on first use, so ``import regimemap.drawing`` does not import matplotlib.
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = [
    "FIGSIZE",
    "MODE_STYLE",
    "MapArtists",
    "OUTCOME_STYLE",
    "atlas_figure",
    "chart_figure",
    "default_title",
    "draw_ambiguity",
    "draw_design_points",
    "draw_map",
    "draw_outcome_map",
    "fit_figure",
    "lifetime_figure",
    "load_matplotlib",
    "map_figure",
    "motion_figure",
    "new_figure",
    "outcome_figure",
    "render_map",
    "render_preset",
    "style_context",
]

_WHERE = {
    "FIGSIZE": "figure",
    "MapArtists": "mapplot",
    "default_title": "mapplot",
    "draw_design_points": "mapplot",
    "draw_map": "mapplot",
    "fit_figure": "figure",
    "map_figure": "figure",
    "new_figure": "figure",
    "render_map": "figure",
    "render_preset": "figure",
    "MODE_STYLE": "style",
    "style_context": "style",
    "atlas_figure": "atlas",
    "draw_ambiguity": "ambiguity",
    "OUTCOME_STYLE": "style",
    "draw_outcome_map": "outcome",
    "outcome_figure": "outcome",
    "motion_figure": "motion",
    "lifetime_figure": "lifetime",
    "chart_figure": "lifetime",
}


def load_matplotlib() -> None:
    """Import matplotlib's Figure and Agg canvas now (the drawing modules import them on first use).

    The command line calls this at a moment of its choosing (with the garbage
    collector paused, see :mod:`regimemap.cli`).
    """
    import matplotlib.backends.backend_agg  # noqa: F401
    import matplotlib.figure  # noqa: F401


def __getattr__(name: str) -> Any:  # PEP 562: matplotlib is imported on first use
    if name in _WHERE:
        return getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
