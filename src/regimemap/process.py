"""The ``regimemap`` process's exit on Ctrl-C and SIGTERM, from its first line of regimemap code.

The standard library only, at import: :func:`exit_on_signal_at_start` runs when this module is
imported, the package's first import (``regimemap/__init__.py``), and does something only in the
``regimemap`` command's own process (the console script, ``python -m regimemap``), never in a
program that imports the library. Until the command runs, Ctrl-C or SIGTERM there ends the
process at once, with the command's one line and exit code: nothing is written yet, and an
interpreter importing numpy would print a traceback. While the command runs,
:mod:`regimemap.cli._signals` takes over; its handlers raise, so that cleanups run, and
:func:`exit_now` ends the process (the line, then ``os._exit``) once they have. A Dask worker
that the process spawns (``study --scheduler local``) imports regimemap too, as it starts:
:func:`die_with_spawning_parent` has it die with its parent from then on.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from typing import Any

__all__ = ["INTERRUPTED", "TERMINATED", "die_with_spawning_parent", "exit_now", "exit_on_signal_at_start",
           "flush_on_exit", "is_console"]

#: The line and exit code of Ctrl-C (SIGINT) and of SIGTERM (128 + the signal's number, as a shell
#: reports a process the signal ended).
INTERRUPTED = ("regimemap: interrupted", 128 + int(signal.SIGINT))
TERMINATED = ("regimemap: terminated", 128 + int(signal.SIGTERM))

_exiting = threading.Lock()
_exiting_thread: list[int] = []
_flushed: list[Any] = []


def is_console() -> bool:
    """Whether this process is the ``regimemap`` command (its console script or ``-m regimemap``)."""
    argv: list[str] = [str(a) for a in getattr(sys, "orig_argv", [])][1:]
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "-m":
            return i + 1 < len(argv) and argv[i + 1] == "regimemap"
        if a.startswith("-m"):
            return a[2:] == "regimemap"
        if a in ("-c", "-") or a.startswith("-c"):
            return False
        if a in ("-X", "-W", "--check-hash-based-pycs"):
            i += 2
            continue
        if a.startswith("-"):
            i += 1
            continue
        return os.path.basename(a) in ("regimemap", "regimemap.exe", "regimemap-script.py")
    return False


def _children() -> list[int]:
    """This process's live children (Linux: /proc; elsewhere none are known)."""
    out: list[int] = []
    try:
        tasks = os.listdir("/proc/self/task")
    except OSError:
        return out
    for task in tasks:
        try:
            with open(f"/proc/self/task/{task}/children") as fh:
                out += [int(pid) for pid in fh.read().split()]
        except (OSError, ValueError):
            continue
    return out


def _kill_children() -> None:
    """SIGKILL the children still alive (a Dask worker still starting), but multiprocessing's
    resource tracker, which removes their semaphores once they are gone."""
    for pid in _children():
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as fh:
                if b"resource_tracker" in fh.read():
                    continue
            os.kill(pid, signal.SIGKILL)
        except OSError:
            continue


def flush_on_exit(*streams: Any) -> None:
    """The streams :func:`exit_now` flushes before the end (the command line's standard output
    and error: this module writes to neither but for the one line, on file descriptor 2)."""
    _flushed[:] = streams


def exit_now(code: int, line: str | None) -> None:
    """End the process now: the streams of :func:`flush_on_exit` flushed, ``line`` on standard error
    (once), ``os._exit(code)``.

    No interpreter teardown: no thread is joined, no atexit handler runs (every file was
    closed or removed before).  A child process still alive (a Dask worker that is still
    starting, and so not yet watching its parent) is killed.  Safe from any thread; the first
    caller wins (a signal handler that interrupts it in its own thread returns at once).
    """
    me = threading.get_ident()
    if not _exiting.acquire(blocking=False):  # never released: the first caller is ending the process
        while _exiting_thread and _exiting_thread[0] != me:  # another thread is: wait for the end
            time.sleep(1.0)
        return  # a second signal, whose handler interrupted the first one's exit here: it goes on
    _exiting_thread.append(me)
    _kill_children()
    for stream in _flushed:
        try:
            stream.flush()
        except Exception:  # noqa: BLE001, S110 - closed, or a broken pipe: exiting anyway
            pass
    if line:
        try:
            os.write(2, (line + "\n").encode())
        except OSError:
            pass
    os._exit(code)


def _exit_on(signum: int, frame: object) -> None:
    line, code = TERMINATED if signum == signal.SIGTERM else INTERRUPTED
    exit_now(code, line)


def exit_on_signal_at_start() -> None:
    """In the ``regimemap`` process only: Ctrl-C and SIGTERM exit at once with the command's line
    and code, until the command installs its own handlers (a signal ignored stays ignored)."""
    if not is_console() or threading.current_thread() is not threading.main_thread():
        return
    for sig in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(sig) is not signal.SIG_IGN:
            signal.signal(sig, _exit_on)


def die_with_spawning_parent() -> None:
    """In a process spawned for a LocalCluster of the ``regimemap`` process (a Dask worker, which
    imports regimemap as it starts): SIGKILL when that parent dies, from this moment on."""
    parent = os.environ.get("REGIMEMAP_DIE_WITH_PARENT", "")  # regimemap.workers.PARENT_VARIABLE
    if parent.isdigit() and int(parent) != os.getpid() and os.getppid() in (int(parent), 1):
        from .workers import die_with_parent

        die_with_parent(int(parent), signal.SIGKILL)


# the package's first import (regimemap/__init__.py): from here on, in the regimemap process
# and in the Dask workers it spawns
exit_on_signal_at_start()
die_with_spawning_parent()
