"""A caisson report for people (text) and for programs (JSON): SI engineering units.

Pressures in kPa, forces in kN/m, moments in kN m/m (per metre of
breakwater), lengths in m; the loaded block's numbers are dimensionless.
:func:`caisson_json` rounds every number to 12 significant digits.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from ..maps.loadedmap import Crossing, Margin, mode_description, mode_label
from ..records.checks import Check, checks_json, checks_lines
from ..records.numbers import format_significant, optional_float, rounded
from .report import REQUIRED_SF, CaissonReport, caisson_checks

__all__ = ["CONSISTENCY_NOTE", "NUMBERS", "REQUIRED_SF", "UNITS", "CaissonNumbers", "Number", "caisson_json",
           "caisson_numbers", "design_check", "design_check_lines", "format_caisson", "impulsive_words",
           "number", "number_rows", "text_context"]

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
    return {"at": float(c.at), "delta": float(c.delta),
            "relative": optional_float(c.relative), "to": mode_label(c.to)}


def _margin_dict(m: Margin) -> dict[str, Any]:
    n = m.nearest
    return {"value": float(m.value), "up": _crossing_dict(m.up), "down": _crossing_dict(m.down),
            "nearest": None if n is None else n.direction}


@dataclass(frozen=True)
class Number:
    """One number of the caisson report, declared once (a field of :class:`CaissonNumbers`).

    Attributes
    ----------
    path : str
        Where it is in the :class:`~regimemap.caisson.report.CaissonReport`, dotted.
    kilo : bool
        The report gives it in thousands of its SI unit (kPa, kN/m, kN m/m, t/m).
    unit : str
        Its unit in the JSON's ``units`` (``""``: dimensionless, not listed).
    label : str
        Its row's name in the text report and the notebook's table (``""``: no row).
    words : str
        What it is, in the row; it may name ``{depth}``, ``{arm}`` and ``{side}``
        (:func:`text_context`).
    digits : int
        Its significant digits in the row.
    heading : str
        The lines before its row (a section of the report), which may name the values of
        :func:`text_context`.
    undefined : str
        The row's words when the number is not finite (it then reads ``n/a``), saying why.
    """

    path: str
    kilo: bool = False
    unit: str = ""
    label: str = ""
    words: str = ""
    digits: int = 4
    heading: str = ""
    undefined: str = ""

    def value(self, r: CaissonReport) -> float:
        """The number in ``r``, in the report's unit (unrounded)."""
        x = _f(operator.attrgetter(self.path)(r))
        return x / 1e3 if self.kilo else x

    @property
    def text_unit(self) -> str:
        """Its unit as the text writes it (``kN m/m`` for JSON's ``kN*m/m``)."""
        return self.unit.replace("*", " ") if self.label else ""


def number(path: str, unit: str = "", label: str = "", words: str = "", *, kilo: bool = False,
           digits: int = 4, heading: str = "", undefined: str = "") -> Any:
    """A field of :class:`CaissonNumbers`, declared once (:class:`Number`)."""
    return field(metadata={"number": Number(path, kilo, unit, label, words, digits, heading, undefined)})


_A = "analysis."
_PRESSURES = ("pressures (Goda 1974, {impulsive})\n"
              "  alpha1 = {alpha1}   alpha2 = {alpha2}   alpha3 = {alpha3}   alpha_I = {alpha_I}"
              "   (alpha* = {which})")


