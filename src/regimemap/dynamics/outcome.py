"""Outcome maps (data only): sweep two inputs, simulate every cell in one batch, refine the boundaries.

:func:`outcome_map` simulates the grid (one batch), then finds where each boundary between two
categories crosses the grid's edges by bisection (:mod:`regimemap.dynamics.boundaries`, a few
batches more), so that the regions are polygons bounded by those curves
(:meth:`OutcomeMap.geometry`, :mod:`regimemap.dynamics.regions`) rather than the cells.
:class:`MapRuns` holds what the runs share, and :func:`grid_map` and :func:`refine_map` do the
two stages one at a time (the command line shows a progress bar for each).

The dimensionless axes are those of Makris & Roussos (2000) and Zhang & Makris
(2001): omega_p/p and k_peak/tan(alpha), with p = sqrt(3 g/(4 R)),
R = B sqrt(1 + gamma^2) and alpha = atan(1/gamma) (Housner 1963).

References
----------
Housner, G. W. (1963). Bull. Seismol. Soc. Am. 53(2), 403-417.

Makris, N. & Roussos, Y. (2000). Geotechnique 50(3), 243-262.

Zhang, J. & Makris, N. (2001). J. Eng. Mech. 127(5), 473-483.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from contextlib import AbstractContextManager
from dataclasses import dataclass, fields, replace
from functools import cached_property
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .block import Block, G, frequency_parameter, slenderness
from .boundaries import TOLERANCE, Crossings, plan_refinement, refinable, refine_crossings
from .pulses import Pulse
from .regions import MapGeometry, assemble
from .stepper import CATEGORY_LABELS, Simulation, simulate

__all__ = ["OutcomeMap", "MapRuns", "outcome_map", "grid_map", "refine_map", "staged_outcome_map",
           "planned_refinement_runs", "SWEEPABLE", "DIMENSIONLESS", "to_dimensionless", "from_dimensionless",
           "dimensionless_values", "TOLERANCE"]

#: ``progress(n)``: n more runs are done.
Progress = Callable[[int], None]
#: ``bars(total, description)``: a context manager yielding the ``progress`` of one stage
#: (e.g. :func:`regimemap.cli._progress.progress_bar`).
Bars = Callable[[int, str], AbstractContextManager[Progress]]

FloatArray = NDArray[np.float64]

_BLOCK_FIELDS = tuple(f.name for f in fields(Block) if f.name != "g")
#: Inputs an outcome map can sweep: the pulse's k_peak, duration or omega_p, and any block field.
SWEEPABLE: tuple[str, ...] = ("k_peak", "duration", "omega_p") + _BLOCK_FIELDS


def to_dimensionless(k_peak: ArrayLike, omega_p: ArrayLike, B: float, gamma: float,
                     g: float = G) -> tuple[FloatArray, FloatArray]:
    """(omega_p/p, k_peak/tan(alpha)) of a uniform block of half width B and gamma = H/B."""
    p = frequency_parameter(B, gamma, g)
    return (np.asarray(omega_p, dtype=np.float64) / p,
            np.asarray(k_peak, dtype=np.float64) / np.tan(slenderness(gamma)))


def from_dimensionless(omega_ratio: ArrayLike, k_ratio: ArrayLike, B: float, gamma: float,
                       g: float = G) -> tuple[FloatArray, FloatArray]:
    """(k_peak, omega_p) from (omega_p/p, k_peak/tan(alpha)): the inverse of :func:`to_dimensionless`."""
    p = frequency_parameter(B, gamma, g)
    return (np.asarray(k_ratio, dtype=np.float64) * np.tan(slenderness(gamma)),
            np.asarray(omega_ratio, dtype=np.float64) * p)


#: The swept inputs that have a dimensionless form, and its name: k_peak/tan(alpha), omega_p/p.
DIMENSIONLESS: dict[str, str] = {"k_peak": "k_peak/tan(alpha)", "duration": "omega_p/p",
                                 "omega_p": "omega_p/p"}


def dimensionless_values(name: str, values: ArrayLike, block: Block, shape: str) -> FloatArray:
    """The values of a swept input in the dimensionless units of :data:`DIMENSIONLESS`.

    ``k_peak`` -> k_peak/tan(alpha), ``omega_p`` -> omega_p/p and ``duration`` -> omega_p/p
    with omega_p the pulse's (pi/duration, or 2 pi/duration for one-sine and one-cosine), for
    the block's own p (which accounts for its radius of gyration) and alpha.

    Raises
    ------
    ValueError
        For an input without a dimensionless form, or a block whose p or alpha is not one
        number (a block field that is swept).
    """
    if name not in DIMENSIONLESS:
        raise ValueError(f"{name} has no dimensionless form (only {', '.join(DIMENSIONLESS)})")
    p_all = np.asarray(block.p, dtype=np.float64)
    alpha_all = np.asarray(block.alpha, dtype=np.float64)
    if p_all.size != 1 or alpha_all.size != 1:
        raise ValueError("dimensionless axes need one block (p and alpha the same in every cell)")
    p, alpha = float(p_all.ravel()[0]), float(alpha_all.ravel()[0])
    v = np.asarray(values, dtype=np.float64)
    if name == "k_peak":
        return np.asarray(v / np.tan(alpha), dtype=np.float64)
    if name == "omega_p":
        return np.asarray(v / p, dtype=np.float64)
    return np.asarray(Pulse.make(shape, 1.0, v).omega_p, dtype=np.float64) / p


@dataclass(frozen=True)
class OutcomeMap:
    """Per-cell outcomes, arrays of shape (len(second_values), len(first_values)).

    Attributes
    ----------
    first_name, second_name : str
        Swept inputs (columns vary the first, rows the second).
    first_values, second_values : ndarray
        Their values.
    category : ndarray of int8
        Outcome code: 0 rest, 1 slide only, 2 rock only, 3 slide-rock, 4 overturned,
        5 still moving at the time limit (labels in :attr:`labels`).
    overturned : ndarray of bool
    max_rotation : ndarray
        Largest |theta| (rad).
    residual_slide : ndarray
        Final slide of the base (m), positive towards O.
    labels : tuple of str
        Category labels by code.
    seconds : float
        Wall time of the grid's batch.
    crossings : Crossings or None
        Where the boundaries between categories cross the grid's edges (refined by
        bisection); None for a map that was not refined (its cells are all it knows).
    refine_seconds : float
        Wall time of the refinement.
    min_rotation : float
        Smallest largest rotation (rad) that counts as rocking (0: any rocking phase).
    """

    first_name: str
    first_values: FloatArray
    second_name: str
    second_values: FloatArray
    category: NDArray[np.int8]
    overturned: NDArray[np.bool_]
    max_rotation: FloatArray
    residual_slide: FloatArray
    labels: tuple[str, ...] = CATEGORY_LABELS
    seconds: float = 0.0
    crossings: Crossings | None = None
    refine_seconds: float = 0.0
    min_rotation: float = 0.0

    @property
    def refined(self) -> bool:
        """Whether the boundaries were refined (:attr:`crossings` is set)."""
        return self.crossings is not None

    @cached_property
    def _grid_geometry(self) -> MapGeometry | None:
        if self.crossings is None:
            return None
        return assemble(self.category, self.crossings)

    def geometry(self, x: ArrayLike | None = None, y: ArrayLike | None = None) -> MapGeometry | None:
        """The regions as polygons and the boundaries as polylines (None if not refined).

        On the axes ``x`` (the columns' values) and ``y`` (the rows'), by default the swept
        values; between two nodes the coordinates are interpolated linearly.
        """
        geo = self._grid_geometry
        if geo is None:
            return None
        return geo.scaled(self.first_values if x is None else x, self.second_values if y is None else y)

    def boundaries(self) -> list[tuple[str, str, FloatArray]]:
        """The boundaries between categories as (label, label, points), points (n, 2) in the swept
        inputs' units (first, second); empty when not refined."""
        geo = self.geometry()
        if geo is None:
            return []
        return [(self.labels[a], self.labels[b], p) for a, b, p in geo.boundaries]


