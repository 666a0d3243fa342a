"""Worked figures of the loaded block, beside the report's 24: ids ``W.1``, ``W.2`` ...

The report's block carries nothing but its weight and the push; a caisson of a
vertical breakwater also carries buoyancy and the wave's uplift.  These
figures show what the loads do to the map:

``W.1``
    Goda's worked upright breakwater (``docs/waves.md`` Section 8) as the
    loaded block: gamma = 0.70, k' = -0.018, buoyancy 0.318 of the dry weight,
    uplift ratio 0.524 at the arm 1/3 (Goda's triangle), with its design
    point k = 0.2776, mu = 0.6.
``W.2``
    The same block in air, on the same axes.
``W.3``
    A slender block (gamma = 3, k' = 0.4) whose uplift grows as fast as the
    push (nu = 1): the lines move left and down, and the block lifts off
    beyond L.
``W.4``
    Goda's caisson as the uplift ratio grows (0, 0.524, 1): an atlas.

The ids start with ``W`` so they cannot be mistaken for the report's figures.
This module does not import matplotlib until it draws.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, cast

from ...mechanics.block import Parameters
from ..describe import load_items, loads_text
from ..points import DesignPoint

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..run import MapRecord
    from ..run_atlas import AtlasRecord

__all__ = ["WorkedFigure", "WORKED", "WORKED_IDS", "render_worked"]

#: Goda's worked caisson as the loaded block (docs/waves.md, Section 8).
GODA = {"gamma": 0.70, "kprime": -0.018, "buoyancy": 0.318, "uplift_ratio": 0.524}
#: Goda's design point: k = P/(m g) with the dry weight, and his friction coefficient.
GODA_POINT = DesignPoint(0.2776, 0.6, "Goda's caisson")


@dataclass(frozen=True)
class WorkedFigure:
    """One worked figure: a map (or an atlas of maps) of a loaded block.

    Attributes
    ----------
    id : str
        ``W.1``, ``W.2`` ...
    caption : str
        What the figure shows (mathtext allowed).
    params : Parameters
        The block (for an atlas: its first panel).
    k_max, mu_max : float or None
        The view (None: automatic).
    points : tuple of DesignPoint
        Design points marked on the map.
    sweep : str or None
        For an atlas: the load the columns sweep, with ``values``.
    """

    id: str
    caption: str
    params: Parameters
    k_max: float | None = None
    mu_max: float | None = None
    points: tuple[DesignPoint, ...] = ()
    sweep: str | None = None
    values: tuple[float, ...] = field(default=())

    @property
    def map_keywords(self) -> dict[str, Any]:
        """What a single map shows: the keywords of :func:`regimemap.maps.run.run_map`
        (the block, the report's view, its axes and the design points)."""
        return {"params": self.params, "view": "report", "k_max": self.k_max,
                "mu_max": self.mu_max, "points": self.points}

    @property
    def atlas_keywords(self) -> dict[str, Any]:
        """What an atlas shows: the keywords of :func:`regimemap.maps.run_atlas.run_atlas`
        (one row, the columns sweeping ``sweep``, the other loads shared, the report's view)."""
        p = self.params
        fixed = {"kprime": p.kprime, **{k: v for k, v in load_items(p) if k != self.sweep}}
        return {"gammas": [p.gamma], "values": list(self.values), "sweep": self.sweep,
                "fixed": fixed, "k_max": self.k_max, "mu_max": self.mu_max, "view": "report"}

    def filename(self, ext: str) -> str:
        """``fig-<id>.<ext>``, e.g. ``fig-W.1.png``."""
        return f"fig-{self.id}.{ext.lstrip('.')}"

    @property
    def title(self) -> str:
        """Two lines: ``Fig. <id>  <caption>`` and the block with its loads (mathtext)."""
        p = self.params
        loads = loads_text(p, tex=True)
        par = rf"($\gamma = {p.gamma:g}$, $k' = {p.kprime:g}$" + (f"; {loads}" if loads else "") + ")"
        return f"Fig. {self.id}  {self.caption}\n{par}"


def _build() -> dict[str, WorkedFigure]:
    sea = Parameters(**GODA)
    air = Parameters(GODA["gamma"], GODA["kprime"])
    slender = Parameters(3.0, 0.4, uplift_ratio=1.0)
    rows = [
        WorkedFigure("W.1", "Goda's worked caisson, submerged: buoyancy and uplift", sea, 6.0,
                     3.0, (GODA_POINT,)),
        WorkedFigure("W.2", "The same caisson in air (no buoyancy, no uplift)", air, 6.0, 3.0,
                     (GODA_POINT,)),
        WorkedFigure("W.3", r"A slender block whose uplift grows with the push ($\nu = 1$)",
                     slender),
        WorkedFigure("W.4", r"Goda's caisson as the uplift ratio $\nu$ grows (columns)", sea, 6.0, 3.0,
                     sweep="uplift_ratio", values=(0.0, 0.524, 1.0)),
    ]
    return {w.id: w for w in rows}


#: The worked figures by id.
WORKED: dict[str, WorkedFigure] = _build()
#: Their ids, in order.
WORKED_IDS: tuple[str, ...] = tuple(WORKED)


def render_worked(worked: WorkedFigure | str, record: MapRecord | AtlasRecord, *,
                  dpi: float | None = None, fig: Figure | None = None, **kwargs: Any) -> Figure:
    """A Figure of one worked figure (pass the previous ``fig`` of a single map to reuse it).

    ``record`` is its map, ``run_map(**worked.map_keywords)``, or for an atlas
    (``worked.sweep``) its panels, ``run_atlas(**worked.atlas_keywords)``
    (:mod:`regimemap.workflows`); ``kwargs`` go to the drawing function.
    """
    from ...drawing.save import DEFAULT_DPI
    from .figure import map_figure

    w = WORKED[worked.upper()] if isinstance(worked, str) else worked
    dpi = DEFAULT_DPI if dpi is None else dpi
    if w.sweep is not None:
        from .atlas import atlas_figure

        return atlas_figure(cast("AtlasRecord", record), dpi=dpi,
                            caption=f"Fig. {w.id}  {w.caption}", **kwargs)
    if fig is not None and len(fig.axes) != 1:
        fig = None  # an atlas before: start afresh
    return map_figure(cast("MapRecord", record), dpi=dpi, fig=fig, title=w.title, **kwargs)[0]
