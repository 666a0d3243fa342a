"""A force history from a CSV file: columns ``t,k`` and optionally ``kprime``.

``t`` is the time in seconds (>= 0, strictly increasing), ``k`` the force over
m g at that time (positive pushes towards O), ``kprime`` the height of the
force over H_C (in [-1, 1]; it then replaces the block's k').  The history is
linearly interpolated between the samples and is zero after the last one
(:meth:`regimemap.dynamics.Pulse.from_arrays`).  Bad files are refused with the
file, the line and the column of the first problem, as for points files
(:mod:`regimemap.maps.file_points`).
"""

from __future__ import annotations

import csv
import math
import os

from ..dynamics.limits import INPUT_LIMITS
from ..dynamics.pulses import Pulse
from ..io.textfile import NUMBER, guarded_lines, open_text_file, read_header

__all__ = ["read_pulse_csv", "MAX_PULSE_SAMPLES", "MAX_PULSE_FILE_BYTES"]

#: Largest number of samples accepted from a pulse file.
MAX_PULSE_SAMPLES = 1_000_000
#: Largest pulse file accepted, in bytes (checked before opening it, and again while
#: reading; a path that is not a regular file is refused: :mod:`regimemap.io.inputs`).
MAX_PULSE_FILE_BYTES = 128 * 1024 * 1024


_COLUMNS = ("t", "k", "kprime")


def _value(text: str, what: str, where: str) -> float:
    lim = INPUT_LIMITS[what]
    rng = lim.text if what != "kprime" else "a number in [-1, 1]"
    if not text:
        raise ValueError(f"{where}: {what} is missing; it must be {rng}")
    if not NUMBER.fullmatch(text):
        raise ValueError(f"{where}: {what} must be {rng}, got {text!r} (not a number)")
    v = float(text)
    if not lim.contains(v):
        raise ValueError(f"{where}: {what} must be {rng}, got {text!r}")
    return v + 0.0


def read_pulse_csv(path: str | os.PathLike[str]) -> Pulse:
    """Read a sampled force history (a :class:`~regimemap.dynamics.Pulse` of shape ``arrays``).

    The header names ``t`` and ``k`` and optionally ``kprime`` (case-insensitive,
    any order; other columns are ignored).  Blank lines are skipped.  At least
    two samples, times from 0 up, strictly increasing, the last one > 0; at most
    :data:`MAX_PULSE_SAMPLES` samples and :data:`MAX_PULSE_FILE_BYTES` bytes.

    Raises
    ------
    ValueError
        Naming the file, the line and the column of the first bad value, or a
        missing or repeated column.
    """
    path = os.fspath(path)
    fh = open_text_file(path, "pulse file", MAX_PULSE_FILE_BYTES)
    ts: list[float] = []
    ks: list[float] = []
    kps: list[float] = []
    with fh:
        reader = csv.reader(guarded_lines(fh, path, "pulse file", MAX_PULSE_FILE_BYTES))
        try:
            cols, idx = read_header(reader, path, ("t", "k"), _COLUMNS)
            has_kprime = "kprime" in idx
            for row in reader:
                line = reader.line_num
                if not row or all(not c.strip() for c in row):
                    continue
                if len(row) < len(cols):
                    row = row + [""] * (len(cols) - len(row))
                where = f"{path}, line {line}"
                t = _value(row[idx["t"]].strip(), "t", f"{where}, column t")
                if ts and not t > ts[-1]:
                    raise ValueError(f"{where}, column t: times must increase, got {t:g} after {ts[-1]:g}")
                k = _value(row[idx["k"]].strip(), "k", f"{where}, column k")
                if has_kprime:
                    kps.append(_value(row[idx["kprime"]].strip(), "kprime", f"{where}, column kprime"))
                if len(ts) >= MAX_PULSE_SAMPLES:
                    raise ValueError(f"{where}: more than {MAX_PULSE_SAMPLES} samples (the limit)")
                ts.append(t)
                ks.append(k)
        except (csv.Error, UnicodeDecodeError) as exc:
            raise ValueError(f"{path}, line {reader.line_num + 1}: not CSV text ({exc})") from None
    if len(ts) < 2:
        raise ValueError(f"{path}: {len(ts)} sample(s); a pulse needs at least two rows t,k")
    if not math.isfinite(ts[-1]) or ts[-1] <= 0.0:  # pragma: no cover - increasing times from >= 0
        raise ValueError(f"{path}: the last time must be > 0")
    return Pulse.from_arrays(ts, ks, kps if has_kprime else None)
