"""Outcome maps over two swept inputs: :func:`run_outcome` (``regimemap outcome``) and
:func:`run_dynamics_figure` (one of the figures D.1-D.3, ``regimemap dynamics-figures``).

Each computes an outcome map (rest, slide, rock, slide-rock, overturned, still moving) with
its boundaries refined by bisection (:func:`regimemap.dynamics.outcome.staged_outcome_map`)
and returns a record holding its inputs, the map, what is derived from it (the count of each
category, the axes in dimensionless units) and its warnings; :mod:`regimemap.io.dynamics`
writes the record, :mod:`regimemap.drawing.outcome` draws it.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import NDArray

from ..mechanics.notices import Notice
from ._record import Field, Record

if TYPE_CHECKING:  # pragma: no cover
    from ..dynamics import Block
    from ..dynamics.options import MapOptions
    from ..dynamics.outcome import Bars, OutcomeMap
    from ..dynamics.presets import DynamicsFigure

__all__ = ["DynamicsFigureRecord", "OutcomeRecord", "run_dynamics_figure", "run_outcome"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class OutcomeRecord(Record):
    """An outcome map of :func:`run_outcome`: its inputs, the map and what is derived from it.

    Attributes
    ----------
    options : MapOptions
        The inputs: the pulse shape, the two swept inputs (columns, rows) and their values,
        the fixed ones (:func:`regimemap.dynamics.options.map_options`).
    restitution : float or None
        The ratio of a rocking impact; None is Housner's plastic impact.
    min_rotation : float
        Rocking counts only above this largest rotation (degrees).
    block : Block
        The block of the map (a swept field holds its first value).
    outcome : OutcomeMap
        The map, its axes named and valued as the swept inputs (``first_name``, ``first_values``
        ...), its boundaries refined unless ``refine=False``.
    counts : dict
        The number of cells of each category, by label (every label, zeros included).
    dimensionless_axes : dict
        With ``dimensionless``: the swept inputs among k_peak, duration and omega_p by name, their
        values as omega_p/p or k_peak/tan(alpha) (Makris & Roussos 2000).
    notices : tuple of Notice
    """

    options: MapOptions
    restitution: float | None
    min_rotation: float
    block: Block
    outcome: OutcomeMap
    counts: dict[str, int]
    dimensionless_axes: dict[str, FloatArray] = field(default_factory=dict)
    notices: tuple[Notice, ...] = ()

    CAPTION: ClassVar[str] = "regimemap outcome: an outcome map over two swept inputs"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("options.shape", "pulse", "", "shape of the force pulse"),
        Field("options.swept", "swept", "", "the inputs along the columns and the rows"),
        Field("n_runs", "runs", "", "cells of the grid"),
        Field("counts", "categories", "", "cells of each category"),
        Field("outcome.seconds", "grid time", "s", "time of the grid's runs"),
        Field("outcome.refined", "refined", "", "boundaries refined by bisection to 1/1000 of each axis"),
    )

    @property
    def n_runs(self) -> int:
        """The cells (runs) of the grid."""
        return self.options.n_runs

    @property
    def inputs(self) -> dict[str, Any]:
        """The inputs not swept, as the data files hold them: ``pulse`` (the shape), the fixed
        values given, ``restitution`` and ``min_rotation`` (degrees) when given."""
        out: dict[str, Any] = {"pulse": self.options.shape}
        out.update({n: v for n, v in self.options.fixed.items() if v is not None})
        if self.restitution is not None:
            out["restitution"] = self.restitution
        if self.min_rotation:
            out["min_rotation"] = self.min_rotation
        return out

    @property
    def extra_axes(self) -> dict[str, FloatArray]:
        """The dimensionless axes as the data files name them (``k_peak_dimensionless`` ...)."""
        return {f"{n}_dimensionless": v for n, v in self.dimensionless_axes.items()}


def run_outcome(options: MapOptions, *, restitution: float | None = None, min_rotation: float = 0.0,
                refine: bool = True, dimensionless: bool = False, bars: Bars | None = None) -> OutcomeRecord:
    """Simulate the grid of an outcome map over two swept inputs, refine its boundaries, count.

    Parameters
    ----------
    options : MapOptions
        The inputs, checked (:func:`regimemap.dynamics.options.map_options`).
    restitution : float, optional
        Ratio of a rocking impact; None is Housner's plastic impact.
    min_rotation : float
        Count rocking only above this largest rotation (degrees).
    refine : bool
        Refine the boundaries between categories by bisection to 1/1000 of each axis.
    dimensionless : bool
        Give the swept k_peak, duration or omega_p also as k_peak/tan(alpha) and omega_p/p.
    bars : callable, optional
        ``bars(total, description)``: a progress bar for each stage
        (:func:`regimemap.dynamics.outcome.staged_outcome_map`).

    Returns
    -------
    OutcomeRecord

    Raises
    ------
    OptionError
        When the longest run needs more time steps than the limit (naming ``--duration`` or
        ``--omega-p``).
    """
    from ..dynamics.outcome import DIMENSIONLESS, MapRuns, dimensionless_values, staged_outcome_map

    options.check_steps()
    block = options.block()
    swept, shape = options.swept, options.shape
    first, second = options.axis(0), options.axis(1)
    (n1, v1), (n2, v2) = options.sweep(0), options.sweep(1)
    runs = MapRuns(block, shape, n1, n2, k_peak=options.fixed.get("k_peak"),
                   duration=options.fixed_duration(), restitution=restitution,
                   min_rotation=math.radians(min_rotation))
    m = staged_outcome_map(runs, v1, v2, refine=refine, bars=bars)
    m = replace(m, first_name=swept[0], first_values=first, second_name=swept[1], second_values=second)
    counts = np.bincount(m.category.ravel().astype(np.int64), minlength=len(m.labels))
    dim = {n: dimensionless_values(n, axis, block, shape) for n, axis in zip(swept, (first, second))
           if dimensionless and n in DIMENSIONLESS}
    return OutcomeRecord(options=options, restitution=restitution, min_rotation=min_rotation, block=block,
                         outcome=m, counts=dict(zip(m.labels, counts.tolist())), dimensionless_axes=dim)


@dataclass(frozen=True)
class DynamicsFigureRecord(Record):
    """One of the figures D.1-D.3 of :func:`run_dynamics_figure`: its definition and its map.

    Attributes
    ----------
    figure : DynamicsFigure
        The figure's block, pulse and swept inputs (:data:`regimemap.dynamics.presets.DYNAMICS_FIGURES`).
    outcome : OutcomeMap
        Its map, boundaries refined.
    x, y : ndarray
        The values of the map's columns and rows as drawn (dimensionless for D.1 and D.2).
    from_cache : bool
        Whether the map was read from the cache.
    notices : tuple of Notice
    """

    figure: DynamicsFigure
    outcome: OutcomeMap
    x: FloatArray
    y: FloatArray
    from_cache: bool = False
    notices: tuple[Notice, ...] = ()

    CAPTION: ClassVar[str] = "regimemap dynamics-figures: one figure's outcome map"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("figure.id", "figure", "", "D.1, D.2 or D.3"),
        Field("outcome.category.size", "runs", "", "cells of the grid"),
        Field("refine_runs", "boundary runs", "", "runs of the bisection of the boundaries"),
        Field("from_cache", "from the cache", "", "whether the map was read from the cache"),
    )

    @property
    def data(self) -> tuple[OutcomeMap, FloatArray, FloatArray]:
        """The map and the values of its columns and rows as drawn."""
        return self.outcome, self.x, self.y

    @property
    def refine_runs(self) -> int:
        """The runs of the bisection of the boundaries (0 when not refined)."""
        return self.outcome.crossings.runs if self.outcome.crossings is not None else 0


def run_dynamics_figure(figure: DynamicsFigure, *, cache: str | os.PathLike[str] | None = None,
                        bars: Bars | None = None) -> DynamicsFigureRecord:
    """The outcome map of one of the figures D.1-D.3, computed or read from ``cache``.

    Parameters
    ----------
    figure : DynamicsFigure
        One of :data:`regimemap.dynamics.presets.DYNAMICS_FIGURES`.
    cache : str or path, optional
        A folder of computed maps (:func:`regimemap.io.dynamics.cached_outcome`), reused while
        the figure's definition and :mod:`regimemap.dynamics` are unchanged.
    bars : callable, optional
        ``bars(total, description)``: a progress bar for each stage.
    """
    from ..io.dynamics import cached_outcome

    m, x, y, hit = cached_outcome(cache, figure.id, repr(figure), lambda: figure.compute(bars))
    return DynamicsFigureRecord(figure=figure, outcome=m, x=x, y=y, from_cache=hit)
