"""A whole breakwater under a rising sea (``regimemap study``), in one folder.

Its input declaration, the study file (:mod:`.file`; its keys, sections and
scenarios :mod:`.file_sections`, their limits :mod:`.file_limits`, the commented
example :mod:`.file_example`); its run (:mod:`.run`, one task per section and
scenario :mod:`.run_tasks`); its record (:mod:`.record`, kept as it runs in
:mod:`.record_store`, written as a table :mod:`.record_table` or a NetCDF file
:mod:`.record_netcdf`); its figures (:mod:`.figures`, :mod:`.figures_style`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .figures import study_figure
    from .file import Study, read_study
    from .file_example import example_study_text
    from .file_sections import StudyFileError
    from .record import StudyCheck, StudyRecord, StudyRow
    from .run import run_study

__all__ = ["Study", "StudyCheck", "StudyFileError", "StudyRecord", "StudyRow", "example_study_text",
           "read_study", "run_study", "study_figure"]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
