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

Two things every process of regimemap's shares live here too: a signal whose exception lands in
a finalizer is raised again in the code that runs next (:class:`LostSignals`: the command's
handlers and every worker of :mod:`regimemap.workers` use it), and a process asks to receive a
signal when its parent dies (:func:`die_with_parent`: a pool's worker, a Dask worker).
"""

from __future__ import annotations

import _thread
import os
import signal
import sys
import threading
import time
from collections.abc import Callable
from types import FrameType
from typing import Any

__all__ = ["INTERRUPTED", "TERMINATED", "LostSignals", "die_with_parent", "die_with_spawning_parent",
           "exit_now", "exit_on_signal_at_start", "flush_on_exit", "is_console"]

#: The line and exit code of Ctrl-C (SIGINT) and of SIGTERM (128 + the signal's number, as a shell
#: reports a process the signal ended).
INTERRUPTED = ("regimemap: interrupted", 128 + int(signal.SIGINT))
TERMINATED = ("regimemap: terminated", 128 + int(signal.SIGTERM))

_exiting = threading.Lock()
_exiting_thread: list[int] = []
_flushed: list[Any] = []


def _send_to_main_thread(main: int, signum: int, pending: Callable[[], bool]) -> None:
    """``signum`` to the main thread (``main``, its ident), from a thread of its own: it arrives
    after the caller returns.

    ``pthread_kill`` wakes a main thread that sleeps or waits (the call is retried after the
    handler, PEP 475); where it is missing, :func:`_thread.interrupt_main` sets the signal as
    pending.  Both from another thread, because ``signal.raise_signal`` and ``os.kill`` run the
    handler at once, in their caller.  A signal that arrives just before the main thread starts
    to wait is handled only when the wait ends, so it is sent again every :data:`_RESEND`
    seconds while ``pending()`` (for at most :data:`_RESEND_FOR` seconds).  Only built-in calls
    here and in the hook: a handler that runs in any other code of Python's would raise there.
    """
    if not hasattr(signal, "pthread_kill"):  # pragma: no cover - not POSIX
        _thread.start_new_thread(_thread.interrupt_main, (signal.Signals(signum),))
    else:
        _thread.start_new_thread(_kill_thread, (main, signum, pending))


#: Seconds between two sends of a signal still not handled, and for how long it is sent.
_RESEND = 0.02
_RESEND_FOR = 2.0


def _kill_thread(thread: int, signum: int, pending: Callable[[], bool]) -> None:
    """``signum`` to ``thread`` until it is handled; nothing if it has ended (an exiting interpreter)."""
    for _ in range(round(_RESEND_FOR / _RESEND)):
        try:
            signal.pthread_kill(thread, signum)
        except OSError:
            return
        time.sleep(_RESEND)
        if not pending():
            return


class LostSignals:
    """A signal's exception that lands in a finalizer, raised again in the code that runs next.

    Python runs a ``__del__`` method or a weakref callback wherever an object dies, and an
    exception raised there cannot leave it: Python prints ``Exception ignored in ...`` with a
    traceback on stderr and carries on, as if the signal had never come.  While this is
    installed (``with``), ``sys.unraisablehook`` takes an exception of ``kinds`` back without a
    word and the signal is sent again to the main thread (:func:`_send_to_main_thread`), whose
    handler then raises in the code that runs next.  A handler first asks :meth:`deferred`: a
    signal handled inside the hook itself is sent again too, rather than raised there; and a
    handler raises once (:meth:`raising`), then again only for a signal :attr:`lost` (a signal
    may be sent more than once, :func:`_send_to_main_thread`).  Used by
    the ``regimemap`` process while a command runs (:func:`regimemap.cli._signals.stop_signals`)
    and by every worker of the process pool (:mod:`regimemap.workers`).

    Parameters
    ----------
    kinds
        The exceptions the handlers raise (KeyboardInterrupt, ...).
    """

    def __init__(self, kinds: tuple[type[BaseException], ...]) -> None:
        self.kinds = kinds
        #: The signal whose exception the handlers raised last (sent again when it is lost).
        self.signum: int | None = None
        #: Whether the exception of :attr:`signum` was lost in a finalizer and is being sent again.
        self.lost = False
        self._hook: Any = sys.unraisablehook
        self._main = _thread.get_ident()

    def __enter__(self) -> LostSignals:
        """Install the hook, from the main thread (a pool's worker: the thread forked)."""
        self._main = _thread.get_ident()
        self._hook = sys.unraisablehook
        sys.unraisablehook = self._unraisable
        return self

    def __exit__(self, *exc: object) -> None:
        sys.unraisablehook = self._hook

    def raising(self, signum: int) -> None:
        """Note that a handler raises the exception of ``signum`` now."""
        self.signum = signum
        self.lost = False

    def deferred(self, signum: int, frame: FrameType | None) -> bool:
        """Whether a handler of ``signum`` runs inside the hook: then the signal is sent again."""
        if frame is not None and frame.f_code in _HOOK_CODE:
            _send_to_main_thread(self._main, signum, lambda: self.lost)
            return True
        return False

    def _unraisable(self, info: Any) -> None:
        if self.signum is not None and isinstance(info.exc_value, self.kinds):
            self.lost = True
            _send_to_main_thread(self._main, self.signum, lambda: self.lost)
            return
        self._hook(info)


#: The code of the hook and of what it calls: a handler that runs there does not raise.
_HOOK_CODE = (LostSignals._unraisable.__code__, _send_to_main_thread.__code__)


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


#: ``prctl``'s option that sends a signal when the parent dies (linux/prctl.h).
_PR_SET_PDEATHSIG = 1


def _watch_parent(parent: int, signum: int) -> None:  # pragma: no cover - not Linux
    """A worker's thread where prctl is missing: ``signum`` to itself once the parent is gone."""
    while os.getppid() == parent:
        time.sleep(0.5)
    os.kill(os.getpid(), signum)


def die_with_parent(parent: int, signum: int) -> None:
    """Make this (worker) process receive ``signum`` when the process ``parent`` dies.

    Linux: ``prctl(PR_SET_PDEATHSIG)``, then a check that the parent did not
    die before it (the worker is then an orphan already).  Elsewhere a daemon
    thread polls the parent's pid.  Called by a pool's worker as it starts, and
    by a LocalCluster's worker (SIGKILL) as it imports regimemap
    (:data:`regimemap.workers.PARENT_VARIABLE`).
    """
    done = False
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            done = libc.prctl(_PR_SET_PDEATHSIG, int(signum), 0, 0, 0) == 0
        except (OSError, AttributeError):  # pragma: no cover - no libc prctl
            done = False
    if not done:  # pragma: no cover - not Linux
        threading.Thread(target=_watch_parent, args=(parent, signum), daemon=True,
                         name="regimemap-parent-watch").start()
    if os.getppid() != parent:  # the parent died before prctl
        os.kill(os.getpid(), signum)


def die_with_spawning_parent() -> None:
    """In a process spawned for a LocalCluster of the ``regimemap`` process (a Dask worker, which
    imports regimemap as it starts): SIGKILL when that parent dies, from this moment on."""
    parent = os.environ.get("REGIMEMAP_DIE_WITH_PARENT", "")  # regimemap.workers.PARENT_VARIABLE
    if parent.isdigit() and int(parent) != os.getpid() and os.getppid() in (int(parent), 1):
        die_with_parent(int(parent), signal.SIGKILL)


# the package's first import (regimemap/__init__.py): from here on, in the regimemap process
# and in the Dask workers it spawns
exit_on_signal_at_start()
die_with_spawning_parent()
