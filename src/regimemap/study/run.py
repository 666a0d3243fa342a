"""``run_study``: a whole breakwater -- its sections under climate scenarios -- as one record.

Every section x scenario x climate replicate is a task
(:mod:`regimemap.study.run_tasks`); replicate 0 is the design's climate, 1..N
the bootstrap climates of its wave record (``[lifetime] climate_replicates``).
The tasks run in this process, in ``jobs`` local processes
(:func:`regimemap.lifetime.parallel.worker_pool`) or on Dask (``scheduler``:
``"local"`` starts a LocalCluster, else a scheduler's address), submitted lazily,
a few per worker at a time, so memory is bounded by the tasks in flight.  Each
finished task is stored at once (:class:`regimemap.study.record_store.StudyStore`) and
the record is built from the stored results only, in the study's order: the same
seed gives the same bytes whatever ran the tasks, and however often the run was
interrupted and resumed.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, wait
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..lifetime.finite import require_finite
from ..records.checks import Check
from ..records.notices import Notice
from .record import StudyCheck, StudyRecord, StudyRow
from .run_tasks import LIMITS, StudyTask, run_task, task_seed

if TYPE_CHECKING:
    from regimemap.study.file import SectionSpec, Study
    from regimemap.study.record_store import StudyStore

__all__ = ["BAND_LEVEL", "StudyCheck", "StudyRecord", "StudyRow", "run_study", "study_checks", "study_tasks"]

#: Level of the climate band (the replicates' percentile interval), as ``regimemap lifetime``'s.
BAND_LEVEL = 0.9
#: Tasks in flight per worker.
_WINDOW = 2


def study_tasks(study: Study, climates: list[Any] | None = None) -> Iterator[tuple[str, StudyTask]]:
    """The study's tasks in order, each with its store name, built one at a time.

    ``climates`` holds the bootstrap climates (replicates 1..N), None without them.
    """
    from regimemap.study.record_store import task_name

    for i, section in enumerate(study.sections):
        caisson = section.caisson()
        for j, scenario in enumerate(study.scenarios):
            model = study.model(section, scenario)
            for r, climate in enumerate([None, *(climates or [])]):
                kind = "widths" if section.target is None else ("target" if r == 0 else "chart")
                task = StudyTask(kind=kind, caisson=caisson,
                                 model=model if climate is None else model.with_(climate=climate),
                                 widths=section.widths, trials=study.trials, seed=task_seed(study.seed, i, r),
                                 target=section.target, tolerance=section.tolerance,
                                 sf_impulsive=section.design.caisson.impulsive,
                                 label=_label(study, section, scenario.name, r))
                yield task_name(i, j, r), task


def _label(study: Study, section: SectionSpec, scenario: str, replicate: int) -> str:
    """A task in words, for its messages: the study file, the section, the scenario, the climate."""
    climate = "" if replicate == 0 else f", bootstrap climate {replicate}"
    return f"{study.source}: section {section.name!r}, scenario {scenario!r}{climate}"


def _climates(study: Study) -> list[Any] | None:
    """The bootstrap climates of the study's record (its ``climate_replicates``), None without."""
    if study.replicates < 2:
        return None
    from regimemap.climate.life import replicate_climates
    from regimemap.lifetime.file_record import record_analysis

    record = study.sections[0].design.lifetime_spec().record
    assert record is not None
    boot = int(np.random.SeedSequence(study.seed, spawn_key=(2**32 - 2,)).generate_state(1, np.uint32)[0])
    return list(replicate_climates(record_analysis(record, study.replicates, boot)))


def _serial(todo: Iterator[tuple[str, StudyTask]]) -> Iterator[tuple[str, dict[str, Any]]]:
    for name, task in todo:
        yield name, run_task(task)


def _processes(todo: Iterator[tuple[str, StudyTask]], jobs: int) -> Iterator[tuple[str, dict[str, Any]]]:
    from regimemap.lifetime.parallel import submit_all, worker_pool

    with worker_pool(jobs) as pool:
        flying: dict[Future[dict[str, Any]], str] = {}
        for name, task in todo:
            flying[submit_all(pool, run_task, [(task,)])[0]] = name
            while len(flying) >= _WINDOW * jobs:
                done, _ = wait(flying, return_when=FIRST_COMPLETED)
                for f in done:
                    yield flying.pop(f), f.result()
        while flying:
            done, _ = wait(flying, return_when=FIRST_COMPLETED)
            for f in done:
                yield flying.pop(f), f.result()


