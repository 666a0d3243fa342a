"""The look of the lifetime figures: colours, line styles, the tolerable limits, numbers, log axes.

Shared by the exceedance figure (:mod:`regimemap.lifetime.figures.exceedance`), the design
chart (:mod:`regimemap.lifetime.figures.chart`) and the design sheet's lifetime
panel.  No matplotlib at import time.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ...records.numbers import format_significant, significant

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = [
    "BAND", "BAR_EDGE", "CLIMATE_DASHES", "CLIMATE_FILL", "CLIMATE_HATCH", "CLIMATE_LINE", "ESD_LINE",
    "FILL", "FS", "LIFE", "LIFE_LW", "LIMIT", "LIMIT_DASHES", "OFF_MOUND", "OFF_MOUND_HATCH", "SF_DASHES",
    "STORM", "STORM_DASHES", "STORM_LW", "TARGET", "TARGET_TEXT", "TOLERABLE", "decade_range",
    "draw_title_block", "format_log_axis", "impulsive_words", "limit_text", "metres", "percent",
    "significant", "title_height", "value_pm",
]

#: The tolerable expected sliding distances [m] drawn on every figure, with their source.
TOLERABLE: tuple[tuple[float, str], ...] = (
    (0.1, "Goda & Takagi 2000"),
    (0.3, "Shimosako & Takahashi 1999"),
)

# Paul Tol's colour-blind-safe schemes: the lifetime curve a wide light blue (*medium
# contrast*), the single-storm curve dark red dashes on top of it (visible where the two
# coincide: one storm often makes the whole of a lifetime's slide), the ESD black; the light
# blue of his *light* scheme for fills.
LIFE = "#6699CC"
LIFE_LW = 2.2
STORM = "#994455"
STORM_LW = 1.0
STORM_DASHES = (3.0, 1.8)
FILL = "#BBCCEE"
BAR_EDGE = "#2F5F8F"
BAND = "0.86"  # one standard error about the ESD
TARGET = "#BB5566"  # the target ESD and the width meeting it
TARGET_TEXT = "#993344"  # the same, dark enough for text
LIMIT = "0.25"
ESD_LINE = "#004488"  # the chart's ESD: Tol's high-contrast dark blue
#: Dashes of the width of Goda's deterministic design (dash-dot-dot).
SF_DASHES = (6.0, 1.8, 1.2, 1.8, 1.2, 1.8)
#: Line styles of the tolerable limits (0.1 m, 0.3 m): dashed and dash-dotted.
LIMIT_DASHES: tuple[tuple[float, ...], ...] = ((5.0, 2.5), (6.0, 2.0, 1.2, 2.0))
FS = 8.0  # axis labels; tick labels and the lines' labels half a point smaller
#: The climate's uncertainty (a wave record's replicate climates): Paul Tol's green for its lines
#: (long dashes for a curve over the climates), his pale green with a sparse green hatch for a band
#: (told apart from the blue fills and the grey standard error in any colour vision, and by the
#: hatch in greyscale).
CLIMATE_LINE = "#228833"
CLIMATE_DASHES = (6.0, 2.0)
CLIMATE_FILL = "#CCDDAA"
CLIMATE_HATCH = "\\\\"
#: The zone beyond the sliding limit, off the mound: Tol's pale yellow with a hatch of his olive
#: (told apart from the blue fills in any colour vision, and by the hatch in greyscale).
OFF_MOUND = "#EEEEBB"
OFF_MOUND_HATCH = "////"


def impulsive_words(impulsive: bool) -> str:
    """The wave force's coefficient in a figure's subtitle (mathtext)."""
    return (r"impulsive = true ($\alpha^* = \max(\alpha_2, \alpha_I)$)" if impulsive
            else r"impulsive = false ($\alpha^* = \alpha_2$)")


def draw_title_block(fig: Figure, title: str, height: float, fontsize: float = FS) -> None:
    """The title at the top left: its first line larger, the others (the run's facts) below.

    ``height`` is the figure's height in inches; the block takes 0.1 in above, 0.22 in for the
    first line and 0.17 in for each further one (:func:`title_height`).
    """
    first, *rest = title.split("\n")
    x = 0.1 / fig.get_figwidth()
    fig.text(x, 1.0 - 0.1 / height, first, fontsize=fontsize + 1.5, ha="left", va="top",
             fontweight="bold")
    for i, line in enumerate(rest):
        fig.text(x, 1.0 - (0.34 + 0.17 * i) / height, line, fontsize=fontsize - 0.5, ha="left", va="top")


def title_height(title: str | None) -> float:
    """The height in inches :func:`draw_title_block` takes (0 without a title)."""
    if not title:
        return 0.0
    return 0.34 + 0.17 * title.count("\n")


# -- numbers ---------------------------------------------------------------------------------


def metres(x: float) -> str:
    """A length for a label: ``1.14``, ``0.0305``, ``284`` (three significant digits)."""
    return significant(x, 3)


def value_pm(value: float, se: float) -> str:
    """``value ± se``, the standard error to two significant digits and the value to match."""
    if not math.isfinite(se) or se <= 0.0 or value <= 0.0:
        return metres(value)
    decimals = max(0, 1 - int(math.floor(math.log10(se))))
    if decimals > 6:  # a tiny error: write both in three significant digits
        return f"{metres(value)} \u00b1 {significant(se, 2)}"
    return f"{value:.{decimals}f} \u00b1 {se:.{decimals}f}"


def percent(p: float) -> str:
    """A share in per cent for a label: ``89.6 %``, ``0.04 %``, ``100 %``."""
    v = 100.0 * p
    if v == 0.0 or v == 100.0:
        return f"{v:.0f} %"
    if v >= 10.0:
        return f"{v:.1f} %"
    return f"{format_significant(v, 2)} %"


def decade_range(lo: float, hi: float) -> tuple[float, float]:
    """``lo`` down and ``hi`` up to whole powers of ten."""
    return 10.0 ** math.floor(math.log10(lo)), 10.0 ** math.ceil(math.log10(hi))


def format_log_axis(ax: Axes, axis: str = "x") -> None:
    """Decades labelled as plain numbers where short (0.01 ... 1000), else as powers of ten."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    def fmt(v: float, _pos: int | None = None) -> str:
        if v <= 0:
            return ""
        e = int(round(math.log10(v)))
        if abs(math.log10(v) - e) > 1e-6:
            return ""
        if -2 <= e <= 3:
            return f"{v:g}"
        return f"$10^{{{e}}}$".replace("-", "\u2212")

    a = ax.xaxis if axis == "x" else ax.yaxis
    a.set_major_locator(LogLocator(base=10.0, numticks=12))
    a.set_major_formatter(FuncFormatter(fmt))
    a.set_minor_locator(LogLocator(base=10.0, subs=tuple(np.arange(2, 10) * 0.1), numticks=12))
    a.set_minor_formatter(NullFormatter())



def limit_text(lim: float, source: str | None = None) -> str:
    """A tolerable limit in words: ``0.1 m (Goda & Takagi 2000)``."""
    return f"{lim:g} m" + (f" ({source})" if source else "")

