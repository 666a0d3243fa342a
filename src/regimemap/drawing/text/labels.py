"""The texts of a map: names of the points, labels of the curves, mode symbols, arrows off view.

:func:`~regimemap.maps.figures.mapplot.draw_map` calls these once the fills and the
lines are drawn.  Each works in one :class:`Frame` of conversions (data, view
fractions, points) and keeps a list of *obstacles* -- the boxes (view fractions)
of the texts written so far -- so that a later text keeps clear of the earlier
ones; where a text goes is decided by :mod:`regimemap.drawing.text.placement`.
Text sizes come from the size model :func:`regimemap.drawing.style.text_size`
(no renderer): :func:`regimemap.drawing.text.tidy.tidy_figure` measures and moves
them afterwards.  The four kinds of text share the frame and the obstacles, hence one
module of some length.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ...maps.mapdata import CurveData, MapData
from ...mechanics.modes import Mode
from ..style import mode_symbol, text_size
from .placement import (
    Box,
    band_columns,
    curve_label_anchor,
    interior_point,
    label_anchor,
    leader_label_anchor,
    overlaps,
    point_along,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

    from ...mechanics.curves import NamedPoint

__all__ = [
    "ABOVE",
    "CURVE_FS",
    "LEFT_OF",
    "OFF_VIEW_FS",
    "POINT_FS",
    "POINT_OFFSET",
    "REGION_FS",
    "RIGHT_OF",
    "Z_LABEL",
    "Z_POINT",
    "Frame",
    "curve_labels",
    "mark_off_view",
    "name_points",
    "point_offsets",
    "point_text",
    "region_labels",
]

#: Font sizes (points) of the mode symbols, the names of the points, the curves' labels and
#: the texts of the arrows to the points off view.
REGION_FS = 11.0
POINT_FS = 10.0
CURVE_FS = 10.0
OFF_VIEW_FS = 8.0
#: zorders of the named points' markers and of every label (above the lines, below design points).
Z_POINT, Z_LABEL = 3.0, 4.0

Offset = tuple[float, float, str, str]

# Offsets (points) of the names of the report's points, chosen so that the
# name sits where the report writes it and off the lines through the point.
POINT_OFFSET: dict[str, Offset] = {
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
#: The offsets of a name on the k axis crowded by a neighbour: left of it, right of it, above it.
LEFT_OF: Offset = (-3.0, 3.0, "right", "bottom")
RIGHT_OF: Offset = (3.0, 3.0, "left", "bottom")
ABOVE: Offset = (0.0, 7.0, "center", "bottom")


class Frame:
    """Conversions between data, view fractions and points for one Axes (no drawing).

    Parameters
    ----------
    ax : Axes
        The axes of a :class:`~matplotlib.figure.Figure` (not of a SubFigure).
    k_max, mu_max : float
        The view.
    """

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
            ha: str, va: str) -> Box:
        """Box (view fractions) of a text of ``size`` (points) at (k, mu) + (dx, dy) points."""
        x = k / self.k_max + dx / self.w_pt
        y = mu / self.mu_max + dy / self.h_pt
        w, h = size[0] / self.w_pt, size[1] / self.h_pt
        x0 = {"left": x, "right": x - w}.get(ha, x - w / 2)
        y0 = {"bottom": y, "top": y - h}.get(va, y - h / 2)
        return (x0, y0, x0 + w, y0 + h)

    def fraction(self, size: tuple[float, float]) -> tuple[float, float]:
        """A text's size (points) as fractions of the view."""
        return (size[0] / self.w_pt, size[1] / self.h_pt)


def point_text(name: str) -> str:
    """A point name as plain text with Unicode primes (B' -> B\u2032, C'' -> C\u2033).

    Drawn in the oblique face that mathtext uses for variables, so it looks
    like ``$B'$`` without the cost of parsing mathtext.
    """
    return name.replace("''", "\u2033").replace("'", "\u2032")


