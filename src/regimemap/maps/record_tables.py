"""Point-query results for people and spreadsheets: flat CSV rows, JSON and a text report."""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence

from ..io.csv import csv_line, csv_text
from ..io.json import json_text
from ..records.numbers import rounded, text
from .margins import Crossing
from .point_result import INITIATION_FIELDS, PointResult

__all__ = ["CSV_COLUMNS", "LOAD_COLUMNS", "columns_for", "format_result", "result_json", "result_row",
           "results_text"]

CSV_COLUMNS: tuple[str, ...] = (
    "name", "k", "mu", "gamma", "kprime", "case", "mode", "hypothesis",
    "fx", "fy", "xi", "xdd", "ydd", "thdd", "slip", "lift", "admissible",
    "margin_k", "margin_k_direction", "margin_k_at", "margin_k_to",
    "margin_mu", "margin_mu_direction", "margin_mu_at", "margin_mu_to",
)

#: Columns added to :data:`CSV_COLUMNS` when a result carries loads: the loads (the
#: names of the points file) and how the mode was chosen.
LOAD_COLUMNS: tuple[str, ...] = (
    "buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration", "crest", "chosen_by",
)


def columns_for(results: Sequence[PointResult]) -> tuple[str, ...]:
    """The CSV columns of ``results``: :data:`CSV_COLUMNS`, and :data:`LOAD_COLUMNS` if any carries loads."""
    return CSV_COLUMNS + (LOAD_COLUMNS if any(r.loads for r in results) else ())


def _fmt(v: float | None) -> str:
    if v is None or not math.isfinite(v):
        return ""
    return text(v)


def result_row(r: PointResult) -> dict[str, str]:
    """One flat CSV row (:data:`CSV_COLUMNS`) of a result; empty cells for None."""
    row = {
        "name": r.name, "k": _fmt(r.k), "mu": _fmt(r.mu), "gamma": _fmt(r.gamma),
        "kprime": _fmt(r.kprime), "case": r.case.value, "mode": r.mode.label,
        "hypothesis": r.hypothesis.name,
        "fx": _fmt(r.fx), "fy": _fmt(r.fy), "xi": _fmt(r.xi), "xdd": _fmt(r.xdd),
        "ydd": _fmt(r.ydd), "thdd": _fmt(r.thdd), "slip": _fmt(r.slip), "lift": _fmt(r.lift),
        "admissible": " ".join(m.label for m in r.admissible),
    }
    if r.loads:
        for key, v in r.loads.items():
            row[key] = "" if v is None else _fmt(v)
        row["chosen_by"] = r.chosen_by
    for m in (r.margin_k, r.margin_mu):
        n = m.nearest
        pre = f"margin_{m.variable}"
        row[pre] = "" if n is None else _fmt(n.relative)
        row[f"{pre}_direction"] = "" if n is None else n.direction
        row[f"{pre}_at"] = "" if n is None else _fmt(n.at)
        row[f"{pre}_to"] = "" if n is None else n.to.label
    return row


def result_json(r: PointResult) -> dict[str, object]:
    """:meth:`PointResult.as_dict` with its numbers rounded to 12 significant digits."""
    return rounded(r.as_dict())


def results_text(results: Sequence[PointResult], to_json: bool) -> str:
    """Classified points as one JSON object (``count``, ``points``) or as CSV (a header,
    :func:`columns_for`, and a row per point, :func:`result_row`)."""
    if to_json:
        return json_text({"count": len(results), "points": [result_json(r) for r in results]}) + "\n"
    columns = columns_for(results)
    return csv_text(columns, (csv_line([row.get(c, "") for c in columns])
                              for row in map(result_row, results)))


def _pct(c: Crossing) -> str:
    if c.on_boundary:
        return "0 (on the boundary)"
    if c.relative is None:
        return f"{c.delta:.4g} (absolute; the value is 0)"
    return f"{100.0 * c.relative:.3g}%"


def format_result(r: PointResult) -> str:
    """A plain-text report of one result, for people."""
    lines = [*_point_lines(r), *_initiation_lines(r), *_margin_lines(r)]
    adm = ", ".join(m.label for m in r.admissible) or "(none)"
    lines.append(f"admissible (solver): {adm}")
    for note in (_unsolvable_note(r), _choice_note(r)):
        if note:
            lines += textwrap.wrap(note, width=88, initial_indent="  ", subsequent_indent="  ")
    return "\n".join(lines)


