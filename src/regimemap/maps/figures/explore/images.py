"""Artists of ``regimemap explore`` drawn from bitmaps: the text panel, the key and the widgets.

Used by :class:`~regimemap.maps.figures.explore.explorer.Explorer`.  A figure is drawn whole on
every change of a slider and matplotlib renders text glyph by glyph; these
artists render their text once per content (with matplotlib, at the canvas's
resolution) and then draw the cached pixels.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist

from ....drawing.style import style_context

if TYPE_CHECKING:  # pragma: no cover
    from collections.abc import Hashable, Sequence

    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.legend import Legend

__all__ = ["KeyImage", "PANEL_FONTSIZE", "TextPanel", "WidgetsImage"]

#: Font size (points) of the panel's text.
PANEL_FONTSIZE = 7.0


class TextPanel(Artist):
    """A block of monospaced text in a box, drawn from a bitmap made once per text.

    A figure is drawn whole on every change of a slider, and matplotlib renders
    text glyph by glyph: the ~1000 characters of a ``classify`` answer would
    cost ~60 ms a frame.  This artist renders its text (with matplotlib, at the
    canvas's resolution) only when the text, the resolution or the size of its
    axes changes, and otherwise draws the cached image (~1 ms).  It fills the
    axes it is added to, the text from the top left.
    """

    def __init__(self, text: str = "", fontsize: float = PANEL_FONTSIZE) -> None:
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


def _crop(pixels: np.ndarray) -> tuple[int, int, np.ndarray]:
    """The smallest block of an RGBA buffer (row 0 at the top) holding every painted pixel.

    Returns (x0, y0, block) with y0 from the bottom and the block's row 0 at
    the bottom, as :meth:`RendererBase.draw_image` takes them; an empty block
    if nothing is painted.
    """
    painted = pixels[:, :, 3] > 0
    rows, cols = np.flatnonzero(painted.any(axis=1)), np.flatnonzero(painted.any(axis=0))
    if rows.size == 0:
        return 0, 0, np.zeros((0, 0, 4), dtype=np.uint8)
    top, bottom, x0, x1 = int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1
    return x0, pixels.shape[0] - bottom, pixels[top:bottom, x0:x1][::-1].copy()


class WidgetsImage(Artist):
    """The widgets that stand still during a drag, drawn from a bitmap of each.

    A frame of a drag draws the whole figure again, and the widgets' texts
    cost ~10 ms of glyphs, although only the slider being dragged changes.
    :meth:`freeze` hides the other widgets' axes and draws, in their place,
    their pixels rendered once (again when what a widget shows, given as its
    ``signature``, the resolution or the layout changes); :meth:`thaw` (at
    the release) shows them again.
    """

    def __init__(self) -> None:
        super().__init__()
        self._cache: dict[int, tuple[tuple[Any, ...], int, int, np.ndarray]] = {}
        self._frozen: list[Axes] = []
        self.renders = 0  # how many times a widget was rendered (the tests count them)

    @property
    def frozen(self) -> tuple[Axes, ...]:
        """The axes drawn from their bitmaps now (hidden themselves)."""
        return tuple(self._frozen)

    def freeze(self, axes: Sequence[Axes], signatures: Sequence[Hashable]) -> None:
        """Draw the visible ones of ``axes`` from pixels; ``signatures``: what each shows."""
        from matplotlib.backends.backend_agg import RendererAgg
        from matplotlib.figure import Figure

        self.thaw()
        for ax, signature in zip(axes, signatures):
            fig = ax.figure
            if not ax.get_visible() or not isinstance(fig, Figure):
                continue
            key = (signature, float(fig.dpi), tuple(fig.bbox.bounds), tuple(ax.get_position().bounds))
            cached = self._cache.get(id(ax))
            if cached is None or cached[0] != key:
                width, height = int(math.ceil(fig.bbox.width)), int(math.ceil(fig.bbox.height))
                renderer = RendererAgg(width, height, fig.dpi)  # type: ignore[no-untyped-call]
                with style_context():
                    ax.draw(renderer)
                pixels = np.asarray(renderer.buffer_rgba())  # type: ignore[no-untyped-call]
                self._cache[id(ax)] = (key, *_crop(pixels))
                self.renders += 1
            ax.set_visible(False)
            self._frozen.append(ax)
        self.stale = True

    def thaw(self) -> None:
        """Show the frozen axes again (and draw nothing)."""
        for ax in self._frozen:
            ax.set_visible(True)
        self._frozen = []
        self.stale = True

    def draw(self, renderer: RendererBase) -> None:
        dpi = float(np.asarray(renderer.points_to_pixels(72.0)))  # the resolution
        for ax in self._frozen:
            key, x0, y0, crop = self._cache[id(ax)]
            if key[1] == dpi and crop.size:
                gc = renderer.new_gc()
                renderer.draw_image(gc, x0, y0, crop)
                gc.restore()
        self.stale = False
