"""Input checks shared by the library and the command line.

Every check raises :class:`ValueError` whose message names the parameter, the
value received and the allowed range, e.g.
``gamma must be a finite number in [0.001, 1000], got -1.0``.

Booleans, strings, ``None``, complex numbers and sequences are refused where a
number is expected (``float(True)`` and ``float("3")`` would otherwise slip
through); the command line converts its text arguments before checking them.
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

__all__ = [
    "check_gamma",
    "check_kprime",
    "check_loads",
    "check_weight",
    "check_positive",
    "check_nonnegative_array",
    "check_axis",
    "check_resolution",
    "MAX_GRID_POINTS",
    "MAX_RESOLUTION",
    "GAMMA_MIN",
    "GAMMA_MAX",
    "MAX_VALUE",
    "MAX_AXIS",
    "MIN_AXIS",
    "check_axis_end",
    "LOAD_LIMITS",
]

#: Largest grid accepted by :func:`regimemap.label_grid` and the CLI
#: (points = rows x columns); 25 million points is about 25 MB of labels.
MAX_GRID_POINTS = 25_000_000
#: Largest number of samples along one axis of a map.
MAX_RESOLUTION = 5000
#: Range of the aspect ratio gamma = H/B.  Beyond it gamma**2 under- or
#: overflows in the report's constants (a = 4 + g^2 - 3 g^2 k' ...), which
#: would give wrong labels or a division by zero; every real block is inside.
GAMMA_MIN = 1e-3
GAMMA_MAX = 1e3
#: Largest k, mu (and plot limit) accepted: above about 1e150 the products
#: a*k, c*k of the rule overflow to inf and the labels would be wrong.
MAX_VALUE = 1e100
#: Largest end of a plotted or exported axis (--k-max, --mu-max): the view is
#: sampled a little beyond it, and the samples must stay below MAX_VALUE.
MAX_AXIS = 1e6
#: Smallest end of a plotted or exported axis: near 1e-14 the other axis's automatic
#: end rounds to 0 and the view has no width.
MIN_AXIS = 1e-6
#: The loads of a block and their allowed ranges, as
#: ``name: (low, high, low open, high open)``: buoyancy beta in [0, 1) (beta = 1
#: floats the block), uplift u and its ratio nu to the push >= 0, the uplift's
#: arm e_u in [-1, 1] (a fraction of B from C towards O'), the radius of
#: gyration i >= 0.001 (over B; below, the solve's accelerations overflow) and the
#: crest (the top of the block over H) > 0,
#: which bounds kprime from above.  The upper ends keep the closed forms finite.
LOAD_LIMITS: dict[str, tuple[float, float, bool, bool]] = {
    "buoyancy": (0.0, 1.0, False, True),
    "uplift": (0.0, 1e6, False, False),
    "uplift_ratio": (0.0, 1e6, False, False),
    "uplift_arm": (-1.0, 1.0, False, False),
    "gyration": (1e-3, 1e3, False, False),
    "crest": (0.0, 1e3, True, False),
}
#: kprime closer to 0 than this is taken as 0 (a subnormal k' would make
#: gamma*|k'| underflow to 0 in 1/(gamma |k'|)); the map is the same.
_KPRIME_ZERO = 1e-300


def _describe(value: Any) -> str:
    """``repr`` of a bad value, short, with plain floats (``nan``, not ``np.float64(nan)``)."""
    if isinstance(value, (np.str_, np.bytes_)):
        value = value.item()
    if isinstance(value, np.bool_):
        text = repr(bool(value))
    elif isinstance(value, (float, np.floating)) and not isinstance(value, bool):
        text = repr(float(value))
    elif isinstance(value, np.integer):
        text = repr(int(value))
    elif isinstance(value, np.complexfloating):
        text = repr(complex(value))
    else:
        text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return text


def _is_number(value: Any) -> bool:
    """True for real numbers (Python or numpy, including 0-d numeric arrays), not for bools."""
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, (numbers.Real, np.floating, np.integer)):
        return True
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value.dtype.kind in "iuf"
    return False


def _as_float(name: str, value: Any, allowed: str) -> float:
    """``float(value)`` if ``value`` is a real number, else ValueError naming ``name`` and ``allowed``."""
    if not _is_number(value):
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)} (not a number)")
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):  # pragma: no cover - exotic numbers
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)}") from None


def check_gamma(gamma: Any) -> float:
    """Return ``gamma`` (the aspect ratio H/B) as a float, or raise.

    Raises
    ------
    ValueError
        If gamma is not a finite number in [GAMMA_MIN, GAMMA_MAX] = [0.001, 1000]
        (in particular if it is <= 0, NaN or infinite).
    """
    allowed = f"a finite number in [{GAMMA_MIN:g}, {GAMMA_MAX:g}]"
    g = _as_float("gamma", gamma, allowed)
    if not math.isfinite(g) or not (GAMMA_MIN <= g <= GAMMA_MAX):
        raise ValueError(f"gamma must be {allowed}, got {_describe(gamma)}")
    return g


def check_kprime(kprime: Any, crest: float = 1.0) -> float:
    """Return ``kprime`` (the force height h/H) as a float, or raise.

    Raises
    ------
    ValueError
        If kprime is not a number in [-1, crest] ([-1, 1] for the report's block).
    """
    allowed = f"a number in [-1, {crest:g}]"
    kp = _as_float("kprime", kprime, allowed)
    if not math.isfinite(kp) or not (-1.0 <= kp <= crest):
        raise ValueError(f"kprime must be {allowed}, got {_describe(kprime)}")
    if abs(kp) < _KPRIME_ZERO:
        kp = 0.0  # fold -0.0 (and subnormal values) into +0.0
    return kp


def _check_load(name: str, value: Any) -> float:
    lo, hi, lo_open, hi_open = LOAD_LIMITS[name]
    allowed = f"a number in {'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"
    v = _as_float(name, value, allowed)
    bad = (not math.isfinite(v) or v < lo or v > hi or (lo_open and v == lo) or (hi_open and v == hi))
    if bad:
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)}")
    return v + 0.0  # fold -0.0


def check_loads(buoyancy: Any = 0.0, uplift: Any = 0.0, uplift_ratio: Any = 0.0,
                uplift_arm: Any = 1.0 / 3.0, gyration: Any = None, crest: Any = 1.0
                ) -> tuple[float, float, float, float, float | None, float]:
    """Return the loads of a block as floats (gyration None stays None), or raise.

    Raises
    ------
    ValueError
        If a load is outside its range of :data:`LOAD_LIMITS`; the message names
        the load, the value received and the allowed range, e.g.
        ``buoyancy must be a number in [0, 1), got 1.0``.
    """
    return (_check_load("buoyancy", buoyancy), _check_load("uplift", uplift),
            _check_load("uplift_ratio", uplift_ratio), _check_load("uplift_arm", uplift_arm),
            None if gyration is None else _check_load("gyration", gyration),
            _check_load("crest", crest))


def check_weight(buoyancy: float, uplift: float, uplift_ratio: float) -> None:
    """Refuse a block that weighs nothing at every push: W = 1 - beta - u - nu k = 0 for all k.

    With buoyancy + uplift = 1 and no uplift ratio the normal force is zero whatever the
    push, so no friction holds the block and the map's lines mu = (q0 + q1 k)/W are
    undefined.  A block lighter or heavier than that (W0 < 0 lifts off, W0 > 0 rests) is
    mapped as usual.

    Raises
    ------
    ValueError
        Naming the uplift and the sum, e.g. ``uplift must not be 1 - buoyancy ...``.
    """
    if 1.0 - buoyancy - uplift == 0.0 and uplift_ratio == 0.0:
        raise ValueError(f"uplift must not be 1 - buoyancy when uplift_ratio is 0: the block would "
                         f"weigh nothing at every push (W = 1 - buoyancy - uplift = 0), got buoyancy "
                         f"{buoyancy:g} + uplift {uplift:g} = 1")


def check_positive(name: str, value: Any, hi: float = MAX_VALUE) -> float:
    """Return ``value`` as a float if it is > 0 and <= ``hi`` (default MAX_VALUE = 1e100), else raise."""
    allowed = f"a finite number > 0 (at most {hi:g})"
    v = _as_float(name, value, allowed)
    if not math.isfinite(v) or v <= 0.0 or v > hi:
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)}")
    return v


def check_axis_end(name: str, value: Any) -> float:
    """Return the end of a map's axis (``k_max``, ``mu_max``) as a float in [MIN_AXIS, MAX_AXIS], or raise."""
    allowed = f"a finite number in [{MIN_AXIS:g}, {MAX_AXIS:g}]"
    v = _as_float(name, value, allowed)
    if not MIN_AXIS <= v <= MAX_AXIS:
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)}")
    return v


