"""``regimemap -v``: the library's diagnostics (:mod:`logging`) on standard error.

The library logs to ``logging.getLogger("regimemap")`` and its children (one
per module: ``regimemap.maps.mapdata``, ``regimemap.lifetime.parallel`` ...)
and never prints.  Without ``-v`` nothing is shown; ``-v`` shows what it does
(INFO: maps computed and their size, lifetime runs and their timing, files
written), ``-vv`` the details (DEBUG: each lifetime chunk, each batch of
simulations).  The notes a command prints as part of its output
(``regimemap: note: ...``) are not log records and are shown either way.
"""

from __future__ import annotations

import logging
import sys
from collections.abc import Callable
from typing import Any

import click

__all__ = ["LOGGER_NAME", "start_logging", "verbose_option"]

#: The library's root logger.
LOGGER_NAME = "regimemap"

#: One record a line: milliseconds since start, level, module, message.
FORMAT = "regimemap: [%(relativeCreated)7.0f ms] %(levelname)s %(name)s: %(message)s"


def start_logging(verbosity: int) -> Callable[[], None]:
    """Show the library's records on standard error: INFO for 1, DEBUG for 2 or more.

    Returns the function that undoes it (removes the handler, restores the
    level), so that commands run in one process (tests, notebooks) do not pile
    up handlers.
    """
    logger = logging.getLogger(LOGGER_NAME)
    if verbosity <= 0:
        return lambda: None
    handler = logging.StreamHandler(sys.stderr)  # the stream of this run (click's runner swaps it)
    handler.setFormatter(logging.Formatter(FORMAT))
    old_level = logger.level
    logger.setLevel(logging.INFO if verbosity == 1 else logging.DEBUG)
    logger.addHandler(handler)

    def undo() -> None:
        logger.removeHandler(handler)
        logger.setLevel(old_level)
        handler.close()

    return undo


def _configure(ctx: click.Context, _param: click.Parameter, value: int) -> int:
    if value:
        ctx.call_on_close(start_logging(value))
    return value


def verbose_option(f: Any) -> Any:
    """``-v/--verbose`` (count) on the group: it configures logging before any command runs."""
    return click.option(
        "-v", "--verbose", count=True, expose_value=False, callback=_configure,
        help="Show what the library does on standard error: -v the main steps (maps computed, "
             "runs and their timing, files written), -vv the details.")(f)
