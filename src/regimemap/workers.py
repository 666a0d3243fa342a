"""The one place where regimemap starts worker processes: a process pool, and Dask's LocalCluster.

Every process regimemap starts comes from here: the pool of :func:`worker_pool`
(the lifetime chunks, the replicate climates, the study's tasks, the report's
figures) and the workers of :func:`local_cluster` (``study --scheduler local``).
Both hold the same three promises:

* **Ctrl-C is the parent's.**  A terminal sends SIGINT to the whole process
  group; the workers ignore it and the parent decides.  It stops its workers
  (:meth:`WorkerPool.stop`: :data:`STOP_SIGNAL`, then SIGKILL after
  :data:`STOP_GRACE` seconds) without waiting for any queued task.  SIGTERM
  too is the parent's (``kill`` of the process group, a job control).
* **A stopped worker leaves nothing half-written.**  :data:`STOP_SIGNAL` raises
  :class:`WorkerStopped` in the worker's task, so the cleanups of an atomic
  write (:mod:`regimemap.io.atomic`) run before the worker ends.
* **No worker outlives its parent.**  On Linux a pool worker asks the kernel
  for :data:`STOP_SIGNAL` when its parent dies (:func:`regimemap.process.die_with_parent`,
  ``prctl(PR_SET_PDEATHSIG)``; it fires
  when the *thread* that forked the worker ends, so the pool forks from the
  thread that owns it, and holds it open for its whole life); elsewhere a
  thread of the worker watches its parent's pid.  A LocalCluster's worker
  processes watch a pipe from the parent (Dask's ``AsyncProcess``); its
  scheduler and nannies run inside the parent.

The pool keeps no thread of ``concurrent.futures``: one daemon thread of its
own hands the tasks to idle workers and sets the futures, so an interrupted
parent never waits on a management thread, a queue's feeder thread or a
wake-up pipe while the interpreter exits.  A worker runs one task at a time;
results come back as :class:`concurrent.futures.Future` (``wait`` and
``as_completed`` work on them), so the numbers do not depend on which worker
ran what.
"""

from __future__ import annotations

import collections
import contextlib
import logging
import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import Future
from multiprocessing.connection import Connection, wait
from multiprocessing.reduction import ForkingPickler
from types import FrameType
from typing import Any, TypeVar

from .process import LostSignals, die_with_parent

__all__ = ["PARENT_VARIABLE", "STOP_GRACE", "STOP_SIGNAL", "PoolBroken", "WorkerPool", "WorkerStopped",
           "available_cores", "local_cluster", "worker_pool"]

_T = TypeVar("_T")

_log = logging.getLogger(__name__)

#: Seconds a worker sent :data:`STOP_SIGNAL` is given to end (its cleanups) before it is killed.
STOP_GRACE = 0.8

#: Seconds a worker is given to end after its last task, when the pool closes normally.
CLOSE_GRACE = 10.0

#: The signals of a terminal or a job control (Ctrl-C, ``kill``): a worker ignores them, the parent decides.
_STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)

#: The signal by which the parent stops a worker (and the kernel, when the parent dies): it raises
#: :class:`WorkerStopped` in the worker.  Not SIGTERM, which a group-wide ``kill`` also sends.
STOP_SIGNAL = getattr(signal, "SIGUSR1", signal.SIGTERM)  # no SIGUSR1 on Windows

#: The environment variable that tells a process spawned for a LocalCluster (a Dask worker) its
#: parent's pid: it asks for SIGKILL when that parent dies, as soon as it imports regimemap
#: (:mod:`regimemap.process`), so even while it is still starting.
PARENT_VARIABLE = "REGIMEMAP_DIE_WITH_PARENT"

#: The signals held off while a worker starts.
_HELD = (*_STOP_SIGNALS, STOP_SIGNAL)

class WorkerStopped(BaseException):
    """Raised in a worker's task by :data:`STOP_SIGNAL`: the parent stops the pool, or has died.

    A BaseException (as KeyboardInterrupt): ``except Exception`` does not
    swallow it, and the cleanups of the task (a temporary file removed) run.
    """


class PoolBroken(RuntimeError):
    """A worker process died while it ran a task (killed from outside, or out of memory)."""


def _block_stop_signals() -> object:
    """Block SIGINT, SIGTERM and :data:`STOP_SIGNAL` in this thread; the previous mask."""
    if not hasattr(signal, "pthread_sigmask"):  # pragma: no cover - not POSIX
        return None
    return signal.pthread_sigmask(signal.SIG_BLOCK, _HELD)


