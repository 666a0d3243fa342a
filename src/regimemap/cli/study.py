"""``regimemap study``: a whole breakwater, section by section, under climate scenarios; resumable.

Reads the study file (:func:`regimemap.io.study.read_study`), runs
:func:`regimemap.workflows.study.run_study` -- its tasks in this process, in local
processes or on Dask, each stored as it finishes -- and writes the table
(:mod:`regimemap.io.study_table`, :mod:`regimemap.io.study_netcdf`) or the figures
(:mod:`regimemap.drawing.study`).
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..io.formats import FIGURE_FORMATS
from ._common import ParamType, RunError, echo_notices, import_matplotlib, output_path, report_written
from ._inputs import DESIGN_FILE
from ._writing import writing

if TYPE_CHECKING:
    from ..io.study import Study
    from ..workflows.study import StudyRecord

__all__ = ["study_cmd"]

TABLE_FORMATS = ("csv", "nc")
FIGURE_KINDS = ("chainage", "years", "width")


def _suffix(path: str) -> str:
    return Path(path).suffix.lower().lstrip(".")


class _Scheduler(ParamType):
    """``local``, or a Dask scheduler's address (:func:`regimemap.io.lifetime_options.check_scheduler`)."""

    name = "text"

    def convert(self, value: object, param: click.Parameter | None, ctx: click.Context | None) -> str:
        from ..io.lifetime_options import check_scheduler

        text = str(value).strip()
        if text == "local":
            return text
        try:
            return check_scheduler(text)
        except ValueError as exc:
            self.fail(f"{exc} (or 'local', a Dask LocalCluster)", param, ctx)


def _check_call(study: str | None, example: bool, outputs: tuple[str, ...], scheduler: str | None,
                jobs: int | None) -> None:
    """The options that go together; the outputs' suffixes and folders."""
    ctx = click.get_current_context()
    if example and study is not None:
        raise click.UsageError("--example prints the example study and takes no STUDY.toml", ctx=ctx)
    if not example and study is None:
        raise click.UsageError("missing STUDY.toml (a study file; `regimemap study --example` prints one)",
                               ctx=ctx)
    if scheduler is not None and scheduler != "local" and jobs is not None:
        raise click.UsageError("--jobs and --scheduler ADDRESS exclude each other: the cluster's workers "
                               "run the tasks (with --scheduler local, --jobs is its workers)", ctx=ctx)
    for path in outputs:
        if _suffix(path) not in TABLE_FORMATS + FIGURE_FORMATS:
            raise click.BadParameter(f"{path!r}: the table is written as .csv or .nc and the figure as .png, "
                                     ".svg or .pdf (from the file suffix)", param_hint="'--output'")
        output_path(path, "--output")
    if any(_suffix(path) == "nc" for path in outputs):  # before a long run, not after it
        from ..io.study_netcdf import check_netcdf

        try:
            check_netcdf()
        except ImportError as exc:
            raise RunError(str(exc)) from None


@contextlib.contextmanager
def _progress(quiet: bool) -> Iterator[Callable[[int, int], None]]:
    """``progress(done, total)`` of :func:`run_study` on the bar of :func:`._progress.progress_bar`
    (opened at the first call, when the total is known)."""
    from ._progress import progress_bar

    with contextlib.ExitStack() as stack:
        bar: list[Callable[[int], None]] = []
        seen = [0]

        def step(done: int, total: int) -> None:
            if not bar:
                bar.append(stack.enter_context(progress_bar(total, "study", quiet, unit=" tasks")))
            bar[0](done - seen[0])
            seen[0] = done

        yield step


def _read(study: str, section: str | None) -> Study:
    """The study file (refused: a usage error, exit 2) and ``--section`` among its sections."""
    from ..io.study import StudyFileError, read_study

    try:
        parsed = read_study(study)
    except StudyFileError as exc:
        raise click.UsageError(str(exc), ctx=click.get_current_context()) from None
    names = [s.name for s in parsed.sections]
    if section is not None and section not in names:
        raise click.BadParameter(f"{section!r} is not a section of the study; accepted: {', '.join(names)}",
                                 param_hint="'--section'")
    return parsed


def _run(study: Study, jobs: int | None, scheduler: str | None, resume: bool, store: str | None,
         quiet: bool) -> StudyRecord:
    """Run the study; a refused store is a usage error (exit 2), a missing cluster a failure."""
    from ..io.study_store import StudyStoreError
    from ..lifetime import ClusterUnavailable, available_cores
    from ..workflows.study import run_study

    source = Path(study.source)
    folder = Path(store) if store is not None else source.parent / f"{source.stem}.store"
    workers = jobs if jobs is not None else available_cores()
    try:
        with _progress(quiet) as step:
            return run_study(study, jobs=workers, scheduler=scheduler, store=folder, resume=resume,
                             progress=step)
    except StudyStoreError as exc:
        raise click.UsageError(str(exc), ctx=click.get_current_context()) from None
    except ClusterUnavailable as exc:
        raise RunError(str(exc)) from None


