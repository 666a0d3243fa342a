"""The evaluation layer: one mode per point, margins, queries and the data behind a map.

Built on :mod:`regimemap.mechanics` (numpy only, no matplotlib): :func:`classify`
and :func:`label_grid` (the final map), the point query and its margins, the
parts where several modes are admissible, the region polygons, the view and
:func:`compute_map`, which returns everything a drawing shows as data.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

# eager: every map needs it, and the function must shadow its module's name (``classify``)
from .classify import classify, column_segments, label_grid

if TYPE_CHECKING:  # pragma: no cover - the names, for type checkers; imported on first use
    from .ambiguity import AmbiguousRegion, ambiguous_regions
    from .geometry import DEFAULT_SAMPLES, region_polygons
    from .mapdata import CurveData, MapData, compute_map
    from .points import DesignPoint
    from .query import Crossing, Margin, PointResult, margin, query_point, query_points
    from .view import auto_extent

__all__ = [
    "AmbiguousRegion",
    "Crossing",
    "CurveData",
    "DEFAULT_SAMPLES",
    "DesignPoint",
    "MapData",
    "Margin",
    "PointResult",
    "ambiguous_regions",
    "auto_extent",
    "classify",
    "column_segments",
    "compute_map",
    "label_grid",
    "margin",
    "query_point",
    "query_points",
    "region_polygons",
]

# imported on first use (PEP 562), so ``import regimemap.maps.classify`` does not load the
# polygons, the ambiguity and the query
if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
