"""Numbers for people, written one way each: in files, in reports, in tables and on figures.

The library keeps exact values (``PointResult``, ``MapData``, the ``.npz``
export); the text files and the JSON written for people round them, so that
``-0.5999999999999999`` reads ``-0.6`` and ``0.08250000000000002`` reads
``0.0825`` (:func:`round_sig`, :func:`json_number`, :func:`text`, :func:`rounded`).  Twelve
digits keep every number the report's closed forms produce well beyond what a map or a
margin can tell.  A report's number keeps its trailing zeros (:func:`format_significant`), a
figure's label has a true minus (:func:`significant`), a notebook's table is plain
(:func:`number`, :func:`number_range`), and a parameter in a title is as short as Python
writes it (:func:`short`; with every digit it needs to read back, :func:`shortest`).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any, TypeVar

import numpy as np

__all__ = ["DIGITS", "format_significant", "json_number", "number", "number_range", "optional_float",
           "round_sig", "rounded", "short", "shortest", "significant", "text"]

#: Significant digits of the numbers written as text (CSV, JSON).
DIGITS = 12


#: A record's JSON object or list of objects.
_Tree = TypeVar("_Tree", dict[str, Any], list[Any])


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


def optional_float(v: float | None) -> float | None:
    """``v`` as a float, or ``None``: a whole number a file gives (``storms_per_year = 10``) is a
    float in a record's JSON (``10.0``), where :func:`rounded` keeps an int as it is."""
    return None if v is None else float(v)


def rounded(obj: _Tree, digits: int = DIGITS) -> _Tree:
    """A record's JSON object (or list) ready for JSON: every float in it, at any depth, rounded as
    :func:`json_number` (``None`` if not finite); numpy's numbers and arrays Python's, tuples lists;
    ints, bools, strings and ``None`` as they are.  The one rounding of every record's JSON."""
    out: _Tree = _rounded(obj, digits)
    return out


def _rounded(obj: Any, digits: int) -> Any:
    if isinstance(obj, dict):
        return {k: _rounded(v, digits) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_rounded(v, digits) for v in obj]
    if isinstance(obj, np.ndarray):
        return _rounded(obj.tolist(), digits)
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        return json_number(float(obj), digits)
    return obj


def format_significant(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant digits for a report: ``26210`` (not ``2.621e+04``), ``0.5200``.

    Trailing zeros are kept (they state the precision); a value that is not finite
    (an infinite heel pressure: no equilibrium) reads ``n/a``, never ``inf``; a value
    that rounds to zero reads ``0``.
    """
    if not math.isfinite(x):
        return "n/a"
    if 10.0 ** digits <= abs(float(f"{x:.{digits}g}")) < 1e12:  # 9999.7 to 4 digits: 10000
        s = f"{x:.0f}"
    else:
        s = f"{x:#.{digits}g}"
        if "e" not in s:
            s = s.rstrip(".")
    return "0" if float(s) == 0.0 else s


def significant(x: float, digits: int = 4) -> str:
    """:func:`format_significant` with a true minus sign, for a figure's label."""
    return format_significant(x, digits).replace("-", "\u2212")


def number(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant digits, plainly: ``0.2525``, ``1.2e+05``, ``n/a`` when not finite."""
    x = float(x)
    if not math.isfinite(x):
        return "n/a"
    text = f"{x:.{digits}g}"
    return "0" if float(text) == 0.0 else text


def number_range(values: Iterable[float], digits: int = 4) -> str:
    """One number, or ``lo \u2026 hi`` for several that differ (NaNs left out)."""
    finite = [float(v) for v in values if not math.isnan(float(v))]
    if not finite:
        return "n/a"
    lo, hi = min(finite), max(finite)
    if number(lo, digits) == number(hi, digits):
        return number(lo, digits)
    return f"{number(lo, digits)} \u2026 {number(hi, digits)}"


def short(x: float) -> str:
    """``x`` as Python's ``g`` format writes it (``0.5``, ``1e-05``): a parameter in a title."""
    return f"{x:g}"


def shortest(x: float) -> str:
    """``x`` as :func:`short` writes it when that reads back as ``x``, else every digit Python needs
    (``repr``): two different numbers never read the same (a return period in a table).

    Examples
    --------
    >>> shortest(50.0), shortest(1.0000001), shortest(0.1)
    ('50', '1.0000001', '0.1')
    """
    s = short(x)
    return s if float(s) == x else repr(float(x))