def point_offsets(points: dict[str, Any], frame: Any) -> dict[str, Offset]:
    """Offsets of the point names; names of points close together on the k axis kept apart.

    D, E, F and G lie on the k axis and may nearly coincide (E and F at
    gamma = 3, k' = -0.2 are 0.05 apart).  Of two points closer than their
    names are wide, the left one is named on its left and the right one on its
    right; a point crowded on both sides is named above.

    Parameters
    ----------
    points : dict[str, NamedPoint]
        The named points (anything with ``k`` and ``mu``).
    frame : Frame
        The view (anything with ``k_max`` and ``w_pt``, the axes' width in points).

    Returns
    -------
    dict[str, (dx, dy, ha, va)]
    """
    out = {name: POINT_OFFSET.get(name, (4.0, 4.0, "left", "bottom")) for name in points}
    on_axis = sorted((pt.k, name) for name, pt in points.items() if pt.mu == 0.0 and name != "O")
    x = [k / frame.k_max * frame.w_pt for k, _ in on_axis]
    width = text_size("M", POINT_FS)[0] + 6.0  # a name and the gaps either side (points)
    for i in range(len(on_axis) - 1):
        if x[i + 1] - x[i] >= width:
            continue
        left, right = on_axis[i][1], on_axis[i + 1][1]
        if out[left] == RIGHT_OF and i > 0 and x[i] - x[i - 1] < width:
            out[left] = ABOVE  # already pushed right by its left neighbour
        elif x[i] >= width:
            out[left] = LEFT_OF
        else:
            out[left] = ABOVE  # no room left of it, inside the axes
        out[right] = RIGHT_OF
    return out


# -- the named points and the line ends -------------------------------------------------------


def name_points(ax: Axes, data: MapData, frame: Frame, obstacles: list[Box]
                ) -> tuple[dict[str, Line2D], dict[str, Text]]:
    """Mark the report's points and write their names, then name the far ends of lines.

    Parameters
    ----------
    ax : Axes
    data : MapData
    frame : Frame
    obstacles : list of Box
        Grows by the boxes of the names and of the markers.

    Returns
    -------
    markers, names : dict[str, Line2D], dict[str, Text]
        By the point's name (``A``, ``B'`` ...; ``B``, ``C`` for line ends).
    """
    markers: dict[str, Line2D] = {}
    names: dict[str, Text] = {}
    offsets = point_offsets(data.points, frame)
    for name, pt in data.points.items():
        (marker,) = ax.plot([pt.k], [pt.mu], linestyle="none", marker="o", markersize=3.2,
                            color="black", zorder=Z_POINT, clip_on=False, label=f"_{name}")
        markers[name] = marker
        dx, dy, ha, va = offsets[name]
        text = point_text(name)
        names[name] = ax.annotate(
            text, (pt.k, pt.mu), xytext=(dx, dy), textcoords="offset points",
            ha=ha, va=va, fontsize=POINT_FS, fontstyle="italic", zorder=Z_LABEL,
            annotation_clip=False,
            bbox={"boxstyle": "square,pad=0.05", "fc": "white", "ec": "none", "alpha": 0.6})
        obstacles.append(frame.box(pt.k, pt.mu, dx, dy, text_size(text, POINT_FS), ha, va))
        obstacles.append(frame.box(pt.k, pt.mu, 0.0, 0.0, (6.0, 6.0), "center", "center"))
    k_max, mu_max = data.k_max, data.mu_max
    for name, (k, mu) in data.line_ends.items():
        if name in names:
            continue
        at_top = mu >= 0.99 * mu_max
        k, mu = min(k, k_max), min(mu, mu_max)
        dx, dy = (4.0, -2.0) if at_top else (-3.0, 4.0)
        ha, va = ("left", "top") if at_top else ("right", "bottom")
        text = point_text(name)
        end_box = frame.box(k, mu, dx, dy, text_size(text, POINT_FS), ha, va)
        if overlaps(end_box, obstacles):
            continue  # a far end named on top of a point's name (E and B of a loaded map)
        names[name] = ax.annotate(
            text, (k, mu), xytext=(dx, dy), textcoords="offset points", ha=ha, va=va,
            fontsize=POINT_FS, fontstyle="italic", zorder=Z_LABEL, annotation_clip=False)
        obstacles.append(end_box)
    return markers, names


