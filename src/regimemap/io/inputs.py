"""The check every input file passes before it is opened: a regular file below a size limit.

A path that names a folder, a named pipe (FIFO), a device or a socket, or a
file larger than the limit of its kind, is refused from its ``os.stat`` alone,
without opening it: ``open()`` blocks on a FIFO until a writer comes, and a
device such as ``/dev/zero`` never ends.  ``os.stat`` follows symbolic links,
so a link to a regular file is accepted.  Each kind of input has its limit:

* design files (TOML): :data:`MAX_DESIGN_FILE_BYTES`, 4 MiB (a design file is
  about 2 KB);
* points and pulse files (CSV): ``MAX_POINTS_FILE_BYTES`` in
  :mod:`regimemap.maps.file_points` and ``MAX_PULSE_FILE_BYTES`` in
  :mod:`regimemap.motion.file_pulses`, 128 MiB, room for their limits of 1,000,000 rows.

The limit is a parameter of :func:`check_input_file`, so a reader of larger
inputs gives its own.
"""

from __future__ import annotations

import codecs
import os
import stat

from .toml_errors import DesignFileError

__all__ = ["DesignInputError", "InputFileError", "MAX_DESIGN_FILE_BYTES", "NotUTF8Error", "check_design_file",
           "check_input_file", "file_kind", "read_design_text", "read_limited", "utf8_text"]

#: Largest design file (TOML) accepted, in bytes.
MAX_DESIGN_FILE_BYTES = 4 * 1024 * 1024

