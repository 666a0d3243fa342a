"""Many maps at once: an atlas of small multiples and an animation over k'.

Size: over 500 lines on purpose: the atlas and the animation share the views, the key
and the panel layout.

:func:`atlas_figure` draws the all-mode map (:func:`regimemap.drawing.mapplot.draw_map`)
for every pair of a list of gamma (rows) and a list of k' (columns), on
shared axes, with one legend and each panel titled with its gamma and k'.
:func:`render_animation` draws a GIF of the map as k' sweeps a range, on
fixed axes, with matplotlib's ``PillowWriter`` (no pyplot).

The value lists use the syntax of the command line (:func:`parse_values`):
``1,2,3`` (a list) or ``-1:1:41`` (start:stop:count, both ends included, as
``numpy.linspace``).  Limits: :data:`MAX_PANELS` panels and
:data:`MAX_FRAMES` frames.

matplotlib is imported inside the functions that draw, never at import time.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..maps.describe import LOAD_SYMBOLS, format_value, loads_text
from ..mechanics.block import Parameters
from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES, Mode
from ..mechanics.validation import check_gamma, check_kprime

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.animation import PillowWriter
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from PIL.Image import Image

__all__ = [
    "MAX_PANELS",
    "MAX_FRAMES",
    "MAX_VALUES",
    "SHARE",
    "parse_values",
    "atlas_extents",
    "atlas_figure",
    "check_animation",
    "sweep_extent",
    "shared_extent",
    "resolve_share",
    "points_outside",
    "render_animation",
    "draw_frame",
    "frame_figure",
    "FRAME_SIZE",
    "SWEEPS",
    "sweep_params",
]

#: What the columns of an atlas or the frames of an animation may sweep: k' or a load,
#: with its symbol (mathtext) and what it is.
SWEEPS: dict[str, tuple[str, str]] = {
    "kprime": ("k'", "force height h/H"),
    **{name: (tex, what) for name, (_, tex, what) in LOAD_SYMBOLS.items()},
}


def sweep_params(gamma: float, sweep: str, value: float,
                 fixed: dict[str, Any] | None = None) -> Parameters:
    """The block of one panel or frame: ``gamma``, ``sweep = value`` and the ``fixed`` rest.

    ``fixed`` holds ``kprime`` (when the sweep is a load) and the loads that do not vary.
    Raises ValueError (from :class:`Parameters`) for a value out of range.
    """
    if sweep not in SWEEPS:
        raise ValueError(f"sweep must be one of {', '.join(SWEEPS)}, got {sweep!r}")
    kw = dict(fixed or {})
    kw[sweep] = value
    kp = kw.pop("kprime", 0.0)
    return Parameters(gamma, kp, **kw)


def _sweep_text(sweep: str, value: float) -> str:
    """``$k' = 0.4$``, ``$\beta = 0.3$``: the swept quantity of a panel or frame (mathtext)."""
    sym = SWEEPS[sweep][0]
    return rf"${sym} = {format_value(value) if sweep != 'kprime' else _fmt(value)}$"

#: Largest number of panels of an atlas (rows x columns).
MAX_PANELS = 48
#: Largest number of frames of an animation.
MAX_FRAMES = 400
#: Largest number of values in one list (rows or columns of an atlas).
MAX_VALUES = 400
#: How the axes of an atlas are shared: one view for the whole figure, one per row, or none.
SHARE: tuple[str, ...] = ("all", "row", "none")

#: Size of one atlas panel in inches (width, height).
PANEL_SIZE: tuple[float, float] = (2.7, 2.35)
#: Samples of k per panel / frame (fewer than a single map: the panels are small).
SAMPLES = 401
#: Resolution (dots per inch) of an atlas by default, and the range allowed.
ATLAS_DPI = 150
ATLAS_DPI_RANGE: tuple[int, int] = (30, 600)
#: Resolution of the frames of an animation by default, and the range allowed.
ANIMATION_DPI = 100
ANIMATION_DPI_RANGE: tuple[int, int] = (30, 300)
#: Frames per second of an animation: the range allowed.
FPS_RANGE: tuple[float, float] = (0.5, 50.0)


