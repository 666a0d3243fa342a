"""The figure and widgets of ``regimemap explore``: where everything sits, and the ranges.

:func:`build_widgets` lays out the map's axes, the sliders, the
check box, the Save button and the text panel on the explorer's figure;
:class:`~regimemap.maps.figures.explore.explorer.Explorer` wires them to its methods.
The other functions act on that figure: show or hide the load sliders,
draw the still widgets from bitmaps during a drag, clear the map, run
``plot``'s legibility pass in place and ask the canvas for a draw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ....drawing.style import agg_figure, style_context
from ....drawing.text.tidy import tidy_figure
from .images import KeyImage, TextPanel, WidgetsImage

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from matplotlib.widgets import Button, CheckButtons, Slider

    from ....drawing.artists import MapArtists

__all__ = [
    "BUOYANCY_RANGE",
    "EXPLORER_FIGSIZE",
    "GAMMA_RANGE",
    "UPLIFT_RATIO_RANGE",
    "Widgets",
    "axes_rect",
    "build_widgets",
    "clear_map",
    "freeze_widgets",
    "new_figure",
    "request_draw",
    "show_load_sliders",
    "tidy_in_place",
]

#: Size of the explorer's figure in inches: the map of ``plot`` (5.5 x 3.6 in) on the
#: left with its title and key, the sliders, buttons and the text panel on the right.
EXPLORER_FIGSIZE: tuple[float, float] = (12.4, 6.0)
#: The range of the gamma slider (log scale); a larger or smaller start widens it.
GAMMA_RANGE: tuple[float, float] = (0.1, 20.0)
#: The range of the buoyancy slider (beta over the dry weight).
BUOYANCY_RANGE: tuple[float, float] = (0.0, 0.9)
#: The range of the uplift-ratio slider (nu: U = (u + nu k) m g).
UPLIFT_RATIO_RANGE: tuple[float, float] = (0.0, 2.0)

#: Where the sliders are (inches from the left) and how wide: labels left of them, values right.
_SLIDER_LEFT, _SLIDER_WIDTH = 7.85, 3.5
#: Font size (points) of the widgets' labels and values.
_WIDGET_FS = 9.0


def new_figure(fig: Figure | None, window: bool) -> Figure:
    """The explorer's figure: ``fig`` cleared and resized, or a new one.

    ``window``: a pyplot figure (a window or a notebook canvas); else a
    figure with an Agg canvas, off screen and outside pyplot.
    """
    if fig is not None:
        fig.clear()
        fig.set_size_inches(EXPLORER_FIGSIZE)
        return fig
    if not window:  # off screen: a figure with an Agg canvas, no pyplot
        with style_context():
            off = agg_figure(EXPLORER_FIGSIZE)
        return off
    import matplotlib.pyplot as plt

    with style_context():
        new = plt.figure(figsize=EXPLORER_FIGSIZE)
    return new


def axes_rect(left: float, top: float, width: float, height: float
              ) -> tuple[float, float, float, float]:
    """An axes rectangle in figure fractions from inches (``top`` from the figure's top)."""
    w, h = EXPLORER_FIGSIZE
    return (left / w, (h - top - height) / h, width / w, height / h)


@dataclass
class Widgets:
    """The axes and widgets of an explorer's figure (:func:`build_widgets`)."""

    ax: Axes  #: the map
    gamma_slider: Slider  #: log10 of gamma
    kprime_slider: Slider
    check_ax: Axes
    loads_check: CheckButtons  #: 'loads' ticked: the two sliders below apply
    save_ax: Axes
    save_button: Button
    buoyancy_slider: Slider
    nu_slider: Slider
    info_ax: Axes  #: the panel's axes
    info: TextPanel  #: the panel's text
    key: KeyImage  #: the key from pixels while a slider is dragged
    still: WidgetsImage  #: the widgets not dragged, from pixels while a slider is dragged


def _slider(fig: Figure, top: float, label: str, lo: float, hi: float, value: float) -> Slider:
    from matplotlib.widgets import Slider

    ax = fig.add_axes(axes_rect(_SLIDER_LEFT, top, _SLIDER_WIDTH, 0.18))
    s = Slider(ax, label, lo, hi, valinit=value, valfmt="%g")
    s.label.set_fontsize(_WIDGET_FS)
    s.valtext.set_fontsize(_WIDGET_FS)
    return s


def build_widgets(fig: Figure, *, gamma: float, kprime: float, crest: float, loads_on: bool,
                  buoyancy: float, uplift_ratio: float, text: str) -> Widgets:
    """Lay out the explorer on ``fig`` (of :data:`EXPLORER_FIGSIZE`), the widgets at these values.

    The sliders' ranges widen to hold a start beyond them (gamma on a log
    scale, k' up to the crest); the panel starts with ``text``.  The value
    texts of the sliders are the numbers as given (``%g``).
    """
    from matplotlib.widgets import Button, CheckButtons

    x0, sw = _SLIDER_LEFT, _SLIDER_WIDTH
    g_lo, g_hi = GAMMA_RANGE
    with style_context():
        # the map: plot's axes size (5.5 x 3.6 in), its title above and its key below
        ax = fig.add_axes(axes_rect(0.75, 0.62, 5.5, 3.6))
        gamma_slider = _slider(fig, 0.30, "γ = H/B", math.log10(min(g_lo, gamma)),
                               math.log10(max(g_hi, gamma)), math.log10(gamma))
        kprime_slider = _slider(fig, 0.62, "k′ = h/H", -1.0, crest, kprime)
        check_ax = fig.add_axes(axes_rect(x0 - 0.12, 0.90, 2.0, 0.34))
        loads_check = CheckButtons(check_ax, ["loads: buoyancy β, uplift ratio ν"], [loads_on])
        check_ax.set_frame_on(False)
        save_ax = fig.add_axes(axes_rect(x0 + sw - 0.8, 0.92, 0.8, 0.3))
        save_button = Button(save_ax, "Save")
        buoyancy_slider = _slider(fig, 1.38, "β (buoyancy)", BUOYANCY_RANGE[0],
                                  max(BUOYANCY_RANGE[1], buoyancy), buoyancy)
        nu_slider = _slider(fig, 1.70, "ν (uplift ratio)", UPLIFT_RATIO_RANGE[0],
                            max(UPLIFT_RATIO_RANGE[1], uplift_ratio), uplift_ratio)
        # the panel: what classify says at the clicked point
        info_ax = fig.add_axes(axes_rect(6.7, 2.05, 5.6, 3.8))
        info_ax.set_axis_off()
        info = TextPanel(text)
        info_ax.add_artist(info)
        key = KeyImage()
        fig.add_artist(key)
        still = WidgetsImage()
        fig.add_artist(still)
    for slider, value in ((gamma_slider, gamma), (kprime_slider, kprime),
                          (buoyancy_slider, buoyancy), (nu_slider, uplift_ratio)):
        slider.valtext.set_text(f"{value:g}")
    save_button.label.set_fontsize(_WIDGET_FS)
    for t in loads_check.labels:
        t.set_fontsize(_WIDGET_FS)
    w = Widgets(ax, gamma_slider, kprime_slider, check_ax, loads_check, save_ax, save_button,
                buoyancy_slider, nu_slider, info_ax, info, key, still)
    show_load_sliders(w, loads_on)
    return w


def show_load_sliders(w: Widgets, on: bool) -> None:
    """Show the buoyancy and uplift-ratio sliders when 'loads' is ticked (the real widgets)."""
    w.still.thaw()
    for s in (w.buoyancy_slider, w.nu_slider):
        s.ax.set_visible(on)


def freeze_widgets(w: Widgets, moving: tuple[Any, ...]) -> None:
    """Draw the sliders other than ``moving`` and the button from bitmaps, until ``w.still.thaw()``.

    What each shows (a slider's value and its text, the button's label) tells
    when its bitmap must be made again.  The check box stays itself: its mark
    is an animated artist that the widget draws after each draw of the figure.
    """
    sliders = (w.gamma_slider, w.kprime_slider, w.buoyancy_slider, w.nu_slider)
    still: list[tuple[Axes, Any]] = [(s.ax, (s.val, s.valtext.get_text()))
                                     for s in sliders if s not in moving]
    still.append((w.save_ax, w.save_button.label.get_text()))
    w.still.freeze([ax for ax, _ in still], [sig for _, sig in still])


def request_draw(fig: Figure) -> None:
    """Ask the canvas for a draw when there is an event loop to do it (window, notebook).

    A canvas without one (Agg: tests, ``-o``, the benchmark) would draw at
    once on every request; it is drawn when saved or when asked instead.
    """
    from matplotlib.backend_bases import FigureCanvasBase

    canvas = fig.canvas
    if type(canvas).draw_idle is not FigureCanvasBase.draw_idle:
        canvas.draw_idle()


def clear_map(ax: Axes) -> None:
    """Remove what :func:`~regimemap.maps.figures.mapplot.draw_map` drew on ``ax`` (the axes stay)."""
    for a in [*ax.patches, *ax.lines, *ax.texts, *ax.collections, *ax.artists]:
        a.remove()
    legend = ax.get_legend()
    if legend is not None:
        legend.remove()


def tidy_in_place(fig: Figure, art: MapArtists) -> None:
    """``plot``'s legibility pass (:func:`~regimemap.drawing.text.tidy.tidy_figure`) on a live figure.

    It measures the texts at its own resolution and restores the figure's:
    with the window manager detached meanwhile, so that the window is not
    resized back and forth.
    """
    canvas = fig.canvas
    manager = canvas.manager
    canvas.manager = None
    try:
        tidy_figure(fig, [art])
    finally:
        canvas.manager = manager
