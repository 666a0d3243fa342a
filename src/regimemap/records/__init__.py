"""What every product's record is made of: warnings and verdicts as data, fields, numbers for people.

A product's run returns a record (:mod:`regimemap.workflows`): its inputs, the quantities a
designer checks, its warnings (:class:`~regimemap.records.notices.Notice`), its requirements
and their verdicts (:class:`~regimemap.records.checks.Check`, written as text lines and JSON
here), and its field table for a notebook (:class:`~regimemap.records.fields.Record`, with
:mod:`~regimemap.records.htmltable`).  Every number a person reads is written by
:mod:`~regimemap.records.numbers`.  The standard library and numpy only, below every other
layer, so that each layer may make a record, and beside the physics core, which knows
nothing of them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .checks import Check, all_pass, checks_json, checks_lines, failed
    from .fields import Field, Record
    from .notices import Notice
    from .numbers import format_significant, json_number, round_sig, rounded, significant

__all__ = [
    "Check",
    "Field",
    "Notice",
    "Record",
    "all_pass",
    "checks_json",
    "checks_lines",
    "failed",
    "format_significant",
    "json_number",
    "round_sig",
    "rounded",
    "significant",
]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
