"""Panel (d) of the caisson design sheet: the loaded map of the design wave, and the path.

The regions are the loaded map's exact polygons, drawn by
:func:`regimemap.maps.figures.mapplot.draw_map` as ``regimemap plot`` draws them (its
fills, boundary curves and named points, from
:func:`regimemap.maps.mapdata.compute_map` in the sheet's view); on them the design
point, the path it follows as the wave grows (0.5 to 1.5 times the design heights,
each tenth marked with the colour of its mode on its own map) and where it leaves
rest.  :func:`draw_map_panel` draws it, :func:`map_legend` writes its key below it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ...drawing.style import text_size
from ...maps.figures.mapplot import MapStyle, draw_map
from ...maps.geometry import area_in_view
from ...maps.mapdata import MapData
from ...mechanics.modes import Mode
from ...records.numbers import significant
from ..report import CaissonReport, MapView
from .panels import FS, mode_style

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ...drawing.artists import MapArtists

__all__ = ["MAP_STYLE", "draw_map_panel", "map_legend", "modes_in_view", "tidy_map_panel"]

#: How the sheet draws the map (:class:`~regimemap.maps.figures.mapplot.MapStyle`): fills,
#: boundary curves and named points, as ``regimemap plot`` draws them (``tidy``: no dotted
#: line drawn over a boundary, arrows to the points off view); no mode symbols, key or
#: title of its own (the sheet writes them).
MAP_STYLE = MapStyle(curves=True, labels=False, legend=False, title="", hatches=True, tidy=True)
#: A text box (points: left, bottom, right, top) from the axes' lower left corner.
_Box = tuple[float, float, float, float]


def modes_in_view(data: MapData) -> list[Mode]:
    """The modes whose regions are seen in the view of ``data``, in code order."""
    seen = 1e-9 * data.k_max * data.mu_max
    return [m for m in data.modes
            if any(len(p) >= 3 and area_in_view(p, data.k_max, data.mu_max) > seen
                   for p in data.polygons.get(m, []))]


def draw_map_panel(ax: Axes, r: CaissonReport, view: MapView, data: MapData
                   ) -> tuple[list[Mode], MapArtists]:
    """Draw (d): the map ``data`` (the design wave's loaded map in ``view``), the path, the labels.

    Returns the modes seen in the view (for :func:`map_legend`) and what
    :func:`~regimemap.maps.figures.mapplot.draw_map` drew.
    """
    art = draw_map(ax, data, MAP_STYLE)
    p = r.path
    ax.plot(p.k, np.full(p.k.shape, r.mu), color="black", lw=0.9, zorder=6)
    tenth = [i for i, s in enumerate(p.factors) if abs(s * 10.0 - round(s * 10.0)) < 1e-9]
    for i in tenth:
        st = mode_style(int(p.modes[i]))
        ax.plot([p.k[i]], [r.mu], marker="s", markersize=5.0, markerfacecolor=st.color,
                markeredgecolor="black", markeredgewidth=0.7, zorder=6)
    ax.plot([r.k], [r.mu], marker="o", markersize=7.0, markerfacecolor="black",
            markeredgecolor="white", markeredgewidth=1.3, zorder=7)
    labels: list[tuple[str, float, dict[str, Any]]] = [
        ("design wave", r.k, {"bbox": {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.2",
                                       "lw": 0.5}})]
    if p.onset is not None and p.onset > float(p.factors[0]):
        ko = float(np.interp(p.onset, p.factors, p.k))
        ax.plot([ko], [r.mu], marker="x", markersize=7.0, color="#b0001c", markeredgewidth=1.6,
                zorder=8)
        labels.append((f"leaves rest at {p.onset:.3f}\u00d7", ko, {
            "color": "#b0001c",
            "bbox": {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "#b0001c", "lw": 0.5}}))
    for i in (tenth[0], tenth[-1]):
        labels.append((f"{p.factors[i]:g}\u00d7", float(p.k[i]), {
            "fontsize": FS - 0.5,
            "bbox": {"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.85}}))
    _axes_style(ax, r)
    _place_path_labels(ax, labels, r.mu, view, _text_boxes(ax))
    return modes_in_view(art.data), art


def tidy_map_panel(fig: Figure, ax: Axes, art: MapArtists) -> None:
    """Move the map's own texts (point names, line names, arrows to points off view) clear of
    the path's labels and of every other text, as the tidy pass of a map does
    (:func:`regimemap.drawing.text.tidy.tidy_figure`); call it once the sheet is laid out."""
    from ...drawing.text.tidy import tidy_figure

    own = {id(t) for t in [*art.point_labels.values(), *art.curve_labels.values(),
                           *art.off_view.values()]}
    tidy_figure(fig, [art], fixed=[t for t in ax.texts if id(t) not in own], fit_titles=False)


def _axes_style(ax: Axes, r: CaissonReport) -> None:
    """The sheet's axis labels, ticks and title (over :func:`draw_map`'s), and the map's loads."""
    for t in ax.texts:  # the map's point names, in the sheet's size
        t.set_fontsize(FS)
    ax.set_xlabel("k = P / (m g)", fontsize=FS, labelpad=4.0)
    ax.set_ylabel("\u03bc", fontsize=FS + 1, labelpad=4.0, rotation=90, va="bottom")
    ax.tick_params(labelsize=FS - 0.5)
    m = r.map
    ax.set_title("(d) loaded regime map of the design wave", fontsize=FS + 1, loc="left", pad=13)
    ax.text(0.0, 1.015, f"\u03b3 = {significant(m.gamma, 3)},  k\u2032 = {significant(m.kprime, 3)},  "
                        f"U/P = {significant(m.uplift_ratio, 3)},  "
                        f"uplift arm {significant(m.uplift_arm, 3)},  "
                        f"buoyancy {significant(m.buoyancy, 3)},  i = {significant(m.gyration or 0.0, 3)}",
            fontsize=FS - 0.5, ha="left", va="bottom", color="0.2", transform=ax.transAxes)


