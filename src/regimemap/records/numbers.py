"""Numbers for people: floats rounded to 12 significant digits in text output.

The library keeps exact values (``PointResult``, ``MapData``, the ``.npz``
export); the text files and the JSON written for people round them, so that
``-0.5999999999999999`` reads ``-0.6`` and ``0.08250000000000002`` reads
``0.0825``.  Twelve digits keep every number the report's closed forms
produce well beyond what a map or a margin can tell.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: Significant digits of the numbers written as text (CSV, JSON).
DIGITS = 12


def round_sig(v: float, digits: int = DIGITS) -> float:
    """``v`` rounded to ``digits`` significant digits (non-finite values unchanged)."""
    v = float(v)
    if not math.isfinite(v) or v == 0.0:
        return v + 0.0
    return float(f"{v:.{digits}g}") + 0.0


def json_number(v: float, digits: int = DIGITS) -> float | None:
    """``v`` rounded as :func:`round_sig`, or ``None`` (JSON's null) if it is not finite."""
    v = float(v)
    return round_sig(v, digits) if math.isfinite(v) else None


def text(v: float, digits: int = DIGITS) -> str:
    """The shortest text of ``v`` rounded to ``digits`` significant digits (``repr`` style)."""
    return repr(round_sig(v, digits))


def rounded(obj: Any, digits: int = DIGITS) -> Any:
    """``obj`` (dicts, lists, numpy scalars and arrays) with every float rounded."""
    if isinstance(obj, dict):
        return {k: rounded(v, digits) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [rounded(v, digits) for v in obj]
    if isinstance(obj, np.ndarray):
        return rounded(obj.tolist(), digits)
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        return round_sig(float(obj), digits)
    return obj