def _as_float_array(name: str, value: Any) -> np.ndarray:
    """``value`` as a float64 array; bools, strings, None, complex and objects are refused."""
    allowed = _ARRAY_ALLOWED
    if value is None or isinstance(value, (str, bytes)):
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)} (not a number)")
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):  # ragged nested sequences
        raise ValueError(
            f"{name} must be {allowed}, got {_describe(value)} (not an array of numbers)") from None
    kind = raw.dtype.kind
    if kind == "O":
        for item in raw.flat:
            if item is None or isinstance(item, (bool, np.bool_, str, bytes, complex,
                                                 np.complexfloating)):
                raise ValueError(f"{name} must be {allowed}, got {_describe(item)} (not a number)")
    elif kind not in "iuf":
        what = {"b": "bool", "c": "complex", "U": "text", "S": "bytes",
                "M": "datetime", "m": "timedelta"}.get(kind, raw.dtype.name)
        bad = raw.flat[0] if raw.size and kind in "bcMm" else value
        raise ValueError(f"{name} must be {allowed}, got {_describe(bad)} ({what}, not a number)")
    try:
        return np.asarray(raw, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):  # pragma: no cover - exotic objects
        raise ValueError(f"{name} must be {allowed}, got {_describe(value)}") from None


_ARRAY_ALLOWED = f"finite numbers >= 0 (at most {MAX_VALUE:g})"


