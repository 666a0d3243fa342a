"""No worker outlives its parent: ``kill -9`` of ``regimemap`` ends every process it started.

Each test starts a run in its own process group, waits until its workers exist (the parent's
descendants in /proc) and the run is under way, kills the parent with SIGKILL (no cleanup of
its own can run) and checks that every process it had started is gone within
:data:`GONE_WITHIN` seconds: the pool's workers by their parent-death signal
(:func:`regimemap.process.die_with_parent`), a LocalCluster's by Dask's pipe from
the parent.  Polled every 50 ms; the seconds it took are in the failure message.
"""

from __future__ import annotations

import os
import signal
import sys
from pathlib import Path

import pytest

from .._processes import START_WITHIN, alive, descendants, describe, kill_group, start, wait_until

pytestmark = [pytest.mark.subprocess, pytest.mark.slow,
              pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc, prctl")]

#: Seconds every worker has to end once the parent is killed.
GONE_WITHIN = 5.0


def _kill_parent_and_check(proc, workers: int, ready=lambda: True) -> None:  # type: ignore[no-untyped-def]
    try:
        took = wait_until(lambda: proc.poll() is None and len(descendants(proc.pid)) >= workers
                          and ready(), START_WITHIN)
        assert took is not None, f"the run's {workers} workers never appeared ({proc.poll()!r})"
        assert proc.poll() is None, "the run ended before the test killed it: make it longer"
        children = descendants(proc.pid)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        gone = wait_until(lambda: not any(alive(p) for p in children), GONE_WITHIN)
        left = describe([p for p in children if alive(p)])
        assert gone is not None, f"{len(left)} of {len(children)} processes outlived their parent: {left}"
        print(f"{len(children)} processes gone {gone:.2f} s after the parent's SIGKILL")  # -s shows it
    finally:
        kill_group(proc.pid)
        proc.communicate()


def test_lifetime_workers_die_with_their_parent(goda: Path, tmp_path: Path) -> None:
    proc = start(["lifetime", str(goda), "--trials", "2000000", "--jobs", "2", "-q", "-o", "l.csv"], tmp_path)
    _kill_parent_and_check(proc, 2)


def _study(tmp_path: Path, trials: int) -> Path:
    from regimemap.study.file_example import example_study_text

    text = example_study_text()
    f = tmp_path / "bw.toml"
    f.write_text(text.replace("trials = 2000 ", f"trials = {trials} ", 1), encoding="utf-8")
    assert f"trials = {trials} " in f.read_text(encoding="utf-8")
    return f


def test_study_workers_die_with_their_parent(tmp_path: Path) -> None:
    proc = start(["study", str(_study(tmp_path, 200000)), "--jobs", "2", "-q"], tmp_path)
    _kill_parent_and_check(proc, 2)


@pytest.mark.deep
def test_local_cluster_dies_with_its_parent(tmp_path: Path) -> None:
    """``--scheduler local``: the scheduler and nannies live in the parent, the workers follow it
    once a task has been stored (a worker still starting ends when it first watches its parent)."""
    pytest.importorskip("distributed")
    store = tmp_path / "bw.store"
    proc = start(["study", str(_study(tmp_path, 3000)), "--scheduler", "local", "--jobs", "2", "-q",
                  "--store", str(store)], tmp_path)
    _kill_parent_and_check(proc, 2, ready=lambda: (store / "tasks").is_dir() and len(os.listdir(store / "tasks")) > 0)
