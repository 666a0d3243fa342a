"""A caisson report for people (text) and for programs (JSON): SI engineering units.

Pressures in kPa, forces in kN/m, moments in kN m/m (per metre of
breakwater), lengths in m; the loaded block's numbers are dimensionless.
:func:`caisson_json` rounds every number to 12 significant digits.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..io.checks import checks_json, checks_lines
from ..io.numbers import json_number as round_sig
from ..maps.describe import format_significant as _sig
from ..maps.loadedmap import Crossing, Margin, mode_description, mode_label
from ..mechanics.checks import Check
from .report import REQUIRED_SF, CaissonReport, caisson_checks

__all__ = ["CONSISTENCY_NOTE", "REQUIRED_SF", "UNITS", "caisson_json", "caisson_numbers", "design_check",
           "design_check_lines", "format_caisson", "impulsive_words", "round_sig"]

#: Why Goda's safety factors and the map agree (docs/waves.md, Sect. 7).
CONSISTENCY_NOTE = (
    "Goda's SF_sliding >= 1 and SF_overturning >= 1 (both) <=> rest (RE) on the loaded map: "
    "with t = B, SF_s = mu (1 - beta - nu k)/k and SF_o = ((1 - beta) - nu k (1 + e_u))/"
    "(k (1 + k') gamma), exactly the map's conditions of rest (docs/waves.md, Sect. 7)")


def _f(x: Any) -> float:
    return float(np.asarray(x))


def _crossing_dict(c: Crossing | None) -> dict[str, Any] | None:
    if c is None:
        return None
    return {"at": round_sig(c.at), "delta": round_sig(c.delta),
            "relative": None if c.relative is None else round_sig(c.relative),
            "to": mode_label(c.to)}


def _margin_dict(m: Margin) -> dict[str, Any]:
    n = m.nearest
    return {"value": round_sig(m.value), "up": _crossing_dict(m.up), "down": _crossing_dict(m.down),
            "nearest": None if n is None else n.direction}


def caisson_numbers(r: CaissonReport) -> dict[str, float]:
    """The report's numbers in engineering units (kPa, kN/m, kN m/m), unrounded."""
    a = r.analysis
    h, p, ld, sec, st, b = a.heights, a.pressures, a.loads, a.section, a.stability, a.block
    return {
        "H13": _f(h.H13), "Hmax": _f(h.Hmax), "hb": _f(h.hb), "L": _f(p.L),
        "beta": _f(p.beta), "eta_star": _f(p.eta_star), "hc_star": _f(p.hc_star),
        "alpha1": _f(p.alpha1), "alpha2": _f(p.alpha2), "alpha3": _f(p.alpha3),
        "alpha_I": _f(p.alpha_I), "alpha_star": _f(p.alpha_star),
        "p1": _f(p.p1) / 1e3, "p2": _f(p.p2) / 1e3, "p3": _f(p.p3) / 1e3, "p4": _f(p.p4) / 1e3,
        "pu": _f(p.pu) / 1e3,
        "P": _f(ld.P) / 1e3, "Mp": _f(ld.Mp) / 1e3, "U": _f(ld.U) / 1e3, "Mu": _f(ld.Mu) / 1e3,
        "W": _f(sec.buoyant_weight) / 1e3, "mass": _f(sec.mass) / 1e3,
        "SF_sliding": _f(st.sliding), "SF_overturning": _f(st.overturning),
        "heel_pressure": _f(st.heel_pressure) / 1e3, "te": _f(st.te),
        "B": _f(b.B), "H_C": _f(b.H), "gamma": _f(b.gamma), "k": _f(b.k), "kprime": _f(b.kprime),
        "buoyancy": _f(b.beta_b), "uplift_ratio": _f(b.nu), "uplift_arm": _f(b.e_u),
        "gyration": _f(b.i), "crest": r.map.crest, "mu": _f(b.mu),
    }


#: Units of the numbers of :func:`caisson_json` (the others are dimensionless).
UNITS = {
    "H13": "m", "Hmax": "m", "hb": "m", "L": "m", "beta": "degree", "eta_star": "m",
    "hc_star": "m", "p1": "kPa", "p2": "kPa", "p3": "kPa", "p4": "kPa", "pu": "kPa",
    "P": "kN/m", "Mp": "kN*m/m", "U": "kN/m", "Mu": "kN*m/m", "W": "kN/m", "mass": "t/m",
    "heel_pressure": "kPa", "te": "m", "B": "m", "H_C": "m",
}


