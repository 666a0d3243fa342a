"""The ``regimemap`` process: its start (the garbage collector paused until matplotlib is imported)
and its end (:func:`run_main`: every error one line and an exit code, Ctrl-C 130, SIGTERM 143)."""

from __future__ import annotations

import contextlib
import gc
import os
import sys
from collections.abc import Iterator

import click

from ..process import INTERRUPTED, TERMINATED, exit_now, flush_on_exit
from ._signals import EXIT_DEADLINE, Terminated, stop_signals

__all__ = ["RunError", "gc_paused_at_start", "import_matplotlib", "refusing", "run_main"]


class RunError(click.ClickException):
    """A failure while running (exit code 1), printed as one line."""

    exit_code = 1


@contextlib.contextmanager
def refusing(param_hint: str, errors: type[Exception] | tuple[type[Exception], ...] = ValueError
             ) -> Iterator[None]:
    """An error of ``errors`` inside (a refused input) becomes a usage error (exit 2) naming
    ``param_hint`` (``"'--points'"``), with the error's message."""
    try:
        yield
    except errors as exc:
        raise click.BadParameter(str(exc), param_hint=param_hint) from None


def _one_line(text: str) -> str:
    """``text`` on one line (newlines and runs of blanks become one space)."""
    return " ".join(str(text).split())


def _say(message: str) -> None:
    try:
        click.echo(_one_line(message), err=True)
    except (OSError, ValueError):  # pragma: no cover - stderr closed
        pass


def _error_message(exc: BaseException) -> str:
    if isinstance(exc, OSError) and exc.strerror:
        where = exc.filename if exc.filename is not None else None
        return f"{exc.strerror}: {str(where)!r}" if where is not None else exc.strerror
    return str(exc) or type(exc).__name__


# -- start-up: the cyclic garbage collector -------------------------------------------------
#
# ``regimemap plot`` is a short process that spends most of its time importing
# matplotlib, which allocates ~120 000 long-lived objects.  With the collector
# running, CPython scans them again and again while they are being created
# (~35-40 ms of a 0.6 s run, measured with gc.callbacks).  ``cli.main``
# therefore pauses the collector at start; a drawing command calls
# :func:`import_matplotlib`, which imports matplotlib, freezes what the imports
# allocated (``gc.freeze``: later collections skip it) and resumes collecting,
# so commands that draw many figures (figures, atlas, animate) still free their
# garbage.  Library users and click's test runner are not affected.

_gc_state = {"paused": False, "frozen": False, "may_freeze": False}


@contextlib.contextmanager
def gc_paused_at_start() -> Iterator[None]:
    """Pause the cyclic GC until :func:`import_matplotlib` (or the end); restore it after."""
    was_enabled = gc.isenabled()
    gc.disable()
    _gc_state["paused"] = was_enabled  # a caller that disabled it keeps it disabled
    # gc.unfreeze() cannot tell whose objects it thaws: freeze only if nobody else has
    _gc_state["may_freeze"] = gc.get_freeze_count() == 0
    try:
        yield
    finally:
        if _gc_state["frozen"]:
            gc.unfreeze()
        _gc_state["paused"] = _gc_state["frozen"] = False
        if was_enabled:
            gc.enable()


def import_matplotlib() -> None:
    """Import matplotlib and its Agg canvas for a drawing command; then resume the GC.

    The renderer imports matplotlib lazily; a drawing command calls this first
    so that the import happens while the collector is paused (see above).
    """
    from ..drawing import load_matplotlib

    load_matplotlib()

    if _gc_state["paused"]:
        _gc_state["paused"] = False
        if _gc_state["may_freeze"]:
            gc.freeze()
            _gc_state["frozen"] = True
        gc.enable()


def _guess_path(group: click.Command, argv: list[str] | None) -> str:
    """``regimemap CMD`` from the arguments, for usage errors click reports without a context."""
    args = sys.argv[1:] if argv is None else argv
    commands = getattr(group, "commands", {})
    for a in args:
        if a in commands:
            return f"regimemap {a}"
        if not a.startswith("-"):
            break
    return "regimemap"


def _stopped(how: tuple[str, int], exiting: bool) -> int:
    """The end of an interrupted command: its one line and exit code.  ``exiting`` (the
    ``regimemap`` process): the process ends here, without the interpreter's teardown
    (:func:`regimemap.process.exit_now`; every cleanup of the command has run)."""
    line, code = how
    if exiting:
        exit_now(code, _one_line(line))
    _say(line)
    return code


def run_main(group: click.Command, argv: list[str] | None = None, *, exiting: bool = False) -> int:
    """Run ``group`` and return an exit code; no traceback ever reaches the user.

    Every error is one line on stderr:

    * usage errors (bad option or value, unknown command) exit 2:
      ``regimemap plot: error: Invalid value for '--gamma': ... (see 'regimemap plot --help')``;
    * failures while running (:class:`RunError`, ``ValueError``, ``OSError``)
      exit 1: ``regimemap: error: ...``;
    * an unexpected exception (a bug) exits 1 with ``regimemap: internal error: ...``
      (set ``REGIMEMAP_DEBUG=1`` to see the traceback);
    * an interrupt (Ctrl-C, SIGINT) exits 130 with ``regimemap: interrupted``,
      SIGTERM 143 with ``regimemap: terminated`` (128 + the signal's number, as
      a shell reports a process the signal ended); worker processes are
      stopped and no file is left half-written (:func:`._signals.stop_signals`; with
      ``exiting``, the process ends here, at the latest 1.5 s after the signal, and a
      second signal is ignored).
    """
    if exiting:
        flush_on_exit(sys.stdout, sys.stderr)
    try:
        with stop_signals(exiting=exiting, deadline=EXIT_DEADLINE if exiting else None):
            # without standalone mode click returns the code of a click.exceptions.Exit (--check's 1)
            code = group.main(args=argv, prog_name="regimemap", standalone_mode=False)
    except Terminated:
        return _stopped(TERMINATED, exiting)
    except click.exceptions.Abort:
        return _stopped(INTERRUPTED, exiting)
    except click.UsageError as exc:
        path = exc.ctx.command_path if exc.ctx is not None else _guess_path(group, argv)
        _say(f"{path}: error: {exc.format_message()} (see '{path} --help')")
        return exc.exit_code
    except click.ClickException as exc:
        _say(f"regimemap: error: {exc.format_message()}")
        return exc.exit_code
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except KeyboardInterrupt:
        return _stopped(INTERRUPTED, exiting)
    except BrokenPipeError:
        return 1
    except (ValueError, OSError) as exc:
        _say(f"regimemap: error: {_error_message(exc)}")
        return 1
    except Exception as exc:  # a bug; still one line, no traceback
        if os.environ.get("REGIMEMAP_DEBUG"):
            raise
        _say(f"regimemap: internal error: {type(exc).__name__}: {exc}"
             " (please report it; REGIMEMAP_DEBUG=1 shows the traceback)")
        return 1
    return code if isinstance(code, int) and not isinstance(code, bool) else 0
