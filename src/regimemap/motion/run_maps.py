"""Outcome maps over two swept inputs: :func:`run_outcome` (``regimemap outcome``) and
:func:`run_dynamics_figure` (one of the figures D.1-D.3, ``regimemap dynamics-figures``).

Each computes an outcome map (rest, slide, rock, slide-rock, overturned, still moving) with
its boundaries refined by bisection (:func:`regimemap.dynamics.outcome.staged_outcome_map`)
and returns a record holding its inputs, the map, what is derived from it (the count of each
category, the axes in dimensionless units) and its warnings; :mod:`regimemap.motion.record_outcome`
writes the record, :mod:`regimemap.motion.figures.outcome` draws it.
"""

from __future__ import annotations

import math
import os
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .record import DynamicsFigureRecord, OutcomeRecord

if TYPE_CHECKING:  # pragma: no cover
    from ..dynamics.outcome import Bars
    from ..dynamics.presets import DynamicsFigure
    from .file import MapOptions

__all__ = ["DynamicsFigureRecord", "OutcomeRecord", "run_dynamics_figure", "run_outcome"]

FloatArray = NDArray[np.float64]


def run_outcome(options: MapOptions, *, restitution: float | None = None, min_rotation: float = 0.0,
                refine: bool = True, dimensionless: bool = False, bars: Bars | None = None) -> OutcomeRecord:
    """Simulate the grid of an outcome map over two swept inputs, refine its boundaries, count.

    Parameters
    ----------
    options : MapOptions
        The inputs, checked (:func:`regimemap.motion.file.map_options`).
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


def run_dynamics_figure(figure: DynamicsFigure, *, cache: str | os.PathLike[str] | None = None,
                        bars: Bars | None = None) -> DynamicsFigureRecord:
    """The outcome map of one of the figures D.1-D.3, computed or read from ``cache``.

    Parameters
    ----------
    figure : DynamicsFigure
        One of :data:`regimemap.dynamics.presets.DYNAMICS_FIGURES`.
    cache : str or path, optional
        A folder of computed maps (:func:`regimemap.motion.record_outcome.cached_outcome`), reused while
        the figure's definition and :mod:`regimemap.dynamics` are unchanged.
    bars : callable, optional
        ``bars(total, description)``: a progress bar for each stage.
    """
    from .record_outcome import cached_outcome

    m, x, y, hit = cached_outcome(cache, figure.id, repr(figure), lambda: figure.compute(bars))
    return DynamicsFigureRecord(figure=figure, outcome=m, x=x, y=y, from_cache=hit)
