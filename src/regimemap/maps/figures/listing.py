"""The report's figures listed in words (``regimemap figures --list``), without drawing.

A line per figure of a set: its id, its block (gamma, kprime and the case, or "loaded"), what it
shows and its caption in plain ASCII.  No matplotlib: the presets and the worked figures are
declarations (:mod:`regimemap.maps.figures.presets`, :mod:`regimemap.maps.figures.worked`).
"""

from __future__ import annotations

from ...records.numbers import short
from .presets import MODEL_FIGURE_ID, PRESETS
from .worked import WORKED

__all__ = ["figure_listing", "plain_caption"]

#: mathtext and its plain ASCII for the terminal.
_PLAIN = ((r"\leq", "<="), (r"\geq", ">="), (r"\gamma", "g"), (r"\ddot{x}_O", "x_O''"),
          (r"\nu", "nu"),
          ("$", ""), ("{", ""), ("}", ""))


def plain_caption(tex: str) -> str:
    """A caption in plain ASCII for the terminal (mathtext removed)."""
    for a, b in _PLAIN:
        tex = tex.replace(a, b)
    return tex


def figure_listing(which: str) -> list[str]:
    """A line per figure of the set ``which`` (``"report"``, ``"worked"`` or ``"all"``)."""
    lines = []
    if which != "worked":
        lines.append(f"{MODEL_FIGURE_ID:5s} the model: the block (half width B, half height H), the "
                     "force F at h = k'H above C, the reactions f_x, f_y at xi, the rotation theta")
        for p in PRESETS.values():
            what = "final map" if not p.raw else "raw region of " + p.modes[0].label
            lines.append(f"{p.id:5s} gamma={short(p.gamma):4s} kprime={short(p.kprime):6s} "
                         f"{p.params.case.value:8s} {what:24s} [{p.caption_source}]  "
                         f"{plain_caption(p.caption)}")
    for w in WORKED.values() if which != "report" else ():
        g, kp = short(w.params.gamma), short(w.params.kprime)
        what = "atlas of final maps" if w.sweep else "final map"
        kind = "loaded" if w.params.loaded else w.params.case.value
        lines.append(f"{w.id:5s} gamma={g:4s} kprime={kp:6s} {kind:8s} {what:24s} [worked]  "
                     f"{plain_caption(w.title.splitlines()[0].split('  ', 1)[1])}")
    return lines
