"""The lifetime sliding under each of many climates: the ESD with the climate's uncertainty and its band.

numpy.  The climates are the bootstrap replicates of a record's extreme-value fit
(:func:`regimemap.climate.life.replicate_climates`); each runs ``trials`` lifetimes
(:func:`regimemap.lifetime.lifetime_sliding`) on its own seed, child ``i`` of
``numpy.random.SeedSequence(seed).spawn(N)``, so the answer is the same with any ``jobs``,
``chunk`` or Dask scheduler.  The ESD with the climate's uncertainty is the mean of the
replicates' ESDs (the expectation over the climate's sampling distribution as well as over
the lifetimes); the band is their percentile interval.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from concurrent.futures import as_completed
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .chart import crossing_width
from .climate import Climate
from .model import Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, make_chunks, run_chunks, submit_all, worker_pool
from .simulate import lifetime_sliding

__all__ = ["ChartBand", "ClimateBand", "climate_band", "climate_band_chart"]


@dataclass(frozen=True)
class ClimateBand:
    """The ESD under each replicate climate.

    Attributes
    ----------
    esd : ndarray
        Each replicate's expected sliding distance [m].
    level : float
        The band's level (0.9).
    seed : int
        The root seed.
    trials : int
        Lifetimes per replicate.
    """

    esd: NDArray[np.float64] = field(repr=False)
    level: float
    seed: int
    trials: int

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


def climate_band(caisson: Caisson, model: LifetimeModel, climates: Sequence[Climate], trials: int,
                 seed: int, level: float = 0.9, *, progress: Callable[[int], None] | None = None,
                 **run: Any) -> ClimateBand:
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
    progress : callable, optional
        Called with the lifetimes finished.
    **run
        ``chunk``, ``jobs``, ``scheduler`` of :func:`lifetime_sliding`.

    Returns
    -------
    ClimateBand
    """
    if len(climates) < 2:
        raise ValueError(f"a climate band needs at least two replicate climates, got {len(climates)}")
    if not 0.0 < level < 1.0:
        raise ValueError(f"level must be in (0, 1), got {level!r}")
    children = np.random.SeedSequence(seed).spawn(len(climates))
    seeds = [int(s.generate_state(1, np.uint32)[0]) for s in children]
    esd = np.empty(len(climates))
    jobs = int(run.get("jobs", 1) or 1)
    chunk = int(run.get("chunk", DEFAULT_CHUNK))
    if jobs > 1 and run.get("scheduler") is None and len(climates) > 1:
        # one pool for all the replicates, each run whole in a worker (as with jobs = 1: its numbers
        # depend only on its seed)
        with worker_pool(min(jobs, len(climates))) as pool:
            futures = submit_all(pool, _one, ((caisson, model.with_(climate=c), trials, s, chunk)
                                              for c, s in zip(climates, seeds)))
            index = {f: i for i, f in enumerate(futures)}
            for future in as_completed(futures):
                esd[index[future]] = future.result()
                if progress is not None:
                    progress(trials)
    else:
        for i, (c, s) in enumerate(zip(climates, seeds)):
            esd[i] = lifetime_sliding(caisson, model.with_(climate=c), trials, s, progress=progress,
                                      **run).expected_sliding
    return ClimateBand(esd=esd, level=float(level), seed=int(seed), trials=int(trials))


def _one(caisson: Caisson, model: LifetimeModel, trials: int, seed: int, chunk: int) -> float:
    """One replicate's ESD, in this process (a worker's task)."""
    return lifetime_sliding(caisson, model, trials, seed, chunk=chunk).expected_sliding


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
    if len(climates) < 2:
        raise ValueError(f"a climate band needs at least two replicate climates, got {len(climates)}")
    if not 0.0 < level < 1.0:
        raise ValueError(f"level must be in (0, 1), got {level!r}")
    w = np.sort(np.asarray(widths, dtype=np.float64).ravel())
    children = np.random.SeedSequence(seed).spawn(len(climates))
    seeds = [int(s.generate_state(1, np.uint32)[0]) for s in children]
    esd = np.empty((len(climates), w.size))
    jobs = int(run.get("jobs", 1) or 1)
    chunk = int(run.get("chunk", DEFAULT_CHUNK))
    if jobs > 1 and run.get("scheduler") is None:
        with worker_pool(min(jobs, len(climates))) as pool:
            futures = submit_all(pool, _one_chart, ((caisson, model.with_(climate=c), w, trials, s, chunk)
                                                    for c, s in zip(climates, seeds)))
            index = {f: i for i, f in enumerate(futures)}
            for future in as_completed(futures):
                esd[index[future]] = future.result()
                if progress is not None:
                    progress(trials)
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
