"""What ``regimemap lifetime`` says of a run besides its report, as plain strings: the notes of
standard error (how many lifetimes, how long, where; the seed drawn; the climate band's run) and
the files a run cannot write (the lifetimes of a chart).  The command line prints them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..io.formats import FIGURES

if TYPE_CHECKING:
    from .run import ChartRecord, LifetimeRecord

__all__ = ["output_refusal", "run_notes"]


def run_notes(record: LifetimeRecord | ChartRecord) -> list[str]:
    """The notes of a run: its lifetimes, years, wall time and processes (or cluster); the seed
    it drew when none was given; the climate band's replicates and wall time.

    Examples
    --------
    A run of 200 lifetimes in this process with ``--seed`` gives one note::

        200 lifetimes of 50 years in 0.1 s in this process
    """
    from .run import ChartRecord

    n, p = record.trials, record.processes
    where = (f"on the Dask cluster at {record.scheduler}" if record.scheduler is not None else
             "in this process" if p == 1 else f"on {p} processes")
    lives = f"{n} lifetime{'' if n == 1 else 's'}"
    what = f"{len(record.widths)} widths x {lives}" if isinstance(record, ChartRecord) else lives
    notes = [f"{what} of {record.model.years} years in {record.seconds:.1f} s {where}"]
    if record.seed is None:
        used = record.used_seed
        notes.append(f"no seed given: this run's seed is {used} (--seed {used} repeats it)")
    if record.band is not None:
        notes.append(f"climate band: {record.band.replicates} replicate climates x {n} lifetimes "
                     f"in {record.band_seconds or 0.0:.1f} s")
    return notes


def output_refusal(path: str, fmt: str, chart: bool) -> str | None:
    """Why a run cannot write ``path`` of format ``fmt`` (``chart``: a design chart, ``--width``),
    or None: the lifetimes (.npz) are one width's."""
    if fmt == "npz" and chart:
        return (f"{path!r}: the lifetimes (.npz) are written for one width, not with --width (a chart is "
                f"written as .csv, its table, or as {FIGURES})")
    return None
