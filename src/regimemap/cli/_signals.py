"""Ctrl-C and SIGTERM while a command runs: one exception each, raised once, in the main thread.

:func:`stop_signals` turns SIGINT into KeyboardInterrupt and SIGTERM into
:class:`Terminated` for the duration of a command (:func:`regimemap.cli._main.run_main`),
so the cleanups of an interrupted run -- a process pool stopped, a temporary file removed --
run for both, and a second signal cannot break them half-way.  Before the command runs (the
imports of the process's start) and after it, :mod:`regimemap.process` ends the ``regimemap``
process at once on either signal; the worker processes ignore both
(:mod:`regimemap.workers`): the parent stops them.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator
from types import FrameType

from ..process import INTERRUPTED, TERMINATED, LostSignals, exit_now

__all__ = ["EXIT_DEADLINE", "Terminated", "stop_signals"]


class Terminated(BaseException):
    """SIGTERM, raised in the main thread while a command runs (:func:`stop_signals`).

    A BaseException, as KeyboardInterrupt is: ``except Exception`` does not
    swallow it, and cleanups (the temporary file of an atomic write, a
    process pool) run as they do for Ctrl-C.
    """


_STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)

#: Seconds the ``regimemap`` process may take to end after the first signal: then it ends anyway
#: (:func:`regimemap.process.exit_now`), whatever it was doing.
EXIT_DEADLINE = 1.5


def _arm_deadline(signum: int, seconds: float) -> None:
    """End the process ``seconds`` from now, with the signal's line and code."""
    line, code = TERMINATED if signum == signal.SIGTERM else INTERRUPTED
    timer = threading.Timer(seconds, exit_now, args=(code, line))
    timer.daemon = True
    timer.name = "regimemap-exit-deadline"
    timer.start()


@contextlib.contextmanager
def stop_signals(*, exiting: bool = False, deadline: float | None = None) -> Iterator[None]:
    """While the block runs, SIGINT raises KeyboardInterrupt and SIGTERM :class:`Terminated`.

    Only the first of them raises: a second Ctrl-C (or the same signal sent to
    a whole process group twice) cannot interrupt the cleanup of the first
    half-way with a traceback.  An interrupt that lands in a finalizer
    (``__del__``, a weakref callback), where Python would print ``Exception
    ignored`` and carry on, is taken back and raised again in the code that
    runs next (:class:`regimemap.process.LostSignals`).  Afterwards the handlers
    are restored, unless ``exiting`` (the
    ``regimemap`` process itself, which ends now) and a signal came: both are
    then ignored until the process has exited.  With a ``deadline`` (the
    ``regimemap`` process: :data:`EXIT_DEADLINE`), the process ends that many
    seconds after the first signal at the latest, whatever it is doing.  A signal the process was
    started with ignored (``nohup``, a background job of a script) stays
    ignored.  An ordinary exception that leaves the block after a signal (the signal landed in
    code that made another error of it, such as a C extension's module initialization, which
    says ``ImportError: initialization failed``) is raised as the signal's exception, from it.
    Outside the main thread nothing is changed.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    saved = {sig: signal.getsignal(sig) for sig in _STOP_SIGNALS}
    caught: list[int] = []
    lost = LostSignals((KeyboardInterrupt, Terminated))

    def stop(signum: int, frame: FrameType | None) -> None:
        if lost.deferred(signum, frame):
            return
        if caught and not lost.lost:  # the first one is being handled
            return
        if not caught:
            caught.append(signum)
            if deadline is not None:
                _arm_deadline(signum, deadline)
        lost.raising(caught[0])
        if caught[0] == signal.SIGTERM:
            raise Terminated(caught[0])
        raise KeyboardInterrupt

    for sig in _STOP_SIGNALS:
        if saved[sig] is not signal.SIG_IGN:
            signal.signal(sig, stop)
    lost.__enter__()
    try:
        yield
    except Exception as exc:
        if not caught:
            raise
        # the signal landed in code that made another error of it (Ctrl-C in a C extension's
        # module initialization is "ImportError: initialization failed"): the command still ends
        # as the signal ends it
        raise (Terminated(caught[0]) if caught[0] == signal.SIGTERM else KeyboardInterrupt()) from exc
    finally:
        lost.__exit__()
        for sig, handler in saved.items():
            # SIG_IGN, not a Python handler: the interpreter keeps it while it shuts down
            signal.signal(sig, signal.SIG_IGN if exiting and caught else handler)
