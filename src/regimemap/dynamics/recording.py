"""The phases of every run of a batch and the time history of one, recorded step by step.

Used by :func:`regimemap.dynamics.simulate` (:mod:`regimemap.dynamics.stepper`); the records
become :attr:`Simulation.phases <regimemap.dynamics.Simulation.phases>` and
:class:`~regimemap.dynamics.History`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .contact import Phase
from .results import History

if TYPE_CHECKING:  # pragma: no cover
    from .batch import Batch, Step

__all__ = ["RunLog", "HISTORY_KEYS"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
CodeArray = NDArray[np.int8]

#: The columns of a time history.
HISTORY_KEYS = ("t", "x", "y", "theta", "vx", "vy", "omega", "k", "phase")


class RunLog:
    """The phases of every run and the time history of one, recorded step by step."""

    def __init__(self, b: Batch, record_phases: bool, history: int | None) -> None:
        self.n = b.size
        self.record_phases = record_phases
        self.runs: list[IntArray] = []
        self.codes: list[CodeArray] = []
        self.starts: list[FloatArray] = []
        self.which = history
        self.hist: dict[str, list[float]] | None = None
        if history is not None:
            if not 0 <= history < self.n:
                raise IndexError(f"history run {history} out of range (n = {self.n})")
            self.hist = {key: [] for key in HISTORY_KEYS}
            self.hist["t"].append(0.0)
            for key, arr in (("x", b.x), ("y", b.y), ("theta", b.th), ("vx", b.vx), ("vy", b.vy),
                             ("omega", b.om)):
                self.hist[key].append(float(arr[history]))
            self.hist["k"].append(0.0)
            self.hist["phase"].append(-1.0)

    def record(self, b: Batch, step: Step) -> None:
        """Log a step (before ``b.prev_code`` takes the new codes)."""
        code = step.code
        if self.record_phases:
            changed = code != b.prev_code
            if changed.any():
                self.runs.append(b.idx[changed])
                self.codes.append(code[changed])
                self.starts.append(step.t_start[changed])
        if self.hist is not None:
            where = np.flatnonzero(b.idx == self.which)
            if where.size:
                j = int(where[0])
                for key, arr in (("t", b.t), ("x", b.x), ("y", b.y), ("theta", b.th), ("vx", b.vx),
                                 ("vy", b.vy), ("omega", b.om), ("k", step.k)):
                    self.hist[key].append(float(arr[j]))
                self.hist["phase"].append(float(code[j]))

    def phases(self) -> list[list[tuple[str, float]]] | None:
        """Per run, its (phase label, start time) in order; None when not recorded."""
        if not self.record_phases:
            return None
        phases: list[list[tuple[str, float]]] = [[] for _ in range(self.n)]
        if self.runs:
            runs = np.concatenate(self.runs)
            codes = np.concatenate(self.codes)
            starts = np.concatenate(self.starts)
            for r_, c_, t_ in zip(runs.tolist(), codes.tolist(), starts.tolist(), strict=True):
                phases[r_].append((Phase(c_).label, t_))
        return phases

    def history(self) -> History | None:
        """The time history of the run asked for, if any."""
        if self.hist is None:
            return None
        return History(**{key: np.asarray(val) for key, val in self.hist.items() if key != "phase"},
                       phase=np.asarray(self.hist["phase"]).astype(np.int8))