# -- the points off view ----------------------------------------------------------------------


def _off_view_text(name: str, k: float, mu: float) -> str:
    return f"{point_text(name)} ({k:.3g}, {mu:.3g})"


def mark_off_view(ax: Axes, points: Sequence[NamedPoint], frame: Frame, obstacles: list[Box]
                  ) -> dict[str, Text]:
    """Mark the characteristic points outside the view at the frame's edge.

    ``points`` are those of :attr:`regimemap.maps.mapdata.MapData.off_view`.

    Each gets a short arrow whose head is on the frame, pointing the way to
    the point, and its name and coordinates at the arrow's tail, inside the
    frame; points beyond the same place of the edge share one arrow.

    Returns
    -------
    dict[str, Text]
        The annotation of each point off view (shared by the points of one arrow).
    """
    k_max, mu_max = frame.k_max, frame.mu_max
    groups: dict[tuple[float, float], list[Any]] = {}
    for pt in points:
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
            fontsize=OFF_VIEW_FS, zorder=Z_LABEL, annotation_clip=False, color="0.1",
            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "0.4", "lw": 0.4,
                  "alpha": 0.9},
            arrowprops={"arrowstyle": "-|>", "color": "0.1", "lw": 0.9, "mutation_scale": 9,
                        "shrinkA": 0.0, "shrinkB": 0.0})
        label.set_gid("off-view")
        for p in pts:
            out[p.name] = label
        longest = max(text.split("\n"), key=len)
        obstacles.append(frame.box(x, y, dx, dy, text_size(longest, OFF_VIEW_FS, len(pts)),
                                   ha, va))
    return out


# -- the curves' labels -----------------------------------------------------------------------


def curve_labels(ax: Axes, data: MapData, frame: Frame, obstacles: list[Box],
                 lines: Sequence[np.ndarray]) -> dict[str, Text]:
    """Label every curve that has a label, beside it, clear of the lines and of the other texts.

    ``lines`` are the curves as dense polylines in view fractions
    (:func:`~regimemap.drawing.text.placement.view_points`).  Returns the labels by curve name.
    """
    out: dict[str, Text] = {}
    for name, cd in data.curves.items():
        if cd.label:
            placed = _curve_label(ax, frame, cd, obstacles, lines)
            if placed is not None:
                out[name] = placed
    return out


def _curve_label(ax: Axes, frame: Frame, cd: CurveData, obstacles: list[Box],
                 lines: Sequence[np.ndarray]) -> Text | None:
    """Write a curve's label beside it, clear of the lines and of the other labels."""
    k_max, mu_max = frame.k_max, frame.mu_max
    size = text_size(cd.label, CURVE_FS)
    box = frame.fraction(size)
    at = curve_label_anchor(cd.points, k_max, mu_max, box, lines, obstacles)
    if at is not None:
        obstacles.append(frame.box(at[0], at[1], 0.0, 0.0, size, "center", "center"))
        return ax.text(at[0], at[1], cd.label, ha="center", va="center", fontsize=CURVE_FS,
                       zorder=Z_LABEL, clip_on=False,
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
                fontsize=CURVE_FS, zorder=Z_LABEL,
                bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
                arrowprops={"arrowstyle": "-", "color": "0.2", "lw": 0.6, "shrinkA": 0.0,
                            "shrinkB": 0.0})
    return None


# -- the mode symbols -------------------------------------------------------------------------


