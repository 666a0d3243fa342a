"""A caisson from its design file to its point on the loaded map (``regimemap caisson``), in one folder.

Its input declaration, the design file (:mod:`.file`; the keys of ``[site]``,
``[wave]`` and ``[caisson]`` :mod:`.file_keys`, its errors :mod:`.file_errors`, the
values that are valid but implausible :mod:`.file_plausibility`, the commented
example :mod:`.file_example`); its run (:mod:`.run`: Goda's loads of
:mod:`regimemap.waves`, the loaded map, the design check); its record as text and
JSON (:mod:`.record`); its figure, the one-page design sheet (:mod:`.figures`).
The ``[lifetime]`` tables of the same file are the lifetime's
(:mod:`regimemap.lifetime.file`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ..io.toml_errors import DesignFileError
    from .figures.page import caisson_sheet
    from .file import Design, parse_design, read_design
    from .file_example import example_design_text
    from .run import CaissonError, CaissonNumbers, CaissonRecord, ImplausibleDesignError, run_caisson

__all__ = ["CaissonError", "CaissonNumbers", "CaissonRecord", "Design", "DesignFileError",
           "ImplausibleDesignError", "caisson_sheet", "example_design_text", "parse_design", "read_design",
           "run_caisson"]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
