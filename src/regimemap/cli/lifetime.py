"""``regimemap lifetime``: the expected sliding distance of a caisson over its design life.

Reads the design file (its ``[lifetime]`` table), runs
:func:`regimemap.lifetime.lifetime_sliding` -- or, with ``--width``,
:func:`regimemap.lifetime.design_chart` -- in this process, in local worker
processes or on a Dask cluster, and writes through :mod:`regimemap.io.lifetime`
and :func:`regimemap.drawing.save.save_figure`.  The checks of the values live in
:mod:`regimemap.io.design` and :mod:`regimemap.io.lifetime`.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ._check import check_option, exit_on_failure
from ._common import ParamType, RunError, import_matplotlib, output_path, report_written
from ._inputs import DESIGN_FILE
from ._plausible import STRICT_HELP, check_plausible
from ._writing import writing

if TYPE_CHECKING:
    from ..io.design import Design, LifetimeSpec
    from ..lifetime import Caisson, DesignChart, LifetimeModel, LifetimeResult
    from ..lifetime.replicates import ChartBand, ClimateBand

__all__ = ["lifetime_cmd"]

FIGURE_FORMATS = ("png", "svg", "pdf")
SAMPLE_FORMATS = ("csv", "npz")


class _Checked(ParamType):
    """A value checked by a function of :mod:`regimemap.io` (its ValueError is the message)."""

    def __init__(self, name: str, check: Callable[[str], Any]):
        self.name = name  # "integer", "number", "text": the kinds the tests know
        self._check = check

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return value
        try:
            return self._check(value)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


def _file_key(key: str) -> Callable[[str], Any]:
    def check(text: str) -> Any:
        from ..io.design import check_lifetime_option

        return check_lifetime_option(key, text)

    return check


def _widths(text: str) -> list[float]:
    from ..io.lifetime_options import parse_widths

    return parse_widths(text)


def _target(text: str) -> float:
    from ..io.lifetime_options import check_target

    return check_target(text)


def _tolerance(text: str) -> float:
    from ..io.lifetime_options import check_tolerance

    return check_tolerance(text)


def _chunk(text: str) -> int:
    from ..io.lifetime_options import check_chunk

    return check_chunk(text)


def _scheduler(text: str) -> str:
    from ..io.lifetime_options import check_scheduler

    return check_scheduler(text)


def _suffix(path: str) -> str:
    return Path(path).suffix.lower().lstrip(".")


@click.command("lifetime",
               short_help="Expected sliding distance of a caisson over its design life (Monte Carlo).")
@click.argument("design", type=DESIGN_FILE, metavar="DESIGN.toml")
@click.option("--trials", type=_Checked("integer", _file_key("trials")), default=None, metavar="N",
              help="Lifetimes to simulate, 1 to 10000000 (default: [lifetime] trials, or 5000).")
@click.option("--seed", type=_Checked("integer", _file_key("seed")), default=None, metavar="S",
              help="Root seed, a whole number >= 0: the same seed gives the same numbers, bit for "
                   "bit on one machine, to 1e-12 on another CPU (default: [lifetime] seed, or a "
                   "fresh one, reported).")
@click.option("--years", type=_Checked("integer", _file_key("years")), default=None, metavar="Y",
              help="Design life in years, 1 to 1000 (default: [lifetime] years, or 50).")
@click.option("--width", "widths", type=_Checked("text", _widths), default=None, metavar="A:B:N",
              help="A design chart instead: the expected sliding distance at N widths from A to B "
                   "metres (N >= 2), all on the same random numbers, with the width for --target and "
                   "the width of Goda's deterministic design (SF = 1.2 under the 50-year wave).")
@click.option("--target", type=_Checked("number", _target), default=None, metavar="ESD",
              help="With --width: the tolerable expected sliding distance in metres, > 0 "
                   "(default: [lifetime] target, or 0.1, Goda & Takagi 2000).")
@click.option("--width-tolerance", "tolerance", type=_Checked("number", _tolerance), default=None,
              metavar="M", help="With --width: bisect the width for --target to M metres, 0.001 to 10 "
                                "(default 0.05); its Monte Carlo interval is printed beside it.")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object instead of text.")
@click.option("-o", "--output", "outputs", type=click.Path(dir_okay=False), metavar="FILE", multiple=True,
              help="Output file (repeatable), written atomically: .png, .svg or .pdf draws the "
                   "figure (with --width: the design chart), .csv or .npz writes every lifetime "
                   "(with --width: .csv writes the chart's table).")
@click.option("--jobs", "-j", type=click.IntRange(1, 256), default=None, metavar="N",
              help="Worker processes on this machine (default: one per core; 1: this process).")
@click.option("--chunk", type=_Checked("integer", _chunk), default=None, metavar="N",
              help="Lifetimes per unit of work (default 500); the numbers do not depend on it.")
@click.option("--scheduler", type=_Checked("text", _scheduler), default=None, metavar="ADDRESS",
              help="Run on an existing Dask cluster, e.g. tcp://host:8786 (needs the 'cluster' extra: "
                   "pip install 'regimemap[cluster]'); the numbers are those of this machine, bit for bit "
                   "when the workers' CPUs have its feature level (else to 1e-12).")
@click.option("--quiet", "-q", is_flag=True, help="No progress bar and no notes on standard error.")
@click.option("--strict", is_flag=True, help=STRICT_HELP)
@check_option
def lifetime_cmd(design: str, trials: int | None, seed: int | None, years: int | None,
                 widths: list[float] | None, target: float | None, tolerance: float | None, as_json: bool,
                 outputs: tuple[str, ...], jobs: int | None, chunk: int | None, scheduler: str | None,
                 quiet: bool, strict: bool, check: bool) -> None:
    """How far a caisson slides over its design life: the expected sliding distance (ESD).

    Reads DESIGN.toml -- the caisson and its site as for `regimemap caisson`, and
    a [lifetime] table with the wave climate and the options (`regimemap
    caisson --example` prints a commented one) -- and simulates TRIALS lifetimes
    (Shimosako & Takahashi 1999): storms from the climate, Rayleigh waves in each
    storm, the slide of every wave in closed form, with the uncertainty factors
    of the wave height, its transformation, the wave force and the friction
    (docs/lifetime.md).

    Prints the ESD with its standard error, the median and quantiles of the
    lifetime sliding, the probabilities that it exceeds each threshold (and that
    one storm alone does), and the share of lifetimes that never slide.  The
    options override the file's [lifetime] values.  The same seed gives the same
    numbers with any --jobs, --chunk or --scheduler: bit for bit on one machine,
    to a relative 1e-12 on another CPU.  Then one line per requirement of
    [lifetime] (ESD <= target; each allowed exceedance probability), PASS or
    FAIL, and the probability of sliding off the mound when [lifetime]
    failure_sliding is given; --check exits 1 when one fails.

    With --width A:B:N it draws up a design chart instead: the ESD at N widths
    (the weight in proportion to the width), the narrowest width whose ESD is at
    most --target, bisected to --width-tolerance, with its 95 % Monte Carlo
    interval (a bootstrap of the lifetimes), and the width with Goda's sliding
    safety factor 1.2; the requirement is the design's width against it.

    \b
    Examples:
      regimemap caisson --example > goda.toml
      regimemap lifetime goda.toml
      regimemap lifetime goda.toml --trials 20000 --seed 7 -o life.png -o life.csv
      regimemap lifetime goda.toml --width 10:25:16 --target 0.1 -o chart.svg
      regimemap lifetime goda.toml --json --scheduler tcp://127.0.0.1:8786
    """
    ctx = click.get_current_context()
    if target is not None and widths is None:
        raise click.UsageError("--target is the tolerable ESD of a design chart: give it with "
                               "--width A:B:N", ctx=ctx)
    if tolerance is not None and widths is None:
        raise click.UsageError("--width-tolerance is the tolerance of a design chart's width: give it "
                               "with --width A:B:N", ctx=ctx)
    if scheduler is not None and jobs is not None:
        raise click.UsageError("--jobs and --scheduler exclude each other: the cluster's workers run "
                               "the lifetimes", ctx=ctx)
    _check_outputs(outputs, widths)
    d, spec, model, caisson = _read_design(design, years, strict)
    n = spec.trials if trials is None else trials
    root = spec.seed if seed is None else seed

    # -- the run ------------------------------------------------------------------------------
    from ..lifetime import (
        ClusterUnavailable,
        LifetimeResult,
        available_cores,
        design_chart,
        lifetime_sliding,
    )
    from ..lifetime.chart import DEFAULT_TOLERANCE, bisection_steps
    from ..lifetime.parallel import DEFAULT_CHUNK
    from ..lifetime.requirements import Requirements, judge_chart, judge_lifetime
    from ._progress import progress_bar

    req = Requirements(target=spec.target, allowed=spec.allowed, failure_sliding=spec.failure_sliding)
    tol = DEFAULT_TOLERANCE if tolerance is None else tolerance

    workers = 1 if scheduler is not None else (jobs if jobs is not None else available_cores())
    run: dict[str, Any] = dict(chunk=DEFAULT_CHUNK if chunk is None else chunk, jobs=workers,
                               scheduler=scheduler)
    t0 = time.perf_counter()
    result: LifetimeResult | DesignChart
    try:
        if widths is None:
            with progress_bar(n, "lifetimes", quiet, unit=" lifetimes") as step:
                result = lifetime_sliding(caisson, model, n, root, progress=step, **run)
            result = judge_lifetime(result, req)
        else:
            # the chart, then at most one bisection run per halving of a chart step to the tolerance
            steps = bisection_steps(widths[1] - widths[0], tol)
            with progress_bar(n * (1 + steps), "design chart", quiet, unit=" lifetimes") as step:
                result = design_chart(caisson, model, widths, n, root, progress=step,
                                      target=req.target if target is None else target,
                                      sf_impulsive=d.caisson.impulsive, tolerance=tol,
                                      failure_sliding=req.failure_sliding, **run)
            problem = result.bracket_problem()
            if problem is not None:
                raise click.BadParameter(problem, param_hint="'--width'")
            result = judge_chart(result, caisson.width)
    except ClusterUnavailable as exc:
        raise RunError(str(exc)) from None
    except ValueError as exc:
        raise RunError(f"{design}: {exc}") from None
    seconds = time.perf_counter() - t0
    if not quiet:
        _note_run(n, model.years, widths, seconds, workers, run["chunk"], scheduler, root, result.seed)
    from ..lifetime.replicates import ClimateBand
    from ._climate_band import run_climate_band

    band = run_climate_band(spec, caisson, model, n, result.seed, run, quiet, design,
                            None if isinstance(result, LifetimeResult) else result)

    # -- the files, then the report ----------------------------------------------------------
    from ..io import lifetime as io_lifetime

    given = spec.climate_as_written()
    written = _write_outputs(outputs, result, Path(design).stem, band)
    if as_json:
        obj = (io_lifetime.lifetime_json(result, model, source=design, written=given)
               if isinstance(result, LifetimeResult)
               else io_lifetime.chart_json(result, model, source=design, written=given))
        if outputs:
            obj["files"] = written
        if band is not None:
            from ..io.climate import chart_band_json, climate_band_json

            obj["climate_band"] = (climate_band_json(band) if isinstance(band, ClimateBand)
                                   else chart_band_json(band))
        click.echo(json.dumps(obj, indent=2, allow_nan=False))
    else:
        click.echo(io_lifetime.format_lifetime(result, model, source=design, written=given)
                   if isinstance(result, LifetimeResult)
                   else io_lifetime.format_chart(result, model, source=design, written=given))
        if band is not None:
            from ..io.climate import chart_band_lines, climate_band_lines

            click.echo("\n".join(climate_band_lines(band) if isinstance(band, ClimateBand)
                                 else chart_band_lines(band)))
        for path in written:
            report_written(path)
    exit_on_failure(result.checks, check)


def _check_outputs(outputs: tuple[str, ...], widths: list[float] | None) -> None:
    """The ``-o`` files, checked before any work: distinct, of a known suffix, writable."""
    if len({str(Path(p).resolve()) for p in outputs}) < len(outputs):
        raise click.BadParameter("the same file is given twice", param_hint="'-o' / '--output'")
    for path in outputs:
        kind = _suffix(path)
        if kind == "npz" and widths is not None:
            raise click.BadParameter(f"{path!r}: the lifetimes (.npz) are written for one width, not "
                                     "with --width (a chart is written as .csv, its table, or as .png, "
                                     ".svg or .pdf)", param_hint="'--output'")
        if kind not in FIGURE_FORMATS + SAMPLE_FORMATS:
            got = f".{kind}" if kind else "no suffix"
            raise click.BadParameter(f"{path!r} has {got}; the figure is written as .png, .svg or .pdf "
                                     "and the lifetimes as .csv or .npz (from the file suffix)",
                                     param_hint="'--output'")
        output_path(path, "--output")


def _read_design(design: str, years: int | None, strict: bool
                 ) -> tuple[Design, LifetimeSpec, LifetimeModel, Caisson]:
    """The design file: its ``[lifetime]`` spec, the model over ``years`` and the caisson;
    the plausibility of the values checked (``--strict``)."""
    from ..io.design import DesignFileError, read_design

    try:
        d = read_design(design)
        spec = d.lifetime_spec()
        model = d.lifetime_model(years=years)
        caisson = d.lifetime_caisson()
    except DesignFileError as exc:
        raise click.BadParameter(str(exc), param_hint="'DESIGN.toml'") from None
    try:
        analysis = d.analyse()
    except ValueError:
        analysis = None
    check_plausible(d, analysis, strict, design)
    return d, spec, model, caisson


def _note_run(n: int, years: int, widths: list[float] | None, seconds: float, workers: int,
              chunk: int, scheduler: str | None, root: int | None, used: int) -> None:
    """The note on standard error: how many lifetimes, how long, where; the seed if none was given."""
    from ..lifetime.parallel import make_chunks

    processes = min(workers, len(make_chunks(n, 0, chunk)))
    where = (f"on the Dask cluster at {scheduler}" if scheduler is not None else
             "in this process" if processes == 1 else f"on {processes} processes")
    lives = f"{n} lifetime{'' if n == 1 else 's'}"
    what = lives if widths is None else f"{len(widths)} widths x {lives}"
    click.echo(f"regimemap: {what} of {years} years in {seconds:.1f} s {where}", err=True)
    if root is None:
        click.echo(f"regimemap: no seed given: this run's seed is {used} (--seed {used} repeats it)",
                   err=True)


def _write_outputs(outputs: tuple[str, ...], result: LifetimeResult | DesignChart,
                   title: str, band: ClimateBand | ChartBand | None = None) -> list[str]:
    """Write the lifetimes (.csv, .npz), the chart's table (.csv) or the figure (.png, .svg, .pdf,
    drawn once) to each file; ``title`` names the section (the design file's stem)."""
    from ..io import lifetime as io_lifetime
    from ..lifetime import LifetimeResult
    from ..lifetime.replicates import ChartBand

    written: list[str] = []
    fig = None
    for path in outputs:
        with writing(path):
            if _suffix(path) in SAMPLE_FORMATS and not isinstance(result, LifetimeResult):
                io_lifetime.write_chart(result, path)  # .csv: _check_outputs refuses .npz
            elif _suffix(path) in SAMPLE_FORMATS:
                assert isinstance(result, LifetimeResult)
                io_lifetime.write_samples(result, path)
            else:
                if fig is None:
                    import_matplotlib()
                    from ..drawing.lifetime.chart import chart_figure, chart_title
                    from ..drawing.lifetime.exceedance import lifetime_figure, lifetime_title

                    fig = (lifetime_figure(result, lifetime_title(title, result))
                           if isinstance(result, LifetimeResult)
                           else chart_figure(result, chart_title(title, result),
                                             band=band if isinstance(band, ChartBand) else None))
                from ..drawing.save import save_figure

                save_figure(fig, path)
        written.append(path)
    return written
