"""``regimemap lifetime``: the expected sliding distance of a caisson over its design life.

Parses the options, calls :func:`regimemap.lifetime.run.run_lifetime` -- or, with
``--width``, :func:`regimemap.lifetime.run.run_chart` -- and writes its record: the
report (text or JSON, :mod:`regimemap.lifetime.record`), the lifetimes or the chart's table
(:mod:`regimemap.lifetime.record_files`) and
the figure (:mod:`regimemap.lifetime.figures`), each file atomically.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..io.formats import record_formats
from ..lifetime.run_notes import output_refusal, run_notes
from ._check import check_option, exit_on_failure, refuse_notices
from ._inputs import DESIGN_FILE
from ._lifetime_options import chart_options, lifetime_options, report_options, run_options
from ._main import RunError, refusing
from ._plausible import STRICT_RECORD_HELP
from ._writing import (
    checked_format,
    distinct_files,
    echo_notes,
    echo_notices,
    output_path,
    print_report,
    write_files,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..lifetime.run import ChartRecord, LifetimeDesign, LifetimeRecord

__all__ = ["lifetime_cmd"]


@click.command("lifetime",
               short_help="Expected sliding distance of a caisson over its design life (Monte Carlo).")
@click.argument("design", type=DESIGN_FILE, metavar="DESIGN.toml")
@lifetime_options
@chart_options
@report_options
@run_options
@click.option("--strict", is_flag=True, help=STRICT_RECORD_HELP)
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
    failure_sliding is given; --check exits 1 when one fails.  The report
    ends with the requirements and the verdict.

    With a [lifetime.record] climate the lifetimes also run under
    climate_replicates replicate climates of the record's fit (default 50;
    0: the fitted climate alone, warned), and the requirements are judged
    including the climate's uncertainty: the ESD and each P(S > x) are the
    means over the replicates, printed with the ESD's 90 % climate band.

    With --width A:B:N it draws up a design chart instead: the ESD at N widths
    (the weight in proportion to the width), the narrowest width whose ESD is at
    most --target, bisected to --width-tolerance, with its 95 % Monte Carlo
    interval (a bootstrap of the lifetimes), and the width with Goda's sliding
    safety factor 1.2; the requirement is the design's width against it --
    with a record, against the width at the climate band's upper level (the
    95 % quantile of the replicates' ESDs), and -o chart.csv adds the band's
    columns.

    \b
    Examples:
      regimemap caisson --example > goda.toml
      regimemap lifetime goda.toml
      regimemap lifetime goda.toml --trials 20000 --seed 7 -o life.png -o life.csv
      regimemap lifetime goda.toml --width 10:25:16 --target 0.1 -o chart.svg
      regimemap lifetime goda.toml --json --scheduler tcp://127.0.0.1:8786
    """
    _check_usage(widths, target, tolerance, jobs, scheduler)
    _check_outputs(outputs, widths)
    inputs = _read_design(design, years, strict)
    record = _run(design, inputs, widths, target, tolerance, trials=trials, seed=seed, jobs=jobs, chunk=chunk,
                  scheduler=scheduler, quiet=quiet)
    refuse_notices(record.notices, "target-not-bracketed", "", "'--width'")
    if not quiet:
        echo_notes(run_notes(record))
    def figure() -> Figure:
        from ..lifetime.figures.record_figure import record_figure

        return record_figure(record, Path(design).stem)

    written = write_files(outputs, figure,
                          data_formats=record_formats("lifetimes"), write_data=record.write_data)
    print_report(as_json, record.report_text, lambda: record.report_json(written), written)
    exit_on_failure(record.result.checks, check)


def _run(design: str, inputs: LifetimeDesign, widths: list[float] | None, target: float | None,
         tolerance: float | None, *, trials: int | None, seed: int | None, jobs: int | None,
         chunk: int | None, scheduler: str | None, quiet: bool) -> LifetimeRecord | ChartRecord:
    """The workflow's run with a progress bar; a run that cannot be made is a :class:`RunError`."""
    from ..lifetime import ClusterUnavailable
    from ..lifetime.run import run_chart, run_lifetime
    from ._progress import progress_bars

    bars = progress_bars(quiet, " lifetimes")
    try:
        if widths is None:
            return run_lifetime(inputs, trials=trials, seed=seed, jobs=jobs, chunk=chunk, scheduler=scheduler,
                                progress=bars)
        return run_chart(inputs, widths, target=target, tolerance=tolerance, trials=trials, seed=seed,
                         jobs=jobs, chunk=chunk, scheduler=scheduler, progress=bars)
    except ClusterUnavailable as exc:
        raise RunError(str(exc)) from None
    except ValueError as exc:
        raise RunError(f"{design}: {exc}") from None


def _check_usage(widths: list[float] | None, target: float | None, tolerance: float | None,
                 jobs: int | None, scheduler: str | None) -> None:
    """The options that need ``--width`` or exclude each other."""
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


def _check_outputs(outputs: tuple[str, ...], widths: list[float] | None) -> None:
    """The ``-o`` files, checked before any work: distinct, of a known suffix, writable."""
    distinct_files(outputs, "'-o' / '--output'")
    for path in outputs:
        refusal = output_refusal(path, checked_format(path, "lifetime", "'--output'"), widths is not None)
        if refusal is not None:
            raise click.BadParameter(refusal, param_hint="'--output'")
        output_path(path, "--output")


def _read_design(design: str, years: int | None, strict: bool) -> LifetimeDesign:
    """The design file read for the workflow: a file it refuses, or (``--strict``) an implausible
    value, is a usage error naming it; the implausible values are warnings otherwise."""
    from ..caisson.file import DesignFileError
    from ..lifetime.run import RECORD_WARNINGS, read_lifetime_design

    with refusing("'DESIGN.toml'", DesignFileError):
        inputs = read_lifetime_design(design, years)
    if strict:
        refuse_notices(inputs.notices, "implausible-value", "--strict refuses implausible values",
                       "'DESIGN.toml'")
        refuse_notices(inputs.notices, RECORD_WARNINGS, "--strict refuses the record's warnings",
                       "'DESIGN.toml'")
    echo_notices(inputs.notices)
    return inputs