def _restore_signals(mask: object) -> None:
    if mask is not None:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)  # type: ignore[arg-type]


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """SIGINT and SIGTERM held off in this thread while the block runs (delivered after it)."""
    mask = _block_stop_signals()
    try:
        yield
    finally:
        _restore_signals(mask)


# -- in the worker ----------------------------------------------------------------------------

#: A worker's :class:`WorkerStopped` lost in a finalizer (a weakref callback of matplotlib's, in
#: the report's figures) is raised again in the code that runs next.
_lost = LostSignals((WorkerStopped,))


def _raise_stopped(signum: int, frame: FrameType | None) -> None:
    """:class:`WorkerStopped`, once: a second stop signal cannot break the cleanup of the first."""
    if _lost.deferred(signum, frame) or (_lost.signum is not None and not _lost.lost):
        return
    _lost.raising(signum)
    raise WorkerStopped(signum)


def _worker_main(conn: Connection, parent: int, others: list[Connection]) -> None:
    """A worker process: run the tasks ``conn`` hands over, one at a time, until told to stop.

    It starts (by fork) with its signals blocked (:class:`WorkerPool`); SIGINT
    and SIGTERM are ignored (the parent decides) and :data:`STOP_SIGNAL`
    raises :class:`WorkerStopped` before they are unblocked.
    """
    for sig in _STOP_SIGNALS:
        signal.signal(sig, signal.SIG_IGN)
    signal.signal(STOP_SIGNAL, _raise_stopped)
    _lost.__enter__()
    for other in others:  # the parent's ends of the other workers' pipes
        other.close()
    try:
        die_with_parent(parent, STOP_SIGNAL)
        if hasattr(signal, "pthread_sigmask"):
            signal.pthread_sigmask(signal.SIG_UNBLOCK, _HELD)
        _serve(conn)
    except (WorkerStopped, EOFError, OSError):
        pass
    finally:
        # no interpreter teardown (atexit, the parent's inherited threads): the parent reaps us
        os._exit(0)


def _serve(conn: Connection) -> None:
    while True:
        task = conn.recv()
        if task is None:
            return
        key, fn, args = task
        try:
            reply = (key, True, fn(*args))
        except WorkerStopped:
            raise
        except BaseException as exc:  # noqa: BLE001 - the task's error is the caller's
            reply = (key, False, exc)
        try:
            data = ForkingPickler.dumps(reply)
        except Exception as exc:  # noqa: BLE001 - a result or an error that does not pickle
            data = ForkingPickler.dumps((key, False, RuntimeError(
                f"{type(exc).__name__}: {exc} (the result of {getattr(fn, '__name__', fn)!r})")))
        conn.send_bytes(data)


# -- in the parent ----------------------------------------------------------------------------

