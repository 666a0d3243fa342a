"""The report's figures into a folder, on every core (``regimemap figures``, ``make figures``).

:func:`write_figures` shares the figures out among worker processes; each
figure is drawn and written by one process alone, atomically
(:func:`regimemap.drawing.save.save_figure`), so the files are byte-identical
to a one-process run.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["cpu_count", "write_figures"]


def _render_chunk(ids: Sequence[str], folder: str, formats: Sequence[str], dpi: float,
                  progress: Callable[[int], None] | None = None) -> list[str]:
    """Draw the figures ``ids`` and write them in every format (one process)."""
    from .figure import render_preset
    from .model import MODEL_FIGURE_ID, model_figure
    from .presets import get_preset
    from .save import save_figure
    from .worked import WORKED, render_worked

    fig: Figure | None = None  # one Figure for all maps: its renderer keeps the text caches warm
    written: list[str] = []
    for fid in ids:
        if fid == MODEL_FIGURE_ID:
            one = model_figure(dpi=dpi)
            name = f"fig-{fid}"
        elif fid in WORKED:
            one = fig = render_worked(WORKED[fid], dpi=dpi, fig=fig)
            name = f"fig-{fid}"
        else:
            preset = get_preset(fid)
            one = fig = render_preset(preset, dpi=dpi, fig=fig)
            name = f"fig-{preset.id}"
        for fmt in formats:
            target = Path(folder) / f"{name}.{fmt}"
            save_figure(one, target, fmt, dpi=dpi)
            written.append(str(target))
        if progress is not None:
            progress(1)
    return written


def cpu_count() -> int:
    """The number of cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def write_figures(folder: str | os.PathLike[str], ids: Sequence[str], formats: Sequence[str],
                  dpi: float, jobs: int | None = None,
                  progress: Callable[[int], None] | None = None) -> list[Path]:
    """Write the figures ``ids`` into ``folder``, in every format, on every core.

    Parameters
    ----------
    folder : path-like
        An existing folder.
    ids : sequence of str
        The report's numbers: ``"2.1"`` (the model) and those of
        :data:`regimemap.drawing.presets.PRESETS`, and the worked figures of
        :data:`regimemap.drawing.worked.WORKED` (``"W.1"`` ...).
    formats : sequence of str
        ``"png"``, ``"svg"``, ``"pdf"``.
    dpi : float
        Resolution of the figures and of PNG output.
    jobs : int, optional
        Worker processes (default: one per core; 1 draws them here).
    progress : callable, optional
        Called with the number of figures just written (a progress bar's ``step``).

    Returns
    -------
    list of Path
        The files written, in the order of ``ids`` and ``formats``.

    Raises
    ------
    OSError
        If a file cannot be written (the files finished before it are complete).
    """
    ids = list(ids)
    jobs = cpu_count() if jobs is None else max(1, int(jobs))
    jobs = min(jobs, len(ids))
    folder_s = os.fspath(folder)
    if jobs <= 1:
        return [Path(p) for p in _render_chunk(ids, folder_s, formats, dpi, progress)]
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else None)
    # deal the figures out in turn: neighbours in the report cost about the same; a few
    # chunks per worker, so that the progress moves as they finish
    n_chunks = min(len(ids), 4 * jobs) if progress is not None else jobs
    chunks = [ids[i::n_chunks] for i in range(n_chunks)]
    with ProcessPoolExecutor(max_workers=jobs, mp_context=ctx) as pool:
        futures = {pool.submit(_render_chunk, chunk, folder_s, tuple(formats), dpi): chunk
                   for chunk in chunks}
        done = {}
        for fut in as_completed(futures):
            chunk = futures[fut]
            paths = fut.result()
            per = len(formats)
            for n, fid in enumerate(chunk):
                done[fid] = paths[n * per:(n + 1) * per]
            if progress is not None:
                progress(len(chunk))
    return [Path(p) for fid in ids for p in done[fid]]
