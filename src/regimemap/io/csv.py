"""CSV: the one writer of every record's table, atomically, and its quoting.

A record's writer gives the header and the rows' text (each number written as that record
writes it: :func:`regimemap.records.numbers.text` for 12 digits, ``repr`` to read back
exactly); here they become a file: UTF-8, one ``\\n`` after each line, the header first,
written atomically (:func:`~regimemap.io.atomic.atomic_open`: a failed write leaves the old
file or none).  :func:`csv_line` quotes the cells that need it, as :mod:`csv` does.
"""

from __future__ import annotations

import io
import os
from collections.abc import Iterable, Sequence

from .atomic import atomic_open

__all__ = ["csv_line", "csv_text", "write_csv"]


def csv_line(cells: Sequence[str]) -> str:
    """One line of ``cells`` (no newline), each quoted only where it must be (a comma, a quote,
    a newline): :mod:`csv`'s ``excel`` dialect with ``\\n`` line ends.

    Examples
    --------
    >>> csv_line(["k", "0.5", 'a "b", c'])
    'k,0.5,"a ""b"", c"'
    """
    import csv  # only when writing CSV: keeps start-up light

    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(cells)
    return buf.getvalue()[:-1]


def csv_text(header: Sequence[str], rows: Iterable[str]) -> str:
    """The table as text: the header (:func:`csv_line`) and each of ``rows``, a ``\\n`` after each."""
    return "".join(f"{line}\n" for line in (csv_line(header), *rows))


def write_csv(path: str | os.PathLike[str], header: Sequence[str], rows: Iterable[str]) -> None:
    """Write the table to ``path``, atomically: the header (:func:`csv_line`), then each of
    ``rows`` -- the text of one row, or of several joined by ``\\n`` -- and a ``\\n`` after each."""
    with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
        fh.write(csv_line(header) + "\n")
        for row in rows:
            fh.write(row + "\n")
