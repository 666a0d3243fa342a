"""Reading a user's text file with guards: one helper for the points and the pulse files.

A path that is not a regular file (a folder, a FIFO, a device), or a file
too large, unreadable or made of endless lines, is refused with a message
naming the file (and the line), never a traceback.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from typing import Any, TextIO

from .inputs import InputFileError, check_input_file

__all__ = ["MAX_LINE", "NUMBER", "guarded_lines", "open_text_file", "read_header"]

#: Longest line accepted, in characters.
MAX_LINE = 65536

#: A decimal number as written in a CSV file or on the command line (ASCII digits,
#: optional sign, fraction and exponent) or one of the words float() knows for
#: infinities and NaN (refused afterwards with a clearer message).  Python's
#: float() alone would also take "1_000" and non-ASCII digits.
NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|[+-]?(?:inf|infinity|nan)",
                    re.ASCII | re.IGNORECASE)


def open_text_file(path: str, what: str, max_bytes: int) -> TextIO:
    """Open ``path`` (a ``what``, e.g. "points file") as UTF-8 text; ValueError if it cannot be read.

    Only a regular file of at most ``max_bytes`` bytes is opened
    (:func:`regimemap.io.inputs.check_input_file`): a folder, a FIFO, a device
    or a larger file is refused before anything is read.

    Raises
    ------
    InputFileError
        A ValueError naming the path and the reason.
    """
    check_input_file(path, max_bytes=max_bytes, what=what)
    try:
        return open(path, newline="", encoding="utf-8-sig")
    except OSError as exc:
        raise InputFileError(path, what, exc.strerror or str(exc),
                             f"cannot read {what} {path!r}: {exc.strerror}") from None


def guarded_lines(fh: TextIO, path: str, what: str, max_bytes: int) -> Iterator[str]:
    """The lines of ``fh``, refusing endless lines and more than ``max_bytes`` (a file that grew
    since :func:`open_text_file` checked its size)."""
    total = 0
    number = 0
    while True:
        try:
            line = fh.readline(MAX_LINE + 1)
        except UnicodeDecodeError as exc:  # decoded a block at a time: the line is not known
            raise ValueError(f"{path}: not a UTF-8 text file (byte 0x{exc.object[exc.start]:02x}; save it "
                             "as UTF-8)") from None
        if not line:
            return
        number += 1
        if len(line) > MAX_LINE:
            raise ValueError(f"{path}, line {number}: not CSV text (a line longer than "
                             f"{MAX_LINE} characters)")
        total += len(line)
        if total > max_bytes:
            raise ValueError(f"{what} {path!r} is more than the limit of {max_bytes} bytes")
        yield line


def read_header(reader: Any, path: str, required: Sequence[str], known: Sequence[str]
                ) -> tuple[list[str], dict[str, int]]:
    """Read a CSV file's header (the first non-blank row) and find its columns.

    Parameters
    ----------
    reader : csv reader
        Over :func:`guarded_lines`; left at the first row after the header.
    path : str
        The file, for messages.
    required, known : sequence of str
        Columns that must be there (e.g. ``("k", "mu")``), and every column the
        caller reads (names are matched case-insensitively, blanks stripped).

    Returns
    -------
    (cols, idx)
        The header's names, lower case, and the position of each known column present.

    Raises
    ------
    ValueError
        Naming the file and the line: an empty file, NUL bytes, a missing or a
        repeated column.
    """
    header: list[str] | None = None
    for row in reader:
        if row and any(c.strip() for c in row):
            header = row
            break
    if header is None:
        raise ValueError(f"{path}: empty file; expected a header with columns {','.join(required)}")
    where = f"{path}, line {reader.line_num}"
    if any("\x00" in c for c in header):
        raise ValueError(f"{where}: not CSV text (NUL bytes; a binary file?)")
    cols = [h.strip().lower() for h in header]
    missing = [c for c in required if c not in cols]
    if missing:
        raise ValueError(
            f"{where}: missing column(s) {', '.join(missing)}; the header must name "
            f"{' and '.join(required)} (got {', '.join(repr(h) for h in header[:6])})")
    twice = [c for c in known if cols.count(c) > 1]
    if twice:
        raise ValueError(f"{where}: column(s) {', '.join(twice)} appear more than once")
    return cols, {c: cols.index(c) for c in known if c in cols}
