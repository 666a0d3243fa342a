"""The style of every drawing: one registry per kind of category, rcParams, text sizes.

:data:`MODE_STYLE` maps each mode to its fill colour and hatch (Paul Tol's
colour-blind-safe *light* scheme plus a distinct hatch, readable in greyscale);
later kinds of map (outcomes after initiation) add registries of their own
beside it.  :func:`style_context` applies regimemap's rcParams (byte-stable SVG
and PDF, TrueType fonts in PDF) without touching matplotlib's global rcParams; the
one process-wide change it makes is a cache: :func:`share_mathtext_parses`.
What every figure draws the same way is here once too: :func:`agg_figure` (a figure
on an Agg canvas, no pyplot), :func:`label_axes` (axis labels, tick labels and a
panel's title) and :func:`key_below` (a figure's key under its axes).
"""

from __future__ import annotations

import contextlib
import functools
import os
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..mechanics.modes import Mode

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from matplotlib.legend import Legend
    from matplotlib.typing import RcKeyType

__all__ = [
    "CONSTRUCTION",
    "FLIGHT_STYLE",
    "OUTCOME_STYLE",
    "DOTTED",
    "HATCH_LW",
    "LINE_LW",
    "MODE_STYLE",
    "ModeStyle",
    "agg_figure",
    "key_below",
    "label_axes",
    "mode_symbol",
    "phase_style",
    "share_mathtext_parses",
    "style_context",
    "text_size",
]


@dataclass(frozen=True)
class ModeStyle:
    """How a mode's region is filled.

    Attributes
    ----------
    color : str
        Fill colour (Paul Tol's *light* scheme, colour-blind safe and light
        enough for black labels and lines on top).
    hatch : str
        matplotlib hatch pattern, distinct per mode so that maps stay
        readable in greyscale print.
    hatch_color : tuple
        RGBA of the hatch lines.
    """

    color: str
    hatch: str
    hatch_color: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.35)


#: Fill style of each mode.  Neighbouring regions (RE|SL along OA, SL|SRO- on
#: CD, SRO-|RO on mu*, SL|SRO'- on DC ...) differ in hue, in lightness and in
#: hatch direction.
MODE_STYLE: dict[Mode, ModeStyle] = {
    Mode.RE: ModeStyle("#DDDDDD", ".."),  # pale grey: nothing moves
    Mode.SL: ModeStyle("#EEDD88", "//"),  # light yellow
    Mode.RO: ModeStyle("#EE8866", "\\\\"),  # orange
    Mode.SRO_MINUS: ModeStyle("#77AADD", "--"),  # light blue
    Mode.SRO_PLUS: ModeStyle("#44BB99", "||"),  # mint
    Mode.SRO_PRIME_MINUS: ModeStyle("#FFAABB", "xx"),  # pink
    Mode.RO_PRIME: ModeStyle("#BBCC33", "++"),  # pear: loaded blocks only (uplift near O)
    Mode.SRO_PRIME_PLUS: ModeStyle("#AAAA00", "oo"),  # never chosen on a map
    Mode.LO: ModeStyle("#99DDFF", "**"),  # light cyan: lift-off, loaded blocks only
}

#: Fill style of each outcome category of :func:`regimemap.dynamics.outcome_map` (codes
#: :data:`regimemap.dynamics.REST` ... :data:`~regimemap.dynamics.OVERTURN`).  The motions take
#: the colour and hatch of the map's mode they are made of (rest as RE, slide only as SL, rock
#: only as RO, slide-rock as SRO-), so a reader carries the colours from one figure to the
#: other; overturning is Paul Tol's *muted* purple, darker than all of them (it stands out in
#: greyscale too), with a light crossed hatch; a run still moving at the time limit is light pink
#: with rings (a hatch no other outcome has).
#: (The codes are written out so that drawing a regime map does not import regimemap.dynamics;
#: tests/motion/test_figures_outcome.py checks them against it.)
OUTCOME_STYLE: dict[int, ModeStyle] = {
    0: MODE_STYLE[Mode.RE],  # REST
    1: MODE_STYLE[Mode.SL],  # SLIDE
    2: MODE_STYLE[Mode.RO],  # ROCK
    3: MODE_STYLE[Mode.SRO_MINUS],  # SLIDE_ROCK
    4: ModeStyle("#AA4499", "xx", (1.0, 1.0, 1.0, 0.5)),  # OVERTURN
    5: ModeStyle("#FFAABB", "oo"),  # STILL_MOVING at the time limit: Tol's light pink, rings
}
#: Style of free flight (no corner in contact), the one phase of a motion that is no map mode.
FLIGHT_STYLE = ModeStyle("#FFFFFF", "oo")