def _fmt(x: float) -> str:
    return f"{x:g}"


def parse_values(text: str, name: str, check: Callable[[float], float],
                 max_count: int = MAX_VALUES) -> list[float]:
    """Parse ``"a,b,c"`` or ``"start:stop:count"`` into a list of checked floats.

    Parameters
    ----------
    text : str
        A comma-separated list of numbers, or ``start:stop:count`` (count
        values from start to stop, both included; count >= 1, and count = 1
        needs start == stop).
    name : str
        Parameter name for messages (``gamma``, ``kprime``).
    check : callable
        Validates one value (e.g. :func:`regimemap.validation.check_kprime`),
        raising ValueError naming the allowed range.
    max_count : int
        Most values accepted.

    Returns
    -------
    list of float

    Raises
    ------
    ValueError
        With the offending piece and the expected syntax.

    Examples
    --------
    >>> parse_values("-1:1:5", "kprime", check_kprime)
    [-1.0, -0.5, 0.0, 0.5, 1.0]
    >>> parse_values("1, 2,3", "gamma", check_gamma)
    [1.0, 2.0, 3.0]
    """
    syntax = "a list like 1,2,3 or a range start:stop:count like -1:1:41"
    s = text.strip()
    if not s:
        raise ValueError(f"{name}: empty; give {syntax}")
    if ":" in s:
        parts = s.split(":")
        if len(parts) != 3:
            raise ValueError(f"{name}: {text!r} is not start:stop:count ({syntax})")
        try:
            start, stop = float(parts[0]), float(parts[1])
        except ValueError:
            raise ValueError(f"{name}: start and stop of {text!r} must be numbers ({syntax})") from None
        try:
            count = int(parts[2])
        except ValueError:
            raise ValueError(f"{name}: the count of {text!r} must be a whole number >= 1, "
                             f"got {parts[2]!r}") from None
        if count < 1:
            raise ValueError(f"{name}: the count of {text!r} must be a whole number >= 1, got {count}")
        if count > max_count:
            raise ValueError(f"{name}: {count} values in {text!r} exceed the limit of {max_count}")
        if count == 1 and start != stop:
            raise ValueError(f"{name}: {text!r} asks for 1 value between two different ends; "
                             f"use a count >= 2 or start == stop")
        for v, what in ((start, "start"), (stop, "stop")):
            try:
                check(v)
            except ValueError as exc:
                raise ValueError(f"{what} of {text!r}: {exc}") from None
        values = np.linspace(start, stop, count).tolist()
    else:
        values = []
        for piece in s.split(","):
            piece = piece.strip()
            if not piece:
                raise ValueError(f"{name}: empty item in {text!r} ({syntax})")
            try:
                values.append(float(piece))
            except ValueError:
                raise ValueError(f"{name}: {piece!r} is not a number ({syntax})") from None
        if len(values) > max_count:
            raise ValueError(f"{name}: {len(values)} values exceed the limit of {max_count}")
    out = []
    for v in values:
        out.append(check(v))
    return out


def _extent_of(p: Parameters, view: str = "designer") -> tuple[float, float]:
    from ..maps.designer_view import view_extent

    return view_extent(p, view)


#: A panel whose own view is this many times smaller than the shared one (in k or
#: in mu) would be crammed into a corner: the atlas then gives each panel its own view.
CRAMMED = 3.0


