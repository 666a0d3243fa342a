"""The motion past initiation (``regimemap simulate``, ``outcome``, ``dynamics-figures``), in one folder.

Over the engine of :mod:`regimemap.dynamics`: the input declaration, a run and an
outcome map from flat options (:mod:`.file`) or a force history from a CSV file
(:mod:`.file_pulses`); the runs (:mod:`.run` one run, :mod:`.run_maps` an outcome
map and the figures D.1-D.3); the records (:mod:`.record`): a run's as text, JSON and a
time-history file (:mod:`.record_simulation`), an outcome map's as files
(:mod:`.record_outcome`); the figures (:mod:`.figures`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .figures.history import motion_figure
    from .figures.outcome import outcome_figure
    from .record import DynamicsFigureRecord, OutcomeRecord, SimulationRecord
    from .run import run_simulation
    from .run_maps import run_dynamics_figure, run_outcome

__all__ = ["DynamicsFigureRecord", "OutcomeRecord", "SimulationRecord", "motion_figure", "outcome_figure",
           "run_dynamics_figure", "run_outcome", "run_simulation"]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
