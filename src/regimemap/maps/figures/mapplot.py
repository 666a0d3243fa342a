"""Draw a regime map with matplotlib, without pyplot and its global state.

:func:`draw_map` draws one :class:`~regimemap.maps.mapdata.MapData` (region
polygons, curves, named points: :func:`regimemap.maps.mapdata.compute_map`) on
an :class:`~matplotlib.axes.Axes`, as a :class:`MapStyle` asks; it computes
nothing (the figure functions of :mod:`regimemap.maps.figures.figure` compute the
data of a block and its view).  The texts are written by
:mod:`regimemap.drawing.text.labels`; what was drawn comes back as
:class:`~regimemap.drawing.artists.MapArtists`.

>>> from regimemap import Parameters
>>> from regimemap.drawing import render_map, save_figure
>>> from regimemap.workflows import run_map
>>> fig = render_map(run_map(Parameters(gamma=3, kprime=0.4)))
>>> save_figure(fig, "map.svg")  # doctest: +SKIP

Output is byte-stable: two renders of the same map give identical PNG, SVG
and PDF files (fixed ``svg.hashsalt``, no dates in the metadata), PDF fonts
are embedded as TrueType (``pdf.fonttype: 42``), and fills and lines are
vector paths in SVG and PDF.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from ...drawing.artists import MapArtists
from ...drawing.style import CONSTRUCTION, DOTTED, HATCH_LW, LINE_LW, MODE_STYLE
from ...drawing.text.labels import Frame, curve_labels, mark_off_view, name_points, region_labels
from ...drawing.text.placement import Box, view_points
from ...mechanics.block import Parameters
from ...mechanics.modes import MAP_MODES, Mode
from ...records.numbers import short
from ..describe import loads_text
from ..geometry import area_in_view
from ..mapdata import CurveData, MapData

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from ..points import DesignPoint

__all__ = [
    "MODE_STYLE",
    "MapArtists",
    "MapStyle",
    "draw_map",
    "draw_design_points",
    "default_title",
]


# zorders: fills < hatch < construction lines < boundaries < points < labels < design points
_Z_FILL, _Z_CONS, _Z_LINE, _Z_DESIGN = 1.0, 2.0, 2.5, 5.0


@dataclass(frozen=True)
class MapStyle:
    """How :func:`draw_map` draws a map: which layers, the title, the key's options.

    Attributes
    ----------
    curves : bool
        Draw the boundary curves and the report's named points (of the data:
        a :class:`~regimemap.maps.mapdata.MapData` computed without curves has none).
    labels : bool
        Write the mode symbol inside each region large enough to hold it (a
        thinner region gets its symbol on the band, or with a leader line).
    legend : bool
        Add a key of the shaded modes and of the line styles, below the axes.
    title : str, optional
        Axes title; default :func:`default_title`; ``""`` for none.
    hatches : bool
        Hatch the fills (distinct per mode, for greyscale print).
    tidy : bool
        Draw for people (default): characteristic points outside the view are
        marked at the frame's edge with an arrow and their coordinates, a thin
        region's symbol is framed on the band, and a dotted line that coincides
        with a boundary is left out (and out of the key).
        :func:`regimemap.drawing.text.tidy.tidy_figure` then moves any text that
        collides; the report's figures are drawn with ``tidy=False``.
    legend_kw : mapping, optional
        Extra keyword arguments of :meth:`~matplotlib.axes.Axes.legend`.

    Examples
    --------
    >>> MapStyle(legend=False, title="")
    MapStyle(curves=True, labels=True, legend=False, title='', hatches=True, tidy=True, legend_kw=None)
    """

    curves: bool = True
    labels: bool = True
    legend: bool = True
    title: str | None = None
    hatches: bool = True
    tidy: bool = True
    legend_kw: Mapping[str, Any] | None = None


def default_title(params: Parameters, *, modes: Sequence[Mode] | None = None,
                  raw: bool = False) -> str:
    """A caption-like title: what is shown, the report's case, and (gamma, k').

    Example: ``All modes, case 1, 0 <= k' <= (1+g^2)/(3g^2), a >= 0`` over
    ``(gamma = 3, k' = 0.2)``, in mathtext.  A block with loads is titled with
    its loads instead of the case: ``All modes, block with loads`` over
    ``(gamma = 0.7, k' = -0.018; beta = 0.318, nu = 0.524, e_u = 1/3)``.
    """
    modes = tuple(MAP_MODES if modes is None else modes)
    if raw and len(modes) == 1:
        what = f"Raw region of {modes[0].tex} ({modes[0].description}), before Section 4.7"
    elif raw:
        which = "all modes" if set(modes) >= set(MAP_MODES) else ", ".join(m.tex for m in modes)
        what = f"Raw regions of {which} (may overlap), before Section 4.7"
    elif set(modes) >= set(MAP_MODES) or len(modes) > 2:
        what = "All modes" if set(modes) >= set(MAP_MODES) else "Modes " + ", ".join(
            m.tex for m in modes)
    else:
        what = "Modes " + ", ".join(m.tex for m in modes)
    loads = loads_text(params, tex=True)
    if loads:  # a loaded block: the loads, not the report's case (which ignores them)
        return (f"{what}, block with loads\n"
                rf"($\gamma = {short(params.gamma)}$, $k' = {short(params.kprime)}$; {loads})")
    return (f"{what}, {params.case.tex}\n"
            rf"($\gamma = {short(params.gamma)}$, $k' = {short(params.kprime)}$)")



def _no_zero_formatter() -> Any:
    """Tick labels as usual, but none at 0 (the origin is named O, as in the report)."""
    from matplotlib.ticker import ScalarFormatter

    class NoZeroFormatter(ScalarFormatter):
        def __call__(self, x: float, pos: int | None = None) -> str:
            return "" if x == 0 else super().__call__(x, pos)

    return NoZeroFormatter()


def draw_map(ax: Axes, data: MapData, style: MapStyle | None = None) -> MapArtists:
    """Draw the map ``data`` on ``ax``, as ``style`` asks.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes of a :class:`~matplotlib.figure.Figure`; their limits become the view.
    data : MapData
        What the map shows (:func:`regimemap.maps.mapdata.compute_map`, or
        :func:`regimemap.maps.mapdata.map_for_view` for the designer's or the
        report's view of a block).
    style : MapStyle, optional
        Which layers, the title and the key (default :class:`MapStyle()`).

    Returns
    -------
    MapArtists
    """
    style = MapStyle() if style is None else style
    if style.tidy and style.curves:
        data = _without_coincident_lines(data)
    out = MapArtists(data=data)
    k_max, mu_max = data.k_max, data.mu_max
    frame = Frame(ax, k_max, mu_max)
    _axes(ax, data, style)
    for mode in data.modes:
        out.fills[mode] = _fills(ax, data, mode, style)

    obstacles: list[Box] = []
    lines: list[np.ndarray] = []
    # curves, the named points and their names, the points off view, the curves' labels
    if style.curves:
        for name, cd in data.curves.items():
            out.curves[name] = _curve(ax, name, cd)
        out.point_markers, out.point_labels = name_points(ax, data, frame, obstacles)
        if style.tidy:
            out.off_view = mark_off_view(ax, data.off_view, frame, obstacles)
        lines = [view_points(c.points, k_max, mu_max) for c in data.curves.values()]
        out.curve_labels = curve_labels(ax, data, frame, obstacles, lines)
    if style.labels:
        out.region_labels = region_labels(ax, data, frame, obstacles, lines, on_band=style.tidy)
    if style.legend:
        out.legend = _key(ax, data, style)

    title = style.title
    if title is None:
        title = default_title(data.params, modes=data.modes, raw=data.raw)
    if title:
        # an explicit y turns off matplotlib's automatic title placement, which
        # measures every tick label first (the layout here is fixed anyway)
        out.title = ax.set_title(title, fontsize=9.5, loc="left", pad=6, y=1.0)
    return out


def _axes(ax: Axes, data: MapData, style: MapStyle) -> None:
    """The view, the axis labels and the tick labels (none at 0 when O is named)."""
    ax.set_xlim(0.0, data.k_max)
    ax.set_ylim(0.0, data.mu_max)
    ax.set_xlabel("$k$", fontsize=12, labelpad=2)
    ax.set_ylabel(r"$\mu$", fontsize=12, labelpad=6, rotation=0, va="center")
    ax.tick_params(labelsize=9)
    if style.curves and "O" in data.points:
        ax.xaxis.set_major_formatter(_no_zero_formatter())
        ax.yaxis.set_major_formatter(_no_zero_formatter())


def _fills(ax: Axes, data: MapData, mode: Mode, style: MapStyle) -> list[Patch]:
    """The filled (and hatched) polygons of one mode's regions."""
    from matplotlib.patches import Polygon

    st = MODE_STYLE[mode]
    patches: list[Patch] = []
    for poly in data.polygons.get(mode, []):
        if len(poly) < 3:
            continue
        patch = Polygon(poly, closed=True, facecolor=st.color, edgecolor="none",
                        linewidth=0.0, hatch=st.hatch if style.hatches else None,
                        hatchcolor=st.hatch_color, zorder=_Z_FILL,
                        alpha=0.75 if data.raw and len(data.modes) > 1 else None,
                        label=f"_{mode.label}")
        patch.set_hatch_linewidth(HATCH_LW)
        ax.add_patch(patch)
        patches.append(patch)
    return patches


def _curve(ax: Axes, name: str, cd: CurveData) -> list[Line2D]:
    """One curve: its boundary runs solid, its construction runs dashed (or all dotted)."""
    from matplotlib.lines import Line2D

    pieces: list[Line2D] = []
    for pts, is_boundary in cd.runs():
        if cd.dotted:
            kw: dict[str, Any] = dict(DOTTED)
        elif is_boundary:
            kw = {"color": "black", "linewidth": LINE_LW}
        else:
            kw = dict(CONSTRUCTION)
        line = Line2D(pts[:, 0], pts[:, 1], zorder=_Z_LINE if is_boundary else _Z_CONS,
                      solid_capstyle="round", solid_joinstyle="round", label=f"_{name}", **kw)
        ax.add_line(line)
        pieces.append(line)
    return pieces


def _key(ax: Axes, data: MapData, style: MapStyle) -> Any:
    """The key below the axes: the modes seen in the view, then the line styles (None if empty)."""
    from .key import key_handles, key_legend

    # the key names the modes seen in the view (the polygons reach beyond it)
    seen = 1e-9 * data.k_max * data.mu_max
    shown = [m for m in data.modes
             if any(len(p) >= 3 and area_in_view(p, data.k_max, data.mu_max) > seen
                    for p in data.polygons.get(m, []))]
    plain = [c for c in data.curves.values() if not c.dotted] if style.curves else []
    dotted = [c for c in data.curves.values() if c.dotted] if style.curves else []
    handles = key_handles(
        shown, hatches=style.hatches, boundary=bool(plain or dotted),
        construction=any(not b for c in plain for _, b in c.runs()),
        dotted_label=("dotted line " + dotted[0].label) if dotted else None)
    kw = {
        "loc": "upper center", "bbox_to_anchor": (0.5, -0.135), "ncol": 2,
        "fontsize": 8.5, "frameon": False, "handleheight": 1.1,
        "columnspacing": 1.5, "borderaxespad": 0.0,
    }
    kw.update(style.legend_kw or {})
    return key_legend(ax, handles, **kw) if handles else None


def _without_coincident_lines(data: MapData) -> MapData:
    """``data`` without the dotted lines that coincide with another drawn curve.

    At k' = -1 the dotted line mu = k|k'| (4.22) is OA itself: drawn twice it
    would be invisible, and named in the key it would mislead.
    """
    drop = []
    for name, cd in data.curves.items():
        if not cd.dotted or len(cd.points) < 2:
            continue
        mine = view_points(cd.points, data.k_max, data.mu_max, 0.01)
        for other_name, other in data.curves.items():
            if other_name == name or other.dotted or len(other.points) < 2:
                continue
            theirs = view_points(other.points, data.k_max, data.mu_max, 0.002)
            d = np.hypot(*(mine[:, None, :] - theirs[None, :, :]).transpose(2, 0, 1)).min(axis=1)
            if float(d.max()) < 2e-3:
                drop.append(name)
                break
    if not drop:
        return data
    return replace(data, curves={n: c for n, c in data.curves.items() if n not in drop})



# -- design points ---------------------------------------------------------------------------


def draw_design_points(ax: Axes, points: Sequence[DesignPoint], *, fontsize: float = 8.5,
                       tagged: bool = True) -> list[Artist]:
    """Mark design points on a map: a black dot with a white rim and the point's name.

    Black with a white rim and a white-backed name reads on every fill colour,
    in colour and in greyscale.

    Parameters
    ----------
    ax : Axes
    points : sequence of DesignPoint
        Points (k, mu, name); unnamed points get no text.
    tagged : bool
        Give the artists the ids :func:`regimemap.drawing.text.tidy.tidy_figure`
        knows them by (``design-dots``, ``design-name``; default).  False
        draws them as the report's figures are drawn.

    Returns
    -------
    list of Artist
        The markers (one Line2D for all) and the name annotations.
    """
    artists: list[Any] = []
    if not points:
        return artists
    ks = [pt.k for pt in points]
    mus = [pt.mu for pt in points]
    (dots,) = ax.plot(ks, mus, linestyle="none", marker="o", markersize=6.0,
                      markerfacecolor="black", markeredgecolor="white", markeredgewidth=1.2,
                      zorder=_Z_DESIGN, label="_design points")
    if tagged:
        dots.set_gid("design-dots")
    artists.append(dots)
    for pt in points:
        if not pt.name:
            continue
        name = ax.annotate(
            pt.name, (pt.k, pt.mu), xytext=(5.0, 5.0), textcoords="offset points", ha="left",
            va="bottom", fontsize=fontsize, zorder=_Z_DESIGN,
            bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.2", "lw": 0.5,
                  "alpha": 0.9})
        if tagged:
            name.set_gid("design-name")
        artists.append(name)
    return artists
