"""Presets of the report's 24 figures (Figs 3.1-3.11 and 4.2-4.7b).

Each preset fixes (gamma, kprime) strictly inside its caption's case, the modes
shaded, whether the figure shows the report's raw region of one mode (Figs
3.1-3.8, 4.2-4.6) or the final map (Figs 3.9a-3.11, 4.7a-b), the view, and
the caption.  The report's figures are sketches without numbers; the values
here were chosen so that each figure shows what its sketch shows (e.g. B' in
view for Figs 4.4a-4.7a, D left of A below C as the report draws it, G = b/|a|
near the right edge in case 2 and well inside in case 3).

Captions lost from the source text (Figs 3.1, 3.3a, 3.4, 3.8, 4.4a-b, 4.5a,
4.6a, 4.7a-b) are reconstructed from the report's wording of their companion
captions and of the text that cites them; :attr:`FigurePreset.caption_source`
says which.  This module does not import matplotlib; drawing is
:func:`regimemap.maps.figures.figure.render_preset`.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ...mechanics.block import Case, Parameters
from ...mechanics.modes import MAP_MODES, Mode

__all__ = ["FigurePreset", "MODEL_FIGURE_ID", "PRESETS", "FIGURE_IDS", "get_preset", "normalise_id",
           "suggest_ids"]

#: The number of the report's model figure (Fig. 2.1, :mod:`regimemap.maps.figures.model`): the
#: figure of the set that is not a map.
MODEL_FIGURE_ID = "2.1"

# -- case conditions (as the captions state them) ----------------------------------------


def above_c(p: Parameters) -> bool:
    """0 <= k' <= 1 (Chapter III)."""
    return 0.0 <= p.kprime <= 1.0


def case_1a(p: Parameters) -> bool:
    """Case 1, 0 <= k' <= (1+g^2)/(3g^2): slope of mu* at A >= 0."""
    return 0.0 <= p.kprime <= p.kprime_1


def case_1b(p: Parameters) -> bool:
    """Case 1, (1+g^2)/(3g^2) <= k' <= (4+g^2)/(3g^2) <= 1: slope of mu* at A <= 0, a >= 0."""
    return p.kprime_1 <= p.kprime <= p.kprime_2 <= 1.0


def case_2_3(p: Parameters) -> bool:
    """Cases 2 and 3, (4+g^2)/(3g^2) <= k' <= 1, a <= 0 (needs gamma > sqrt 2)."""
    return p.gamma > math.sqrt(2.0) and p.kprime_2 <= p.kprime <= 1.0 and p.a <= 0.0


def below_c(p: Parameters) -> bool:
    """-1 <= k' < 0 (Chapter IV)."""
    return -1.0 <= p.kprime < 0.0


def delta_pos(p: Parameters) -> bool:
    """|k'| <= (1+g^2)/(4+g^2), Delta >= 0 (below C)."""
    return p.kprime < 0.0 and p.abs_kprime <= p.kprime_delta and p.delta >= 0.0


def delta_neg(p: Parameters) -> bool:
    """|k'| >= (1+g^2)/(4+g^2), Delta <= 0 (below C)."""
    return p.kprime < 0.0 and p.abs_kprime >= p.kprime_delta and p.delta <= 0.0


# -- caption fragments (mathtext) ---------------------------------------------------------

_C1A = r"case 1, $0 \leq k' \leq (1+\gamma^2)/(3\gamma^2)$, $f_x \geq 0$, $a \geq 0$"
_C1B = (r"case 1, $(1+\gamma^2)/(3\gamma^2) \leq k' \leq (4+\gamma^2)/(3\gamma^2) \leq 1$, "
        r"$f_x \geq 0$, $a \geq 0$")
_C2 = r"case 2, $(4+\gamma^2)/(3\gamma^2) \leq k' \leq 1$, $f_x \geq 0$, $a \leq 0$"
_C3 = r"case 3, $(4+\gamma^2)/(3\gamma^2) \leq k' \leq 1$, $f_x \leq 0$, $a \leq 0$"
_DP = r"$|k'| \leq (1+\gamma^2)/(4+\gamma^2)$"
_DN = r"$|k'| \geq (1+\gamma^2)/(4+\gamma^2)$"


