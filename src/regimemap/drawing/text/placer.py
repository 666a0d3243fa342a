"""The one label placer: the free space of a figure, and the search for a label's first free place.

Every figure that moves a label goes through :class:`Placer`: the map's tidy pass
(:mod:`regimemap.drawing.text.tidy`, whose candidates for each kind of map label are in
:mod:`regimemap.drawing.text.relabel`) and the labels of the lifetime, study and caisson figures
(:class:`regimemap.drawing.text.labelplacer.LabelPlacer`, with fixed candidate lists).  A kind of
label says only where it may go, as a sequence of places tried in turn
(:meth:`Placer.first_free`); what is free is decided here, one way for every figure: inside the
figure's frame (and the box asked for), clear of every box taken so far, and clear of the lines
the caller names.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

import numpy as np

from .placement import box_hits
from .textboxes import GAP, Box, box_of, box_within, boxes_hit

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure

__all__ = ["Placer", "clear_of"]


def clear_of(points: Iterable[np.ndarray], margin: float = 0.0) -> Callable[[Box], bool]:
    """The test that a box (pixels), less ``margin`` on every side, holds none of ``points``.

    ``points`` are dense points of lines (pixels, an array of shape (n, 2) each), as
    :func:`regimemap.drawing.text.placement.box_hits` takes them.
    """
    sets = [p for p in points if p.size]

    def clear(b: Box) -> bool:
        inner = (b[0] + margin, b[1] + margin, b[2] - margin, b[3] - margin)
        return not any(box_hits(inner, p) for p in sets)

    return clear


class Placer:
    """The free space of a figure: the boxes already taken, and the figure's frame.

    Parameters
    ----------
    fig : Figure
        The figure, laid out.
    renderer : RendererBase
        Its renderer, with which the texts are measured.
    taken : list of Box
        Boxes (pixels) no label may meet: the fixed texts, markers.
    """

    def __init__(self, fig: Figure, renderer: RendererBase, taken: list[Box]):
        self.fig = fig
        self.renderer = renderer
        self.taken = list(taken)
        fb = fig.bbox
        self.frame = (fb.x0 + GAP, fb.y0 + GAP, fb.x1 - GAP, fb.y1 - GAP)

    def box(self, t: Any) -> Box:
        """The box of ``t`` as drawn (pixels), with half the :data:`GAP` around it."""
        return box_of(t, self.renderer, GAP / 2)

    def free(self, b: Box, within: Box | None = None) -> bool:
        """Whether the box ``b`` is inside the frame (and ``within``) and meets no box taken."""
        if not box_within(b, self.frame) or (within is not None and not box_within(b, within)):
            return False
        return not any(boxes_hit(b, o) for o in self.taken)

    def take(self, t: Any) -> None:
        """Mark the place of ``t`` as taken."""
        self.taken.append(self.box(t))

    def first_free(self, places: Iterable[Any], within: Box | None = None,
                   clear: Callable[[Box], bool] | None = None) -> tuple[Any, bool]:
        """The first of a label's places that is free: ``(label, True)``, else ``(last, False)``.

        Parameters
        ----------
        places : iterable
            The label moved to each of its places in turn, yielded as the artist that stands
            there (a kind of label may draw a new artist, e.g. with a leader line).  The
            iterable is consumed lazily: a place may be computed from the space taken so far.
        within : Box, optional
            A box (pixels) the label must stay inside, besides the figure's frame.
        clear : callable, optional
            A further test of the label's box (e.g. :func:`clear_of` the curves).

        Returns
        -------
        tuple
            The label at its first free place and True; when none is free, the label as the
            last place left it (None if there was no place) and False.  Nothing is taken: the
            caller decides (:meth:`take`).
        """
        last = None
        for t in places:
            last = t
            b = self.box(t)
            if self.free(b, within) and (clear is None or clear(b)):
                return t, True
        return last, False