def resolve_share(gammas: Sequence[float], kprimes: Sequence[float], share: str = "all",
                  k_max: float | None = None, mu_max: float | None = None,
                  view: str = "designer", *, sweep: str = "kprime",
                  fixed: dict[str, Any] | None = None
                  ) -> tuple[str, list[list[tuple[float, float]]], list[tuple[float, float]]]:
    """The sharing an atlas can afford, its views, and the panels sharing would cram.

    A shared view (``share`` ``"all"`` or ``"row"``) that is more than
    :data:`CRAMMED` times wider or taller than a panel's own view would squeeze
    that panel into a corner; then every panel gets its own view
    (``"none"``), and the crammed panels are returned as (gamma, k') pairs so
    that the caller can say why.  Fixed ``k_max`` and ``mu_max`` always share.

    Returns
    -------
    (share, extents, crammed)
    """
    own = atlas_extents(gammas, kprimes, "none", k_max, mu_max, sweep=sweep, fixed=fixed,
                        view=view)
    ext = atlas_extents(gammas, kprimes, share, k_max, mu_max, sweep=sweep, fixed=fixed,
                        view=view)
    if share == "none" or (k_max is not None and mu_max is not None):
        return share, ext, []
    crammed = [(g, kp) for i, g in enumerate(gammas) for j, kp in enumerate(kprimes)
               if ext[i][j][0] > CRAMMED * own[i][j][0] or ext[i][j][1] > CRAMMED * own[i][j][1]]
    if crammed:
        return "none", own, crammed
    return share, ext, []


def atlas_extents(gammas: Sequence[float], kprimes: Sequence[float], share: str = "all",
                  k_max: float | None = None, mu_max: float | None = None, *,
                  sweep: str = "kprime", fixed: dict[str, Any] | None = None,
                  view: str = "designer") -> list[list[tuple[float, float]]]:
    """The view (k_max, mu_max) of every panel: rows gamma, columns k'.

    ``share="all"``: one view for every panel, :func:`shared_extent` of all
    panels' automatic views (:func:`regimemap.view.auto_extent`); ``"row"``:
    one per row; ``"none"``: each panel's own automatic view.  A given
    ``k_max`` or ``mu_max`` overrides the automatic value everywhere.  The
    columns are the values of ``sweep`` (k' by default, or a load; see
    :func:`sweep_params`).
    """
    if share not in SHARE:
        raise ValueError(f"share must be one of {', '.join(SHARE)}, got {share!r}")
    own = [[_extent_of(sweep_params(g, sweep, v, fixed), view) for v in kprimes] for g in gammas]
    if share == "all":
        km, mm = shared_extent([e for row in own for e in row])
        own = [[(km, mm) for _ in row] for row in own]
    elif share == "row":
        own = [[shared_extent(row)] * len(row) for row in own]
    return [[(k_max if k_max is not None else e[0], mu_max if mu_max is not None else e[1])
             for e in row] for row in own]


def shared_extent(extents: Sequence[tuple[float, float]]) -> tuple[float, float]:
    """One view for several maps: the upper quartile of their automatic views, rounded up.

    The automatic view of a single map (:func:`regimemap.view.auto_extent`)
    reaches out to far points such as D or B', which run off to infinity as
    k' nears 0 or -1; the largest of several views would shrink every other
    map into a corner, the median would cut point A off too many of them.
    The 75th percentile (of k_max and of mu_max separately, rounded up to a
    nice number) keeps A in view for most maps; :func:`points_outside` tells
    which maps lose it.
    """
    from ..maps.view import nice_ceil

    ks = np.array([e[0] for e in extents], dtype=float)
    ms = np.array([e[1] for e in extents], dtype=float)
    if ks.size == 1:
        return float(ks[0]), float(ms[0])
    return (float(nice_ceil(float(np.percentile(ks, 75.0)))),
            float(nice_ceil(float(np.percentile(ms, 75.0)))))


def points_outside(params: Sequence[Parameters], k_max: float, mu_max: float) -> list[Parameters]:
    """The maps whose point A (k_A, mu_A) exists but lies outside [0, k_max] x [0, mu_max]."""
    return [p for p in params
            if math.isfinite(p.k_A) and (p.k_A > k_max or p.mu_A > mu_max)]


def _legend_handles(modes: Sequence[Mode], dotted: bool = False) -> list[Any]:
    """The map key's handles (:func:`regimemap._legend.key_handles`) for every mode."""
    from .key import key_handles

    return key_handles(modes, dotted_label=r"dotted line $\mu = k|k'|$ (4.22)" if dotted else None)


