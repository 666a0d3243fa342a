"""A map on a figure of its own: its size, layout around the key, and the report's figures.

:func:`map_figure` makes a Figure (Agg canvas, no pyplot)
with one map (a record of :func:`regimemap.maps.run.run_map`) drawn by
:func:`regimemap.maps.figures.mapplot.draw_map` and sized to
its key; :func:`render_preset` draws one of the report's figures.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from ...drawing.artists import MapArtists
from ...drawing.save import DEFAULT_DPI
from ...drawing.style import agg_figure, style_context
from ...drawing.text.tidy import tidy_figure
from ..mapdata import MapData
from .mapplot import MapStyle, draw_design_points, draw_map

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..ambiguity import AmbiguousRegion
    from ..points import DesignPoint
    from ..run import MapRecord
    from .presets import FigurePreset

__all__ = ["FIGSIZE", "fit_figure", "map_figure", "new_figure", "preset_figure",
           "render_map", "render_preset"]

#: Size of a map figure in inches (width, height): fits a page width at 100 %.
FIGSIZE: tuple[float, float] = (6.4, 5.6)


# -- figures -------------------------------------------------------------------------------

#: Layout of a map figure, in inches: width, axes size, margins, legend rows.
_W, _AX_W, _AX_H = 6.4, 5.5, 3.6
_LEFT, _TOP, _BOTTOM0, _ROW = 0.62, 0.62, 0.5, 0.2


def _size_for(rows: int, left: float = _LEFT
              ) -> tuple[float, float, tuple[float, float, float, float]]:
    """Figure (width, height) and axes rectangle (figure fractions) for ``rows`` legend rows."""
    bottom = _BOTTOM0 + rows * _ROW + (0.12 if rows else 0.0)
    h = _TOP + _AX_H + bottom
    w = _W + (left - _LEFT)
    return w, h, (left / w, bottom / h, _AX_W / w, _AX_H / h)


def _left_margin(ax: Axes) -> float:
    """Left margin (inches) that fits the mu tick labels and the axis label, without drawing."""
    lo, hi = ax.get_ylim()
    locs = [v for v in ax.yaxis.get_major_locator().tick_values(lo, hi) if lo <= v <= hi]
    fmt = ax.yaxis.get_major_formatter()
    try:
        fmt.set_locs(locs)
        labels = fmt.format_ticks(locs)
    except Exception:  # pragma: no cover - an exotic formatter
        labels = [f"{v:g}" for v in locs]
    n = max((len(t) for t in labels), default=3)
    return max(_LEFT, 0.26 + 0.075 * n)


def new_figure(figsize: tuple[float, float] | None = None, dpi: float = DEFAULT_DPI,
               fig: Figure | None = None) -> tuple[Figure, Axes]:
    """A Figure (Agg canvas, no pyplot) with one map Axes.

    Parameters
    ----------
    figsize : (float, float), optional
        Size in inches; default: :data:`FIGSIZE`, re-fitted to the legend by
        :func:`map_figure`.
    dpi : float
    fig : Figure, optional
        A figure to clear and reuse (keeps its canvas, renderer and their
        text caches: much faster when drawing many maps).
    """

    with style_context():
        reuse = None
        if fig is None:
            fig = agg_figure(figsize=figsize or FIGSIZE, dpi=dpi)
        else:
            if len(fig.axes) == 1 and not fig.texts and not fig.legends:
                reuse = fig.axes[0]  # clearing an Axes is cheaper than making one
            else:
                fig.clear()
            if fig.dpi != dpi:
                fig.set_dpi(dpi)
            if figsize is not None:
                fig.set_size_inches(figsize)
        w, h = fig.get_size_inches()
        rect = (_LEFT / w, 1.0 - (_TOP + _AX_H) / h, _AX_W / w, _AX_H / h)
        if reuse is not None:
            reuse.clear()
            reuse.set_position(rect)
            ax = reuse
        else:
            ax = fig.add_axes(rect)
    return fig, ax


def fit_figure(fig: Figure, ax: Axes) -> None:
    """Resize a map figure so the legend below the axes fits; the axes keep their size.

    Call it again after adding legend entries (e.g. after
    ``regimemap.render_ambiguity.draw_ambiguity``).
    """
    rows = 0
    legend = ax.get_legend()
    if legend is not None:
        n = len(legend.legend_handles)
        ncol = getattr(legend, "_ncols", 2)
        rows = -(-n // max(ncol, 1))
    w, h, rect = _size_for(rows, _left_margin(ax))
    if tuple(np.round(fig.get_size_inches(), 6)) != (round(w, 6), round(h, 6)):
        fig.set_size_inches(w, h)
    ax.set_position(rect)


def map_figure(record: MapRecord | MapData, *, style: MapStyle | None = None,
               figsize: tuple[float, float] | None = None, dpi: float = DEFAULT_DPI,
               points: Sequence[DesignPoint] | None = None, fig: Figure | None = None,
               **style_fields: Any) -> tuple[Figure, Axes, MapArtists]:
    """Draw a map on a new (or reused) Figure; return the figure, its axes and the artists.

    Parameters
    ----------
    record : MapRecord or MapData
        The map (:func:`regimemap.maps.run.run_map`, or its ``data``); a
        record's design points are marked, and its parts where several modes are
        admissible outlined when it has them.
    style : MapStyle, optional
        How the map is drawn (:func:`~regimemap.maps.figures.mapplot.draw_map`).
    figsize : (float, float), optional
        Size in inches; by default the axes are 5.5 x 3.6 inches and the
        figure's height is fitted to the key.
    dpi : float
    points : sequence of DesignPoint, optional
        Design points to mark (:func:`~regimemap.maps.figures.mapplot.draw_design_points`;
        default: the record's).
    fig : Figure, optional
        A figure to reuse (see :func:`new_figure`).
    **style_fields
        Fields of :class:`~regimemap.maps.figures.mapplot.MapStyle` (``title=``,
        ``legend=`` ...), over those of ``style``.

    Returns
    -------
    (Figure, Axes, MapArtists)

    Notes
    -----
    With ``tidy`` (the default) the title is fitted to the figure and any
    text that collides is moved (:func:`regimemap.drawing.text.tidy.tidy_figure`).

    Examples
    --------
    >>> from regimemap.mechanics.block import Parameters
    >>> from regimemap.workflows import run_map
    >>> fig, ax, art = map_figure(run_map(Parameters(3.0, 0.4), samples=51), dpi=40)
    >>> art.extent == (art.data.k_max, art.data.mu_max)
    True
    """
    style = replace(style or MapStyle(), **style_fields)
    data = record if isinstance(record, MapData) else record.data
    if points is None:
        points = () if isinstance(record, MapData) else record.points
    fig, ax = new_figure(figsize, dpi, fig)
    with style_context():
        artists = draw_map(ax, data, style)
        if points:
            artists.extra.extend(draw_design_points(ax, points, tagged=style.tidy))
        if figsize is None:
            fit_figure(fig, ax)
        if style.tidy:
            tidy_figure(fig, [artists])
    regions = None if isinstance(record, MapData) else record.ambiguity
    if regions is not None:
        _draw_ambiguity(fig, ax, artists, regions)
    return fig, ax, artists


def _draw_ambiguity(fig: Figure, ax: Axes, artists: MapArtists,
                    regions: Sequence[AmbiguousRegion]) -> None:
    """The overlay of where several modes are admissible, drawn on the map with its legend
    entries, the figure refitted and its labels tidied around the overlay."""
    from .ambiguity import draw_ambiguity

    k_max, mu_max = artists.extent
    with style_context():
        overlay = draw_ambiguity(ax, regions, k_max, mu_max) or []
        artists.extra.extend(overlay)
        artists.legend = ax.get_legend()  # rebuilt with one more entry
        fit_figure(fig, ax)  # the overlay may have added legend entries
        tidy_figure(fig, [artists], fixed=[a for a in overlay if hasattr(a, "get_text")])


def render_map(record: MapRecord | MapData, **kwargs: Any) -> Figure:
    """A Figure with the map of a record (the keywords of :func:`map_figure`)."""
    return map_figure(record, **kwargs)[0]


def preset_figure(preset: FigurePreset | str, record: MapRecord | MapData, *,
                  dpi: float = DEFAULT_DPI, hatches: bool = True, fig: Figure | None = None
                  ) -> tuple[Figure, Axes, MapArtists]:
    """One of the report's figures (:mod:`regimemap.maps.figures.presets`): figure, axes and artists.

    ``record`` is the preset's map in its own view (the report's, with its explicit
    axes): ``run_map(**preset.map_keywords)``
    (:func:`regimemap.maps.run.run_map`).  The title is the preset's, with the
    tidy pass of every map.  Pass the previous figure as ``fig`` to reuse it.
    """
    from .presets import get_preset

    if isinstance(preset, str):
        preset = get_preset(preset)
    return map_figure(record, dpi=dpi, fig=fig,
                      style=MapStyle(title=preset.title, hatches=hatches))


def render_preset(preset: FigurePreset | str, record: MapRecord | MapData, *,
                  dpi: float = DEFAULT_DPI, hatches: bool = True, fig: Figure | None = None
                  ) -> Figure:
    """A Figure of one of the report's figures (see :func:`preset_figure`)."""
    return preset_figure(preset, record, dpi=dpi, hatches=hatches, fig=fig)[0]
