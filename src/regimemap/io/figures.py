"""Figures and animations to files, atomically (a temporary file, then a rename).

The drawing layer makes the figures and their bytes
(:func:`regimemap.drawing.save.print_figure`); this module owns the files: a
write that fails half-way leaves nothing behind and never a half-written file.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .atomic import atomic_path

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["cpu_count", "save_figure", "write_animation", "write_atlas", "write_figures"]


def save_figure(fig: Figure, path: str | os.PathLike[str], fmt: str | None = None,
                dpi: float | None = None) -> Path:
    """Write ``fig`` to ``path`` atomically (temporary file in the same folder, then rename).

    Parameters
    ----------
    fig : Figure
    path : path-like
    fmt : {"png", "svg", "pdf"}, optional
        Default: from the file suffix.
    dpi : float, optional
        Resolution of PNG output (default: the figure's).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        For an unknown format (message lists png, svg, pdf).
    OSError
        If the file cannot be written (nothing is left behind).
    """
    from ..drawing.save import format_from_path, print_figure

    fmt = format_from_path(path, fmt)
    target = Path(path)
    with atomic_path(target) as tmp:
        print_figure(fig, tmp, fmt, dpi)
    return target


def write_atlas(path: str | os.PathLike[str], gammas: Sequence[float], kprimes: Sequence[float],
                *, fmt: str | None = None, dpi: float | None = None, **kwargs: Any) -> Path:
    """Draw :func:`regimemap.drawing.atlas.atlas_figure` and save it atomically (png, svg or pdf).

    Returns the path written.
    """
    from ..drawing.atlas import atlas_figure
    from ..drawing.save import format_from_path

    fmt = format_from_path(path, fmt)
    fig = atlas_figure(gammas, kprimes, **kwargs)
    return save_figure(fig, path, fmt=fmt, dpi=dpi)


def write_animation(path: str | os.PathLike[str], gamma: float, kprimes: Sequence[float],
                    **kwargs: Any) -> tuple[int, tuple[int, int]]:
    """Write the GIF of :func:`regimemap.drawing.atlas.render_animation` atomically.

    Returns the number of frames and their size in pixels.
    """
    from ..drawing.atlas import check_animation, render_animation

    check_animation(path, gamma, kprimes, kwargs.get("fps", 8.0),
                    sweep=kwargs.get("sweep", "kprime"), fixed=kwargs.get("fixed"))
    with atomic_path(path) as tmp:
        return render_animation(tmp, gamma, kprimes, **kwargs)


def _render_chunk(ids: Sequence[str], folder: str, formats: Sequence[str], dpi: float
                  ) -> list[str]:
    """Draw the figures ``ids`` and write them in every format (one process)."""
    from ..drawing.figure import render_preset
    from ..drawing.model import MODEL_FIGURE_ID, model_figure
    from ..drawing.presets import get_preset
    from ..drawing.worked import WORKED, render_worked

    fig = None  # one Figure for all maps: its renderer keeps the text caches warm
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
    return written


def cpu_count() -> int:
    """The number of cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def write_figures(folder: str | os.PathLike[str], ids: Sequence[str], formats: Sequence[str],
                  dpi: float, jobs: int | None = None) -> list[Path]:
    """Write the figures ``ids`` into ``folder``, in every format, on every core.

    ``ids`` are the report's numbers: ``"2.1"`` (the model) and those of
    :data:`regimemap.drawing.presets.PRESETS`, and the worked figures of
    :data:`regimemap.drawing.worked.WORKED` (``"W.1"`` ...).

    The figures are shared out among ``jobs`` worker processes (default: one
    per core; 1 draws them here).  Each figure is drawn and written by one
    process alone, atomically, so the files are byte-identical to a
    one-process run.

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
        return [Path(p) for p in _render_chunk(ids, folder_s, formats, dpi)]
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else None)
    # deal the figures out in turn: neighbours in the report cost about the same
    chunks = [ids[i::jobs] for i in range(jobs)]
    with ProcessPoolExecutor(max_workers=jobs, mp_context=ctx) as pool:
        futures = [pool.submit(_render_chunk, chunk, folder_s, tuple(formats), dpi)
                   for chunk in chunks]
        done = {}
        for chunk, fut in zip(chunks, futures):
            paths = fut.result()
            per = len(formats)
            for n, fid in enumerate(chunk):
                done[fid] = paths[n * per:(n + 1) * per]
    return [Path(p) for fid in ids for p in done[fid]]