def _text_boxes(ax: Axes) -> list[_Box]:
    """The boxes of the texts already inside the map (point names, curve names), in points."""
    fig = ax.get_figure(root=True)
    assert fig is not None
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    frame = ax.get_window_extent(renderer)
    scale = 72.0 / fig.dpi
    boxes = []
    for t in ax.texts:
        if t.get_transform() is ax.transAxes or not t.get_text().strip():
            continue  # the line of loads above the map
        bb = t.get_window_extent(renderer)
        boxes.append(((bb.x0 - frame.x0) * scale, (bb.y0 - frame.y0) * scale,
                      (bb.x1 - frame.x0) * scale, (bb.y1 - frame.y0) * scale))
    return boxes


def _place_path_labels(ax: Axes, labels: list[tuple[str, float, dict[str, Any]]], mu: float,
                       view: MapView, placed: list[_Box]) -> None:
    """Label points of the path (all at height ``mu``) without overlaps, inside the axes.

    Each label tries, in order: above (centred, left, right), below (the same),
    then further above and below, clear of the boxes ``placed`` (the map's own texts,
    then the labels placed); its size is estimated with
    :func:`~regimemap.drawing.style.text_size` from the axes' size in points.
    """
    bbox = ax.get_position()
    fig = ax.get_figure(root=True)
    assert fig is not None
    fig_w, fig_h = fig.get_size_inches()
    w_pt, h_pt = bbox.width * fig_w * 72.0, bbox.height * fig_h * 72.0
    y0 = mu / view.mu_max * h_pt
    gap, dy = 4.0, 8.0
    candidates = [(sx, sy * level) for level in (1.0, 2.6) for sy in (1.0, -1.0)
                  for sx in (0.0, -1.0, 1.0)]
    for text, k, kw in labels:
        fs = float(kw.pop("fontsize", FS))
        tw, th = text_size(text, fs)
        x = k / view.k_max * w_pt
        choice = candidates[0]
        for sx, sy in candidates:
            left = x - tw - gap if sx < 0 else (x + gap if sx > 0 else x - 0.5 * tw)
            bottom = y0 + dy * sy if sy > 0 else y0 + dy * sy - th
            box = (left, bottom, left + tw, bottom + th)
            inside = box[0] >= 0 and box[2] <= w_pt and box[1] >= 0 and box[3] <= h_pt
            clear = all(box[2] <= b[0] or box[0] >= b[2] or box[3] <= b[1] or box[1] >= b[3]
                        for b in placed)
            if inside and clear:
                choice = (sx, sy)
                placed.append(box)
                break
        sx, sy = choice
        ha = "right" if sx < 0 else ("left" if sx > 0 else "center")
        ax.annotate(text, (k, mu), xytext=(gap * sx, dy * sy), textcoords="offset points", ha=ha,
                    va="bottom" if sy > 0 else "top", fontsize=fs, zorder=8, **kw)


def map_legend(ax: Axes, modes: list[Mode], data: MapData) -> None:
    """The key of (d) below it, as a map's (:func:`regimemap.maps.figures.key.key_handles`): the
    modes seen, the line styles drawn, then the path."""
    from matplotlib.lines import Line2D

    from ...maps.figures.key import key_handles, key_legend

    plain = [c for c in data.curves.values() if not c.dotted]
    dotted = [c for c in data.curves.values() if c.dotted]
    handles = key_handles(modes, boundary=bool(data.curves),
                          construction=any(not b for c in plain for _, b in c.runs()),
                          dotted_label=("dotted line " + dotted[0].label) if dotted else None)
    handles.append(Line2D([], [], color="black", lw=0.9, marker="s", markersize=4.5,
                          markerfacecolor="white", markeredgecolor="black",
                          label="path: H \u00d7 0.5 \u2026 1.5 (see the note)"))
    key_legend(ax, handles, loc="upper left", bbox_to_anchor=(-0.1, -0.125), ncol=2,
               fontsize=FS - 0.5, frameon=False, borderaxespad=0.0, columnspacing=1.5)
