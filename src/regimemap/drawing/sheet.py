"""The one-page design sheet of a caisson (A4 portrait).

Size: over 500 lines on purpose: one function per panel of one page, sharing its layout.

Panels: (a) the cross-section to scale (still-water level, mound and berm,
caisson, crest, the forces on the equivalent block); (b) Goda's pressure
diagram on the wall (``p1``, ``p3``, ``p4``, ``eta*``) and (c) the uplift
triangle (``pu``); (d) the loaded regime map of the design wave with the
design point and the path it follows as the wave grows (0.5 to 1.5 times the
design heights); (e) the safety factors along that path with the mode of
each point on its own map; (f) the numbers; and, when a lifetime simulation is
given, (g) the exceedance curve of the caisson's sliding over its design life
(:func:`regimemap.drawing.lifetime.draw_exceedance`), under (e).

Everything drawn is computed beforehand (:func:`regimemap.maps.caisson.caisson_report`
and :func:`regimemap.maps.caisson.map_view`); this module only draws.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import __version__
from ..maps.caisson import CaissonReport, MapView, map_view
from ..maps.describe import format_significant
from ..maps.loadedmap import LO, Margin, mode_description, mode_label
from ..mechanics.modes import Mode
from .save import DEFAULT_DPI
from .style import HATCH_LW, MODE_STYLE, ModeStyle, style_context, text_size

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..lifetime.results import LifetimeResult
    from .labelplacer import Placed

__all__ = ["SHEET_SIZE", "PANELS", "LIFETIME_PANEL", "sheet_figure"]

#: Size of the sheet in inches: A4 portrait.
SHEET_SIZE: tuple[float, float] = (8.27, 11.69)
#: The panels' axes, by label (``ax.get_label()``), in drawing order.
PANELS: tuple[str, ...] = ("section", "pressure", "uplift", "map", "path", "table")
#: The label of the lifetime panel (g), drawn after :data:`PANELS` when a lifetime is given.
LIFETIME_PANEL = "lifetime"

#: Fill of lift-off, when the map has it (not one of the report's modes).
LO_STYLE = ModeStyle("#BBBBBB", "oo")
_WATER = "#D6E9F5"
_MOUND = "#CDBFA6"
_ARMOUR = "#A8957A"
_CONCRETE = "#B9B9B9"
_PRESSURE = "#77AADD"
_UPLIFT = "#EE8866"
_FS = 7.5
_BLOCK_NOTE = (
    "The equivalent loaded block (docs/waves.md, Sect. 7): half width B, centre of mass C at H_C "
    "above the base, \u03b3 = H_C/B; m g is the dry weight W\u2032 + \u03c1w g V (V the submerged "
    "volume); the wave force P = k m g acts k\u2032H_C above C; the buoyancy \u03c1w g V acts up "
    "through C; the uplift U = (U/P) P acts up, (uplift arm) \u00d7 B from C toward the seaward "
    "corner (1/3 for Goda's triangle).  Goda's SF_sliding \u2265 1 and SF_overturning \u2265 1 "
    "hold exactly when the map says rest (RE).")


def _style(code: int) -> ModeStyle:
    if int(code) == LO:
        return LO_STYLE
    return MODE_STYLE.get(Mode(int(code)), LO_STYLE)


def _g(x: float, digits: int = 4) -> str:
    return format_significant(x, digits).replace("-", "\u2212")


def _num(r: CaissonReport, name: str) -> float:
    return float(np.asarray(r.inputs[name]))


# -- (a) the cross-section ------------------------------------------------------------------

def _dimension(ax: Axes, x: float, y0: float, y1: float, text: str, side: str = "left") -> None:
    ax.annotate("", (x, y0), (x, y1), arrowprops={"arrowstyle": "<->", "lw": 0.6, "color": "0.15",
                                                  "shrinkA": 0, "shrinkB": 0})
    ha = "right" if side == "left" else "left"
    dx = -0.25 if side == "left" else 0.25
    ax.text(x + dx, 0.5 * (y0 + y1), text, ha=ha, va="center", fontsize=_FS - 0.5, color="0.1")


def _hdimension(ax: Axes, y: float, x0: float, x1: float, text: str, below: bool = True) -> None:
    ax.annotate("", (x0, y), (x1, y), arrowprops={"arrowstyle": "<->", "lw": 0.6, "color": "0.15",
                                                  "shrinkA": 0, "shrinkB": 0})
    ax.text(0.5 * (x0 + x1), y + (-0.35 if below else 0.35), text, ha="center",
            va="top" if below else "bottom", fontsize=_FS - 0.5, color="0.1")


def _draw_section(ax: Axes, r: CaissonReport) -> None:
    from matplotlib.patches import Polygon, Rectangle

    h, d, hp = _num(r, "depth"), _num(r, "armour_depth"), _num(r, "base_depth")
    hc, bm, w = _num(r, "crest"), _num(r, "berm_width"), _num(r, "width")
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
    ax.text(sx + 0.9, 0.2, "SWL", fontsize=_FS - 0.5, color="#1f5f99", va="bottom")
    # forces on the equivalent block: C, W' down, P at Mp/P, U at its arm
    xc = 0.5 * w
    ax.plot([xc], [-hp + hcg], marker="o", markersize=4.5, markerfacecolor="white",
            markeredgecolor="black", zorder=7)
    ax.text(xc + 0.35, -hp + hcg + 0.25, "C", fontsize=_FS, zorder=7)
    arrow = {"arrowstyle": "-|>", "lw": 1.1, "color": "black", "shrinkA": 0, "shrinkB": 0,
             "mutation_scale": 8}
    scale = 0.45 * hp
    ax.annotate("", (xc, -hp + hcg - scale), (xc, -hp + hcg), arrowprops=arrow, zorder=7)
    ax.text(xc + 0.35, -hp + hcg - 0.75 * scale, "W\u2032", fontsize=_FS, zorder=7)
    zp = -hp + float(r.analysis.loads.Mp) / float(r.analysis.loads.P)
    ax.annotate("", (0.0, zp), (-0.3 * w, zp), arrowprops=dict(arrow, color="#1f4e99"), zorder=7)
    ax.text(-0.3 * w, zp + 0.3, "P", fontsize=_FS, color="#1f4e99", ha="left", va="bottom", zorder=7)
    xu = w - float(r.analysis.loads.Mu) / float(r.analysis.loads.U)
    ax.annotate("", (xu, -hp), (xu, -hp - 0.3 * hp), arrowprops=dict(arrow, color="#b0431c"), zorder=7)
    ax.text(xu + 0.35, -hp - 0.3 * hp, "U", fontsize=_FS, color="#b0431c", va="bottom", zorder=7,
            bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
    # dimensions
    _dimension(ax, w + 0.6 * berm_lee, -hp, 0.0, f"h\u2032 = {_g(hp, 3)} m", side="right")
    _dimension(ax, w + 0.6 * berm_lee, 0.0, hc, f"h$_c$ = {_g(hc, 3)} m", side="right")
    _dimension(ax, x0 + 0.6, -h, 0.0, f"h = {_g(h, 3)} m", side="right")
    _dimension(ax, -bm - 1.0, -d, 0.0, f"d = {_g(d, 3)} m")
    _hdimension(ax, hc + 0.1 * (h + hc), 0.0, w, f"2B = {_g(w, 3)} m", below=False)
    if bm > 0:
        _hdimension(ax, -d + 0.35, -bm, 0.0, f"B$_M$ = {_g(bm, 3)} m", below=False)
    ax.set_xlim(x0, x1)
    ax.set_ylim(-h - 0.06 * (h + hc), top)
    ax.set_aspect("equal", adjustable="box")
    ax.set_anchor("NW")
    ax.set_ylabel("elevation (m)", fontsize=_FS)
    ax.set_xlabel("distance from the seaward face (m); mound slopes schematic", fontsize=_FS)
    ax.tick_params(labelsize=_FS - 0.5)
    ax.set_title("(a) cross-section to scale, waves from the left", fontsize=_FS + 1, loc="left")


# -- (b, c) pressures ------------------------------------------------------------------------

def _draw_pressure(ax: Axes, r: CaissonReport) -> None:
    p = r.analysis.pressures
    hp, hc = _num(r, "base_depth"), _num(r, "crest")
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
    ax.text(pmax * 0.98, 0.15, "SWL", fontsize=_FS - 1, color="#1f5f99", ha="left", va="bottom")
    box = {"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.75}
    lab: dict[str, Any] = {"fontsize": _FS, "ha": "left", "bbox": box}
    ax.text(p1 - 0.04 * pmax, -0.3, f"p$_1$ = {_g(p1)} kPa", va="top", **lab)
    ax.text(p3 - 0.04 * pmax, -hp + 0.25, f"p$_3$ = {_g(p3)} kPa", va="bottom", **lab)
    if eta > hc:
        ax.text(p4 - 0.04 * pmax, hc - 0.25, f"p$_4$ = {_g(p4)} kPa", va="top", **lab)
    ax.text(0.03 * pmax, eta, f"\u03b7* = {_g(eta)} m", ha="right", va="bottom", fontsize=_FS)
    ax.plot([0.0], [eta], marker="_", color="#1f4e99", markersize=8)
    ax.set_xlim(pmax, 0.0)
    ax.set_ylim(-hp - 0.08 * (hp + top), top)
    ax.set_xlabel("pressure (kPa), on the seaward face", fontsize=_FS)
    ax.set_ylabel("elevation (m)", fontsize=_FS)
    ax.tick_params(labelsize=_FS - 0.5)
    ax.set_title("(b) Goda pressures on the wall", fontsize=_FS + 1, loc="left")


def _draw_uplift(ax: Axes, r: CaissonReport) -> None:
    p = r.analysis.pressures
    w = _num(r, "width")
    pu = float(p.pu) / 1e3
    ax.fill([0.0, 0.0, w], [0.0, pu, 0.0], color=_UPLIFT, alpha=0.55, lw=0)
    ax.plot([0.0, 0.0, w], [0.0, pu, 0.0], color="#b0431c", lw=1.0)
    ax.plot([0.0, w], [0.0, 0.0], color="0.1", lw=3.0, solid_capstyle="butt")
    ax.text(0.03 * w, pu, f"p$_u$ = {_g(pu)} kPa", ha="left", va="top", fontsize=_FS)
    u = float(r.analysis.loads.U) / 1e3
    ax.text(0.97 * w, 0.72 * pu, f"U = {_g(u)} kN/m", ha="right", va="center", fontsize=_FS)
    ax.set_xlim(-0.05 * w, 1.05 * w)
    ax.set_ylim(1.3 * pu, -0.15 * pu)  # pressure downward: the triangle hangs under the base
    ax.set_xlabel("from the seaward toe (m)", fontsize=_FS)
    ax.set_ylabel("uplift (kPa)", fontsize=_FS)
    ax.tick_params(labelsize=_FS - 0.5)
    ax.set_title("(c) uplift under the base", fontsize=_FS + 1, loc="left")


# -- (d) the loaded map and the path ---------------------------------------------------------

def _draw_map(ax: Axes, r: CaissonReport, view: MapView) -> list[int]:
    kk, mm = np.meshgrid(view.k_axis, view.mu_axis)
    codes = [int(c) for c in np.unique(view.grid)]
    for c in codes:
        st = _style(c)
        mask = (view.grid == c).astype(np.float64)
        cs = ax.contourf(kk, mm, mask, levels=[0.5, 1.5], colors=[st.color], hatches=[st.hatch],
                         zorder=1)
        cs.set_edgecolor(st.hatch_color)
        cs.set_linewidth(0.0)
        ax.contour(kk, mm, mask, levels=[0.5], colors="black", linewidths=0.9, zorder=2)
    for name, (k, mu) in sorted(view.points.items()):
        ax.plot([k], [mu], marker="o", markersize=2.5, color="black", zorder=3)
        ax.annotate(name, (k, mu), xytext=(3, 3), textcoords="offset points", fontsize=_FS,
                    zorder=3)
    p = r.path
    ax.plot(p.k, np.full(p.k.shape, r.mu), color="black", lw=0.9, zorder=4)
    tenth = [i for i, s in enumerate(p.factors) if abs(s * 10.0 - round(s * 10.0)) < 1e-9]
    for i in tenth:
        st = _style(int(p.modes[i]))
        ax.plot([p.k[i]], [r.mu], marker="s", markersize=5.0, markerfacecolor=st.color,
                markeredgecolor="black", markeredgewidth=0.7, zorder=5)
    ax.plot([r.k], [r.mu], marker="o", markersize=7.0, markerfacecolor="black",
            markeredgecolor="white", markeredgewidth=1.3, zorder=7)
    labels: list[tuple[str, float, dict[str, Any]]] = [
        ("design wave", r.k, {"bbox": {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.2",
                                       "lw": 0.5}})]
    if p.onset is not None and p.onset > float(p.factors[0]):
        ko = float(np.interp(p.onset, p.factors, p.k))
        ax.plot([ko], [r.mu], marker="x", markersize=7.0, color="#b0001c", markeredgewidth=1.6,
                zorder=8)
        labels.append((f"leaves rest at {p.onset:.3f}\u00d7", ko, {
            "color": "#b0001c",
            "bbox": {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "#b0001c", "lw": 0.5}}))
    for i in (tenth[0], tenth[-1]):
        labels.append((f"{p.factors[i]:g}\u00d7", float(p.k[i]), {
            "fontsize": _FS - 0.5,
            "bbox": {"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.85}}))
    _place_path_labels(ax, labels, r.mu, view)
    ax.set_xlim(0.0, view.k_max)
    ax.set_ylim(0.0, view.mu_max)
    ax.set_xlabel("k = P / (m g)", fontsize=_FS)
    ax.set_ylabel("\u03bc", fontsize=_FS + 1)
    ax.tick_params(labelsize=_FS - 0.5)
    m = r.map
    ax.set_title("(d) loaded regime map of the design wave", fontsize=_FS + 1, loc="left", pad=13)
    ax.text(0.0, 1.015, f"\u03b3 = {_g(m.gamma, 3)},  k\u2032 = {_g(m.kprime, 3)},  "
                 f"U/P = {_g(m.uplift_ratio, 3)},  uplift arm {_g(m.uplift_arm, 3)},  "
                 f"buoyancy {_g(m.buoyancy, 3)},  i = {_g(m.gyration or 0.0, 3)}",
                 fontsize=_FS - 0.5, ha="left", va="bottom", color="0.2", transform=ax.transAxes)
    return codes


def _place_path_labels(ax: Axes, labels: list[tuple[str, float, dict[str, Any]]], mu: float,
                       view: MapView) -> None:
    """Label points of the path (all at height ``mu``) without overlaps, inside the axes.

    Each label tries, in order: above (centred, left, right), below (the same),
    then further above and below; its size is estimated with
    :func:`~regimemap.drawing.style.text_size` from the axes' size in points.
    """
    bbox = ax.get_position()
    fig_w, fig_h = SHEET_SIZE
    w_pt, h_pt = bbox.width * fig_w * 72.0, bbox.height * fig_h * 72.0
    y0 = mu / view.mu_max * h_pt
    placed: list[tuple[float, float, float, float]] = []
    gap, dy = 4.0, 8.0
    for text, k, kw in labels:
        fs = float(kw.pop("fontsize", _FS))
        tw, th = text_size(text, fs)
        x = k / view.k_max * w_pt
        candidates = []
        for level in (1.0, 2.6):
            for sy in (1.0, -1.0):
                for sx in (0.0, -1.0, 1.0):
                    candidates.append((sx, sy * level))
        choice = candidates[0]
        for sx, sy in candidates:
            left = x - tw - gap if sx < 0 else (x + gap if sx > 0 else x - 0.5 * tw)
            bottom = y0 + dy * sy if sy > 0 else y0 + dy * sy - th
            box = (left, bottom, left + tw, bottom + th)
            inside = box[0] >= 0 and box[2] <= w_pt and box[1] >= 0 and box[3] <= h_pt
            clear = all(box[2] <= b[0] or box[0] >= b[2] or box[3] <= b[1] or box[1] >= b[3]
                        for b in placed)
            if inside and clear:
                choice = (sx, sy)
                placed.append(box)
                break
        sx, sy = choice
        ha = "right" if sx < 0 else ("left" if sx > 0 else "center")
        ax.annotate(text, (k, mu), xytext=(gap * sx, dy * sy), textcoords="offset points", ha=ha,
                    va="bottom" if sy > 0 else "top", fontsize=fs, zorder=8, **kw)


def _legend(ax: Axes, codes: list[int]) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles: list[Any] = []
    for c in codes:
        st = _style(c)
        h = Patch(facecolor=st.color, edgecolor="0.4", hatch=st.hatch, lw=0.4,
                  label=f"{mode_label(c)}  {mode_description(c)}")
        handles.append(h)
    handles.append(Line2D([], [], color="black", lw=0.9, marker="s", markersize=4.5,
                          markerfacecolor="white", markeredgecolor="black",
                          label="path, H \u00d7 0.5 \u2026 1.5: marker = mode on its own map"))
    leg = ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(-0.1, -0.14), ncol=2,
                    fontsize=_FS - 0.5, frameon=False, handlelength=2.2, borderaxespad=0.0)
    for patch in leg.get_patches():
        patch.set_hatch_linewidth(HATCH_LW)


# -- (e) the path: safety factors and modes --------------------------------------------------

def _draw_path(ax: Axes, r: CaissonReport, required: tuple[float, float] = (1.2, 1.2)) -> None:
    p = r.path
    st = p.analysis.stability
    s = p.factors
    sfs, sfo = np.asarray(st.sliding), np.asarray(st.overturning)
    ymax = 3.0
    # the mode of each point on its own map, as a band along the bottom
    edges = np.concatenate([[s[0]], 0.5 * (s[1:] + s[:-1]), [s[-1]]])
    for i in range(s.size):
        stl = _style(int(p.modes[i]))
        ax.axvspan(edges[i], edges[i + 1], ymin=0.0, ymax=0.07, facecolor=stl.color, lw=0,
                   zorder=1)
    ax.plot(s, np.minimum(sfs, 10 * ymax), color="#1f4e99", lw=1.3, label="SF sliding")
    ax.plot(s, np.minimum(sfo, 10 * ymax), color="#b0431c", lw=1.3, dashes=(5, 2),
            label="SF overturning")
    for sf, name, color in ((sfs, "sliding", "#1f4e99"), (sfo, "overturning", "#b0431c")):
        _curve_label(ax, s, sf, name, color, ymax)
    ax.axhline(1.0, color="black", lw=0.7)
    for need in sorted(set(required)):  # the safety factors the design must reach
        ax.axhline(need, color="black", lw=0.6, dashes=(1, 1.5))
        ax.text(float(s[0]), need, f" required {need:g}", fontsize=_FS - 1.0, va="bottom", ha="left",
                color="0.2")  # at the left end: clear of the curves, which fall from the top left
    ax.axvline(1.0, color="0.4", lw=0.6, dashes=(2, 2))
    ax.text(1.0, ymax * 0.97, " design", fontsize=_FS - 0.5, va="top", ha="left", color="0.3")
    if p.onset is not None and p.onset > float(s[0]):
        ax.axvline(p.onset, color="#b0001c", lw=0.8)
        assert p.onset_mode is not None
        ax.text(p.onset, 0.11 * ymax, f" {mode_label(p.onset_mode)} from {p.onset:.3f}\u00d7",
                fontsize=_FS - 0.5, color="#b0001c", va="bottom", ha="left")
    ax.set_xlim(float(s[0]), float(s[-1]))
    ax.set_ylim(0.0, ymax)
    ax.set_xlabel("wave-height factor s (H$_{1/3}$, H$_{max}$ \u00d7 s)", fontsize=_FS)
    ax.set_ylabel("safety factor", fontsize=_FS)
    ax.tick_params(labelsize=_FS - 0.5)
    ax.set_title("(e) as the wave grows", fontsize=_FS + 1, loc="left")


def _curve_label(ax: Axes, s: np.ndarray, sf: np.ndarray, name: str, color: str, ymax: float
                 ) -> None:
    """Name a curve beside it, where it first comes down to 2/3 of the view (or its top)."""
    target = min(2.0 / 3.0 * ymax, float(np.max(sf)))
    i = int(np.argmax(sf <= target)) if np.any(sf <= target) else 0
    i = min(i, s.size - 1)
    ax.text(float(s[i]) + 0.02 * float(s[-1] - s[0]), float(sf[i]), name, color=color,
            fontsize=_FS - 0.5, ha="left", va="bottom",
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


def _draw_table(ax: Axes, r: CaissonReport) -> None:
    a = r.analysis
    h, p, ld, sec, st, b = a.heights, a.pressures, a.loads, a.section, a.stability, a.block
    f = float
    c1 = [
        ("design wave", "", ""),
        ("H\u2081/\u2083", _g(f(h.H13)), "m"), ("H$_{max}$", _g(f(h.Hmax)), "m"),
        ("T\u2081/\u2083", _g(_num(r, "period"), 3), "s"), ("\u03b2", _g(f(p.beta), 3), "\u00b0"),
        ("L", _g(f(p.L)), "m"), ("\u03b7*", _g(f(p.eta_star)), "m"),
        ("\u03b1\u2081", _g(f(p.alpha1)), ""), ("\u03b1\u2082", _g(f(p.alpha2)), ""),
        ("\u03b1\u2083", _g(f(p.alpha3)), ""), ("\u03b1$_I$", _g(f(p.alpha_I)), ""),
    ]
    c2 = [
        ("pressures and loads", "", ""),
        ("p\u2081", _g(f(p.p1) / 1e3), "kPa"), ("p\u2083", _g(f(p.p3) / 1e3), "kPa"),
        ("p\u2084", _g(f(p.p4) / 1e3), "kPa"), ("p$_u$", _g(f(p.pu) / 1e3), "kPa"),
        ("P", _g(f(ld.P) / 1e3), "kN/m"), ("M$_P$", _g(f(ld.Mp) / 1e3), "kN\u00b7m/m"),
        ("U", _g(f(ld.U) / 1e3), "kN/m"), ("M$_U$", _g(f(ld.Mu) / 1e3), "kN\u00b7m/m"),
        ("W\u2032", _g(f(sec.buoyant_weight) / 1e3), "kN/m"),
    ]
    c3 = [
        ("safety factors", "", ""),
        ("sliding", _g(f(st.sliding)), ""), ("overturning", _g(f(st.overturning)), ""),
        ("heel pressure", _g(f(st.heel_pressure) / 1e3), "kPa"),
        ("loaded block", "", ""),
        ("B, H$_C$", f"{_g(f(b.B), 3)}, {_g(f(b.H), 3)}", "m"), ("\u03b3", _g(f(b.gamma)), ""),
        ("k, \u03bc", f"{_g(f(b.k))}, {_g(f(b.mu), 3)}", ""), ("k\u2032", _g(f(b.kprime), 3), ""),
        ("buoyancy", _g(f(b.beta_b)), ""),
    ]
    c4 = [
        ("", "", ""),
        ("uplift ratio", _g(f(b.nu)), ""), ("uplift arm", _g(f(b.e_u)), ""),
        ("gyration", _g(f(b.i)), ""),
        ("on the loaded map", "", ""),
        ("mode", mode_label(r.mode), ""),
        ("", _margin_text(r.margin_k), ""), ("", _margin_text(r.margin_mu), ""),
        ("", _onset_text(r), ""),
    ]
    ax.set_axis_off()
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(0.0, 1.0)
    ax.set_title("(f) the numbers (per metre of breakwater)", fontsize=_FS + 1, loc="left")
    cols = ((0.0, c1), (0.25, c2), (0.51, c3), (0.76, c4))
    dy = 1.0 / 11.5
    for x, rows in cols:
        for j, (name, value, unit) in enumerate(rows):
            y = 1.0 - (j + 0.6) * dy
            if value == "" and name:
                ax.text(x, y, name, fontsize=_FS, fontweight="bold", va="center")
                continue
            if name == "" and value:
                ax.text(x, y, value, fontsize=_FS, va="center", ha="left")
                continue
            ax.text(x, y, name, fontsize=_FS, va="center")
            ax.text(x + 0.16, y, value, fontsize=_FS, va="center", ha="right")
            ax.text(x + 0.167, y, unit, fontsize=_FS - 0.5, va="center", ha="left", color="0.25")


# -- (g) the lifetime ------------------------------------------------------------------------

def _path_note(r: CaissonReport, short: bool) -> str:
    """The note under (e) (``short``: under (g), in fewer words)."""
    p = r.path
    kp = f"{_g(float(p.kprime[0]), 3)} \u2026 {_g(float(p.kprime[-1]), 3)}"
    up = f"{_g(float(p.uplift_ratio[0]), 3)} \u2026 {_g(float(p.uplift_ratio[-1]), 3)}"
    if short:
        return (f"(d): the regions of the design wave; along the path k\u2032 ({kp}) and U/P ({up}) "
                "change: each marker and (e)'s band has the colour of the mode on its own map.  "
                "SF \u2265 1 (both) \u21d4 rest.  (g): ESD \u00b1 1 standard error (grey); "
                "tolerable ESD 0.1 m (Goda & Takagi 2000), 0.3 m (Shimosako & Takahashi 1999).")
    return (f"The regions are those of the design wave.  Along the path k\u2032 ({kp}) and U/P "
            f"({up}) change with the wave, so each marker (and the band along the bottom of (e)) "
            "has the colour of the mode on its own map.  SF \u2265 1 (both) \u21d4 rest on the map.")


def _lifetime_panels(fig: Figure, r: CaissonReport, lifetime: LifetimeResult,
                     rect: Callable[[float, float, float, float], tuple[float, float, float, float]]
                     ) -> tuple[Axes, Placed]:
    """(e) shorter, (g) the exceedance curve of the lifetime under it, and the note, shorter.

    Returns (g)'s axes and its labels, to place once the rest of the sheet is drawn.
    """
    from .lifetime import draw_exceedance

    ax_path = fig.add_axes(rect(5.55, 5.1, 2.35, 1.35), label="path")
    _draw_path(ax_path, r)
    ax_l = fig.add_axes(rect(5.55, 3.33, 2.35, 1.05), label=LIFETIME_PANEL)
    placed = draw_exceedance(ax_l, lifetime, storm=False, fontsize=_FS)
    ax_l.set_ylabel("$P(S > x)$", fontsize=_FS)
    ax_l.set_xlabel(f"$x$ (m); $S$ = sliding in {lifetime.years} years", fontsize=_FS)
    ax_l.tick_params(labelsize=_FS - 0.5)
    ax_l.set_title(f"(g) over the design life: {lifetime.trials} lifetimes", fontsize=_FS + 1,
                   loc="left")
    fig.text(5.4 / SHEET_SIZE[0], 2.86 / SHEET_SIZE[1],
             "\n".join(textwrap.wrap(_path_note(r, True), 54)), fontsize=_FS - 1.0, va="top",
             ha="left", color="0.15", linespacing=1.3)
    return ax_l, placed


def _place_lifetime_labels(fig: Figure, ax: Axes, placed: Placed) -> None:
    """Place the labels of (g) clear of every text of the sheet and of (g)'s lines."""
    from .labelplacer import LabelPlacer

    placer = LabelPlacer(fig)
    try:
        placer.avoid_lines_of(ax)
        for t, cands, texts in placed:
            placer.place(ax, t, cands, texts=texts)
    finally:
        placer.close()


