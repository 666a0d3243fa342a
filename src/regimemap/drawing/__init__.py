"""The drawing layer: the only part of regimemap that imports matplotlib.

One room per family of figures, and what they share at the top:

* :mod:`.maps` -- the regime map, its key, a map figure, the report's figures,
  the atlas and the animation;
* :mod:`.outcome` -- outcome maps of :mod:`regimemap.dynamics`;
* :mod:`.motion` -- one run's motion, and the figures D.1-D.3;
* :mod:`.sheet` -- the caisson's design sheet;
* :mod:`.lifetime` -- the exceedance figure and the design chart of a caisson's
  design life;
* :mod:`.climate` -- a wave record's extremes: the record, return levels, QQ and
  threshold diagnostics;
* :mod:`.study` -- a whole breakwater: sliding along the chainage, by service
  year, and the width for a target, a line per climate scenario;
* :mod:`.explore` -- ``regimemap explore``, the map with sliders;
* :mod:`.text` -- label placement and the passes that keep texts legible;
* :mod:`.style`, :mod:`.save`, :mod:`.limits`, :mod:`.verdict` -- the style of
  every drawing, figure bytes and files (written atomically through
  :mod:`regimemap.io`, the layer below), the sizes the command line checks, the
  PASS/FAIL badge.

Names are imported on first use (:func:`regimemap._lazy.attach`), so ``import
regimemap.drawing`` does not import matplotlib; the ``if TYPE_CHECKING`` block
gives type checkers and IDEs the real names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .climate.figures import climate_figure, diagnostics_figure
    from .lifetime.chart import chart_figure
    from .lifetime.exceedance import lifetime_figure
    from .maps.ambiguity import draw_ambiguity
    from .maps.animation import write_animation
    from .maps.artists import MapArtists
    from .maps.atlas import atlas_figure, write_atlas
    from .maps.figure import FIGSIZE, fit_figure, map_figure, new_figure, render_map, render_preset
    from .maps.mapplot import MapStyle, default_title, draw_design_points, draw_map
    from .motion.history import motion_figure
    from .outcome.figure import OutcomeStyle, draw_outcome_map, outcome_figure
    from .save import save_figure
    from .study.figures import study_figure
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
    "climate_figure",
    "default_title",
    "diagnostics_figure",
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
    "study_figure",
    "style_context",
    "write_animation",
    "write_atlas",
]

def load_matplotlib() -> None:
    """Import matplotlib's Figure and Agg canvas now (the drawing modules import them on first use).

    The command line calls this at a moment of its choosing (with the garbage
    collector paused, see :mod:`regimemap.cli`).
    """
    import matplotlib.backends.backend_agg  # noqa: F401
    import matplotlib.figure  # noqa: F401


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, {
        "maps.ambiguity": ["draw_ambiguity"],
        "maps.animation": ["write_animation"],
        "maps.artists": ["MapArtists"],
        "maps.atlas": ["atlas_figure", "write_atlas"],
        "maps.figure": ["FIGSIZE", "fit_figure", "map_figure", "new_figure", "render_map", "render_preset"],
        "maps.mapplot": ["MapStyle", "default_title", "draw_design_points", "draw_map"],
        "lifetime.exceedance": ["lifetime_figure"],
        "lifetime.chart": ["chart_figure"],
        "climate.figures": ["climate_figure", "diagnostics_figure"],
        "motion.history": ["motion_figure"],
        "outcome.figure": ["OutcomeStyle", "draw_outcome_map", "outcome_figure"],
        "save": ["save_figure"],
        "study.figures": ["study_figure"],
        "style": ["MODE_STYLE", "OUTCOME_STYLE", "style_context"],
    })
