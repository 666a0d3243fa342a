"""One run's motion: its time history as a figure, and the block moving, to scale, as a GIF.

:func:`motion_figure` draws the pulse k(t), the slide of the base and the
rotation theta(t) one above the other, with the phases of the motion (rest,
slide, rock, slide-rock, flight) shaded in the regime maps' colours
(:func:`regimemap.drawing.style.phase_style`).  :func:`render_block_animation`
draws the block, its base and the push at a series of instants and writes
them as a GIF (:func:`write_block_animation`: to a file, atomically).  Both take a
:class:`regimemap.dynamics.History` (the data); nothing is computed here beyond
interpolating it at the frames' times.  :func:`simulation_figure` and
:func:`simulation_animation` draw them for the record of
:func:`regimemap.motion.run.run_simulation` (its history, its block, and the inputs it
came from in the title, :func:`simulation_title`).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ...drawing.save import DEFAULT_DPI
from ...drawing.style import agg_figure, phase_style, style_context
from ...dynamics.stepper import History, Phase
from ...io.formats import format_for
from ...mechanics.modes import Mode

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..record import SimulationRecord

__all__ = ["MOTION_FIGSIZE", "ANIMATION_FPS", "ANIMATION_MAX_FRAMES", "BLOCK_ANIMATION_DPI",
           "phase_runs", "motion_figure", "render_block_animation", "simulation_animation",
           "simulation_figure", "simulation_title", "write_block_animation"]

#: Size of the history figure in inches.
MOTION_FIGSIZE: tuple[float, float] = (6.4, 6.4)
#: Frames per second of the block animation, the most frames it has, and its dots per inch.
ANIMATION_FPS = 20.0
ANIMATION_MAX_FRAMES = 240
BLOCK_ANIMATION_DPI = 80
#: Fewest frames: a run shorter than this many frames at real speed is shown slowed down.
_MIN_FRAMES = 60


def _phase_name(code: int) -> str:
    if code == Phase.FLIGHT:
        return "FLIGHT  free flight"
    mode = Mode(code)
    return f"{mode.label}  {mode.description}"


def phase_runs(history: History) -> list[tuple[int, float, float]]:
    """The phases of a history as (Phase code, start, end) intervals of time.

    ``history.phase[i]`` is the phase of the step from ``t[i-1]`` to ``t[i]``.
    """
    codes = history.phase[1:].astype(np.int64)
    t = history.t
    if codes.size == 0:
        return []
    change = np.flatnonzero(np.diff(codes)) + 1
    starts = np.concatenate(([0], change))
    ends = np.concatenate((change, [codes.size]))
    return [(int(codes[s]), float(t[s]), float(t[e])) for s, e in zip(starts, ends)]


def _shade(ax: Axes, runs: list[tuple[int, float, float]]) -> None:
    from matplotlib.collections import PolyCollection

    by_code: dict[int, list[NDArray[np.float64]]] = {}
    for code, a, b in runs:
        by_code.setdefault(code, []).append(np.array([[a, 0.0], [b, 0.0], [b, 1.0], [a, 1.0]]))
    for code in sorted(by_code):
        pc = PolyCollection(by_code[code], facecolors=phase_style(code).color, edgecolors="none",
                            linewidths=0.0, transform=ax.get_xaxis_transform(), zorder=0.5,
                            antialiaseds=False)
        ax.add_collection(pc, autolim=False)


def motion_figure(history: History, *, H: float, alpha: float, duration: float, title: str | None = None,
                  dpi: float = DEFAULT_DPI, fig: Figure | None = None) -> Figure:
    """A Figure with k(t), the slide of the base and theta(t) of one run, phases shaded.

    Parameters
    ----------
    history : History
        The run's time history (``simulate(..., history=i)``).
    H : float
        Height of C above the base (m), for the slide of the base.
    alpha : float
        Slenderness angle (rad): the rotation at which the block tips over statically,
        drawn as a dotted line.
    duration : float
        End of the pulse (s), drawn as a dashed line.
    title : str, optional
    dpi : float
    fig : Figure, optional
        A figure to clear and reuse.
    """
    from matplotlib.patches import Patch

    with style_context():
        if fig is None:
            fig = agg_figure(figsize=MOTION_FIGSIZE, dpi=dpi)
        else:
            fig.clear()
        t = history.t
        runs = phase_runs(history)
        axes = fig.subplots(3, 1, sharex=True)
        fig.subplots_adjust(left=0.14, right=0.97, top=0.93, bottom=0.19, hspace=0.12)
        series = ((history.k, "force $k$ (× $mg$)"),
                  (history.base_slide(H), "slide of the base (m)\npositive towards O"),
                  (history.theta, r"rotation $\theta$ (rad)"))
        for ax, (y, label) in zip(axes, series):
            _shade(ax, runs)
            ax.plot(t, y, color="black", linewidth=1.0, zorder=2)
            ax.axhline(0.0, color="0.4", linewidth=0.5, zorder=1)
            ax.axvline(duration, color="0.25", linewidth=0.7, dashes=(4.0, 2.5), zorder=1)
            ax.set_ylabel(label, fontsize=9)
            ax.tick_params(labelsize=8.5)
            ax.set_xlim(float(t[0]), float(t[-1]) if t[-1] > t[0] else 1.0)
        for sign in (1.0, -1.0):
            if abs(float(np.max(np.abs(history.theta)))) > 0.2 * alpha:
                axes[2].axhline(sign * alpha, color="0.1", linewidth=0.9, dashes=(1.0, 2.0), zorder=1)
        axes[2].set_xlabel("time $t$ (s)", fontsize=10)
        if title:
            axes[0].set_title(title, fontsize=10)
        present = sorted({code for code, _, _ in runs})
        handles: list[Any] = [Patch(facecolor=phase_style(c).color, edgecolor="0.4", linewidth=0.4,
                                    label=_phase_name(c)) for c in present]
        from matplotlib.lines import Line2D

        handles.append(Line2D([], [], color="0.25", linewidth=0.7, dashes=(4.0, 2.5),
                              label="end of the pulse"))
        if len(axes[2].lines) > 2:
            handles.append(Line2D([], [], color="0.1", linewidth=0.9, dashes=(1.0, 2.0),
                                  label=r"$\theta = \pm\alpha$"))
        fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.005), ncols=2,
                   fontsize=8, frameon=False, handlelength=2.0, columnspacing=1.5)
    return fig


def _frame_times(end: float, fps: float, max_frames: int) -> tuple[NDArray[np.float64], float]:
    """Frame times and the speed-up over real time (< 1 is slow motion)."""
    if end <= 0.0:
        return np.zeros(1), 1.0
    n_real = end * fps
    if n_real > max_frames:
        speed = n_real / max_frames
    elif n_real < _MIN_FRAMES:
        speed = n_real / _MIN_FRAMES
    else:
        speed = 1.0
    n = max(2, int(round(n_real / speed)) + 1)
    return np.linspace(0.0, end, n), speed


def render_block_animation(path: str | os.PathLike[str] | IO[bytes], history: History, *, B: float,
                           H: float, kprime: float = 0.0, overturned: bool = False,
                           fps: float = ANIMATION_FPS, max_frames: int = ANIMATION_MAX_FRAMES,
                           dpi: float = BLOCK_ANIMATION_DPI, title: str | None = None
                           ) -> tuple[int, tuple[int, int], float]:
    """Write a GIF of the block moving on its base, to scale (one length unit on both axes).

    Parameters
    ----------
    path : path-like or binary file
        Where the GIF goes (written as GIF whatever the name).
    history : History
        The run's time history.
    B, H : float
        Half width and height of C above the base (m).
    kprime : float
        Height of the push above C over H (the arrow is drawn there, its length
        proportional to k(t)).
    overturned : bool
        Say so in the last frames.
    fps, max_frames, dpi : float, int, float
        Frames per second, most frames (longer runs are sped up, very short ones
        slowed down; the speed is written in each frame) and resolution.
    title : str, optional

    Returns
    -------
    (frames, (width, height), speed)
    """
    from matplotlib.patches import FancyArrow, Polygon
    from PIL import Image

    t = history.t
    times, speed = _frame_times(float(t[-1]), fps, max_frames)
    x = np.interp(times, t, history.x)
    y = np.interp(times, t, history.y)
    th = np.interp(times, t, history.theta)
    k = np.interp(times, t, history.k)
    idx = np.clip(np.searchsorted(t, times, side="left"), 1, max(t.size - 1, 1))
    phase = history.phase[idx] if t.size > 1 else np.zeros(times.size, dtype=np.int8)
    body = np.array([[-B, -H], [B, -H], [B, H], [-B, H]])

    def corners(i: int) -> NDArray[np.float64]:
        c, s = math.cos(th[i]), math.sin(th[i])
        rot = np.array([[c, -s], [s, c]])
        return np.asarray(body @ rot.T + np.array([x[i], H + y[i]]), dtype=np.float64)

    # the view: every position of the block, plus room for the arrow
    allc = np.concatenate([corners(i) for i in range(times.size)])
    kmax = float(np.max(np.abs(k))) if np.any(k) else 1.0
    arrow_len = 1.2 * max(B, 0.35 * H)
    x0 = float(allc[:, 0].min()) - 0.3 * B
    x1 = float(allc[:, 0].max()) + arrow_len + 0.3 * B
    y1 = float(allc[:, 1].max()) + 0.25 * H
    y0 = -0.12 * (y1 + 0.0)
    w_in, h_in = 0.96 * 6.4, 0.86 * 3.6  # the axes, in inches: one length unit on both axes
    if (x1 - x0) / (y1 - y0) > w_in / h_in:
        grow = (x1 - x0) * h_in / w_in - (y1 - y0)
        y1 += grow
    else:
        grow = (y1 - y0) * w_in / h_in - (x1 - x0)
        x0 -= 0.5 * grow
        x1 += 0.5 * grow
    with style_context():
        fig = agg_figure(figsize=(6.4, 3.6), dpi=dpi)
        ax = fig.add_axes((0.02, 0.02, 0.96, 0.86))
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal", adjustable="box")
        ax.set_axis_off()
        ax.axhspan(y0, 0.0, facecolor="0.85", edgecolor="none", zorder=0)
        ax.axhline(0.0, color="black", linewidth=1.2, zorder=1)
        # where the middle of the base started: the slide is read against it
        ax.plot([0.0, 0.0], [0.0, -0.6 * abs(y0)], color="black", linewidth=1.0, zorder=1)
        block = Polygon(corners(0), closed=True, facecolor="#BBCCEE", edgecolor="black", linewidth=1.0,
                        zorder=2)
        ax.add_patch(block)
        centre = ax.plot([], [], marker="o", markersize=3, color="black", zorder=3)[0]
        arrow: list[Any] = []
        text = ax.text(0.01, 0.99, "", transform=ax.transAxes, ha="left", va="top", fontsize=9,
                       family="DejaVu Sans Mono", zorder=5)
        speed_txt = ("real time" if speed == 1.0 else
                     (f"{speed:.3g}x faster" if speed > 1.0 else f"{1 / speed:.3g}x slower"))
        fig.text(0.5, 0.97, (title + "  " if title else "") + f"({speed_txt})", ha="center", va="top",
                 fontsize=9)
        frames: list[Any] = []
        size = (0, 0)
        for i in range(times.size):
            block.set_xy(corners(i))
            c_, s_ = math.cos(th[i]), math.sin(th[i])
            cx, cy = x[i], H + y[i]
            centre.set_data([cx], [cy])
            for a in arrow:
                a.remove()
            arrow.clear()
            if abs(k[i]) > 1e-9 * kmax:
                px, py = cx - s_ * kprime * H, cy + c_ * kprime * H
                length = arrow_len * float(k[i]) / kmax
                arrow.append(ax.add_patch(FancyArrow(
                    px + length, py, -length, 0.0, width=0.06 * arrow_len, head_width=0.18 * arrow_len,
                    head_length=0.22 * min(arrow_len, abs(length) + 1e-12), length_includes_head=True,
                    color="#CC3311", zorder=4)))
            ph = int(phase[i])
            name = "FLIGHT" if ph == Phase.FLIGHT else (Mode(ph).label if ph >= 0 else "RE")
            state = ("OVERTURNED" if overturned and i == times.size - 1 else name)
            text.set_text(f"t = {times[i]:7.3f} s   k = {k[i]:+.3f}   theta = {math.degrees(th[i]):+7.2f} deg"
                          f"   {state}")
            fig.canvas.draw()
            buf = np.asarray(fig.canvas.buffer_rgba())  # type: ignore[attr-defined]
            size = (buf.shape[1], buf.shape[0])
            frames.append(Image.fromarray(buf[:, :, :3].copy(), "RGB").quantize(
                colors=64, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE))
        if overturned:
            frames.extend([frames[-1]] * int(fps))  # hold the last frame a second
        frames[0].save(path, format="GIF", save_all=True, append_images=frames[1:],
                       duration=int(round(1000 / fps)), loop=0)
    return len(frames), size, speed


def write_block_animation(path: str | os.PathLike[str], history: History, **kwargs: Any
                          ) -> tuple[int, tuple[int, int], float]:
    """Write the GIF of :func:`render_block_animation` to a ``.gif`` file, atomically.

    Parameters
    ----------
    path : path-like
        The ``.gif`` file.
    history : History
        The run's time history.
    **kwargs
        The keywords of :func:`render_block_animation` (``B``, ``H`` ...).

    Returns
    -------
    (frames, (width, height), speed)
        The number of frames, their size in pixels and the speed-up over real time.

    Raises
    ------
    ValueError
        For a file that is not ``.gif`` (nothing written).
    OSError
        If the file cannot be written (nothing is left behind).
    """
    from ...io.atomic import atomic_path

    format_for(path, "animation")
    with atomic_path(path) as tmp:
        return render_block_animation(tmp, history, **kwargs)


def simulation_title(record: SimulationRecord) -> str:
    """The title of a run's figures: the pulse and the block (or the design file)."""
    inp, T = record.inputs, record.duration
    design, pulse_file, k_peak, mu = inp["design"], inp["pulse_file"], inp["k_peak"], inp["mu"]
    if design is not None:  # the file gives the block: the title says which, and fits
        return f"{Path(design).name}: design wave, k = {k_peak:.4g}, τ0 = {T:.4g} s; μ = {mu:.3g}"
    kprime = inp["kprime"]
    kp = "" if kprime is None else f", k' = {kprime:g}"
    what = (f"{inp['pulse']} pulse, k_peak = {k_peak:g}, T = {T:g} s" if pulse_file is None
            else f"pulse {Path(pulse_file).name}")
    return f"{what}; γ = {inp['gamma']:g}, B = {inp['half_width']:g} m, μ = {mu:g}{kp}"


def _history(record: SimulationRecord) -> History:
    if record.simulation.history is None:
        raise ValueError("the run kept no time history: run_simulation(..., history=True)")
    return record.simulation.history


def simulation_figure(record: SimulationRecord) -> Figure:
    """k(t), the slide of the base and theta(t) of a run kept with its history, the phases shaded."""
    return motion_figure(_history(record), H=record.H, alpha=record.alpha, duration=record.duration,
                         title=simulation_title(record))


def simulation_animation(path: str | os.PathLike[str], record: SimulationRecord
                         ) -> tuple[int, tuple[int, int], float]:
    """The block of a run moving, to scale, as a GIF written atomically to ``path``.

    Returns the number of frames, their size in pixels and the speed-up over real time
    (:func:`~regimemap.motion.figures.history.write_block_animation`).
    """
    kprime = record.inputs["kprime"]
    return write_block_animation(path, _history(record), B=record.inputs["half_width"], H=record.H,
                                 kprime=kprime if kprime is not None else 0.0, overturned=record.overturned,
                                 title=simulation_title(record))