def _categories(sim: Simulation, min_rotation: float) -> NDArray[np.int8]:
    """The runs' categories, rocking counted from ``min_rotation`` (rad)."""
    return np.asarray(sim.categories(min_rotation), dtype=np.int8)


@dataclass(frozen=True)
class MapRuns:
    """What the runs of an outcome map share: all but the values of the two swept inputs.

    Attributes
    ----------
    block : Block
        The block; the swept fields are replaced.
    shape : str
        Pulse shape (see :data:`regimemap.dynamics.SHAPES`).
    first, second : str
        The swept inputs (:data:`SWEEPABLE`): columns and rows.  ``omega_p`` sets the
        duration through :meth:`Pulse.from_frequency`.
    k_peak, duration : array_like, optional
        The pulse's values when not swept.
    restitution, dt : optional
        Passed to :func:`regimemap.dynamics.simulate`.
    pulse_params : dict, optional
        Shape parameters (``peak_at``, ``peak_ratio``, ``impulsive_fraction``).
    min_rotation : float
        Smallest largest rotation (rad) that counts as rocking.
    """

    block: Block
    shape: str
    first: str
    second: str
    k_peak: ArrayLike | None = None
    duration: ArrayLike | None = None
    restitution: float | None = None
    dt: float | None = None
    pulse_params: dict[str, float] | None = None
    min_rotation: float = 0.0

    def __post_init__(self) -> None:
        for name in (self.first, self.second):
            if name not in SWEEPABLE:
                raise ValueError(f"cannot sweep {name!r}; sweepable: {', '.join(SWEEPABLE)}")
        if self.first == self.second:
            raise ValueError("the two swept inputs must differ")
        if "duration" in (self.first, self.second) and "omega_p" in (self.first, self.second):
            raise ValueError("sweep duration or omega_p, not both")
        if self.k_peak is None and "k_peak" not in (self.first, self.second):
            raise ValueError("k_peak must be given or swept")
        if self.duration is None and not {"duration", "omega_p"} & {self.first, self.second}:
            raise ValueError("duration (or omega_p) must be given or swept")
        if not (np.isfinite(self.min_rotation) and self.min_rotation >= 0.0):
            raise ValueError(f"min_rotation must be a finite angle >= 0, got {self.min_rotation!r}")

    def simulate(self, first: ArrayLike, second: ArrayLike, progress: Progress | None = None) -> Simulation:
        """One batch: a run for each pair (``first[n]``, ``second[n]``) of the swept values.

        ``progress(n)`` is called with the runs done, as they finish.
        """
        values: dict[str, Any] = {self.first: np.asarray(first, dtype=np.float64).ravel(),
                                  self.second: np.asarray(second, dtype=np.float64).ravel()}
        params = dict(self.pulse_params or {})
        kp = _given(values.get("k_peak", self.k_peak), "k_peak")
        if "omega_p" in values:
            pulse = Pulse.from_frequency(self.shape, kp, values["omega_p"], **params)
        else:
            duration = _given(values.get("duration", self.duration), "duration")
            pulse = Pulse.make(self.shape, kp, duration, **params)
        changes = {name: val for name, val in values.items() if name in _BLOCK_FIELDS}
        blk = self.block.with_(**changes) if changes else self.block
        return _run(blk, pulse, self.restitution, self.dt, progress)

    def categories(self, first: ArrayLike, second: ArrayLike, progress: Progress | None = None
                   ) -> NDArray[np.int8]:
        """The categories of the runs of :meth:`simulate`."""
        return _categories(self.simulate(first, second, progress), self.min_rotation)


