"""The lifetime workflows: the expected sliding distance of a design, and its design chart.

:func:`run_lifetime` runs the lifetimes of a design file's caisson under its ``[lifetime]``
climate (Shimosako & Takahashi 1999) and judges its requirements; :func:`run_chart` runs the
same section at several widths and finds the width for a target ESD (with its Monte Carlo
interval) and Goda's deterministic width.  With ``[lifetime.record]`` both add the climate's
band -- the runs under ``climate_replicates`` replicate climates of the record's fit
(:data:`regimemap.lifetime.replicates.DEFAULT_REPLICATES` when the file gives none) -- and judge
the requirements on it: the ESD and exceedance probabilities including the climate's
uncertainty (the means over the replicates), the chart's width at the band's upper level.
Each returns one record (:class:`LifetimeRecord`, :class:`ChartRecord`) with the
inputs, the section and climate a designer checks, the warnings as notices and the results;
``regimemap lifetime`` is this call followed by writing the record.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from ..records.fields import Field, Record
from ..records.notices import Notice
from .finite import quiet_arithmetic, require_finite
from .results import STATISTICS
from .run_design import RECORD_WARNINGS, LifetimeDesign, read_lifetime_design

if TYPE_CHECKING:
    from ..caisson.file import Design
    from . import Caisson, DesignChart, LifetimeModel, LifetimeResult, Requirements
    from .file_record import RecordSpec
    from .replicates import ChartBand, ClimateBand

__all__ = ["BAND_LEVEL", "RECORD_WARNINGS", "ChartRecord", "LifetimeDesign", "LifetimeRecord", "Progress",
           "read_lifetime_design", "run_chart", "run_lifetime"]

#: Level of the ESD's climate band.
BAND_LEVEL = 0.9

#: A factory of progress bars: ``progress(total, what)`` is a context manager yielding
#: ``step(n)``, called with the lifetimes done since the last call.
Progress = Callable[[int, str], AbstractContextManager[Callable[[int], None]]]


def _no_step(n: int) -> None:
    """The ``step`` of no progress bar."""


@contextlib.contextmanager
def _no_bar(total: int, what: str) -> Iterator[Callable[[int], None]]:
    yield _no_step


def _section_fields() -> tuple[Field, ...]:
    return (Field("width", "b", "m", "the caisson's full width"),
            Field("buoyant_weight", "W'", "N/m", "buoyant weight at still water"),
            Field("friction", "mu", "", "friction between caisson and mound"),
            Field("H0_10", "H0'_10", "m", "the climate's 10-year wave"),
            Field("H0_50", "H0'_50", "m", "the climate's 50-year wave"),
            Field("design_H0", "H0' (design)", "m", "the design file's wave"),
            Field("trials", "trials", "", "lifetimes per run"),
            Field("used_seed", "seed", "", "the root seed of the run"))


@dataclass(frozen=True)
class _LifetimeRun(Record):
    """The inputs, the intermediate quantities and the run's facts of both lifetime records."""

    source: str | None
    caisson: Caisson
    model: LifetimeModel
    trials: int
    seed: int | None
    requirements: Requirements
    climate_as_written: str | None
    width: float
    buoyant_weight: float
    friction: float
    H0_10: float
    H0_50: float
    design_H0: float | None
    notices: tuple[Notice, ...]
    used_seed: int
    seconds: float
    processes: int
    scheduler: str | None
    band_seconds: float | None
    wave_record: RecordSpec | None


