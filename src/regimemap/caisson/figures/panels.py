"""The panels of the caisson design sheet (:mod:`regimemap.caisson.figures.page`), but the map.

One function per panel, each drawing on the axes it is given: (a) the
cross-section to scale (:func:`draw_section`), (b) Goda's pressures on the wall
(:func:`draw_pressure`), (c) the uplift under the base (:func:`draw_uplift`),
(e) the safety factors as the wave grows (:func:`draw_path`) and (f) the numbers
(:func:`draw_table`); the loaded map (d) is :mod:`regimemap.caisson.figures.map_panel`.
Everything drawn is computed beforehand (:func:`regimemap.caisson.report.caisson_report`);
these functions only draw.  Also the sheet's small helpers: its font size
:data:`FS`, :func:`~regimemap.records.numbers.significant` for numbers and :func:`mode_style` for a
mode's fill.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from ...drawing.style import MODE_STYLE, ModeStyle, label_axes
from ...drawing.verdict import FAIL_COLOUR
from ...maps.loadedmap import Margin, mode_label
from ...mechanics.modes import Mode
from ...records.checks import Check
from ...records.numbers import significant
from ..report import CaissonReport

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes

__all__ = ["FS", "draw_path", "draw_pressure", "draw_section", "draw_table", "draw_uplift",
           "mode_style", "num"]

_WATER = "#D6E9F5"
_MOUND = "#CDBFA6"
_ARMOUR = "#A8957A"
_CONCRETE = "#B9B9B9"
_PRESSURE = "#77AADD"
_UPLIFT = "#EE8866"
#: The sheet's font size (points) of labels and numbers; titles are 1 point larger.
FS = 7.5


def mode_style(code: int) -> ModeStyle:
    """The fill of a mode code, as every map draws it (:data:`regimemap.drawing.style.MODE_STYLE`)."""
    return MODE_STYLE[Mode(int(code))]


def num(r: CaissonReport, name: str) -> float:
    """The design's input ``name`` (``depth``, ``width`` ...) as a float."""
    return float(np.asarray(r.inputs[name]))


# -- (a) the cross-section ------------------------------------------------------------------

def _dimension(ax: Axes, x: float, y0: float, y1: float, text: str, side: str = "left") -> None:
    ax.annotate("", (x, y0), (x, y1), arrowprops={"arrowstyle": "<->", "lw": 0.6, "color": "0.15",
                                                  "shrinkA": 0, "shrinkB": 0})
    ha = "right" if side == "left" else "left"
    dx = -0.25 if side == "left" else 0.25
    ax.text(x + dx, 0.5 * (y0 + y1), text, ha=ha, va="center", fontsize=FS - 0.5, color="0.1")


def _hdimension(ax: Axes, y: float, x0: float, x1: float, text: str, below: bool = True) -> None:
    ax.annotate("", (x0, y), (x1, y), arrowprops={"arrowstyle": "<->", "lw": 0.6, "color": "0.15",
                                                  "shrinkA": 0, "shrinkB": 0})
    ax.text(0.5 * (x0 + x1), y + (-0.35 if below else 0.35), text, ha="center",
            va="top" if below else "bottom", fontsize=FS - 0.5, color="0.1")


