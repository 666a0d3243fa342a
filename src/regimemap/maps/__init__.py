"""The evaluation layer: one mode per point, margins, queries and the data behind a map.

Built on :mod:`regimemap.mechanics` (numpy only, no matplotlib): :func:`classify`
and :func:`label_grid` (the final map), the point query and its margins, the
parts where several modes are admissible, the region polygons, the view and
:func:`compute_map`, which returns everything a drawing shows as data.
"""

from __future__ import annotations

from .ambiguity import AmbiguousRegion, ambiguous_regions
from .classify import classify, column_segments, label_grid
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