def _panel_title(g: float, kp: float, sweep: str = "kprime") -> str:
    return rf"$\gamma = {_fmt(g)}$, " + _sweep_text(sweep, kp)


def _fixed_text(sweep: str, fixed: dict[str, Any] | None) -> str:
    """What the panels or frames share besides gamma: k' (when a load is swept) and the loads."""
    if not fixed:
        return ""
    parts = [_sweep_text(name, v) for name, v in fixed.items()
             if name != sweep and v is not None and not (name == "uplift_arm" and not (
                 fixed.get("uplift") or fixed.get("uplift_ratio") or sweep.startswith("uplift")))]
    return ", ".join(parts)


def _key_modes(datas: Sequence[Any]) -> tuple[Mode, ...]:
    """The modes shown by any of several maps (their MapData), in code order."""
    shown = {m for d in datas for m, polys in d.polygons.items() if any(len(q) >= 3 for q in polys)}
    return tuple(m for m in LOADED_MAP_MODES if m in shown)


def atlas_figure(gammas: Sequence[float], kprimes: Sequence[float], *, share: str = "all",
                 k_max: float | None = None, mu_max: float | None = None,
                 panel_size: tuple[float, float] = PANEL_SIZE, samples: int = SAMPLES,
                 dpi: float = ATLAS_DPI, curves: bool = True, labels: bool = True,
                 extents: Sequence[Sequence[tuple[float, float]]] | None = None,
                 sweep: str = "kprime", fixed: dict[str, Any] | None = None,
                 view: str = "designer", tidy: bool = True, caption: str | None = None
                 ) -> Figure:
    """Small multiples of the all-mode map: rows gamma, columns k' (or a load).

    Parameters
    ----------
    gammas, kprimes : sequence of float
        Aspect ratios (rows) and the values of the columns, force heights k'
        by default; at most :data:`MAX_PANELS` panels in all.
    sweep : str
        What the columns vary: ``"kprime"`` or a load of :data:`SWEEPS`
        (``"buoyancy"``, ``"uplift_ratio"`` ...).
    fixed : dict, optional
        What every panel shares: ``kprime`` when a load is swept, and the
        other loads (keywords of :class:`Parameters`).
    share : {"all", "row", "none"}
        Share the axes over the whole figure (default; tick labels only on
        the outer panels), within each row, or not at all
        (:func:`atlas_extents`; a shared view is :func:`shared_extent`).
    k_max, mu_max : float, optional
        Fix the view instead of the automatic one.
    panel_size : (float, float)
        Size of one panel in inches.
    extents : rows of (k_max, mu_max), optional
        The view of every panel, as :func:`atlas_extents` returns it (computed
        from ``share``, ``k_max`` and ``mu_max`` when omitted, by
        :func:`resolve_share`: panels that a shared view would cram get views of
        their own, and the suptitle says so).
    view : {"designer", "report"}
        The panels' own views (:func:`regimemap.maps.designer_view.view_extent`).
    tidy : bool
        Mark the points off view and move any text that collides
        (:func:`regimemap.drawing.tidy.tidy_figure`; default).  False leaves
        every label where :func:`~regimemap.drawing.mapplot.draw_map` put it.
    caption : str, optional
        A first line of the title (a figure's number and caption); the top
        margin makes room for every line of the title.
    samples : int
        Samples of k per panel.
    dpi : float
        Resolution of raster output.
    curves, labels : bool
        Draw the boundary curves / named points, and the mode symbols in
        regions large enough (see :func:`regimemap.render.draw_map`).

    Returns
    -------
    matplotlib.figure.Figure
        With an Agg canvas (no pyplot); one Axes per panel, in row-major
        order, each with the title ``gamma = ..., k' = ...``, and one legend.

    Raises
    ------
    ValueError
        Invalid gamma or k', an empty list, or too many panels.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from ..maps.mapdata import compute_map
    from .key import key_legend
    from .mapplot import draw_map
    from .style import style_context

    gammas = [check_gamma(g) for g in gammas]
    if sweep == "kprime":
        kprimes = [check_kprime(k, (fixed or {}).get("crest", 1.0)) for k in kprimes]
    nr, nc = len(gammas), len(kprimes)
    if nr == 0 or nc == 0:
        raise ValueError("an atlas needs at least one gamma and one kprime")
    if nr * nc > MAX_PANELS:
        raise ValueError(f"{nr} x {nc} = {nr * nc} panels exceed the limit of {MAX_PANELS}")
    crammed: list[tuple[float, float]] = []
    if extents is None:
        share, extents, crammed = resolve_share(gammas, kprimes, share, k_max, mu_max, view=view,
                                                sweep=sweep, fixed=fixed)
    pw, ph = panel_size
    blocks = [[sweep_params(g, sweep, v, fixed) for v in kprimes] for g in gammas]
    loaded = any(p.loaded for row in blocks for p in row)
    datas: list[list[Any]] = [[None] * nc for _ in range(nr)]
    if loaded:  # the key lists the modes the panels show (lift-off ...): compute them first
        datas = [[compute_map(p, k_max=extents[i][j][0], mu_max=extents[i][j][1],
                              samples=samples, curves=curves) for j, p in enumerate(row)]
                 for i, row in enumerate(blocks)]
        from .key import key_handles

        flat = [d for row in datas for d in row]
        dotted = [d.curves["dotted"].label for d in flat if "dotted" in d.curves]
        handles = key_handles(_key_modes(flat),
                              dotted_label=("dotted line " + dotted[0]) if dotted else None)
    else:
        handles = _legend_handles(MAP_MODES, dotted=curves and min(p.kprime for row in blocks
                                                                    for p in row) < 0.0)
    columns = r"$k' = h/H$" if sweep == "kprime" else (
        f"${SWEEPS[sweep][0]}$ ({SWEEPS[sweep][1]})")
    title = caption + "\n" if caption else ""
    title += (rf"Regime maps: rows $\gamma = H/B$, columns {columns}"
             + ("" if share == "none" else
                f" (axes shared {'across the figure' if share == 'all' else 'in each row'})"))
    shared_text = _fixed_text(sweep, fixed) if loaded or sweep != "kprime" else ""
    if shared_text:
        title += "\n" + shared_text
    if crammed:
        names = "; ".join(rf"$\gamma = {_fmt(g)}$, {_sweep_text(sweep, v)}"
                          for g, v in crammed[:3])
        more = f" and {len(crammed) - 3} more" if len(crammed) > 3 else ""
        title += ("\neach panel has its own view: a shared one would cram " + names + more
                  + " into a corner")
    key_cols = min(4, max(2, nc))
    key_rows = -(-len(handles) // key_cols)
    # the key below the panels: 0.1 in from the edge, ~0.2 in a row, then the
    # bottom panels' tick labels and k
    # the title's lines (and one more for a long line wrapped to fit), ~0.19 in each,
    # below 0.15 in of margin, above the panels' titles
    lines = title.count("\n") + 1 + (1 if crammed else 0)
    top = max(0.7, 0.45 + 0.19 * lines)
    left, right, bottom = 0.62, 0.25 if tidy else 0.2, 0.62 + 0.2 * key_rows
    # room between panels for the tick labels and mu of the panel on the right
    wspace, hspace = (0.3 if share == "all" else (0.72 if tidy else 0.5)), (
        0.42 if share == "all" else 0.6)
    fw = left + right + nc * pw + (nc - 1) * wspace
    fh = top + bottom + nr * ph + (nr - 1) * hspace
    with style_context():
        fig = Figure(figsize=(fw, fh), dpi=dpi)
        FigureCanvasAgg(fig)
        shared: Axes | None = None
        row_first: Axes | None = None
        arts = []
        for i, g in enumerate(gammas):
            for j, kp in enumerate(kprimes):
                block = blocks[i][j]
                x0 = (left + j * (pw + wspace)) / fw
                y0 = (bottom + (nr - 1 - i) * (ph + hspace)) / fh
                kw: dict[str, Any] = {}
                if share == "all" and shared is not None:
                    kw = {"sharex": shared, "sharey": shared}
                elif share == "row" and j > 0 and row_first is not None:
                    kw = {"sharex": row_first, "sharey": row_first}
                ax = fig.add_axes((x0, y0, pw / fw, ph / fh), **kw)
                if shared is None:
                    shared = ax
                if j == 0:
                    row_first = ax
                km, mm = extents[i][j]
                art = draw_map(ax, block, k_max=km, mu_max=mm, legend=False,
                               title=_panel_title(g, kp, sweep), samples=samples, curves=curves,
                               labels=labels, data=datas[i][j], tidy=tidy)
                # the curves' names (mu*(k), mu = k|k'| ...) crowd a small panel and
                # spill into the next one: the legend and the full map name them
                for t in art.curve_labels.values():
                    t.remove()
                art.curve_labels.clear()
                for t in set(art.off_view.values()):
                    t.set_fontsize(6.5)
                arts.append(art)
                ax.title.set_fontsize(9)
                ax.xaxis.label.set_fontsize(10)
                ax.yaxis.label.set_fontsize(10)
                ax.tick_params(labelsize=7.5)
                if share == "all":
                    if i < nr - 1:
                        ax.tick_params(labelbottom=False)
                        ax.set_xlabel("")
                    if j > 0:
                        ax.tick_params(labelleft=False)
                        ax.set_ylabel("")
                elif share == "row" and j > 0:
                    ax.tick_params(labelleft=False)
                    ax.set_ylabel("")
                ax.set_gid(f"panel-{i}-{j}")
        key_legend(fig, handles, loc="lower center", ncols=key_cols,
                   bbox_to_anchor=(0.5, 0.1 / fh), fontsize=8, frameon=False,
                   handleheight=1.1, columnspacing=1.5)
        fig.suptitle(title, fontsize=10.5, y=1.0 - 0.15 / fh, va="top")
        if tidy:
            from .tidy import tidy_figure

            tidy_figure(fig, arts)
    fig._regimemap_maps = arts  # type: ignore[attr-defined]  # what each panel drew
    return fig


# --------------------------------------------------------------------------------------
# animation
# --------------------------------------------------------------------------------------
def sweep_extent(gamma: float, kprimes: Sequence[float], view: str = "designer", *,
                 sweep: str = "kprime", fixed: dict[str, Any] | None = None
                 ) -> tuple[float, float]:
    """One view for every frame: :func:`shared_extent` of the frames' own views."""
    return shared_extent([_extent_of(sweep_params(gamma, sweep, v, fixed), view) for v in kprimes])


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
    if Path(path).suffix.lower() != ".gif":
        raise ValueError(f"the animation is written as GIF: give a .gif file, got {os.fspath(path)!r}")


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
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from .style import style_context

    w, h = figsize or FRAME_SIZE
    with style_context():
        fig = Figure(figsize=(w, h), dpi=dpi)
        FigureCanvasAgg(fig)
        ax = fig.add_axes((_F_LEFT / w, _F_BOTTOM / h, 1.0 - (_F_LEFT + _F_RIGHT) / w,
                           1.0 - (_F_TOP + _F_BOTTOM) / h))
    return fig, ax


