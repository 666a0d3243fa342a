"""Design points classified: what ``regimemap classify`` computes, as a record to write.

:func:`run_query` takes design points (:class:`~regimemap.maps.points.DesignPoint`,
each with its own gamma, k' and loads where it has them) and the block's
defaults, and returns a :class:`QueryRecord`: for every point the mode of the
map (Section 4.7 of the report below the centre of mass; least constraint with
loads), the reactions and accelerations at initiation from the equations of
motion and the margin to the nearest change of mode
(:func:`regimemap.maps.query.query_points`).  :mod:`regimemap.maps.record_tables` writes it
as text, CSV or JSON.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any, ClassVar

from ..records.fields import Field, Record
from ..records.notices import Notice
from .point_result import PointResult
from .points import DesignPoint
from .query import query_points

__all__ = ["QueryRecord", "run_query"]


@dataclass(frozen=True)
class QueryRecord(Record):
    """Design points and what happens at each.

    Attributes
    ----------
    points : tuple of DesignPoint
        The points asked about, as given.
    gamma, kprime : float or None
        The defaults of points without their own gamma or k'.
    loads : dict
        The default loads (keywords of :class:`~regimemap.mechanics.block.Parameters`).
    results : tuple of PointResult
        One per point, in order: mode, physics at initiation, admissible modes, margin.
    notices : tuple of Notice
        None so far: every failure is an error naming the point.
    """

    points: tuple[DesignPoint | tuple[float, float], ...]
    gamma: float | None
    kprime: float | None
    loads: dict[str, Any]
    results: tuple[PointResult, ...]
    notices: tuple[Notice, ...] = ()

    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("gamma", "gamma", "", "default aspect ratio H/B"),
        Field("kprime", "k'", "", "default height of the force h/H"),
        Field("count", "points", "", "design points classified"),
        Field("modes", "modes", "", "the mode at each point"),
    )
    CAPTION: ClassVar[str] = "Design points classified"

    @property
    def count(self) -> int:
        """The number of points."""
        return len(self.results)

    @property
    def modes(self) -> tuple[str, ...]:
        """The label of the mode at each point."""
        return tuple(r.mode.label for r in self.results)


def run_query(points: Iterable[DesignPoint | tuple[float, float]], gamma: float | None = None,
              kprime: float | None = None, **loads: Any) -> QueryRecord:
    """Classify design points: mode, physics at initiation and margin of each.

    Parameters
    ----------
    points : iterable of DesignPoint or (k, mu) pairs
        A point's own gamma, k' and loads take precedence over the defaults.
    gamma, kprime : float, optional
        Defaults for points without their own.
    **loads
        The default loads: ``buoyancy``, ``uplift``, ``uplift_ratio``, ``uplift_arm``,
        ``gyration``, ``crest`` (as :func:`regimemap.classify` takes them).

    Returns
    -------
    QueryRecord

    Raises
    ------
    ValueError
        A point without gamma or k' and no default, or a value out of range (the
        message names the point by position and name).

    Examples
    --------
    >>> rec = run_query([DesignPoint(0.5, 0.8)], gamma=3.0, kprime=0.4)
    >>> rec.modes
    ('RO',)
    """
    pts = tuple(points)
    results = query_points(pts, gamma=gamma, kprime=kprime, **loads)
    return QueryRecord(points=pts, gamma=gamma, kprime=kprime, loads=dict(loads),
                       results=tuple(results))