_KINDS = (
    (stat.S_ISDIR, "a folder"),
    (stat.S_ISFIFO, "a named pipe (FIFO)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


class InputFileError(ValueError):
    """An input path that is not a regular file, cannot be stat'ed, or is too large.

    Attributes
    ----------
    path : str
        The path as given.
    what : str
        The kind of input, e.g. ``"points file"``.
    reason : str
        Why it is refused, e.g. ``"it is a named pipe (FIFO), not a regular file"``
        or ``"No such file or directory"``.
    """

    def __init__(self, path: str, what: str, reason: str, message: str):
        super().__init__(message)
        self.path = path
        self.what = what
        self.reason = reason


def _size(n: int) -> str:
    """``n`` bytes as the messages write a limit: ``4194304 bytes (4 MiB)``."""
    mib = n / (1024 * 1024)
    return f"{n} bytes ({mib:g} MiB)" if n >= 1024 * 1024 and mib == int(mib) else f"{n} bytes"


def file_kind(mode: int) -> str:
    """What an ``st_mode`` is, in words: ``"a regular file"``, ``"a folder"``, ``"a named pipe (FIFO)"``."""
    if stat.S_ISREG(mode):
        return "a regular file"
    for test, name in _KINDS:
        if test(mode):
            return name
    return "not a regular file"  # pragma: no cover - no other kinds on POSIX


def check_input_file(path: str | os.PathLike[str], *, max_bytes: int, what: str) -> int:
    """Refuse ``path`` unless it is a regular file of at most ``max_bytes`` bytes.

    Only ``os.stat`` is called (it follows symbolic links): the file is not
    opened, so a FIFO or a device is refused at once.

    Parameters
    ----------
    path : str or path-like
        The input as the user named it.
    max_bytes : int
        The limit of this kind of input (e.g. :data:`MAX_DESIGN_FILE_BYTES`).
    what : str
        The kind of input, for the message (``"design file"``, ``"points file"``).

    Returns
    -------
    int
        The size of the file, in bytes.

    Raises
    ------
    InputFileError
        ``cannot read points file 'x.csv': No such file or directory``,
        ``points file 'designs' is a folder, not a file``,
        ``design file '/dev/zero' is a character device, not a regular file``,
        ``design file 'big.toml' is 209715200 bytes, more than the limit of 4194304 bytes (4 MiB)``.
    """
    p = os.fspath(path)
    try:
        st = os.stat(p)
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the path
        reason = (exc.strerror or str(exc)) if isinstance(exc, OSError) else "not a valid path"
        raise InputFileError(p, what, reason, f"cannot read {what} {p!r}: {reason}") from None
    if stat.S_ISDIR(st.st_mode):
        reason = "it is a folder, not a file"
        raise InputFileError(p, what, reason, f"{what} {p!r} is a folder, not a file")
    if not stat.S_ISREG(st.st_mode):
        kind = file_kind(st.st_mode)
        reason = f"it is {kind}, not a regular file"
        raise InputFileError(p, what, reason, f"{what} {p!r} is {kind}, not a regular file")
    if st.st_size > max_bytes:
        reason = f"it is {st.st_size} bytes, more than the limit of {_size(max_bytes)}"
        raise InputFileError(p, what, reason, f"{what} {p!r} is {st.st_size} bytes, more than the "
                                              f"limit of {_size(max_bytes)}")
    return int(st.st_size)


def read_limited(path: str | os.PathLike[str], *, max_bytes: int, what: str) -> bytes:
    """The bytes of ``path`` after :func:`check_input_file`; at most ``max_bytes`` are read.

    A file that grew past the limit since the check is refused too.

    Raises
    ------
    InputFileError
        See :func:`check_input_file`.
    OSError
        If the file cannot be opened or read.
    """
    check_input_file(path, max_bytes=max_bytes, what=what)
    p = os.fspath(path)
    # O_NONBLOCK: should the path have become a FIFO since the check, open() does not wait
    fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    with open(fd, "rb", closefd=True) as fh:
        mode = os.fstat(fh.fileno()).st_mode
        if not stat.S_ISREG(mode):
            kind = file_kind(mode)
            raise InputFileError(p, what, f"it is {kind}, not a regular file",
                                 f"{what} {p!r} is {kind}, not a regular file")
        data = fh.read(max_bytes + 1)
    if len(data) > max_bytes:
        reason = f"it is more than the limit of {_size(max_bytes)}"
        raise InputFileError(p, what, reason, f"{what} {p!r} is more than the limit of {_size(max_bytes)}")
    return data


class NotUTF8Error(ValueError):
    """Bytes that are not UTF-8 text: :attr:`where` says the first bad byte, its offset and its line
    (``byte 0x94 at offset 3, line 1``)."""

    def __init__(self, where: str) -> None:
        super().__init__(f"not a UTF-8 text file: {where}")
        self.where = where


def utf8_text(raw: bytes) -> str:
    """``raw`` decoded as UTF-8, a byte order mark at its start dropped.

    Raises
    ------
    NotUTF8Error
        Naming the first byte that is not UTF-8, its offset in ``raw`` and its line.
    """
    start = len(codecs.BOM_UTF8) if raw.startswith(codecs.BOM_UTF8) else 0
    try:
        return raw[start:].decode("utf-8")
    except UnicodeDecodeError as exc:
        at = start + exc.start
        line = raw.count(b"\n", 0, at) + 1
        raise NotUTF8Error(f"byte 0x{raw[at]:02x} at offset {at}, line {line}") from None


class DesignInputError(InputFileError, DesignFileError):
    """A design file refused by :func:`check_input_file`: both an :class:`InputFileError` and a
    :class:`~regimemap.io.toml_errors.DesignFileError`."""


def _design_error(exc: InputFileError) -> DesignInputError:
    return DesignInputError(exc.path, exc.what, exc.reason,
                            f"{exc.path}: cannot read the {exc.what}: {exc.reason}")


def check_design_file(path: str | os.PathLike[str]) -> int:
    """:func:`check_input_file` for a design file (at most :data:`MAX_DESIGN_FILE_BYTES`).

    Raises
    ------
    DesignInputError
        ``/dev/zero: cannot read the design file: it is a character device, not a regular file``.
    """
    try:
        return check_input_file(path, max_bytes=MAX_DESIGN_FILE_BYTES, what="design file")
    except InputFileError as exc:
        raise _design_error(exc) from None


def read_design_text(path: str | os.PathLike[str], what: str = "design file") -> str:
    """The text of a design file, after :func:`check_design_file` (UTF-8, newlines as ``\\n``,
    as ``Path.read_text`` gives them, and a byte order mark at its start dropped, as editors on
    Windows write one).  Every TOML file the tool reads -- a design file, a study file, a study's
    base design -- is read here.

    ``what`` names the file in the messages (``"study file"``).

    Raises
    ------
    DesignInputError
        See :func:`check_design_file`; also when the file is not UTF-8 (``/x.toml: cannot read the
        design file: not a UTF-8 text file: byte 0x94 at offset 3, line 1``).
    OSError
        If the file cannot be read.
    """
    try:
        data = read_limited(path, max_bytes=MAX_DESIGN_FILE_BYTES, what=what)
    except InputFileError as exc:
        raise _design_error(exc) from None
    try:
        text = utf8_text(data)
    except NotUTF8Error as exc:
        p = os.fspath(path)
        raise _design_error(InputFileError(p, what, str(exc), f"{what} {p!r}: {exc}")) from None
    return text.replace("\r\n", "\n").replace("\r", "\n")