def _point_lines(r: PointResult) -> list[str]:
    """The point and its block, the loads (or the report's case) and the mode."""
    p_side = "above" if r.kprime > 0 else ("below" if r.kprime < 0 else "at")
    title = f"point {r.name!r}: " if r.name else ""
    lines = [f"{title}k = {r.k:g}, mu = {r.mu:g}   (gamma = {r.gamma:g}, k' = {r.kprime:g}: "
             f"force {p_side} the centre of mass)"]
    if r.loads:
        from .describe import format_value

        shown = []
        for key, sym in (("buoyancy", "beta"), ("uplift", "u"), ("uplift_ratio", "nu"),
                         ("uplift_arm", "e_u"), ("gyration", "i"), ("crest", "crest")):
            v = r.loads.get(key)
            shown.append(f"{sym} = {'uniform' if v is None else format_value(v)}")
        lines.append(f"loads     {', '.join(shown)}")
    else:
        lines.append(f"case      {r.case.value}: {r.case.description}")
    lines.append(f"mode      {r.mode.label}  ({r.mode.description})")
    return lines


def _initiation_lines(r: PointResult) -> list[str]:
    """The reactions and accelerations at initiation (:data:`INITIATION_FIELDS`), slip and lift."""
    lines = [f"at initiation (solver, hypothesis {r.hypothesis.name}"
             + ("" if r.hypothesis_admissible or not r.solvable else ", NOT admissible")
             + "):"]
    for key, what in INITIATION_FIELDS:
        lines.append(f"  {key:<5} = {_val(getattr(r, key)):>11}   {what}")
    if r.slip is None and not r.solvable and r.hypothesis.sigma != 0:
        lines.append(f"  {'slip':<5} = {'n/a':>11}")
    elif r.slip is None and r.hypothesis.contact == "none":
        lines.append(f"  {'slip':<5} = {'none':>11}   no contact: the block leaves the base")
    elif r.slip is None:
        lines.append(f"  {'slip':<5} = {'none':>11}   the contact sticks")
    else:
        where = "base" if r.hypothesis.contact == "full" else f"corner {r.hypothesis.contact}"
        lines.append(f"  {'slip':<5} = {_val(r.slip):>11}   horizontal acceleration of the "
                     f"slipping {where} / g")
    if r.lift is not None:
        lines.append(f"  {'lift':<5} = {_val(r.lift):>11}   upward acceleration of the "
                     f"lifting corner / g")
    return lines


def _margin_lines(r: PointResult) -> list[str]:
    """The margins along k and along mu, down and up."""
    lines = ["margin    (smallest change that changes the mode, the other variable fixed)"]
    for m in (r.margin_k, r.margin_mu):
        parts = []
        for direction, c in (("down", m.down), ("up", m.up)):
            if c is None:
                if direction == "down" and m.value == 0.0:
                    parts.append("down: -- (already 0)")
                else:
                    parts.append(f"{direction}: no change")
                continue
            if c.on_boundary:
                parts.append(f"{c.direction}: 0 (on the boundary) -> {c.to.label}")
                continue
            sign = "-" if c.direction == "down" else "+"
            parts.append(f"{c.direction}: {sign}{_pct(c)} to {m.variable} = {c.at:.6g} -> "
                         f"{c.to.label}")
        lines.append(f"  {m.variable:<3} {';  '.join(parts)}")
    return lines


def _unsolvable_note(r: PointResult) -> str:
    """Why the physics is missing where the solver cannot solve ("" where it can)."""
    if r.solvable:
        return ""
    return ("the equations-of-motion solver reports this system as singular (at mu = mu_B', "
            "or a known limitation of its singularity test at large gamma or mu), so the "
            "physics and the admissible set are not available; the mode and the margin come "
            "from the closed-form map and stand")


def _choice_note(r: PointResult) -> str:
    """How the mode was chosen where several are admissible ("" where one is)."""
    if r.chosen_by == "Section 4.7":
        return (f"several modes satisfy the equations of motion here (non-uniqueness of rigid "
                f"contact with friction, below C and mu > mu_B' = {r.thresholds['mu_Bprime']:.4g}); "
                f"Section 4.7 of the report keeps {r.mode.label}")
    if r.chosen_by == "least constraint":
        return (f"several modes satisfy the equations of motion here; chosen by least "
                f"constraint (Gauss): {r.mode.label}, the motion closest to free fall "
                f"(a convention of rigid contact)")
    if r.chosen_by == "boundary":
        return (f"the point is on a boundary, where the modes of both sides are admissible; "
                f"the map gives it {r.mode.label}")
    return ""


def _val(v: float | None) -> str:
    if v is None or not math.isfinite(v):
        return "n/a"
    if v == 0.0 or abs(v) < 1e-13:
        return "0"
    return f"{v:.6g}"