def _given(value: ArrayLike | None, name: str) -> ArrayLike:
    if value is None:  # pragma: no cover - MapRuns checks it
        raise ValueError(f"{name} must be given or swept")
    return value


def _run(block: Block, pulse: Pulse, restitution: float | None, dt: float | None,
         progress: Progress | None) -> Simulation:
    """simulate(), reporting the runs to ``progress`` as they finish."""
    t0 = time.perf_counter()
    sim = simulate(block, pulse, restitution=restitution, dt=dt, record_phases=False, progress=progress)
    logging.getLogger(__name__).debug("batch of %d runs (%s pulses): %.2f s", np.size(sim.overturned),
                                      pulse.shape, time.perf_counter() - t0)
    return sim


def grid_map(runs: MapRuns, first_values: ArrayLike, second_values: ArrayLike, *,
             progress: Progress | None = None) -> OutcomeMap:
    """Simulate every node of the grid (one batch) and tabulate the outcomes (not refined).

    ``progress(n)`` is called with the runs done.
    """
    a1 = np.asarray(first_values, dtype=np.float64).ravel()
    a2 = np.asarray(second_values, dtype=np.float64).ravel()
    X, Y = np.meshgrid(a1, a2)
    t0 = time.perf_counter()
    sim = runs.simulate(X.ravel(), Y.ravel(), progress)
    seconds = time.perf_counter() - t0
    logging.getLogger(__name__).info("outcome grid %s x %s: %d x %d = %d runs in %.2f s", runs.first,
                                     runs.second, a1.size, a2.size, X.size, seconds)
    shape2 = X.shape
    cat = _categories(sim, runs.min_rotation).reshape(shape2)
    labels = tuple(CATEGORY_LABELS)
    return OutcomeMap(first_name=runs.first, first_values=a1, second_name=runs.second, second_values=a2,
                      category=cat, overturned=sim.overturned.reshape(shape2),
                      max_rotation=sim.max_rotation.reshape(shape2),
                      residual_slide=sim.residual_slide.reshape(shape2), labels=labels, seconds=seconds,
                      min_rotation=runs.min_rotation)