@dataclass(frozen=True)
class LifetimeRecord(_LifetimeRun):
    """The expected sliding distance of a design over its life (:func:`run_lifetime`).

    Attributes
    ----------
    source : str or None
        The design file.
    caisson, model : Caisson, LifetimeModel
        The section at its site; the climate and options.
    trials : int
        Lifetimes simulated.
    seed : int or None
        The root seed asked for (None: a fresh one, ``used_seed``).
    requirements : Requirements
        ESD <= target, the allowed exceedances, the failure's sliding.
    climate_as_written : str or None
        The climate as the design file wrote it.
    width, buoyant_weight, friction : float
        The section: ``b`` [m], ``W'`` [N/m], ``mu``.
    H0_10, H0_50 : float
        The climate's 10- and 50-year waves ``H0'`` [m].
    design_H0 : float or None
        The design file's wave ``H0'`` [m] (None when given as ``H1/3`` and ``Hmax``).
    notices : tuple of Notice
        The warnings (the file's implausible values).
    used_seed : int
        The run's root seed.
    seconds : float
        The run's wall time [s] (the band's apart).
    processes : int
        Processes that ran it (1 on a cluster).
    scheduler : str or None
        The Dask cluster's address.
    band_seconds : float or None
        The climate band's wall time [s]; None without a band.
    wave_record : RecordSpec or None
        The ``[lifetime.record]`` whose fit is the climate (None: a typed-in climate).
    result : LifetimeResult
        Every lifetime, its statistics, the checks and the failure.
    band : ClimateBand or None
        The ESD under the record's bootstrap climates.
    """

    CAPTION: ClassVar[str] = "Lifetime sliding"
    FIELDS: ClassVar[tuple[Field, ...]] = _section_fields() + tuple(
        Field(f"result.{s.key}", s.label, s.unit, s.description)
        for s in STATISTICS
        if not s.per_threshold and s.key not in ("failure", "trials", "seed", "width")) + (
        Field("band.expected_sliding", "ESD including the climate's uncertainty", "m",
              "the mean over the record's replicate climates (None: no record)"),
        Field("band.lower", "its 90 % climate band, lower", "m", "the replicates' 5 % percentile"),
        Field("band.upper", "its 90 % climate band, upper", "m", "the replicates' 95 % percentile"))

    result: LifetimeResult
    band: ClimateBand | None

    def report_text(self) -> str:
        """The report for people (:func:`regimemap.lifetime.record.format_lifetime`, the band's lines
        before the requirements and the verdict, which end it)."""
        from .record import format_lifetime

        return format_lifetime(self.result, self.model, source=self.source, written=self.climate_as_written,
                               band=self.band)

    def report_json(self, files: Sequence[str] = ()) -> dict[str, Any]:
        """The JSON-ready report (:func:`regimemap.lifetime.record.lifetime_json`, with ``climate_band``),
        with the ``files`` written before the ``checks`` and ``verdict`` that end it."""
        from .record import lifetime_json

        out = lifetime_json(self.result, self.model, source=self.source, written=self.climate_as_written,
                            band=self.band)
        return _files_first(out, files)

    def write_data(self, path: str | Path) -> None:
        """Write every lifetime to ``path`` (.csv or .npz, atomically)."""
        from .record_files import write_samples

        write_samples(self.result, path)