def impulsive_words(r: CaissonReport) -> str:
    """Whether Goda's pressures include Takahashi's impulsive coefficient, in words (the setting named)."""
    if r.inputs.get("impulsive", True):
        return "with Takahashi's impulsive coefficient alpha_I ([caisson] impulsive = true, the default)"
    return "without Takahashi's impulsive coefficient ([caisson] impulsive = false)"


def design_check(r: CaissonReport, required: tuple[float, float] = REQUIRED_SF) -> dict[str, Any]:
    """The safety factors against the required ones: ``{"sliding": {...}, "overturning": {...}}``.

    Each entry holds ``value``, ``required`` and ``meets`` (``value >= required``).
    """
    st = r.analysis.stability
    out: dict[str, Any] = {}
    for name, value, need in (("sliding", _f(st.sliding), required[0]),
                              ("overturning", _f(st.overturning), required[1])):
        out[name] = {"value": round_sig(value), "required": need, "meets": bool(value >= need)}
    return out


def design_check_lines(r: CaissonReport, required: tuple[float, float] = REQUIRED_SF,
                       checks: Sequence[Check] | None = None) -> list[str]:
    """The design check: a heading, one line per requirement (PASS or FAIL first) and, last, the verdict.

    ``checks`` defaults to :func:`~regimemap.caisson.report.caisson_checks` (the safety
    factors against ``required``); a failed safety factor that is still at least 1 gets a
    note (the caisson rests under the design wave, without the margin asked for).
    """
    checks = caisson_checks(r, required) if checks is None else checks
    *each, verdict = checks_lines(checks)
    lines = ["design check (--check: exit status 1 when a requirement fails)", *each]
    short = [c.name for c in checks if not c.passed and c.name.endswith("safety factor")
             and c.value >= 1.0]
    if short:
        lines.append(f"  ({' and '.join(short)} >= 1: the caisson stays at rest under the design wave, "
                     "but without the margin the design asks for)")
    return [*lines, verdict]


