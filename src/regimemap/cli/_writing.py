"""How the commands write their files and what they print: one error for a file that cannot be
written, the ``-o`` files checked to be distinct, in a writable folder and of a suffix their record
is written in (the one registry, :mod:`regimemap.io.formats`), each file written once with the
figure drawn once, the path of each file written, and the one printer of the notices."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ..io.formats import SuffixError, format_for, suffix_of
from ..io.json import json_text
from ._main import RunError, import_matplotlib, refusing

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..records.notices import Notice

__all__ = ["checked_format", "checked_output", "distinct_files", "echo_notes", "echo_notices",
           "figure_output", "file_suffix", "output_dir", "output_path", "print_report", "report_written",
           "write_figure", "write_files", "writing"]


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
    regimemap.cli._main.RunError: cannot write /no/such/folder/x.csv: No such file or directory
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
    with refusing(param_hint, SuffixError):
        return format_for(path, record)


def checked_output(path: str, record: str | Sequence[tuple[str, Sequence[str]]], param: str = "--output",
                   hint: str | None = None) -> str:
    """The format of output ``path`` for ``record`` (:func:`checked_format`, a usage error naming
    ``hint``, by default ``param``), its folder checked (:func:`output_path`, naming ``param``)."""
    fmt = checked_format(path, record, hint or f"'{param}'")
    output_path(path, param)
    return fmt


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
                write_figure(fig, path)
        written.append(path)
    return written


def write_figure(fig: Figure, path: str | os.PathLike[str], fmt: str | None = None,
                 dpi: float | None = None) -> None:
    """Save ``fig`` to ``path`` atomically (:func:`regimemap.drawing.save.save_figure`: the format
    ``fmt``, else the suffix's); a file that cannot be written is :func:`writing`'s error."""
    from ..drawing.save import save_figure

    with writing(path):
        save_figure(fig, path, fmt, dpi=dpi)


def output_path(path: str | os.PathLike[str], param: str = "--output") -> Path:
    """Check that the folder of ``path`` exists and is writable; raise a usage error if not."""
    from ..io.atomic import check_output_path

    try:
        return check_output_path(path, param)
    except ValueError as exc:
        raise click.BadParameter(str(exc).replace(f"{param} ", "", 1), param_hint=f"'{param}'") from None


def figure_output(path: str) -> tuple[Path, str]:
    """``-o`` of a command that writes one figure: the file, its folder checked (:func:`output_path`),
    and its format from the suffix (:func:`regimemap.drawing.save.format_from_path`); a suffix of
    no figure is a usage error naming ``'-o' / '--output'``."""
    from ..drawing.save import format_from_path

    with refusing("'-o' / '--output'"):
        fmt = format_from_path(path)
    return output_path(path, "--output"), fmt


def report_written(path: str | os.PathLike[str], note: str | None = None) -> None:
    """Report a written file the one way every command does: its path on standard output.

    A ``note`` about it (frames, points ...) goes to standard error, so that
    ``$(regimemap ...)`` captures the path alone.
    """
    click.echo(os.fspath(path))
    if note:
        click.echo(f"regimemap: {note}", err=True)


def echo_notices(notices: Iterable[Notice], prefix: dict[str, str] | None = None, *,
                 source: str | None = None) -> None:
    """Notices on standard error, one line each: ``regimemap: warning: MESSAGE`` -- the one
    printer of every command's warnings.

    ``prefix`` gives another start of the line to the notices of some codes
    (``{"crammed": "regimemap: note: "}``); ``source`` (a design file's name) goes before
    each message: ``regimemap: warning: SOURCE: MESSAGE``.
    """
    where = f"{source}: " if source else ""
    for n in notices:
        click.echo(f"{(prefix or {}).get(n.code, 'regimemap: warning: ')}{where}{n.message}", err=True)


def print_report(as_json: bool, text: Callable[[], str | None], data: Callable[[], dict[str, Any]],
                 written: Sequence[str] = (), indent: int = 2) -> None:
    """A command's report on standard output, the one way every command prints it: with
    ``as_json`` one JSON object, ``data()`` (``indent``: its indent), else the text, ``text()``
    (None: none), then the path of each file ``written`` (:func:`report_written`)."""
    if as_json:
        click.echo(json_text(data(), indent=indent))
        return
    report = text()
    if report is not None:
        click.echo(report)
    for path in written:
        report_written(path)


def echo_notes(notes: Iterable[str], prefix: str = "regimemap: ") -> None:
    """Notes on standard error, one line each: ``regimemap: NOTE`` (or ``prefix`` + ``NOTE``)."""
    for note in notes:
        click.echo(f"{prefix}{note}", err=True)


def output_dir(path: str | os.PathLike[str], param: str = "--out", *, create: bool = False,
               later: bool = False) -> Path:
    """Check that ``path`` is an existing folder where files can be created; usage error if not.

    With ``create``, a missing folder whose parent exists (and accepts new
    files) is created first; a missing parent is still a usage error.  With
    ``later``, a missing folder is accepted, not created, when its parent
    exists and accepts new files (the writer creates it, as a study's
    ``--store``); a missing parent is refused as for a file of ``-o``
    (:func:`output_path`): ``folder 'PARENT' does not exist``.

    Like :func:`output_path` for a folder: the check creates and removes an
    empty hidden file, since permission bits do not tell (root, read-only or
    virtual file systems such as /proc).
    """
    from ..io.atomic import folder_problem

    p = Path(path)
    if not str(path).strip():
        raise click.BadParameter(f"must be a folder, got {str(path)!r}", param_hint=f"'{param}'")
    if p.exists() and not p.is_dir():
        raise click.BadParameter(f"{str(path)!r} is a file, not a folder", param_hint=f"'{param}'")
    if later and not p.is_dir():
        parent = p.parent if str(p.parent) else Path(".")
        if not parent.is_dir():
            what = "is a file, not a folder" if parent.exists() else "does not exist"
            raise click.BadParameter(f"folder {str(parent)!r} {what}", param_hint=f"'{param}'")
        problem = folder_problem(parent)
        if problem:
            raise click.BadParameter(f"folder {str(parent)!r} {problem}", param_hint=f"'{param}'")
        return p
    if not p.is_dir() and create:
        parent = p.parent if str(p.parent) else Path(".")
        if parent.is_dir() and not folder_problem(parent):
            try:
                p.mkdir()
            except FileExistsError:
                pass
            except OSError as exc:
                raise click.BadParameter(f"cannot create folder {str(path)!r}: {exc.strerror}",
                                         param_hint=f"'{param}'") from None
    if not p.is_dir():
        hint = " (its parent folder must exist)" if create else ""
        raise click.BadParameter(f"folder {str(path)!r} does not exist{hint}",
                                 param_hint=f"'{param}'")
    problem = folder_problem(p)
    if problem:
        raise click.BadParameter(f"folder {str(path)!r} {problem}", param_hint=f"'{param}'")
    return p
