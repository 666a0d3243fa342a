"""The file formats, by suffix: declared once, with the one error for a suffix that is not one.

Every file regimemap writes is chosen by its suffix.  :data:`FORMATS` declares each format
once -- its suffix, its kind (a figure, data, an animation) and what it is -- and
:data:`RECORDS` says which formats each record is written in.  From them:

* :func:`suffix_of` -- the suffix of a path, as every dispatch reads it;
* :func:`kind_of` -- the kind of a suffix (``"figure"``, ``"data"``, ``"animation"``);
* :func:`record_formats` -- the suffixes a record is written in;
* :func:`format_for` -- the format of a path for a record, or :class:`SuffixError`;
* :func:`suffix_error` -- that error, worded once for every command and writer;
* :data:`FIGURE_FORMATS` -- the figure suffixes, the tuple the commands list.

A new figure format is one new :class:`Format` row (matplotlib writes it); a new data format
is one row here and its writer beside the record's other writers.  The registry follows
xarray's ``backends`` (``plugins.guess_engine``: the engine from the file name), kept to
suffixes: the writers stay with their records.

Examples
--------
>>> format_for("map.SVG", "figure")
'svg'
>>> kind_of("npz")
'data'
>>> format_for("run.txt", "time history")
Traceback (most recent call last):
...
regimemap.io.formats.SuffixError: unknown file suffix .txt in 'run.txt'; use .npz or .csv for the time history
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

__all__ = [
    "BY_SUFFIX",
    "FIGURES",
    "FIGURE_FORMATS",
    "FORMATS",
    "RECORDS",
    "Format",
    "SuffixError",
    "format_for",
    "kind_of",
    "listed",
    "record_formats",
    "suffix_error",
    "suffix_of",
    "suffixes",
]

Kind = Literal["figure", "data", "animation"]


@dataclass(frozen=True)
class Format:
    """A file format: its suffix (lower case, no dot), its kind and what it is; for a figure, how
    matplotlib writes it byte-stable (:func:`regimemap.drawing.save.print_figure`).

    Attributes
    ----------
    suffix, kind, what : str
        The suffix, ``"figure"``, ``"data"`` or ``"animation"``, and what the file is, in words.
    creator : tuple of str
        The metadata keys that name regimemap and its release (figures).
    undated : tuple of str
        The metadata keys set to None: no date in the file, so the same figure is the same bytes.
    options : tuple of (str, object)
        Further keyword arguments of ``savefig`` for this format.
    """

    suffix: str
    kind: Kind
    what: str
    creator: tuple[str, ...] = ()
    undated: tuple[str, ...] = ()
    options: tuple[tuple[str, Any], ...] = ()


#: Every format regimemap writes, each once.  Figures are written by
#: :func:`regimemap.drawing.save.save_figure` (matplotlib's backend of the suffix).
FORMATS: tuple[Format, ...] = (
    # zlib level 1: ~20 % faster to write than the default 6, ~15 % larger files
    Format("png", "figure", "raster image (--dpi)", creator=("Software",),
           options=(("pil_kwargs", {"compress_level": 1}),)),
    Format("svg", "figure", "vector image", creator=("Creator",), undated=("Date",)),
    Format("pdf", "figure", "vector document", creator=("Creator", "Producer"), undated=("CreationDate",)),
    Format("gif", "animation", "animated image"),
    Format("npz", "data", "numpy arrays (numpy.load)"),
    Format("csv", "data", "comma-separated table"),
    Format("json", "data", "one JSON object"),
    Format("nc", "data", "NetCDF (needs the 'netcdf' extra)"),
)

_KIND = {f.suffix: f.kind for f in FORMATS}
#: Each format by its suffix.
BY_SUFFIX: dict[str, Format] = {f.suffix: f for f in FORMATS}


def suffixes(kind: Kind) -> tuple[str, ...]:
    """The suffixes of the formats of ``kind``, in the order of :data:`FORMATS`."""
    return tuple(f.suffix for f in FORMATS if f.kind == kind)


#: The figure formats: ``("png", "svg", "pdf")``.
FIGURE_FORMATS: tuple[str, ...] = suffixes("figure")

#: Each record's files: (what the file holds, its suffixes), in the order an error lists them.
RECORDS: dict[str, tuple[tuple[str, tuple[str, ...]], ...]] = {
    "figure": (("a figure", FIGURE_FORMATS),),
    "animation": (("the animation", suffixes("animation")),),
    "map data": (("the map's data", ("npz", "csv", "json")),),
    "time history": (("the time history", ("npz", "csv")),),
    "outcome data": (("an outcome map's data", ("npz", "csv", "json")),),
    "lifetimes": (("the lifetimes", ("csv", "npz")),),
    "lifetime": (("the figure", FIGURE_FORMATS), ("the lifetimes", ("csv", "npz"))),
    "design sheet": (("the design sheet", FIGURE_FORMATS),),
    "climate figures": (("the figures", FIGURE_FORMATS),),
    "study table": (("the table", ("csv", "nc")),),
    "study": (("the table", ("csv", "nc")), ("the figure", FIGURE_FORMATS)),
}


def record_formats(record: str) -> tuple[str, ...]:
    """Every suffix of ``record`` (a key of :data:`RECORDS`), in its order.

    Examples
    --------
    >>> record_formats("lifetime")
    ('png', 'svg', 'pdf', 'csv', 'npz')
    """
    return tuple(f for _, formats in RECORDS[record] for f in formats)


class SuffixError(ValueError):
    """A file whose suffix is not one its record is written in (:func:`suffix_error`)."""


def suffix_of(path: str | os.PathLike[str]) -> str:
    """The suffix of ``path`` in lower case, without its dot (``"svg"``; ``""`` for none)."""
    return Path(path).suffix.lower().lstrip(".")


def kind_of(suffix: str) -> Kind | None:
    """The kind of a suffix (``"figure"``, ``"data"``, ``"animation"``; a dot and case ignored),
    None for a suffix no format has."""
    return _KIND.get(suffix.lower().lstrip("."))


def listed(formats: Sequence[str]) -> str:
    """Suffixes in words: ``.png, .svg or .pdf``."""
    dotted = [f".{f}" for f in formats]
    return dotted[0] if len(dotted) == 1 else f"{', '.join(dotted[:-1])} or {dotted[-1]}"


#: The figure suffixes in words (``.png, .svg or .pdf``), as every command's help says them.
FIGURES = listed(FIGURE_FORMATS)


def _parts(record: str | Sequence[tuple[str, Sequence[str]]]) -> Sequence[tuple[str, Sequence[str]]]:
    return RECORDS[record] if isinstance(record, str) else record


def suffix_error(path: str | os.PathLike[str], record: str | Sequence[tuple[str, Sequence[str]]]
                 ) -> SuffixError:
    """The one error for a file whose suffix ``record`` is not written in.

    ``unknown file suffix .txt in 'run.txt'; use .npz or .csv for the time history`` (or
    ``no file suffix in 'run'; ...``).

    Parameters
    ----------
    path : path-like
        The file.
    record : str or sequence of (str, sequence of str)
        A key of :data:`RECORDS`, or its parts: what each file holds and its suffixes.
    """
    suffix, shown = suffix_of(path), os.fspath(path)
    head = f"unknown file suffix .{suffix} in {shown!r}" if suffix else f"no file suffix in {shown!r}"
    uses = ", ".join(f"{listed(formats)} for {what}" for what, formats in _parts(record))
    return SuffixError(f"{head}; use {uses}")


def format_for(path: str | os.PathLike[str], record: str | Sequence[tuple[str, Sequence[str]]]) -> str:
    """The format (suffix) of ``path`` for ``record``: the one dispatch by suffix.

    Parameters
    ----------
    path : path-like
        The file to write.
    record : str or sequence of (str, sequence of str)
        A key of :data:`RECORDS`, or its parts.

    Returns
    -------
    str
        The suffix, lower case and without its dot: the format the file is written in.

    Raises
    ------
    SuffixError
        For a suffix ``record`` is not written in (:func:`suffix_error`).
    """
    suffix = suffix_of(path)
    if any(suffix in formats for _, formats in _parts(record)):
        return suffix
    raise suffix_error(path, record)
