"""One call per workflow: plain inputs in, one frozen record out.

Each command of the command line is one of these calls followed by writing
its record: a notebook user makes the call the command makes.  A workflow
reads its inputs through :mod:`regimemap.io` (a design file's path or the
objects themselves), computes through the evaluation packages (maps,
dynamics, lifetime, climate) and returns a record holding the inputs, the
intermediate quantities a designer checks, the warnings as data
(:class:`~regimemap.records.notices.Notice`) and the results.  It prints
nothing and draws nothing: :mod:`regimemap.io` writes a record,
:mod:`regimemap.drawing` draws it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ..caisson.run import CaissonError, CaissonNumbers, CaissonRecord, ImplausibleDesignError, run_caisson
    from ..climate.run import ClimateRecord, run_climate
    from ..lifetime.run import (
        ChartRecord,
        LifetimeDesign,
        LifetimeRecord,
        read_lifetime_design,
        run_chart,
        run_lifetime,
    )
    from ..maps.run import MapRecord, points_of_map, run_map
    from ..maps.run_atlas import AnimationRecord, AtlasRecord, run_animation, run_atlas
    from ..maps.run_query import QueryRecord, run_query
    from ..motion.run import SimulationRecord, run_simulation
    from ..motion.run_maps import DynamicsFigureRecord, OutcomeRecord, run_dynamics_figure, run_outcome
    from ..records.fields import Field, Record
    from ..records.notices import Notice
    from ..study.run import StudyRecord, StudyRow, run_study

__all__ = [
    "AnimationRecord",
    "AtlasRecord",
    "CaissonError",
    "CaissonNumbers",
    "CaissonRecord",
    "ChartRecord",
    "ClimateRecord",
    "DynamicsFigureRecord",
    "Field",
    "ImplausibleDesignError",
    "LifetimeDesign",
    "LifetimeRecord",
    "MapRecord",
    "Notice",
    "OutcomeRecord",
    "QueryRecord",
    "Record",
    "SimulationRecord",
    "StudyRecord",
    "StudyRow",
    "points_of_map",
    "read_lifetime_design",
    "run_animation",
    "run_atlas",
    "run_caisson",
    "run_chart",
    "run_climate",
    "run_dynamics_figure",
    "run_lifetime",
    "run_map",
    "run_outcome",
    "run_query",
    "run_simulation",
    "run_study",
]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