@dataclass(frozen=True)
class CaissonNumbers:
    """The numbers of a caisson report in engineering units, as its text, JSON and table print them.

    Lengths in m, ``beta`` in degrees, pressures in kPa, forces in kN/m, moments in
    kN m/m, ``mass`` in t/m; the loaded block's numbers are dimensionless (docs/waves.md
    for the equations).  Each field is declared once with :func:`number`: where the
    report holds it, its unit, and its row in the text (:func:`format_caisson`) and the
    notebook's table; :func:`caisson_numbers`, :data:`UNITS` and the rows are read from
    these fields.
    """

    H13: float = number(_A + "heights.H13", "m", "H1/3", "significant height",
                        heading="design wave at the wall (Goda 2000)")
    Hmax: float = number(_A + "heights.Hmax", "m", "Hmax", "design (maximum) height")
    hb: float = number(_A + "heights.hb", "m")
    L: float = number(_A + "pressures.L", "m", "L", "wave length of T1/3 at h = {depth} m")
    beta: float = number(_A + "pressures.beta", "degree")
    eta_star: float = number(_A + "pressures.eta_star", "m", "eta*",
                             "elevation where the wave pressure vanishes")
    hc_star: float = number(_A + "pressures.hc_star", "m")
    alpha1: float = number(_A + "pressures.alpha1")
    alpha2: float = number(_A + "pressures.alpha2")
    alpha3: float = number(_A + "pressures.alpha3")
    alpha_I: float = number(_A + "pressures.alpha_I")
    alpha_star: float = number(_A + "pressures.alpha_star")
    p1: float = number(_A + "pressures.p1", "kPa", "p1", "at the still-water level", kilo=True,
                       heading=_PRESSURES)
    p2: float = number(_A + "pressures.p2", "kPa", kilo=True)
    p3: float = number(_A + "pressures.p3", "kPa", "p3", "at the base of the upright section", kilo=True)
    p4: float = number(_A + "pressures.p4", "kPa", "p4", "at the crest", kilo=True)
    pu: float = number(_A + "pressures.pu", "kPa", "pu", "uplift at the seaward toe", kilo=True)
    P: float = number(_A + "loads.P", "kN/m", "P", "horizontal wave force", kilo=True,
                      heading="loads per metre of breakwater")
    Mp: float = number(_A + "loads.Mp", "kN*m/m", "Mp", "its moment about the base", kilo=True)
    U: float = number(_A + "loads.U", "kN/m", "U", "uplift force", kilo=True)
    Mu: float = number(_A + "loads.Mu", "kN*m/m", "Mu", "its moment about the leeward heel", kilo=True)
    W: float = number(_A + "section.buoyant_weight", "kN/m", "W'", "buoyant weight (weight in still water)",
                      kilo=True)
    mass: float = number(_A + "section.mass", "t/m", kilo=True)
    SF_sliding: float = number(_A + "stability.sliding", "", "sliding", "mu (W' - U) / P",
                               heading="safety factors (Goda)")
    SF_overturning: float = number(_A + "stability.overturning", "", "overturning", "(W' t - Mu) / Mp, t = B")
    heel_pressure: float = number(_A + "stability.heel_pressure", "kPa", "heel pressure",
                                  "bearing pressure at the heel", kilo=True,
                                  undefined="no bearing at the heel: the resultant falls outside the base "
                                            "(Goda 2000, Sect. 4.2)")
    te: float = number(_A + "stability.te", "m")
    B: float = number(_A + "block.B", "m", "B", "half the width of the upright section",
                      heading="equivalent loaded block (docs/waves.md, Sect. 7)")
    H_C: float = number(_A + "block.H", "m", "H_C", "height of the centre of mass above the base")
    gamma: float = number(_A + "block.gamma", "", "gamma", "H_C / B")
    k: float = number(_A + "block.k", "", "k", "P / (m g), m g the dry weight", digits=6)
    kprime: float = number(_A + "block.kprime", "", "k'",
                           "(Mp/P - H_C)/H_C: P acts {arm} m {side} the centre of mass", digits=6)
    buoyancy: float = number(_A + "block.buoyancy", "", "buoyancy", "rho_w g V_submerged / (m g)", digits=6)
    uplift_ratio: float = number(_A + "block.uplift_ratio", "", "uplift ratio", "U / P", digits=6)
    uplift_arm: float = number(_A + "block.uplift_arm", "", "uplift arm",
                               "U acts this many B from C toward the seaward corner", digits=6)
    gyration: float = number(_A + "block.gyration", "", "gyration", "radius of gyration / B", digits=6)
    crest: float = number("map.crest")
    mu: float = number(_A + "block.mu", "", "mu", "friction coefficient", digits=6)

    @classmethod
    def of(cls, numbers: Mapping[str, float]) -> CaissonNumbers:
        """The fields of ``numbers`` (:func:`caisson_numbers`)."""
        return cls(**{f.name: numbers[f.name] for f in fields(cls)})


#: The declaration of each number, by name, in the report's order.
NUMBERS: dict[str, Number] = {f.name: f.metadata["number"] for f in fields(CaissonNumbers)}


def caisson_numbers(r: CaissonReport) -> dict[str, float]:
    """The report's numbers in engineering units (kPa, kN/m, kN m/m), unrounded."""
    return {name: spec.value(r) for name, spec in NUMBERS.items()}


#: Units of the numbers of :func:`caisson_json` (the others are dimensionless).
UNITS = {name: spec.unit for name, spec in NUMBERS.items() if spec.unit}


