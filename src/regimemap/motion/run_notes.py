"""What the commands of the motion say of their runs on standard error, as plain strings: an
outcome map's size before it runs, each figure of ``regimemap dynamics-figures`` (its time, its
runs or the cache) and the files written, the frames of a run's animation."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import os

    from .file import MapOptions
    from .record import DynamicsFigureRecord

__all__ = ["animation_note", "dynamics_figure_note", "dynamics_files_note", "outcome_start_note"]


def outcome_start_note(options: MapOptions) -> str:
    """``simulating N runs (COLUMNS x ROWS) ...``: the grid of an outcome map, before it runs."""
    return f"simulating {options.n_runs} runs ({len(options.axis(0))} x {len(options.axis(1))}) ..."


def dynamics_figure_note(record: DynamicsFigureRecord, seconds: float) -> str:
    """``D.1: 2.5 s (grid 7680 runs, boundaries 912 runs)``, or ``(from the cache)``."""
    how = ("from the cache" if record.from_cache else
           f"grid {record.outcome.category.size} runs, boundaries {record.refine_runs} runs")
    return f"{record.figure.id}: {seconds:.1f} s ({how})"


def dynamics_files_note(figures: int, formats: Sequence[str], folder: str | os.PathLike[str]) -> str:
    """``6 files (3 figures x png, svg) in FOLDER``."""
    return f"{len(formats) * figures} files ({figures} figures x {', '.join(formats)}) in {folder}"


def animation_note(path: str, frames: int, size: tuple[int, int], speed: float) -> str:
    """``PATH: N frames, W x H pixels, real time`` (or ``S x real time``): a run's animation."""
    w, h = size
    return f"{path}: {frames} frames, {w} x {h} pixels, " + ("real time" if speed == 1.0 else
                                                             f"{speed:.3g} x real time")
