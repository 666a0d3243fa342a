"""The look of the study figures: one colour, marker and dash pattern per scenario; the frame.

Paul Tol's colour-blind-safe colours (his *high-contrast* blue and red first, then *bright*
and *muted* ones), each scenario with a marker and a dash pattern of its own, so that the
scenarios stay apart in greyscale too.  The frame (:func:`new_frame`) is the design chart's:
a page wide, the title block at the top left (:func:`regimemap.lifetime.figures.style.draw_title_block`),
the key below the axes.  No matplotlib at import time.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..drawing.style import agg_figure, key_below
from ..lifetime.figures.style import FS, draw_title_block, title_height

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["AXES_WIDTH", "FIG_WIDTH", "KEY_COLUMN_CHARS", "ScenarioStyle", "draw_key", "key_columns",
           "new_frame", "scenario_style", "study_facts"]

_COLOURS = ("#004488", "#BB5566", "#997700", "#228833", "#AA3377", "#33BBEE", "#332288", "#999933")
_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "h")
_DASHES: tuple[tuple[float, ...], ...] = ((), (5.0, 2.0), (1.5, 1.5), (6.0, 2.0, 1.5, 2.0),
                                          (3.0, 1.5), (8.0, 2.5), (1.0, 1.0, 4.0, 1.0), (2.5, 2.5))
#: Hatches of the scenarios' climate bands (a fill reads in greyscale by its hatch).
_HATCHES = ("////", "\\\\\\\\", "||||", "----", "xxxx", "....", "++++", "oooo")


@dataclass(frozen=True)
class ScenarioStyle:
    """How one scenario is drawn: colour, marker, dashes (empty: solid) and its band's hatch."""

    color: str
    marker: str
    dashes: tuple[float, ...]
    hatch: str

    def line(self, **kwargs: Any) -> dict[str, Any]:
        """Keyword arguments of ``Axes.plot`` for the scenario's line (and ``kwargs``)."""
        out: dict[str, Any] = {"color": self.color, "marker": self.marker, "lw": 1.3, "markersize": 4.0}
        if self.dashes:
            out["dashes"] = self.dashes
        return {**out, **kwargs}


def scenario_style(index: int) -> ScenarioStyle:
    """The style of the scenario at ``index`` in the study's order (cycling after eight)."""
    k = index % len(_COLOURS)
    return ScenarioStyle(_COLOURS[k], _MARKERS[k], _DASHES[k], _HATCHES[k])


def study_facts(sections: int, scenarios: int, trials: int, seed: int, years: int) -> str:
    """The run's facts, the title's second line."""
    return (f"{sections} section{'s' if sections != 1 else ''} \u00d7 {scenarios} "
            f"scenario{'s' if scenarios != 1 else ''}, {trials} lifetimes of {years} years per task, "
            f"seed {seed}")


#: Width of the figures and of their axes, inches (a page wide, as the design chart).
FIG_WIDTH = 7.0
_LEFT, _RIGHT = 0.7, 0.2
AXES_WIDTH = FIG_WIDTH - _LEFT - _RIGHT


def new_frame(title: str, key_rows: int, *, dpi: float, top_extra: float = 0.0) -> tuple[Figure, Axes, float]:
    """A figure with one axes, the title block drawn, room for ``key_rows`` rows of key below.

    ``top_extra`` inches are kept between the title and the axes (for section names above
    them).  Returns the figure, the axes and the figure's height in inches.
    """

    top = 0.15 + title_height(title) + 0.05 + top_extra
    width, left, ah = FIG_WIDTH, _LEFT, 2.9
    bottom = 0.5 + 0.08 + 0.17 * key_rows
    h = top + ah + bottom
    fig = agg_figure(figsize=(width, h), dpi=dpi)
    ax = fig.add_axes((left / width, bottom / h, AXES_WIDTH / width, ah / h), label="study")
    draw_title_block(fig, title, h)
    return fig, ax, h


#: The longest entry (characters) of a key in two columns; a longer one puts the key in one.
KEY_COLUMN_CHARS = 52


def key_columns(key: list[tuple[Any, str]]) -> tuple[int, int]:
    """The key's columns (two, or one when an entry is longer than :data:`KEY_COLUMN_CHARS`) and rows."""
    ncols = 2 if max((len(text) for _, text in key), default=0) <= KEY_COLUMN_CHARS else 1
    return ncols, (len(key) + ncols - 1) // ncols


def draw_key(fig: Figure, key: list[tuple[Any, str]], h: float) -> None:
    """The key below the axes, in :func:`key_columns`' columns."""
    key_below(fig, key, 0.06 / h, FS - 0.5, ncols=key_columns(key)[0], handlelength=2.8)
