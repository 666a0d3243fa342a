"""Ctrl-C and SIGTERM while a command runs: one exception each, raised once, in the main thread.

:func:`stop_signals` turns SIGINT into KeyboardInterrupt and SIGTERM into
:class:`Terminated` for the duration of a command (:func:`regimemap.cli._common.run_main`),
so the cleanups of an interrupted run -- a process pool stopped, a temporary file removed --
run for both, and a second signal cannot break them half-way.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

__all__ = ["Terminated", "stop_signals"]


class Terminated(BaseException):
    """SIGTERM, raised in the main thread while a command runs (:func:`stop_signals`).

    A BaseException, as KeyboardInterrupt is: ``except Exception`` does not
    swallow it, and cleanups (the temporary file of an atomic write, a
    process pool) run as they do for Ctrl-C.
    """


_STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


@contextlib.contextmanager
def stop_signals(*, exiting: bool = False) -> Iterator[None]:
    """While the block runs, SIGINT raises KeyboardInterrupt and SIGTERM :class:`Terminated`.

    Only the first of them raises: a second Ctrl-C (or the same signal sent to
    a whole process group twice) cannot interrupt the cleanup of the first
    half-way with a traceback.  Afterwards the handlers are restored, unless
    ``exiting`` (the ``regimemap`` process itself, which ends now) and a
    signal came: both are then ignored until the process has exited.  A
    signal the process was started with ignored (``nohup``, a background job
    of a script) stays ignored.  Outside the main thread nothing is changed.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    saved = {sig: signal.getsignal(sig) for sig in _STOP_SIGNALS}
    caught: list[int] = []

    def stop(signum: int, frame: object) -> None:
        if caught:  # the first one is being handled
            return
        caught.append(signum)
        if signum == signal.SIGTERM:
            raise Terminated(signum)
        raise KeyboardInterrupt

    for sig in _STOP_SIGNALS:
        if saved[sig] is not signal.SIG_IGN:
            signal.signal(sig, stop)
    try:
        yield
    finally:
        for sig, handler in saved.items():
            # SIG_IGN, not a Python handler: the interpreter keeps it while it shuts down
            signal.signal(sig, signal.SIG_IGN if exiting and caught else handler)
