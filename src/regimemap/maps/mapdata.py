"""What a map shows: its region polygons, boundary curves and named points (no matplotlib).

This module computes everything a drawing needs, after the split of
pycalphad's ``mapping`` package (strategies compute, ``plotting.py`` draws).
:func:`compute_map` returns a :class:`MapData`; the renderer
(:mod:`regimemap.maps.figures.mapplot`) only turns it into artists, so the numbers
behind every line and fill of a figure stay reachable.

The curves and named points (sampled in the view, split into boundary and
construction runs) are found by :mod:`regimemap.maps.mapcurves`.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.curves import NamedPoint
from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES, Mode
from ..records.htmltable import html_table
from .describe import loads_text
from .designer_view import points_off_view
from .geometry import DEFAULT_SAMPLES, area_in_view, region_polygons
from .mapcurves import CurveData, curve_data, drawn_points, line_ends
from .view import auto_extent, simplify

__all__ = ["CurveData", "MapData", "compute_map", "map_for_view"]

_log = logging.getLogger(__name__)

# -- the whole map -------------------------------------------------------------------------


@dataclass(frozen=True)
class MapData:
    """Everything a map shows, in data coordinates (no matplotlib).

    Attributes
    ----------
    params : Parameters
    k_max, mu_max : float
        The view ``[0, k_max] x [0, mu_max]``.
    modes : tuple of Mode
        The modes whose regions are shaded.
    raw : bool
        True for the report's raw regions (single-mode figures), False for
        the final map (one mode per point, Section 4.7).
    polygons : dict[Mode, list[ndarray]]
        Region polygons from :func:`regimemap.maps.geometry.region_polygons`,
        simplified; they extend above the view and are clipped when drawn.
    curves : dict[str, CurveData]
        The boundary curves drawn (see the module docstring for the names).
    points : dict[str, NamedPoint]
        The report's named points that lie in view on a drawn curve.
    line_ends : dict[str, tuple[float, float]]
        Names written at the far end of a line, as the report's sketches do
        (``B`` on AB, ``C`` on DC below C).
    off_view : tuple of NamedPoint
        The named points outside the view, that a drawing marks at its edge
        (:func:`regimemap.maps.designer_view.points_off_view`).
    """

    params: Parameters
    k_max: float
    mu_max: float
    modes: tuple[Mode, ...]
    raw: bool
    polygons: dict[Mode, list[np.ndarray]]
    curves: dict[str, CurveData]
    points: dict[str, NamedPoint]
    line_ends: dict[str, tuple[float, float]] = field(default_factory=dict)
    off_view: tuple[NamedPoint, ...] = ()

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(0, k_max, 0, mu_max)``, as matplotlib's ``extent``."""
        return (0.0, self.k_max, 0.0, self.mu_max)

    # -- display: a readable repr and a table for Jupyter -------------------------------------
    def _what(self) -> str:
        p = self.params
        loads = loads_text(p)
        kind = "raw regions" if self.raw else "final map"
        return (f"gamma={p.gamma:g}, k'={p.kprime:g}" + (f"; {loads}" if loads else "")
                + f": {kind}, view k <= {self.k_max:g}, mu <= {self.mu_max:g}")

    def _view_shares(self) -> dict[Mode, float]:
        """The share of the view that each mode's region covers (0 to 1; raw maps may overlap)."""
        whole = self.k_max * self.mu_max
        return {m: sum(area_in_view(poly, self.k_max, self.mu_max)
                       for poly in self.polygons.get(m, []) if len(poly) >= 3) / whole
                for m in self.modes}

    def __repr__(self) -> str:
        """Two lines: the block and the view; the modes in view, the curves and the points."""
        shares = self._view_shares()
        seen = [m.label for m in self.modes if shares[m] > 1e-9]
        n = sum(len(v) for v in self.polygons.values())
        return (f"MapData({self._what()};\n  modes in view {', '.join(seen) or 'none'} "
                f"({n} polygons), curves {', '.join(self.curves) or 'none'}, "
                f"points {', '.join(self.points) or 'none'})")

    def _repr_html_(self) -> str:
        """The map's regions, curves and points as a small table (Jupyter's rich display)."""
        shares = self._view_shares()
        rows: list[tuple[object, ...]] = [
            (m.label, f"{100.0 * shares[m]:.1f} %", len(self.polygons.get(m, [])), m.description)
            for m in self.modes]
        if self.curves:
            rows.append(("curves", len(self.curves), "", ", ".join(self.curves)))
        if self.points:
            rows.append(("points", len(self.points), "", ", ".join(
                f"{pt.name} ({pt.k:.4g}, {pt.mu:.4g})" for pt in self.points.values())))
        return html_table(rows, caption=f"Regime map, {self._what()}",
                          header=("mode", "share of the view", "polygons", ""))


