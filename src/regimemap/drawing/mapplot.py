"""Draw regime maps with matplotlib, without pyplot and its global state.

Size: over 500 lines on purpose: :func:`draw_map` and its label helpers share one
frame of conversions (data, view fractions, points) and the offsets of the named points.

The numbers come from :mod:`regimemap.maps.mapdata` (region polygons, curves,
named points) and the labels are placed by :mod:`regimemap.drawing.placement`;
this module only turns them into artists.  Every drawing function takes an
:class:`~matplotlib.axes.Axes` and returns what it drew.

>>> from regimemap import Parameters
>>> from regimemap.drawing import render_map
>>> from regimemap.io import save_figure
>>> fig = render_map(Parameters(gamma=3, kprime=0.4))
>>> save_figure(fig, "map.svg")  # doctest: +SKIP

Output is byte-stable: two renders of the same map give identical PNG, SVG
and PDF files (fixed ``svg.hashsalt``, no dates in the metadata), PDF fonts
are embedded as TrueType (``pdf.fonttype: 42``), and fills and lines are
vector paths in SVG and PDF.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..maps.describe import loads_text
from ..maps.geometry import DEFAULT_SAMPLES, area_in_view
from ..maps.mapdata import MapData, compute_map
from ..mechanics.block import Parameters
from ..mechanics.modes import MAP_MODES, Mode
from .placement import (
    curve_label_anchor,
    interior_point,
    label_anchor,
    leader_label_anchor,
    overlaps,
    view_points,
)
from .style import CONSTRUCTION, DOTTED, HATCH_LW, LINE_LW, MODE_STYLE, mode_symbol, text_size

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.legend import Legend
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    from matplotlib.text import Text

    from ..maps.points import DesignPoint

__all__ = [
    "MODE_STYLE",
    "MapArtists",
    "draw_map",
    "draw_design_points",
    "default_title",
]



# zorders: fills < hatch < construction lines < boundaries < points < labels
_Z_FILL, _Z_CONS, _Z_LINE, _Z_POINT, _Z_LABEL, _Z_DESIGN = 1.0, 2.0, 2.5, 3.0, 4.0, 5.0


# -- the artists of one map ------------------------------------------------------------------


@dataclass
class MapArtists:
    """What :func:`draw_map` drew, and the data behind it.

    Attributes
    ----------
    data : MapData
        Polygons, curves, named points and extent (:mod:`regimemap.view`).
    fills : dict[Mode, list[Patch]]
        The region patches of each mode.
    curves : dict[str, list[Line2D]]
        Line pieces of each curve (boundary pieces solid, construction
        pieces dashed), by the report's name (``OA``, ``mu_star`` ...).
    curve_labels : dict[str, Text]
        Labels of the curves (``mu_star``: ":math:`\\mu^*(k)`" ...).
    region_labels : dict[Mode, list[Text]]
        Mode symbols written inside the regions.
    point_markers : dict[str, Line2D]
        Markers of the named points (``A``, ``B'`` ...).
    point_labels : dict[str, Text]
        Names of the points, and of line ends (``B``, ``C``).
    legend : Legend or None
    title : Text or None
    extra : list[Artist]
        Anything else drawn on the axes by regimemap (design points ...).
    off_view : dict[str, Text]
        Arrows at the frame's edge to the characteristic points outside the
        view, with their names and coordinates (``tidy`` maps only).
    """

    data: MapData
    fills: dict[Mode, list[Patch]] = field(default_factory=dict)
    curves: dict[str, list[Line2D]] = field(default_factory=dict)
    curve_labels: dict[str, Text] = field(default_factory=dict)
    region_labels: dict[Mode, list[Text]] = field(default_factory=dict)
    point_markers: dict[str, Line2D] = field(default_factory=dict)
    point_labels: dict[str, Text] = field(default_factory=dict)
    legend: Legend | None = None
    title: Text | None = None
    extra: list[Artist] = field(default_factory=list)
    off_view: dict[str, Text] = field(default_factory=dict)

    @property
    def extent(self) -> tuple[float, float]:
        """``(k_max, mu_max)`` of the view."""
        return (self.data.k_max, self.data.mu_max)

    @property
    def polygons(self) -> dict[Mode, list[np.ndarray]]:
        """The region polygons (k, mu) that the fills show."""
        return self.data.polygons


def _fmt(x: float) -> str:
    return f"{x:g}"


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
                rf"($\gamma = {_fmt(params.gamma)}$, $k' = {_fmt(params.kprime)}$; {loads})")
    return (f"{what}, {params.case.tex}\n"
            rf"($\gamma = {_fmt(params.gamma)}$, $k' = {_fmt(params.kprime)}$)")


def _point_text(name: str) -> str:
    """A point name as plain text with Unicode primes (B' -> B\u2032, C'' -> C\u2033).

    Drawn in the oblique face that mathtext uses for variables, so it looks
    like ``$B'$`` without the cost of parsing mathtext.
    """
    return name.replace("''", "\u2033").replace("'", "\u2032")


# Offsets (points) of the names of the report's points, chosen so that the
# name sits where the report writes it and off the lines through the point.
_POINT_OFFSET: dict[str, tuple[float, float, str, str]] = {
    "O": (-4.0, -4.0, "right", "top"),
    "A": (-5.0, 3.0, "right", "bottom"),
    "B'": (5.0, -3.0, "left", "top"),
    "C": (5.0, 0.0, "left", "center"),
    "C'": (5.0, -3.0, "left", "top"),
    "D": (3.0, 3.0, "left", "bottom"),
    "E": (3.0, 3.0, "left", "bottom"),
    "F": (-3.0, 3.0, "right", "bottom"),
    "G": (3.0, 3.0, "left", "bottom"),
}
_LEFT_OF = (-3.0, 3.0, "right", "bottom")
_RIGHT_OF = (3.0, 3.0, "left", "bottom")
_ABOVE = (0.0, 7.0, "center", "bottom")


def _point_offsets(points: dict[str, Any], frame: _Frame
                   ) -> dict[str, tuple[float, float, str, str]]:
    """Offsets of the point names; names of points close together on the k axis kept apart.

    D, E, F and G lie on the k axis and may nearly coincide (E and F at
    gamma = 3, k' = -0.2 are 0.05 apart).  Of two points closer than their
    names are wide, the left one is named on its left and the right one on its
    right; a point crowded on both sides is named above.
    """
    out = {name: _POINT_OFFSET.get(name, (4.0, 4.0, "left", "bottom")) for name in points}
    on_axis = sorted((pt.k, name) for name, pt in points.items() if pt.mu == 0.0 and name != "O")
    x = [k / frame.k_max * frame.w_pt for k, _ in on_axis]
    width = text_size("M", _POINT_FS)[0] + 6.0  # a name and the gaps either side (points)
    for i in range(len(on_axis) - 1):
        if x[i + 1] - x[i] >= width:
            continue
        left, right = on_axis[i][1], on_axis[i + 1][1]
        if out[left] == _RIGHT_OF and i > 0 and x[i] - x[i - 1] < width:
            out[left] = _ABOVE  # already pushed right by its left neighbour
        elif x[i] >= width:
            out[left] = _LEFT_OF
        else:
            out[left] = _ABOVE  # no room left of it, inside the axes
        out[right] = _RIGHT_OF
    return out


_REGION_FS = 11.0
_POINT_FS = 10.0
_CURVE_FS = 10.0


class _Frame:
    """Conversions between data, view fractions and points for one Axes (no drawing)."""

    def __init__(self, ax: Axes, k_max: float, mu_max: float):
        from matplotlib.figure import Figure

        fig = ax.figure
        if not isinstance(fig, Figure):  # a SubFigure has no size of its own
            raise TypeError("regimemap draws maps on the axes of a Figure, not of a SubFigure")
        w_in, h_in = fig.get_size_inches()
        pos = ax.get_position()
        self.w_pt = 72.0 * w_in * pos.width
        self.h_pt = 72.0 * h_in * pos.height
        self.k_max, self.mu_max = k_max, mu_max

    def box(self, k: float, mu: float, dx: float, dy: float, size: tuple[float, float],
            ha: str, va: str) -> tuple[float, float, float, float]:
        """Box (view fractions) of a text of ``size`` (points) at (k, mu) + (dx, dy) points."""
        x = k / self.k_max + dx / self.w_pt
        y = mu / self.mu_max + dy / self.h_pt
        w, h = size[0] / self.w_pt, size[1] / self.h_pt
        x0 = {"left": x, "right": x - w}.get(ha, x - w / 2)
        y0 = {"bottom": y, "top": y - h}.get(va, y - h / 2)
        return (x0, y0, x0 + w, y0 + h)


def _no_zero_formatter() -> Any:
    """Tick labels as usual, but none at 0 (the origin is named O, as in the report)."""
    from matplotlib.ticker import ScalarFormatter

    class NoZeroFormatter(ScalarFormatter):
        def __call__(self, x: float, pos: int | None = None) -> str:
            return "" if x == 0 else super().__call__(x, pos)

    return NoZeroFormatter()


def draw_map(ax: Axes, params: Parameters, *, k_max: float | None = None,
             mu_max: float | None = None, modes: Iterable[Mode] | None = None,
             raw: bool = False, curves: bool = True, labels: bool = True,
             legend: bool = True, title: str | None = None, samples: int = DEFAULT_SAMPLES,
             hatches: bool = True, include: Iterable[tuple[float, float]] = (),
             data: MapData | None = None, legend_kw: dict[str, Any] | None = None,
             view: str = "designer", tidy: bool = True) -> MapArtists:
    """Draw the regime map of ``params`` on ``ax``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    params : Parameters
    k_max, mu_max : float, optional
        The view ``[0, k_max] x [0, mu_max]`` (default :func:`regimemap.view.auto_extent`).
    modes : iterable of Mode, optional
        Modes to shade (default all six).
    raw : bool
        Shade the report's raw region of each mode (single-mode figures)
        instead of the final map.
    curves : bool
        Draw the boundary curves and the report's named points.
    labels : bool
        Write the mode symbol inside each region large enough to hold it (with
        a leader line when the region is too thin).
    legend : bool
        Add a legend of the shaded modes and of the line styles, below the axes.
    title : str, optional
        Axes title; default :func:`default_title`; ``""`` for none.
    samples : int
        Samples of k for polygons and curves.
    hatches : bool
        Hatch the fills (distinct per mode, for greyscale print).
    include : iterable of (k, mu)
        Points to keep in the automatic view.
    data : MapData, optional
        Precomputed :func:`regimemap.view.compute_map` result (the other data
        arguments are then ignored).
    legend_kw : dict, optional
        Extra keyword arguments of :meth:`~matplotlib.axes.Axes.legend`.
    view : {"designer", "report"}
        The default view (:func:`regimemap.maps.designer_view.view_extent`):
        mu up to 1.2 and every boundary that crosses that band, or every
        characteristic point of the map.  ``k_max``/``mu_max`` win over both.
    tidy : bool
        Draw for people (default): characteristic points outside the view are
        marked at the frame's edge with an arrow and their coordinates, and a
        dotted line that coincides with a boundary is left out (and out of the
        key).  :func:`regimemap.drawing.tidy.tidy_figure` then moves any text
        that collides; the report's figures are drawn with ``tidy=False``.

    Returns
    -------
    MapArtists
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon

    if data is None:
        include = list(include)
        if k_max is None or mu_max is None:
            from ..maps.designer_view import view_extent

            modes_t = tuple(MAP_MODES if modes is None else (Mode(m) for m in modes))
            if modes is not None:  # None: every mode the block shows (LO with loads)
                modes = modes_t
            raw_mode = modes_t[0] if raw and len(modes_t) == 1 else None
            k_max, mu_max = view_extent(params, view, raw_mode, include=include, k_max=k_max,
                                        mu_max=mu_max)
        data = compute_map(params, k_max=k_max, mu_max=mu_max, modes=modes, raw=raw,
                           samples=samples, curves=curves, include=include)
    if tidy and curves:
        data = _without_coincident_lines(data)
    out = MapArtists(data=data)
    k_max, mu_max = data.k_max, data.mu_max
    frame = _Frame(ax, k_max, mu_max)
    ax.set_xlim(0.0, k_max)
    ax.set_ylim(0.0, mu_max)
    ax.set_xlabel("$k$", fontsize=12, labelpad=2)
    ax.set_ylabel(r"$\mu$", fontsize=12, labelpad=6, rotation=0, va="center")
    ax.tick_params(labelsize=9)
    if curves and "O" in data.points:
        ax.xaxis.set_major_formatter(_no_zero_formatter())
        ax.yaxis.set_major_formatter(_no_zero_formatter())

    # fills
    for mode in data.modes:
        st = MODE_STYLE[mode]
        patches: list[Patch] = []
        for poly in data.polygons.get(mode, []):
            if len(poly) < 3:
                continue
            patch = Polygon(poly, closed=True, facecolor=st.color, edgecolor="none",
                            linewidth=0.0, hatch=st.hatch if hatches else None,
                            hatchcolor=st.hatch_color, zorder=_Z_FILL,
                            alpha=0.75 if data.raw and len(data.modes) > 1 else None,
                            label=f"_{mode.label}")
            patch.set_hatch_linewidth(HATCH_LW)
            ax.add_patch(patch)
            patches.append(patch)
        out.fills[mode] = patches

    obstacles: list[tuple[float, float, float, float]] = []
    # curves, their labels and the named points
    if curves:
        for name, cd in data.curves.items():
            pieces: list[Line2D] = []
            for pts, is_boundary in cd.runs():
                if cd.dotted:
                    kw: dict[str, Any] = dict(DOTTED)
                elif is_boundary:
                    kw = {"color": "black", "linewidth": LINE_LW}
                else:
                    kw = dict(CONSTRUCTION)
                line = Line2D(pts[:, 0], pts[:, 1], zorder=_Z_LINE if is_boundary else _Z_CONS,
                              solid_capstyle="round", solid_joinstyle="round",
                              label=f"_{name}", **kw)
                ax.add_line(line)
                pieces.append(line)
            out.curves[name] = pieces
        offsets = _point_offsets(data.points, frame)
        for name, pt in data.points.items():
            (marker,) = ax.plot([pt.k], [pt.mu], linestyle="none", marker="o", markersize=3.2,
                                color="black", zorder=_Z_POINT, clip_on=False, label=f"_{name}")
            out.point_markers[name] = marker
            dx, dy, ha, va = offsets[name]
            text = _point_text(name)
            out.point_labels[name] = ax.annotate(
                text, (pt.k, pt.mu), xytext=(dx, dy), textcoords="offset points",
                ha=ha, va=va, fontsize=_POINT_FS, fontstyle="italic", zorder=_Z_LABEL,
                annotation_clip=False,
                bbox={"boxstyle": "square,pad=0.05", "fc": "white", "ec": "none", "alpha": 0.6})
            obstacles.append(frame.box(pt.k, pt.mu, dx, dy, text_size(text, _POINT_FS), ha, va))
            obstacles.append(frame.box(pt.k, pt.mu, 0.0, 0.0, (6.0, 6.0), "center", "center"))
        for name, (k, mu) in data.line_ends.items():
            if name in out.point_labels:
                continue
            at_top = mu >= 0.99 * mu_max
            k, mu = min(k, k_max), min(mu, mu_max)
            dx, dy = (4.0, -2.0) if at_top else (-3.0, 4.0)
            ha, va = ("left", "top") if at_top else ("right", "bottom")
            text = _point_text(name)
            end_box = frame.box(k, mu, dx, dy, text_size(text, _POINT_FS), ha, va)
            if overlaps(end_box, obstacles):
                continue  # a far end named on top of a point's name (E and B of a loaded map)
            out.point_labels[name] = ax.annotate(
                text, (k, mu), xytext=(dx, dy), textcoords="offset points", ha=ha, va=va,
                fontsize=_POINT_FS, fontstyle="italic", zorder=_Z_LABEL, annotation_clip=False)
            obstacles.append(end_box)
        if tidy:
            out.off_view = _mark_off_view(ax, params, k_max, mu_max, obstacles, frame)
    lines = [view_points(c.points, k_max, mu_max) for c in data.curves.values()] if curves else []
    if curves:
        for name, cd in data.curves.items():
            if cd.label:
                placed = _curve_label(ax, frame, cd, obstacles, lines)
                if placed is not None:
                    out.curve_labels[name] = placed

    # region labels
    if labels:
        small: list[tuple[Mode, np.ndarray]] = []
        for mode in data.modes:
            texts = []
            size = text_size(mode.tex, _REGION_FS)
            box = (size[0] / frame.w_pt, size[1] / frame.h_pt)
            for poly in data.polygons.get(mode, []):
                anchor = label_anchor(poly, k_max, mu_max, box, obstacles=obstacles, lines=lines)
                if anchor is None:
                    small.append((mode, poly))
                    continue
                text, style = mode_symbol(mode)
                texts.append(ax.text(
                    anchor[0], anchor[1], text, ha="center", va="center",
                    fontsize=_REGION_FS, fontstyle=style, zorder=_Z_LABEL,
                    bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none",
                          "alpha": 0.8}))
                obstacles.append(frame.box(anchor[0], anchor[1], 0, 0, size, "center", "center"))
            out.region_labels[mode] = texts
        for mode, poly in small:  # too thin for a label: on the band, or with a leader line
            t = (_band_label if tidy else _leader_label)(ax, frame, mode, poly, obstacles, lines)
            if t is not None:
                out.region_labels.setdefault(mode, []).append(t)

    if legend:
        from .key import key_handles, key_legend

        # the key names the modes seen in the view (the polygons reach beyond it)
        seen = 1e-9 * data.k_max * data.mu_max
        shown = [m for m in data.modes
                 if any(len(p) >= 3 and area_in_view(p, data.k_max, data.mu_max) > seen
                        for p in data.polygons.get(m, []))]
        plain = [c for c in data.curves.values() if not c.dotted] if curves else []
        dotted = [c for c in data.curves.values() if c.dotted] if curves else []
        handles = key_handles(
            shown, hatches=hatches, boundary=bool(plain or dotted),
            construction=any(not b for c in plain for _, b in c.runs()),
            dotted_label=("dotted line " + dotted[0].label) if dotted else None)
        kw = {
            "loc": "upper center", "bbox_to_anchor": (0.5, -0.135), "ncol": 2,
            "fontsize": 8.5, "frameon": False, "handleheight": 1.1,
            "columnspacing": 1.5, "borderaxespad": 0.0,
        }
        kw.update(legend_kw or {})
        if handles:
            out.legend = key_legend(ax, handles, **kw)

    if title is None:
        title = default_title(params, modes=data.modes, raw=data.raw)
    if title:
        # an explicit y turns off matplotlib's automatic title placement, which
        # measures every tick label first (the layout here is fixed anyway)
        out.title = ax.set_title(title, fontsize=9.5, loc="left", pad=6, y=1.0)
    return out


def _curve_label(ax: Axes, frame: _Frame, cd: Any,
                 obstacles: list[tuple[float, float, float, float]],
                 lines: Sequence[np.ndarray]) -> Text | None:
    """Write a curve's label beside it, clear of the lines and of the other labels."""
    k_max, mu_max = frame.k_max, frame.mu_max
    size = text_size(cd.label, _CURVE_FS)
    box = (size[0] / frame.w_pt, size[1] / frame.h_pt)
    at = curve_label_anchor(cd.points, k_max, mu_max, box, lines, obstacles)
    if at is not None:
        obstacles.append(frame.box(at[0], at[1], 0.0, 0.0, size, "center", "center"))
        return ax.text(at[0], at[1], cd.label, ha="center", va="center", fontsize=_CURVE_FS,
                       zorder=_Z_LABEL, clip_on=False,
                       bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                             "alpha": 0.7})
    # crowded (lines close together): a label with a leader to a point of the curve
    for frac in (0.8, 0.6, 0.4):
        target = point_along(cd.points, k_max, mu_max, frac)
        if target is None:
            return None
        at = leader_label_anchor(target, k_max, mu_max, box, lines, obstacles)
        if at is not None:
            obstacles.append(frame.box(at[0], at[1], 0.0, 0.0, size, "center", "center"))
            return ax.annotate(
                cd.label, target, xytext=at, textcoords="data", ha="center", va="center",
                fontsize=_CURVE_FS, zorder=_Z_LABEL,
                bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
                arrowprops={"arrowstyle": "-", "color": "0.2", "lw": 0.6, "shrinkA": 0.0,
                            "shrinkB": 0.0})
    return None


def point_along(pts: np.ndarray, k_max: float, mu_max: float, frac: float
                 ) -> tuple[float, float] | None:
    """The point at ``frac`` of the visible length of a polyline (data coordinates)."""
    q = view_points(pts, k_max, mu_max, 0.003)
    q = q[(q[:, 0] >= 0) & (q[:, 0] <= 1) & (q[:, 1] >= 0) & (q[:, 1] <= 1)]
    if len(q) < 2:
        return None
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(q, axis=0).T))])
    i = int(np.clip(np.searchsorted(s, frac * s[-1]), 0, len(q) - 1))
    return float(q[i, 0] * k_max), float(q[i, 1] * mu_max)


