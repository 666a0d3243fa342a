"""An animation of the map: a GIF as k' (or a load) sweeps a range, on fixed axes.

:func:`render_animation` draws every frame (:func:`draw_frame`: the all-mode map
of :func:`regimemap.maps.figures.mapplot.draw_map`, its caption, the frame's value in
a box, the key) on one figure and writes the GIF with matplotlib's
``PillowWriter`` (no pyplot); :func:`write_animation` writes it to a file
atomically.  The frames (their values, blocks, shared view and maps) are computed by
:func:`regimemap.maps.sweeps.sweep_frames` and handed over.  Limit: :data:`MAX_FRAMES` frames.

matplotlib is imported inside the functions that draw, never at import time.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from ...drawing.limits import ANIMATION_DPI, ANIMATION_DPI_RANGE, FPS_RANGE, MAX_FRAMES
from ...io.formats import format_for
from ...mechanics.block import Parameters
from ...mechanics.modes import MAP_MODES, Mode
from ...mechanics.validation import check_gamma
from ...records.numbers import short
from ..describe import loads_text
from ..sweeps import sweep_params
from .atlas import key_modes, sweep_text
from .mapplot import MapStyle, draw_map

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.animation import PillowWriter
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from PIL.Image import Image

    from ...drawing.artists import MapArtists
    from ..mapdata import MapData
    from ..sweeps import SweepFrames

__all__ = [
    "ANIMATION_DPI",
    "ANIMATION_DPI_RANGE",
    "FPS_RANGE",
    "FRAME_SIZE",
    "MAX_FRAMES",
    "check_animation",
    "draw_frame",
    "frame_figure",
    "render_animation",
    "write_animation",
]



def _pillow_writer(fps: float) -> PillowWriter:
    """matplotlib's PillowWriter, saving GIF whatever the (temporary) file name."""
    from matplotlib.animation import PillowWriter

    class _GifWriter(PillowWriter):
        _frames: list[Image]  # the frames grabbed so far (set by PillowWriter.setup)

        def finish(self) -> None:  # as PillowWriter.finish, with the format given
            self._frames[0].save(
                self.outfile, format="GIF", save_all=True, append_images=self._frames[1:],
                duration=int(1000 / self.fps), loop=0)

    # matplotlib's stubs say int; the writer takes any rate (the GIF stores 1000 / fps ms a frame)
    return _GifWriter(fps=fps)  # type: ignore[arg-type]


def check_animation(path: str | os.PathLike[str], gamma: float, kprimes: Sequence[float],
                    fps: float, *, sweep: str = "kprime", fixed: dict[str, Any] | None = None
                    ) -> None:
    """Refuse an animation that cannot be written (before any file is touched).

    Raises
    ------
    ValueError
        Naming the parameter and its range, or a file that is not ``.gif``.
    """
    _check_frames(gamma, kprimes, fps, sweep, fixed)
    format_for(path, "animation")


def _check_frames(gamma: float, kprimes: Sequence[float], fps: float, sweep: str = "kprime",
                  fixed: dict[str, Any] | None = None) -> None:
    check_gamma(gamma)
    kps = [sweep_params(gamma, sweep, k, fixed) for k in kprimes]
    if not kps:
        raise ValueError("an animation needs at least one kprime")
    if len(kps) > MAX_FRAMES:
        raise ValueError(f"{len(kps)} frames exceed the limit of {MAX_FRAMES}")
    lo, hi = FPS_RANGE
    if not (lo <= fps <= hi):
        raise ValueError(f"fps must be a number in [{lo:g}, {hi:g}], got {fps!r}")


#: Size of an animation frame in inches: 520 x 450 pixels at the default 100 dpi.
FRAME_SIZE: tuple[float, float] = (5.2, 4.5)
#: Layout of a frame (inches): margins around the map; the key is below it.
_F_LEFT, _F_RIGHT, _F_TOP, _F_BOTTOM = 0.55, 0.15, 0.5, 0.95


def _frame_handles(modes: Sequence[Mode]) -> list[Any]:
    """The key of an animation frame: one swatch per mode, with a short description."""
    from .key import key_handles

    short = {Mode.SRO_MINUS: "slide-rock, slips left", Mode.SRO_PLUS: "slide-rock, slips right",
             Mode.SRO_PRIME_MINUS: "slide-rock about O'"}
    handles = key_handles(modes, boundary=False, construction=False)
    for h, m in zip(handles, modes):
        h.set_label(short.get(m, h.get_label()))
    return handles


def frame_figure(figsize: tuple[float, float] | None = None, dpi: float = ANIMATION_DPI
                 ) -> tuple[Figure, Axes]:
    """The figure of an animation frame: a map, its key below, its caption above."""
    from ...drawing.style import agg_figure, style_context

    w, h = figsize or FRAME_SIZE
    with style_context():
        fig = agg_figure(figsize=(w, h), dpi=dpi)
        ax = fig.add_axes((_F_LEFT / w, _F_BOTTOM / h, 1.0 - (_F_LEFT + _F_RIGHT) / w,
                           1.0 - (_F_TOP + _F_BOTTOM) / h))
    return fig, ax