class WorkerPool:
    """``jobs`` worker processes, forked now, each running one task at a time.

    Use it through :func:`worker_pool`.  :meth:`submit` returns a
    :class:`concurrent.futures.Future`; a thread of the pool hands the tasks
    to the idle workers in the order submitted and sets the futures.
    """

    def __init__(self, jobs: int):
        if jobs < 1:
            raise ValueError(f"jobs must be >= 1, got {jobs!r}")
        methods = multiprocessing.get_all_start_methods()
        self._ctx = multiprocessing.get_context("fork" if "fork" in methods else None)
        self._pending: collections.deque[tuple[Future[Any], Callable[..., Any], tuple[Any, ...]]] = \
            collections.deque()
        self._busy: dict[int, Future[Any]] = {}
        self._lock = threading.Lock()
        self._closing = False  # no more tasks: end once the queued ones are done
        self._stopping = False  # end now
        self._broken: PoolBroken | None = None
        self._conns: list[Connection] = []
        self._procs: list[Any] = []
        self._wake_r, self._wake_w = os.pipe()
        parent = os.getpid()
        try:
            with signals_held():  # the workers start with them blocked, until their handlers are set
                for _ in range(jobs):
                    mine, theirs = self._ctx.Pipe(duplex=True)
                    proc = self._ctx.Process(target=_worker_main, args=(theirs, parent, list(self._conns)),
                                             daemon=True, name="regimemap-worker")
                    self._procs.append(proc)
                    proc.start()
                    theirs.close()
                    self._conns.append(mine)
        except BaseException:
            self._reap(kill=True)
            self._release()
            raise
        self._thread = threading.Thread(target=self._dispatch, name="regimemap-pool", daemon=True)
        with signals_held():  # the thread keeps them blocked: the main thread handles them
            self._thread.start()

    @property
    def pids(self) -> list[int]:
        """The workers' process ids."""
        return [int(p.pid) for p in self._procs]

    def submit(self, fn: Callable[..., _T], *args: Any) -> Future[_T]:
        """Run ``fn(*args)`` in a worker (``fn`` a module-level function); its future."""
        future: Future[_T] = Future()
        with self._lock:
            if self._broken is not None:
                raise PoolBroken(str(self._broken))
            if self._closing or self._stopping:
                raise RuntimeError("the pool is closed")
            self._pending.append((future, fn, args))
        self._wake()
        return future

    def _wake(self) -> None:
        with contextlib.suppress(OSError):
            os.write(self._wake_w, b"x")

    def _hand_out(self, idle: list[int]) -> bool:
        """Give queued tasks to the idle workers (under the lock); False once the thread should end."""
        if self._stopping:
            return False
        while idle and self._pending:
            future, fn, args = self._pending.popleft()
            if not future.set_running_or_notify_cancel():
                continue
            try:
                data = ForkingPickler.dumps((id(future), fn, args))
            except Exception as exc:  # noqa: BLE001 - arguments that do not pickle: the caller's error
                future.set_exception(exc)
                continue
            i = idle.pop(0)
            self._busy[i] = future
            self._conns[i].send_bytes(data)  # an idle worker is reading: this does not block
        return not (self._closing and not self._pending and not self._busy)

    def _dispatch(self) -> None:
        """The pool's thread: tasks to idle workers, results to their futures."""
        idle = list(range(len(self._conns)))
        try:
            while True:
                with self._lock:
                    if not self._hand_out(idle):
                        return
                    busy = [self._conns[i] for i in self._busy]
                for r in wait([self._wake_r, *busy]):
                    if r == self._wake_r:
                        os.read(self._wake_r, 4096)
                        continue
                    assert isinstance(r, Connection)
                    i = self._conns.index(r)
                    _, ok, value = r.recv()
                    with self._lock:
                        future = self._busy.pop(i)
                    idle.append(i)
                    if ok:
                        future.set_result(value)
                    else:
                        future.set_exception(value)
        except (EOFError, OSError, ValueError) as exc:  # a worker died, or the pool is being stopped
            with self._lock:
                if self._stopping:
                    return
                self._broken = PoolBroken(f"a worker process died while it ran a task ({type(exc).__name__})")
                futures = list(self._busy.values()) + [f for f, _, _ in self._pending]
                self._pending.clear()
            for future in futures:
                with contextlib.suppress(Exception):  # a running one, or a pending one not cancelled
                    if future.running() or future.set_running_or_notify_cancel():
                        future.set_exception(self._broken)

    def close(self) -> None:
        """End the pool once its tasks are done: each worker is told to stop and reaped."""
        with self._lock:
            self._closing = True
        self._wake()
        self._thread.join()
        for conn in self._conns:
            with contextlib.suppress(OSError, ValueError):
                conn.send(None)
        deadline = time.monotonic() + CLOSE_GRACE
        for proc in self._procs:
            proc.join(max(0.0, deadline - time.monotonic()))
        self._reap(kill=True)
        self._release()

    def stop(self) -> None:
        """Stop the pool now: drop the queued tasks, stop the workers (:data:`STOP_SIGNAL`, then
        SIGKILL after :data:`STOP_GRACE` seconds); Ctrl-C and SIGTERM are held off meanwhile."""
        with signals_held():
            with self._lock:
                self._stopping = True
                while self._pending:
                    self._pending.popleft()[0].cancel()
            self._wake()
            for proc in self._procs:
                with contextlib.suppress(OSError, ValueError, AttributeError):
                    if proc.is_alive():
                        os.kill(proc.pid, STOP_SIGNAL)
            deadline = time.monotonic() + STOP_GRACE
            for proc in self._procs:
                with contextlib.suppress(OSError, ValueError, AttributeError):
                    proc.join(max(0.0, deadline - time.monotonic()))
            self._reap(kill=True)
            self._thread.join(STOP_GRACE)
            self._release()

    def _reap(self, *, kill: bool) -> None:
        """SIGKILL (``kill``) the workers still alive and reap every one."""
        for proc in self._procs:
            with contextlib.suppress(OSError, ValueError, AttributeError):
                if kill and proc.is_alive():
                    proc.kill()
                proc.join(STOP_GRACE)

    def _release(self) -> None:
        for conn in self._conns:
            conn.close()
        for fd in (self._wake_r, self._wake_w):
            with contextlib.suppress(OSError):
                os.close(fd)


