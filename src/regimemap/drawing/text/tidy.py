"""Keep every text of a map figure legible: nothing overlaps, nothing leaves the figure.

:func:`regimemap.maps.figures.mapplot.draw_map` places its labels
(:mod:`regimemap.drawing.text.labels`) with a size model of the text
(:func:`regimemap.drawing.style.text_size`) and knows nothing of the tick
labels, the title, the key or the design points drawn after it.
:func:`tidy_figure` runs once the figure is laid out: it measures
every text with the renderer (window extents, in pixels), fits the titles
to the figure (wrapped at commas, then smaller), and moves each label that
meets another text or leaves the figure, in order of importance — the names
of the report's points, the names of design points, the arrows to points
outside the view, the names of the lines, the mode symbols — to the first
free place among its candidates (:mod:`regimemap.drawing.text.relabel`):

* a point's name: around the point, then farther with a leader line;
* a line's name: beside the line (:func:`regimemap.drawing.text.placement.curve_label_anchor`),
  then away from it with a leader to it;
* a mode symbol: inside its region (:func:`regimemap.drawing.text.placement.label_anchor`),
  then anywhere on the region (a thin band), framed.

A label with no free place is hidden (and listed in the report); none is
left overlapping.  :func:`text_boxes` lists the boxes that the tests check.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..artists import MapArtists
from .placer import Placer
from .relabel import (
    axes_bounds,
    inside,
    line_pixels,
    off_lines,
    place_annotation,
    place_curve_label,
    place_off_view,
    place_region_label,
    polygon_of,
    replace_label,
)
from .textboxes import GAP, Box, box_of, major_tick_labels, visible_text

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure
    from matplotlib.text import Text

__all__ = ["MEASURE_DPI", "TidyReport", "fit_title", "text_boxes", "tidy_figure"]

#: Resolution at which the texts are measured and placed (dots per inch): a map is laid
#: out the same way whatever the resolution of its file (an SVG does not depend on --dpi).
MEASURE_DPI = 150.0
#: Smallest font size (points) a title is shrunk to.
_MIN_TITLE_FS = 6.0


@dataclass
class TidyReport:
    """What :func:`tidy_figure` did: the labels it moved and those it had to hide."""

    moved: list[str] = field(default_factory=list)
    hidden: list[str] = field(default_factory=list)


# -- boxes -------------------------------------------------------------------------------------


def _marker_boxes(ax: Axes, line: Any, renderer: RendererBase) -> list[Box]:
    """Boxes of the markers of a Line2D (one per point), in pixels."""
    if line is None or not line.get_visible() or line.axes is None:
        return []
    r = 0.5 * line.get_markersize() * ax.figure.dpi / 72.0 + 0.5 * line.get_markeredgewidth()
    xy = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
    return [(x - r, y - r, x + r, y + r) for x, y in xy]


def text_boxes(fig: Figure, maps: Sequence[MapArtists], extra: Iterable[Artist] = ()
               ) -> dict[str, list[tuple[str, Box]]]:
    """Every text and marker of a figure of maps, by kind, as drawn (pixels).

    Kinds: ``fixed`` (tick and axis labels, titles, keys, the suptitle and
    ``extra``), ``markers`` (the report's points and design points) and
    ``labels`` (point names, design-point names, arrows to points off view,
    line names, mode symbols).  Call after :func:`tidy_figure` (or a draw).
    """
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fixed: list[tuple[str, Box]] = []
    markers: list[tuple[str, Box]] = []
    labels: list[tuple[str, Box]] = []
    seen_axes = []
    for art in maps:
        ax = _axes_of(art)
        if ax is None or ax in seen_axes:
            continue
        seen_axes.append(ax)
        fixed += _axes_boxes(ax, renderer)
        markers += _map_marker_boxes(ax, art, renderer)
        labels += [(f"{kind} {t.get_text()!r}", box_of(t, renderer))
                   for kind, t in _movable(art) if visible_text(t)]
    for leg in fig.legends:
        if leg.get_visible():
            fixed.append(("key", box_of(leg, renderer)))
    sup: Any = getattr(fig, "_suptitle", None)
    if visible_text(sup):
        fixed.append(("suptitle", box_of(sup, renderer)))
    for a in extra:
        if a.get_visible():
            fixed.append((f"extra {a.get_gid() or type(a).__name__}", box_of(a, renderer)))
    return {"fixed": fixed, "markers": markers, "labels": labels}


def _axes_boxes(ax: Axes, renderer: RendererBase) -> list[tuple[str, Box]]:
    """The boxes of the texts of one Axes that stay: tick and axis labels, titles, key."""
    out = [(f"tick {t.get_text()}", box_of(t, renderer)) for t in major_tick_labels(ax)]
    titles: list[Any] = [getattr(ax, n, None) for n in ("title", "_left_title", "_right_title")]
    out += [(f"axis text {t.get_text()!r}", box_of(t, renderer))
            for t in [ax.xaxis.label, ax.yaxis.label, *titles] if visible_text(t)]
    leg = ax.get_legend()
    if leg is not None and leg.get_visible():
        out.append(("key", box_of(leg, renderer)))
    return out


def _map_marker_boxes(ax: Axes, art: MapArtists, renderer: RendererBase
                      ) -> list[tuple[str, Box]]:
    """The boxes of a map's markers: the report's points, then the design points."""
    out: list[tuple[str, Box]] = []
    for name, m in art.point_markers.items():
        out += [(f"point {name}", b) for b in _marker_boxes(ax, m, renderer)]
    for a in art.extra:
        if a.get_gid() == "design-dots":
            out += [("design point", b) for b in _marker_boxes(ax, a, renderer)]
    return out


def _axes_of(art: MapArtists) -> Any:
    """The Axes a map was drawn on (None if it drew nothing)."""
    artists: list[Any] = [a for lst in art.fills.values() for a in lst]
    artists += [a for lst in art.curves.values() for a in lst]
    artists += list(art.point_labels.values()) + [art.title]
    for a in artists:
        if a is not None and a.axes is not None:
            return a.axes
    return None


def _movable(art: MapArtists) -> list[tuple[str, Any]]:
    """The labels of a map that may move, most important first."""
    named = set(art.data.points)
    out: list[tuple[str, Any]] = [("point", t) for n, t in art.point_labels.items() if n in named]
    seen: list[Any] = []
    for t in art.off_view.values():
        if not any(t is s for s in seen):
            seen.append(t)
            out.append(("off-view", t))
    out += [("point", t) for n, t in art.point_labels.items() if n not in named]  # line ends
    out += [("design", a) for a in art.extra if a.get_gid() == "design-name"]
    out += [("curve", t) for t in art.curve_labels.values()]
    out += [("region", t) for lst in art.region_labels.values() for t in lst]
    return out


# -- titles ----------------------------------------------------------------------------------


def _split_outside_math(line: str, sep: str = ", ") -> list[str]:
    """``line`` cut after each ``sep`` that is not inside ``$...$``."""
    parts, cur, in_math, i = [], "", False, 0
    while i < len(line):
        if line[i] == "$":
            in_math = not in_math
        if not in_math and line.startswith(sep, i):
            parts.append(cur + sep.rstrip())
            cur, i = "", i + len(sep)
            continue
        cur += line[i]
        i += 1
    if cur:
        parts.append(cur)
    return parts


def fit_title(t: Text, renderer: RendererBase, right: float, top: float) -> bool:
    """Fit a title between its anchor and ``right``, below ``top`` (pixels): wrap, then shrink.

    Lines too long are wrapped at their commas (never inside mathtext); if a
    line is still too long, or the title rises above ``top``, the font gets
    smaller, down to 6 points.  Returns True when the title was changed.
    """
    if not visible_text(t):
        return False

    def fits() -> bool:
        b = box_of(t, renderer)
        return b[2] <= right and b[3] <= top

    if fits():
        return False
    original = t.get_text()
    lines: list[str] = []
    for line in original.split("\n"):
        t.set_text(line)
        if box_of(t, renderer)[2] <= right:
            lines.append(line)
            continue
        cur = ""
        for piece in _split_outside_math(line):
            trial = (cur + " " + piece) if cur else piece
            t.set_text(trial)
            if cur and box_of(t, renderer)[2] > right:
                lines.append(cur)
                cur = piece
            else:
                cur = trial
        if cur:
            lines.append(cur)
    t.set_text("\n".join(lines))
    size = float(t.get_fontsize())
    while not fits() and size > _MIN_TITLE_FS:
        size = max(_MIN_TITLE_FS, size - 0.5)
        t.set_fontsize(size)
    return True


# -- the whole figure ------------------------------------------------------------------------


def tidy_figure(fig: Figure, maps: Sequence[MapArtists], *, fixed: Iterable[Artist] = (),
                fit_titles: bool = True) -> TidyReport:
    """Make the text of a laid-out figure of maps legible (see the module docstring).

    Parameters
    ----------
    fig : Figure
        With an Agg canvas; its size and the axes' positions are final.
    maps : sequence of MapArtists
        What :func:`regimemap.maps.figures.mapplot.draw_map` drew, one per map.
    fixed : iterable of Artist
        Other texts that must stay where they are (e.g. the k' of an animation frame).
    fit_titles : bool
        Wrap or shrink the titles (and the suptitle) to fit the figure.

    Returns
    -------
    TidyReport

    Notes
    -----
    The texts are measured with the figure at :data:`MEASURE_DPI` (and the
    figure's resolution restored afterwards), so the layout, and the bytes of
    an SVG or PDF, do not depend on the resolution asked for a PNG.
    """
    dpi = fig.dpi
    fig.set_dpi(MEASURE_DPI)  # the same decisions at every output resolution
    try:
        return _tidy(fig, maps, list(fixed), fit_titles)
    finally:
        fig.set_dpi(dpi)


def _tidy(fig: Figure, maps: Sequence[MapArtists], fixed: list[Artist], fit_titles: bool
          ) -> TidyReport:
    report = TidyReport()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    fig.draw_without_rendering()  # the ticks, titles and keys in their final places
    if fit_titles:
        _fit_titles(fig, maps, renderer, report)
    boxes = text_boxes(fig, maps, fixed)
    placer = Placer(fig, renderer, [b for _, b in boxes["fixed"]]
                     + [b for _, b in boxes["markers"]])
    for art in maps:
        ax = _axes_of(art)
        if ax is None:
            continue
        axes_box = axes_bounds(ax)
        lines = line_pixels(ax, art)
        for kind, t in _movable(art):
            if not visible_text(t):
                continue
            within = axes_box if kind in ("curve", "region", "off-view") else None
            if _fits_here(art, kind, t, placer, lines) and placer.free(placer.box(t), within):
                placer.take(t)
                continue
            new, ok = _move(ax, art, kind, t, placer, lines, axes_box)
            replace_label(art, t, new)
            label = f"{kind} {new.get_text()!r}"
            if ok:
                placer.take(new)
                if kind != "curve":
                    report.moved.append(label)
            else:
                new.set_visible(False)
                report.hidden.append(label)
    return report


def _fit_titles(fig: Figure, maps: Sequence[MapArtists], renderer: RendererBase,
                report: TidyReport) -> None:
    """Fit each map's title, and the suptitle, inside the figure (see :func:`fit_title`)."""
    fb = fig.bbox
    for art in maps:
        if art.title is not None and fit_title(art.title, renderer, fb.x1 - GAP, fb.y1 - GAP):
            report.moved.append(f"title {art.title.get_text()!r}")
    sup = getattr(fig, "_suptitle", None)
    if sup is not None:
        fit_title(sup, renderer, fb.x1 - GAP, fb.y1 - GAP)


def _mode_of(art: MapArtists, t: Any) -> Any:
    """The mode whose symbol ``t`` is (None if it is none of them)."""
    return next((m for m, lst in art.region_labels.items() if any(v is t for v in lst)), None)


def _fits_here(art: MapArtists, kind: str, t: Any, placer: Placer, lines: Any) -> bool:
    """Whether a label may stay where it was drawn, if nothing else is there.

    A mode symbol must lie on its region (or point to it), a point's name off the lines
    (a name written on a line reads badly); a curve's label is always placed again, with
    its measured size, closer to its line.
    """
    if kind == "region":
        xy = t.get_position()
        poly = polygon_of(art, _mode_of(art, t), (float(xy[0]), float(xy[1])))
        return (getattr(t, "arrow_patch", None) is not None
                or (poly is not None and inside(poly, xy)))
    if kind == "point" and getattr(t, "arrow_patch", None) is None:
        return bool(off_lines(placer.box(t), lines))
    return kind != "curve"


def _move(ax: Axes, art: MapArtists, kind: str, t: Any, placer: Placer, lines: Any,
          axes_box: Box) -> tuple[Any, bool]:
    """Find a label a free place among its candidates: the label (maybe a new one), found."""
    if kind in ("point", "design"):
        return place_annotation(ax, t, placer, None, lines if kind == "point" else None)
    if kind == "off-view":
        return t, place_off_view(t, placer, axes_box)
    if kind == "curve":
        name = next((n for n, v in art.curve_labels.items() if v is t), "")
        return place_curve_label(ax, art, name, t, placer)
    return place_region_label(ax, art, _mode_of(art, t), t, placer)
