"""Fig. 2.1, the report's model: the block, its half-dimensions, the force and the reactions.

The report's model figure is lost from its source text; :func:`model_figure`
redraws it from the definitions of Chapter II: a rigid block of width 2B and
height 2H (B and H are *half* the width and the height, gamma = H/B) with its
centre of mass C, standing on a rigid base with friction mu on its corners O
(left, leeward: the force pushes towards it) and O' (right); the horizontal
force F = mgk pushes to the left at the height h = k'H above C; the base
pushes back with f_x (positive to the right) and f_y, acting at xi from C; the
block turns by theta (counter-clockwise positive) and C moves by x, y.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ...drawing.save import DEFAULT_DPI
from ...drawing.style import agg_figure, style_context

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["MODEL_TITLE", "model_figure"]

#: The model figure's caption (mathtext).
MODEL_TITLE = (r"Fig. 2.1  The model: a rigid block of half width $B$ and half height $H$"
               "\n"
               r"($\gamma = H/B$) on a rigid base with friction $\mu$, pushed by "
               r"$F = mgk$ at $h = k'H$ above $C$")

# the block as drawn: B = 1, H = 1.6 (gamma = 1.6), k' = 0.55, xi = -0.45
_B, _H, _KP, _XI = 1.0, 1.6, 0.55, -0.45


def _dimension(ax: Axes, a: tuple[float, float], b: tuple[float, float], text: str,
               offset: tuple[float, float], **kw: Any) -> None:
    """A dimension line with arrows at both ends and its text beside its middle."""
    ax.annotate("", a, xytext=b, arrowprops={"arrowstyle": "<|-|>", "lw": 0.8, "color": "0.15",
                                             "mutation_scale": 8, "shrinkA": 0, "shrinkB": 0})
    mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    ax.annotate(text, (mx, my), xytext=offset, textcoords="offset points", fontsize=11,
                ha=kw.get("ha", "center"), va=kw.get("va", "center"), color="0.05")


def _arrow(ax: Axes, tail: tuple[float, float], head: tuple[float, float], color: str = "black",
           lw: float = 1.6) -> None:
    ax.annotate("", head, xytext=tail,
                arrowprops={"arrowstyle": "-|>", "lw": lw, "color": color, "mutation_scale": 14,
                            "shrinkA": 0, "shrinkB": 0})


def draw_model(ax: Axes) -> None:
    """Draw the model of the block on ``ax`` (equal axes, no ticks)."""
    from matplotlib.patches import Arc, Polygon, Rectangle

    B, H = _B, _H
    h = _KP * H
    ax.set_aspect("equal")
    ax.set_xlim(-2.05, 2.35)
    ax.set_ylim(-0.75, 2 * H + 0.55)
    ax.set_axis_off()
    # the base: a line with hatching below
    ax.add_patch(Rectangle((-1.9, -0.18), 3.8, 0.18, facecolor="none", edgecolor="0.35",
                           hatch="////", linewidth=0.0))
    ax.plot([-1.9, 1.9], [0.0, 0.0], color="black", lw=1.2)
    ax.text(1.9, -0.33, r"rigid base, friction $\mu$", fontsize=10, ha="right", va="top")
    # the block, its centre lines
    ax.add_patch(Polygon([(-B, 0), (B, 0), (B, 2 * H), (-B, 2 * H)], closed=True,
                         facecolor="#dde6f0", edgecolor="black", lw=1.4))
    ax.plot([-B, B], [H, H], color="0.45", lw=0.6, ls=(0, (6, 3, 1, 3)))
    ax.plot([0, 0], [0, 2 * H], color="0.45", lw=0.6, ls=(0, (6, 3, 1, 3)))
    ax.plot([0], [H], marker="o", color="black", markersize=5)
    ax.annotate("$C$", (0, H), xytext=(-5, 5), textcoords="offset points", fontsize=12,
                ha="right", va="bottom")
    # the corners
    for x, name, ha in ((-B, "$O$", "right"), (B, "$O'$", "left")):
        ax.plot([x], [0], marker="o", color="black", markersize=4)
        ax.annotate(name, (x, 0), xytext=(-6 if ha == "right" else 6, 3),
                    textcoords="offset points", fontsize=12, ha=ha, va="bottom")
    # half-dimensions: B below the base line's level inside the block, H on the left
    _dimension(ax, (0, 0.35), (B, 0.35), "$B$", (0, 7))
    _dimension(ax, (-B, 0.35), (0, 0.35), "$B$", (0, 7))
    _dimension(ax, (-1.45, H), (-1.45, 2 * H), "$H$", (-8, 0), ha="right")
    _dimension(ax, (-1.45, 0), (-1.45, H), "$H$", (-8, 0), ha="right")
    ax.plot([-1.55, -B], [2 * H, 2 * H], color="0.4", lw=0.5)
    ax.plot([-1.55, -B], [H, H], color="0.4", lw=0.5)
    ax.plot([-1.55, -B], [0, 0], color="0.4", lw=0.5)
    # the force F at h = k'H above C, pushing to the left on the right face
    _arrow(ax, (B + 0.95, H + h), (B, H + h), color="#b03020", lw=2.0)
    ax.text(B + 0.5, H + h + 0.1, "$F = mgk$", fontsize=12, ha="center", va="bottom",
            color="#b03020")
    _dimension(ax, (B + 0.55, H), (B + 0.55, H + h), "$h = k'H$", (6, 0), ha="left")
    ax.plot([0, B + 0.65], [H, H], color="0.4", lw=0.5)
    # the weight
    _arrow(ax, (0, H), (0, H - 0.55), color="0.25", lw=1.2)
    ax.text(0.07, H - 0.45, "$mg$", fontsize=11, ha="left", va="center", color="0.25")
    # the reactions at xi from C
    xr = _XI * B
    _arrow(ax, (xr, -0.62), (xr, 0.0), color="#1f5fa8", lw=1.8)
    ax.text(xr + 0.06, -0.5, "$f_y$", fontsize=12, ha="left", va="center", color="#1f5fa8")
    _arrow(ax, (xr - 0.75, -0.1), (xr, -0.1), color="#1f5fa8", lw=1.8)
    ax.text(xr - 0.78, -0.1, "$f_x$", fontsize=12, ha="right", va="center", color="#1f5fa8")
    _dimension(ax, (xr, 0.9), (0, 0.9), r"$\xi$", (0, 7))
    ax.plot([xr, xr], [0.0, 1.0], color="0.4", lw=0.5, ls=":")
    # the rotation theta (counter-clockwise positive) and the displacements of C
    ax.add_patch(Arc((0, H), 1.2, 1.2, theta1=35, theta2=120, color="0.15", lw=1.0))
    _arrow(ax, (-0.27, H + 0.55), (-0.31, H + 0.53), color="0.15", lw=1.0)
    ax.text(0.38, H + 0.55, r"$\theta$", fontsize=12, ha="left", va="bottom")
    _arrow(ax, (0.15, 2 * H + 0.25), (0.75, 2 * H + 0.25), color="0.15", lw=1.0)
    ax.text(0.8, 2 * H + 0.25, "$x$", fontsize=11, ha="left", va="center")
    _arrow(ax, (-0.15, 2 * H + 0.08), (-0.15, 2 * H + 0.5), color="0.15", lw=1.0)
    ax.text(-0.2, 2 * H + 0.45, "$y$", fontsize=11, ha="right", va="center")


def model_figure(dpi: float = DEFAULT_DPI, fig: Figure | None = None) -> Figure:
    """Fig. 2.1 on a Figure of its own (Agg canvas, no pyplot)."""

    with style_context():
        if fig is None:
            fig = agg_figure(figsize=(6.4, 5.6), dpi=dpi)
        else:
            fig.clear()
            fig.set_size_inches(6.4, 5.6)
            fig.set_dpi(dpi)
        ax = fig.add_axes((0.02, 0.02, 0.96, 0.82))
        draw_model(ax)
        fig.text(0.03, 0.975, MODEL_TITLE, fontsize=10, ha="left", va="top")
    return fig
