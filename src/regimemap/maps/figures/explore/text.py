"""The words and numbers of ``regimemap explore``: file names, rounding, titles, the hint.

What :class:`~regimemap.maps.figures.explore.explorer.Explorer` writes and how it rounds what the widgets give
(matplotlib is imported only by :func:`window_problem` and
:func:`drag_title`, when called).
"""

from __future__ import annotations

import math
import os
import sys

from ....mechanics.block import Parameters

__all__ = [
    "HINT",
    "default_file_stem",
    "drag_title",
    "snap_click",
    "snap_gamma",
    "snap_kprime",
    "snap_load",
    "window_problem",
]

#: The panel's text before a click.
HINT = ("Click on the map: the mode at that point, its margins\n"
        "and the physics at initiation (as `regimemap classify`).\n\n"
        "Drag the sliders to change gamma and k'; tick 'loads'\n"
        "for the buoyancy beta and the uplift ratio nu.\n"
        "'Save' writes this map as `regimemap plot` draws it.")


def default_file_stem(params: Parameters) -> str:
    """A file name without suffix for the saved view: ``regime-g3-kp0.4`` (``-loaded`` for loads).

    ``regimemap explore`` names its files exactly as ``regimemap plot`` does
    (``regime-g0.7-kp-0.02-b0.32-nu0.52``); this is the stand-alone default.
    """
    stem = f"regime-g{params.gamma:g}-kp{params.kprime:g}"
    return stem + ("-loaded" if params.loaded else "")


def snap_gamma(g: float) -> float:
    """gamma to three significant digits (what the slider shows, the title and the file name)."""
    return float(f"{g:.3g}")


def snap_kprime(kp: float) -> float:
    """k' to 0.001 (never -0.0)."""
    return round(float(kp), 3) + 0.0  # -0.0 -> 0.0


def snap_load(v: float) -> float:
    """A load of a slider (beta, nu) to 0.001."""
    return round(float(v), 3) + 0.0


def snap_click(x: float, span: float) -> float:
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


_GAMMA, _KPRIME = r"\gamma", "k'"
#: The symbols of the title's second line as plain (Unicode) text, from their mathtext.
_PLAIN_SYMBOLS = {_GAMMA: "\u03b3", _KPRIME: "k\u2032", r"\beta": "\u03b2", r"\nu": "\u03bd",
                  "e_u": "e\u1d64", r"\mathrm{crest}": "crest"}


def drag_title(params: Parameters) -> str:
    """``plot``'s title with its second line as plain text, for the frames of a drag.

    The default title's second line is mathtext (``($\\gamma = 3.05$, ...)``),
    and matplotlib parses a line holding any ``$`` as mathtext as a whole: a
    new string to parse at every frame of a drag (~10-30 ms).  Here the
    symbols are Unicode (gamma, k-prime, beta, nu, e with subscript u, in the
    same font) and the numbers plain text with a true minus sign: no mathtext
    at all.  The first line is ``plot``'s own (it changes with the report's
    case only, and matplotlib caches its parse).  The release draws ``plot``'s
    title again.
    """
    from ...describe import LOAD_SYMBOLS, format_value, load_items
    from ..mapplot import default_title

    def num(text: str) -> str:
        return text.replace("-", "\u2212")

    def sym(tex: str) -> str:
        return _PLAIN_SYMBOLS.get(tex, tex)

    first = default_title(params).split("\n")[0]
    gamma, kprime = num(f"{params.gamma:g}"), num(f"{params.kprime:g}")
    parts = [f"{sym(_GAMMA)} = {gamma}", f"{sym(_KPRIME)} = {kprime}"]
    loads = [f"{sym(LOAD_SYMBOLS[name][1])} = {num(format_value(v))}" for name, v in load_items(params)]
    return f"{first}\n(" + ", ".join(parts) + ("; " + ", ".join(loads) if loads else "") + ")"
