"""The figures of a whole breakwater (``regimemap study``): the expected sliding distance along the
chainage, one section's sliding by service year, the width for the target along the chainage, a
line per climate scenario (:mod:`.figures`), and the scenarios' look (:mod:`.style`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .figures import FIGURE_KINDS, study_figure

__all__ = ["FIGURE_KINDS", "study_figure"]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, {"figures": ["FIGURE_KINDS", "study_figure"]})