@dataclass(frozen=True)
class ChartRecord(_LifetimeRun):
    """ESD against width and the width for a target ESD (:func:`run_chart`).

    Attributes
    ----------
    source, caisson, model, trials, seed, requirements, climate_as_written, width, buoyant_weight, \
friction, H0_10, H0_50, design_H0, notices, used_seed, seconds, processes, scheduler, band_seconds, \
wave_record
        As :class:`LifetimeRecord`; ``width`` is the design's own, judged against the chart;
        ``notices`` also holds ``target-not-bracketed`` when the chart's widths do not bracket
        the target, or the band's upper curve does not (then the chart is not judged).
    widths : tuple of float
        The chart's widths [m].
    target, tolerance : float
        The tolerable ESD [m] and the bisection's tolerance [m].
    result : DesignChart
        The chart, the width for the target with its interval, Goda's width, the checks.
    band : ChartBand or None
        The chart under the record's bootstrap climates.
    """

    CAPTION: ClassVar[str] = "Design chart"
    FIELDS: ClassVar[tuple[Field, ...]] = _section_fields() + (
        Field("target", "target ESD", "m", "the tolerable expected sliding distance"),
        Field("result.width_for_target", "width for the target", "m", "None: no width of the chart"),
        Field("result.width_interval.lower", "its interval, lower", "m", "Monte Carlo"),
        Field("result.width_interval.upper", "its interval, upper", "m", "Monte Carlo"),
        Field("result.sf_width", "width for SF = 1.2", "m", "Goda's deterministic design"),
        Field("band.width_for_target", "width with the climate's band", "m", "its upper curve"))

    widths: tuple[float, ...]
    target: float
    tolerance: float
    result: DesignChart
    band: ChartBand | None

    def report_text(self) -> str:
        """The report for people (:func:`regimemap.lifetime.record.format_chart`, the band's lines before
        the requirement and the verdict, which end it)."""
        from .record import format_chart

        return format_chart(self.result, self.model, source=self.source, written=self.climate_as_written,
                            band=self.band)

    def report_json(self, files: Sequence[str] = ()) -> dict[str, Any]:
        """The JSON-ready report (:func:`regimemap.lifetime.record.chart_json`, with ``climate_band``),
        with the ``files`` written before the ``checks`` and ``verdict`` that end it."""
        from .record import chart_json

        out = chart_json(self.result, self.model, source=self.source, written=self.climate_as_written,
                         band=self.band)
        return _files_first(out, files)

    def write_data(self, path: str | Path) -> None:
        """Write the chart's table to ``path`` (.csv, atomically; with the band's columns)."""
        from .record_files import write_chart

        write_chart(self.result, path, band=self.band)


def _files_first(out: dict[str, Any], files: Sequence[str]) -> dict[str, Any]:
    """``out`` with ``files`` (when any) before its closing ``checks`` and ``verdict``."""
    if not files:
        return out
    tail = {k: out.pop(k) for k in ("checks", "verdict")}
    out["files"] = list(files)
    out.update(tail)
    return out


def _prepare(design: LifetimeDesign | Design | str | Path, years: int | None, trials: int | None,
             seed: int | None, jobs: int | None, chunk: int | None, scheduler: str | None
             ) -> tuple[LifetimeDesign, int, dict[str, Any], Requirements]:
    from . import Requirements, available_cores
    from .parallel import DEFAULT_CHUNK

    if scheduler is not None and jobs not in (None, 1):
        raise ValueError("jobs and scheduler exclude each other: the cluster's workers run the lifetimes")
    inputs = design if isinstance(design, LifetimeDesign) else read_lifetime_design(design, years)
    spec = inputs.spec
    n = spec.trials if trials is None else int(trials)
    workers = 1 if scheduler is not None else (available_cores() if jobs is None else int(jobs))
    run = dict(chunk=DEFAULT_CHUNK if chunk is None else int(chunk), jobs=workers, scheduler=scheduler)
    req = Requirements(target=spec.target, allowed=spec.allowed, failure_sliding=spec.failure_sliding)
    return inputs, n, run, req


def _common(inputs: LifetimeDesign, n: int, seed: int | None, req: Requirements, run: dict[str, Any],
            used: int, seconds: float, band_seconds: float | None, notices: tuple[Notice, ...]
            ) -> dict[str, Any]:
    """The fields both records share."""
    from .parallel import make_chunks

    c, m, d = inputs.caisson, inputs.model, inputs.design
    return dict(source=inputs.source, caisson=c, model=m, trials=n, seed=seed, requirements=req,
                climate_as_written=inputs.spec.climate_as_written(), width=float(c.width),
                buoyant_weight=float(c.section().buoyant_weight), friction=float(c.friction),
                H0_10=float(m.climate.return_value(10)), H0_50=float(m.climate.return_value(50)),
                design_H0=d.wave.H0, notices=inputs.notices + notices, used_seed=int(used),
                seconds=seconds, processes=min(run["jobs"], len(make_chunks(n, 0, run["chunk"]))),
                scheduler=run["scheduler"], band_seconds=band_seconds, wave_record=inputs.spec.record)


