"""The lifetime sliding under each of many climates: the ESD with the climate's uncertainty and its band.

numpy.  The climates are the replicates of a record's extreme-value fit
(:func:`regimemap.climate.life.replicate_climates`); each runs ``trials`` lifetimes
(:func:`regimemap.lifetime.lifetime_sliding`) on its own seed, child ``i`` of
``numpy.random.SeedSequence(seed).spawn(N)``, so the answer is the same with any ``jobs``,
``chunk`` or Dask scheduler.  The ESD with the climate's uncertainty is the mean of the
replicates' ESDs (the expectation over the climate's sampling distribution as well as over
the lifetimes); the band is their percentile interval.  Each replicate also keeps, from the
same lifetimes (no second run), its ``P(S > x)`` at the requirements' slides and on a fixed
grid of slides (:data:`CURVE_X`); pooled over the replicates -- their mean, the law of total
probability over equally likely climates -- they are the exceedance probabilities with the
climate's uncertainty, and their percentiles the exceedance curve's band.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from concurrent.futures import as_completed
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .chart import crossing_width, target_bracket_problem
from .climate import Climate
from .model import Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, make_chunks, run_chunks, submit_all, worker_pool
from .results import Failure, LifetimeResult
from .simulate import lifetime_sliding

__all__ = ["CURVE_X", "DEFAULT_REPLICATES", "ChartBand", "ClimateBand", "band_bracket_problem",
           "climate_band", "climate_band_chart"]

#: Replicate climates of a record when the design file gives no ``climate_replicates``.  The ESD
#: including the climate's uncertainty is their mean: its Monte Carlo error is the replicates'
#: spread over sqrt(N), for a ten-year record at 44007 (coefficient of variation about 0.8 between
#: the replicates' ESDs) about 12 % of the ESD with 50, and the cost is N times the lifetimes of
#: the fitted climate alone.
DEFAULT_REPLICATES = 50

#: The slides [m] at which each replicate's exceedance curve ``P(S > x)`` is kept for the band of
#: the exceedance figure: 20 a decade from 0.1 mm to 10 km.
CURVE_X: NDArray[np.float64] = np.logspace(-4.0, 4.0, 161)


@dataclass(frozen=True)
class ClimateBand:
    """The lifetimes under each replicate climate: their ESDs and exceedance probabilities.

    Attributes
    ----------
    esd : ndarray, shape (replicates,)
        Each replicate's expected sliding distance [m].
    level : float
        The band's level (0.9).
    seed : int
        The root seed.
    trials : int
        Lifetimes per replicate.
    thresholds : tuple of float
        The slides ``x`` [m] whose ``P(S > x)`` each replicate kept (:attr:`exceed`).
    exceed : ndarray, shape (replicates, thresholds)
        Each replicate's ``P(S > x)`` at :attr:`thresholds`.
    curve : ndarray, shape (replicates, CURVE_X)
        Each replicate's ``P(S > x)`` at :data:`CURVE_X`.
    """

    esd: NDArray[np.float64] = field(repr=False)
    level: float
    seed: int
    trials: int
    thresholds: tuple[float, ...] = ()
    exceed: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 0)), repr=False)
    curve: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, CURVE_X.size)), repr=False)

    @property
    def replicates(self) -> int:
        """Climates run."""
        return int(self.esd.size)

    @property
    def expected_sliding(self) -> float:
        """The ESD with the climate's uncertainty: the mean over the replicates [m]."""
        return float(self.esd.mean())

    @property
    def std_error(self) -> float:
        """Standard error of :attr:`expected_sliding` (replicates' spread / sqrt(N)) [m]."""
        return float(self.esd.std(ddof=1) / math.sqrt(self.esd.size)) if self.esd.size > 1 else math.nan

    @property
    def lower(self) -> float:
        """Lower end of the band [m]."""
        return float(np.quantile(self.esd, 0.5 * (1.0 - self.level)))

    @property
    def upper(self) -> float:
        """Upper end of the band [m]."""
        return float(np.quantile(self.esd, 0.5 * (1.0 + self.level)))

    def _column(self, x: float) -> NDArray[np.float64]:
        for j, t in enumerate(self.thresholds):
            if t == float(x):
                return np.asarray(self.exceed[:, j], dtype=np.float64)
        kept = ", ".join(f"{t:g}" for t in self.thresholds) or "none"
        raise KeyError(f"the band kept P(S > x) at x = {kept} m, not at {x:g} m")

    def exceedance(self, x: float) -> float:
        """``P(S > x)`` with the climate's uncertainty: the mean of the replicates' [-].

        Raises KeyError when ``x`` is not one of :attr:`thresholds`.
        """
        return float(self._column(x).mean())

    def exceedance_error(self, x: float) -> float:
        """Standard error of :meth:`exceedance` (the replicates' spread / sqrt(N))."""
        col = self._column(x)
        return float(col.std(ddof=1) / math.sqrt(col.size)) if col.size > 1 else math.nan

    def failure(self, limit: float) -> Failure:
        """The probability of sliding farther than ``limit`` [m] with the climate's uncertainty:
        the replicates' mean, with its standard error."""
        return Failure(float(limit), self.exceedance(limit), self.exceedance_error(limit))

    def curve_band(self) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                                  NDArray[np.float64]]:
        """``(x, lower, mean, upper)``: the exceedance curve ``P(S > x)`` at :data:`CURVE_X` -- its
        band's ends (the ``(1 -+ level)/2`` quantiles over the replicates) and the pooled mean."""
        lo, hi = np.quantile(self.curve, [0.5 * (1.0 - self.level), 0.5 * (1.0 + self.level)], axis=0)
        return (CURVE_X.copy(), np.asarray(lo, dtype=np.float64), np.asarray(self.curve.mean(axis=0),
                dtype=np.float64), np.asarray(hi, dtype=np.float64))


