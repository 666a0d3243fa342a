"""The one process pool (regimemap.workers): results, errors, stop, signals."""

from __future__ import annotations

import os
import signal
import sys
import time
from concurrent.futures import as_completed
from pathlib import Path

import pytest

from regimemap.workers import STOP_SIGNAL, PoolBroken, WorkerPool, worker_pool

pytestmark = [pytest.mark.subprocess,
              pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork, signals")]


def _square(x: int) -> tuple[int, int]:
    return x * x, os.getpid()


def _fail(x: int) -> None:
    raise ValueError(f"bad {x}")


def _sleep_then_mark(folder: str, seconds: float) -> str:
    """A long task whose cleanup leaves a mark (as an atomic write removes its temporary file)."""
    try:
        Path(folder, "started").touch()
        time.sleep(seconds)
        return "done"
    finally:
        Path(folder, f"cleaned-{os.getpid()}").touch()


class _StoppedWhenCollected:
    """An object whose finalizer gets the stop signal (a weakref callback of matplotlib's did)."""

    def __del__(self) -> None:
        os.kill(os.getpid(), STOP_SIGNAL)  # its handler runs here, inside the finalizer


def _stopped_in_a_finalizer(folder: str) -> str:
    try:
        _StoppedWhenCollected()
        time.sleep(5.0)
        return "carried on"
    finally:
        Path(folder, "cleaned").touch()


def test_results_come_back_in_any_order_from_every_worker() -> None:
    with worker_pool(2) as pool:
        futures = [pool.submit(_square, i) for i in range(20)]
        pids = set(pool.pids)
        got = {f.result()[0] for f in as_completed(futures)}
        used = {f.result()[1] for f in futures}
    assert got == {i * i for i in range(20)}
    assert used <= pids and os.getpid() not in used


def test_a_task_s_error_is_the_caller_s() -> None:
    with worker_pool(2) as pool:
        future = pool.submit(_fail, 3)
        with pytest.raises(ValueError, match="bad 3"):
            future.result()
        assert pool.submit(_square, 4).result()[0] == 16  # the pool carries on


def test_workers_ignore_ctrl_c_and_sigterm(tmp_path: Path) -> None:
    with worker_pool(1) as pool:
        future = pool.submit(_sleep_then_mark, str(tmp_path), 1.0)
        while not (tmp_path / "started").exists():
            time.sleep(0.01)
        for sig in (signal.SIGINT, signal.SIGTERM):
            os.kill(pool.pids[0], sig)
        assert future.result(timeout=60) == "done"


def test_stop_ends_a_running_task_after_its_cleanup(tmp_path: Path) -> None:
    pool = WorkerPool(2)
    futures = [pool.submit(_sleep_then_mark, str(tmp_path), 600.0) for _ in range(4)]
    while not (tmp_path / "started").exists():
        time.sleep(0.01)
    pids = pool.pids
    pool.stop()
    assert all(f.cancelled() for f in futures[2:])
    for pid in pids:  # reaped: no such child any more
        with pytest.raises(ChildProcessError):
            os.waitpid(pid, os.WNOHANG)
    cleaned = {p.name for p in tmp_path.iterdir()} - {"started"}
    assert cleaned and cleaned <= {f"cleaned-{pid}" for pid in pids}


def test_a_stop_lost_in_a_finalizer_still_stops_the_worker_after_its_cleanup(tmp_path: Path, capfd) -> None:
    """Python prints "Exception ignored in" and carries on when a handler raises in a finalizer:
    the worker sends itself the signal again, and its task stops, cleaned up, without a word."""
    start = time.monotonic()
    with pytest.raises(PoolBroken), worker_pool(1) as pool:
        pool.submit(_stopped_in_a_finalizer, str(tmp_path)).result(timeout=60)
    assert time.monotonic() - start < 4.0
    assert (tmp_path / "cleaned").exists()
    err = capfd.readouterr().err
    assert "Exception ignored" not in err and "Traceback" not in err, err


def test_a_worker_killed_breaks_the_pool_with_an_error(tmp_path: Path) -> None:
    with pytest.raises(PoolBroken), worker_pool(1) as pool:
        future = pool.submit(_sleep_then_mark, str(tmp_path), 600.0)
        while not (tmp_path / "started").exists():
            time.sleep(0.01)
        os.kill(pool.pids[0], signal.SIGKILL)
        future.result(timeout=60)