def region_labels(ax: Axes, data: MapData, frame: Frame, obstacles: list[Box],
                  lines: Sequence[np.ndarray], *, on_band: bool) -> dict[Mode, list[Text]]:
    """Write each mode's symbol inside every region of it that is large enough to hold it.

    A region too thin for its symbol is labelled afterwards: on the band itself,
    framed (``on_band``, the tidy maps), else beside it with an arrow pointing in.

    Returns
    -------
    dict[Mode, list[Text]]
        The symbols of each mode shaded.
    """
    out: dict[Mode, list[Text]] = {}
    small: list[tuple[Mode, np.ndarray]] = []
    k_max, mu_max = data.k_max, data.mu_max
    for mode in data.modes:
        texts = []
        size = text_size(mode.tex, REGION_FS)
        box = frame.fraction(size)
        for poly in data.polygons.get(mode, []):
            anchor = label_anchor(poly, k_max, mu_max, box, obstacles=obstacles, lines=lines)
            if anchor is None:
                small.append((mode, poly))
                continue
            text, style = mode_symbol(mode)
            texts.append(ax.text(
                anchor[0], anchor[1], text, ha="center", va="center",
                fontsize=REGION_FS, fontstyle=style, zorder=Z_LABEL,
                bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none",
                      "alpha": 0.8}))
            obstacles.append(frame.box(anchor[0], anchor[1], 0, 0, size, "center", "center"))
        out[mode] = texts
    for mode, poly in small:  # too thin for a label: on the band, or with a leader line
        t = (_band_label if on_band else _leader_label)(ax, frame, mode, poly, obstacles, lines)
        if t is not None:
            out.setdefault(mode, []).append(t)
    return out


def _band_label(ax: Axes, frame: Frame, mode: Mode, poly: np.ndarray, obstacles: list[Box],
                lines: Sequence[np.ndarray]) -> Text | None:
    """Label a region too thin to hold its symbol: on the band itself, framed.

    The label's centre lies inside its region, at the thickest part of the
    band in view, so that it can never be read as the label of a neighbour;
    :func:`regimemap.drawing.text.tidy.tidy_figure` moves it along the band if it
    meets another text.
    """
    xs, lo, hi = band_columns(poly, frame.k_max, frame.mu_max, 400)
    room = hi - lo
    if room.max() <= 0.0:
        return None
    good = np.flatnonzero(room >= 0.6 * room.max())
    c = int(good[len(good) // 2])
    target = (float(xs[c] * frame.k_max), float(0.5 * (lo[c] + hi[c]) * frame.mu_max))
    size = text_size(mode.tex, REGION_FS)
    obstacles.append(frame.box(target[0], target[1], 0.0, 0.0, size, "center", "center"))
    text, style = mode_symbol(mode)
    t = ax.text(target[0], target[1], text, ha="center", va="center", fontsize=REGION_FS,
                fontstyle=style, zorder=Z_LABEL,
                bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.3", "lw": 0.6,
                      "alpha": 0.9})
    t.set_gid("band-label")
    return t


def _leader_label(ax: Axes, frame: Frame, mode: Mode, poly: np.ndarray, obstacles: list[Box],
                  lines: Sequence[np.ndarray]) -> Text | None:
    """Label a region too thin to hold its symbol, with an arrow pointing into it."""
    target = interior_point(poly, frame.k_max, frame.mu_max)
    if target is None:
        return None
    size = text_size(mode.tex, REGION_FS)
    at = leader_label_anchor(target, frame.k_max, frame.mu_max, frame.fraction(size), lines,
                             obstacles)
    if at is None:
        return None
    obstacles.append(frame.box(at[0], at[1], 0.0, 0.0, size, "center", "center"))
    text, style = mode_symbol(mode)
    return ax.annotate(
        text, target, xytext=at, textcoords="data", ha="center", va="center",
        fontsize=REGION_FS, fontstyle=style, zorder=Z_LABEL,
        bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.3", "lw": 0.5,
              "alpha": 0.9},
        arrowprops={"arrowstyle": "-|>", "color": "black", "lw": 0.8,
                    "shrinkA": 0.0, "shrinkB": 1.0, "mutation_scale": 8})