def draw_section(ax: Axes, r: CaissonReport) -> None:
    from matplotlib.patches import Polygon, Rectangle

    h, d, hp = num(r, "depth"), num(r, "armour_depth"), num(r, "base_depth")
    hc, bm, w = num(r, "crest"), num(r, "berm_width"), num(r, "width")
    b = r.analysis.block
    hcg = float(b.H)
    toe_sea = -bm - 2.0 * (h - d)  # seaward slope 1:2 (schematic)
    berm_lee = max(0.25 * w, 2.0)
    toe_lee = w + berm_lee + 1.5 * (h - hp)  # leeward slope 1:1.5 (schematic)
    x0, x1 = toe_sea - 0.12 * w - 6.0, toe_lee + 0.12 * w
    top = hc + 0.25 * (h + hc)
    ax.add_patch(Rectangle((x0, -h), x1 - x0, h, facecolor=_WATER, edgecolor="none", zorder=0))
    # sea bed and mound
    ax.fill_between([x0, x1], [-h - 0.06 * (h + hc)] * 2, [-h, -h], color="#E8DFC8", lw=0, zorder=1)
    ax.plot([x0, x1], [-h, -h], color="0.3", lw=0.8, zorder=2)
    mound = [(toe_sea, -h), (-bm - 2.0 * (h - hp), -hp), (0.0, -hp), (w, -hp), (w + berm_lee, -hp),
             (toe_lee, -h)]
    ax.add_patch(Polygon(mound, closed=True, facecolor=_MOUND, edgecolor="0.35", lw=0.6, zorder=2,
                         hatch="..", label="_mound"))
    armour = [(-bm - 2.0 * (hp - d), -hp), (-bm, -d), (0.0, -d), (0.0, -hp)]
    ax.add_patch(Polygon(armour, closed=True, facecolor=_ARMOUR, edgecolor="0.3", lw=0.6, zorder=3))
    # caisson
    ax.add_patch(Rectangle((0.0, -hp), w, hp + hc, facecolor=_CONCRETE, edgecolor="0.1", lw=1.0,
                           zorder=4))
    # still-water level
    ax.plot([x0, 0.0], [0.0, 0.0], color="#1f5f99", lw=0.9, zorder=3)
    ax.plot([w, x1], [0.0, 0.0], color="#1f5f99", lw=0.9, zorder=3)
    sx = toe_sea + 0.5 * (0.0 - toe_sea)
    ax.plot([sx], [0.32], marker="v", color="#1f5f99", markersize=5, zorder=5)
    ax.text(sx + 0.9, 0.2, "SWL", fontsize=FS - 0.5, color="#1f5f99", va="bottom")
    # forces on the equivalent block: C, W' down, P at Mp/P, U at its arm
    xc = 0.5 * w
    ax.plot([xc], [-hp + hcg], marker="o", markersize=4.5, markerfacecolor="white",
            markeredgecolor="black", zorder=7)
    ax.text(xc + 0.35, -hp + hcg + 0.25, "C", fontsize=FS, zorder=7)
    arrow = {"arrowstyle": "-|>", "lw": 1.1, "color": "black", "shrinkA": 0, "shrinkB": 0,
             "mutation_scale": 8}
    scale = 0.45 * hp
    ax.annotate("", (xc, -hp + hcg - scale), (xc, -hp + hcg), arrowprops=arrow, zorder=7)
    ax.text(xc + 0.35, -hp + hcg - 0.75 * scale, "W\u2032", fontsize=FS, zorder=7)
    zp = -hp + float(r.analysis.loads.Mp) / float(r.analysis.loads.P)
    ax.annotate("", (0.0, zp), (-0.3 * w, zp), arrowprops=dict(arrow, color="#1f4e99"), zorder=7)
    ax.text(-0.3 * w, zp + 0.3, "P", fontsize=FS, color="#1f4e99", ha="left", va="bottom", zorder=7)
    xu = w - float(r.analysis.loads.Mu) / float(r.analysis.loads.U)
    ax.annotate("", (xu, -hp), (xu, -hp - 0.3 * hp), arrowprops=dict(arrow, color="#b0431c"), zorder=7)
    ax.text(xu + 0.35, -hp - 0.3 * hp, "U", fontsize=FS, color="#b0431c", va="bottom", zorder=7,
            bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
    # dimensions
    _dimension(ax, w + 0.6 * berm_lee, -hp, 0.0, f"h\u2032 = {significant(hp, 3)} m", side="right")
    _dimension(ax, w + 0.6 * berm_lee, 0.0, hc, f"h$_c$ = {significant(hc, 3)} m", side="right")
    _dimension(ax, x0 + 0.6, -h, 0.0, f"h = {significant(h, 3)} m", side="right")
    _dimension(ax, -bm - 1.0, -d, 0.0, f"d = {significant(d, 3)} m")
    _hdimension(ax, hc + 0.1 * (h + hc), 0.0, w, f"2B = {significant(w, 3)} m", below=False)
    if bm > 0:
        _hdimension(ax, -d + 0.35, -bm, 0.0, f"B$_M$ = {significant(bm, 3)} m", below=False)
    ax.set_xlim(x0, x1)
    ax.set_ylim(-h - 0.06 * (h + hc), top)
    ax.set_aspect("equal", adjustable="box")
    ax.set_anchor("NW")
    label_axes(ax, "distance from the seaward face (m); mound slopes schematic", "elevation (m)", FS,
               "(a) cross-section to scale, waves from the left")


# -- (b, c) pressures ------------------------------------------------------------------------

def draw_pressure(ax: Axes, r: CaissonReport) -> None:
    p = r.analysis.pressures
    hp, hc = num(r, "base_depth"), num(r, "crest")
    p1, p3, p4 = float(p.p1) / 1e3, float(p.p3) / 1e3, float(p.p4) / 1e3
    eta = float(p.eta_star)
    hcs = min(eta, hc)
    zs = [-hp, 0.0, hcs]
    ps = [p3, p1, p4 if eta > hc else 0.0]
    ax.fill_betweenx(zs, [0.0] * 3, ps, color=_PRESSURE, alpha=0.55, lw=0)
    ax.plot(ps, zs, color="#1f4e99", lw=1.0)
    ax.plot([ps[0], 0.0], [-hp, -hp], color="#1f4e99", lw=1.0)
    if eta > hc:
        ax.plot([p4, 0.0], [hc, eta], color="#1f4e99", lw=0.8, dashes=(3, 2))
        ax.plot([p4, 0.0], [hc, hc], color="#1f4e99", lw=1.0)
    pmax = max(p1, p3) * 1.18
    top = max(eta, hc) + 0.08 * (hp + max(eta, hc))
    # the wall, at p = 0 (right edge; the waves come from the left)
    ax.plot([0.0, 0.0], [-hp, hc], color="0.1", lw=3.0, solid_capstyle="butt")
    ax.axhline(0.0, color="#1f5f99", lw=0.7, dashes=(5, 2))
    ax.text(pmax * 0.98, 0.15, "SWL", fontsize=FS - 1, color="#1f5f99", ha="left", va="bottom")
    box = {"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.75}
    lab: dict[str, Any] = {"fontsize": FS, "ha": "left", "bbox": box}
    ax.text(p1 - 0.04 * pmax, -0.3, f"p$_1$ = {significant(p1)} kPa", va="top", **lab)
    ax.text(p3 - 0.04 * pmax, -hp + 0.25, f"p$_3$ = {significant(p3)} kPa", va="bottom", **lab)
    if eta > hc:
        ax.text(p4 - 0.04 * pmax, hc - 0.25, f"p$_4$ = {significant(p4)} kPa", va="top", **lab)
    ax.text(0.03 * pmax, eta, f"\u03b7* = {significant(eta)} m", ha="right", va="bottom", fontsize=FS)
    ax.plot([0.0], [eta], marker="_", color="#1f4e99", markersize=8)
    ax.set_xlim(pmax, 0.0)
    ax.set_ylim(-hp - 0.08 * (hp + top), top)
    label_axes(ax, "pressure (kPa), on the seaward face", "elevation (m)", FS,
               "(b) Goda pressures on the wall")


def draw_uplift(ax: Axes, r: CaissonReport) -> None:
    p = r.analysis.pressures
    w = num(r, "width")
    pu = float(p.pu) / 1e3
    ax.fill([0.0, 0.0, w], [0.0, pu, 0.0], color=_UPLIFT, alpha=0.55, lw=0)
    ax.plot([0.0, 0.0, w], [0.0, pu, 0.0], color="#b0431c", lw=1.0)
    ax.plot([0.0, w], [0.0, 0.0], color="0.1", lw=3.0, solid_capstyle="butt")
    ax.text(0.03 * w, pu, f"p$_u$ = {significant(pu)} kPa", ha="left", va="top", fontsize=FS)
    u = float(r.analysis.loads.U) / 1e3
    ax.text(0.97 * w, 0.72 * pu, f"U = {significant(u)} kN/m", ha="right", va="center", fontsize=FS)
    ax.set_xlim(-0.05 * w, 1.05 * w)
    ax.set_ylim(1.3 * pu, -0.15 * pu)  # pressure downward: the triangle hangs under the base
    label_axes(ax, "from the seaward toe (m)", "uplift (kPa)", FS, "(c) uplift under the base")



# -- (e) the path: safety factors and modes --------------------------------------------------

def draw_path(ax: Axes, r: CaissonReport, required: tuple[float, float] = (1.2, 1.2)) -> None:
    p = r.path
    st = p.analysis.stability
    s = p.factors
    sfs, sfo = np.asarray(st.sliding), np.asarray(st.overturning)
    ymax = 3.0
    # the mode of each point on its own map, as a band along the bottom
    edges = np.concatenate([[s[0]], 0.5 * (s[1:] + s[:-1]), [s[-1]]])
    for i in range(s.size):
        stl = mode_style(int(p.modes[i]))
        ax.axvspan(edges[i], edges[i + 1], ymin=0.0, ymax=0.07, facecolor=stl.color, lw=0,
                   zorder=1)
    ax.plot(s, np.minimum(sfs, 10 * ymax), color="#1f4e99", lw=1.3, label="SF sliding")
    ax.plot(s, np.minimum(sfo, 10 * ymax), color="#b0431c", lw=1.3, dashes=(5, 2),
            label="SF overturning")
    for sf, name, color in ((sfs, "sliding", "#1f4e99"), (sfo, "overturning", "#b0431c")):
        _curve_label(ax, s, sf, name, color, ymax)
    ax.axhline(1.0, color="black", lw=0.7)
    levels = sorted(set(required))  # the safety factors the design must reach
    for j, need in enumerate(levels):
        ax.axhline(need, color="black", lw=0.6, dashes=(1, 1.5))
        # at the left end: clear of the curves, which fall from the top left; of two levels,
        # the lower one's label goes under its line, clear of the other's
        ax.text(float(s[0]), need, f" required {need:g}", fontsize=FS - 1.0, ha="left", color="0.2",
                va="top" if j == 0 and len(levels) > 1 else "bottom")
    ax.axvline(1.0, color="0.4", lw=0.6, dashes=(2, 2))
    ax.text(1.0, ymax * 0.97, " design", fontsize=FS - 0.5, va="top", ha="left", color="0.3")
    if p.onset is not None and p.onset > float(s[0]):
        ax.axvline(p.onset, color="#b0001c", lw=0.8)
        assert p.onset_mode is not None
        # beside its line, on the side with room for it (the label spans ~40 % of the axis)
        right = p.onset <= float(s[0]) + 0.6 * (float(s[-1]) - float(s[0]))
        words = f"{mode_label(p.onset_mode)} from {p.onset:.3f}\u00d7"
        ax.text(p.onset, 0.11 * ymax, f" {words}" if right else f"{words} ", fontsize=FS - 0.5,
                color="#b0001c", va="bottom", ha="left" if right else "right")
    ax.set_xlim(float(s[0]), float(s[-1]))
    ax.set_ylim(0.0, ymax)
    label_axes(ax, "wave-height factor s (H$_{1/3}$, H$_{max}$ \u00d7 s)", "safety factor", FS,
               "(e) as the wave grows")


def _curve_label(ax: Axes, s: np.ndarray, sf: np.ndarray, name: str, color: str, ymax: float
                 ) -> None:
    """Name a curve beside it, where it first comes down to 2/3 of the view (or its top)."""
    target = min(2.0 / 3.0 * ymax, float(np.max(sf)))
    i = int(np.argmax(sf <= target)) if np.any(sf <= target) else 0
    i = min(i, s.size - 1)
    ax.text(float(s[i]) + 0.02 * float(s[-1] - s[0]), float(sf[i]), name, color=color,
            fontsize=FS - 0.5, ha="left", va="bottom",
            bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})


# -- (f) the numbers --------------------------------------------------------------------------

def _margin_text(m: Margin) -> str:
    c = m.up if m.variable == "k" else m.down
    sign = "+" if m.variable == "k" else "\u2212"
    word = "more k" if m.variable == "k" else "less \u03bc"
    if c is None:
        return f"{word}: no change"
    rel = f"{sign}{100.0 * c.relative:.3g}%" if c.relative is not None else f"{sign}{c.delta:.3g}"
    return f"{word}: {rel} \u2192 {mode_label(c.to)}"


def _onset_text(r: CaissonReport) -> str:
    p = r.path
    if p.onset is None:
        return f"rests up to {float(p.factors[-1]):g}\u00d7 H"
    assert p.onset_mode is not None
    if p.onset <= float(p.factors[0]) and int(p.modes[0]) != 0:
        return f"moves ({mode_label(p.onset_mode)}) at {float(p.factors[0]):g}\u00d7 H"
    return f"{mode_label(p.onset_mode)} from {p.onset:.3f}\u00d7 H"


def draw_table(ax: Axes, r: CaissonReport, checks: Mapping[str, Check | None] | None = None) -> None:
    """(f) the numbers, four columns; a row named in ``checks`` (``"sliding"``, ``"overturning"``)
    whose check fails has its number in the fail colour, in bold."""
    checks = {} if checks is None else checks
    a = r.analysis
    h, p, ld, sec, st, b = a.heights, a.pressures, a.loads, a.section, a.stability, a.block
    f = float
    c1 = [
        ("design wave", "", ""),
        ("H\u2081/\u2083", significant(f(h.H13)), "m"), ("H$_{max}$", significant(f(h.Hmax)), "m"),
        ("T\u2081/\u2083", significant(num(r, "period"), 3), "s"),
        ("\u03b2", significant(f(p.beta), 3), "\u00b0"),
        ("L", significant(f(p.L)), "m"), ("\u03b7*", significant(f(p.eta_star)), "m"),
        ("\u03b1\u2081", significant(f(p.alpha1)), ""), ("\u03b1\u2082", significant(f(p.alpha2)), ""),
        ("\u03b1\u2083", significant(f(p.alpha3)), ""), ("\u03b1$_I$", significant(f(p.alpha_I)), ""),
    ]
    c2 = [
        ("pressures and loads", "", ""),
        ("p\u2081", significant(f(p.p1) / 1e3), "kPa"), ("p\u2083", significant(f(p.p3) / 1e3), "kPa"),
        ("p\u2084", significant(f(p.p4) / 1e3), "kPa"), ("p$_u$", significant(f(p.pu) / 1e3), "kPa"),
        ("P", significant(f(ld.P) / 1e3), "kN/m"), ("M$_P$", significant(f(ld.Mp) / 1e3), "kN\u00b7m/m"),
        ("U", significant(f(ld.U) / 1e3), "kN/m"), ("M$_U$", significant(f(ld.Mu) / 1e3), "kN\u00b7m/m"),
        ("W\u2032", significant(f(sec.buoyant_weight) / 1e3), "kN/m"),
    ]
    c3 = [
        ("safety factors", "", ""),
        ("sliding", significant(f(st.sliding)), ""), ("overturning", significant(f(st.overturning)), ""),
        ("heel pressure", significant(f(st.heel_pressure) / 1e3), "kPa"),
        ("loaded block", "", ""),
        ("B, H$_C$", f"{significant(f(b.B), 3)}, {significant(f(b.H), 3)}", "m"),
        ("\u03b3", significant(f(b.gamma)), ""),
        ("k, \u03bc", f"{significant(f(b.k))}, {significant(f(b.mu), 3)}", ""),
        ("k\u2032", significant(f(b.kprime), 3), ""),
        ("buoyancy", significant(f(b.buoyancy)), ""),
    ]
    c4 = [
        ("", "", ""),
        ("uplift ratio", significant(f(b.uplift_ratio)), ""),
        ("uplift arm", significant(f(b.uplift_arm)), ""),
        ("gyration", significant(f(b.gyration)), ""),
        ("on the loaded map", "", ""),
        ("mode", mode_label(r.mode), ""),
        ("", _margin_text(r.margin_k), ""), ("", _margin_text(r.margin_mu), ""),
        ("", _onset_text(r), ""),
    ]
    ax.set_axis_off()
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(0.0, 1.0)
    ax.set_title("(f) the numbers (per metre of breakwater)", fontsize=FS + 1, loc="left")
    cols = ((0.0, c1), (0.25, c2), (0.51, c3), (0.76, c4))
    dy = 1.0 / 11.5
    for x, rows in cols:
        for j, (name, value, unit) in enumerate(rows):
            y = 1.0 - (j + 0.6) * dy
            if value == "" and name:
                ax.text(x, y, name, fontsize=FS, fontweight="bold", va="center")
                continue
            if name == "" and value:
                ax.text(x, y, value, fontsize=FS, va="center", ha="left")
                continue
            ax.text(x, y, name, fontsize=FS, va="center")
            check = checks.get(name)
            bad = check is not None and not check.passed
            ax.text(x + 0.16, y, value, fontsize=FS, va="center", ha="right",
                    color=FAIL_COLOUR if bad else "black", fontweight="bold" if bad else "normal")
            ax.text(x + 0.167, y, unit, fontsize=FS - 0.5, va="center", ha="left", color="0.25")
