"""The loads of a block in words and symbols, for titles, reports and file names (no matplotlib).

One place writes the loads the way every output states them: buoyancy beta,
uplift u, uplift ratio nu, the uplift's arm e_u, the radius of gyration i and
the crest, each only where it differs from the report's block (the arm only
where there is uplift).  ``1/3`` (Goda's triangle) is written as a fraction.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..mechanics.block import Parameters

__all__ = ["LOAD_SYMBOLS", "format_value", "load_items", "loads_text"]

#: Each load: (plain symbol, mathtext symbol, what it is).
LOAD_SYMBOLS: dict[str, tuple[str, str, str]] = {
    "buoyancy": ("beta", r"\beta", "buoyancy / dry weight"),
    "uplift": ("u", "u", "uplift at zero push / dry weight"),
    "uplift_ratio": ("nu", r"\nu", "uplift growth per unit push"),
    "uplift_arm": ("e_u", "e_u", "arm of the uplift from C towards O' / B"),
    "gyration": ("i", "i", "radius of gyration about C / B"),
    "crest": ("crest", r"\mathrm{crest}", "top of the block above C / H"),
}


def format_value(x: float) -> str:
    """``x`` shortest (``%g``), or as a small fraction when it is one (``1/3``, ``-2/3``)."""
    text = f"{x:g}"
    if x != 0.0 and math.isfinite(x) and len(text.lstrip("-")) > 6:
        fr = Fraction(x).limit_denominator(12)
        if fr.denominator > 1 and abs(float(fr) - x) <= 1e-12 * abs(x):
            return f"{fr.numerator}/{fr.denominator}"
    return text


def load_items(p: Parameters) -> list[tuple[str, float]]:
    """The loads ``p`` carries, as (name, value), in the order of :data:`LOAD_SYMBOLS`."""
    uplifted = p.uplift != 0.0 or p.uplift_ratio != 0.0
    shown = {"buoyancy": p.buoyancy != 0.0, "uplift": p.uplift != 0.0, "uplift_ratio": p.uplift_ratio != 0.0,
             "uplift_arm": uplifted, "gyration": p.gyration is not None, "crest": p.crest != 1.0}
    return [(name, getattr(p, name)) for name in LOAD_SYMBOLS if shown[name]]


def loads_text(p: Parameters, tex: bool = False) -> str:
    """The loads of ``p``, e.g. ``beta = 0.32, nu = 0.52, e_u = 1/3`` ("" for the report's block).

    With ``tex=True`` the same in mathtext: ``$\\beta = 0.32$, $\\nu = 0.52$, $e_u = 1/3$``.

    Examples
    --------
    >>> loads_text(Parameters(0.7, -0.02, buoyancy=0.32, uplift_ratio=0.52))
    'beta = 0.32, nu = 0.52, e_u = 1/3'
    >>> loads_text(Parameters(3.0, 0.4))
    ''
    """
    parts = []
    for name, value in load_items(p):
        plain, sym, _ = LOAD_SYMBOLS[name]
        v = format_value(value)
        parts.append(f"${sym} = {v}$" if tex else f"{plain} = {v}")
    return ", ".join(parts)
