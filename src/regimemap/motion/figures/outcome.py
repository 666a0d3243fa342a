"""An outcome map: what a pulse does to the block over two swept inputs.

Draws an :class:`regimemap.dynamics.OutcomeMap` (the data; this module only
draws): each outcome category -- rest, slide only, rock only, slide-rock,
overturned, still moving -- as a filled, hatched region in the style of the
regime maps (:data:`regimemap.drawing.style.OUTCOME_STYLE`), black boundaries
between categories, contours of the residual slide and of the maximum
rotation where they mean something, a label in every region with room for
one, and the key below the axes.

A refined map (the default of :func:`regimemap.dynamics.outcome_map`) is drawn
as polygons bounded by its refined boundaries (:meth:`OutcomeMap.geometry`),
the contours clipped on them; a map that was not refined is drawn as its cells
(each node the centre of a cell reaching half-way to its neighbours: a
staircase at the grid's pitch).  The text is placed by
:mod:`regimemap.motion.figures.outcome_text`; the words (axis labels, title) are
:mod:`regimemap.motion.figures.outcome_words`'s.  The two ways of drawing the regions
(polygons or cells) and their contours share the figure's style and key, hence
one module of some length.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ...drawing.save import DEFAULT_DPI
from ...drawing.style import HATCH_LW, LINE_LW, OUTCOME_STYLE, style_context
from ...drawing.text.placement import cell_edges
from ...dynamics.outcome import OutcomeMap
from ...dynamics.regions import MapGeometry
from ...dynamics.stepper import OVERTURN, ROCK, SLIDE, SLIDE_ROCK, STILL_MOVING
from .outcome_artists import CategoryLookup, OutcomeArtists
from .outcome_words import AXIS_LABELS, axis_label, outcome_title, rotation_text

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from matplotlib.path import Path as MplPath


__all__ = ["AXIS_LABELS", "OutcomeArtists", "OUTCOME_FIGSIZE", "OutcomeStyle", "axis_label", "cell_edges",
           "category_rectangles", "draw_outcome_map", "outcome_figure", "outcome_title", "rotation_text"]

#: Size of an outcome-map figure in inches (width, height): the regime map's width.
OUTCOME_FIGSIZE: tuple[float, float] = (6.4, 5.9)

# zorders: fills < hatch < boundaries < contours < labels
_Z_FILL, _Z_EDGE, _Z_CONTOUR, _Z_LABEL = 1.0, 2.5, 3.0, 6.0
#: Contours: residual slide solid, maximum rotation dashed (both dark: they cross every fill).
SLIDE_CONTOUR: dict[str, Any] = {"colors": "#222255", "linewidths": 0.9}
ROTATION_CONTOUR: dict[str, Any] = {"colors": "#222222", "linewidths": 0.9, "linestyles": [(0, (4.0, 2.0))]}


def category_rectangles(category: NDArray[Any], code: int) -> list[tuple[int, int, int, int]]:
    """Cells of ``category == code`` as few rectangles (j0, j1, i0, i1): columns j0..j1-1, rows i0..i1-1.

    Runs along each row, merged with the identical runs of the rows above.
    """
    mask = np.asarray(category) == code
    out: list[tuple[int, int, int, int]] = []
    open_: dict[tuple[int, int], int] = {}  # (j0, j1) -> first row
    for i in range(mask.shape[0]):
        row = np.concatenate(([False], mask[i], [False]))
        d = np.flatnonzero(np.diff(row.astype(np.int8)))
        runs = set(zip(d[0::2].tolist(), d[1::2].tolist()))
        for run in sorted(set(open_) - runs):
            out.append((run[0], run[1], open_.pop(run), i))
        for run in sorted(runs - set(open_)):
            open_[run] = i
    for run in sorted(open_):
        out.append((run[0], run[1], open_[run], mask.shape[0]))
    out.sort(key=lambda r: (r[2], r[0]))
    return out


def _boundary_segments(category: NDArray[Any], xe: NDArray[np.float64], ye: NDArray[np.float64]
                       ) -> list[NDArray[np.float64]]:
    """Cell edges between different categories, joined along straight runs."""
    segs: list[NDArray[np.float64]] = []
    c = np.asarray(category)
    # vertical edges: between columns j-1 and j, row i
    diff_v = c[:, 1:] != c[:, :-1]
    for j in range(diff_v.shape[1]):
        col = np.concatenate(([False], diff_v[:, j], [False]))
        d = np.flatnonzero(np.diff(col.astype(np.int8)))
        for i0, i1 in zip(d[0::2], d[1::2]):
            segs.append(np.array([[xe[j + 1], ye[i0]], [xe[j + 1], ye[i1]]]))
    diff_h = c[1:, :] != c[:-1, :]
    for i in range(diff_h.shape[0]):
        row = np.concatenate(([False], diff_h[i], [False]))
        d = np.flatnonzero(np.diff(row.astype(np.int8)))
        for j0, j1 in zip(d[0::2], d[1::2]):
            segs.append(np.array([[xe[j0], ye[i + 1]], [xe[j1], ye[i + 1]]]))
    return segs


def _nice_levels(values: NDArray[np.float64], n: int = 6, span: float = 1e-3) -> NDArray[np.float64]:
    """Round contour levels strictly inside the range of the finite non-zero ``values``.

    When the positive values span more than two decades (slides from millimetres to
    metres), the levels are 1, 2, 5 (or, when that gives too many, 1, 3) times powers of ten
    from ``span`` times the largest value up, at most ``n`` of them; otherwise evenly spaced
    round numbers.
    """
    from matplotlib.ticker import MaxNLocator

    v = values[np.isfinite(values)]
    if v.size == 0:
        return np.array([])
    lo, hi = float(v.min()), float(v.max())
    if not hi > lo:
        return np.array([])
    pos = v[v > 0]
    if lo >= 0.0 and pos.size and hi > 100.0 * float(pos.min()):
        floor = max(float(pos.min()), hi * span)
        e0 = math.floor(math.log10(floor))
        e1 = math.ceil(math.log10(hi))
        logs = np.array([m * 10.0 ** e for e in range(e0, e1 + 1) for m in (1.0, 2.0, 5.0)])
        logs = logs[(logs > floor) & (logs < hi)]
        if logs.size > n:  # too many lines: 1 and 3 times powers of ten
            thin = np.array([m * 10.0 ** e for e in range(e0, e1 + 1) for m in (1.0, 3.0)])
            logs = thin[(thin > floor) & (thin < hi)]
        return np.asarray(logs[-n:], dtype=np.float64)
    levels = np.asarray(MaxNLocator(nbins=n, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi),
                        dtype=np.float64)
    keep = (levels > lo) & (levels < hi) & (np.abs(levels) > 1e-12 * max(abs(lo), abs(hi)))
    return np.asarray(levels[keep], dtype=np.float64)


def _compound(loops: Sequence[NDArray[np.float64]]) -> MplPath:
    """One path of closed loops (a region with its holes and islands)."""
    from matplotlib.path import Path as MplPath

    verts: list[NDArray[np.float64]] = []
    codes: list[NDArray[np.uint8]] = []
    for p in loops:
        if len(p) < 3:
            continue
        verts.append(np.vstack([p, p[:1]]))
        c = np.full(len(p) + 1, MplPath.LINETO, dtype=np.uint8)
        c[0], c[-1] = MplPath.MOVETO, MplPath.CLOSEPOLY
        codes.append(c)
    if not verts:
        return MplPath(np.zeros((0, 2)))
    return MplPath(np.concatenate(verts), np.concatenate(codes))


def _extend(data: NDArray[np.float64], keep: NDArray[np.bool_], passes: int = 2
            ) -> np.ma.MaskedArray[Any, Any]:
    """``data`` where ``keep``, carried ``passes`` nodes beyond it (the mean of the neighbours
    already known), masked farther: contours then run past a boundary, to be clipped on it."""
    z = np.where(keep, data, 0.0)
    known = keep.copy()
    for _ in range(passes):
        zp = np.pad(np.where(known, z, 0.0), 1)
        kp = np.pad(known.astype(np.float64), 1)
        total = np.zeros(z.shape)
        count = np.zeros(z.shape)
        for di, dj in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            sl = (slice(1 + di, 1 + di + z.shape[0]), slice(1 + dj, 1 + dj + z.shape[1]))
            total += zp[sl]
            count += kp[sl]
        grow = ~known & (count > 0)
        z[grow] = total[grow] / count[grow]
        known = known | grow
    return np.ma.masked_where(~known, z)


@dataclass(frozen=True)
class OutcomeStyle:
    """How :func:`draw_outcome_map` draws a map (what it shows, not where).

    Attributes
    ----------
    contours : bool
        Draw the contours of the residual slide (solid, labelled in metres) and of the
        maximum rotation (dashed, labelled in degrees) where they mean something.
    labels : bool
        Write the category's name inside each region that has room for it.
    legend : bool
        Draw the key below the axes.
    hatches : bool
        Hatch the regions (as the regime maps do).
    slide_unit : str
        Suffix of the slide contour labels.
    refined : bool
        Draw a refined map's regions as the polygons bounded by its refined boundaries
        (:meth:`OutcomeMap.geometry`); False, or a map that was not refined, draws the cells
        as computed (a staircase at the grid's pitch).
    note : str, optional
        A last entry of the key, without a symbol; by default, for a map with a
        ``min_rotation``, the smallest rotation that counts as rocking.
    """

    contours: bool = True
    labels: bool = True
    legend: bool = True
    hatches: bool = True
    slide_unit: str = " m"
    refined: bool = True
    note: str | None = None


def draw_outcome_map(ax: Axes, m: OutcomeMap, *, x: Sequence[float] | NDArray[np.float64] | None = None,
                     y: Sequence[float] | NDArray[np.float64] | None = None,
                     xlabel: str | None = None, ylabel: str | None = None, title: str | None = None,
                     style: OutcomeStyle | None = None, **style_fields: Any) -> OutcomeArtists:
    """Draw an outcome map on ``ax``.

    Parameters
    ----------
    ax : Axes
    m : OutcomeMap
        The data (:func:`regimemap.dynamics.outcome_map`).
    x, y : array_like, optional
        The horizontal and vertical coordinates of the columns and rows (default the swept
        values, ``m.first_values`` and ``m.second_values``; e.g. dimensionless values from
        :func:`regimemap.dynamics.outcome.dimensionless_values`).  Each must be monotonic.
    xlabel, ylabel, title : str, optional
        Axis labels (default: the swept names) and title (mathtext allowed).
    style : OutcomeStyle, optional
        What is drawn: contours, labels, key, hatches, the slide's unit, refined regions, a
        note in the key.
    **style_fields
        Fields of :class:`OutcomeStyle` (``contours=``, ``legend=`` ...), over those of
        ``style``.

    Returns
    -------
    OutcomeArtists

    Notes
    -----
    The labels of the regions and of the contours, and the title, are fitted once the axes
    are drawn (:func:`regimemap.motion.figures.outcome_text.place_outcome_text`, with the figure's
    layout as it is then): none overlaps another text or leaves the figure.
    """
    from matplotlib.collections import LineCollection
    from matplotlib.figure import Figure

    st = replace(style or OutcomeStyle(), **style_fields)
    xs = np.asarray(m.first_values if x is None else x, dtype=np.float64)
    ys = np.asarray(m.second_values if y is None else y, dtype=np.float64)
    cat = np.asarray(m.category)
    rot = np.asarray(m.max_rotation, dtype=np.float64)
    slide = np.asarray(m.residual_slide, dtype=np.float64)
    if cat.shape != (ys.size, xs.size):
        raise ValueError(f"the map is {cat.shape[0]} x {cat.shape[1]} (rows x columns), the axes have "
                         f"{ys.size} and {xs.size} values")
    geo = m.geometry(xs, ys) if st.refined else None  # on the drawn axes, before any flip
    note = st.note
    if note is None and m.min_rotation > 0.0:
        note = f"rocking: max rotation > {rotation_text(m.min_rotation)}"
    # increasing axes (a decreasing one, e.g. omega_p from a duration sweep, is flipped)
    if xs.size > 1 and xs[0] > xs[-1]:
        xs, cat, rot, slide = xs[::-1], cat[:, ::-1], rot[:, ::-1], slide[:, ::-1]
    if ys.size > 1 and ys[0] > ys[-1]:
        ys, cat, rot, slide = ys[::-1], cat[::-1], rot[::-1], slide[::-1]
    xe, ye = cell_edges(xs), cell_edges(ys)
    out = OutcomeArtists()
    with style_context():
        if geo is None:
            ax.set_xlim(xe[0], xe[-1])
            ax.set_ylim(ye[0], ye[-1])
        else:  # the polygons cover the nodes' span
            ax.set_xlim(xs[0], xs[-1])
            ax.set_ylim(ys[0], ys[-1])
        ax.set_xlabel(xlabel if xlabel is not None else m.first_name, fontsize=11)
        ax.set_ylabel(ylabel if ylabel is not None else m.second_name, fontsize=11)
        ax.tick_params(labelsize=9)
        if title:
            out.title = ax.set_title(title, fontsize=10.5)
        present = [c for c in sorted(OUTCOME_STYLE) if c < len(m.labels) and np.any(cat == c)]
        paths = _region_paths(cat, present, geo, xe, ye)
        _draw_regions(ax, out, m.labels, paths, st.hatches)
        segs = [p for _, _, p in geo.boundaries] if geo is not None else _boundary_segments(cat, xe, ye)
        out.boundary_lines = segs
        if segs:
            out.boundaries = LineCollection(segs, colors="black", linewidths=0.8 * LINE_LW,
                                            capstyle="projecting" if geo is None else "round",
                                            joinstyle="round", zorder=_Z_EDGE)
            ax.add_collection(out.boundaries)
        out.category_at = CategoryLookup(cat, xs, ys, paths if geo is not None else None)

        handles = _region_handles(m.labels, present, st.hatches)
        if st.contours and xs.size > 1 and ys.size > 1:
            handles += _draw_contours(ax, out, cat, slide, np.degrees(rot), xs, ys, geo, st.slide_unit)
        if st.labels:
            _draw_region_labels(ax, out, m.labels, present, float(xs.mean()), float(ys.mean()))
        if note:
            from matplotlib.lines import Line2D

            handles.append(Line2D([], [], color="none", label=note))
        if st.legend and handles:
            out.legend = ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.13),
                                   ncols=3, fontsize=8.5, frameon=False, handlelength=2.2,
                                   handleheight=1.1, columnspacing=1.4, borderaxespad=0.0)
        fig = ax.get_figure()
        if isinstance(fig, Figure):
            from .outcome_text import place_outcome_text

            out.report = place_outcome_text(fig, ax, out, cat, xs, ys)
    return out


def _region_paths(cat: NDArray[Any], present: list[int], geo: MapGeometry | None,
                  xe: NDArray[np.float64], ye: NDArray[np.float64]) -> dict[int, MplPath]:
    """The outline of each category present: the refined polygons, or its cells (rectangles)."""
    from matplotlib.path import Path as MplPath

    paths: dict[int, MplPath] = {}
    for code in present:
        if geo is not None:
            paths[code] = _compound(geo.regions.get(code, []))
            continue
        verts: list[tuple[float, float]] = []
        codes: list[Any] = []
        for j0, j1, i0, i1 in category_rectangles(cat, code):
            verts += [(xe[j0], ye[i0]), (xe[j1], ye[i0]), (xe[j1], ye[i1]), (xe[j0], ye[i1]),
                      (xe[j0], ye[i0])]
            codes += [MplPath.MOVETO, MplPath.LINETO, MplPath.LINETO, MplPath.LINETO,
                      MplPath.CLOSEPOLY]
        paths[code] = MplPath(verts, codes)
    return paths


def _draw_regions(ax: Axes, out: OutcomeArtists, labels: Sequence[str], paths: dict[int, MplPath],
                  hatches: bool) -> None:
    """Fill (and hatch) each category's region."""
    from matplotlib.patches import PathPatch

    for code, path in paths.items():
        st = OUTCOME_STYLE[code]
        patch = PathPatch(path, facecolor=st.color, edgecolor="none", linewidth=0.0,
                          hatch=st.hatch if hatches else None, hatchcolor=st.hatch_color,
                          zorder=_Z_FILL, label=f"_{labels[code]}")
        patch.set_hatch_linewidth(HATCH_LW)
        ax.add_patch(patch)
        out.regions[code] = patch


def _region_handles(labels: Sequence[str], present: list[int], hatches: bool) -> list[Any]:
    """The key's entries of the categories present."""
    from matplotlib.patches import Rectangle

    handles: list[Any] = []
    for code in present:
        st = OUTCOME_STYLE[code]
        h = Rectangle((0, 0), 1, 1, facecolor=st.color, edgecolor="0.4", linewidth=0.4,
                      hatch=st.hatch if hatches else None, hatchcolor=st.hatch_color,
                      label=labels[code])
        h.set_hatch_linewidth(HATCH_LW)
        handles.append(h)
    return handles


def _draw_region_labels(ax: Axes, out: OutcomeArtists, labels: Sequence[str], present: list[int],
                        x: float, y: float) -> None:
    """A label per category present, at (x, y) until :func:`place_outcome_text` places it."""
    for code in present:
        st = OUTCOME_STYLE[code]
        t = ax.text(x, y, labels[code], ha="center", va="center",
                    fontsize=8.5, color="white" if code == OVERTURN else "black", zorder=_Z_LABEL,
                    bbox={"boxstyle": "round,pad=0.25", "fc": st.color, "ec": "none",
                          "alpha": 0.9})
        t.set_gid(f"region-{code}")
        out.labels.append(t)


def _draw_contours(ax: Axes, out: OutcomeArtists, cat: NDArray[Any], slide: NDArray[np.float64],
                   rot_deg: NDArray[np.float64], xs: NDArray[np.float64], ys: NDArray[np.float64],
                   geo: MapGeometry | None, slide_unit: str) -> list[Any]:
    """The contours of the residual slide and of the largest rotation, each where it means
    something (the slide where the base slipped, the rotation where the block rocked, neither
    where it overturned or was still moving); their entries of the key."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import PathPatch

    handles: list[Any] = []
    moved = (cat != OVERTURN) & (cat != STILL_MOVING)
    for key, data, codes, unit, style, what, span in (
            ("residual_slide", slide, (SLIDE, SLIDE_ROCK), slide_unit, SLIDE_CONTOUR, "residual slide", 1e-3),
            ("max_rotation", rot_deg, (ROCK, SLIDE_ROCK), "°", ROTATION_CONTOUR, "maximum rotation", 1e-2)):
        where = np.isin(cat, codes)
        if not where.any():
            continue
        levels = _nice_levels(np.asarray(data[where]), span=span)
        if levels.size == 0:
            continue
        if geo is None:  # 0 elsewhere (the lines run on to the boundary), masked where it overturned
            z = np.ma.masked_where(~moved, np.where(where, data, 0.0))
        else:  # carried past the boundaries, then clipped on them
            z = _extend(np.where(where, data, 0.0), moved)
        cs = ax.contour(xs, ys, z, levels=levels, zorder=_Z_CONTOUR, **style)
        if geo is not None:
            clip = _compound([p for c in codes for p in geo.regions.get(c, [])])
            cs.set_clip_path(PathPatch(clip, transform=ax.transData))
        out.contours[key] = cs
        out.contour_units[key] = unit
        ls = style.get("linestyles", ["solid"])[0]
        handles.append(Line2D([], [], color=style["colors"], linewidth=style["linewidths"], linestyle=ls,
                              label=f"{what} ({unit.strip()})"))
    return handles


def outcome_figure(m: OutcomeMap, *, dpi: float = DEFAULT_DPI, figsize: tuple[float, float] | None = None,
                   fig: Figure | None = None, **kwargs: Any) -> tuple[Figure, Axes, OutcomeArtists]:
    """A Figure (Agg canvas, no pyplot) with one outcome map; ``kwargs`` go to :func:`draw_outcome_map`.

    The artists are also kept as the figure's ``_regimemap_outcome`` (for the tests of its text).
    """
    from ...maps.figures.figure import new_figure

    fig, ax = new_figure(figsize or OUTCOME_FIGSIZE, dpi, fig)
    w, h = fig.get_size_inches()
    ax.set_position((0.78 / w, 1.05 / h, 5.3 / w, (h - 1.05 - 0.55) / h))
    artists = draw_outcome_map(ax, m, **kwargs)
    setattr(fig, "_regimemap_outcome", artists)  # noqa: B010
    return fig, ax, artists
