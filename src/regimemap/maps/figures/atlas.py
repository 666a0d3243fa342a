"""Many maps at once: an atlas of small multiples, rows gamma and columns k' (or a load).

:func:`atlas_figure` draws the all-mode map (:func:`regimemap.maps.figures.mapplot.draw_map`)
for every pair of a list of gamma (rows) and a list of k' (columns), on
shared axes, with one legend and each panel titled with its gamma and k';
:func:`write_atlas` writes it to a file atomically.  The panels' blocks, the
views they share and their maps are computed by
:func:`regimemap.maps.run_atlas.run_atlas` and handed over in its record; the
animation over k' is :mod:`regimemap.maps.figures.animation`.  Limit:
:data:`MAX_PANELS` panels.

matplotlib is imported inside the functions that draw, never at import time.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ...drawing.limits import ATLAS_DPI, ATLAS_DPI_RANGE, MAX_PANELS
from ...mechanics.modes import LOADED_MAP_MODES, MAP_MODES, Mode
from ...records.numbers import short
from ..describe import format_value
from ..sweeps import SWEEPS

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ...drawing.artists import MapArtists
    from ..mapdata import MapData
    from ..run_atlas import AtlasRecord
    from .mapplot import MapStyle

__all__ = [
    "ATLAS_DPI",
    "ATLAS_DPI_RANGE",
    "MAX_PANELS",
    "PANEL_SIZE",
    "atlas_figure",
    "key_modes",
    "sweep_text",
    "write_atlas",
]

#: Size of one atlas panel in inches (width, height).
PANEL_SIZE: tuple[float, float] = (2.7, 2.35)

def sweep_text(sweep: str, value: float) -> str:
    r"""``$k' = 0.4$``, ``$\beta = 0.3$``: the swept quantity of a panel or frame (mathtext).

    Parameters
    ----------
    sweep : str
        ``"kprime"`` or a load of :data:`regimemap.maps.sweeps.SWEEPS`.
    value : float

    Returns
    -------
    str
    """
    sym = SWEEPS[sweep][0]
    return rf"${sym} = {format_value(value) if sweep != 'kprime' else short(value)}$"


def _legend_handles(modes: Sequence[Mode], dotted: bool = False) -> list[Any]:
    """The map key's handles (:func:`regimemap.maps.figures.key.key_handles`) for every mode."""
    from .key import key_handles

    return key_handles(modes, dotted_label=r"dotted line $\mu = k|k'|$ (4.22)" if dotted else None)


def _panel_title(g: float, kp: float, sweep: str = "kprime") -> str:
    return rf"$\gamma = {short(g)}$, " + sweep_text(sweep, kp)


def _fixed_text(sweep: str, fixed: dict[str, Any] | None) -> str:
    """What the panels or frames share besides gamma: k' (when a load is swept) and the loads."""
    if not fixed:
        return ""
    parts = [sweep_text(name, v) for name, v in fixed.items()
             if name != sweep and v is not None and not (name == "uplift_arm" and not (
                 fixed.get("uplift") or fixed.get("uplift_ratio") or sweep.startswith("uplift")))]
    return ", ".join(parts)


def key_modes(datas: Sequence[MapData]) -> tuple[Mode, ...]:
    """The modes shown by any of several maps, in code order (the key of an atlas or animation).

    Parameters
    ----------
    datas : sequence of MapData

    Returns
    -------
    tuple of Mode
    """
    shown = {m for d in datas for m, polys in d.polygons.items() if any(len(q) >= 3 for q in polys)}
    return tuple(m for m in LOADED_MAP_MODES if m in shown)


@dataclass(frozen=True)
class _Frame:
    """Where the panels of an atlas go (inches): figure size, margins, panel size and gaps."""

    fw: float
    fh: float
    left: float
    bottom: float
    pw: float
    ph: float
    wspace: float
    hspace: float
    nr: int

    def rect(self, i: int, j: int) -> tuple[float, float, float, float]:
        """The axes rectangle (figure fractions) of the panel in row ``i``, column ``j``."""
        x0 = (self.left + j * (self.pw + self.wspace)) / self.fw
        y0 = (self.bottom + (self.nr - 1 - i) * (self.ph + self.hspace)) / self.fh
        return (x0, y0, self.pw / self.fw, self.ph / self.fh)


