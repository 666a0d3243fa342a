"""The regime map, live: sliders for gamma and k' (and the loads), a click for the physics.

:class:`Explorer` builds one matplotlib figure: the map of ``regimemap plot``
on the left, drawn by the same functions (:func:`~regimemap.drawing.figure.map_data`
and :func:`~regimemap.drawing.mapplot.draw_map`: the same view, the same
polygons); on the right, sliders for the aspect ratio gamma (log scale) and
the force height k', a check box that shows two more sliders for the
buoyancy beta and the uplift ratio nu, a *Save* button, and a text panel.
A click on the map shows in the panel (and prints) the mode at that point,
its margins and the physics at initiation; *Save* writes the current view as
``regimemap plot`` draws it (the same :func:`~regimemap.drawing.figure.map_figure`,
the same bytes).

Only matplotlib's own widgets are used (``Slider``, ``CheckButtons``,
``Button``), so the same code runs in a desktop window (``regimemap
explore``) and in Jupyter with ``%matplotlib widget`` (ipympl, the extra
``regimemap[notebook]``).  Each widget calls one plain method --
:meth:`Explorer.set_gamma`, :meth:`~Explorer.set_kprime`,
:meth:`~Explorer.set_loads`, :meth:`~Explorer.click`, :meth:`~Explorer.save` --
which the tests and a notebook call directly, without events.

Speed.  While a slider is dragged the map is redrawn by ``draw_map`` alone,
from exactly ``plot``'s data (the same polygons and lines, at the same
resolution), but without the mode symbols in the regions, with the key drawn
from a bitmap (:class:`KeyImage`) and with the panel's answer left for later;
when the mouse is released (and after every call from code) the map is
drawn whole, with ``plot``'s legibility pass
(:func:`~regimemap.drawing.tidy.tidy_figure`), and the panel is brought up to
date.  The panel's text is drawn from a bitmap made once per text
(:class:`TextPanel`).  ``bench/bench_explore.py`` measures both kinds of update.

This module uses pyplot (to open a window or a notebook canvas) when no
figure is given; it never changes matplotlib's global settings.
"""

from __future__ import annotations

import math
import os
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist

from ..io.tables import format_result
from ..maps.geometry import DEFAULT_SAMPLES
from ..maps.points import DesignPoint
from ..maps.query import PointResult, query_points
from ..mechanics.block import LOAD_DEFAULTS, Parameters
from .artists import MapArtists
from .figure import map_data, map_figure
from .mapplot import MapStyle, draw_design_points, draw_map
from .save import DEFAULT_DPI, format_from_path, save_figure
from .style import style_context
from .tidy import tidy_figure

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import Event, RendererBase
    from matplotlib.figure import Figure
    from matplotlib.legend import Legend
    from matplotlib.widgets import Button, CheckButtons, Slider