@dataclass(frozen=True)
class FigurePreset:
    """One figure of the report.

    Attributes
    ----------
    id : str
        The report's number, e.g. ``"3.9a"``.
    gamma, kprime : float
        Parameters, strictly inside the caption's case.
    modes : tuple of Mode
        Modes shaded.
    raw : bool
        True: the report's raw region of the (single) mode, as derived before
        Section 4.7; False: the final map.
    caption : str
        The caption (mathtext), without the figure number.
    caption_source : str
        ``"report"`` (the caption survives in the report) or
        ``"reconstructed"``.
    condition : callable
        ``condition(Parameters) -> bool``, the case condition of the caption.
    cases : tuple of Case
        The :class:`~regimemap.params.Case` values the parameters must fall in.
    k_max, mu_max : float or None
        View; None for :func:`regimemap.maps.view.auto_extent`.
    note : str
        Added to the parameter line under the caption (mathtext).
    """

    id: str
    gamma: float
    kprime: float
    modes: tuple[Mode, ...]
    raw: bool
    caption: str
    caption_source: str
    condition: Callable[[Parameters], bool]
    cases: tuple[Case, ...]
    k_max: float | None = None
    mu_max: float | None = None
    note: str = ""

    @property
    def params(self) -> Parameters:
        """The preset's :class:`~regimemap.params.Parameters`."""
        return Parameters(self.gamma, self.kprime)

    @property
    def map_keywords(self) -> dict[str, Any]:
        """What the figure's map is: the keywords of :func:`regimemap.maps.run.run_map`
        (the block, the report's view, its axes, the modes shaded, raw or final)."""
        return {"params": self.params, "view": "report", "k_max": self.k_max,
                "mu_max": self.mu_max, "modes": self.modes, "raw": self.raw}

    def filename(self, ext: str) -> str:
        """``fig-<id>.<ext>``, e.g. ``fig-3.9a.png``."""
        return f"fig-{self.id}.{ext.lstrip('.')}"

    @property
    def title(self) -> str:
        """Two lines: ``Fig. <id>  <caption>`` and the parameters (mathtext)."""
        par = rf"($\gamma = {_num(self.gamma)}$, $k' = {_num(self.kprime)}$"
        if self.note:
            par += "; " + self.note
        par += ")"
        return f"Fig. {self.id}  {self.caption}\n{par}"


def _num(x: float) -> str:
    return f"{x:g}"


def _g_note(p: Parameters, beyond: bool) -> str:
    G = p.b_over_abs_a
    where = r"shown mostly beyond $G$" if beyond else r"shown up to a little beyond $G$"
    return rf"$G$: $k = b/|a| = {G:.3g}$, where $f_x = 0$; {where}"


