"""The figures of a run of :func:`regimemap.motion.run.run_simulation`: its history and its GIF.

They read a :class:`~regimemap.motion.record.SimulationRecord` -- its time history, its
block and the inputs it came from (for the title) -- and draw with
:func:`~regimemap.motion.figures.history.motion_figure` and
:func:`~regimemap.motion.figures.history.write_block_animation`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from .history import motion_figure, write_block_animation

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ...dynamics.stepper import History
    from ..run import SimulationRecord

__all__ = ["simulation_animation", "simulation_figure", "simulation_title"]


def simulation_title(record: SimulationRecord) -> str:
    """The title of a run's figures: the pulse and the block (or the design file)."""
    inp, T = record.inputs, record.duration
    design, pulse_file, k_peak, mu = inp["design"], inp["pulse_file"], inp["k_peak"], inp["mu"]
    if design is not None:  # the file gives the block: the title says which, and fits
        return f"{Path(design).name}: design wave, k = {k_peak:.4g}, τ0 = {T:.4g} s; μ = {mu:.3g}"
    kprime = inp["kprime"]
    kp = "" if kprime is None else f", k' = {kprime:g}"
    what = (f"{inp['pulse']} pulse, k_peak = {k_peak:g}, T = {T:g} s" if pulse_file is None
            else f"pulse {Path(pulse_file).name}")
    return f"{what}; γ = {inp['gamma']:g}, B = {inp['half_width']:g} m, μ = {mu:g}{kp}"


def _history(record: SimulationRecord) -> History:
    if record.simulation.history is None:
        raise ValueError("the run kept no time history: run_simulation(..., history=True)")
    return record.simulation.history


def simulation_figure(record: SimulationRecord) -> Figure:
    """k(t), the slide of the base and theta(t) of a run kept with its history, the phases shaded."""
    return motion_figure(_history(record), H=record.H, alpha=record.alpha, duration=record.duration,
                         title=simulation_title(record))


def simulation_animation(path: str | os.PathLike[str], record: SimulationRecord
                         ) -> tuple[int, tuple[int, int], float]:
    """The block of a run moving, to scale, as a GIF written atomically to ``path``.

    Returns the number of frames, their size in pixels and the speed-up over real time
    (:func:`~regimemap.motion.figures.history.write_block_animation`).
    """
    kprime = record.inputs["kprime"]
    return write_block_animation(path, _history(record), B=record.inputs["half_width"], H=record.H,
                                 kprime=kprime if kprime is not None else 0.0, overturned=record.overturned,
                                 title=simulation_title(record))