def _band_label(ax: Axes, frame: _Frame, mode: Mode, poly: np.ndarray,
                obstacles: list[tuple[float, float, float, float]],
                lines: Sequence[np.ndarray]) -> Text | None:
    """Label a region too thin to hold its symbol: on the band itself, framed.

    The label's centre lies inside its region, at the thickest part of the
    band in view, so that it can never be read as the label of a neighbour;
    :func:`regimemap.drawing.tidy.tidy_figure` moves it along the band if it
    meets another text.
    """
    from .tidy import band_columns

    xs, lo, hi = band_columns(poly, frame.k_max, frame.mu_max, 400)
    room = hi - lo
    if room.max() <= 0.0:
        return None
    good = np.flatnonzero(room >= 0.6 * room.max())
    c = int(good[len(good) // 2])
    target = (float(xs[c] * frame.k_max), float(0.5 * (lo[c] + hi[c]) * frame.mu_max))
    size = text_size(mode.tex, _REGION_FS)
    obstacles.append(frame.box(target[0], target[1], 0.0, 0.0, size, "center", "center"))
    text, style = mode_symbol(mode)
    t = ax.text(target[0], target[1], text, ha="center", va="center", fontsize=_REGION_FS,
                fontstyle=style, zorder=_Z_LABEL,
                bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.3", "lw": 0.6,
                      "alpha": 0.9})
    t.set_gid("band-label")
    return t


def _leader_label(ax: Axes, frame: _Frame, mode: Mode, poly: np.ndarray,
                  obstacles: list[tuple[float, float, float, float]],
                  lines: Sequence[np.ndarray]) -> Text | None:
    """Label a region too thin to hold its symbol, with an arrow pointing into it."""
    target = interior_point(poly, frame.k_max, frame.mu_max)
    if target is None:
        return None
    size = text_size(mode.tex, _REGION_FS)
    box = (size[0] / frame.w_pt, size[1] / frame.h_pt)
    at = leader_label_anchor(target, frame.k_max, frame.mu_max, box, lines, obstacles)
    if at is None:
        return None
    obstacles.append(frame.box(at[0], at[1], 0.0, 0.0, size, "center", "center"))
    text, style = mode_symbol(mode)
    return ax.annotate(
        text, target, xytext=at, textcoords="data", ha="center", va="center",
        fontsize=_REGION_FS, fontstyle=style, zorder=_Z_LABEL,
        bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.3", "lw": 0.5,
              "alpha": 0.9},
        arrowprops={"arrowstyle": "-|>", "color": "black", "lw": 0.8,
                    "shrinkA": 0.0, "shrinkB": 1.0, "mutation_scale": 8})


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
    from dataclasses import replace

    return replace(data, curves={n: c for n, c in data.curves.items() if n not in drop})


