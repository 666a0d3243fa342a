"""The options of ``regimemap lifetime`` that the design file does not hold, checked.

:func:`parse_widths` (``--width A:B:N``, within the plausible widths of a caisson),
:func:`check_target`, :func:`check_tolerance`, :func:`check_chunk` and
:func:`check_scheduler`: each returns the value or raises ValueError with the
range, for the command line to report as a usage error.
"""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from ..caisson.file import MAX_TRIALS
from ..caisson.file_plausibility import RANGES

__all__ = ["MAX_WIDTHS", "WIDTH_RANGE", "check_chunk", "check_scheduler", "check_target", "check_tolerance",
           "parse_widths"]

#: Most widths of a design chart (each one is simulated with every lifetime).
MAX_WIDTHS = 200
#: The widths a design chart may span [m]: the plausible widths of a caisson (those of
#: :data:`regimemap.caisson.file_plausibility.RANGES`; real caissons are 10-40 m wide).
WIDTH_RANGE: tuple[float, float] = (RANGES["width"][0], RANGES["width"][1])


def parse_widths(text: str) -> list[float]:
    """``A:B:N``: ``N`` widths from ``A`` to ``B`` metres, both included (a design chart).

    Raises
    ------
    ValueError
        Unless ``A < B`` are finite numbers within :data:`WIDTH_RANGE` and
        ``N`` a whole number in [2, :data:`MAX_WIDTHS`]; the message names what
        is accepted.
    """
    lo, hi = WIDTH_RANGE
    accepted = (f"A:B:N, N widths from A to B metres ({lo:g} <= A < B <= {hi:g}, the widths of "
                f"caissons; N a whole number from 2 to {MAX_WIDTHS}), e.g. 10:25:16")
    parts = str(text).split(":")
    if len(parts) != 3:
        raise ValueError(f"widths must be {accepted}; got {text!r}")
    try:
        a, b = float(parts[0]), float(parts[1])
    except ValueError:
        raise ValueError(f"widths must be {accepted}; got {text!r} (A or B is not a number)") from None
    try:
        n = int(parts[2].strip(), 10)
    except ValueError:
        raise ValueError(f"widths must be {accepted}; got {text!r} (N is not a whole number)") from None
    if not (math.isfinite(a) and math.isfinite(b) and a < b):
        raise ValueError(f"widths must be {accepted}; got {text!r} (need A < B)")
    if a < lo or b > hi:
        raise ValueError(f"widths must be {accepted}; got {text!r} (outside the {lo:g}-{hi:g} m "
                         "of caisson widths)")
    if not 2 <= n <= MAX_WIDTHS:
        raise ValueError(f"widths must be {accepted}; got {text!r} (N = {n})")
    return [float(w) for w in np.linspace(a, b, n)]


def check_target(value: Any) -> float:
    """The tolerable expected sliding distance of a design chart: a finite number > 0 [m]."""
    accepted = "a tolerable expected sliding distance > 0 in metres (e.g. 0.1, Goda & Takagi 2000)"
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"target must be {accepted}, got {value!r} (not a number)") from None
    if isinstance(value, bool) or not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"target must be {accepted}, got {value!r}")
    return x


def check_tolerance(value: Any) -> float:
    """The tolerance of the width for the target: a finite number in [0.001, 10] metres."""
    accepted = "a tolerance of the width for the target, 0.001 <= tolerance <= 10 in metres (default 0.05)"
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"width-tolerance must be {accepted}, got {value!r} (not a number)") from None
    if isinstance(value, bool) or not (math.isfinite(x) and 0.001 <= x <= 10.0):
        raise ValueError(f"width-tolerance must be {accepted}, got {value!r}")
    return x


def check_chunk(value: Any) -> int:
    """Lifetimes per unit of work: a whole number in [1, :data:`~regimemap.caisson.file.MAX_TRIALS`]."""
    accepted = f"a whole number of lifetimes per unit of work, 1 <= chunk <= {MAX_TRIALS}"
    try:
        n = int(str(value).strip(), 10)
    except ValueError:
        raise ValueError(f"chunk must be {accepted}, got {value!r} (not a whole number)") from None
    if isinstance(value, bool) or not 1 <= n <= MAX_TRIALS:
        raise ValueError(f"chunk must be {accepted}, got {value!r}")
    return n


#: ``[scheme://]host:port`` of a Dask scheduler (tcp, tls, ws, wss; the host may be [IPv6]);
#: Dask's other transports (``inproc://``, ``ucx://``) are passed on as they are.
_ADDRESS = re.compile(r"^(?:(?:tcp|tls|ws|wss)://)?(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):(\d{1,5})$")


def check_scheduler(address: str) -> str:
    """The address of a Dask scheduler, ``tcp://host:8786`` (the form only; not whether it answers).

    Raises
    ------
    ValueError
        For an empty address, or a tcp/tls/ws/wss address without a port in [1, 65535].
    """
    text = str(address).strip()
    accepted = "the address of a Dask scheduler, [tcp://]host:port, e.g. tcp://127.0.0.1:8786"
    if text.startswith(("inproc://", "ucx://")):
        return text
    m = _ADDRESS.match(text)
    if m is None or not 1 <= int(m.group(1)) <= 65535:
        raise ValueError(f"scheduler must be {accepted}; got {address!r}")
    return text