def _build() -> dict[str, FigurePreset]:
    g = 3.0
    kp_1a, kp_1b, kp_23 = 0.2, 0.425, 0.85  # (1+g^2)/(3g^2) = 0.370, (4+g^2)/(3g^2) = 0.481
    # (1+g^2)/(4+g^2) = 0.769.  Delta >= 0: |k'| = 0.3 keeps B' in view and the SRO-
    # region between AB and mu* (A to B') visible; Delta <= 0: |k'| = 0.85 > 1/2 puts D
    # left of A, as the report draws it.
    kp_dp, kp_dn = -0.3, -0.85
    p23 = Parameters(g, kp_23)
    k2 = 1.0  # a little beyond G = 0.905
    k3 = 4.0  # well beyond G
    n2, n3 = _g_note(p23, False), _g_note(p23, True)
    RE, SL, RO, SM, SP, SPM = (Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS,
                               Mode.SRO_PRIME_MINUS)
    above = (Case.ABOVE_1A, Case.ABOVE_1B, Case.ABOVE_2_3)
    below = (Case.BELOW_DELTA_POS, Case.BELOW_DELTA_NEG)
    A1, B1, C23 = (Case.ABOVE_1A,), (Case.ABOVE_1B,), (Case.ABOVE_2_3,)
    DP, DN = (Case.BELOW_DELTA_POS,), (Case.BELOW_DELTA_NEG,)
    above_modes = (RE, SL, RO, SM, SP)
    below_modes = (RE, SL, RO, SM, SPM)
    rows = [
        # id, gamma, kprime, modes, raw, caption, source, condition, cases, k_max, note
        ("3.1", g, 0.3, (RE,), True, "Rest region", "reconstructed", above_c, above, None, ""),
        ("3.2", g, 0.3, (SL,), True, "Slide region", "report", above_c, above, None, ""),
        ("3.3a", g, kp_1a, (RO,), True, "Rock region, " + _C1A, "reconstructed", case_1a, A1,
         None, ""),
        ("3.3b", g, kp_1b, (RO,), True, "Rock region, " + _C1B, "report", case_1b, B1, None, ""),
        ("3.4", g, kp_23, (RO,), True, "Rock region, " + _C2, "reconstructed", case_2_3, C23, k2,
         n2),
        ("3.5", g, kp_23, (RO,), True, "Rock region, " + _C3, "report", case_2_3, C23, k3, n3),
        ("3.6a", g, kp_1a, (SM,), True, "Slide-rock region, " + _C1A, "report", case_1a, A1,
         None, ""),
        ("3.6b", g, kp_1b, (SM,), True, "Slide-rock region, " + _C1B, "report", case_1b, B1,
         None, ""),
        ("3.7", g, kp_23, (SM,), True, "Slide-rock region, " + _C2, "report", case_2_3, C23, k2,
         n2),
        ("3.8", g, kp_23, (SP,), True, r"Slide-rock region ($\ddot{x}_O \geq 0$), " + _C3,
         "reconstructed", case_2_3, C23, k3, n3),
        ("3.9a", g, kp_1a, above_modes, False, "All modes, " + _C1A, "report", case_1a, A1, None,
         ""),
        ("3.9b", g, kp_1b, above_modes, False, "All modes, " + _C1B, "report", case_1b, B1, None,
         ""),
        ("3.10", g, kp_23, above_modes, False, "All modes, " + _C2, "report", case_2_3, C23, k2,
         n2),
        ("3.11", g, kp_23, above_modes, False, "All modes, " + _C3, "report", case_2_3, C23, k3,
         n3),
        ("4.2", g, kp_dp, (RE,), True, "Rest region", "report", below_c, below, None, ""),
        ("4.3", g, kp_dp, (SL,), True, "Slide region", "report", below_c, below, None, ""),
        ("4.4a", g, kp_dp, (RO,), True, r"Rock (about $O$) region, " + _DP, "reconstructed",
         delta_pos, DP, None, ""),
        ("4.4b", g, kp_dn, (RO,), True, r"Rock (about $O$) region, " + _DN, "reconstructed",
         delta_neg, DN, None, ""),
        ("4.5a", g, kp_dp, (SM,), True, r"Slide-rock (about $O$) region, " + _DP,
         "reconstructed", delta_pos, DP, None, ""),
        ("4.5b", g, kp_dn, (SM,), True, r"Slide-rock (about $O$) region, " + _DN, "report",
         delta_neg, DN, None, ""),
        ("4.6a", g, kp_dp, (SPM,), True, r"Slide-rock (about $O'$) region, " + _DP,
         "reconstructed", delta_pos, DP, None, ""),
        ("4.6b", g, kp_dn, (SPM,), True, r"Slide-rock (about $O'$) region, " + _DN, "report",
         delta_neg, DN, None, ""),
        ("4.7a", g, kp_dp, below_modes, False, "All modes, " + _DP, "reconstructed", delta_pos,
         DP, None, ""),
        ("4.7b", g, kp_dn, below_modes, False, "All modes, " + _DN, "reconstructed", delta_neg,
         DN, None, ""),
    ]
    out: dict[str, FigurePreset] = {}
    for fid, gamma, kprime, modes, raw, cap, src, cond, cases, k_max, note in rows:
        out[fid] = FigurePreset(fid, gamma, kprime, tuple(modes), raw, cap, src, cond,
                                tuple(cases), k_max, None, note)
    return out


#: The 24 presets by id, in the report's order.
PRESETS: dict[str, FigurePreset] = _build()
#: The ids, in the report's order.
FIGURE_IDS: tuple[str, ...] = tuple(PRESETS)

assert len(PRESETS) == 24
assert all(set(p.modes) <= set(MAP_MODES) for p in PRESETS.values())


def normalise_id(fid: str) -> str:
    """A figure number as typed (``"Fig. 3.9A"``, ``"fig-2.1"``) in the form of the ids."""
    return _normalise(fid)


def _normalise(fid: str) -> str:
    s = fid.strip().lower()
    for prefix in ("figure", "fig.", "fig", "-"):
        if s.startswith(prefix):
            s = s[len(prefix):].strip(" -_.")
    return s


def suggest_ids(fid: str, n: int = 3) -> list[str]:
    """The known ids closest to ``fid`` (difflib), best first."""
    return difflib.get_close_matches(_normalise(fid), FIGURE_IDS, n=n, cutoff=0.4)


def get_preset(fid: str) -> FigurePreset:
    """The preset of figure ``fid`` (``"3.9a"``, also ``"Fig. 3.9a"``, ``"fig-3.9A"``).

    Raises
    ------
    KeyError
        If there is no such figure; the message suggests the nearest ids.
    """
    key = _normalise(fid)
    if key in PRESETS:
        return PRESETS[key]
    near = suggest_ids(fid)
    hint = f"; did you mean {', '.join(near)}?" if near else ""
    raise KeyError(f"no figure {fid!r} in the report{hint} (known: {', '.join(FIGURE_IDS)})")
