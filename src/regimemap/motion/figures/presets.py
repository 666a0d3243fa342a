"""The figures D.1-D.3 of :mod:`regimemap.dynamics.presets`, as ``regimemap dynamics-figures`` draws them.

:func:`regimemap.motion.run_maps.run_dynamics_figure` computes each map (or reads it from
the cache) and :func:`dynamics_figure` draws it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ...drawing.save import DEFAULT_DPI

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np
    from matplotlib.figure import Figure

    from ...dynamics.outcome import OutcomeMap
    from ...dynamics.presets import DynamicsFigure

__all__ = ["dynamics_figure"]


def dynamics_figure(figure: DynamicsFigure, data: tuple[OutcomeMap, np.ndarray, np.ndarray], *,
                    dpi: float = DEFAULT_DPI, fig: Figure | None = None) -> Figure:
    """The figure of one of D.1-D.3: its outcome map, axes labelled and titled.

    Parameters
    ----------
    figure : DynamicsFigure
        The figure's block, pulse and swept inputs (:data:`regimemap.dynamics.presets.DYNAMICS_FIGURES`).
    data : (OutcomeMap, ndarray, ndarray)
        The map and the values of its columns and rows as drawn, as
        :meth:`~regimemap.dynamics.presets.DynamicsFigure.compute` returns them.
    dpi : float
    fig : Figure, optional
        A figure to reuse.
    """
    from .outcome import axis_label, outcome_figure

    m, x, y = data
    if figure.dimensionless:
        xl, yl = axis_label("omega_p", True), axis_label("k_peak", True)
    else:
        xl, yl = axis_label(figure.first[0]), axis_label(figure.second[0])
    kwargs: dict[str, Any] = {"x": x, "y": y, "xlabel": xl, "ylabel": yl, "title": figure.title}
    return outcome_figure(m, dpi=dpi, fig=fig, **kwargs)[0]