# -- the sheet -----------------------------------------------------------------------------

def sheet_figure(report: CaissonReport, *, title: str | None = None, dpi: float = DEFAULT_DPI,
                 view: MapView | None = None, lifetime: LifetimeResult | None = None,
                 required: tuple[float, float] = (1.2, 1.2)) -> Figure:
    """The one-page design sheet of a caisson (A4 portrait, no pyplot).

    Parameters
    ----------
    report : CaissonReport
        From :func:`regimemap.maps.caisson.caisson_report`.
    title : str, optional
        Shown after "caisson design sheet" (e.g. the design file's name).
    dpi : float
        Resolution of PNG output.
    view : MapView, optional
        The map's view and grid (default :func:`regimemap.maps.caisson.map_view`).
    lifetime : LifetimeResult, optional
        The caisson's sliding over its design life
        (:func:`regimemap.lifetime.lifetime_sliding`): adds panel (g), its exceedance
        curve with the ESD and the tolerable limits, under (e) (which gets shorter, and its
        note too).
    required : tuple of float, optional
        The safety factors the design must reach (sliding, overturning; 1.2 and 1.2 by
        default, the design file's ``[caisson] required_*``), drawn in (e) beside SF = 1.

    Returns
    -------
    Figure
        Axes labelled as :data:`PANELS`, then :data:`LIFETIME_PANEL` when ``lifetime`` is given.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    view = map_view(report) if view is None else view
    W, H = SHEET_SIZE

    def rect(x: float, y: float, w: float, h: float) -> tuple[float, float, float, float]:
        return (x / W, y / H, w / W, h / H)

    with style_context():
        fig = Figure(figsize=SHEET_SIZE, dpi=dpi)
        FigureCanvasAgg(fig)
        head = "caisson design sheet" + (f": {title}" if title else "")
        fig.text(0.6 / W, 1.0 - 0.38 / H, head, fontsize=13, fontweight="bold", va="top")
        a = report.analysis
        inp = report.inputs
        wave = (f"H\u2080\u2032 = {_num(report, 'H0'):g} m" if inp.get("H0") is not None
                else "H\u2081/\u2083, H$_{max}$ given at the wall")
        fig.text(0.6 / W, 1.0 - 0.68 / H,
                 f"{wave}, T\u2081/\u2083 = {_num(report, 'period'):g} s, "
                 f"\u03b2 = {float(a.pressures.beta):g}\u00b0, "
                 f"tan \u03b8 = {_num(report, 'slope'):g}, \u03bc = {report.mu:g}, "
                 f"W\u2032 = {_g(float(a.section.buoyant_weight) / 1e3)} kN/m.\n"
                 "Goda (2000) with Takahashi's \u03b1$_I$"
                 + ("" if inp.get("impulsive", True) else " (off)")
                 + f"; regimemap {__version__}",
                 fontsize=_FS + 0.5, va="top", color="0.2", linespacing=1.4)

        ax_sec = fig.add_axes(rect(0.75, 8.55, 4.6, 1.85), label="section")
        _draw_section(ax_sec, report)
        fig.text(0.6 / W, 7.95 / H, "\n".join(textwrap.wrap(_BLOCK_NOTE, 86)), fontsize=_FS - 0.5,
                 va="top", ha="left", color="0.15", linespacing=1.35)
        ax_p = fig.add_axes(rect(5.95, 8.75, 1.95, 1.65), label="pressure")
        _draw_pressure(ax_p, report)
        ax_u = fig.add_axes(rect(5.95, 7.35, 1.95, 0.72), label="uplift")
        _draw_uplift(ax_u, report)

        ax_map = fig.add_axes(rect(0.75, 3.4, 4.1, 3.05), label="map")
        codes = _draw_map(ax_map, report, view)
        _legend(ax_map, codes)
        lifetime_labels = None
        if lifetime is None:
            ax_path = fig.add_axes(rect(5.55, 4.5, 2.35, 1.95), label="path")
            _draw_path(ax_path, report, required)
            fig.text(5.4 / W, 3.95 / H, "\n".join(textwrap.wrap(_path_note(report, False), 47)),
                     fontsize=_FS - 0.5, va="top", ha="left", color="0.15", linespacing=1.35)
        else:
            lifetime_labels = _lifetime_panels(fig, report, lifetime, rect)

        ax_t = fig.add_axes(rect(0.6, 0.3, 7.2, 1.95), label="table")
        _draw_table(ax_t, report)
        if lifetime_labels is not None:  # once every other text is on the sheet
            _place_lifetime_labels(fig, *lifetime_labels)
    return fig
