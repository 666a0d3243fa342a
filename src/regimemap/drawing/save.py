"""Figures to bytes and files: the format of a file, its metadata, matplotlib's writer.

:func:`print_figure` writes a figure to a path or an open binary file, with
byte-stable metadata (no dates) and regimemap's style; :func:`save_figure`
writes it to a file atomically, through :func:`regimemap.io.atomic.atomic_path`
(a temporary file in the same folder, then a rename): a write that fails
half-way leaves nothing behind and never a half-written file.
"""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Iterator
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from ..io.formats import BY_SUFFIX, FIGURE_FORMATS, format_for, suffix_of
from .style import style_context

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["DEFAULT_DPI", "DPI_RANGE", "FORMATS", "format_from_path", "metadata", "print_figure",
           "save_figure"]

#: Output formats (file suffixes) that :func:`print_figure` writes: the registry's figure formats.
FORMATS: tuple[str, ...] = FIGURE_FORMATS
#: Resolution of PNG output (dots per inch): 960 px across a map, sharp on
#: screens and in the README; use 300 for print (SVG or PDF are better there).
DEFAULT_DPI = 150
#: The resolutions (dots per inch) a map or a figure of the report may be drawn at.
DPI_RANGE: tuple[float, float] = (20.0, 1200.0)


def format_from_path(path: str | os.PathLike[str], fmt: str | None = None) -> str:
    """The output format: ``fmt`` if given, else the file suffix (png, svg or pdf).

    Raises
    ------
    ValueError
        For an unknown format, a suffix that contradicts ``fmt``, or without ``fmt`` a suffix
        that is not a figure's (:class:`regimemap.io.formats.SuffixError`); the message lists
        png, svg, pdf.
    """
    suffix = suffix_of(path)
    if fmt is not None:
        fmt = fmt.lower().lstrip(".")
        if fmt not in FORMATS:
            raise ValueError(f"unknown format {fmt!r}; use one of {', '.join(FORMATS)}")
        if suffix and suffix in FORMATS and suffix != fmt:
            raise ValueError(f"file suffix .{suffix} does not match format {fmt!r}")
        return fmt
    return format_for(path, "figure")


def figure_version(version: str | None = None) -> str:
    """The release a figure names: the version's leading numbers, without dev, local or date parts.

    Between two tags every commit has its own version (``0.1.1.dev4+g1a2b3c4``,
    and ``.d20261128`` on a tree with uncommitted changes); a figure names only
    the release it belongs to, so that redrawing it from an unchanged computation
    gives the same bytes on the next commit too (on the same machine).

    Examples
    --------
    >>> figure_version("0.1.1.dev4+g1a2b3c4.d20261128")
    '0.1.1'
    >>> figure_version("0.2.0")
    '0.2.0'
    """
    if version is None:
        from .. import __version__

        version = __version__
    match = re.match(r"\d+(?:\.\d+)*", version)
    return match.group(0) if match else version


def metadata(fmt: str) -> dict[str, Any]:
    """The metadata of a file of format ``fmt``: no dates, and regimemap's name and release, under
    the keys its :class:`~regimemap.io.formats.Format` declares."""
    declared = BY_SUFFIX[fmt]
    creator = f"regimemap {figure_version()}"
    return {**dict.fromkeys(declared.undated), **dict.fromkeys(declared.creator, creator)}


def print_figure(fig: Figure, target: str | os.PathLike[str] | IO[bytes], fmt: str,
                 dpi: float | None = None) -> None:
    """Write ``fig`` in format ``fmt`` to ``target`` (a path or a binary file), byte-stable (the
    same bytes every run on one machine; docs/guide/development.md, "Reproducibility").

    Parameters
    ----------
    fig : Figure
    target : path-like or binary file
    fmt : {"png", "svg", "pdf"}
    dpi : float, optional
        Resolution of PNG output (default: the figure's, :data:`DEFAULT_DPI`).
    """
    extra = dict(BY_SUFFIX[fmt].options)
    meta = metadata(fmt)
    if meta:  # a format without metadata (webp, jpeg ...) refuses even an empty dict
        extra["metadata"] = meta
    with style_context(), _quiet_font_subsetting():
        fig.savefig(target, format=fmt, dpi=dpi if dpi is not None else fig.dpi, **extra)


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
    from ..io.atomic import atomic_path  # tempfile: imported when a file is written

    fmt = format_from_path(path, fmt)
    target = Path(path)
    with atomic_path(target) as tmp:
        print_figure(fig, tmp, fmt, dpi)
    return target


@contextlib.contextmanager
def _quiet_font_subsetting() -> Iterator[None]:
    """Silence fontTools' "'created' timestamp seems very low" while fonts are embedded.

    Embedding TrueType fonts (PDF, ``pdf.fonttype: 42``) reads the bundled
    fonts' ``head`` tables, whose old dates make fontTools log two harmless
    warnings; the logger's level is restored afterwards.
    """
    import logging

    logger = logging.getLogger("fontTools.ttLib.tables._h_e_a_d")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        yield
    finally:
        logger.setLevel(level)
