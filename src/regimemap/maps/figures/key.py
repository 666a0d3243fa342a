"""The key below a map: a swatch, the mode's symbol, and what the mode is.

Each mode's entry is a hatched swatch followed by the mode's symbol in its
own column (*RE*, *SL*, *RO*, :math:`SRO_-` ...) and a plain description
("slide-rock about O, O slipping left"); the line styles (boundary,
construction, dotted) follow with a short line in the swatch column, so every
description starts at the same place.

Only the symbol needs mathtext, and only for sub- and superscripts; the
descriptions are plain text.  (A whole label such as
``"$SRO_{-}$  slide-rock about O"`` is one more mathtext parse per entry, and
its parts could not be aligned.)

This module imports matplotlib; :mod:`regimemap.maps.figures.mapplot` and
:mod:`regimemap.maps.figures.atlas` import it only when they draw.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from matplotlib.legend_handler import HandlerBase, HandlerLine2D
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.text import Text

from ...drawing.style import CONSTRUCTION, DOTTED, HATCH_LW, LINE_LW, MODE_STYLE, mode_symbol
from ...mechanics.modes import Mode

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import FigureBase
    from matplotlib.legend import Legend
    from matplotlib.transforms import Transform

__all__ = ["ModeSwatch", "HANDLER_MAP", "HANDLELENGTH", "key_handles", "key_legend"]

#: Length of the swatch (and of the line samples), in font sizes.
SWATCH = 2.2
#: Gap between the swatch and the symbol, in font sizes.
SYMBOL_GAP = 0.55
#: Width of the symbol column, in font sizes (fits SRO'-).
SYMBOL_COLUMN = 3.0
#: The legend's ``handlelength``: swatch, gap and symbol column.
HANDLELENGTH = SWATCH + SYMBOL_GAP + SYMBOL_COLUMN


class ModeSwatch(Rectangle):
    """A legend handle for a mode: a filled, hatched swatch and the mode's symbol.

    Use it with :data:`HANDLER_MAP`; its label is the mode's description.
    """

    def __init__(self, mode: Mode, xy: tuple[float, float] = (0.0, 0.0), width: float = 1.0,
                 height: float = 1.0, **kwargs: Any):
        super().__init__(xy, width, height, **kwargs)
        self.mode = mode


class _HandlerModeSwatch(HandlerBase):
    """Draws a :class:`ModeSwatch`: the swatch, then the symbol on the label's baseline."""

    def create_artists(self, legend: Legend, orig_handle: Any, xdescent: float,
                       ydescent: float, width: float, height: float, fontsize: float,
                       trans: Transform) -> list[Any]:
        swatch_w = min(width, SWATCH * fontsize)
        swatch = ModeSwatch(orig_handle.mode, (-xdescent, -ydescent), swatch_w, height)
        self.update_prop(swatch, orig_handle, legend)
        swatch.set_hatch_linewidth(orig_handle.get_hatch_linewidth())
        swatch.set_transform(trans)
        text, style = mode_symbol(orig_handle.mode)
        # y = 0 is the baseline of the entry's label (the legend aligns on baselines)
        symbol = Text(-xdescent + swatch_w + SYMBOL_GAP * fontsize, 0.0, text,
                      fontproperties=legend.prop, fontstyle=style, ha="left", va="baseline")
        symbol.set_transform(trans)
        return [swatch, symbol]


class _HandlerKeyLine(HandlerLine2D):
    """A line sample as long as the swatches (the symbol column stays empty)."""

    def get_xdata(self, legend: Legend, xdescent: float, ydescent: float, width: float,
                  height: float, fontsize: float) -> tuple[Any, Any]:
        return super().get_xdata(legend, xdescent, ydescent, min(width, SWATCH * fontsize),
                                 height, fontsize)


#: ``handler_map`` for a legend of :class:`ModeSwatch` and line handles.
HANDLER_MAP: dict[type, HandlerBase] = {
    ModeSwatch: _HandlerModeSwatch(),
    Line2D: _HandlerKeyLine(),
}


def key_handles(modes: Sequence[Mode], *, hatches: bool = True, boundary: bool = True,
                construction: bool = True, dotted_label: str | None = None) -> list[Any]:
    """Legend handles in the renderer's style: a swatch per mode, then the line styles.

    Parameters
    ----------
    modes : sequence of Mode
        Modes with an entry, in order.
    hatches : bool
        Hatch the swatches as the regions.
    boundary, construction : bool
        Add "boundary of a region" and "construction line".
    dotted_label : str, optional
        Add the dotted line with this label (e.g. ``"dotted line $\\mu = k|k'|$ (4.22)"``).
    """
    handles: list[Any] = []
    for mode in modes:
        st = MODE_STYLE[mode]
        h = ModeSwatch(mode, facecolor=st.color, edgecolor="0.4", linewidth=0.4,
                       hatch=st.hatch if hatches else None, hatchcolor=st.hatch_color,
                       label=mode.description)
        h.set_hatch_linewidth(HATCH_LW)
        handles.append(h)
    if boundary:
        handles.append(Line2D([], [], color="black", linewidth=LINE_LW,
                              label="boundary of a region"))
    if construction:
        handles.append(Line2D([], [], label="construction line", **CONSTRUCTION))
    if dotted_label:
        handles.append(Line2D([], [], label=dotted_label, **DOTTED))
    return handles


def key_legend(target: Axes | FigureBase, handles: Sequence[Any], **kwargs: Any) -> Legend:
    """Add the key to ``target`` (an Axes or a Figure): ``target.legend`` with the handlers."""
    kw: dict[str, Any] = {"handlelength": HANDLELENGTH, "handler_map": HANDLER_MAP}
    kw.update(kwargs)
    return target.legend(handles=list(handles), **kw)
