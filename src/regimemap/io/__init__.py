"""Files in and out: atomic writes, design points and pulses from CSV, wave records, map export, results.

Every writer here writes atomically (a temporary file in the same folder, then
a rename): a failed write leaves nothing behind.  This package sits below the
drawing layer: it reads and writes files and never draws (figures are written
by :func:`regimemap.drawing.save_figure`, which writes through
:func:`atomic_path`).  Names are imported on first use (``csv`` only when it
is needed); the ``if TYPE_CHECKING`` block gives type checkers and IDEs the
real names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ..climate.file import read_record
    from ..maps.file_points import parse_point_spec, read_points_csv
    from ..maps.record_export import export_map
    from ..maps.record_tables import format_result, result_row
    from ..motion.file_pulses import read_pulse_csv
    from ..motion.record_outcome import write_outcome
    from ..motion.record_simulation import write_history
    from .atomic import atomic_open, atomic_path

__all__ = [
    "atomic_open",
    "atomic_path",
    "export_map",
    "format_result",
    "parse_point_spec",
    "read_points_csv",
    "read_pulse_csv",
    "read_record",
    "result_row",
    "write_history",
    "write_outcome",
]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
