"""The report's figures into a folder, on every core (``regimemap figures``, ``make figures``).

:func:`write_figures` shares the figures out among worker processes; each
figure is drawn and written by one process alone, atomically
(:func:`regimemap.drawing.save.save_figure`), so the files are byte-identical
to a one-process run on the same machine.  The workers are those of
:func:`regimemap.workers.worker_pool`, the one place where regimemap
starts processes.  :func:`render_figure` draws one of
them by its id from its maps; the maps are computed by the function the caller
hands over (``compute``: the command line's, which calls the workflows
:func:`regimemap.maps.run.run_map` and :func:`regimemap.maps.run_atlas.run_atlas`),
in the worker that draws the figure.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..run import MapRecord
    from ..run_atlas import AtlasRecord

__all__ = ["FigureMaps", "render_figure", "write_figures"]

#: The maps of a figure by its id: a map, an atlas, or None for the model figure (2.1), which
#: draws no map.  A module-level function, so that worker processes can be handed it.
FigureMaps = Callable[[str], "MapRecord | AtlasRecord | None"]


#: The figure a worker process keeps between its tasks (see :func:`_render_chunk`).
_KEPT: dict[str, Figure] = {}


def render_figure(fid: str, maps: MapRecord | AtlasRecord | None, *, dpi: float,
                  fig: Figure | None = None) -> Figure:
    """One figure by its id, from its computed maps: the model (2.1), a worked figure (W.1 ...)
    or the report's.

    ``maps`` is what the figure shows, computed from
    :attr:`~regimemap.maps.figures.presets.FigurePreset.map_keywords` or
    :attr:`~regimemap.maps.figures.worked.WorkedFigure.map_keywords` /
    :attr:`~regimemap.maps.figures.worked.WorkedFigure.atlas_keywords` (None for the model
    figure); pass the previous figure of a single map as ``fig`` to reuse it.
    """
    from .figure import render_preset
    from .model import model_figure
    from .presets import MODEL_FIGURE_ID, get_preset
    from .worked import WORKED, render_worked

    if fid == MODEL_FIGURE_ID:
        return model_figure(dpi=dpi)
    if maps is None:
        raise ValueError(f"figure {fid} draws maps: give them (its map_keywords' record)")
    if fid.strip().upper() in WORKED:
        return render_worked(WORKED[fid.strip().upper()], maps, dpi=dpi, fig=fig)
    return render_preset(get_preset(fid), maps, dpi=dpi, fig=fig)  # type: ignore[arg-type]


def _render_chunk(ids: Sequence[str], folder: str, formats: Sequence[str], dpi: float,
                  compute: FigureMaps, progress: Callable[[int], None] | None = None,
                  keep: bool = False) -> list[str]:
    """Draw the figures ``ids`` and write them in every format (one process).

    One Figure is reused for all the maps: its renderer keeps the text caches warm.  With
    ``keep`` (a worker process) it is also kept for the worker's next task.
    """
    from ...drawing.save import save_figure
    from .presets import MODEL_FIGURE_ID, get_preset
    from .worked import WORKED

    fig: Figure | None = _KEPT.pop("fig", None) if keep else None
    written: list[str] = []
    for fid in ids:
        one = render_figure(fid, compute(fid), dpi=dpi, fig=fig)
        if fid == MODEL_FIGURE_ID:
            name = f"fig-{fid}"
        else:
            fig = one
            name = f"fig-{fid if fid in WORKED else get_preset(fid).id}"
        for fmt in formats:
            target = Path(folder) / f"{name}.{fmt}"
            save_figure(one, target, fmt, dpi=dpi)
            written.append(str(target))
        if progress is not None:
            progress(1)
    if keep and fig is not None:
        _KEPT["fig"] = fig
    return written


def _longest_first(ids: Sequence[str]) -> list[str]:
    """``ids`` in the order the workers take them: the worked figures (W.4 is an atlas of
    maps, W.1-W.3 loaded maps with more labels: 1.5-3 times a report's figure) first, so
    that the short ones even out the end."""
    return sorted(ids, key=lambda fid: not fid.upper().startswith("W"))


def write_figures(folder: str | os.PathLike[str], ids: Sequence[str], formats: Sequence[str],
                  dpi: float, compute: FigureMaps, jobs: int | None = None,
                  progress: Callable[[int], None] | None = None) -> list[Path]:
    """Write the figures ``ids`` into ``folder``, in every format, on every core.

    Parameters
    ----------
    folder : path-like
        An existing folder.
    ids : sequence of str
        The report's numbers: ``"2.1"`` (the model) and those of
        :data:`regimemap.maps.figures.presets.PRESETS`, and the worked figures of
        :data:`regimemap.maps.figures.worked.WORKED` (``"W.1"`` ...).
    formats : sequence of str
        ``"png"``, ``"svg"``, ``"pdf"``.
    dpi : float
        Resolution of the figures and of PNG output.
    compute : callable
        The maps of a figure by its id (:data:`FigureMaps`), called in the process that
        draws it: a module-level function (a worker process is handed it by name).
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
    from ...workers import available_cores, worker_pool

    ids = list(ids)
    jobs = available_cores() if jobs is None else max(1, int(jobs))
    jobs = min(jobs, len(ids))
    folder_s = os.fspath(folder)
    if jobs <= 1:
        return [Path(p) for p in _render_chunk(ids, folder_s, formats, dpi, compute, progress)]
    from concurrent.futures import as_completed

    # one figure a task, the longest first: a worker that is free takes the next one, so the
    # workers finish together (a fixed deal left one ~0.3 s behind the other); each worker
    # keeps its figure between tasks.  Ctrl-C or a failure stops the pool at once: the figures
    # not started are not drawn, the one being written is removed whole (io.atomic)
    done: dict[str, list[str]] = {}
    with worker_pool(jobs) as pool:
        futures = {pool.submit(_render_chunk, [fid], folder_s, tuple(formats), dpi, compute, None, True):
                   fid for fid in _longest_first(ids)}
        for fut in as_completed(futures):
            done[futures[fut]] = fut.result()
            if progress is not None:
                progress(1)
    return [Path(p) for fid in ids for p in done[fid]]
