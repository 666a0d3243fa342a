"""The map of one block: what ``regimemap plot`` computes, as a record to draw.

:func:`run_map` takes the block (:class:`~regimemap.mechanics.block.Parameters`), the
view and the design points to mark, and returns a :class:`MapRecord`: the map
(:class:`~regimemap.maps.mapdata.MapData`: the region polygons of Section 4.7,
the boundary curves and the named points in the view), the points drawn on it,
the parts where several modes are admissible (when asked) and the warnings as
:class:`~regimemap.records.notices.Notice` data.
:func:`regimemap.maps.figures.figure.map_figure` draws the record.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from ..mechanics.block import Parameters
from ..mechanics.modes import Mode
from ..records.fields import Field, Record
from ..records.notices import Notice
from .geometry import DEFAULT_SAMPLES
from .mapdata import MapData, map_for_view
from .points import LOAD_FIELDS, DesignPoint

if TYPE_CHECKING:  # pragma: no cover
    from .ambiguity import AmbiguousRegion

__all__ = ["MapRecord", "points_of_map", "run_map"]


@dataclass(frozen=True)
class MapRecord(Record):
    """The map of one block in one view, with the design points marked on it.

    Attributes
    ----------
    params : Parameters
        The block (gamma, k' and its loads).
    view : str
        The default view asked for: ``"designer"`` or ``"report"``.
    data : MapData
        The map: polygons, curves and named points in ``[0, k_max] x [0, mu_max]``.
    points : tuple of DesignPoint
        The design points of this block, drawn on the map and kept in its view.
    ambiguity : tuple of AmbiguousRegion or None
        The parts of the view where the equations of motion admit several modes
        (:func:`regimemap.maps.ambiguity.ambiguous_in_view`), when asked for.
    notices : tuple of Notice
        ``other-block`` (points of another gamma, k' or loads, not drawn) and
        ``outside-view`` (points beyond the view drawn).
    """

    params: Parameters
    view: str
    data: MapData
    points: tuple[DesignPoint, ...] = ()
    ambiguity: tuple[AmbiguousRegion, ...] | None = None
    notices: tuple[Notice, ...] = ()

    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("params.gamma", "gamma", "", "aspect ratio H/B"),
        Field("params.kprime", "k'", "", "height of the force h/H"),
        Field("params.case.value", "case", "", "the report's case of the block"),
        Field("view", "view", "", "the default view: designer or report"),
        Field("data.k_max", "k_max", "", "right end of the k axis"),
        Field("data.mu_max", "mu_max", "", "top of the mu axis"),
        Field("data.modes", "modes", "", "the modes shaded"),
        Field("points", "points", "", "design points drawn"),
    )
    CAPTION: ClassVar[str] = "Regime map"


def _num(x: float) -> str:
    return f"{x:g}"


def _names(points: Sequence[DesignPoint], count: int) -> str:
    return ", ".join(p.name or f"({_num(p.k)}, {_num(p.mu)})" for p in points[:count])


def _same_block(pt: DesignPoint, params: Parameters) -> bool:
    """Whether a point's own gamma, k' and loads (where it has them) are the block's."""
    if pt.gamma is not None and not math.isclose(pt.gamma, params.gamma, rel_tol=1e-9):
        return False
    if pt.kprime is not None and not math.isclose(pt.kprime, params.kprime, rel_tol=1e-9,
                                                  abs_tol=1e-12):
        return False
    loads = params.loads
    for key in LOAD_FIELDS:
        own = getattr(pt, key)
        if own is None:
            continue
        want = loads[key]
        if want is None or not math.isclose(own, want, rel_tol=1e-9, abs_tol=1e-12):
            return False
    return True


def points_of_map(points: Iterable[DesignPoint], params: Parameters
                  ) -> tuple[tuple[DesignPoint, ...], tuple[Notice, ...]]:
    """The points of the block ``params`` and a notice naming those of another block.

    A point without its own gamma, k' or a load takes the block's.

    Returns
    -------
    (points, notices)
    """
    keep: list[DesignPoint] = []
    other: list[DesignPoint] = []
    for pt in points:
        (keep if _same_block(pt, params) else other).append(pt)
    if not other:
        return tuple(keep), ()
    more = f" and {len(other) - 5} more" if len(other) > 5 else ""
    return tuple(keep), (Notice(
        "other-block", f"{len(other)} point(s) have another gamma or kprime or other loads "
        f"and are not drawn on this map: {_names(other, 5)}{more}", "points", len(other)),)


def _outside(points: Sequence[DesignPoint], k_hi: float, mu_hi: float) -> tuple[Notice, ...]:
    outside = [p for p in points if p.k > k_hi or p.mu > mu_hi]
    if not outside:
        return ()
    return (Notice("outside-view", f"{len(outside)} point(s) outside the view "
                   f"k <= {_num(k_hi)}, mu <= {_num(mu_hi)}: {_names(outside, 5)}",
                   "points", len(outside)),)


# The map's request, one keyword each as ``regimemap plot`` gives them (PLR0913 accepted here).
def run_map(params: Parameters, *, view: str = "designer", k_max: float | None = None,  # noqa: PLR0913
            mu_max: float | None = None, modes: Iterable[Mode] | None = None, raw: bool = False,
            samples: int = DEFAULT_SAMPLES, curves: bool = True,
            points: Iterable[DesignPoint] = (), ambiguity: bool = False) -> MapRecord:
    """The map of ``params``: what ``regimemap plot`` computes before it draws.

    Parameters
    ----------
    params : Parameters
        The block.
    view : {"designer", "report"}
        The default view (:func:`regimemap.maps.designer_view.view_extent`): mu up
        to 1.2 and every boundary crossing that band, or every characteristic point.
    k_max, mu_max : float, optional
        The view ``[0, k_max] x [0, mu_max]`` (wins over ``view``).
    modes : iterable of Mode, optional
        The modes to shade (default: every mode the block shows).
    raw : bool
        Each mode's raw region, before Section 4.7 resolves overlaps.
    samples : int
        Samples of k for the polygons and curves.
    curves : bool
        Compute the boundary curves and the named points.
    points : iterable of DesignPoint
        Design points; those of this block are kept in the automatic view, the
        others are named in an ``other-block`` notice.
    ambiguity : bool
        Also find where several modes are admissible
        (:func:`regimemap.maps.ambiguity.ambiguous_in_view`, Section 4.7 below C;
        least constraint with loads).

    Returns
    -------
    MapRecord

    Examples
    --------
    >>> from regimemap.mechanics.block import Parameters
    >>> rec = run_map(Parameters(3.0, 0.4), samples=51)
    >>> rec.data.k_max > 0 and rec.notices == ()
    True
    """
    kept, notices = points_of_map(points, params)
    data = map_for_view(params, view=view, k_max=k_max, mu_max=mu_max, modes=modes, raw=raw,
                        samples=samples, curves=curves, include=[(p.k, p.mu) for p in kept])
    regions = None
    if ambiguity:
        from .ambiguity import ambiguous_in_view

        regions = tuple(ambiguous_in_view(params, data.k_max, data.mu_max))
    notices += _outside(kept, data.k_max, data.mu_max)
    return MapRecord(params=params, view=view, data=data, points=kept, ambiguity=regions,
                     notices=notices)