def _dask(todo: Iterator[tuple[str, StudyTask]], scheduler: str,
          jobs: int) -> Iterator[tuple[str, dict[str, Any]]]:
    from regimemap.lifetime.parallel import ClusterUnavailable

    try:
        from distributed import Client, as_completed
    except ImportError:
        raise ClusterUnavailable(
            "--scheduler needs Dask's distributed package: pip install 'regimemap[cluster]'") from None
    from regimemap.workers import local_cluster

    with contextlib.ExitStack() as stack:
        if scheduler == "local":  # its processes leave Ctrl-C to this one, and die with it
            cluster = stack.enter_context(local_cluster(jobs))
            client = stack.enter_context(Client(cluster))
        else:
            try:
                client = stack.enter_context(Client(scheduler, timeout="10s"))
            except Exception as exc:  # noqa: BLE001 - any failure to connect
                raise ClusterUnavailable(f"cannot reach the Dask scheduler at {scheduler!r}: "
                                         f"{str(exc) or type(exc).__name__}") from None
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        names: dict[Any, str] = {}
        queue = as_completed()
        try:
            for name, task in todo:
                f = client.submit(run_task, task, pure=False)
                names[f] = name
                queue.add(f)
                while queue.count() >= _WINDOW * workers:
                    done = next(queue)
                    yield names.pop(done), done.result()
            for done in queue:
                yield names.pop(done), done.result()
        except BaseException:
            with contextlib.suppress(Exception):
                client.cancel(list(names))
            raise


def run_study(study: Study | str | Path, *, jobs: int = 1, scheduler: str | None = None,
              store: str | Path | None = None, resume: bool = False, overwrite: bool = False,
              progress: Callable[[int, int], None] | None = None) -> StudyRecord:
    """Run a study: every section under every scenario (and climate replicate), stored as it goes.

    Parameters
    ----------
    study : Study, str or Path
        A parsed study (:func:`regimemap.study.file.read_study`) or its file.
    jobs : int, optional
        Local worker processes (1: this process); with ``scheduler="local"``
        the LocalCluster's workers.
    scheduler : str, optional
        ``"local"`` (a Dask LocalCluster) or a Dask scheduler's address.
    store : str or Path, optional
        The results store's folder (:class:`regimemap.study.record_store.StudyStore`);
        None: none (the results are kept in memory).
    resume : bool, optional
        Run only the tasks missing from ``store``.
    overwrite : bool, optional
        Replace the study store at ``store`` (this study's or another's): the run is stored
        in a new folder beside it, which replaces the old one only once every task is
        stored (:func:`regimemap.study.record_store.replacing_store`); an interrupted or failed
        run leaves the old store as it was.  Not with ``resume``.
    progress : callable, optional
        ``progress(done, total)`` after each task (and once at the start).

    Returns
    -------
    StudyRecord

    Raises
    ------
    regimemap.study.file.StudyFileError
        The study file is refused.
    regimemap.study.record_store.StudyStoreError
        The store is another study's, or this study's without ``resume`` or ``overwrite``
        (or, with ``overwrite``, a folder that is not a study store).
    regimemap.lifetime.ClusterUnavailable
        Dask is missing or its scheduler cannot be reached.
    regimemap.lifetime.finite.NonFiniteResult
        A task's result is not finite (nothing of it is stored; the tasks stored stay).
    """
    from regimemap.study.file import read_study
    from regimemap.study.record_store import StudyStore, replacing_store

    s = study if not isinstance(study, (str, Path)) else read_study(study)
    if resume and overwrite:
        raise ValueError("resume and overwrite exclude each other: resume finishes a store, overwrite "
                         "replaces it")
    climates = _climates(s)
    total = len(s.sections) * len(s.scenarios) * (1 + len(climates or []))
    with contextlib.ExitStack() as stack:
        kept: StudyStore | None = None
        if store is not None:
            kept = (stack.enter_context(replacing_store(store, s.study_hash, s.source, total)) if overwrite
                    else StudyStore(store, s.study_hash, s.source, total, resume=resume))
        return _run(s, climates, total, kept, jobs, scheduler, progress)