__all__ = [
    "BUOYANCY_RANGE",
    "EXPLORER_FIGSIZE",
    "Explorer",
    "GAMMA_RANGE",
    "UPLIFT_RATIO_RANGE",
    "default_file_stem",
    "drag_title",
    "window_problem",
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

#: Loads that the sliders set; the others (uplift, arm, gyration, crest) stay as given.
_SLIDER_LOADS = ("buoyancy", "uplift_ratio")
_PANEL_FS = 7.0
_HINT = ("Click on the map: the mode at that point, its margins\n"
         "and the physics at initiation (as `regimemap classify`).\n\n"
         "Drag the sliders to change gamma and k'; tick 'loads'\n"
         "for the buoyancy beta and the uplift ratio nu.\n"
         "'Save' writes this map as `regimemap plot` draws it.")

Describe = Callable[[PointResult], str]
Write = Callable[["Figure", Path, str, float], object]


def default_file_stem(params: Parameters) -> str:
    """A file name without suffix for the saved view: ``regime-g3-kp0.4`` (``-loaded`` for loads).

    ``regimemap explore`` names its files exactly as ``regimemap plot`` does
    (``regime-g0.7-kp-0.02-b0.32-nu0.52``); this is the stand-alone default.
    """
    stem = f"regime-g{params.gamma:g}-kp{params.kprime:g}"
    return stem + ("-loaded" if params.loaded else "")


def _snap_gamma(g: float) -> float:
    """gamma to three significant digits (what the slider shows, the title and the file name)."""
    return float(f"{g:.3g}")


def _snap_kprime(kp: float) -> float:
    return round(float(kp), 3) + 0.0  # -0.0 -> 0.0


def _snap_load(v: float) -> float:
    return round(float(v), 3) + 0.0


def _snap_click(x: float, span: float) -> float:
    """A clicked coordinate rounded to 1/1000 of the axis (or finer): a number one can type."""
    if not (math.isfinite(x) and span > 0.0):
        return max(float(x), 0.0)
    digits = -math.floor(math.log10(span / 1000.0))
    return max(round(float(x), digits) + 0.0, 0.0)


#: The built-in matplotlib backends that draw to files only (no window).
_FILE_BACKENDS = frozenset({"agg", "cairo", "pdf", "pgf", "ps", "svg", "template"})


def window_problem() -> str | None:
    """Why pyplot cannot open a window here, in words (None if it can).

    The backend draws to files only (Agg: no display, or ``MPLBACKEND=agg``),
    or a GUI backend cannot start.
    """
    try:
        import matplotlib.pyplot as plt

        backend = str(plt.get_backend())
    except ImportError as exc:  # e.g. a GUI backend whose toolkit is missing
        return f"the matplotlib backend cannot start ({exc})"
    name = backend.lower().removeprefix("module://")
    if name in _FILE_BACKENDS or name.endswith("backend_inline"):
        headless = sys.platform.startswith("linux") and not (
            os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
        why = "there is no display (DISPLAY is not set), so " if headless else ""
        return f"{why}matplotlib's backend is {backend!r}, which draws to files only"
    return None


def drag_title(params: Parameters) -> str:
    """``plot``'s title with its numbers as plain text, for the frames of a drag.

    The default title writes the numbers in mathtext (``$\\gamma = 3.05$``):
    a new string to parse at every frame of a drag (~10 ms).  Here only the
    symbols are mathtext (parsed once, then cached) and the numbers are plain
    text in the same font, with a true minus sign; the first line is
    ``plot``'s own.  The release draws ``plot``'s title again.
    """
    from ..maps.describe import LOAD_SYMBOLS, format_value, load_items
    from .mapplot import default_title

    def num(text: str) -> str:
        return text.replace("-", "\u2212")

    first = default_title(params).split("\n")[0]
    parts = [rf"$\gamma$ = {num(f'{params.gamma:g}')}", f"$k'$ = {num(f'{params.kprime:g}')}"]
    loads = [f"${LOAD_SYMBOLS[name][1]}$ = {num(format_value(v))}" for name, v in load_items(params)]
    return f"{first}\n(" + ", ".join(parts) + ("; " + ", ".join(loads) if loads else "") + ")"


class TextPanel(Artist):
    """A block of monospaced text in a box, drawn from a bitmap made once per text.

    A figure is drawn whole on every change of a slider, and matplotlib renders
    text glyph by glyph: the ~1000 characters of a ``classify`` answer would
    cost ~60 ms a frame.  This artist renders its text (with matplotlib, at the
    canvas's resolution) only when the text, the resolution or the size of its
    axes changes, and otherwise draws the cached image (~1 ms).  It fills the
    axes it is added to, the text from the top left.
    """

    def __init__(self, text: str = "", fontsize: float = _PANEL_FS) -> None:
        super().__init__()
        self._text = text
        self._fontsize = fontsize
        self._cache: tuple[tuple[str, float, int, int], np.ndarray] | None = None
        self.renders = 0  # how many times the text was rendered (the tests count them)

    def get_text(self) -> str:
        return self._text

    def set_text(self, text: str) -> None:
        if text != self._text:
            self._text = text
            self.stale = True

    def image(self, dpi: float, width: int, height: int) -> np.ndarray:
        """The text as RGBA pixels, ``height`` x ``width``, row 0 at the bottom."""
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        key = (self._text, float(dpi), int(width), int(height))
        if self._cache is None or self._cache[0] != key:
            with style_context():
                fig = Figure(figsize=(width / dpi, height / dpi), dpi=dpi, facecolor="none")
                canvas = FigureCanvasAgg(fig)
                pad = 6.0 / 72.0 * dpi  # the box's padding, in pixels
                fig.text(pad / width, 1.0 - pad / height, self._text, va="top", ha="left",
                         family="monospace", fontsize=self._fontsize, linespacing=1.25,
                         bbox={"boxstyle": "round,pad=0.5", "fc": "0.97", "ec": "0.75",
                               "lw": 0.6})
                canvas.draw()  # type: ignore[no-untyped-call]
            pixels = np.asarray(canvas.buffer_rgba())[::-1].copy()  # type: ignore[no-untyped-call]
            self._cache = (key, pixels)
            self.renders += 1
        return self._cache[1]

    def draw(self, renderer: RendererBase) -> None:
        if not self.get_visible() or self.axes is None or not self._text:
            self.stale = False
            return
        box = self.axes.bbox
        width, height = int(round(box.width)), int(round(box.height))
        if width < 2 or height < 2:
            return
        gc = renderer.new_gc()
        dpi = float(np.asarray(renderer.points_to_pixels(72.0)))  # the resolution
        renderer.draw_image(gc, box.x0, box.y0, self.image(dpi, width, height))
        gc.restore()
        self.stale = False


class KeyImage(Artist):
    """The map's key drawn from a bitmap while a slider moves.

    :func:`draw_map` makes a new key at every redraw, and the key is the most
    expensive part of a frame (~20 ms of glyphs).  While a slider is dragged
    the key's content rarely changes: :meth:`show` hides the new key and
    draws, in its place, the pixels of a key with the same entries rendered
    once (again only when the entries, the resolution or the layout change).
    After the release the real key is drawn again (:meth:`hide`).
    """

    def __init__(self) -> None:
        super().__init__()
        self._cache: tuple[tuple[Any, ...], float, float, np.ndarray] | None = None
        self._shown = False
        self.set_zorder(5.0)
        self.renders = 0

    def show(self, legend: Legend) -> None:
        """Draw ``legend`` (of a map of this figure) from pixels instead of itself."""
        from matplotlib.backends.backend_agg import RendererAgg
        from matplotlib.figure import Figure

        fig = legend.figure
        assert isinstance(fig, Figure) and legend.axes is not None
        signature = (tuple(t.get_text() for t in legend.get_texts()), float(fig.dpi),
                     tuple(fig.bbox.bounds), tuple(legend.axes.get_position().bounds))
        if self._cache is None or self._cache[0] != signature:
            width, height = int(math.ceil(fig.bbox.width)), int(math.ceil(fig.bbox.height))
            renderer = RendererAgg(width, height, fig.dpi)  # type: ignore[no-untyped-call]
            with style_context():
                legend.draw(renderer)
                box = legend.get_window_extent(renderer)
            x0, y0 = max(int(math.floor(box.x0)) - 2, 0), max(int(math.floor(box.y0)) - 2, 0)
            x1 = min(int(math.ceil(box.x1)) + 2, width)
            y1 = min(int(math.ceil(box.y1)) + 2, height)
            pixels = np.asarray(renderer.buffer_rgba())  # type: ignore[no-untyped-call]
            crop = pixels[height - y1:height - y0, x0:x1][::-1].copy()
            self._cache = (signature, float(x0), float(y0), crop)
            self.renders += 1
        legend.set_visible(False)
        self._shown = True
        self.stale = True

    def hide(self) -> None:
        """Draw nothing (the real key is shown)."""
        self._shown = False
        self.stale = True

    @property
    def shown(self) -> bool:
        return self._shown

    def draw(self, renderer: RendererBase) -> None:
        dpi = float(np.asarray(renderer.points_to_pixels(72.0)))  # the resolution
        if self._shown and self._cache is not None and self._cache[0][1] == dpi \
                and self._cache[3].size:
            _, x0, y0, crop = self._cache
            gc = renderer.new_gc()
            renderer.draw_image(gc, x0, y0, crop)
            gc.restore()
        self.stale = False


class Explorer:
    """The regime map of one block with sliders, a click query and a Save button.

    Parameters
    ----------
    params : Parameters, optional
        The block to start from (default gamma = 3, k' = 0.4).  Its buoyancy
        and uplift ratio are the starting values of their sliders (ticked on
        when either is not 0); its other loads (uplift, arm, gyration, crest)
        stay fixed.
    resolution : int
        Samples of k of the polygons and curves (``plot --resolution``).
    fig : Figure, optional
        A figure to draw on (cleared); default: a new pyplot figure of
        :data:`EXPLORER_FIGSIZE`, so that a window or a notebook canvas shows it.
    window : bool
        False: without ``fig``, draw on a figure of its own with an Agg canvas,
        off screen and outside pyplot (``regimemap explore -o``, scripts).
    describe : callable, optional
        ``PointResult -> str``: the text of a clicked point; default
        :func:`regimemap.io.format_result`, the text of ``regimemap classify``.
    write : callable, optional
        ``(figure, path, format, dpi)``: writes the saved view; default
        :func:`regimemap.drawing.save.save_figure` (atomic, the bytes of ``plot``).
    file_stem : callable, optional
        ``Parameters -> str``: the file name (without ``.png``) of *Save*;
        default :func:`default_file_stem`.  ``regimemap explore``
        (:func:`regimemap.cli.explore.open_explorer`) passes ``plot``'s.
    echo : callable or None
        Where the text of a click and the path of a saved file are printed
        (default :func:`print`; None: nowhere).

    Attributes
    ----------
    fig : Figure
    ax : Axes
        The map's axes.
    artists : MapArtists
        What :func:`draw_map` drew last (its ``data`` is the :class:`MapData` of the map).
    result : PointResult or None
        The answer at the last clicked point, at the current parameters.
    info_text : str
        The text of the panel.
    last_update : float
        Seconds taken by the last redraw of the map (without the canvas draw).

    Examples
    --------
    In Jupyter, after ``%matplotlib widget``::

        from regimemap import Parameters
        from regimemap.drawing.explore import Explorer

        ex = Explorer(Parameters(gamma=3, kprime=0.4))
        ex.set_gamma(2.5)          # what the slider does
        ex.click(0.45, 0.6)        # what a click does
        ex.save("map.png")         # what the Save button does
    """

    def __init__(self, params: Parameters | None = None, *, resolution: int = DEFAULT_SAMPLES,
                 fig: Figure | None = None, describe: Describe | None = None,
                 write: Write | None = None, file_stem: Callable[[Parameters], str] | None = None,
                 echo: Callable[[str], None] | None = print, window: bool = True) -> None:
        from ..mechanics.validation import check_resolution

        p = Parameters(3.0, 0.4) if params is None else params
        self.resolution = check_resolution("resolution", resolution)
        self.describe: Describe = describe if describe is not None else format_result
        self.write: Write = write if write is not None else save_figure
        self.file_stem = file_stem if file_stem is not None else default_file_stem
        self.echo = echo
        self._gamma = float(p.gamma)
        self._kprime = float(p.kprime)
        self._loads_on = p.buoyancy != 0.0 or p.uplift_ratio != 0.0
        self._load_values = {"buoyancy": float(p.buoyancy), "uplift_ratio": float(p.uplift_ratio)}
        self._fixed = {k: v for k, v in p.loads.items() if k not in _SLIDER_LOADS}
        self._point: DesignPoint | None = None
        self.result: PointResult | None = None
        self.info_text = _HINT
        self.last_update = 0.0
        self._syncing = False
        self._pending = False  # a slider was dragged: tidy and the panel wait for the release
        self.fig = self._new_figure(fig, window)
        self._build()
        self.artists: MapArtists = self._draw(final=True)
        # the widgets hold their callbacks weakly through the canvas: keep this object
        # alive as long as its figure (a notebook cell may not keep a reference)
        self.fig.__dict__["regimemap_explorer"] = self

    # -- the block ------------------------------------------------------------------------------
    @property
    def params(self) -> Parameters:
        """The block now shown (the loads of the sliders only when 'loads' is ticked)."""
        return Parameters(self._gamma, self._kprime, **self.loads)

    @property
    def loads(self) -> dict[str, Any]:
        """The load keywords of :attr:`params` that differ from the report's block."""
        out = {k: v for k, v in self._fixed.items() if v != LOAD_DEFAULTS[k]}
        if self._loads_on:
            out.update({k: v for k, v in self._load_values.items() if v != 0.0})
        order = list(LOAD_DEFAULTS)
        return dict(sorted(out.items(), key=lambda kv: order.index(kv[0])))

    @property
    def point(self) -> DesignPoint | None:
        """The last clicked point (drawn on the map and in the saved file), or None."""
        return self._point

    @property
    def loads_enabled(self) -> bool:
        """Whether the buoyancy and uplift-ratio sliders apply ('loads' ticked)."""
        return self._loads_on

    # -- what the widgets call ----------------------------------------------------------------
    def set_gamma(self, value: float, *, final: bool = True) -> None:
        """Show the map of aspect ratio ``value`` (rounded to 3 significant digits).

        ``final=False`` (a slider being dragged) skips the legibility pass and
        the panel until :meth:`finish` (the release of the mouse).
        """
        g = _snap_gamma(value)
        Parameters(g, self._kprime, **self.loads)  # refuse a bad value before changing anything
        changed = g != self._gamma
        self._gamma = g
        self._sync_slider(self.gamma_slider, math.log10(g), f"{g:g}")
        self._update(final, changed)

    def set_kprime(self, value: float, *, final: bool = True) -> None:
        """Show the map of force height ``value`` (rounded to 0.001)."""
        kp = _snap_kprime(value)
        Parameters(self._gamma, kp, **self.loads)
        changed = kp != self._kprime
        self._kprime = kp
        self._sync_slider(self.kprime_slider, kp, f"{kp:g}")
        self._update(final, changed)

    def set_loads(self, buoyancy: float | None = None, uplift_ratio: float | None = None, *,
                  enabled: bool | None = None, final: bool = True) -> None:
        """Set the buoyancy beta and / or the uplift ratio nu (rounded to 0.001), or the toggle.

        Giving a value ticks 'loads' on (unless ``enabled=False``);
        ``set_loads(enabled=False)`` shows the report's block again (the
        slider values are kept for the next time).
        """
        values = dict(self._load_values)
        if buoyancy is not None:
            values["buoyancy"] = _snap_load(buoyancy)
        if uplift_ratio is not None:
            values["uplift_ratio"] = _snap_load(uplift_ratio)
        on = self._loads_on if enabled is None and buoyancy is None and uplift_ratio is None \
            else (True if enabled is None else bool(enabled))
        extra = {k: v for k, v in values.items() if v != 0.0} if on else {}
        before = self.params
        Parameters(self._gamma, self._kprime, **{**self._fixed, **extra})
        self._load_values = values
        if on != self._loads_on:
            self._loads_on = on
            check = self.loads_check
            self._syncing, drawon = True, check.drawon
            check.drawon = False
            try:
                if check.get_status()[0] != on:
                    check.set_active(0)
            finally:
                self._syncing, check.drawon = False, drawon
        self._sync_slider(self.buoyancy_slider, values["buoyancy"], f"{values['buoyancy']:g}")
        self._sync_slider(self.nu_slider, values["uplift_ratio"], f"{values['uplift_ratio']:g}")
        self._show_load_sliders()
        self._update(final, self.params != before)

    def click(self, k: float, mu: float) -> PointResult:
        """The answer at (k, mu): shown in the panel, printed, and the point marked on the map.

        The point is rounded to 1/1000 of the view (a number one can type
        back into ``regimemap classify``).  The answer is what
        ``regimemap classify`` computes (:func:`regimemap.query_points`), as
        text by ``describe``.
        """
        data = self.artists.data
        pt = DesignPoint(_snap_click(k, data.k_max), _snap_click(mu, data.mu_max))
        self._point = pt
        self._draw(final=True)
        result = self.result
        assert result is not None
        if self.echo is not None:
            self.echo(self.info_text)
        self._request_draw()
        return result

    def clear_point(self) -> None:
        """Forget the clicked point (the map and the panel without it)."""
        self._point = None
        self.result = None
        self.info_text = _HINT
        self._draw(final=True)
        self._request_draw()

    def save(self, path: str | Path | None = None) -> Path:
        """Write the current view as ``regimemap plot`` draws it; return the path.

        The same function as ``plot`` (:func:`~regimemap.drawing.figure.map_figure`
        with its defaults, ``--resolution``, the loads and the clicked point
        as ``--point K,MU``) and the same writer, so the file has ``plot``'s
        bytes.  Default path: ``file_stem(params) + ".png"`` in the current folder.
        """
        target = Path(path) if path is not None else Path(f"{self.file_stem(self.params)}.png")
        fmt = format_from_path(target)
        points = [self._point] if self._point is not None else []
        fig, _, _ = map_figure(self.params, dpi=DEFAULT_DPI, points=points,
                               samples=self.resolution, view="designer")
        self.write(fig, target, fmt, DEFAULT_DPI)
        if self.echo is not None:
            self.echo(str(target))
        return target

    def finish(self) -> None:
        """Complete an update left for the end of a drag: the legibility pass and the panel."""
        if self._pending:
            self._pending = False
            self._draw(final=True)
            self._request_draw()

    def show(self, title: str = "regimemap explore") -> None:
        """Show the window and wait until it is closed (``pyplot.show``)."""
        import matplotlib.pyplot as plt

        manager = self.fig.canvas.manager
        if manager is not None:
            manager.set_window_title(title)
        plt.show()

    def close(self) -> None:
        """Close the figure (pyplot's window or canvas; an off-screen figure is just released)."""
        self.fig.__dict__.pop("regimemap_explorer", None)
        if self.fig.canvas.manager is not None:
            import matplotlib.pyplot as plt

            plt.close(self.fig)

    def __repr__(self) -> str:
        loads = "".join(f", {k}={v:g}" for k, v in self.loads.items() if isinstance(v, float))
        at = "" if self._point is None else f"; point k={self._point.k:g}, mu={self._point.mu:g}"
        return f"<Explorer gamma={self._gamma:g}, k'={self._kprime:g}{loads}{at}>"

    # -- figure and widgets --------------------------------------------------------------------
    @staticmethod
    def _new_figure(fig: Figure | None, window: bool) -> Figure:
        if fig is not None:
            fig.clear()
            fig.set_size_inches(EXPLORER_FIGSIZE)
            return fig
        if not window:  # off screen: a figure with an Agg canvas, no pyplot
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure

            with style_context():
                off = Figure(figsize=EXPLORER_FIGSIZE)
            FigureCanvasAgg(off)
            return off
        import matplotlib.pyplot as plt

        with style_context():
            new = plt.figure(figsize=EXPLORER_FIGSIZE)
        return new

    def _rect(self, left: float, top: float, width: float, height: float
              ) -> tuple[float, float, float, float]:
        """An axes rectangle in figure fractions from inches (``top`` from the figure's top)."""
        w, h = EXPLORER_FIGSIZE
        return (left / w, (h - top - height) / h, width / w, height / h)

    def _build(self) -> None:
        from matplotlib.widgets import Button, CheckButtons, Slider

        fig = self.fig
        x0, sw = _SLIDER_LEFT, _SLIDER_WIDTH
        with style_context():
            # the map: plot's axes size (5.5 x 3.6 in), its title above and its key below
            self.ax: Axes = fig.add_axes(self._rect(0.75, 0.62, 5.5, 3.6))
            self.gamma_slider: Slider = self._slider(
                Slider, 0.30, "γ = H/B", *self._gamma_range(), math.log10(self._gamma),
                f"{self._gamma:g}")
            crest = float(self._fixed.get("crest", 1.0))
            self.kprime_slider: Slider = self._slider(
                Slider, 0.62, "k′ = h/H", -1.0, crest, self._kprime, f"{self._kprime:g}")
            self.check_ax: Axes = fig.add_axes(self._rect(x0 - 0.12, 0.90, 2.0, 0.34))
            self.loads_check: CheckButtons = CheckButtons(
                self.check_ax, ["loads: buoyancy β, uplift ratio ν"], [self._loads_on])
            self.check_ax.set_frame_on(False)
            self.save_ax: Axes = fig.add_axes(self._rect(x0 + sw - 0.8, 0.92, 0.8, 0.3))
            self.save_button: Button = Button(self.save_ax, "Save")
            b0 = self._load_values["buoyancy"]
            n0 = self._load_values["uplift_ratio"]
            self.buoyancy_slider: Slider = self._slider(
                Slider, 1.38, "β (buoyancy)", BUOYANCY_RANGE[0], max(BUOYANCY_RANGE[1], b0),
                b0, f"{b0:g}")
            self.nu_slider: Slider = self._slider(
                Slider, 1.70, "ν (uplift ratio)", UPLIFT_RATIO_RANGE[0],
                max(UPLIFT_RATIO_RANGE[1], n0), n0, f"{n0:g}")
            # the panel: what classify says at the clicked point
            self.info_ax: Axes = fig.add_axes(self._rect(6.7, 2.05, 5.6, 3.8))
            self.info_ax.set_axis_off()
            self._info = TextPanel(self.info_text)
            self.info_ax.add_artist(self._info)
            self._key = KeyImage()
            fig.add_artist(self._key)
        self.save_button.label.set_fontsize(9.0)
        for t in self.loads_check.labels:
            t.set_fontsize(9.0)
        self._show_load_sliders()
        self.gamma_slider.on_changed(self._on_gamma)
        self.kprime_slider.on_changed(self._on_kprime)
        self.buoyancy_slider.on_changed(self._on_buoyancy)
        self.nu_slider.on_changed(self._on_nu)
        self.loads_check.on_clicked(self._on_check)
        self.save_button.on_clicked(self._on_save)
        self._cids = [fig.canvas.mpl_connect("button_press_event", self._on_press),
                      fig.canvas.mpl_connect("button_release_event", self._on_release)]

    def _gamma_range(self) -> tuple[float, float]:
        lo, hi = GAMMA_RANGE
        return (math.log10(min(lo, self._gamma)), math.log10(max(hi, self._gamma)))

    def _slider(self, cls: type[Slider], top: float, label: str, lo: float, hi: float,
                value: float, text: str) -> Slider:
        ax = self.fig.add_axes(self._rect(_SLIDER_LEFT, top, _SLIDER_WIDTH, 0.18))
        s = cls(ax, label, lo, hi, valinit=value, valfmt="%g")
        s.label.set_fontsize(9.0)
        s.valtext.set_fontsize(9.0)
        s.valtext.set_text(text)
        return s

    def _show_load_sliders(self) -> None:
        for s in (self.buoyancy_slider, self.nu_slider):
            s.ax.set_visible(self._loads_on)

    def _sync_slider(self, slider: Slider, value: float, text: str) -> None:
        """Move a slider to ``value`` without calling back; show ``text`` as its value."""
        value = min(max(value, slider.valmin), slider.valmax)  # the value itself may be beyond
        if slider.val != value:
            self._syncing, drawon = True, slider.drawon
            slider.drawon = False  # one draw for the whole update (_request_draw)
            try:
                slider.set_val(value)
            finally:
                self._syncing, slider.drawon = False, drawon
        slider.valtext.set_text(text)

    # -- callbacks (events -> the plain methods) ------------------------------------------------
    def _dragging(self) -> bool:
        return any(getattr(s, "drag_active", False) for s in
                   (self.gamma_slider, self.kprime_slider, self.buoyancy_slider, self.nu_slider))

    def _guard(self, action: Callable[[], None]) -> None:
        """Run a widget's action; a refused value is shown in the panel, not raised into the GUI."""
        if self._syncing:
            return
        try:
            action()
        except ValueError as exc:
            self._set_info(f"not shown: {exc}")
            self._request_draw()

    def _on_gamma(self, val: float) -> None:
        self._guard(lambda: self.set_gamma(10.0 ** val, final=not self._dragging()))

    def _on_kprime(self, val: float) -> None:
        self._guard(lambda: self.set_kprime(val, final=not self._dragging()))

    def _on_buoyancy(self, val: float) -> None:
        self._guard(lambda: self.set_loads(buoyancy=val, final=not self._dragging()))

    def _on_nu(self, val: float) -> None:
        self._guard(lambda: self.set_loads(uplift_ratio=val, final=not self._dragging()))

    def _on_check(self, label: str | None) -> None:
        self._guard(lambda: self.set_loads(enabled=bool(self.loads_check.get_status()[0])))

    def _on_save(self, event: Event) -> None:
        try:
            self.save()
        except (OSError, ValueError) as exc:
            self._set_info(f"not saved: {exc}")
            self._request_draw()

    def _on_press(self, event: Any) -> None:
        if event.inaxes is not self.ax or event.button != 1 or event.xdata is None:
            return
        toolbar: Any = getattr(self.fig.canvas, "toolbar", None)
        if toolbar is not None and toolbar.mode:
            return  # zooming or panning
        self._guard(lambda: self._click_event(event.xdata, event.ydata))

    def _click_event(self, k: float, mu: float) -> None:
        self.click(k, mu)

    def _on_release(self, event: Any) -> None:
        self.finish()

    # -- drawing -----------------------------------------------------------------------------------
    def _update(self, final: bool, changed: bool = True) -> None:
        """Redraw after a change (nothing to do if the map is the same and nothing waits)."""
        if not changed and not (final and self._pending):
            return
        self._pending = not final
        self._draw(final)
        self._request_draw()

    def _request_draw(self) -> None:
        """Ask the canvas for a draw when there is an event loop to do it (window, notebook).

        A canvas without one (Agg: tests, ``-o``, the benchmark) would draw at
        once on every request; it is drawn when saved or when asked instead.
        """
        from matplotlib.backend_bases import FigureCanvasBase

        canvas = self.fig.canvas
        if type(canvas).draw_idle is not FigureCanvasBase.draw_idle:
            canvas.draw_idle()

    def _clear_map(self) -> None:
        ax = self.ax
        for a in [*ax.patches, *ax.lines, *ax.texts, *ax.collections, *ax.artists]:
            a.remove()
        legend = ax.get_legend()
        if legend is not None:
            legend.remove()

    def _draw(self, final: bool) -> MapArtists:
        """Draw the map of :attr:`params` as ``plot`` does (``final``: with its tidy pass)."""
        t0 = time.perf_counter()
        params = self.params
        pt = self._point
        self._clear_map()
        with style_context():
            # what map_figure computes for plot: the view, the polygons, the curves
            data = map_data(params, view="designer", samples=self.resolution,
                            include=[(pt.k, pt.mu)] if pt is not None else [])
            # while dragging, the mode symbols wait for the release (placing them is a
            # quarter of draw_map's time, and the tidy pass would move them anyway)
            style = MapStyle() if final else MapStyle(labels=False, title=drag_title(params))
            art = draw_map(self.ax, data, style)
            if pt is not None:
                art.extra.extend(draw_design_points(self.ax, [pt], tagged=True))
            if final:
                self._key.hide()
                self._tidy(art)
            elif art.legend is not None:
                self._key.show(art.legend)
        self.artists = art
        if pt is not None:
            if final:
                self.result = query_points([pt], **self._query_keywords(params))[0]
                self._set_info(self.describe(self.result))
            else:
                self._set_info(f"k = {pt.k:g}, mu = {pt.mu:g}: updated when the slider "
                               "is released")
        self.last_update = time.perf_counter() - t0
        return art

    def _tidy(self, art: MapArtists) -> None:
        """``plot``'s legibility pass on this figure.

        It measures the texts at its own resolution and restores the figure's:
        with the window manager detached meanwhile, so that the window is not
        resized back and forth.
        """
        canvas = self.fig.canvas
        manager = canvas.manager
        canvas.manager = None
        try:
            tidy_figure(self.fig, [art])
        finally:
            canvas.manager = manager

    @staticmethod
    def _query_keywords(params: Parameters) -> dict[str, Any]:
        return {"gamma": params.gamma, "kprime": params.kprime, **params.loads}

    def _set_info(self, text: str) -> None:
        self.info_text = text
        self._info.set_text(text)
