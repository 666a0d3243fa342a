"""The coverage benchmark's figure: how often each interval method held the known truth.

Draws the results of bench/bench_calibration.py (``bench/results/calibration.json``, its
``coverage`` part, read by the caller): one row of panels per interval method, one column per
level (90 %, 95 %); in each panel the coverage of every case (the shape ``xi`` and the record's
years) for H10, H50 and H100, with bars of two binomial standard errors, the nominal level and
the benchmark's goal (3 points below and above it).  Paul Tol's colour-blind-safe colours, and a
marker of its own for each return period, so that the figure reads in grey too.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..drawing.save import DEFAULT_DPI
from ..drawing.style import agg_figure, style_context

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["calibration_figure"]

#: Return periods: Tol's high-contrast blue, yellow and red, with a marker each.
PERIOD_STYLE = {"10": ("#004488", "o"), "50": ("#DDAA33", "s"), "100": ("#BB5566", "^")}
#: The goal around each nominal level (the benchmark's: 87-93 %, 92-97.5 %).
GOAL = {"90": (87.0, 93.0), "95": (92.0, 97.5)}
GOAL_FILL = "#DDDDDD"
FS = 8.0


def _panel(ax: Axes, method: Mapping[str, Any], level: str, first: bool) -> float:
    """Draw one panel; the lowest bar's end [%]."""
    cases = list(method["cases"])
    lo, hi = GOAL[level]
    lowest = lo
    ax.axhspan(lo, hi, color=GOAL_FILL, lw=0.0, zorder=0)
    ax.axhline(float(level), color="0.2", lw=0.9, zorder=1)
    for k, (period, (colour, marker)) in enumerate(PERIOD_STYLE.items()):
        xs, ys, es = [], [], []
        for i, case in enumerate(cases):
            per = case["periods"].get(period)
            if per is None or per[level]["coverage"] is None:
                continue
            xs.append(i + 0.22 * (k - 1))
            ys.append(100.0 * per[level]["coverage"])
            es.append(200.0 * per[level]["se"])
            lowest = min(lowest, ys[-1] - es[-1])
        ax.errorbar(xs, ys, yerr=es, fmt=marker, color=colour, ms=3.6, mfc="white" if k == 1 else colour,
                    mew=0.9, elinewidth=0.8, capsize=1.5, ls="none", zorder=3,
                    label=f"$H_{{{period}}}$" if first else None)
    shapes = [c["xi"] for c in cases]
    for i in range(1, len(cases)):
        if shapes[i] != shapes[i - 1]:
            ax.axvline(i - 0.5, color="0.6", lw=0.6, zorder=1)
    ax.set_xticks(range(len(cases)), [f"{c['years']:.0f}" for c in cases], fontsize=FS - 1)
    ax.set_xlim(-0.6, len(cases) - 0.4)
    for i, x in enumerate(shapes):
        if i == 0 or x != shapes[i - 1]:
            n = shapes.count(x)
            ax.text(i + 0.5 * (n - 1), 1.01, f"$\\xi$ = {x:+.1f}".replace("+0.0", "0"),
                    transform=ax.get_xaxis_transform(), ha="center", va="bottom", fontsize=FS - 1)
    ax.tick_params(labelsize=FS - 1)
    return lowest


def calibration_figure(coverage: Mapping[str, Mapping[str, Any]], methods: Sequence[str] | None = None,
                       *, dpi: float = DEFAULT_DPI) -> Figure:
    """Coverage per case, return period, level and method, with binomial error bars.

    Parameters
    ----------
    coverage : mapping
        The ``coverage`` part of bench/results/calibration.json: for each method, ``cases`` (each
        with ``xi``, ``years`` and ``periods``: for ``"10"``, ``"50"``, ``"100"`` and levels
        ``"90"``, ``"95"`` a ``coverage`` and its ``se``) and ``records_per_case``.
    methods : sequence of str, optional
        The methods to draw, one row each, in this order (default: every method in ``coverage``).
    dpi : float

    Returns
    -------
    Figure
        Axes labelled ``<method> <level>`` (Agg canvas, no pyplot).

    Raises
    ------
    ValueError
        No method to draw, or one not in ``coverage``.
    """

    names = list(coverage) if methods is None else list(methods)
    if not names:
        raise ValueError("no interval method to draw")
    for m in names:
        if m not in coverage:
            raise ValueError(f"no coverage of the method {m!r} (have {', '.join(coverage) or 'none'})")
    rows = len(names)
    with style_context():
        inches = 0.5 + 2.15 * rows
        fig = agg_figure(figsize=(7.0, inches), dpi=dpi)
        height = 1.0 / inches
        for r, m in enumerate(names):
            for j, level in enumerate(("90", "95")):
                bottom = height * (0.55 + 2.15 * (rows - 1 - r))
                ax = fig.add_axes((0.08 + 0.47 * j, bottom, 0.42, 1.55 * height), label=f"{m} {level}")
                lowest = _panel(ax, coverage[m], level, first=(r == 0 and j == 0))
                ax.set_ylim(max(0.0, 5.0 * ((lowest - 1.0) // 5.0)), 100.8)
                ax.set_title(f"{m}, {level} % intervals ({coverage[m]['records_per_case']} records a case)",
                             fontsize=FS + 0.5, loc="left", pad=12.0)
                if j == 0:
                    ax.set_ylabel("coverage [%]", fontsize=FS)
                if r == rows - 1:
                    ax.set_xlabel("record length [years]", fontsize=FS)
        fig.legend(loc="lower left", ncols=3, fontsize=FS - 1, frameon=False, bbox_to_anchor=(0.06, -0.01))
        fig.text(0.99, 0.005, "bars: 2 binomial standard errors; grey: the goal, nominal ± 3 points",
                 ha="right", va="bottom", fontsize=FS - 2, color="0.3")
    return fig