def _run(s: Study, climates: list[Any] | None, total: int, kept: StudyStore | None, jobs: int,
         scheduler: str | None, progress: Callable[[int, int], None] | None) -> StudyRecord:
    """The tasks missing from ``kept`` (all without a store), stored as they finish; the record."""
    memory: dict[str, dict[str, Any]] = {}
    have = kept.done() if kept is not None else set()
    done = len(have)
    if progress is not None:
        progress(done, total)
    todo = ((name, task) for name, task in study_tasks(s, climates) if name not in have)
    if scheduler is not None:
        results = _dask(todo, scheduler, max(1, jobs))
    elif jobs > 1 and total - done > 1:
        results = _processes(todo, min(jobs, total - done))
    else:
        results = _serial(todo)
    with contextlib.closing(results):  # type: ignore[type-var]
        for name, result in results:
            if kept is not None:
                kept.save(name, result)
            else:
                memory[name] = _round_trip(result)
            done += 1
            if progress is not None:
                progress(done, total)
    return _assemble(s, climates, kept, memory)


def _round_trip(result: dict[str, Any]) -> dict[str, Any]:
    """A result as the store would give it back (JSON), so a record never depends on having a store."""
    import json

    out: dict[str, Any] = json.loads(json.dumps(result))
    return out


def _passes(by_year: list[float]) -> tuple[tuple[float, int | None], ...]:
    from regimemap.lifetime.results import year_passing

    return tuple((x, year_passing(np.asarray(by_year), x)) for x in LIMITS)


def _assemble(s: Study, climates: list[Any] | None, kept: StudyStore | None,
              memory: dict[str, dict[str, Any]]) -> StudyRecord:
    """The record, from the stored results of every task, in the study's order."""
    from regimemap.study.record_store import task_name

    def get(name: str) -> dict[str, Any]:
        got = kept.load(name) if kept is not None else memory.get(name)
        if got is None:  # pragma: no cover - every task was run above
            raise RuntimeError(f"task {name} has no result")
        where = f"{kept.path(name)}" if kept is not None else f"task {name}"
        for key in ("esd", "exceedance", "by_year", "chart_esd"):  # a store written before the check
            require_finite(f"the stored {key}", got.get(key, []), where)
        return got

    n_rep = len(climates or [])
    rows: list[StudyRow] = []
    notices: list[Notice] = list(s.notices)
    for i, section in enumerate(s.sections):
        for j, scenario in enumerate(s.scenarios):
            main = get(task_name(i, j, 0))
            reps = [get(task_name(i, j, r)) for r in range(1, n_rep + 1)]
            if main.get("bracket"):
                notices.append(Notice("target-not-bracketed", f"section {section.name!r}, scenario "
                                      f"{scenario.name!r}: {main['bracket']}", "width", None))
            rows += _rows(s, section, scenario.name, main, reps)
    targets = [sec.target for sec in s.sections if sec.target is not None]
    return StudyRecord(source=s.source, study_hash=s.study_hash, seed=s.seed, trials=s.trials, years=s.years,
                       sections=tuple((sec.name, sec.chainage) for sec in s.sections),
                       scenarios=tuple(sc.name for sc in s.scenarios), target=targets[0] if targets else None,
                       rows=tuple(rows), notices=tuple(notices))


def _esd_at(widths: np.ndarray, design: np.ndarray, esd: np.ndarray, width: float, found: float) -> float:
    """A replicate climate's ESD at the width found for the target, from the charts: the ESD found
    (``found``, the design climate's at ``width``) times the replicate's ratio to the design
    climate's chart (``esd / design`` at the chart's widths, interpolated linearly in width between
    the widths where the design climate's ESD is positive; nearest beyond them).  So the band is
    the charts' spread carried to the width found, not an interpolation of a steep ESD curve."""
    ok = design > 0.0
    if not np.any(ok):
        return found
    ratio = np.asarray(esd[ok] / design[ok], dtype=np.float64)
    return float(found * np.interp(width, widths[ok], ratio))


