"""``regimemap study``: a whole breakwater, section by section, under climate scenarios; resumable.

Reads the study file (:func:`regimemap.study.file.read_study`), runs
:func:`regimemap.study.run.run_study` -- its tasks in this process, in local
processes or on Dask, each stored as it finishes -- and writes the table
(:mod:`regimemap.study.record_table`, :mod:`regimemap.study.record_netcdf`) or the figures
(:mod:`regimemap.study.figures`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..io.formats import FIGURES, record_formats, suffix_of
from ._common import Checked, jobs_option, json_option, outputs_option, quiet_option
from ._inputs import DESIGN_FILE
from ._main import RunError
from ._writing import checked_output, distinct_files, echo_notices, output_dir, print_report, write_files

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..study.file import Study
    from ..study.run import StudyRecord

__all__ = ["study_cmd"]

FIGURE_KINDS = ("chainage", "years", "width")


def _scheduler(text: str) -> str:
    """``local``, or a Dask scheduler's address (:func:`regimemap.lifetime.file_options.check_scheduler`)."""
    from ..lifetime.file_options import check_scheduler

    if text.strip() == "local":
        return "local"
    try:
        return check_scheduler(text.strip())
    except ValueError as exc:
        raise ValueError(f"{exc} (or 'local', a Dask LocalCluster)") from None


#: The message when Dask's distributed is missing (found before anything is made).
NO_DASK = "--scheduler needs Dask's distributed package: pip install 'regimemap[cluster]'"


def _missing(module: str) -> bool:
    """Whether ``module`` cannot be imported (not installed, or blocked in ``sys.modules``)."""
    import importlib.util

    try:
        return importlib.util.find_spec(module) is None
    except (ImportError, ValueError):
        return True


def _store_folder(study: str, store: str | None) -> Path:
    """The results store's folder: ``--store``, else ``STUDY.store`` beside the study file."""
    source = Path(study)
    return Path(store) if store is not None else source.parent / f"{source.stem}.store"


def _check_store(study: str, store: str | None, resume: bool, overwrite: bool) -> None:
    """The store's folder checked before any work, as ``-o``'s are (a usage error naming
    ``--store``): a missing one must have an existing parent that accepts new files (it is made
    by the run, not here); an existing one must accept new files (not with ``--resume``: a
    finished store is only read), and with ``--overwrite`` so must its parent (the new run is
    stored beside it)."""
    folder = _store_folder(study, store)
    try:
        if not folder.is_dir():
            output_dir(folder, "--store", later=True)
            return
        if not resume:
            output_dir(folder, "--store")
        if overwrite:
            output_dir(folder.parent if str(folder.parent) else Path("."), "--store")
    except click.BadParameter as exc:
        if store is not None:
            raise
        raise click.BadParameter(f"{exc.message} (the default store, {str(folder)!r}: give --store DIR)",
                                 param_hint="'--store'") from None


def _check_call(study: str | None, example: bool, outputs: tuple[str, ...], scheduler: str | None,
                jobs: int | None, resume: bool = False, overwrite: bool = False,
                store: str | None = None) -> None:
    """The options that go together; the outputs' suffixes and folders, the store's folder; the
    extras they need."""
    ctx = click.get_current_context()
    if example and study is not None:
        raise click.UsageError("--example prints the example study and takes no STUDY.toml", ctx=ctx)
    if not example and study is None:
        raise click.UsageError("missing STUDY.toml (a study file; `regimemap study --example` prints one)",
                               ctx=ctx)
    if scheduler is not None and scheduler != "local" and jobs is not None:
        raise click.UsageError("--jobs and --scheduler ADDRESS exclude each other: the cluster's workers "
                               "run the tasks (with --scheduler local, --jobs is its workers)", ctx=ctx)
    if resume and overwrite:
        raise click.UsageError("--resume and --overwrite exclude each other: --resume finishes the "
                               "store's run, --overwrite replaces the store with a new run", ctx=ctx)
    distinct_files(outputs, "'-o' / '--output'")
    for path in outputs:
        checked_output(path, "study")
    if study is not None:
        _check_store(study, store, resume, overwrite)
    # the extras, before the store or any file is made and before a long run
    if scheduler is not None and _missing("distributed"):
        raise click.BadParameter(NO_DASK, param_hint="'--scheduler'")
    if any(suffix_of(path) == "nc" for path in outputs) and _missing("xarray"):
        from ..study.record_netcdf import NO_XARRAY

        bad = next(path for path in outputs if suffix_of(path) == "nc")
        raise click.BadParameter(f"{bad!r}: {NO_XARRAY} (or write the table as .csv)",
                                 param_hint="'--output'")


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
    from ..study.file import StudyFileError, read_study

    try:
        parsed = read_study(study)
    except StudyFileError as exc:
        raise click.UsageError(str(exc), ctx=click.get_current_context()) from None
    names = [s.name for s in parsed.sections]
    if section is not None and section not in names:
        raise click.BadParameter(f"{section!r} is not a section of the study; accepted: {', '.join(names)}",
                                 param_hint="'--section'")
    return parsed


def _run(study: Study, jobs: int | None, scheduler: str | None, resume: bool, overwrite: bool,
         store: str | None, quiet: bool) -> StudyRecord:
    """Run the study; a refused store is a usage error (exit 2), a missing cluster a failure."""
    from ..lifetime import ClusterUnavailable, available_cores
    from ..study.record_store import StudyStoreError
    from ..study.run import run_study

    folder = _store_folder(study.source, store)
    workers = jobs if jobs is not None else available_cores()
    try:
        with _progress(quiet) as step:
            return run_study(study, jobs=workers, scheduler=scheduler, store=folder, resume=resume,
                             overwrite=overwrite, progress=step)
    except StudyStoreError as exc:
        raise click.UsageError(str(exc), ctx=click.get_current_context()) from None
    except ClusterUnavailable as exc:
        raise RunError(str(exc)) from None


