"""One call per workflow: plain inputs in, one frozen record out.

Each command of the command line is one of these calls followed by writing
its record: a notebook user makes the call the command makes.  A workflow
reads its inputs through :mod:`regimemap.io` (a design file's path or the
objects themselves), computes through the evaluation packages (maps,
dynamics, lifetime, climate) and returns a record holding the inputs, the
intermediate quantities a designer checks, the warnings as data
(:class:`~regimemap.mechanics.notices.Notice`) and the results.  It prints
nothing and draws nothing: :mod:`regimemap.io` writes a record,
:mod:`regimemap.drawing` draws it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ._record import Field, Notice, Record
    from .study import StudyRecord, StudyRow, run_study

__all__ = ["Field", "Notice", "Record", "StudyRecord", "StudyRow", "run_study"]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, {
        "_record": ["Field", "Notice", "Record"],
        "study": ["StudyRecord", "StudyRow", "run_study"],
    })
