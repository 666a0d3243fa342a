"""JSON: the one writer of every record's JSON object, on standard output or in a file, atomically.

A record's builder (``caisson_json``, ``lifetime_json``, ...) makes the object JSON-ready:
its numbers rounded to 12 significant digits, ``null`` where one is not finite
(:func:`regimemap.records.numbers.rounded`).  Here it is written: never a ``NaN`` or an
``Infinity`` (``allow_nan=False``: a number that escaped the rounding is an error, not a file
no JSON reader takes).
"""

from __future__ import annotations

import json
import os
from typing import Any

from .atomic import atomic_open

__all__ = ["json_text", "write_json"]


def json_text(obj: Any, indent: int | None = 1, ascii_only: bool = True) -> str:
    """``obj`` as JSON text (no newline at the end); ``indent`` None for one line, ``ascii_only``
    False to keep non-ASCII characters as they are."""
    return json.dumps(obj, indent=indent, ensure_ascii=ascii_only, allow_nan=False)


def write_json(path: str | os.PathLike[str], obj: Any, indent: int | None = 1, ascii_only: bool = True
               ) -> None:
    """Write :func:`json_text` of ``obj`` and a newline to ``path`` (UTF-8), atomically."""
    text = json_text(obj, indent, ascii_only)
    with atomic_open(path, "w", encoding="utf-8") as fh:
        fh.write(text + "\n")