def text_context(r: CaissonReport, n: Mapping[str, float],
                 written: Mapping[str, str] | None = None) -> dict[str, str]:
    """The values the rows' words and headings name: the depth as written, where P acts, the
    choice of Goda's coefficients (the alphas, to 4 digits)."""
    depth = (written or {}).get("site.depth") or f"{float(r.inputs['depth']):g}"
    side = "above" if n["kprime"] > 0 else ("below" if n["kprime"] < 0 else "at")
    which = "alpha_I" if n["alpha_I"] > n["alpha2"] and n["alpha_star"] == n["alpha_I"] else "alpha2"
    return {"depth": depth, "arm": format_significant(abs(n["kprime"]) * n["H_C"], 3), "side": side,
            "which": which,
            "impulsive": impulsive_words(r),
            **{a: format_significant(n[a]) for a in ("alpha1", "alpha2", "alpha3", "alpha_I")}}


def number_rows(n: Mapping[str, float],
                context: Mapping[str, str]) -> list[tuple[str, float, str, str, int, str]]:
    """``(label, value, unit, words, digits, heading)`` of every number with a row, in order, its words and
    heading filled from ``context`` (:func:`text_context`)."""
    return [(s.label, n[name], s.text_unit,
             (s.undefined if s.undefined and not math.isfinite(n[name]) else s.words).format_map(context),
             s.digits, s.heading.format_map(context)) for name, s in NUMBERS.items() if s.label]


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
        out[name] = {"value": value, "required": need, "meets": bool(value >= need)}
    return rounded(out)


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
    out.update({k: float(v) for k, v in caisson_numbers(r).items()})
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
        "onset_factor": optional_float(p.onset),
        "onset_Hmax": None if p.onset is None else float(p.onset * hmax),
        "onset_mode": None if p.onset_mode is None else mode_label(p.onset_mode),
        "points": [{
            "factor": float(p.factors[i]), "Hmax": float(p.factors[i] * hmax), "k": float(p.k[i]),
            "kprime": float(p.kprime[i]), "uplift_ratio": float(p.uplift_ratio[i]),
            "SF_sliding": float(st.sliding[i]), "SF_overturning": float(st.overturning[i]),
            "mode": mode_label(p.modes[i]), "mode_on_design_map": mode_label(p.design_map_modes[i]),
        } for i in tenths],
    }
    out["units"] = dict(UNITS)
    if lifetime is not None:
        out["lifetime"] = dict(lifetime)
    out["design_check"] = design_check(r, required)
    out["checks"] = checks_json(checks)
    out["verdict"] = "PASS" if all(c.passed for c in checks) else "FAIL"
    return rounded(out)


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

    for label, value, unit, words, digits, heading in number_rows(n, text_context(r, n, written)):
        if heading:
            lines.extend(heading.split("\n"))
        lines.append(f"  {label:<14}{format_significant(value, digits):>10} {unit:<8} {words}")
    lines.append(f"mode on the loaded map: {mode_label(r.mode)} ({mode_description(r.mode)})")
    lines.append("  margin (smallest change that changes the mode, the other variable fixed):")
    lines.append(_margin_line(r.margin_k))
    lines.append(_margin_line(r.margin_mu))
    p = r.path
    lo, hi = float(p.factors[0]), float(p.factors[-1])
    lines.append(f"as the wave grows (H1/3 and Hmax times s = {lo:g} .. {hi:g}, loads recomputed, "
                 "each point on its own map):")
    def span(values: Any) -> str:
        return f"{format_significant(float(values[0]))} .. {format_significant(float(values[-1]))}"

    lines.append(f"  k' {span(p.kprime)},  uplift ratio {span(p.uplift_ratio)},  k {span(p.k)}")
    hmax = n["Hmax"]
    if p.onset is None:
        lines.append(f"  the caisson stays at rest up to s = {hi:g} "
                     f"(Hmax = {format_significant(hi * hmax)} m)")
    elif p.onset <= lo and p.modes[0] != 0:
        assert p.onset_mode is not None
        lines.append(f"  the caisson already moves at s = {lo:g}: {mode_label(p.onset_mode)} "
                     f"({mode_description(p.onset_mode)})")
    else:
        assert p.onset_mode is not None
        lines.append(f"  the caisson leaves rest at s = {p.onset:.4f} "
                     f"(Hmax = {format_significant(p.onset * hmax)} m): "
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