def caisson_json(r: CaissonReport, source: str | None = None,
                 required: tuple[float, float] = REQUIRED_SF,
                 checks: Sequence[Check] | None = None,
                 lifetime: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """One JSON-ready object: heights, pressures, loads, safety factors, block, mode, margins, path.

    ``checks`` lists the requirements, ``[{"name", "value", "required",
    "relation", "unit", "pass"}, ...]`` (default
    :func:`~regimemap.caisson.report.caisson_checks` of ``required``: the safety
    factors against the required ones, sliding and overturning, 1.2 by
    default) and ``verdict`` says ``"PASS"`` or ``"FAIL"``; ``design_check``
    keeps the older form of the safety factors' check.  ``impulsive`` says
    whether Goda's pressures include Takahashi's impulsive coefficient.
    ``lifetime`` (given a ``[lifetime]`` table,
    :func:`regimemap.lifetime.record.lifetime_brief_json`) is the sliding over the
    design life -- its wave record and climate band when it has one.  The object
    ends with ``design_check``, ``checks`` and ``verdict``.

    Numbers are rounded to 12 significant digits (``null`` if not finite);
    ``units`` names the unit of each dimensional key.
    """
    out: dict[str, Any] = {}
    if source is not None:
        out["source"] = source
    out.update({k: round_sig(v) for k, v in caisson_numbers(r).items()})
    out["mode"] = mode_label(r.mode)
    out["mode_description"] = mode_description(r.mode)
    out["margin"] = {"k": _margin_dict(r.margin_k), "mu": _margin_dict(r.margin_mu)}
    out["at_rest_by_goda"] = r.safe_by_goda
    out["impulsive"] = bool(r.inputs.get("impulsive", True))
    checks = caisson_checks(r, required) if checks is None else checks
    out["consistent"] = r.consistent
    p = r.path
    hmax = _f(r.analysis.heights.Hmax)
    tenths = [i for i, s in enumerate(p.factors) if abs(s * 10.0 - round(s * 10.0)) < 1e-9]
    st = p.analysis.stability
    out["path"] = {
        "scaling": "H13 and Hmax times factor; loads recomputed; each point on its own map",
        "onset_factor": None if p.onset is None else round_sig(p.onset),
        "onset_Hmax": None if p.onset is None else round_sig(p.onset * hmax),
        "onset_mode": None if p.onset_mode is None else mode_label(p.onset_mode),
        "points": [{
            "factor": round_sig(p.factors[i]), "Hmax": round_sig(p.factors[i] * hmax),
            "k": round_sig(p.k[i]), "kprime": round_sig(p.kprime[i]),
            "uplift_ratio": round_sig(p.uplift_ratio[i]),
            "SF_sliding": round_sig(st.sliding[i]), "SF_overturning": round_sig(st.overturning[i]),
            "mode": mode_label(p.modes[i]), "mode_on_design_map": mode_label(p.design_map_modes[i]),
        } for i in tenths],
    }
    out["units"] = dict(UNITS)
    if lifetime is not None:
        out["lifetime"] = dict(lifetime)
    out["design_check"] = design_check(r, required)
    out["checks"] = checks_json(checks)
    out["verdict"] = "PASS" if all(c.passed for c in checks) else "FAIL"
    return out


def _margin_line(m: Margin) -> str:
    parts = []
    order = (("up", m.up), ("down", m.down)) if m.variable == "k" else (("down", m.down), ("up", m.up))
    for direction, c in order:
        if c is None:
            parts.append(f"{direction}: " + ("-- (already 0)" if direction == "down" and m.value == 0.0
                                             else "no change"))
            continue
        sign = "+" if direction == "up" else "-"
        rel = (f"{sign}{100.0 * c.relative:.3g}%" if c.relative is not None
               else f"{sign}{c.delta:.4g}")
        parts.append(f"{direction}: {rel} to {m.variable} = {c.at:.6g} -> {mode_label(c.to)}")
    return f"    {m.variable:<3} " + ";  ".join(parts)


def _inputs_lines(written: Mapping[str, str]) -> list[str]:
    """The file's values, table by table, as the file writes them (``written``: ``"site.depth"`` ->
    ``"10.1"``)."""
    lines = []
    for table in ("site", "wave", "caisson"):
        items = [f"{k.split('.', 1)[1]} = {v}" for k, v in written.items() if k.split(".", 1)[0] == table]
        if items:
            lines.append(f"  [{table}] " + ", ".join(items))
    return lines


def format_caisson(r: CaissonReport, source: str | None = None,
                   required: tuple[float, float] = REQUIRED_SF, checks: Sequence[Check] | None = None,
                   written: Mapping[str, str] | None = None, lifetime: Sequence[str] = ()) -> str:
    """The report for people: heights, pressures, loads, safety factors, block, mode and margins,
    then the sliding over the design life and, last, the design check and its verdict.

    ``checks``: the requirements of the design check (default
    :func:`~regimemap.caisson.report.caisson_checks` of ``required``); ``written``:
    the design file's values as it writes them (``{"site.depth": "10.1"}``,
    :attr:`regimemap.caisson.file.Design.written`), echoed under the file's name;
    ``lifetime``: the lines of the sliding over the design life
    (:func:`regimemap.lifetime.record.lifetime_brief_lines`), before the design check.
    """
    n = caisson_numbers(r)
    lines: list[str] = []
    if source:
        lines.append(f"caisson design: {source}")
    if written:
        lines.extend(_inputs_lines(written))

    def row(name: str, value: float, unit: str, what: str, digits: int = 4) -> None:
        lines.append(f"  {name:<14}{_sig(value, digits):>10} {unit:<8} {what}")

    lines.append("design wave at the wall (Goda 2000)")
    row("H1/3", n["H13"], "m", "significant height")
    row("Hmax", n["Hmax"], "m", "design (maximum) height")
    depth = (written or {}).get("site.depth") or f"{float(r.inputs['depth']):g}"
    row("L", n["L"], "m", f"wave length of T1/3 at h = {depth} m")
    row("eta*", n["eta_star"], "m", "elevation where the wave pressure vanishes")
    lines.append(f"pressures (Goda 1974, {impulsive_words(r)})")
    which = "alpha_I" if n["alpha_I"] > n["alpha2"] and n["alpha_star"] == n["alpha_I"] else "alpha2"
    lines.append(f"  alpha1 = {_sig(n['alpha1'])}   alpha2 = {_sig(n['alpha2'])}   "
                 f"alpha3 = {_sig(n['alpha3'])}   alpha_I = {_sig(n['alpha_I'])}   (alpha* = {which})")
    row("p1", n["p1"], "kPa", "at the still-water level")
    row("p3", n["p3"], "kPa", "at the base of the upright section")
    row("p4", n["p4"], "kPa", "at the crest")
    row("pu", n["pu"], "kPa", "uplift at the seaward toe")
    lines.append("loads per metre of breakwater")
    row("P", n["P"], "kN/m", "horizontal wave force")
    row("Mp", n["Mp"], "kN m/m", "its moment about the base")
    row("U", n["U"], "kN/m", "uplift force")
    row("Mu", n["Mu"], "kN m/m", "its moment about the leeward heel")
    row("W'", n["W"], "kN/m", "buoyant weight (weight in still water)")
    lines.append("safety factors (Goda)")
    row("sliding", n["SF_sliding"], "", "mu (W' - U) / P")
    row("overturning", n["SF_overturning"], "", "(W' t - Mu) / Mp, t = B")
    row("heel pressure", n["heel_pressure"], "kPa", "bearing pressure at the heel")
    lines.append("equivalent loaded block (docs/waves.md, Sect. 7)")
    row("B", n["B"], "m", "half the width of the upright section")
    row("H_C", n["H_C"], "m", "height of the centre of mass above the base")
    row("gamma", n["gamma"], "", "H_C / B")
    row("k", n["k"], "", "P / (m g), m g the dry weight", 6)
    side = "above" if n["kprime"] > 0 else ("below" if n["kprime"] < 0 else "at")
    row("k'", n["kprime"], "", f"(Mp/P - H_C)/H_C: P acts {_sig(abs(n['kprime']) * n['H_C'], 3)} m "
        f"{side} the centre of mass", 6)
    row("buoyancy", n["buoyancy"], "", "rho_w g V_submerged / (m g)", 6)
    row("uplift ratio", n["uplift_ratio"], "", "U / P", 6)
    row("uplift arm", n["uplift_arm"], "", "U acts this many B from C toward the seaward corner", 6)
    row("gyration", n["gyration"], "", "radius of gyration / B", 6)
    row("mu", n["mu"], "", "friction coefficient", 6)
    lines.append(f"mode on the loaded map: {mode_label(r.mode)} ({mode_description(r.mode)})")
    lines.append("  margin (smallest change that changes the mode, the other variable fixed):")
    lines.append(_margin_line(r.margin_k))
    lines.append(_margin_line(r.margin_mu))
    p = r.path
    lo, hi = float(p.factors[0]), float(p.factors[-1])
    lines.append(f"as the wave grows (H1/3 and Hmax times s = {lo:g} .. {hi:g}, loads recomputed, "
                 "each point on its own map):")
    lines.append(f"  k' {_sig(float(p.kprime[0]))} .. {_sig(float(p.kprime[-1]))},  uplift ratio "
                 f"{_sig(float(p.uplift_ratio[0]))} .. {_sig(float(p.uplift_ratio[-1]))},  "
                 f"k {_sig(float(p.k[0]))} .. {_sig(float(p.k[-1]))}")
    hmax = n["Hmax"]
    if p.onset is None:
        lines.append(f"  the caisson stays at rest up to s = {hi:g} (Hmax = {_sig(hi * hmax)} m)")
    elif p.onset <= lo and p.modes[0] != 0:
        assert p.onset_mode is not None
        lines.append(f"  the caisson already moves at s = {lo:g}: {mode_label(p.onset_mode)} "
                     f"({mode_description(p.onset_mode)})")
    else:
        assert p.onset_mode is not None
        lines.append(f"  the caisson leaves rest at s = {p.onset:.4f} (Hmax = {_sig(p.onset * hmax)} m): "
                     f"{mode_label(p.onset_mode)} ({mode_description(p.onset_mode)})")
    verdict = "both SF >= 1" if r.safe_by_goda else "an SF < 1"
    agree = "consistent" if r.consistent else "INCONSISTENT (please report it)"
    lines.append("consistency with Goda (docs/waves.md, Sect. 7):")
    lines.append("  SF_sliding >= 1 and SF_overturning >= 1  <=>  rest (RE) on the loaded map, since (t = B)")
    lines.append("    SF_sliding     = mu (1 - buoyancy - nu k) / k")
    lines.append("    SF_overturning = ((1 - buoyancy) - nu k (1 + e_u)) / (k (1 + k') gamma)")
    lines.append(f"  (nu = uplift ratio, e_u = uplift arm); here {verdict} and the mode is "
                 f"{mode_label(r.mode)}: {agree}")
    lines.extend(lifetime)
    lines.extend(design_check_lines(r, required, checks))
    return "\n".join(lines)