def refine_map(m: OutcomeMap, runs: MapRuns, *, tol: float = TOLERANCE,
               progress: Progress | None = None) -> OutcomeMap:
    """``m`` with its boundaries refined by bisection
    (:func:`regimemap.dynamics.boundaries.refine_crossings`).

    Each boundary's crossing of a grid edge is found to ``tol`` times the range of the swept
    input along that edge, all edges at once (one batch per step).  A map with an axis of one
    value, or an axis that is not strictly monotonic, is returned as it is.  ``progress(n)``
    is called with the runs done (:func:`plan_refinement` tells how many there will be).
    """
    x, y = np.asarray(m.first_values), np.asarray(m.second_values)
    if not refinable(x, y):
        return m
    t0 = time.perf_counter()
    crossings = refine_crossings(x, y, m.category, lambda a, b: runs.categories(a, b, progress), tol=tol)
    return replace(m, crossings=crossings, refine_seconds=time.perf_counter() - t0)


# One call for MapRuns (block, pulse and run keywords), grid_map and refine_map: its keywords
# are theirs, one each, as documented in docs/dynamics.md (PLR0913 accepted here).
def outcome_map(block: Block, shape: str, first: tuple[str, ArrayLike], second: tuple[str, ArrayLike],  # noqa: PLR0913
                *, k_peak: ArrayLike | None = None, duration: ArrayLike | None = None,
                restitution: float | None = None, dt: float | None = None,
                pulse_params: dict[str, float] | None = None, min_rotation: float = 0.0,
                refine: bool = True, tol: float = TOLERANCE,
                progress: Progress | None = None) -> OutcomeMap:
    """Simulate every combination of two swept inputs (one batch), tabulate the outcomes and
    refine the boundaries between them.

    Parameters
    ----------
    block : Block
        The block; the swept fields are replaced.
    shape : str
        Pulse shape (see :data:`regimemap.dynamics.SHAPES`).
    first, second : (str, array_like)
        Name (one of :data:`SWEEPABLE`) and values of the inputs along the
        columns and the rows.  ``omega_p`` sets the duration through
        :meth:`Pulse.from_frequency`.
    k_peak, duration : array_like, optional
        The pulse's fixed values when not swept.
    restitution, dt : optional
        Passed to :func:`regimemap.dynamics.simulate`.
    pulse_params : dict, optional
        Shape parameters (``peak_at``, ``peak_ratio``, ``impulsive_fraction``).
    min_rotation : float
        Smallest largest rotation (rad) that counts as rocking (0: any rocking phase).
    refine : bool
        Find the boundaries between categories by bisection (:func:`refine_map`); False
        leaves the grid as computed.
    tol : float
        Tolerance of the refinement, a fraction of the range of the swept input.
    progress : callable, optional
        Called with the number of runs done, as they are done (the grid's, then the
        refinement's: :func:`plan_refinement` on the grid tells how many).

    Returns
    -------
    OutcomeMap
    """
    (n1, v1), (n2, v2) = first, second
    runs = MapRuns(block, shape, n1, n2, k_peak=k_peak, duration=duration, restitution=restitution, dt=dt,
                   pulse_params=pulse_params, min_rotation=min_rotation)
    m = grid_map(runs, v1, v2, progress=progress)
    return refine_map(m, runs, tol=tol, progress=progress) if refine else m


def planned_refinement_runs(m: OutcomeMap, tol: float = TOLERANCE) -> int:
    """Runs that :func:`refine_map` will simulate on ``m`` (unless a probe finds a third category)."""
    if not refinable(m.first_values, m.second_values):
        return 0
    return plan_refinement(m.first_values, m.second_values, m.category, tol).runs


def staged_outcome_map(runs: MapRuns, first_values: ArrayLike, second_values: ArrayLike, *,
                       refine: bool = True, tol: float = TOLERANCE,
                       bars: Bars | None = None) -> OutcomeMap:
    """:func:`grid_map`, then :func:`refine_map`, each stage reporting to a progress bar of its own.

    ``bars(total, description)`` is entered once per stage -- ``"simulating"`` with the grid's
    runs, ``"refining boundaries"`` with the refinement's planned runs -- and yields the
    ``progress`` callable of that stage.
    """
    n = np.asarray(first_values).size * np.asarray(second_values).size
    if bars is None:
        m = grid_map(runs, first_values, second_values)
        return refine_map(m, runs, tol=tol) if refine else m
    with bars(int(n), "simulating") as step:
        m = grid_map(runs, first_values, second_values, progress=step)
    if not refine:
        return m
    planned = planned_refinement_runs(m, tol)
    with bars(planned, "refining boundaries") as step:
        return refine_map(m, runs, tol=tol, progress=_capped(step, planned))


def _capped(step: Progress, total: int) -> Progress:
    """``step``, never counting past ``total`` (a probe that finds a third category adds runs
    that the plan did not count)."""
    left = [total]

    def capped(n: int) -> None:
        k = min(n, left[0])
        left[0] -= k
        if k:
            step(k)

    return capped
