"""How the commands write their files: one error for a file that cannot be written, the ``-o``
files checked to be distinct and of a suffix their record is written in (the one registry,
:mod:`regimemap.io.formats`), and each file written once with the figure drawn once."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..io.formats import SuffixError, format_for, suffix_of
from ._common import RunError, import_matplotlib

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["checked_format", "distinct_files", "file_suffix", "write_files", "writing"]


@contextlib.contextmanager
def writing(path: str | os.PathLike[str] | None, what: str | None = None) -> Iterator[None]:
    """Write ``path`` inside the block: an :class:`OSError` becomes the one-line :class:`RunError`
    ``cannot write PATH: reason`` (exit 1), with no traceback.

    Parameters
    ----------
    path : str, path-like or None
        The file (or folder) written.
    what : str, optional
        What the message says is being written, instead of ``path`` (e.g. ``to the cache DIR``).

    Examples
    --------
    >>> with writing("/no/such/folder/x.csv"):
    ...     open("/no/such/folder/x.csv", "w")
    Traceback (most recent call last):
    ...
    regimemap.cli._common.RunError: cannot write /no/such/folder/x.csv: No such file or directory
    """
    try:
        yield
    except OSError as exc:
        raise RunError(f"cannot write {path if what is None else what}: {exc.strerror or exc}") from None


#: The suffix of a path in lower case, without its dot (:func:`regimemap.io.formats.suffix_of`).
file_suffix = suffix_of


def checked_format(path: str, record: str | Sequence[tuple[str, Sequence[str]]], param_hint: str) -> str:
    """The format of output ``path`` for ``record`` (:func:`regimemap.io.formats.format_for`);
    a suffix it is not written in is a usage error (exit 2) naming ``param_hint``
    (``"'--output'"``), worded by :func:`regimemap.io.formats.suffix_error`."""
    try:
        return format_for(path, record)
    except SuffixError as exc:
        raise click.BadParameter(str(exc), param_hint=param_hint) from None


def distinct_files(paths: Sequence[str], param_hint: str) -> None:
    """Refuse (usage error, exit 2) a file given twice among ``paths``, however it is spelt
    (``a.svg`` and ``./a.svg``); ``param_hint`` names the options (``"'-o' / '--output'"``)."""
    if len({str(Path(p).resolve()) for p in paths}) < len(paths):
        raise click.BadParameter("the same file is given twice", param_hint=param_hint)


def write_files(paths: Sequence[str], draw: Callable[[], Figure], *,
                data_formats: Sequence[str] = (), write_data: Callable[[str], object] | None = None
                ) -> list[str]:
    """Write each of ``paths`` atomically, in order: a file whose suffix is one of
    ``data_formats`` by ``write_data(path)``, any other as the figure ``draw()`` returns (drawn
    once, on the first figure file, and saved by :func:`regimemap.drawing.save.save_figure` in the
    format of the suffix).  A file that cannot be written is :func:`writing`'s error.

    Returns
    -------
    list of str
        The paths written.
    """
    written: list[str] = []
    fig: Figure | None = None
    for path in paths:
        with writing(path):
            if file_suffix(path) in data_formats:
                assert write_data is not None
                write_data(path)
            else:
                if fig is None:
                    import_matplotlib()
                    fig = draw()
                from ..drawing.save import save_figure

                save_figure(fig, path)
        written.append(path)
    return written
