"""``--check``: the verdict of the requirements as the exit status (1 when any fails)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import click

from ..mechanics.checks import Check, all_pass

__all__ = ["CHECK_HELP", "check_option", "exit_on_failure"]

CHECK_HELP = ("Exit with status 1 when any requirement fails (the report and the files are written "
              "first; usage errors still exit 2).")


def check_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """The ``--check`` flag, passed to the command as ``check``."""
    return click.option("--check", "check", is_flag=True, help=CHECK_HELP)(f)


def exit_on_failure(checks: Sequence[Check], check: bool) -> None:
    """Exit with status 1 under ``--check`` when a requirement fails; return otherwise."""
    if check and not all_pass(checks):
        raise click.exceptions.Exit(1)