def _rows(s: Study, section: SectionSpec, scenario: str, main: dict[str, Any],
          reps: list[dict[str, Any]]) -> list[StudyRow]:
    """The rows of a section under a scenario: its design climate's task ``main`` and the replicate
    climates' ``reps`` -- the band of each width's ESD; of a target, the width at the band's upper
    level and the band of the ESD at the width found (:func:`_esd_at`)."""
    from regimemap.lifetime.replicates import ChartBand

    upper = None
    chart = None
    if section.target is not None and len(reps) >= 2:
        chart = ChartBand(widths=np.asarray(section.widths), esd=np.array([r["chart_esd"] for r in reps]),
                          level=BAND_LEVEL, target=section.target, seed=s.seed, trials=s.trials)
        upper = chart.width_for_target
    interval = main.get("interval")
    rows = []
    for k, width in enumerate(main["widths"]):
        band = None
        if len(reps) >= 2:
            at = (np.array([r["esd"][k] for r in reps]) if chart is None else
                  np.array([_esd_at(chart.widths, np.asarray(main["chart_esd"]), e, float(width),
                                    float(main["esd"][k])) for e in chart.esd]))
            q = np.quantile(at, [0.5 * (1.0 - BAND_LEVEL), 0.5 * (1.0 + BAND_LEVEL)])
            band = (float(q[0]), float(q[1]))
        rows.append(StudyRow(
            section=section.name, chainage=section.chainage, scenario=scenario, width=float(width),
            expected_sliding=float(main["esd"][k]), std_error=_nan(main["std_error"][k]),
            exceedance=tuple(zip(LIMITS, (float(p) for p in main["exceedance"][k]))),
            by_year=tuple(float(x) for x in main["by_year"][k]), passes=_passes(main["by_year"][k]),
            band=band, required_width=None if section.target is None else main.get("required_width"),
            required_width_interval=None if interval is None else (float(interval[0]), float(interval[1])),
            required_width_upper=upper))
    return rows


def _nan(x: Any) -> float:
    return math.nan if x is None else float(x)


def study_checks(study: Study, record: StudyRecord) -> tuple[StudyCheck, ...]:
    """The requirement of each section under each scenario, in the study's order.

    A section of fixed widths meets its ``[lifetime] target`` (the tolerable ESD) when one of its
    widths does: the narrowest that does is named (none: the widest, which fails).  A section with
    a ``target`` meets it when the width found is at most the section's ``[caisson] width``.  The
    ESD judged is the row's upper end of the climate band when the row holds one (a record
    climate with ``climate_replicates``), else the ESD of the design's climate; for a target, the
    width at the band's upper level when the row holds it.  The basis says which.

    Parameters
    ----------
    study : Study
        The study run (its sections' targets and widths).
    record : StudyRecord
        Its record (:func:`run_study`).

    Returns
    -------
    tuple of StudyCheck
        One per section x scenario.
    """
    out = []
    for section in study.sections:
        for scenario in study.scenarios:
            rows = record.rows_for(section.name, scenario.name)
            out.append(StudyCheck(section.name, scenario.name, *_check(section, rows)))
    return tuple(out)


def _widths_text(widths: tuple[float, ...]) -> str:
    return ", ".join(f"{w:g}" for w in widths) + " m"


def _check(section: SectionSpec, rows: tuple[StudyRow, ...]) -> tuple[Check, str]:
    """The check of a section under one scenario (its ``rows``) and its basis in words."""
    if section.target is not None:
        own = section.design.caisson.width
        row = rows[0] if rows else None
        upper = None if row is None else row.required_width_upper
        found = None if row is None else (upper if upper is not None else row.required_width)
        which = "at the climate band's upper level" if upper is not None else "of the design's climate"
        basis = (f"the width for ESD {section.target:g} m ({which}) against the section's [caisson] width"
                 if found is not None else
                 f"the width for ESD {section.target:g} m (not found between {_widths_text(section.widths)}) "
                 "against the section's [caisson] width")
        width = math.nan if found is None else found
        return Check.at_most("width for the target ESD", width, own, "m"), basis
    target = section.design.lifetime_spec().target
    banded = bool(rows) and all(r.band is not None for r in rows)

    def esd(r: StudyRow) -> float:
        return r.band[1] if r.band is not None else r.expected_sliding

    which = (f"the ESD at the upper end of the {BAND_LEVEL:.0%} climate band" if banded
             else "the ESD of the design's climate")
    passing = [r for r in rows if esd(r) <= target]
    if len(rows) == 1:
        chosen, how = rows[0], ""
    elif passing:
        chosen, how = passing[0], f", the narrowest of {_widths_text(section.widths)} that meets it"
    else:
        chosen, how = rows[-1], f", the widest of {_widths_text(section.widths)}; none meets it"
    basis = f"{which} at {chosen.width:g} m{how}"
    return Check.at_most("expected sliding distance", esd(chosen), target, "m"), basis
