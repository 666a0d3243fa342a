"""A study's record as tidy data: the CSV table and the JSON summary of ``regimemap study``.

One row per section x scenario x width (:class:`regimemap.study.record.StudyRow`),
in the record's order; numbers are written as Python's shortest repr (they read
back to the same bits), an absent value as an empty cell (CSV) or null (JSON).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..io.csv import csv_line, csv_text, write_csv
from ..records.numbers import rounded
from .record import COLUMNS, LIMITS

if TYPE_CHECKING:
    from collections.abc import Sequence

    from .record import StudyCheck, StudyRecord, StudyRow

__all__ = ["STUDY_COLUMNS", "study_check_lines", "study_checks_json", "study_csv_text", "study_json",
           "study_lines", "write_study_csv"]

#: The CSV table's columns (units: m, years; probabilities), from :data:`~regimemap.study.record.COLUMNS`.
STUDY_COLUMNS = tuple(name for column in COLUMNS for name in column.csv_columns)


def _cell(x: Any) -> str:
    if x is None:
        return ""
    if isinstance(x, float):
        return "" if math.isnan(x) else repr(x)
    return str(x)


def _json_number(x: Any) -> Any:
    return None if isinstance(x, float) and math.isnan(x) else x


def _row_cells(r: StudyRow) -> list[str]:
    cells = []
    for column in COLUMNS:
        v = column.of(r)
        if column.kind == "limits":
            cells += [_cell(dict(v).get(x)) for x in LIMITS]
        elif column.kind == "pair":
            cells += [_cell(None if v is None else v[k]) for k in (0, 1)]
        elif column.kind != "years":
            cells.append(_cell(v))
    return cells


def _row_json(r: StudyRow) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for column in COLUMNS:
        v = column.of(r)
        if column.kind == "limits":
            out[column.name] = {f"{x:g}": y for x, y in v}
        elif column.kind in ("pair", "years"):
            out[column.name] = None if v is None else list(v)
        else:
            out[column.name] = _json_number(v)
    return out


def study_csv_text(record: StudyRecord) -> str:
    """The table as CSV text (header :data:`STUDY_COLUMNS`, one line per row)."""
    return csv_text(STUDY_COLUMNS, (csv_line(_row_cells(r)) for r in record.rows))


def write_study_csv(path: str | Path, record: StudyRecord) -> None:
    """Write :func:`study_csv_text` to ``path`` atomically."""
    write_csv(path, STUDY_COLUMNS, (csv_line(_row_cells(r)) for r in record.rows))


def study_json(record: StudyRecord) -> dict[str, Any]:
    """The JSON summary: the study, its sections and scenarios, ``rows`` and ``notices``."""
    rows = [_row_json(r) for r in record.rows]
    return {"study": record.source, "study_hash": record.study_hash, "seed": record.seed,
            "trials": record.trials, "years": record.years,
            "sections": [{"name": n, "chainage": c} for n, c in record.sections],
            "scenarios": list(record.scenarios), "target": record.target, "rows": rows,
            "notices": [n.as_dict() for n in record.notices]}


def study_lines(record: StudyRecord) -> list[str]:
    """The table as text: one line per row, after a header naming the study."""
    out = [f"study: {record.source}", f"{len(record.sections)} sections x {len(record.scenarios)} scenarios, "
           f"{record.trials} lifetimes of {record.years} years per task, seed {record.seed}", ""]
    head = (f"{'section':<16} {'scenario':<20} {'width m':>8} {'ESD m':>10} {'+-':>8} {'P>0.1':>6} "
            f"{'P>0.3':>6} {'y>0.1':>5} {'y>0.3':>5}  band / width for target")
    out.append(head)
    for r in record.rows:
        p = dict(r.exceedance)
        y = dict(r.passes)
        extra = ""
        if r.band is not None:
            extra = f"band {r.band[0]:.3g}-{r.band[1]:.3g} m"
        if r.required_width is not None:
            extra += f"width for ESD target: {r.required_width:.2f} m"
            if r.required_width_interval is not None:
                extra += f" ({r.required_width_interval[0]:.2f}-{r.required_width_interval[1]:.2f})"
            if r.required_width_upper is not None:
                extra += f", {r.required_width_upper:.2f} m at the band's upper level"
        se = "-" if math.isnan(r.std_error) else f"{r.std_error:.2g}"  # one lifetime: no error
        out.append(f"{r.section[:16]:<16} {r.scenario[:20]:<20} {r.width:>8.2f} "
                   f"{r.expected_sliding:>10.4g} {se:>8} {p[0.1]:>6.3f} {p[0.3]:>6.3f} "
                   f"{_year(y[0.1]):>5} {_year(y[0.3]):>5}  {extra}".rstrip())
    return out


def _year(y: int | None) -> str:
    return "-" if y is None else str(y)


def _length(x: float) -> str:
    return f"{x:.4g} m" if math.isfinite(x) else "none"


def study_check_lines(checks: Sequence[StudyCheck]) -> list[str]:
    """One line per section x scenario, PASS or FAIL first (as ``regimemap lifetime``'s
    requirements, :func:`regimemap.records.checks.checks_lines`), then the overall verdict.

    Examples
    --------
    >>> from regimemap.study.record import StudyCheck
    >>> from regimemap.records.checks import Check
    >>> c = StudyCheck("trunk", "today", Check.at_most("expected sliding distance", 0.04, 0.1, "m"),
    ...                "the ESD of the design's climate at 15 m")
    >>> for line in study_check_lines([c]):
    ...     print(line)
    PASS  trunk / today: the ESD of the design's climate at 15 m: 0.04 m <= 0.1 m
    verdict: PASS (every requirement met)
    """
    lines = [f"{c.check.verdict}  {c.section} / {c.scenario}: {c.basis}: {_length(c.check.value)} "
             f"{c.check.relation} {_length(c.check.required)}" for c in checks]
    bad = sum(not c.passed for c in checks)
    lines.append("verdict: PASS (every requirement met)" if bad == 0
                 else f"verdict: FAIL ({bad} of {len(checks)} requirements not met)")
    return lines


def study_checks_json(checks: Sequence[StudyCheck]) -> list[dict[str, Any]]:
    """``[{"section", "scenario", "name", "basis", "value", "required", "relation", "unit", "pass"}]``
    (numbers to 12 digits; a value not found is null)."""
    rows = [{"section": c.section, "scenario": c.scenario, "name": c.check.name, "basis": c.basis,
             "value": float(c.check.value), "required": float(c.check.required),
             "relation": c.check.relation, "unit": c.check.unit, "pass": c.passed} for c in checks]
    return rounded(rows)
