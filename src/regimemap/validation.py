"""Input checks shared by the library and the command line.

Every check raises :class:`ValueError` whose message names the parameter, the
value received and the allowed range, e.g.
``gamma must be a finite number > 0, got -1.0``.
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

__all__ = [
    "check_gamma",
    "check_kprime",
    "check_positive",
    "check_nonnegative_array",
    "check_axis",
    "check_resolution",
    "MAX_GRID_POINTS",
    "MAX_RESOLUTION",
]

#: Largest grid accepted by :func:`regimemap.label_grid` and the CLI
#: (points = rows x columns); 25 million points is about 25 MB of labels.
MAX_GRID_POINTS = 25_000_000
#: Largest number of samples along one axis of a map.
MAX_RESOLUTION = 5000


def _as_float(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        try:
            if isinstance(value, (str, bytes)) or isinstance(value, bool):
                raise TypeError
            value = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be a number, got {value!r}") from None
    return float(value)


def check_gamma(gamma: Any) -> float:
    """Return ``gamma`` (the aspect ratio H/B) as a float, or raise.

    Raises
    ------
    ValueError
        If gamma is not a finite number > 0.
    """
    g = _as_float("gamma", gamma)
    if not math.isfinite(g) or g <= 0.0:
        raise ValueError(f"gamma must be a finite number > 0, got {gamma!r}")
    return g


def check_kprime(kprime: Any) -> float:
    """Return ``kprime`` (the force height h/H) as a float, or raise.

    Raises
    ------
    ValueError
        If kprime is not a number in [-1, 1].
    """
    kp = _as_float("kprime", kprime)
    if not math.isfinite(kp) or not (-1.0 <= kp <= 1.0):
        raise ValueError(f"kprime must be a number in [-1, 1], got {kprime!r}")
    if kp == 0.0:
        kp = 0.0  # fold -0.0 into +0.0
    return kp


def check_positive(name: str, value: Any) -> float:
    """Return ``value`` as a float if it is finite and > 0, else raise."""
    v = _as_float(name, value)
    if not math.isfinite(v) or v <= 0.0:
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return v


def check_nonnegative_array(name: str, value: Any) -> np.ndarray:
    """Return ``value`` as a float64 array of finite numbers >= 0, else raise."""
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be numbers >= 0, got {value!r}") from None
    if arr.size and not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[0]
        raise ValueError(f"{name} must be finite numbers >= 0, got {bad!r}")
    if arr.size and np.any(arr < 0.0):
        bad = arr[arr < 0.0].ravel()[0]
        raise ValueError(f"{name} must be numbers >= 0, got {float(bad)!r}")
    return arr


def check_axis(name: str, value: Any) -> np.ndarray:
    """Return a 1-D axis of finite numbers >= 0, or raise."""
    arr = check_nonnegative_array(name, value)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array, got an array of shape {arr.shape}")
    return arr


def check_resolution(name: str, value: Any) -> int:
    """Return a number of samples along one axis, 2..MAX_RESOLUTION, or raise."""
    if isinstance(value, bool):
        raise ValueError(f"{name} must be a whole number in [2, {MAX_RESOLUTION}], got {value!r}")
    try:
        n = int(value)
        if n != value and not (isinstance(value, str) and str(n) == value.strip()):
            raise TypeError
    except (TypeError, ValueError, OverflowError):
        raise ValueError(
            f"{name} must be a whole number in [2, {MAX_RESOLUTION}], got {value!r}"
        ) from None
    if not 2 <= n <= MAX_RESOLUTION:
        raise ValueError(f"{name} must be a whole number in [2, {MAX_RESOLUTION}], got {value!r}")
    return n