def _uncounted(inputs: LifetimeDesign) -> tuple[Notice, ...]:
    """The notice ``climate-uncertainty-not-counted`` of a record's climate run without replicates
    (``climate_replicates = 0``)."""
    spec = inputs.spec
    if spec.record is None or spec.climate_replicates >= 2:
        return ()
    return (Notice("climate-uncertainty-not-counted",
                   f"{inputs.source or inputs.design.source}: [lifetime] climate_replicates = 0: the "
                   "requirements are judged on the record's fitted climate alone, its uncertainty not "
                   "counted", quantity="climate_replicates", value=0),)


def _band(inputs: LifetimeDesign, n: int, used: int, run: dict[str, Any], progress: Progress,
          chart: DesignChart | None = None, thresholds: Sequence[float] = ()
          ) -> tuple[ClimateBand | ChartBand | None, float | None]:
    """The climate band (of the ESD, or of the chart's widths) and its wall time; None without a
    record (or with ``climate_replicates = 0``).  The replicate climates and the lifetimes draw from
    the children of the run's root seed (``SeedSequence(seed).spawn(2)``), so the band is the same
    with any jobs, chunk or scheduler; each replicate keeps ``P(S > x)`` at ``thresholds``."""
    spec = inputs.spec
    if spec.record is None or spec.climate_replicates < 2:
        return None, None
    from ..climate.life import replicate_climates
    from .file_record import record_analysis
    from .replicates import climate_band, climate_band_chart

    boot, life = (int(s.generate_state(1, np.uint32)[0]) for s in np.random.SeedSequence(used).spawn(2))
    t0 = time.perf_counter()
    climates = replicate_climates(record_analysis(spec.record, spec.climate_replicates, boot))
    band: ClimateBand | ChartBand
    with progress(n * len(climates), "climate band") as step:
        if chart is None:
            band = climate_band(inputs.caisson, inputs.model, climates, n, life, BAND_LEVEL,
                                thresholds=thresholds, progress=step, **run)
        else:
            band = climate_band_chart(inputs.caisson, inputs.model, climates, chart.widths, n, life,
                                      chart.target, BAND_LEVEL, progress=step, **run)
    return band, time.perf_counter() - t0


def run_lifetime(design: LifetimeDesign | Design | str | Path, *, trials: int | None = None,
                 seed: int | None = None, years: int | None = None, jobs: int | None = 1,
                 chunk: int | None = None, scheduler: str | None = None,
                 progress: Progress | None = None) -> LifetimeRecord:
    """The expected sliding distance of a design over its life, judged against its requirements.

    Parameters
    ----------
    design : LifetimeDesign, Design, str or Path
        The design file (its caisson and ``[lifetime]`` table), parsed or read
        (:func:`read_lifetime_design`).
    trials, seed, years : int, optional
        Instead of the file's ``trials``, ``seed`` (None in both: a fresh seed) and ``years``.
    jobs : int or None, optional
        Worker processes (None: one per core; 1: this process).
    chunk : int, optional
        Lifetimes per unit of work (the numbers do not depend on it).
    scheduler : str, optional
        A Dask cluster's address (not with ``jobs`` > 1).
    progress : Progress, optional
        A factory of progress bars (``progress(total, what)``).

    Returns
    -------
    LifetimeRecord

    Raises
    ------
    regimemap.caisson.file.DesignFileError
        The design file cannot be read or has no ``[lifetime]`` table.
    regimemap.lifetime.ClusterUnavailable
        The scheduler cannot be reached.
    ValueError
        The run cannot be made (the message says why).
    """
    from . import lifetime_sliding
    from .replicates import ClimateBand
    from .requirements import band_thresholds, judge_lifetime

    inputs, n, run, req = _prepare(design, years, trials, seed, jobs, chunk, scheduler)
    bars: Progress = _no_bar if progress is None else progress
    root = inputs.spec.seed if seed is None else seed
    t0 = time.perf_counter()
    with bars(n, "lifetimes") as step, quiet_arithmetic():
        result = lifetime_sliding(inputs.caisson, inputs.model, n, root, progress=step, **run)
    require_finite("the lifetime sliding", result.sliding)
    require_finite("the expected sliding by year", result.by_year)
    seconds = time.perf_counter() - t0
    band, band_seconds = _band(inputs, n, result.seed, run, bars,
                               thresholds=tuple(result.thresholds) + band_thresholds(req))
    assert band is None or isinstance(band, ClimateBand)
    if band is not None:
        require_finite("the ESD under the replicate climates", band.esd)
    result = judge_lifetime(result, req, band)
    return LifetimeRecord(**_common(inputs, n, root, req, run, result.seed, seconds, band_seconds,
                                    _uncounted(inputs)),
                          result=result, band=band)


