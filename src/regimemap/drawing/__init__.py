"""The drawing layer: the only part of regimemap that imports matplotlib.

Styles (:mod:`.style`), label placement (:mod:`.placement`, :mod:`.labels`,
:mod:`.labelplacer`), the key (:mod:`.key`), the map (:mod:`.mapplot`, drawing
what :mod:`.artists` records; :mod:`.figure`, a map on a figure of its own), its
tidy pass (:mod:`.tidy`), the ambiguity overlay (:mod:`.ambiguity`), the atlas
(:mod:`.atlas`) and the animation (:mod:`.animation`), the report's figure
presets (:mod:`.presets`, :mod:`.batch` for all of them at once), figure bytes
and files (:mod:`.save`), the motions after initiation (:mod:`.outcome`,
:mod:`.motion`) and the figures of a caisson's sliding over its design life
(:mod:`.lifetime`, :mod:`.lifetime_chart`).  Files are written atomically
through :mod:`regimemap.io`, the layer below.

Names are imported on first use, so ``import regimemap.drawing`` does not
import matplotlib; the ``if TYPE_CHECKING`` block gives type checkers and IDEs
the real names.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .maps.ambiguity import draw_ambiguity
    from .maps.animation import write_animation
    from .maps.artists import MapArtists
    from .maps.atlas import atlas_figure, write_atlas
    from .maps.figure import FIGSIZE, fit_figure, map_figure, new_figure, render_map, render_preset
    from .lifetime.exceedance import lifetime_figure
    from .lifetime.chart import chart_figure
    from .maps.mapplot import MapStyle, default_title, draw_design_points, draw_map
    from .motion.history import motion_figure
    from .outcome.figure import OutcomeStyle, draw_outcome_map, outcome_figure
    from .save import save_figure
    from .style import MODE_STYLE, OUTCOME_STYLE, style_context

__all__ = [
    "FIGSIZE",
    "MODE_STYLE",
    "MapArtists",
    "MapStyle",
    "OUTCOME_STYLE",
    "OutcomeStyle",
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
    "save_figure",
    "style_context",
    "write_animation",
    "write_atlas",
]

_WHERE = {
    "FIGSIZE": "maps.figure",
    "MapArtists": "maps.artists",
    "MapStyle": "maps.mapplot",
    "default_title": "maps.mapplot",
    "draw_design_points": "maps.mapplot",
    "draw_map": "maps.mapplot",
    "fit_figure": "maps.figure",
    "map_figure": "maps.figure",
    "new_figure": "maps.figure",
    "render_map": "maps.figure",
    "render_preset": "maps.figure",
    "MODE_STYLE": "style",
    "style_context": "style",
    "atlas_figure": "maps.atlas",
    "write_atlas": "maps.atlas",
    "write_animation": "maps.animation",
    "draw_ambiguity": "maps.ambiguity",
    "save_figure": "save",
    "OUTCOME_STYLE": "style",
    "OutcomeStyle": "outcome.figure",
    "draw_outcome_map": "outcome.figure",
    "outcome_figure": "outcome.figure",
    "motion_figure": "motion.history",
    "lifetime_figure": "lifetime.exceedance",
    "chart_figure": "lifetime.chart",
}


def load_matplotlib() -> None:
    """Import matplotlib's Figure and Agg canvas now (the drawing modules import them on first use).

    The command line calls this at a moment of its choosing (with the garbage
    collector paused, see :mod:`regimemap.cli`).
    """
    import matplotlib.backends.backend_agg  # noqa: F401
    import matplotlib.figure  # noqa: F401


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any

    def __getattr__(name: str) -> Any:  # PEP 562: matplotlib is imported on first use
        if name in _WHERE:
            return getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    """The module's names and its public names (imported on first use), for ``dir()`` and IDEs."""
    return sorted(set(globals()) | set(__all__))