def _write(record: StudyRecord, outputs: tuple[str, ...], figure: str, section: str | None) -> None:
    """Each output file: the table (.csv, .nc) or the figure (.png, .svg, .pdf, drawn once)."""
    fig = None
    for path in outputs:
        with writing(path):
            if _suffix(path) == "csv":
                from ..io.study_table import write_study_csv

                write_study_csv(path, record)
            elif _suffix(path) == "nc":
                from ..io.study_netcdf import write_study_netcdf

                write_study_netcdf(path, record)
            else:
                if fig is None:
                    import_matplotlib()
                    from ..drawing.study.figures import study_figure

                    fig = study_figure(record, kind=figure, section=section)
                from ..drawing.save import save_figure

                save_figure(fig, path)
        report_written(path)


@click.command("study", short_help="A breakwater's sections under climate scenarios (resumable, parallel).")
@click.argument("study", type=DESIGN_FILE, metavar="STUDY.toml", required=False)
@click.option("--example", is_flag=True, help="Print the commented example study (three sections, two "
              "scenarios) and exit.")
@click.option("--jobs", "-j", type=click.IntRange(1, 256), default=None, metavar="N",
              help="Worker processes on this machine (default: one per core; 1: this process); with "
                   "--scheduler local, the LocalCluster's workers.")
@click.option("--scheduler", type=_Scheduler(), default=None, metavar="local|ADDRESS",
              help="Run the tasks on Dask: 'local' starts a LocalCluster, else a scheduler's address "
                   "(tcp://host:8786); needs the 'cluster' extra.")
@click.option("--resume", is_flag=True, help="Run only the tasks missing from the store (the same numbers "
              "as an uninterrupted run); refused when the study file has changed.")
@click.option("--store", default=None, metavar="DIR",
              help="The results store, one file per finished task (default: STUDY.store beside the "
                   "study file).")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object (the rows) instead of text.")
@click.option("-o", "--output", "outputs", type=click.Path(dir_okay=False), metavar="FILE", multiple=True,
              help="Output file (repeatable), written atomically: .csv or .nc the table, .png, .svg or "
                   ".pdf the figure (--figure).")
@click.option("--figure", type=click.Choice(FIGURE_KINDS), default="chainage", show_default=True,
              help="The figure: ESD along the chainage, expected sliding by service year (of --section), "
                   "or the required width along the chainage.")
@click.option("--section", default=None, metavar="NAME", help="The section of --figure years (default: "
              "the first).")
@click.option("--quiet", "-q", is_flag=True, help="No progress bar.")
def study_cmd(study: str | None, example: bool, jobs: int | None, scheduler: str | None, resume: bool,
              store: str | None, as_json: bool, outputs: tuple[str, ...], figure: str, section: str | None,
              quiet: bool) -> None:
    """A whole breakwater: every section of STUDY.toml under every climate scenario.

    A study file holds a base design (the tables of a design file inline, or
    base = "design.toml"), [[section]] tables (name, chainage, the design keys
    they change, the widths or a target ESD) and [[scenario]] tables (sea-level
    rise, wave-height and storm-rate factors by service year). Every section x
    scenario (x bootstrap climate of a wave record) is a task on the section's
    own random numbers, the same for every scenario; each finished task is kept
    in the store, so an interrupted run is finished by --resume, to the same
    numbers. Prints one line per section x scenario x width: the expected
    sliding distance (ESD), P(S > 0.1 m), P(S > 0.3 m), the first service year
    the expected sliding passes 0.1 m and 0.3 m, and the width for a target.

    \b
    Examples:
      regimemap study --example > breakwater.toml
      regimemap study breakwater.toml --jobs 2 -o table.csv
      regimemap study breakwater.toml --resume --json
      regimemap study breakwater.toml --scheduler local -o esd.svg
    """
    from ..io.study_table import study_json, study_lines

    _check_call(study, example, outputs, scheduler, jobs)
    if example:
        from ..io.study_example import example_study_text

        click.echo(example_study_text(), nl=False)
        return
    assert study is not None
    record = _run(_read(study, section), jobs, scheduler, resume, store, quiet)
    echo_notices(record.notices)
    _write(record, outputs, figure, section)
    if as_json:
        click.echo(json.dumps(study_json(record), indent=1))
    elif not outputs:
        click.echo("\n".join(study_lines(record)))