def _off_view_text(name: str, k: float, mu: float) -> str:
    return f"{_point_text(name)} ({k:.3g}, {mu:.3g})"


_OFF_VIEW_FS = 8.0


def _mark_off_view(ax: Axes, params: Parameters, k_max: float, mu_max: float,
                   obstacles: list[tuple[float, float, float, float]], frame: _Frame
                   ) -> dict[str, Text]:
    """Mark the characteristic points outside the view at the frame's edge.

    Each gets a short arrow whose head is on the frame, pointing the way to
    the point, and its name and coordinates at the arrow's tail, inside the
    frame; points beyond the same place of the edge share one arrow.
    """
    from ..maps.designer_view import points_off_view

    groups: dict[tuple[float, float], list[Any]] = {}
    for pt in points_off_view(params, k_max, mu_max):
        x, y = min(pt.k, k_max), min(pt.mu, mu_max)
        groups.setdefault((round(x / k_max, 2), round(y / mu_max, 2)), []).append(pt)
    out: dict[str, Text] = {}
    for (fx, fy), pts in groups.items():
        pt = pts[0]
        x, y = min(pt.k, k_max), min(pt.mu, mu_max)
        right, up = pt.k > k_max, pt.mu > mu_max
        ux, uy = (1.0 if right else 0.0), (1.0 if up else 0.0)
        n = float(np.hypot(ux, uy)) or 1.0
        ux, uy = ux / n, uy / n
        dx, dy = -18.0 * ux, -18.0 * uy
        ha = "right" if (right or fx > 0.85) else ("left" if fx < 0.15 else "center")
        if up:
            va = "top"
        else:
            va = "bottom" if fy < 0.5 else "top"
            dy += 3.0 if va == "bottom" else -3.0
        text = "\n".join(_off_view_text(p.name, p.k, p.mu) for p in pts)
        label = ax.annotate(
            text, (x, y), xytext=(dx, dy), textcoords="offset points", ha=ha, va=va,
            fontsize=_OFF_VIEW_FS, zorder=_Z_LABEL, annotation_clip=False, color="0.1",
            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "0.4", "lw": 0.4,
                  "alpha": 0.9},
            arrowprops={"arrowstyle": "-|>", "color": "0.1", "lw": 0.9, "mutation_scale": 9,
                        "shrinkA": 0.0, "shrinkB": 0.0})
        label.set_gid("off-view")
        for p in pts:
            out[p.name] = label
        longest = max(text.split("\n"), key=len)
        obstacles.append(frame.box(x, y, dx, dy, text_size(longest, _OFF_VIEW_FS, len(pts)),
                                   ha, va))
    return out


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
        Give the artists the ids :func:`regimemap.drawing.tidy.tidy_figure`
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