def phase_style(code: int) -> ModeStyle:
    """The fill of a phase of a motion (:class:`regimemap.dynamics.Phase` code): its mode's, or
    :data:`FLIGHT_STYLE`."""
    # the contact phases share their codes with RE ... SRO'+ (0-7); code 8 is flight, not
    # lift-off (Mode.LO, a mode of the map that a phase never carries)
    return MODE_STYLE[Mode(code)] if 0 <= code < Mode.LO.value else FLIGHT_STYLE


#: Line widths (points) of hatches and of boundary curves.
HATCH_LW = 0.45
LINE_LW = 1.15
#: Dashed construction lines and the report's dotted lines.
#: (keyword arguments of :class:`~matplotlib.lines.Line2D`)
CONSTRUCTION: dict[str, Any] = {"color": "0.3", "linewidth": 0.7, "dashes": (4.0, 2.5)}
DOTTED: dict[str, Any] = {"color": "0.1", "linewidth": 1.0, "dashes": (1.0, 2.0)}

#: rcParams for every map (applied with :func:`style_context`, never globally).
_RC: dict[RcKeyType, Any] = {
    "svg.hashsalt": "regimemap",
    "svg.fonttype": "path",
    "pdf.fonttype": 42,
    "ps.fonttype": 42,
    "pdf.compression": 6,
    "hatch.linewidth": HATCH_LW,
    "mathtext.fontset": "dejavusans",
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans"],
    "axes.unicode_minus": True,
    "path.simplify": False,
    "savefig.bbox": None,
    "savefig.pad_inches": 0.1,
    "savefig.facecolor": "white",
    "savefig.edgecolor": "white",
    "savefig.transparent": False,
    "figure.facecolor": "white",
    "axes.linewidth": 0.8,
    "xtick.direction": "out",
    "ytick.direction": "out",
}


@contextlib.contextmanager
def style_context() -> Iterator[None]:
    """matplotlib ``rc_context`` with regimemap's fixed style (no global change).

    The first call also gives matplotlib's mathtext parsers one shared parse cache
    (:func:`share_mathtext_parses`).
    """
    import matplotlib

    if not _shared["mathtext"]:
        share_mathtext_parses()
    with matplotlib.rc_context(_RC):
        yield


_shared = {"mathtext": False}


