"""``regimemap lifetime`` with ``[lifetime.record]`` and ``climate_replicates``: the ESD's climate band.

The record's bootstrap gives the replicate climates (:func:`regimemap.io.design_record.record_analysis`,
:func:`regimemap.climate.life.replicate_climates`); each runs the lifetimes
(:func:`regimemap.lifetime.replicates.climate_band`).  Both draw from children of the run's root
seed (``SeedSequence(seed).spawn(2)``: the bootstrap, then the lifetimes), so the same seed gives
the same band with any ``--jobs``, ``--chunk`` or scheduler.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, Any

import click
import numpy as np

from ._common import RunError

if TYPE_CHECKING:
    from ..io.design import LifetimeSpec
    from ..lifetime import Caisson, LifetimeModel
    from ..lifetime.chart import DesignChart
    from ..lifetime.replicates import ChartBand, ClimateBand

__all__ = ["BAND_LEVEL", "run_climate_band"]

#: Level of the ESD's climate band.
BAND_LEVEL = 0.9


def run_climate_band(spec: LifetimeSpec, caisson: Caisson, model: LifetimeModel, trials: int, seed: int,
                     run: dict[str, Any], quiet: bool, source: str,
                     chart: DesignChart | None = None) -> ClimateBand | ChartBand | None:
    """The band (of the ESD, or with ``chart`` of its widths), or None when the design file asks for none."""
    if spec.record is None or spec.climate_replicates < 2:
        return None
    from ..climate.life import replicate_climates
    from ..io.design_record import record_analysis
    from ..lifetime.replicates import climate_band, climate_band_chart
    from ._progress import progress_bar

    boot, life = (int(s.generate_state(1, np.uint32)[0]) for s in np.random.SeedSequence(seed).spawn(2))
    t0 = time.perf_counter()
    try:
        climates = replicate_climates(record_analysis(spec.record, spec.climate_replicates, boot))
        band: ClimateBand | ChartBand
        with progress_bar(trials * len(climates), "climate band", quiet, unit=" lifetimes") as step:
            if chart is None:
                band = climate_band(caisson, model, climates, trials, life, BAND_LEVEL, progress=step, **run)
            else:
                band = climate_band_chart(caisson, model, climates, chart.widths, trials, life, chart.target,
                                          BAND_LEVEL, progress=step, **run)
    except ValueError as exc:
        raise RunError(f"{source}: {exc}") from None
    if not quiet:
        click.echo(f"regimemap: climate band: {band.replicates} bootstrap climates x {trials} lifetimes "
                   f"in {time.perf_counter() - t0:.1f} s", err=True)
    return band
