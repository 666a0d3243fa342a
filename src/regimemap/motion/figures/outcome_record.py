"""The figure of an outcome map of :func:`regimemap.motion.run_maps.run_outcome` (``regimemap outcome``).

It reads an :class:`~regimemap.motion.record.OutcomeRecord` -- the map, its swept inputs,
their dimensionless values when the record has them, the fixed inputs for the title -- and
draws it with :func:`~regimemap.motion.figures.outcome.outcome_figure`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...drawing.save import DEFAULT_DPI
from .outcome import outcome_figure
from .outcome_words import axis_label, outcome_title

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..run_maps import OutcomeRecord

__all__ = ["outcome_record_figure"]


def outcome_record_figure(record: OutcomeRecord, *, dpi: float = DEFAULT_DPI) -> Figure:
    """The outcome map of ``record`` on a figure of its own: its axes labelled (dimensionless
    where the record has dimensionless axes), titled with its pulse and fixed inputs."""
    first, second = record.options.swept
    shape, dim = record.options.shape, record.dimensionless_axes
    title = outcome_title(shape, record.options.fixed, record.restitution, record.outcome.min_rotation)
    return outcome_figure(record.outcome, x=dim.get(first), y=dim.get(second),
                          xlabel=axis_label(first, first in dim, shape),
                          ylabel=axis_label(second, second in dim, shape), title=title, dpi=dpi)[0]