def _frame(nr: int, nc: int, panel_size: tuple[float, float], share: str, tidy: bool,
           title_lines: int, key_rows: int) -> _Frame:
    """The layout: the key below the panels (0.1 in from the edge, ~0.2 in a row, then the
    bottom panels' tick labels and k), the title's lines above (~0.19 in each, below 0.15 in
    of margin, above the panels' titles) and room between panels for the tick labels and mu
    of the panel on the right."""
    top = max(0.7, 0.45 + 0.19 * title_lines)
    left, right, bottom = 0.62, 0.25 if tidy else 0.2, 0.62 + 0.2 * key_rows
    wspace = 0.3 if share == "all" else (0.72 if tidy else 0.5)
    hspace = 0.42 if share == "all" else 0.6
    pw, ph = panel_size
    fw = left + right + nc * pw + (nc - 1) * wspace
    fh = top + bottom + nr * ph + (nr - 1) * hspace
    return _Frame(fw, fh, left, bottom, pw, ph, wspace, hspace, nr)


def _key_of(datas: Sequence[MapData], loaded: bool, dotted: bool) -> list[Any]:
    """The figure's key: the modes any panel shows (with loads), else the six, and the lines."""
    from .key import key_handles

    if loaded:  # the key lists the modes the panels show (lift-off ...)
        labels = [d.curves["dotted"].label for d in datas if "dotted" in d.curves]
        return key_handles(key_modes(datas),
                           dotted_label=("dotted line " + labels[0]) if labels else None)
    return _legend_handles(MAP_MODES, dotted=dotted)


def _draw_panel(ax: Axes, data: MapData, style: MapStyle, title: str, where: tuple[int, int, int],
                share: str) -> MapArtists:
    """One panel: the map without its key and curve names, small texts, inner tick labels off.

    ``where`` is (row, column, rows).  The curves' names (mu*(k), mu = k|k'| ...) crowd a
    small panel and spill into the next one: the legend and the full map name them.
    """
    from .mapplot import draw_map

    i, j, nr = where
    art = draw_map(ax, data, replace(style, legend=False, title=title))
    for t in art.curve_labels.values():
        t.remove()
    art.curve_labels.clear()
    for t in set(art.off_view.values()):
        t.set_fontsize(6.5)
    ax.title.set_fontsize(9)
    ax.xaxis.label.set_fontsize(10)
    ax.yaxis.label.set_fontsize(10)
    ax.tick_params(labelsize=7.5)
    inner_x = share == "all" and i < nr - 1
    inner_y = (share == "all" or share == "row") and j > 0
    if inner_x:
        ax.tick_params(labelbottom=False)
        ax.set_xlabel("")
    if inner_y:
        ax.tick_params(labelleft=False)
        ax.set_ylabel("")
    ax.set_gid(f"panel-{i}-{j}")
    return art


def _draw_panels(fig: Figure, frame: _Frame, datas: Sequence[Sequence[MapData]],
                 titles: Sequence[Sequence[str]], style: MapStyle, share: str) -> list[MapArtists]:
    """Every panel, in row-major order, on axes shared as ``share`` says."""
    shared: Axes | None = None
    row_first: Axes | None = None
    arts = []
    for i, row in enumerate(datas):
        for j, data in enumerate(row):
            kw: dict[str, Any] = {}
            if share == "all" and shared is not None:
                kw = {"sharex": shared, "sharey": shared}
            elif share == "row" and j > 0 and row_first is not None:
                kw = {"sharex": row_first, "sharey": row_first}
            ax = fig.add_axes(frame.rect(i, j), **kw)
            shared = ax if shared is None else shared
            row_first = ax if j == 0 else row_first
            arts.append(_draw_panel(ax, data, style, titles[i][j], (i, j, frame.nr), share))
    return arts


