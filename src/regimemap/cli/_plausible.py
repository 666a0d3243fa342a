"""Warnings for valid but implausible design files (likely unit slips), and ``--strict``.

The checks are :func:`regimemap.caisson.file_plausibility.implausible_notices` (run by
:func:`regimemap.caisson.run.run_caisson`); :func:`caisson_record` turns them into one warning
line each on standard error, with the file's name (:func:`~regimemap.cli._writing.echo_notices`),
or, with ``--strict``, a usage error (exit 2) naming the first, and a caisson that cannot be
analysed into the command line's one-line error.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import click

from ._main import RunError
from ._writing import echo_notices

if TYPE_CHECKING:  # pragma: no cover
    from regimemap.caisson.file import Design
    from regimemap.caisson.run import CaissonRecord
    from regimemap.records.notices import Notice

__all__ = ["STRICT_HELP", "STRICT_RECORD_HELP", "caisson_record"]

STRICT_HELP = ("Refuse a design file whose values are valid but implausible for a breakwater "
               "(likely unit slips: a depth over 100 m, a section heavier than 30 kN/m^3 ...); "
               "without it they are warnings on standard error.")
#: ``--strict`` of the commands that run the lifetime (``lifetime``, ``caisson``).
STRICT_RECORD_HELP = STRICT_HELP + " With a [lifetime.record], its warnings too (quality control, fit)."


def _refusal(notices: Sequence[Notice], source: str, param_hint: str) -> click.BadParameter:
    """The usage error of ``--strict``: the first implausible value (or warning of the design's
    wave record) and how many more."""
    more = f" (and {len(notices) - 1} more)" if len(notices) > 1 else ""
    what = "implausible values" if notices[0].code == "implausible-value" else "the record's warnings"
    return click.BadParameter(f"{source}: {notices[0].message}{more}; --strict refuses {what}",
                              param_hint=param_hint)


def caisson_record(design: Design, source: str, *, strict: bool = False, sheet: bool = False,
                   param_hint: str = "'DESIGN.toml'", usage_error: bool = False) -> CaissonRecord:
    """:func:`~regimemap.caisson.run.run_caisson` of ``design``, its warnings on standard error.

    With ``strict`` an implausible value is a usage error naming ``param_hint``; a caisson
    that cannot be analysed is a one-line error naming ``source``, after the warnings of its
    inputs: exit 1, or with ``usage_error`` a usage error naming ``param_hint`` (exit 2).
    """
    from ..caisson.run import CaissonError, ImplausibleDesignError, run_caisson

    try:
        record = run_caisson(design, strict=strict, sheet=sheet)
    except ImplausibleDesignError as exc:
        raise _refusal(exc.notices, source, param_hint) from None
    except CaissonError as exc:
        echo_notices(exc.notices, source=source)
        if usage_error:
            raise click.BadParameter(f"{source}: {exc}", param_hint=param_hint) from None
        raise RunError(f"{source}: {exc}") from None
    echo_notices(record.notices, source=source)
    return record