def draw_frame(fig: Figure, ax: Axes, gamma: float, kprime: float, k_max: float, mu_max: float,
               *, modes: Sequence[Mode] = MAP_MODES, samples: int = SAMPLES,
               block: Parameters | None = None, swept: str | None = None,
               data: Any = None) -> Any:
    """Draw one frame of an animation on ``ax`` (cleared first); return its MapArtists.

    The caption states the report's case (or the block's loads) above the map,
    the frame's gamma and k' (or ``swept``, the swept load, in mathtext) sit in
    a box beside it (outside the map), and the key below lists the modes, sized
    to the frame; then :func:`regimemap.drawing.tidy.tidy_figure` keeps every
    text clear of the others.  ``block`` is the frame's block with loads
    (default ``Parameters(gamma, kprime)``) and ``data`` its precomputed map.
    """
    from .key import key_legend
    from .mapplot import draw_map
    from .style import style_context
    from .tidy import fit_title, tidy_figure

    p = Parameters(gamma, kprime) if block is None else block
    loads = loads_text(p, tex=True)
    caption = f"All modes, block with loads ({loads})" if loads else f"All modes, {p.case.tex}"
    corner = rf"$\gamma = {_fmt(gamma)}$, " + (rf"$k' = {kprime:+.3f}$" if swept is None else swept)
    with style_context():
        ax.cla()
        for leg in list(fig.legends):
            leg.remove()
        for t in list(fig.texts):
            t.remove()
        art = draw_map(ax, p, k_max=k_max, mu_max=mu_max, legend=False, samples=samples,
                       title=caption, data=data)
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


