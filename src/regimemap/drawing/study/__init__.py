"""The figures of a whole breakwater (``regimemap study``): the expected sliding distance along the
chainage, one section's sliding by service year, the width for the target along the chainage, a
line per climate scenario (:mod:`.figures`), and the scenarios' look (:mod:`.style`).

A room of :mod:`regimemap.drawing` like the others (its modules are its API); the room's front
door re-exports :func:`~regimemap.drawing.study.figures.study_figure` (importing it imports no
matplotlib: the figures import it when they draw).
"""

from __future__ import annotations

from .figures import FIGURE_KINDS as FIGURE_KINDS
from .figures import study_figure as study_figure