def available_cores() -> int:
    """The number of cores this process may run on (at least 1): the default number of workers."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


@contextlib.contextmanager
def worker_pool(jobs: int) -> Iterator[WorkerPool]:
    """A :class:`WorkerPool` of ``jobs`` workers for the block; closed when it ends, stopped at once
    (:meth:`WorkerPool.stop`) if it raises, is interrupted, or is left early (a generator closed
    before its end)."""
    pool = WorkerPool(jobs)
    try:
        yield pool
    except BaseException:
        pool.stop()
        raise
    pool.close()


def _start_resource_tracker() -> None:
    """Start multiprocessing's resource tracker now, on /dev/null.

    Started by the cluster's first worker, it would unblock SIGINT and SIGTERM
    in the thread that spawns the workers.  Its standard streams are not the
    command's: it outlives an interrupted ``regimemap`` by a moment, and would
    write there a warning about the semaphores it cleans up.
    """
    from multiprocessing import resource_tracker

    saved = [os.dup(1), os.dup(2)]
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(null, 1)
            os.dup2(null, 2)
            resource_tracker.ensure_running()
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(null)
    finally:
        for fd in saved:
            os.close(fd)


@contextlib.contextmanager
def local_cluster(jobs: int) -> Iterator[Any]:
    """A Dask ``LocalCluster`` of ``jobs`` single-threaded worker processes, for the block.

    It is started in a thread of its own with SIGINT and SIGTERM blocked: the
    cluster's event loop and the worker processes it spawns inherit that mask,
    so Ctrl-C (SIGINT to the process group) is the parent's alone, and
    interrupts the start as it does any other moment.  The workers leave when
    the parent does (Dask's pipe from the parent, even after ``kill -9``).
    Interrupted, the cluster is closed quietly, at most :data:`STOP_GRACE`
    seconds (the process exits right after).
    """
    _start_resource_tracker()
    was = os.environ.get(PARENT_VARIABLE)
    os.environ[PARENT_VARIABLE] = str(os.getpid())  # inherited by the spawned workers
    with contextlib.ExitStack() as stack:
        stack.callback(_restore_variable, was)
        yield stack.enter_context(_started_cluster(jobs))


def _restore_variable(was: str | None) -> None:
    if was is None:
        os.environ.pop(PARENT_VARIABLE, None)
    else:
        os.environ[PARENT_VARIABLE] = was


@contextlib.contextmanager
def _started_cluster(jobs: int) -> Iterator[Any]:
    from distributed import LocalCluster

    made: dict[str, Any] = {}
    abandoned = threading.Event()

    def start() -> None:
        try:
            # no dashboard; the scheduler's HTTP server on a free port of this machine's loopback,
            # not on 8787 (taken by another cluster: a warning)
            made["cluster"] = LocalCluster(n_workers=jobs, threads_per_worker=1, processes=True,
                                           dashboard_address=None,
                                           scheduler_kwargs={"dashboard": False,
                                                             "dashboard_address": "127.0.0.1:0"})
        except BaseException as exc:  # noqa: BLE001 - handed to the main thread
            made["error"] = exc
            return
        if abandoned.is_set():  # the caller was interrupted while the cluster started
            with contextlib.suppress(Exception):
                made["cluster"].close()

    with signals_held():
        starter = threading.Thread(target=start, name="regimemap-local-cluster", daemon=True)
        starter.start()
    try:
        while starter.is_alive():
            starter.join(0.1)
    except BaseException:
        abandoned.set()
        raise
    if "error" in made:
        raise made["error"]
    cluster = made["cluster"]
    try:
        yield cluster
    except BaseException as exc:
        if not isinstance(exc, Exception):  # an interrupt: no logs of the cluster's teardown
            logging.getLogger("distributed").setLevel(logging.CRITICAL + 1)
        with contextlib.suppress(Exception):
            cluster.close(timeout=STOP_GRACE if not isinstance(exc, Exception) else None)
        raise
    cluster.close()