def _where(arr: np.ndarray, mask: np.ndarray) -> str:
    if arr.ndim == 0:
        return ""
    idx = np.unravel_index(int(np.flatnonzero(mask)[0]), arr.shape)
    return f" at index {idx[0] if len(idx) == 1 else tuple(int(i) for i in idx)}"


def check_nonnegative_array(name: str, value: Any) -> np.ndarray:
    """Return ``value`` as a float64 array of numbers in [0, MAX_VALUE], else raise.

    The message names ``name``, the first bad value and its index.  The check
    uses two reductions (min and max), so it allocates nothing of the size of
    ``value`` when all is well.
    """
    arr = _as_float_array(name, value)
    if arr.size:
        lo = arr.min()
        hi = arr.max()
        if not (math.isfinite(lo) and math.isfinite(hi)):
            mask = ~np.isfinite(arr)
        elif lo < 0.0:
            mask = arr < 0.0
        elif hi > MAX_VALUE:
            mask = arr > MAX_VALUE
        else:
            return arr
        bad = arr[mask].ravel()[0]
        raise ValueError(f"{name} must be {_ARRAY_ALLOWED}, got {_describe(bad)}{_where(arr, mask)}")
    return arr


def check_axis(name: str, value: Any, max_size: int = MAX_GRID_POINTS) -> np.ndarray:
    """Return a 1-D axis of at most ``max_size`` finite numbers >= 0, or raise.

    The shape and the size are checked before any value is looked at, so a
    huge axis is refused at once.
    """
    shape = np.shape(value) if isinstance(value, np.ndarray) else None
    if shape is not None:
        if len(shape) != 1:
            raise ValueError(f"{name} must be a 1-D array, got an array of shape {shape}")
        if shape[0] > max_size:
            raise ValueError(
                f"{name} has {shape[0]} values, more than the limit of {max_size} "
                "(MAX_GRID_POINTS)"
            )
    arr = check_nonnegative_array(name, value)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array, got an array of shape {arr.shape}")
    if arr.size > max_size:
        raise ValueError(
            f"{name} has {arr.size} values, more than the limit of {max_size} (MAX_GRID_POINTS)"
        )
    return arr


def check_resolution(name: str, value: Any) -> int:
    """Return a number of samples along one axis, 2..MAX_RESOLUTION, or raise.

    Accepts an int, a float with an integral value, or (from the command line)
    a string of digits.
    """
    msg = f"{name} must be a whole number in [2, {MAX_RESOLUTION}], got {_describe(value)}"
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(msg)
    try:
        if isinstance(value, str):
            text = value.strip()
            if not text.lstrip("+-").isdigit() or not text.isascii():
                raise ValueError
            n = int(text)
        elif isinstance(value, (numbers.Integral, np.integer)):
            n = int(value)
        elif isinstance(value, (numbers.Real, np.floating)):
            real = float(value)
            if not math.isfinite(real) or real != int(real):
                raise ValueError
            n = int(real)
        else:
            raise TypeError
    except (TypeError, ValueError, OverflowError):
        raise ValueError(msg) from None
    if not 2 <= n <= MAX_RESOLUTION:
        raise ValueError(msg)
    return n