def draw_frame(fig: Figure, ax: Axes, gamma: float, kprime: float, data: MapData,
               *, modes: Sequence[Mode] = MAP_MODES, block: Parameters | None = None,
               swept: str | None = None) -> MapArtists:
    """Draw one frame of an animation on ``ax`` (cleared first); return its MapArtists.

    The caption states the report's case (or the block's loads) above the map,
    the frame's gamma and k' (or ``swept``, the swept load, in mathtext) sit in
    a box beside it (outside the map), and the key below lists the modes, sized
    to the frame; then :func:`regimemap.drawing.text.tidy.tidy_figure` keeps every
    text clear of the others.  ``data`` is the frame's map (its view is the frame's),
    ``block`` the frame's block with loads (default ``Parameters(gamma, kprime)``).
    """
    from ...drawing.style import style_context
    from ...drawing.text.tidy import fit_title, tidy_figure
    from .key import key_legend

    p = Parameters(gamma, kprime) if block is None else block
    loads = loads_text(p, tex=True)
    caption = f"All modes, block with loads ({loads})" if loads else f"All modes, {p.case.tex}"
    corner = rf"$\gamma = {short(gamma)}$, " + (rf"$k' = {kprime:+.3f}$" if swept is None else swept)
    with style_context():
        ax.cla()
        for leg in list(fig.legends):
            leg.remove()
        for t in list(fig.texts):
            t.remove()
        art = draw_map(ax, data, MapStyle(legend=False, title=caption))
        if art.title is not None:
            art.title.set_fontsize(8.5)
        for t in art.curve_labels.values():
            t.set_fontsize(8.5)
        key_legend(fig, _frame_handles(modes), loc="lower center", ncols=3,
                   bbox_to_anchor=(0.5, 0.02), fontsize=8.0, frameon=False, handleheight=1.0,
                   columnspacing=1.2, borderaxespad=0.0)
        box = fig.text(1.0 - 0.08 / fig.get_size_inches()[0], 1.0 - 0.06 / fig.get_size_inches()[1],
                       corner, ha="right", va="top",
                       fontsize=9.5,
                       bbox={"boxstyle": "round,pad=0.25", "fc": "white", "ec": "0.3", "lw": 0.6})
        box.set_gid("frame-kprime")
        renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
        if art.title is not None:
            bb = box.get_window_extent(renderer)
            fit_title(art.title, renderer, bb.x0 - 6.0, fig.bbox.y1 - 2.0)
        tidy_figure(fig, [art], fixed=[box], fit_titles=False)
    return art


def render_animation(path: str | os.PathLike[str], frames: SweepFrames, *, fps: float = 8.0,
                     dpi: float = ANIMATION_DPI, figsize: tuple[float, float] | None = None,
                     progress: Callable[[int, int], None] | None = None
                     ) -> tuple[int, tuple[int, int]]:
    """Write a GIF of the frames' maps, one frame each.

    Parameters
    ----------
    path : path-like
        Output ``.gif``.
    frames : SweepFrames
        The frames' values, blocks, view and maps (:func:`regimemap.maps.sweeps.sweep_frames`;
        1 to :data:`MAX_FRAMES` of them).
    fps : float
        Frames per second (0.5 to 50).
    dpi : float
        Pixels per inch of the frames.
    figsize : (float, float), optional
        Inches (default :data:`FRAME_SIZE`).
    progress : callable, optional
        Called as ``progress(i, n)`` after frame i of n.

    Returns
    -------
    (frames, (width, height))
        Number of frames written and their size in pixels.

    Notes
    -----
    Each frame is the all-mode map (:func:`draw_frame`): the caption states
    the case, a box outside the map gives gamma and k', and the key lists all
    six modes in every frame, so it does not jump.
    """
    from ...drawing.style import style_context

    _check_frames(frames.gamma, frames.values, fps, frames.sweep, frames.fixed)
    fig, ax = frame_figure(figsize, dpi)
    writer = _pillow_writer(fps)
    modes: Sequence[Mode] = MAP_MODES
    datas = frames.maps
    if frames.loaded:  # one key for every frame: the modes any frame shows
        datas = list(datas)
        modes = key_modes(datas)
    n = len(frames.values)
    with style_context():
        writer.setup(fig, str(path), dpi=dpi)
        for i, (value, block, data) in enumerate(zip(frames.values, frames.blocks, datas)):
            draw_frame(fig, ax, frames.gamma, block.kprime, data, modes=modes, block=block,
                       swept=sweep_text(frames.sweep, value) if frames.sweep != "kprime" else None)
            writer.grab_frame()
            if progress is not None:
                progress(i + 1, n)
        frame_size = tuple(int(v) for v in writer.frame_size)
        writer.finish()
    return n, (frame_size[0], frame_size[1])


def write_animation(path: str | os.PathLike[str], frames: SweepFrames,
                    **kwargs: Any) -> tuple[int, tuple[int, int]]:
    """Write the GIF of :func:`render_animation` atomically (checked before any file is touched).

    Parameters
    ----------
    path : path-like
        The ``.gif`` file.
    frames : SweepFrames
        The frames (:func:`regimemap.maps.sweeps.sweep_frames`).
    **kwargs
        The keywords of :func:`render_animation`.

    Returns
    -------
    (frames, (width, height))
        The number of frames and their size in pixels.

    Raises
    ------
    ValueError
        For too many frames, an fps out of range or a file that is not ``.gif`` (nothing written).
    OSError
        If the file cannot be written (nothing is left behind).
    """
    from ...io.atomic import atomic_path

    check_animation(path, frames.gamma, frames.values, kwargs.get("fps", 8.0),
                    sweep=frames.sweep, fixed=frames.fixed)
    with atomic_path(path) as tmp:
        return render_animation(tmp, frames, **kwargs)