def render_animation(path: str | os.PathLike[str], gamma: float, kprimes: Sequence[float], *,
                    k_max: float | None = None, mu_max: float | None = None, fps: float = 8.0,
                    dpi: float = ANIMATION_DPI, figsize: tuple[float, float] | None = None,
                    samples: int = SAMPLES,
                    progress: Callable[[int, int], None] | None = None,
                    sweep: str = "kprime", fixed: dict[str, Any] | None = None
                    ) -> tuple[int, tuple[int, int]]:
    """Write a GIF of the map of ``gamma`` as k' runs through ``kprimes``.

    Parameters
    ----------
    path : path-like
        Output ``.gif`` (written atomically).
    gamma : float
        Aspect ratio H/B.
    kprimes : sequence of float
        k' of each frame (1 to :data:`MAX_FRAMES` values in [-1, 1]), or the
        value of ``sweep`` in each frame.
    k_max, mu_max : float, optional
        The view of every frame (default :func:`sweep_extent`; the axes are
        the same in every frame).
    fps : float
        Frames per second (0.5 to 50).
    dpi : float
        Pixels per inch of the frames.
    figsize : (float, float), optional
        Inches (default :data:`FRAME_SIZE`).
    samples : int
        Samples of k per frame.
    progress : callable, optional
        Called as ``progress(i, n)`` after frame i of n.
    sweep, fixed : str, dict
        What the frames vary (k' or a load) and what they share, as in
        :func:`atlas_figure`.

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
    from ..maps.mapdata import compute_map
    from .style import style_context

    _check_frames(gamma, kprimes, fps, sweep, fixed)
    g = check_gamma(gamma)
    kps = [check_kprime(k) for k in kprimes] if sweep == "kprime" else [float(v) for v in kprimes]
    blocks = [sweep_params(g, sweep, v, fixed) for v in kps]
    if k_max is None or mu_max is None:
        ek, em = sweep_extent(g, kps, sweep=sweep, fixed=fixed)
        k_max = ek if k_max is None else k_max
        mu_max = em if mu_max is None else mu_max
    fig, ax = frame_figure(figsize, dpi)
    writer = _pillow_writer(fps)
    modes: Sequence[Mode] = MAP_MODES
    datas: list[Any] = [None] * len(blocks)
    if any(p.loaded for p in blocks):  # one key for every frame: the modes any frame shows
        datas = [compute_map(p, k_max=k_max, mu_max=mu_max, samples=samples) for p in blocks]
        modes = _key_modes(datas)
    with style_context():
        writer.setup(fig, str(path), dpi=dpi)
        for i, kp in enumerate(kps):
            draw_frame(fig, ax, g, blocks[i].kprime, k_max, mu_max, modes=modes, samples=samples,
                       block=blocks[i], swept=_sweep_text(sweep, kp) if sweep != "kprime" else None,
                       data=datas[i])
            writer.grab_frame()
            if progress is not None:
                progress(i + 1, len(kps))
        frame_size = tuple(int(v) for v in writer.frame_size)
        writer.finish()
    return len(kps), (frame_size[0], frame_size[1])
