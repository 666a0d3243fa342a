"""The report of ``regimemap caisson`` from its record, as text or as one JSON object.

The text is :func:`regimemap.caisson.record.format_caisson`'s, the JSON object
:func:`regimemap.caisson.record.caisson_json`'s (the design sheet's path its first key), each
with the sliding over the design life when the design has a ``[lifetime]`` table
(:mod:`regimemap.lifetime.record`'s brief)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .run import CaissonRecord

__all__ = ["caisson_report_json", "caisson_report_text"]


def caisson_report_text(record: CaissonRecord, source: str) -> str:
    """The report for people of the design file ``source``, the sliding over the design life
    in a few lines (none without ``[lifetime]``)."""
    from ..lifetime.record import lifetime_brief_lines
    from .record import format_caisson

    run = record.lifetime_run
    life = [] if run is None else lifetime_brief_lines(run.result, run.model, run.band, run.wave_record)
    return format_caisson(record.report, source=source, required=record.required, checks=record.checks,
                          written=record.design.written, lifetime=life)


def caisson_report_json(record: CaissonRecord, source: str, sheet: str | None = None) -> dict[str, Any]:
    """The JSON-ready report of the design file ``source``, with ``sheet`` (the design sheet
    written) first and the sliding over the design life (None without ``[lifetime]``)."""
    from ..lifetime.record import lifetime_brief_json
    from .record import caisson_json

    run = record.lifetime_run
    life = None if run is None else lifetime_brief_json(run.result, run.model, run.band, run.wave_record)
    obj = caisson_json(record.report, source=source, required=record.required, checks=record.checks,
                       lifetime=life)
    return obj if sheet is None else {"sheet": sheet, **obj}
