"""The regime map, live: sliders for gamma and k' (and the loads), a click for the physics.

:class:`Explorer` builds one matplotlib figure: the map of ``regimemap plot``
on the left, computed by the ``compute`` it is given (``regimemap explore`` gives
:func:`regimemap.maps.mapdata.map_for_view`, as ``plot`` computes it) and drawn by
:func:`~regimemap.maps.figures.mapplot.draw_map` (the same view, the same polygons);
on the right, sliders for the aspect ratio gamma (log scale) and
the force height k', a check box that shows two more sliders for the
buoyancy beta and the uplift ratio nu, a *Save* button, and a text panel.
A click on the map shows in the panel (and prints) the mode at that point,
its margins and the physics at initiation (the ``classify`` it is given: ``regimemap
explore`` gives :func:`regimemap.maps.query.classify_point`); *Save* writes the current view as
``regimemap plot`` draws it (the same :func:`~regimemap.maps.figures.figure.map_figure`,
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
resolution), but without the mode symbols in the regions, with a title
without mathtext (:func:`drag_title`), with the key and the widgets that do
not move drawn from bitmaps
(:class:`~regimemap.maps.figures.explore.images.KeyImage`,
:class:`~regimemap.maps.figures.explore.images.WidgetsImage`) and with the panel's
answer left for later; when the mouse is released (and after every call from
code) the map is drawn whole, with ``plot``'s legibility pass
(:func:`~regimemap.drawing.text.tidy.tidy_figure`), and the panel is brought up to
date.  The panel's text is drawn from a bitmap made once per text
(:class:`~regimemap.maps.figures.explore.images.TextPanel`).
``bench/bench_explore.py`` measures both kinds of update.

The figure's layout and widgets are built by
:mod:`~regimemap.maps.figures.explore.layout`, the bitmap artists live in
:mod:`~regimemap.maps.figures.explore.images`, the texts and rounding in
:mod:`~regimemap.maps.figures.explore.text`, the callbacks of the widgets and the mouse in
:mod:`~regimemap.maps.figures.explore.events` (the base class of :class:`Explorer`); this
module wires them to :class:`Explorer`.  It uses pyplot (to
open a window or a notebook canvas) when no figure is given; it never
changes matplotlib's global settings.  The module is one class, whose methods
share the window's state (the block, the sliders, the map drawn, the panel),
hence its length.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ....drawing.artists import MapArtists
from ....drawing.save import DEFAULT_DPI, format_from_path, save_figure
from ....drawing.style import style_context
from ....mechanics.block import LOAD_DEFAULTS, Parameters
from ...geometry import DEFAULT_SAMPLES
from ...mapdata import MapData
from ...points import DesignPoint
from ...query import PointResult
from ...record_tables import format_result
from ..figure import map_figure
from ..mapplot import MapStyle, draw_design_points, draw_map
from .events import ExplorerEvents
from .images import KeyImage, TextPanel, WidgetsImage
from .layout import (
    build_widgets,
    clear_map,
    freeze_widgets,
    new_figure,
    request_draw,
    show_load_sliders,
    tidy_in_place,
)
from .text import (
    HINT,
    default_file_stem,
    drag_title,
    snap_click,
    snap_gamma,
    snap_kprime,
    snap_load,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from matplotlib.widgets import Button, CheckButtons, Slider

__all__ = ["Explorer"]

#: Loads that the sliders set; the others (uplift, arm, gyration, crest) stay as given.
_SLIDER_LOADS = ("buoyancy", "uplift_ratio")

Describe = Callable[[PointResult], str]
#: ``compute(params, *, view, samples, include) -> MapData``: the map of a block in a view.
Compute = Callable[..., MapData]
#: ``classify(point, params) -> PointResult``: the answer at a point for a block.
Classify = Callable[[DesignPoint, Parameters], PointResult]
Write = Callable[["Figure", Path, str, float], object]


class Explorer(ExplorerEvents):
    """The regime map of one block with sliders, a click query and a Save button.

    Parameters
    ----------
    params : Parameters, optional
        The block to start from (default gamma = 3, k' = 0.4).  Its buoyancy
        and uplift ratio are the starting values of their sliders (ticked on
        when either is not 0); its other loads (uplift, arm, gyration, crest)
        stay fixed.
    compute : callable
        ``compute(params, view="designer", samples=resolution, include=[(k, mu)])``: the
        map of a block, as ``plot`` computes it (:func:`regimemap.maps.mapdata.map_for_view`).
    classify : callable
        ``classify(point, params)``: the answer at a clicked point, as ``regimemap
        classify`` computes it (:func:`regimemap.maps.query.classify_point`).
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
    point : DesignPoint, optional
        A point (k, mu) marked from the start, with its answer in the panel, as if
        clicked (``regimemap explore --design``: the design wave's point), not rounded.

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
        from regimemap.cli.explore import open_explorer

        ex = open_explorer(Parameters(gamma=3, kprime=0.4))
        ex.set_gamma(2.5)          # what the slider does
        ex.click(0.45, 0.6)        # what a click does
        ex.save("map.png")         # what the Save button does
    """

    def __init__(self, params: Parameters | None = None, *, compute: Compute, classify: Classify,
                 resolution: int = DEFAULT_SAMPLES,
                 fig: Figure | None = None, describe: Describe | None = None,
                 write: Write | None = None, file_stem: Callable[[Parameters], str] | None = None,
                 echo: Callable[[str], None] | None = print, window: bool = True,
                 point: DesignPoint | None = None) -> None:
        from ....mechanics.validation import check_resolution

        p = Parameters(3.0, 0.4) if params is None else params
        self.resolution = check_resolution("resolution", resolution)
        self.compute = compute
        self.classify = classify
        self.describe: Describe = describe if describe is not None else format_result
        self.write: Write = write if write is not None else save_figure
        self.file_stem = file_stem if file_stem is not None else default_file_stem
        self.echo = echo
        self._gamma = float(p.gamma)
        self._kprime = float(p.kprime)
        self._loads_on = p.buoyancy != 0.0 or p.uplift_ratio != 0.0
        self._load_values = {"buoyancy": float(p.buoyancy), "uplift_ratio": float(p.uplift_ratio)}
        self._fixed = {k: v for k, v in p.loads.items() if k not in _SLIDER_LOADS}
        self._point: DesignPoint | None = point
        self.result: PointResult | None = None
        self.info_text = HINT
        self.last_update = 0.0
        self._syncing = False
        self._pending = False  # a slider was dragged: tidy and the panel wait for the release
        self.fig = new_figure(fig, window)
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
        g = snap_gamma(value)
        Parameters(g, self._kprime, **self.loads)  # refuse a bad value before changing anything
        changed = g != self._gamma
        self._gamma = g
        self._sync_slider(self.gamma_slider, math.log10(g), f"{g:g}")
        self._update(final, changed, (self.gamma_slider,))

    def set_kprime(self, value: float, *, final: bool = True) -> None:
        """Show the map of force height ``value`` (rounded to 0.001)."""
        kp = snap_kprime(value)
        Parameters(self._gamma, kp, **self.loads)
        changed = kp != self._kprime
        self._kprime = kp
        self._sync_slider(self.kprime_slider, kp, f"{kp:g}")
        self._update(final, changed, (self.kprime_slider,))

    def set_loads(self, buoyancy: float | None = None, uplift_ratio: float | None = None, *,
                  enabled: bool | None = None, final: bool = True) -> None:
        """Set the buoyancy beta and / or the uplift ratio nu (rounded to 0.001), or the toggle.

        Giving a value ticks 'loads' on (unless ``enabled=False``);
        ``set_loads(enabled=False)`` shows the report's block again (the
        slider values are kept for the next time).
        """
        values = dict(self._load_values)
        if buoyancy is not None:
            values["buoyancy"] = snap_load(buoyancy)
        if uplift_ratio is not None:
            values["uplift_ratio"] = snap_load(uplift_ratio)
        on = self._loads_on if enabled is None and buoyancy is None and uplift_ratio is None \
            else (True if enabled is None else bool(enabled))
        extra = {k: v for k, v in values.items() if v != 0.0} if on else {}
        before = self.params
        Parameters(self._gamma, self._kprime, **{**self._fixed, **extra})
        self._load_values = values
        toggled = on != self._loads_on
        if toggled:
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
        show_load_sliders(self._widgets, self._loads_on)
        moving = ((self.buoyancy_slider,) if buoyancy is not None else ()) + (
            (self.nu_slider,) if uplift_ratio is not None else ())
        # ticking 'loads' at beta = nu = 0 changes no map but shows (or hides) two sliders: draw
        self._update(final, toggled or self.params != before, moving)

    def click(self, k: float, mu: float) -> PointResult:
        """The answer at (k, mu): shown in the panel, printed, and the point marked on the map.

        The point is rounded to 1/1000 of the view (a number one can type
        back into ``regimemap classify``).  The answer is what
        ``regimemap classify`` computes (:func:`regimemap.query_points`), as
        text by ``describe``.
        """
        data = self.artists.data
        pt = DesignPoint(snap_click(k, data.k_max), snap_click(mu, data.mu_max))
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
        self.info_text = HINT
        self._draw(final=True)
        self._request_draw()

    def save(self, path: str | Path | None = None) -> Path:
        """Write the current view as ``regimemap plot`` draws it; return the path.

        The same function as ``plot`` (:func:`~regimemap.maps.figures.figure.map_figure`
        with its defaults, ``--resolution``, the loads and the clicked point
        as ``--point K,MU``) and the same writer, so the file has ``plot``'s
        bytes.  Default path: ``file_stem(params) + ".png"`` in the current folder.
        """
        target = Path(path) if path is not None else Path(f"{self.file_stem(self.params)}.png")
        fmt = format_from_path(target)
        points = [self._point] if self._point is not None else []
        fig, _, _ = map_figure(self._map_data(self.params, self._point), dpi=DEFAULT_DPI,
                               points=points)
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
    def _build(self) -> None:
        w = build_widgets(self.fig, gamma=self._gamma, kprime=self._kprime,
                          crest=float(self._fixed.get("crest", 1.0)), loads_on=self._loads_on,
                          buoyancy=self._load_values["buoyancy"],
                          uplift_ratio=self._load_values["uplift_ratio"], text=self.info_text)
        self.ax: Axes = w.ax
        self.gamma_slider: Slider = w.gamma_slider
        self.kprime_slider: Slider = w.kprime_slider
        self.check_ax: Axes = w.check_ax
        self.loads_check: CheckButtons = w.loads_check
        self.save_ax: Axes = w.save_ax
        self.save_button: Button = w.save_button
        self.buoyancy_slider: Slider = w.buoyancy_slider
        self.nu_slider: Slider = w.nu_slider
        self.info_ax: Axes = w.info_ax
        self._info: TextPanel = w.info
        self._key: KeyImage = w.key
        self._still: WidgetsImage = w.still
        self._widgets = w
        self.gamma_slider.on_changed(self._on_gamma)
        self.kprime_slider.on_changed(self._on_kprime)
        self.buoyancy_slider.on_changed(self._on_buoyancy)
        self.nu_slider.on_changed(self._on_nu)
        self.loads_check.on_clicked(self._on_check)
        self.save_button.on_clicked(self._on_save)
        canvas = self.fig.canvas
        self._cids = [canvas.mpl_connect("button_press_event", self._on_press),
                      canvas.mpl_connect("button_release_event", self._on_release)]

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

    # -- drawing -----------------------------------------------------------------------------------
    def _update(self, final: bool, changed: bool = True, moving: tuple[Any, ...] = ()) -> None:
        """Redraw after a change (nothing to do if the map is the same and nothing waits).

        ``moving``: the widgets being changed; while dragging, the others are
        drawn from their bitmaps.
        """
        if not changed and not (final and self._pending):
            return
        self._pending = not final
        if not final:
            freeze_widgets(self._widgets, moving)
        self._draw(final)
        self._request_draw()

    def _request_draw(self) -> None:
        request_draw(self.fig)

    def _draw(self, final: bool) -> MapArtists:
        """Draw the map of :attr:`params` as ``plot`` does (``final``: with its tidy pass)."""
        t0 = time.perf_counter()
        if final:
            self._still.thaw()
        params = self.params
        pt = self._point
        clear_map(self.ax)
        with style_context():
            # what map_figure computes for plot: the view, the polygons, the curves
            data = self._map_data(params, pt)
            # while dragging, the mode symbols wait for the release (placing them is a
            # quarter of draw_map's time, and the tidy pass would move them anyway)
            style = MapStyle() if final else MapStyle(labels=False, title=drag_title(params))
            art = draw_map(self.ax, data, style)
            if pt is not None:
                art.extra.extend(draw_design_points(self.ax, [pt], tagged=True))
            if final:
                self._key.hide()
                tidy_in_place(self.fig, art)
            elif art.legend is not None:
                self._key.show(art.legend)
        self.artists = art
        if pt is not None:
            if final:
                self.result = self.classify(pt, params)
                self._set_info(self.describe(self.result))
            else:
                self._set_info(f"k = {pt.k:g}, mu = {pt.mu:g}: updated when the slider "
                               "is released")
        self.last_update = time.perf_counter() - t0
        return art

    def _map_data(self, params: Parameters, pt: DesignPoint | None) -> MapData:
        """What ``plot`` computes for its map: the designer's view, kept around the clicked point."""
        return self.compute(params, view="designer", samples=self.resolution,
                            include=[(pt.k, pt.mu)] if pt is not None else [])

    def _set_info(self, text: str) -> None:
        self.info_text = text
        self._info.set_text(text)
