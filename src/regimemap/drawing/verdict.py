"""The verdict badge: PASS or FAIL in the title block of a figure, where the eye goes first."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..records.checks import Check, all_pass

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure
    from matplotlib.text import Text

__all__ = ["FAIL_COLOUR", "PASS_COLOUR", "draw_verdict_badge", "verdict_colour"]

#: Okabe & Ito's vermillion and bluish green: told apart by readers with either
#: red-green colour deficiency, and the badge's word says it in greyscale too.
FAIL_COLOUR = "#D55E00"
PASS_COLOUR = "#009E73"


def verdict_colour(check: Check) -> str:
    """The colour a number is written in: :data:`FAIL_COLOUR` when its check fails, else black."""
    return "black" if check.passed else FAIL_COLOUR


def draw_verdict_badge(fig: Figure, checks: Sequence[Check], x: float = 0.985, y: float = 0.985,
                       fontsize: float = 10.0) -> Text | None:
    """Write PASS or FAIL (with the count of failed requirements) in a box at (x, y), figure fraction.

    The box's top right corner is at (x, y).  Nothing is drawn when there is no
    requirement.  Returns the text artist (None when nothing is drawn).
    """
    if not checks:
        return None
    ok = all_pass(checks)
    bad = sum(not c.passed for c in checks)
    word = "PASS" if ok else f"FAIL ({bad} of {len(checks)})"
    colour = PASS_COLOUR if ok else FAIL_COLOUR
    return fig.text(x, y, word, ha="right", va="top", fontsize=fontsize, fontweight="bold",
                    color="white", bbox={"boxstyle": "round,pad=0.35", "facecolor": colour,
                                         "edgecolor": colour})
