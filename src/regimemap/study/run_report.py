"""The report of ``regimemap study`` from its record: the table's lines and, with ``--check``, the
requirements, or the one JSON object with the rows, the requirements and the files written
(:mod:`regimemap.study.record_table` words each part)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .record import StudyCheck, StudyRecord

__all__ = ["study_report_json", "study_report_text"]


def study_report_text(record: StudyRecord, checks: Sequence[StudyCheck] | None, *, table: bool = True
                      ) -> str | None:
    """The report as text: the table (one line per section x scenario x width) when ``table``,
    then, when ``checks`` is not None (``--check``), ``requirements:`` and a line per requirement;
    None when there is neither."""
    from .record_table import study_check_lines, study_lines

    parts = ["\n".join(study_lines(record))] if table else []
    if checks is not None:
        parts += ["requirements:", "\n".join(f"  {line}" for line in study_check_lines(checks))]
    return "\n".join(parts) if parts else None


def study_report_json(record: StudyRecord, checks: Sequence[StudyCheck] | None,
                      written: Sequence[str] = ()) -> dict[str, Any]:
    """The JSON-ready report: :func:`regimemap.study.record_table.study_json`, with ``checks`` when
    they are given (``--check``) and ``written``, the files, when any."""
    from .record_table import study_checks_json, study_json

    data = study_json(record)
    if checks is not None:
        data["checks"] = study_checks_json(checks)
    if written:
        data["written"] = list(written)
    return data
