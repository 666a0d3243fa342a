"""Boxes of drawn texts, in pixels: measured with the renderer, compared, kept apart.

The primitives of the passes that keep the texts of a figure legible: the map's
tidy pass (:mod:`regimemap.drawing.text.tidy`, :mod:`regimemap.drawing.text.relabel`) and
the labels of the other figures (:mod:`regimemap.drawing.text.labelplacer`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.text import Text

__all__ = ["GAP", "Box", "box_of", "box_within", "boxes_hit", "major_tick_labels", "visible_text"]

#: A box (x0, y0, x1, y1), in pixels.
Box = tuple[float, float, float, float]

#: Gap (pixels) kept between two texts, and between a text and the figure's edge.
GAP = 2.0


def box_of(artist: Artist | Any, renderer: RendererBase, pad: float = 0.0) -> Box:
    """The window extent of ``artist`` (pixels), grown by ``pad`` on every side."""
    bb = artist.get_window_extent(renderer)
    return (bb.x0 - pad, bb.y0 - pad, bb.x1 + pad, bb.y1 + pad)


def boxes_hit(a: Box, b: Box) -> bool:
    """Whether the boxes ``a`` and ``b`` overlap."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def box_within(a: Box, b: Box) -> bool:
    """Whether the box ``a`` lies inside the box ``b``."""
    return a[0] >= b[0] and a[1] >= b[1] and a[2] <= b[2] and a[3] <= b[3]


def visible_text(t: Any) -> bool:
    """Whether ``t`` is a text that is drawn: visible, not blank, on a figure."""
    return bool(t is not None and t.get_visible() and t.get_text().strip()
                and t.figure is not None)


def major_tick_labels(ax: Axes) -> list[Text]:
    """The labels of the major ticks that are drawn (in view, visible, not empty)."""
    out = []
    for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        lo, hi = min(lo, hi), max(lo, hi)
        eps = 1e-9 * (hi - lo)
        for tick in axis.get_major_ticks():
            if lo - eps <= tick.get_loc() <= hi + eps:
                out += [lab for lab in (tick.label1, tick.label2) if visible_text(lab)]
    return out
