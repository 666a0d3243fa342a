"""Draw the parts of a map where several modes are admissible (matplotlib).

:func:`draw_ambiguity` outlines each part it is handed
(:func:`regimemap.maps.ambiguity.ambiguous_in_view`) with a bold dashed line and a
light stipple - no fill, so the map's own colours stay visible underneath -
and writes the admissible set with the mode Section 4.7 keeps, e.g.
"{SL, RO, SRO-} -> SL (§4.7)", or with loads the mode of least constraint,
"{LO, RO, SRO-} -> LO (least constraint)".  Both rules are conventions of
rigid contact, not consequences of it (a compliant-contact engine started RO,
not SL, at 40 of 40 sampled points of the {SL, RO, SRO-} sliver); the overlay
shows where the map's mode is such a convention.  A legend entry "several modes admissible" is
added to the axes' legend.  Where no part is in view (always above C) nothing
is drawn and an empty list is returned.

matplotlib is imported by this module; import it only when drawing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from ..ambiguity import AmbiguousRegion

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.backend_bases import RendererBase

__all__ = ["draw_ambiguity", "AMBIGUITY_STYLE", "LEGEND_LABEL", "legend_handle"]

#: Legend text of the outline.
LEGEND_LABEL = "several modes admissible"

#: Style of the outline and the stipple.
AMBIGUITY_STYLE: dict[str, Any] = {
    "edgecolor": "#1a1a1a",
    "linewidth": 1.8,
    "linestyle": (0, (5, 2.5)),
    "stipple": "..",
    "stipple_color": "#555555",
    "stipple_alpha": 0.45,
    "text_size": 7.5,
}

#: gid given to every artist drawn here (so tests and callers can find them).
GID = "regimemap-ambiguity"


def legend_handle() -> Line2D:
    """A proxy artist for the legend entry of the outline."""
    st = AMBIGUITY_STYLE
    return Line2D([], [], color=st["edgecolor"], linewidth=st["linewidth"],
                  linestyle=st["linestyle"], label=LEGEND_LABEL)


def _clip_poly(poly: np.ndarray, k_max: float, mu_max: float) -> np.ndarray:
    return np.column_stack([np.clip(poly[:, 0], 0.0, k_max), np.clip(poly[:, 1], 0.0, mu_max)])


def _add_to_legend(ax: Axes, handle: Artist) -> Artist | None:
    """Append ``handle`` to the axes' legend, keeping its placement and look.

    Returns the new legend, or None when the axes have no legend (the outline
    then carries the label for a later ``ax.legend()``).
    """
    old = ax.get_legend()
    if old is None:
        return None
    handles = list(getattr(old, "legend_handles", None) or getattr(old, "legendHandles", []))
    labels = [t.get_text() for t in old.get_texts()]
    if LEGEND_LABEL in labels:
        return old
    kwargs: dict[str, Any] = {
        "loc": getattr(old, "_loc", "best"),
        "ncols": getattr(old, "_ncols", 1),
        "prop": old.prop,
        "frameon": old.get_frame_on(),
        "handlelength": old.handlelength,
        "handleheight": old.handleheight,
        "handletextpad": old.handletextpad,
        "columnspacing": old.columnspacing,
        "borderaxespad": old.borderaxespad,
        "borderpad": old.borderpad,
        "labelspacing": old.labelspacing,
        # the map key's handlers (swatch and symbol, short line samples)
        "handler_map": old.get_legend_handler_map(),
    }
    if getattr(old, "_bbox_to_anchor", None) is not None:
        # the anchor in axes fractions (independent of the dpi the figure is saved at)
        bb = old.get_bbox_to_anchor().transformed(ax.transAxes.inverted())
        kwargs["bbox_to_anchor"] = (bb.x0, bb.y0, bb.width, bb.height)
    title = old.get_title().get_text()
    if title:
        kwargs["title"] = title
    return ax.legend(handles + [handle], labels + [LEGEND_LABEL], **kwargs)


def draw_ambiguity(ax: Axes, regions: Sequence[AmbiguousRegion], k_max: float, mu_max: float, *,
                   annotate: bool = True, legend: bool = True) -> list[Artist]:
    """Outline and annotate the parts of the view where several modes are admissible.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes showing the map over [0, k_max] x [0, mu_max].
    regions : sequence of AmbiguousRegion
        The parts in that view (:func:`regimemap.maps.ambiguity.ambiguous_in_view`).
    k_max, mu_max : float
        The view.
    annotate : bool
        Write "{admissible set} -> chosen (§4.7)" at each part.
    legend : bool
        Add the entry "several modes admissible" to the axes' legend (if the
        axes have a legend; otherwise the outline carries the label, for a
        later ``ax.legend()``).

    Returns
    -------
    list of Artist
        The stipples, outlines and annotations drawn (and the legend, if it
        was rebuilt); empty when no part is in view (e.g. above C).

    Notes
    -----
    A legend cannot take a new entry in place: the axes' legend is replaced
    by a new one with the same entries, placement and handlers, plus this one.
    A :class:`~regimemap.drawing.artists.MapArtists` of the map then still holds the
    old legend; set its ``legend`` to ``ax.get_legend()``.
    """
    st = AMBIGUITY_STYLE
    artists: list[Artist] = []
    if not regions:
        return artists
    if legend:
        # first, so that the labels below can keep clear of the (wider) legend
        new = _add_to_legend(ax, legend_handle())
        if new is not None:
            artists.append(new)
    polys = []
    for i, r in enumerate(regions):
        stipple = Polygon(r.polygon, closed=True, fill=False, hatch=st["stipple"],
                          edgecolor=st["stipple_color"], linewidth=0.0,
                          alpha=st["stipple_alpha"], zorder=3.4, label="_nolegend_")
        outline = Polygon(r.polygon, closed=True, fill=False, edgecolor=st["edgecolor"],
                          linewidth=st["linewidth"], linestyle=st["linestyle"], zorder=3.5,
                          label=LEGEND_LABEL if i == 0 else "_nolegend_")
        for a in (stipple, outline):
            a.set_gid(GID)
            a.set_clip_on(True)
            ax.add_patch(a)
            polys.append(a)
    artists[:0] = polys
    if annotate:
        placed: list[tuple[Any, ...]] = list(_legend_box(ax))
        for r in regions:
            artists.append(_annotate(ax, r, k_max, mu_max, placed))
    return artists


def _annotate(ax: Axes, r: AmbiguousRegion, k_max: float, mu_max: float,
              placed: list[tuple[Any, ...]]) -> Artist:
    """Write the region's label inside it when it fits, else beside it with an arrow.

    ``placed`` holds the boxes (axes fractions x0, y0, x1, y1) of labels
    already written; an outside label avoids them.
    """
    from ...drawing.text.placement import label_anchor

    st = AMBIGUITY_STYLE
    text = r.tex
    fs = st["text_size"]
    box = _label_size(ax, r, fs)
    poly = _clip_poly(r.polygon, k_max, mu_max)
    inside = label_anchor(poly, k_max, mu_max, box)
    bbox = dict(boxstyle="round,pad=0.25", facecolor="white", edgecolor="0.3",
                linewidth=0.6, alpha=0.9)
    if inside is not None and _free(_frac_box(inside[0] / k_max, inside[1] / mu_max, box), placed):
        placed.append(_frac_box(inside[0] / k_max, inside[1] / mu_max, box))
        t = ax.text(inside[0], inside[1], text, fontsize=fs, ha="center", va="center",
                    multialignment="center", bbox=bbox, zorder=6, clip_on=True)
        t.set_gid(GID)
        return t
    target = r.anchor(k_max, mu_max)
    assert target is not None
    tx0, ty0 = target[0] / k_max, target[1] / mu_max
    cx, cy, b = _outside_spot(poly, (tx0, ty0), box, k_max, mu_max, placed)
    placed.append(b)
    placed.append((cx, cy, tx0, ty0, "arrow"))
    t = ax.annotate(text, xy=target, xytext=(cx * k_max, cy * mu_max), fontsize=fs,
                    ha="center", va="center", multialignment="center", bbox=bbox, zorder=6,
                    arrowprops=dict(arrowstyle="-|>", color="0.15", linewidth=0.8,
                                    shrinkA=0, shrinkB=1))
    t.set_gid(GID)
    return t


def _label_size(ax: Axes, r: AmbiguousRegion, fs: float) -> tuple[float, float]:
    """The size of the region's label (two lines, with a margin) as fractions of the axes
    (approximate text metrics)."""
    from ...drawing.style import text_size

    fig = ax.figure
    if not isinstance(fig, Figure):  # a SubFigure has no size of its own
        raise TypeError("regimemap draws maps on the axes of a Figure, not of a SubFigure")
    pos = ax.get_position()
    w_in = max(pos.width * fig.get_figwidth(), 1e-6)
    h_in = max(pos.height * fig.get_figheight(), 1e-6)
    longest = max(r.label.replace(" (Section 4.7)", " (§4.7)").split(" -> "), key=len)
    w_pt, h_pt = text_size(longest, fs, lines=2)
    return (w_pt / 72.0 / w_in + 0.02, h_pt / 72.0 / h_in + 0.02)


def _frac_box(cx: float, cy: float, box: tuple[float, float]) -> tuple[float, float, float, float]:
    """The box of size ``box`` centred at (cx, cy) (axes fractions)."""
    return (cx - box[0] / 2, cy - box[1] / 2, cx + box[0] / 2, cy + box[1] / 2)


def _free(b: tuple[float, float, float, float], placed: list[tuple[Any, ...]]) -> bool:
    """``b`` overlaps no label placed before, nor an arrow drawn before."""
    boxes = [q for q in placed if len(q) == 4]
    if not all(b[2] < q[0] or q[2] < b[0] or b[3] < q[1] or q[3] < b[1] for q in boxes):
        return False
    # nor on an arrow drawn before (stored as 5-tuples: x0, y0, x1, y1, "arrow")
    t = np.linspace(0.0, 1.0, 24)
    for q in placed:
        if len(q) == 5:
            xs, ys = q[0] + (q[2] - q[0]) * t, q[1] + (q[3] - q[1]) * t
            if ((xs > b[0]) & (xs < b[2]) & (ys > b[1]) & (ys < b[3])).any():
                return False
    return True


def _outside_spot(poly: np.ndarray, target: tuple[float, float], box: tuple[float, float], k_max: float,
                  mu_max: float, placed: list[tuple[Any, ...]]
                  ) -> tuple[float, float, tuple[float, float, float, float]]:
    """Where a label beside its part goes (centre and box, axes fractions): the nearest free
    candidate whose arrow crosses no label and which is off the part, else the nearest with
    less of that, else left of the part at mid height."""
    tx0, ty0 = target
    # candidate spots for the label (axes fractions), nearest first, inside the view,
    # not on another label and not on the part itself
    cands = []
    for dx in (-0.3, -0.2, 0.0, 0.2, -0.4, 0.3):
        for dy in (-0.22, 0.2, -0.35, 0.32, 0.0, -0.5):
            cx, cy = tx0 + dx, ty0 + dy
            b = _frac_box(cx, cy, box)
            if b[0] < 0.01 or b[2] > 0.99 or b[1] < 0.01 or b[3] > 0.99:
                continue
            cands.append((dx * dx + dy * dy, cx, cy, b))
    cands.sort(key=lambda c: c[0])

    def clear_path(cx: float, cy: float) -> bool:
        """The arrow from the label to the part crosses no other label."""
        t = np.linspace(0.0, 1.0, 24)
        xs, ys = cx + (tx0 - cx) * t, cy + (ty0 - cy) * t
        return not any(((xs > q[0]) & (xs < q[2]) & (ys > q[1]) & (ys < q[3])).any()
                       for q in placed if len(q) == 4)

    choice = next((c for c in cands if _free(c[3], placed) and clear_path(c[1], c[2])
                   and not _hits(poly, c[3], k_max, mu_max)), None)
    if choice is None:
        choice = next((c for c in cands if _free(c[3], placed) and clear_path(c[1], c[2])), None)
    if choice is None:
        choice = next((c for c in cands if _free(c[3], placed)), None)
    if choice is None:
        cx = min(max(tx0 - 0.3, box[0] / 2 + 0.01), 1 - box[0] / 2 - 0.01)
        return cx, 0.5, _frac_box(cx, 0.5, box)
    _, cx, cy, b = choice
    return cx, cy, b


def _legend_box(ax: Axes) -> list[tuple[float, float, float, float]]:
    """The axes' legend as a box in axes fractions (empty if none or not measurable)."""
    leg = ax.get_legend()
    if leg is None:
        return []
    fig = ax.figure
    canvas = fig.canvas
    try:
        if hasattr(canvas, "get_renderer"):
            renderer = canvas.get_renderer()
            bb = leg.get_window_extent(renderer)
        else:  # a bare Figure: measure with a temporary Agg canvas, then put the old one back
            if not isinstance(fig, Figure):  # a SubFigure cannot take a canvas of its own
                return []
            from matplotlib.backends.backend_agg import FigureCanvasAgg

            try:
                # (backend_agg is not annotated: its get_renderer returns a RendererAgg)
                get_renderer: Callable[[], RendererBase] = FigureCanvasAgg(fig).get_renderer
                bb = leg.get_window_extent(get_renderer())
            finally:
                fig.set_canvas(canvas)
    except Exception:  # pragma: no cover - cannot measure: place labels anyway
        return []
    bb = bb.transformed(ax.transAxes.inverted())
    return [(bb.x0 - 0.01, bb.y0 - 0.01, bb.x1 + 0.01, bb.y1 + 0.01)]


def _hits(poly: np.ndarray, b: tuple[float, float, float, float], k_max: float,
          mu_max: float) -> bool:
    """Whether the box b (axes fractions) overlaps the polygon (tested on a few points)."""
    from matplotlib.path import Path

    xs = np.linspace(b[0], b[2], 5) * k_max
    ys = np.linspace(b[1], b[3], 3) * mu_max
    pts = np.array([(x, y) for x in xs for y in ys])
    return bool(Path(poly).contains_points(pts).any())
