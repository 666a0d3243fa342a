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

__all__ = ["save_figure", "write_animation", "write_atlas"]


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