def run_chart(design: LifetimeDesign | Design | str | Path, widths: Any, *, target: float | None = None,
              tolerance: float | None = None, trials: int | None = None, seed: int | None = None,
              years: int | None = None, jobs: int | None = 1, chunk: int | None = None,
              scheduler: str | None = None, progress: Progress | None = None) -> ChartRecord:
    """ESD against width for a design's section, the width for a target ESD and Goda's width.

    The chart runs the same lifetimes at every width (the weight in proportion to the width),
    bisects the narrowest width whose ESD is at most ``target`` to ``tolerance`` with its 95 %
    Monte Carlo interval, and judges the design's own width against it.

    Parameters
    ----------
    design : LifetimeDesign, Design, str or Path
        As :func:`run_lifetime`.
    widths : sequence of float
        Full widths [m], increasing, at least two.
    target : float, optional
        The tolerable ESD [m] (default: the file's ``target``).
    tolerance : float, optional
        The bisection's tolerance [m] (default
        :data:`regimemap.lifetime.chart.DEFAULT_TOLERANCE`).
    trials, seed, years, jobs, chunk, scheduler, progress
        As :func:`run_lifetime`.

    Returns
    -------
    ChartRecord
        With the notice ``target-not-bracketed`` (and the chart not judged) when the ESD at
        both ends of ``widths`` is on the same side of the target -- or, with a climate band, the
        band's upper curve is (:func:`regimemap.lifetime.replicates.band_bracket_problem`).

    Raises
    ------
    As :func:`run_lifetime`.
    """
    from . import design_chart
    from .chart import DEFAULT_TOLERANCE, bisection_steps
    from .replicates import ChartBand, band_bracket_problem
    from .requirements import judge_chart

    inputs, n, run, req = _prepare(design, years, trials, seed, jobs, chunk, scheduler)
    bars: Progress = _no_bar if progress is None else progress
    root = inputs.spec.seed if seed is None else seed
    ws = [float(w) for w in widths]
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    goal = req.target if target is None else float(target)
    t0 = time.perf_counter()
    # the chart, then at most one bisection run per halving of a chart step to the tolerance
    with bars(n * (1 + bisection_steps(ws[1] - ws[0], tol)), "design chart") as step, quiet_arithmetic():
        chart = design_chart(inputs.caisson, inputs.model, ws, n, root, progress=step, target=goal,
                             sf_impulsive=inputs.design.caisson.impulsive, tolerance=tol,
                             failure_sliding=req.failure_sliding, **run)
    require_finite("the design chart's ESD", chart.expected_sliding)
    seconds = time.perf_counter() - t0
    problem = chart.bracket_problem()
    band, band_seconds = (None, None) if problem else _band(inputs, n, chart.seed, run, bars, chart)
    assert band is None or isinstance(band, ChartBand)
    if problem is None and band is not None:
        problem = band_bracket_problem(band)
    notices: tuple[Notice, ...] = _uncounted(inputs)
    if problem is None:
        chart = judge_chart(chart, inputs.caisson.width, band)
    else:
        notices += (Notice("target-not-bracketed", problem, quantity="widths", value=goal),)
    return ChartRecord(**_common(inputs, n, root, req, run, chart.seed, seconds, band_seconds, notices),
                       widths=tuple(ws), target=goal, tolerance=tol, result=chart, band=band)