def atlas_figure(record: AtlasRecord, *, dpi: float = ATLAS_DPI, style: MapStyle | None = None,
                 caption: str | None = None,
                 panel_size: tuple[float, float] = PANEL_SIZE) -> Figure:
    """Small multiples of the all-mode map: rows gamma, columns k' (or a load).

    Parameters
    ----------
    record : AtlasRecord
        The panels: their blocks, views and maps (:func:`regimemap.maps.run_atlas.run_atlas`).
    dpi : float
        Resolution of raster output.
    style : MapStyle, optional
        How each panel is drawn (:class:`~regimemap.maps.figures.mapplot.MapStyle`):
        its ``curves`` (boundary curves and named points, as computed), ``labels``
        (mode symbols), ``hatches`` and ``tidy`` (mark the points off view and move
        any text that collides, :func:`regimemap.drawing.text.tidy.tidy_figure`; False
        leaves every label where :func:`~regimemap.maps.figures.mapplot.draw_map` put
        it).  Each panel has its own title and no key: the figure has one.
    caption : str, optional
        A first line of the title (a figure's number and caption); the top
        margin makes room for every line of the title.
    panel_size : (float, float)
        The size of one panel in inches.

    Returns
    -------
    matplotlib.figure.Figure
        With an Agg canvas (no pyplot); one Axes per panel, in row-major
        order, each with the title ``gamma = ..., k' = ...``, and one legend.
        When a shared view would cram panels, each has its own and the title says so.
    """
    from ...drawing.style import agg_figure, style_context
    from .key import key_legend
    from .mapplot import MapStyle

    style = MapStyle() if style is None else style
    pw, ph = float(panel_size[0]), float(panel_size[1])
    gammas, kprimes, sweep, fixed = record.gammas, record.values, record.sweep, record.fixed
    share, crammed, datas = record.share, record.crammed, record.maps
    nr, nc = len(gammas), len(kprimes)
    loaded = record.loaded
    handles = _key_of([d for row in datas for d in row], loaded, style.curves and min(
        p.kprime for row in record.blocks for p in row) < 0.0)
    title = _atlas_title(caption, sweep, fixed, share, crammed, loaded)
    key_cols = min(4, max(2, nc))
    # the title's lines, and one more for a long line wrapped to fit
    frame = _frame(nr, nc, (pw, ph), share, style.tidy, title.count("\n") + 1 + (1 if crammed else 0),
                   -(-len(handles) // key_cols))
    titles = [[_panel_title(g, kp, sweep) for kp in kprimes] for g in gammas]
    with style_context():
        fig = agg_figure(figsize=(frame.fw, frame.fh), dpi=dpi)
        arts = _draw_panels(fig, frame, datas, titles, style, share)
        key_legend(fig, handles, loc="lower center", ncols=key_cols,
                   bbox_to_anchor=(0.5, 0.1 / frame.fh), fontsize=8, frameon=False,
                   handleheight=1.1, columnspacing=1.5)
        fig.suptitle(title, fontsize=10.5, y=1.0 - 0.15 / frame.fh, va="top")
        if style.tidy:
            from ...drawing.text.tidy import tidy_figure

            tidy_figure(fig, arts)
    fig._regimemap_maps = arts  # type: ignore[attr-defined]  # what each panel drew
    return fig


def _atlas_title(caption: str | None, sweep: str, fixed: dict[str, Any] | None, share: str,
                 crammed: Sequence[tuple[float, float]], loaded: bool) -> str:
    """The suptitle: the caption, what rows and columns are, what the panels share, the crammed."""
    columns = r"$k' = h/H$" if sweep == "kprime" else (
        f"${SWEEPS[sweep][0]}$ ({SWEEPS[sweep][1]})")
    title = caption + "\n" if caption else ""
    title += (rf"Regime maps: rows $\gamma = H/B$, columns {columns}"
              + ("" if share == "none" else
                 f" (axes shared {'across the figure' if share == 'all' else 'in each row'})"))
    shared_text = _fixed_text(sweep, fixed) if loaded or sweep != "kprime" else ""
    if shared_text:
        title += "\n" + shared_text
    if crammed:
        names = "; ".join(rf"$\gamma = {short(g)}$, {sweep_text(sweep, v)}"
                          for g, v in crammed[:3])
        more = f" and {len(crammed) - 3} more" if len(crammed) > 3 else ""
        title += ("\neach panel has its own view: a shared one would cram " + names + more
                  + " into a corner")
    return title


def write_atlas(path: str | os.PathLike[str], record: AtlasRecord, *, fmt: str | None = None,
                dpi: float | None = None, **kwargs: Any) -> Path:
    """Draw :func:`atlas_figure` and save it atomically (png, svg or pdf).

    Parameters
    ----------
    path : path-like
        The file; its suffix gives the format unless ``fmt`` does.
    record : AtlasRecord
        The panels (:func:`regimemap.maps.run_atlas.run_atlas`).
    fmt : {"png", "svg", "pdf"}, optional
    dpi : float, optional
        Resolution of PNG output (default: the figure's, given in ``kwargs``).
    **kwargs
        The other keywords of :func:`atlas_figure`.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        For an unknown format (before anything is drawn).
    OSError
        If the file cannot be written (nothing is left behind).
    """
    from ...drawing.save import format_from_path, save_figure

    fmt = format_from_path(path, fmt)
    fig = atlas_figure(record, **kwargs)
    return save_figure(fig, path, fmt=fmt, dpi=dpi)