def _check_band(climates: Sequence[Climate], level: float) -> None:
    """A band's replicate climates (at least two) and level (in (0, 1)), else a ValueError."""
    if len(climates) < 2:
        raise ValueError(f"a climate band needs at least two replicate climates, got {len(climates)}")
    if not 0.0 < level < 1.0:
        raise ValueError(f"level must be in (0, 1), got {level!r}")


def _child_seeds(seed: int, n: int) -> list[int]:
    """The seed of each of ``n`` replicates: of child ``i`` of ``SeedSequence(seed).spawn(n)``."""
    return [int(s.generate_state(1, np.uint32)[0]) for s in np.random.SeedSequence(seed).spawn(n)]


def _pooled(jobs: int, task: Callable[..., NDArray[np.float64]], arguments: Sequence[tuple[Any, ...]],
            out: NDArray[np.float64], trials: int, progress: Callable[[int], None] | None) -> None:
    """``task(*arguments[i])`` into ``out[i]`` for each replicate ``i``, in a pool of up to ``jobs``
    workers (one replicate each); ``progress`` counts a replicate's ``trials`` as it finishes."""
    with worker_pool(min(jobs, len(arguments))) as pool:
        futures = submit_all(pool, task, arguments)
        index = {f: i for i, f in enumerate(futures)}
        for future in as_completed(futures):
            out[index[future]] = future.result()
            if progress is not None:
                progress(trials)


def _stats(result: LifetimeResult, thresholds: Sequence[float]) -> NDArray[np.float64]:
    """A replicate's numbers from its lifetimes: ``[ESD, P(S > x) at thresholds, P(S > x) at
    CURVE_X]``."""
    s = np.sort(result.sliding)
    at = np.asarray(list(thresholds) + CURVE_X.tolist())
    over = (s.size - np.searchsorted(s, at, side="right")) / s.size  # exactly mean(sliding > x)
    return np.concatenate([[result.expected_sliding], over])


def climate_band(caisson: Caisson, model: LifetimeModel, climates: Sequence[Climate], trials: int,
                 seed: int, level: float = 0.9, *, thresholds: Sequence[float] = (),
                 progress: Callable[[int], None] | None = None, **run: Any) -> ClimateBand:
    """Run ``trials`` lifetimes under each climate (``model`` with its climate replaced).

    Parameters
    ----------
    caisson : Caisson
    model : LifetimeModel
        Every option but the climate.
    climates : sequence of Climate
        The replicate climates (at least two).
    trials : int
        Lifetimes per climate.
    seed : int
        Root seed: climate ``i`` runs on ``SeedSequence(seed).spawn(N)[i]``.
    level : float
        The band's level, in (0, 1).
    thresholds : sequence of float, optional
        Slides [m] whose ``P(S > x)`` each replicate keeps (the requirements' ``allowed`` and
        ``failure_sliding``).
    progress : callable, optional
        Called with the lifetimes finished.
    **run
        ``chunk``, ``jobs``, ``scheduler`` of :func:`lifetime_sliding`.

    Returns
    -------
    ClimateBand
    """
    _check_band(climates, level)
    xs = tuple(sorted({float(x) for x in thresholds}))
    seeds = _child_seeds(seed, len(climates))
    stats = np.empty((len(climates), 1 + len(xs) + CURVE_X.size))
    jobs = int(run.get("jobs", 1) or 1)
    chunk = int(run.get("chunk", DEFAULT_CHUNK))
    if jobs > 1 and run.get("scheduler") is None:
        # one pool for all the replicates, each run whole in a worker (as with jobs = 1: its numbers
        # depend only on its seed)
        _pooled(jobs, _one, [(caisson, model.with_(climate=c), trials, s, chunk, xs)
                             for c, s in zip(climates, seeds)], stats, trials, progress)
    else:
        for i, (c, s) in enumerate(zip(climates, seeds)):
            stats[i] = _stats(lifetime_sliding(caisson, model.with_(climate=c), trials, s, progress=progress,
                                               **run), xs)
    return ClimateBand(esd=stats[:, 0].copy(), level=float(level), seed=int(seed), trials=int(trials),
                       thresholds=xs, exceed=stats[:, 1:1 + len(xs)].copy(),
                       curve=stats[:, 1 + len(xs):].copy())


