"""The expected sliding distance of one caisson: :func:`lifetime_sliding`.

numpy only (Dask only when a scheduler is named).
"""

from __future__ import annotations

from collections.abc import Callable

from .model import Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, make_chunks, root_seed, run_chunks
from .results import LifetimeResult

__all__ = ["lifetime_sliding"]


def lifetime_sliding(caisson: Caisson, model: LifetimeModel, trials: int = 5000, seed: int | None = None,
                     *, chunk: int = DEFAULT_CHUNK, jobs: int = 1, scheduler: str | None = None,
                     progress: Callable[[int], None] | None = None) -> LifetimeResult:
    """Monte Carlo of the sliding of a caisson over its design life (Shimosako & Takahashi 1999).

    Parameters
    ----------
    caisson : Caisson
        The section at its site.
    model : LifetimeModel
        Climate, design life and every modelling option.
    trials : int, optional
        Lifetimes to simulate (5000).
    seed : int, optional
        Root seed (None: fresh entropy, reported in the result).
    chunk : int, optional
        Lifetimes per unit of work (rounded up to whole blocks of 100); the
        result does not depend on it.
    jobs : int, optional
        Local worker processes.
    scheduler : str, optional
        Address of a Dask scheduler to run the chunks on.
    progress : callable, optional
        Called with the number of lifetimes finished, chunk by chunk.

    Returns
    -------
    LifetimeResult

    Examples
    --------
    >>> from regimemap.lifetime import Caisson, Climate, LifetimeModel
    >>> goda = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1,
    ...                crest=3.4, friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)
    >>> model = LifetimeModel(Climate.from_return_values(5.0, 6.3))
    >>> r = lifetime_sliding(goda, model, trials=200, seed=1)
    >>> r.trials, r.seed
    (200, 1)
    """
    if model.trend is not None:
        model.trend.check_site(caisson)
    seed_ = root_seed(seed)
    chunks = make_chunks(trials, seed_, chunk)
    out = run_chunks((caisson,), model, chunks, jobs=jobs, scheduler=scheduler, progress=progress)
    return LifetimeResult(sliding=out.sliding[0], max_storm=out.max_storm[0], storms=out.storms,
                          seed=seed_, years=model.years, thresholds=model.thresholds,
                          width=caisson.width, sliding_waves=out.sliding_waves, impulsive=model.impulsive,
                          by_year=out.years.mean()[0], by_year_error=out.years.std_error()[0])