def compute_map(params: Parameters, *, k_max: float | None = None, mu_max: float | None = None,
                modes: Iterable[Mode] | None = None, raw: bool = False, samples: int = DEFAULT_SAMPLES,
                curves: bool = True, include: Iterable[tuple[float, float]] = (),
                tolerance: float = 2e-4) -> MapData:
    """Compute the polygons, curves and named points of one map.

    Parameters
    ----------
    params : Parameters
    k_max, mu_max : float, optional
        The view; computed by :func:`auto_extent` when omitted.
    modes : iterable of Mode, optional
        Modes to shade (default: the six map modes, or
        :data:`~regimemap.mechanics.modes.LOADED_MAP_MODES` for a loaded block).
    raw : bool
        The report's raw region of each mode instead of the final map.
    samples : int
        Samples of k for the region polygons and the curves (>= 2).
    curves : bool
        Compute the boundary curves and named points, in view and off it (else empty).
    include : iterable of (k, mu)
        Points to keep in the automatic view.
    tolerance : float
        Simplification tolerance of the polygons, as a fraction of the view.

    Returns
    -------
    MapData
    """
    t0 = time.perf_counter()
    p = params
    default = LOADED_MAP_MODES if p.loaded else MAP_MODES
    modes_t = tuple(default if modes is None else (Mode(m) for m in modes))
    raw_mode = modes_t[0] if raw and len(modes_t) == 1 else None
    include = list(include)
    if k_max is None or mu_max is None:
        k_max, mu_max = auto_extent(p, raw_mode, include=include, k_max=k_max, mu_max=mu_max)
    samples = max(int(samples), 2)
    polys = region_polygons(p, k_max, mu_max, modes=modes_t, raw=raw, samples=samples)
    scale = (k_max, mu_max)
    polys = {m: [simplify(poly, tolerance, scale) for poly in lst] for m, lst in polys.items()}

    drawn_curves: dict[str, CurveData] = {}
    points: dict[str, NamedPoint] = {}
    ends: dict[str, tuple[float, float]] = {}
    off_view: tuple[NamedPoint, ...] = ()
    if curves:
        n_curve = max(16, min(samples, 400))
        drawn_curves = curve_data(p, k_max, mu_max, n_curve, raw, raw_mode, modes_t, tolerance)
        points = drawn_points(p, drawn_curves, k_max, mu_max)
        ends = line_ends(p, drawn_curves, points)
        off_view = tuple(points_off_view(p, float(k_max), float(mu_max)))
    if _log.isEnabledFor(logging.INFO):
        _log.info("map gamma=%g, k'=%g%s: view k <= %g, mu <= %g; %d polygons (%d vertices), "
                  "%d curves, %d points; %d samples, %.3f s", p.gamma, p.kprime,
                  " (raw regions)" if raw else "", k_max, mu_max, sum(len(v) for v in polys.values()),
                  sum(len(poly) for v in polys.values() for poly in v), len(drawn_curves), len(points),
                  samples, time.perf_counter() - t0)
    return MapData(p, float(k_max), float(mu_max), modes_t, bool(raw), polys, drawn_curves,
                   points, ends, off_view)


def map_for_view(params: Parameters, *, view: str = "designer", k_max: float | None = None,
             mu_max: float | None = None, modes: Iterable[Mode] | None = None, raw: bool = False,
             samples: int = DEFAULT_SAMPLES, curves: bool = True,
             include: Iterable[tuple[float, float]] = ()) -> MapData:
    """What the map of ``params`` shows, in the designer's or the report's view.

    Parameters
    ----------
    params : Parameters
    view : {"designer", "report"}
        The default view (:func:`regimemap.maps.designer_view.view_extent`):
        mu up to 1.2 and every boundary that crosses that band, or every
        characteristic point of the map.  ``k_max``/``mu_max`` win over both.
    k_max, mu_max : float, optional
        The view ``[0, k_max] x [0, mu_max]``.
    modes : iterable of Mode, optional
        Modes to shade (default: every mode the block shows).
    raw : bool
        The report's raw region of each mode (single-mode figures) instead of the final map.
    samples : int
        Samples of k for polygons and curves.
    curves : bool
        Compute the boundary curves and the named points.
    include : iterable of (k, mu)
        Points to keep in the view.

    Returns
    -------
    MapData
        :func:`compute_map` of that view.
    """
    include = list(include)
    if k_max is None or mu_max is None:
        from .designer_view import view_extent

        modes_t = tuple(MAP_MODES if modes is None else (Mode(m) for m in modes))
        if modes is not None:  # None: every mode the block shows (LO with loads)
            modes = modes_t
        raw_mode = modes_t[0] if raw and len(modes_t) == 1 else None
        k_max, mu_max = view_extent(params, view, raw_mode, include=include, k_max=k_max,
                                    mu_max=mu_max)
    return compute_map(params, k_max=k_max, mu_max=mu_max, modes=modes, raw=raw,
                       samples=samples, curves=curves, include=include)