def _one(caisson: Caisson, model: LifetimeModel, trials: int, seed: int, chunk: int,
         thresholds: Sequence[float] = ()) -> NDArray[np.float64]:
    """One replicate's numbers (:func:`_stats`), in this process (a worker's task)."""
    return _stats(lifetime_sliding(caisson, model, trials, seed, chunk=chunk), thresholds)


@dataclass(frozen=True)
class ChartBand:
    """The ESD of each chart width under each replicate climate, and the width for the target at
    the band's upper level.

    Attributes
    ----------
    widths : ndarray
        The chart's widths [m], increasing.
    esd : ndarray
        ESD [m], shape ``(replicates, widths)``: row ``i`` under climate ``i``, every width on
        the same random numbers (as :func:`regimemap.lifetime.design_chart`).
    level : float
        The band's level (0.9): its upper curve is the ``(1 + level)/2`` quantile over the climates.
    target : float
        The tolerable ESD [m].
    seed : int
        The root seed.
    trials : int
        Lifetimes per climate and width.
    """

    widths: NDArray[np.float64] = field(repr=False)
    esd: NDArray[np.float64] = field(repr=False)
    level: float
    target: float
    seed: int
    trials: int

    @property
    def replicates(self) -> int:
        """Climates run."""
        return int(self.esd.shape[0])

    @property
    def upper(self) -> NDArray[np.float64]:
        """The band's upper curve: the ``(1 + level)/2`` quantile of the ESD at each width [m]."""
        return np.asarray(np.quantile(self.esd, 0.5 * (1.0 + self.level), axis=0), dtype=np.float64)

    @property
    def lower(self) -> NDArray[np.float64]:
        """The band's lower curve [m]."""
        return np.asarray(np.quantile(self.esd, 0.5 * (1.0 - self.level), axis=0), dtype=np.float64)

    @property
    def width_for_target(self) -> float | None:
        """The narrowest width whose ESD at the band's upper level meets the target [m]: where the
        upper curve falls to ``target``, interpolated in log ESD between the chart's widths
        (:func:`regimemap.lifetime.chart.crossing_width`); None when no width meets it."""
        upper = self.upper
        if not np.any(upper <= self.target):
            return None
        return crossing_width(self.widths, upper, self.target)


def band_bracket_problem(band: ChartBand) -> str | None:
    """Why the chart's widths do not bracket the target at the band's upper level (its upper curve
    at both ends); None when they do."""
    return target_bracket_problem(band.widths, band.upper, band.target,
                                  f"the upper end of the {100 * band.level:g} % climate band")


def climate_band_chart(caisson: Caisson, model: LifetimeModel, climates: Sequence[Climate],
                       widths: ArrayLike, trials: int, seed: int, target: float,
                       level: float = 0.9, *, progress: Callable[[int], None] | None = None,
                       **run: Any) -> ChartBand:
    """The design chart's ESD under each replicate climate: the width for ``target`` at the band's
    upper level.

    Climate ``i`` runs ``trials`` lifetimes at every width on ``SeedSequence(seed).spawn(N)[i]``
    (as :func:`climate_band`); ``run``: ``chunk``, ``jobs`` (one climate per worker) or
    ``scheduler`` (each climate's chunks on the cluster).  ``progress`` counts lifetimes.
    """
    _check_band(climates, level)
    w = np.sort(np.asarray(widths, dtype=np.float64).ravel())
    seeds = _child_seeds(seed, len(climates))
    esd = np.empty((len(climates), w.size))
    jobs = int(run.get("jobs", 1) or 1)
    chunk = int(run.get("chunk", DEFAULT_CHUNK))
    if jobs > 1 and run.get("scheduler") is None:
        _pooled(jobs, _one_chart, [(caisson, model.with_(climate=c), w, trials, s, chunk)
                                   for c, s in zip(climates, seeds)], esd, trials, progress)
    else:
        scheduler = run.get("scheduler")
        for i, (c, s) in enumerate(zip(climates, seeds)):
            esd[i] = _one_chart(caisson, model.with_(climate=c), w, trials, s, chunk, scheduler)
            if progress is not None:
                progress(trials)
    return ChartBand(widths=w, esd=esd, level=float(level), target=float(target), seed=int(seed),
                     trials=int(trials))


def _one_chart(caisson: Caisson, model: LifetimeModel, widths: NDArray[np.float64], trials: int, seed: int,
               chunk: int, scheduler: str | None = None) -> NDArray[np.float64]:
    """One climate's ESD at every width, on the same random numbers (a worker's task)."""
    caissons = tuple(caisson.with_width(float(x)) for x in widths)
    out = run_chunks(caissons, model, make_chunks(trials, seed, chunk), scheduler=scheduler)
    return np.asarray(out.sliding.mean(axis=1), dtype=np.float64)
