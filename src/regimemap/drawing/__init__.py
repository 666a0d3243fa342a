"""What every figure shares, and the index of the figures: the only shared package that imports matplotlib.

Shared by the products' figures (``figures*`` of :mod:`regimemap.maps`,
:mod:`regimemap.caisson`, :mod:`regimemap.motion`, :mod:`regimemap.lifetime`,
:mod:`regimemap.climate` and :mod:`regimemap.study`): :mod:`.style` (colours and
hatches per category, rcParams), :mod:`.save` (figure bytes and files, written
atomically through :mod:`regimemap.io`, the layer below), :mod:`.limits` (the sizes
the command line checks), :mod:`.verdict` (the PASS/FAIL badge), :mod:`.artists`
(what a drawn map holds) and :mod:`.text` (label placement and the passes that keep
texts legible).  The names below are also those of the figures themselves, each
imported from its product on first use.

Names are imported on first use (:func:`regimemap._lazy.attach`), so ``import
regimemap.drawing`` does not import matplotlib; the ``if TYPE_CHECKING`` block
gives type checkers and IDEs the real names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ..climate.figures import climate_figure, diagnostics_figure
    from ..lifetime.figures.chart import chart_figure
    from ..lifetime.figures.exceedance import lifetime_figure
    from ..maps.figures.ambiguity import draw_ambiguity
    from ..maps.figures.animation import write_animation
    from ..maps.figures.atlas import atlas_figure, write_atlas
    from ..maps.figures.figure import FIGSIZE, fit_figure, map_figure, new_figure, render_map, render_preset
    from ..maps.figures.mapplot import MapStyle, default_title, draw_design_points, draw_map
    from ..motion.figures.history import motion_figure
    from ..motion.figures.outcome import OutcomeStyle, draw_outcome_map, outcome_figure
    from ..study.figures import study_figure
    from .artists import MapArtists
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
    __getattr__, __dir__ = attach(__name__, __file__)
