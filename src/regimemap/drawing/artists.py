"""What a map drawing returns: :class:`MapArtists`, the artists of one map and its data.

A data type of its own, so that the code that reads a drawn map (the tidy pass,
:mod:`regimemap.drawing.text.tidy`; the atlas; the explorer) depends on this type, not
on the renderer (:mod:`regimemap.maps.figures.mapplot`).  No matplotlib at run time.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ..maps.mapdata import MapData
from ..mechanics.modes import Mode

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.legend import Legend
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    from matplotlib.text import Text

__all__ = ["MapArtists"]


@dataclass
class MapArtists:
    """What :func:`~regimemap.maps.figures.mapplot.draw_map` drew, and the data behind it.

    Attributes
    ----------
    data : MapData
        Polygons, curves, named points and extent (:mod:`regimemap.maps.mapdata`).
    fills : dict[Mode, list[Patch]]
        The region patches of each mode.
    curves : dict[str, list[Line2D]]
        Line pieces of each curve (boundary pieces solid, construction
        pieces dashed), by the report's name (``OA``, ``mu_star`` ...).
    curve_labels : dict[str, Text]
        Labels of the curves (``mu_star``: ":math:`\\mu^*(k)`" ...).
    region_labels : dict[Mode, list[Text]]
        Mode symbols written inside the regions.
    point_markers : dict[str, Line2D]
        Markers of the named points (``A``, ``B'`` ...).
    point_labels : dict[str, Text]
        Names of the points, and of line ends (``B``, ``C``).
    legend : Legend or None
    title : Text or None
    extra : list[Artist]
        Anything else drawn on the axes by regimemap (design points ...).
    off_view : dict[str, Text]
        Arrows at the frame's edge to the characteristic points outside the
        view, with their names and coordinates (``tidy`` maps only).
    """

    data: MapData
    fills: dict[Mode, list[Patch]] = field(default_factory=dict)
    curves: dict[str, list[Line2D]] = field(default_factory=dict)
    curve_labels: dict[str, Text] = field(default_factory=dict)
    region_labels: dict[Mode, list[Text]] = field(default_factory=dict)
    point_markers: dict[str, Line2D] = field(default_factory=dict)
    point_labels: dict[str, Text] = field(default_factory=dict)
    legend: Legend | None = None
    title: Text | None = None
    extra: list[Artist] = field(default_factory=list)
    off_view: dict[str, Text] = field(default_factory=dict)

    @property
    def extent(self) -> tuple[float, float]:
        """``(k_max, mu_max)`` of the view."""
        return (self.data.k_max, self.data.mu_max)

    @property
    def polygons(self) -> dict[Mode, list[np.ndarray]]:
        """The region polygons (k, mu) that the fills show."""
        return self.data.polygons
