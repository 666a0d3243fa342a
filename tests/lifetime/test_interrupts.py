"""Ctrl-C and SIGTERM end a lifetime run at once: exit 130 / 143, one line, nothing left behind.

Each test starts ``regimemap lifetime`` in its own process group (as a shell
starts a job), waits until the Monte Carlo run is under way (the ``-v`` log
line of :func:`regimemap.lifetime.parallel.run_chunks`), sends the signal to
the whole group (what Ctrl-C in a terminal does), and checks that the command
exits within seconds with the exit code of the signal, a single line on
standard error and no traceback, that no output or temporary file is left,
and that no process of the group outlives it.  The runs are sized to last
minutes: the signal always comes in the middle.
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from regimemap.caisson.file import example_design_text

from .._processes import START_WITHIN, describe, group_members, start
from ..conftest import band_design

pytestmark = [pytest.mark.subprocess, pytest.mark.slow,
              pytest.mark.skipif(not sys.platform.startswith("linux"), reason="process groups, /proc")]

#: Seconds the command may take to exit after the signal (it hung for minutes before).
EXIT_WITHIN = 10.0


@pytest.fixture
def goda_in_a_folder(tmp_path: Path) -> Path:
    d = tmp_path / "design"
    d.mkdir()
    f = d / "goda.toml"
    f.write_text(example_design_text(), encoding="utf-8")
    return f


def _start(args: list[str], cwd: Path) -> subprocess.Popen[bytes]:
    """``regimemap -v ARGS``: its log says when the run is under way (:func:`_wait_for`)."""
    return start(["-v", *args], cwd)


def _wait_for(proc: subprocess.Popen[bytes], *needles: str) -> bytes:
    """Standard error up to the first line containing every needle (the run has started)."""
    assert proc.stderr is not None
    fd = proc.stderr.fileno()
    seen = b""
    deadline = time.monotonic() + START_WITHIN
    while time.monotonic() < deadline:
        ready, _, _ = select.select([fd], [], [], 1.0)
        if not ready:
            continue
        chunk = os.read(fd, 65536)
        if not chunk:
            break
        seen += chunk
        for line in seen.decode("utf-8", "replace").splitlines():
            if all(n in line for n in needles):
                return seen
    os.killpg(proc.pid, signal.SIGKILL)
    raise AssertionError(f"the run did not start: {seen.decode('utf-8', 'replace')!r}")


def _interrupt(proc: subprocess.Popen[bytes], sig: int, started: bytes, out_dir: Path,
               code: int, message: str, delay: float = 0.5, again: int = 0,
               finished: bool = False) -> None:
    """Send ``sig`` to the group after ``delay`` seconds (and ``again`` more times, 20 ms apart).

    ``finished``: files written whole before the signal may stay (not a temporary file).
    """
    time.sleep(delay)  # mid-chunk
    assert proc.poll() is None, "the run ended before the signal: make it longer"
    os.killpg(proc.pid, sig)
    for _ in range(again):
        time.sleep(0.02)
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:  # all gone already
            break
    try:
        _, rest = proc.communicate(timeout=EXIT_WITHIN)
    except subprocess.TimeoutExpired:
        members = describe(group_members(proc.pid))
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise AssertionError(f"still running {EXIT_WITHIN} s after the signal: {members}") from None
    stderr = (started + rest).decode("utf-8", "replace")
    assert "Traceback" not in stderr, stderr
    assert proc.returncode == code, (proc.returncode, stderr)
    # the -v log lines ("regimemap: [  123 ms] INFO ...") aside, one line: the message
    said = [ln for ln in rest.decode("utf-8", "replace").splitlines()
            if ln.strip() and not ln.startswith("regimemap: [")]
    assert said == [message], stderr
    deadline = time.monotonic() + 5.0
    while group_members(proc.pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert group_members(proc.pid) == [], "a process of the run outlived it"
    left = sorted(os.listdir(out_dir))
    if finished:
        left = [name for name in left if name.startswith(".")]
    assert left == [], "an output or a temporary file was left"


def _lifetime(goda_in_a_folder: Path, *more: str) -> list[str]:
    return ["lifetime", str(goda_in_a_folder), "--trials", "2000000", "-o", "life.png", "-o", "life.csv", *more]


@pytest.mark.parametrize("jobs", [1, 2, 3])
def test_ctrl_c_ends_the_run(goda_in_a_folder: Path, tmp_path: Path, jobs: int) -> None:
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(_lifetime(goda_in_a_folder, "--jobs", str(jobs)), out)
    where = "in this process" if jobs == 1 else f"in {jobs} processes"
    started = _wait_for(proc, "lifetimes of", where)
    _interrupt(proc, signal.SIGINT, started, out, 130, "regimemap: interrupted")


@pytest.mark.parametrize("jobs", [1, 2])
def test_sigterm_ends_the_run(goda_in_a_folder: Path, tmp_path: Path, jobs: int) -> None:
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(_lifetime(goda_in_a_folder, "--jobs", str(jobs), "--quiet"), out)
    where = "in this process" if jobs == 1 else f"in {jobs} processes"
    started = _wait_for(proc, "lifetimes of", where)
    _interrupt(proc, signal.SIGTERM, started, out, 143, "regimemap: terminated")


def test_ctrl_c_twice_is_still_one_line(goda_in_a_folder: Path, tmp_path: Path) -> None:
    """A second Ctrl-C while the first is handled does not break the exit with a traceback."""
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(_lifetime(goda_in_a_folder, "--jobs", "2"), out)
    started = _wait_for(proc, "lifetimes of", "in 2 processes")
    _interrupt(proc, signal.SIGINT, started, out, 130, "regimemap: interrupted", again=3)


@pytest.mark.deep
def test_ctrl_c_during_the_width_bisection(goda_in_a_folder: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(["lifetime", str(goda_in_a_folder), "--trials", "3000", "--width", "10:25:5", "--target", "0.1",
                   "--jobs", "2", "-o", "chart.png"], out)
    started = _wait_for(proc, "lifetimes of", "x 2 widths", "in 2 processes")  # a bisection step
    _interrupt(proc, signal.SIGINT, started, out, 130, "regimemap: interrupted", delay=0.2)


@pytest.mark.deep
def test_ctrl_c_on_a_dask_cluster(goda_in_a_folder: Path, tmp_path: Path) -> None:
    pytest.importorskip("distributed")
    from distributed import LocalCluster

    out = tmp_path / "out"
    out.mkdir()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster:
        proc = _start(_lifetime(goda_in_a_folder, "--scheduler", cluster.scheduler_address), out)
        started = _wait_for(proc, "lifetimes of", "on the Dask scheduler")
        _interrupt(proc, signal.SIGINT, started, out, 130, "regimemap: interrupted", delay=1.0)
        deadline = time.monotonic() + 10.0
        while cluster.scheduler.tasks and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not cluster.scheduler.tasks, "the run's tasks were left on the cluster"


@pytest.mark.deep
def test_ctrl_c_ends_the_figures_pool(tmp_path: Path) -> None:
    """``figures --jobs 2``: the figures not started are not drawn; those drawn are whole."""
    out = tmp_path / "out"
    out.mkdir()
    proc = start(["figures", "--out", str(out), "--format", "png,svg,pdf", "--jobs", "2"], tmp_path)
    deadline = time.monotonic() + START_WITHIN
    while len(group_members(proc.pid)) < 3 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)  # the two workers are up
    _interrupt(proc, signal.SIGINT, b"", out, 130, "regimemap: interrupted", delay=1.0, finished=True)
    assert len(os.listdir(out)) < 60, "every figure was drawn after Ctrl-C"


@pytest.mark.deep
def test_ctrl_c_during_a_climate_band(tmp_path: Path) -> None:
    """The replicate climates of ``[lifetime.record]`` run on the same stoppable pool."""
    d = tmp_path / "design"
    d.mkdir()
    site = band_design(d)
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(["lifetime", str(site), "--trials", "2000", "--jobs", "2", "-o", "band.png"], out)
    started = _wait_for(proc, "lifetimes of", "in this process")  # a replicate, whole in a worker
    _interrupt(proc, signal.SIGINT, started, out, 130, "regimemap: interrupted")


def _numpy_loaded(pid: int) -> bool:
    try:
        return "_multiarray_umath" in Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return False


@pytest.mark.parametrize("sig,code,message", [(signal.SIGINT, 130, "regimemap: interrupted"),
                                              (signal.SIGTERM, 143, "regimemap: terminated")])
def test_a_signal_while_the_process_starts(goda_in_a_folder: Path, tmp_path: Path, sig: int, code: int,
                                           message: str) -> None:
    """During the imports (numpy loading, before the command runs): the same one line and code."""
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(_lifetime(goda_in_a_folder, "--jobs", "2"), out)
    deadline = time.monotonic() + START_WITHIN
    while not _numpy_loaded(proc.pid) and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.002)
    _interrupt(proc, sig, b"", out, code, message, delay=0.0, again=2)


def test_ctrl_c_while_a_local_cluster_starts(tmp_path: Path) -> None:
    """``study --scheduler local``: its workers, still starting, print nothing and are gone."""
    pytest.importorskip("distributed")
    from regimemap.study.file_example import example_study_text

    study = tmp_path / "bw.toml"
    study.write_text(example_study_text(), encoding="utf-8")
    out = tmp_path / "out"
    out.mkdir()
    proc = _start(["study", str(study), "--scheduler", "local", "--jobs", "2", "-q",
                   "--store", str(tmp_path / "bw.store")], out)
    deadline = time.monotonic() + START_WITHIN
    while len(group_members(proc.pid)) < 3 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)  # the resource tracker and a worker at least: the cluster is starting
    _interrupt(proc, signal.SIGINT, b"", out, 130, "regimemap: interrupted", delay=0.0, again=2)
