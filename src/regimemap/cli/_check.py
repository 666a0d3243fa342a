"""A record's verdict and warnings on the command line: ``--check``, ``--strict`` and the notices.

``--check`` makes the verdict of the requirements the exit status (1 when any fails); a
record's notices (:class:`~regimemap.records.notices.Notice`) are printed on standard error
by :func:`regimemap.cli._writing.echo_notices`, or, those ``--strict`` refuses, are a usage
error (exit 2) naming the first.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import click

from ..records.checks import Check, all_pass
from ..records.notices import Notice

__all__ = ["CHECK_HELP", "check_option", "exit_on_failure", "refuse_notices"]

CHECK_HELP = ("Exit with status 1 when any requirement fails (the report and the files are written "
              "first; usage errors still exit 2).")


def check_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """The ``--check`` flag, passed to the command as ``check``."""
    return click.option("--check", "check", is_flag=True, help=CHECK_HELP)(f)


def exit_on_failure(checks: Sequence[Check], check: bool) -> None:
    """Exit with status 1 under ``--check`` when a requirement fails; return otherwise."""
    if check and not all_pass(checks):
        raise click.exceptions.Exit(1)


def refuse_notices(notices: Sequence[Notice], codes: str | tuple[str, ...], why: str,
                   param_hint: str) -> None:
    """A usage error (exit 2) naming the first notice of ``codes`` (and how many more), then ``why``
    (``"--strict refuses implausible values"``); return when there is none."""
    found = [n for n in notices if n.code in ((codes,) if isinstance(codes, str) else codes)]
    if found:
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        reason = f"; {why}" if why else ""
        raise click.BadParameter(f"{found[0].message}{more}{reason}", param_hint=param_hint)