def agg_figure(figsize: tuple[float, float], dpi: float | None = None, **kwargs: Any) -> Figure:
    """A :class:`~matplotlib.figure.Figure` on an Agg canvas (no pyplot, no window).

    ``kwargs`` go to the figure (``facecolor`` ...); ``dpi`` None is matplotlib's default.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, dpi=dpi, **kwargs)
    FigureCanvasAgg(fig)
    return fig


def key_below(fig: Figure, key: Sequence[tuple[Any, str]], y: float, fontsize: float, *,
              ncols: int = 2, handlelength: float = 2.6, columnspacing: float = 1.2) -> Legend:
    """A figure's key centred below its axes, without a frame: the (handle, text) pairs of
    ``key`` in ``ncols`` columns, its bottom at ``y`` (figure fraction)."""
    return fig.legend([k for k, _ in key], [v for _, v in key], loc="lower center",
                      bbox_to_anchor=(0.5, y), ncols=ncols, fontsize=fontsize, frameon=False,
                      handlelength=handlelength, columnspacing=columnspacing, borderaxespad=0.0)


def label_axes(ax: Axes, xlabel: str | None, ylabel: str, fontsize: float, title: str | None = None,
               *, title_larger: float = 1.0) -> None:
    """Name the axes in ``fontsize`` points (the x axis unless ``xlabel`` is None), their tick
    labels half a point smaller and, when given, the ``title`` at the left, ``title_larger``
    points larger."""
    if xlabel is not None:
        ax.set_xlabel(xlabel, fontsize=fontsize)
    ax.set_ylabel(ylabel, fontsize=fontsize)
    ax.tick_params(labelsize=fontsize - 0.5)
    if title is not None:
        ax.set_title(title, fontsize=fontsize + title_larger, loc="left")


def share_mathtext_parses(maxsize: int = 512) -> bool:
    """Make every mathtext parser of the process share one parse cache; True if installed.

    matplotlib caches a mathtext parse per *parser* (``MathTextParser._parse_cached``, an
    ``lru_cache`` of 50 entries whose key holds the parser), and every SVG file gets a new
    parser (a renderer of its own, with its own ``TextToPath``): every formula of every
    map was parsed again for each SVG written -- ~300 parses of ~140 distinct formulas
    for ``regimemap figures --format png,svg``, 0.7-0.9 s of its ~8 s of CPU.  The
    parse depends on the parser only through its output type (vector or raster), so the
    cache is keyed on that instead: the same results, computed once per process.  A
    matplotlib whose parser has no such cache is left alone (False).
    """
    _shared["mathtext"] = True
    from matplotlib.mathtext import MathTextParser

    cached = MathTextParser.__dict__.get("_parse_cached")
    original: Callable[..., Any] | None = getattr(cached, "__wrapped__", None)
    if original is None or getattr(cached, "regimemap_shared", False):
        return False
    parsers: dict[str, Any] = {}  # one parser of each output type, for the original method

    @functools.lru_cache(maxsize=maxsize)
    def shared(kind: str, *args: Any) -> Any:
        return original(parsers[kind], *args)

    def _parse_cached(self: Any, *args: Any) -> Any:
        kind = getattr(self, "_output_type", None)
        if not isinstance(kind, str):  # pragma: no cover - another matplotlib
            return original(self, *args)
        parsers.setdefault(kind, self)
        return shared(kind, *args)

    _parse_cached.regimemap_shared = True  # type: ignore[attr-defined]
    MathTextParser._parse_cached = _parse_cached  # type: ignore[attr-defined]
    if hasattr(os, "register_at_fork"):  # not on Windows, where workers are not forked
        os.register_at_fork(after_in_child=lambda: _forget_the_parents_parses(shared, cached))
    return True


def _forget_the_parents_parses(*caches: Any) -> None:
    """In a process just forked (a worker of ``regimemap figures``): empty the mathtext caches.

    A parse holds the FreeType fonts it was laid out with, and a font reads its file through
    the file's offset, which a fork shares: a worker and its parent (or two workers) loading
    glyphs of one inherited font at once read each other's bytes (``FT_Load_Glyph ... failed
    with error 0x16: too many hints``).  matplotlib empties its own font cache at a fork; the
    parses are the other place fonts are kept.
    """
    for cache in caches:
        cache.cache_clear()


def mode_symbol(mode: Mode) -> tuple[str, str]:
    """A mode's symbol for a region label: (text, fontstyle).

    ``$RE$``, ``$SL$`` and ``$RO$`` are written as plain oblique text: the
    face mathtext uses for them (same glyphs; the box behind them is a little
    taller), without the cost of parsing mathtext.  Symbols with sub- or
    superscripts stay mathtext (Unicode subscripts sit too high).
    """
    tex = mode.tex
    inner = tex[1:-1]
    if tex.startswith("$") and tex.endswith("$") and inner.isalpha():
        return inner, "italic"
    return tex, "normal"


def text_size(text: str, fontsize: float, lines: int = 1) -> tuple[float, float]:
    """Rough size (points) of a short label with its white box, without drawing it.

    The one text-size model of the drawings (region, point, curve and overlay
    labels): ``text`` is the longest line (mathtext markup is not counted),
    ``lines`` the number of lines.
    """
    plain = text.replace("$", "").replace("_{-}", "-").replace("_{+}", "+").replace("\\", "")
    plain = plain.replace("mu", "m").replace("{", "").replace("}", "").replace("^", "")
    return (0.62 * fontsize * len(plain) + 5.0, 1.25 * fontsize * lines + 4.0)
