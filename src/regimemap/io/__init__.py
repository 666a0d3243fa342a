"""Files in and out: atomic writes, design points from CSV, map export and figures to files.

Every writer here writes atomically (a temporary file in the same folder, then
a rename): a failed write leaves nothing behind.  Names are imported on first
use (``csv`` and matplotlib only when they are needed).
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = [
    "atomic_open",
    "atomic_path",
    "export_map",
    "format_result",
    "parse_point_spec",
    "read_points_csv",
    "read_pulse_csv",
    "result_row",
    "save_figure",
    "write_animation",
    "write_atlas",
    "write_history",
    "write_outcome",
]

_WHERE = {
    "atomic_open": "atomic",
    "atomic_path": "atomic",
    "export_map": "export",
    "format_result": "tables",
    "parse_point_spec": "points",
    "read_points_csv": "points",
    "result_row": "tables",
    "save_figure": "figures",
    "write_animation": "figures",
    "write_atlas": "figures",
    "read_pulse_csv": "pulses",
    "write_history": "dynamics",
    "write_outcome": "dynamics",
}


def __getattr__(name: str) -> Any:  # PEP 562
    if name in _WHERE:
        return getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
