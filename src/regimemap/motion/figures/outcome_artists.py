"""What an outcome map drawing returns: :class:`OutcomeArtists`, and the two small types it
carries (:class:`CategoryLookup`, the category at points of the drawing; :class:`TextReport`,
what the text placement did).

Data types of their own, so that the renderer (:mod:`regimemap.motion.figures.outcome`) and the text
placement that reads what it drew (:mod:`regimemap.motion.figures.outcome_text`) both depend on them
and not on each other.  No matplotlib at run time.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.collections import LineCollection
    from matplotlib.contour import QuadContourSet
    from matplotlib.legend import Legend
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MplPath
    from matplotlib.text import Text

__all__ = ["CategoryLookup", "OutcomeArtists", "TextReport"]


class CategoryLookup:
    """The category at points of a drawn outcome map (data coordinates; -1 off the map).

    From the region polygons of a refined map, else from the cells (each node's cell reaches
    half-way to its neighbours).  ``category``, ``xs`` and ``ys`` are the grid with increasing
    axes.
    """

    def __init__(self, category: NDArray[Any], xs: NDArray[np.float64], ys: NDArray[np.float64],
                 regions: dict[int, MplPath] | None = None):
        self.category = np.asarray(category)
        from ...drawing.text.placement import cell_edges

        self.xe, self.ye = cell_edges(xs), cell_edges(ys)
        self.regions = regions

    def __call__(self, points: NDArray[np.float64]) -> NDArray[np.int64]:
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        out = np.full(len(pts), -1, dtype=np.int64)
        if self.regions is not None:
            for code, path in self.regions.items():
                if np.asarray(path.vertices).size:
                    out[path.contains_points(pts)] = code
            return out
        j = np.searchsorted(self.xe, pts[:, 0]) - 1
        i = np.searchsorted(self.ye, pts[:, 1]) - 1
        ok = (j >= 0) & (j < self.category.shape[1]) & (i >= 0) & (i < self.category.shape[0])
        out[ok] = self.category[i[ok], j[ok]]
        return out


@dataclass
class TextReport:
    """What :func:`~regimemap.motion.figures.outcome_text.place_outcome_text` did: the texts it placed
    and those it left out."""

    placed: list[str] = field(default_factory=list)
    hidden: list[str] = field(default_factory=list)



@dataclass
class OutcomeArtists:
    """What :func:`~regimemap.motion.figures.outcome.draw_outcome_map` drew.

    Attributes
    ----------
    regions : dict
        Category code -> the PathPatch of its region (one per category present).
    boundaries : LineCollection or None
        The black lines between categories.
    boundary_lines : list of ndarray
        Their polylines (data coordinates).
    contours : dict
        ``"residual_slide"`` and ``"max_rotation"`` -> their ContourSet (when drawn).
    contour_units : dict
        The same keys -> the unit written after a level.
    labels : list of Text
        Region labels (those with room;
        :func:`~regimemap.motion.figures.outcome_text.place_outcome_text` removes the others).
    contour_labels : list of Text
        One label per contour level that has room for it.
    title : Text or None
    legend : Legend or None
    category_at : CategoryLookup or None
        The category at points of the drawing.
    report : TextReport or None
        What the text placement did.
    """

    regions: dict[int, PathPatch] = field(default_factory=dict)
    boundaries: LineCollection | None = None
    boundary_lines: list[NDArray[np.float64]] = field(default_factory=list)
    contours: dict[str, QuadContourSet] = field(default_factory=dict)
    contour_units: dict[str, str] = field(default_factory=dict)
    labels: list[Text] = field(default_factory=list)
    contour_labels: list[Text] = field(default_factory=list)
    title: Text | None = None
    legend: Legend | None = None
    category_at: CategoryLookup | None = None
    report: TextReport | None = None