def _write(record: StudyRecord, outputs: tuple[str, ...], figure: str, section: str | None) -> list[str]:
    """Each output file: the table (.csv, .nc) or the figure (.png, .svg, .pdf, drawn once); the files
    written, in order."""
    def table(path: str) -> None:
        from ..study.record_netcdf import write_study_netcdf
        from ..study.record_table import write_study_csv

        (write_study_csv if suffix_of(path) == "csv" else write_study_netcdf)(path, record)

    def draw() -> Figure:
        from ..study.figures import study_figure

        return study_figure(record, kind=figure, section=section)

    return write_files(outputs, draw,
                       data_formats=record_formats("study table"), write_data=table)


@click.command("study", short_help="A breakwater's sections under climate scenarios (resumable, parallel).")
@click.argument("study", type=DESIGN_FILE, metavar="STUDY.toml", required=False)
@click.option("--example", is_flag=True, help="Print the commented example study (three sections, two "
              "scenarios) and exit.")
@jobs_option("Worker processes on this machine (default: one per core; 1: this process); with --scheduler "
             "local, the LocalCluster's workers.")
@click.option("--scheduler", type=Checked("text", _scheduler), default=None, metavar="local|ADDRESS",
              help="Run the tasks on Dask: 'local' starts a LocalCluster, else a scheduler's address "
                   "(tcp://host:8786); needs the 'cluster' extra.")
@click.option("--resume", is_flag=True, help="Run only the tasks missing from the store (the same numbers "
              "as an uninterrupted run); refused when the study file has changed.")
@click.option("--overwrite", is_flag=True, help="Run the study again in place of its store (or of another "
              "study's): the old store is replaced only when every task of the new run is stored; not "
              "with --resume.")
@click.option("--store", default=None, metavar="DIR",
              help="The results store, one file per finished task (default: STUDY.store beside the "
                   "study file).")
@json_option("Print one JSON object (the rows; with --check, the requirements) instead of text.")
@outputs_option(f"Output file (repeatable), written atomically: .csv or .nc the table, {FIGURES} the "
                "figure (--figure).")
@click.option("--figure", type=click.Choice(FIGURE_KINDS), default="chainage", show_default=True,
              help="The figure: ESD along the chainage, expected sliding by service year (of --section), "
                   "or the required width along the chainage.")
@click.option("--section", default=None, metavar="NAME", help="The section of --figure years (default: "
              "the first).")
@quiet_option("No progress bar; with -o, no table either (the files hold it).")
@click.option("--check", is_flag=True, help="Print one requirement line per section x scenario (PASS or "
              "FAIL: the section's [lifetime] target ESD, or its width against the width for its target) "
              "and exit with status 1 when any fails (the files are written first).")
def study_cmd(study: str | None, example: bool, jobs: int | None, scheduler: str | None, resume: bool,
              overwrite: bool, store: str | None, as_json: bool, outputs: tuple[str, ...], figure: str,
              section: str | None, quiet: bool, check: bool) -> None:
    """A whole breakwater: every section of STUDY.toml under every climate scenario.

    A study file holds a base design (the tables of a design file inline, or
    base = "design.toml"), [[section]] tables (name, chainage, the design keys
    they change, the widths or a target ESD) and [[scenario]] tables (sea-level
    rise, wave-height and storm-rate factors by service year). Every scenario's
    sea level is checked against every section in every service year before
    any task runs (a crest under water is refused). Every section x scenario
    (x bootstrap climate of a wave record) is a task on the section's own
    random numbers, the same for every scenario; each finished task is kept in
    the store, so an interrupted run is finished by --resume, to the same
    numbers, and --overwrite runs it again. Prints one line per section x
    scenario x width (also with -o, unless --quiet): the expected sliding
    distance (ESD), P(S > 0.1 m), P(S > 0.3 m), the first service year the
    expected sliding passes 0.1 m and 0.3 m, and the width for a target; with
    --check, one requirement line per section x scenario.

    \b
    Examples:
      regimemap study --example > breakwater.toml
      regimemap study breakwater.toml --jobs 2 -o table.csv
      regimemap study breakwater.toml --resume --json
      regimemap study breakwater.toml --overwrite --check
      regimemap study breakwater.toml --scheduler local -o esd.svg
    """
    from ..study.run import study_checks
    from ..study.run_report import study_report_json, study_report_text

    _check_call(study, example, outputs, scheduler, jobs, resume, overwrite, store)
    if example:
        from ..study.file_example import example_study_text

        click.echo(example_study_text(), nl=False)
        return
    assert study is not None
    parsed = _read(study, section)
    echo_notices(parsed.notices)  # before the run: the file's warnings
    record = _run(parsed, jobs, scheduler, resume, overwrite, store, quiet)
    echo_notices([n for n in record.notices if n not in parsed.notices])
    checks = study_checks(parsed, record) if check else None
    written = _write(record, outputs, figure, section)
    print_report(as_json, lambda: study_report_text(record, checks, table=not (outputs and quiet)),
                 lambda: study_report_json(record, checks, written), written, indent=1)
    if checks is not None and not all(c.passed for c in checks):
        raise click.exceptions.Exit(1)
