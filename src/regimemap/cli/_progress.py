"""A progress bar on standard error for the long runs of the commands (tqdm).

:func:`progress_bar` is a context manager that yields a function ``step(n)``:
the library's ``progress`` callbacks (``regimemap.lifetime.lifetime_sliding``
and the like) are handed it as they are.  The bar appears only when a run
lasts over a second, only on a terminal (never in a pipe, a file or a test),
and never with ``--quiet``; it is removed when the run ends, so standard error
keeps only the notes.  tqdm is imported only when a bar is shown.
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager

__all__ = ["DELAY", "Bars", "progress_bar", "progress_bars"]

#: ``bars(total, what)``: the bar of one stage of a run (the ``progress`` of the library's runs).
Bars = Callable[[int, str], AbstractContextManager[Callable[[int], None]]]

#: Seconds a run must last before its bar is drawn.
DELAY = 1.0


def _ignore(n: int) -> None:
    """The ``step`` of a bar that is not shown."""


def _stderr_is_terminal() -> bool:
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, ValueError):  # no stderr, or closed
        return False


@contextlib.contextmanager
def progress_bar(total: int | None, description: str, quiet: bool = False, *,
                 unit: str = "it") -> Iterator[Callable[[int], None]]:
    """A bar on standard error; yields ``step(n)``, to call with the units done since the last call.

    Parameters
    ----------
    total : int or None
        Units of the whole run (None: unknown; the bar counts without a percentage).
    description : str
        Written before the bar (``"lifetimes"``).
    quiet : bool, optional
        No bar at all (``--quiet``).
    unit : str, optional
        Name of a unit, for the counts and the rate (``" lifetimes"``: tqdm writes
        it right after the number).

    Yields
    ------
    callable
        ``step(n)``; it does nothing when no bar is shown.

    Notes
    -----
    The bar is drawn after :data:`DELAY` seconds (tqdm's ``delay``), so a
    short run prints nothing, and only when standard error is a terminal.
    """
    if quiet or not _stderr_is_terminal():
        yield _ignore
        return
    from tqdm import tqdm

    bar = tqdm(total=total, desc=description, unit=unit, file=sys.stderr, delay=DELAY, leave=False,
               dynamic_ncols=True)
    try:
        def step(n: int) -> None:
            bar.update(n)

        yield step
    finally:
        bar.close()


def progress_bars(quiet: bool, unit: str, prefix: str = "") -> Bars:
    """``bars(total, what)``: a :func:`progress_bar` of ``unit`` for each stage ``what`` of a run,
    described ``prefix + what`` (none with ``quiet`` or off a terminal)."""
    def bars(total: int, what: str) -> AbstractContextManager[Callable[[int], None]]:
        return progress_bar(total, f"{prefix}{what}", quiet, unit=unit)

    return bars
