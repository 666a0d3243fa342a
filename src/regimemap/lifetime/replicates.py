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
from numpy.typing import NDArray

from .climate import Climate
from .model import Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, submit_all, worker_pool
from .simulate import lifetime_sliding

__all__ = ["ClimateBand", "climate_band"]


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
