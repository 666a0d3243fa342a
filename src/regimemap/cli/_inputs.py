"""The click type of every argument and option that names an input file.

Before the command runs, the path is checked as the library's readers check it
(:func:`regimemap.io.inputs.check_input_file`: a regular file below the limit
of its kind, from ``os.stat`` alone): a folder, a FIFO, a device or an
oversize file is a usage error (exit 2) naming the argument, the path and the
reason, at once and without reading it.  A path that does not exist is left
to the command's reader, which refuses it the same way (exit 2) once the
command's own usage checks (options that exclude each other ...) have passed.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import click

from ._common import ParamType
from ._main import refusing

if TYPE_CHECKING:
    from ..caisson.file import Design

__all__ = ["InputFile", "DESIGN_FILE", "POINTS_FILE", "PULSE_FILE", "RECORD_FILE", "read_design_file"]


def _check(kind: str, path: str) -> None:
    """Refuse ``path`` as an input of ``kind`` ("design", "points", "pulse" or "record"); ValueError
    if so."""
    if kind == "design":
        from ..io.inputs import check_design_file

        check_design_file(path)
        return
    if kind == "record":
        from ..climate.file import check_record_file

        check_record_file(path)
        return
    from ..io.inputs import check_input_file

    if kind == "points":
        from ..maps import file_points as points

        check_input_file(path, max_bytes=points.MAX_POINTS_FILE_BYTES, what="points file")
    else:
        from ..motion import file_pulses as pulses

        check_input_file(path, max_bytes=pulses.MAX_PULSE_FILE_BYTES, what="pulse file")


class InputFile(ParamType):
    """An input file of one kind: a regular file below its size limit; the path (str) is kept."""

    def __init__(self, kind: str):
        if kind not in ("design", "points", "pulse", "record"):
            raise ValueError(f"kind must be 'design', 'points', 'pulse' or 'record', got {kind!r}")
        self.kind = kind
        self.name = "file"  # as click.Path(dir_okay=False) names itself

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        path = str(value)
        if not os.path.exists(path):  # the reader says so, after the command's own usage checks
            return path
        try:
            _check(self.kind, path)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)
        return path


#: A design file (TOML): ``caisson``, ``lifetime``, ``simulate --design``.
DESIGN_FILE = InputFile("design")
#: A points file (CSV): ``plot --points``, ``classify --points``.
POINTS_FILE = InputFile("points")
#: A pulse file (CSV): ``simulate --pulse-file``.
PULSE_FILE = InputFile("pulse")
#: A wave record (CSV, text, NDBC, NetCDF; gzip): ``climate``.
RECORD_FILE = InputFile("record")


def read_design_file(path: str, param_hint: str) -> Design:
    """:func:`regimemap.caisson.file.read_design` of ``path``; a file it refuses is a usage error (exit 2)
    naming the argument ``param_hint`` (``"'DESIGN.toml'"``, ``"'--design'"``)."""
    from ..caisson.file import DesignFileError, read_design

    with refusing(param_hint, DesignFileError):
        return read_design(path)
