"""Ctrl-C at random moments, 1 to 5 times, 50 runs across the commands: always one clean exit.

Each case starts a command in its own process group (as a shell starts a job), sends SIGINT to
the group 1 to 5 times at moments drawn from its own seeded stream -- from the start-up (the
imports, counted from the process's first line of regimemap) to well inside the run, the signals 0-300 ms apart -- and checks: exit 130, standard
error ``regimemap: interrupted`` alone (blank lines aside), no traceback or ``Exception
ignored``, no process of the group left, no temporary file, and no output unless whole (a
figure finished before the signal; the study's stored tasks).  The runs are sized to last far
longer than the last signal.  Marked ``stress``: ``make test-stress`` (and CI) runs it, not
``make test``.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text

from .._processes import START_WITHIN, describe, group_members, kill_group, start, wait_until
from ..conftest import band_design

pytestmark = [pytest.mark.stress, pytest.mark.subprocess, pytest.mark.slow,
              pytest.mark.skipif(not sys.platform.startswith("linux"), reason="process groups, /proc")]

#: The root seed of the cases' moments.
SEED = 34
#: Runs in all.
RUNS = 50
#: Seconds the command may take to exit after the last signal (it ends itself within 1.5 s).
EXIT_WITHIN = 15.0


def _design(d: Path) -> Path:
    f = d / "goda.toml"
    f.write_text(example_design_text(), encoding="utf-8")
    return f


def _study(d: Path) -> Path:
    from regimemap.study.file_example import example_study_text

    f = d / "bw.toml"
    f.write_text(example_study_text().replace("trials = 2000 ", "trials = 200000 ", 1), encoding="utf-8")
    return f


#: Each command: its arguments (from the inputs' folder) and the latest first signal (s after
#: numpy is loaded: the rest of the start-up takes ~1 s of it).
COMMANDS = {
    "lifetime": (lambda d: ["lifetime", str(_design(d)), "--trials", "2000000", "--jobs", "2",
                            "-o", "life.png", "-o", "life.csv"], 4.0),
    "chart": (lambda d: ["lifetime", str(_design(d)), "--trials", "200000", "--width", "10:25:5",
                         "--target", "0.1", "--jobs", "2", "-o", "chart.png"], 4.0),
    "band": (lambda d: ["lifetime", str(band_design(d)), "--trials", "2000", "--jobs", "2",
                        "-o", "band.png"], 5.0),
    "study": (lambda d: ["study", str(_study(d)), "--jobs", "2", "--store", "bw.store", "-q"], 5.0),
    "outcome": (lambda d: ["outcome", "--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--mu", "0.5",
                           "--pulse", "half-sine", "--k-peak", "0.3:1.5:121", "--duration", "0.2:1:121",
                           "-o", "m.png", "-o", "m.npz"], 3.0),
    "figures": (lambda d: ["figures", "--out", ".", "--format", "png,svg", "--jobs", "2"], 4.0),
}


def _has_numpy(pid: int) -> bool:
    try:
        return "_multiarray_umath" in Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return False


def _cases() -> list[tuple[int, str]]:
    names = list(COMMANDS)
    return [(i, names[i % len(names)]) for i in range(RUNS)]


def _left_over(out: Path, command: str) -> list[str]:
    """Files of ``out`` that should not be there: temporary ones; outputs, but whole figures
    (``figures``) and the stored tasks of a study."""
    bad = []
    for path in out.rglob("*"):
        rel = path.relative_to(out)
        if path.is_dir():
            continue
        if any(part.startswith(".") for part in rel.parts) or path.suffix == ".part":
            bad.append(str(rel))
        elif command == "figures" and path.name.startswith("fig-"):
            continue
        elif command == "study" and rel.parts[0] == "bw.store":
            continue
        else:
            bad.append(str(rel))
    return bad


@pytest.mark.parametrize("index,command", _cases(), ids=lambda v: str(v))
def test_ctrl_c_at_random_moments(tmp_path: Path, index: int, command: str) -> None:
    rng = np.random.default_rng([SEED, index])
    build, latest = COMMANDS[command]
    inputs = tmp_path / "in"
    inputs.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    args = build(inputs)
    signals = int(rng.integers(1, 6))
    first = float(rng.uniform(0.05, latest))
    gaps = rng.uniform(0.0, 0.3, signals - 1)
    proc = start(args, out)
    try:
        # the moments count from the first line of regimemap (numpy is loaded just after it):
        # Python's own start, before it, is out of the package's reach
        up = wait_until(lambda: _has_numpy(proc.pid) or proc.poll() is not None, START_WITHIN, 0.005)
        assert up is not None and proc.poll() is None, f"{command} did not start"
        time.sleep(first)
        assert proc.poll() is None, f"{command} ended before the first signal ({first:.2f} s): make it longer"
        os.killpg(proc.pid, signal.SIGINT)
        for gap in gaps:
            time.sleep(float(gap))
            try:
                os.killpg(proc.pid, signal.SIGINT)
            except ProcessLookupError:
                break
        try:
            stdout, stderr = proc.communicate(timeout=EXIT_WITHIN)
        except subprocess.TimeoutExpired:
            members = describe(group_members(proc.pid))
            raise AssertionError(f"still running {EXIT_WITHIN} s after the signals: {members}") from None
    finally:
        kill_group(proc.pid)
        if proc.returncode is None:
            proc.communicate()
    text = stderr.decode("utf-8", "replace")
    where = f"{command}, {signals} signal(s) from {first:.2f} s"
    assert "Traceback" not in text and "Exception ignored" not in text, (where, text)
    assert proc.returncode == 130, (where, proc.returncode, text)
    said = [ln for ln in text.splitlines() if ln.strip()]
    # a note printed before the signal (outcome's "simulating ... runs") may come first
    assert said[-1:] == ["regimemap: interrupted"] and said.count(said[-1]) == 1, (where, text)
    gone = wait_until(lambda: not group_members(proc.pid), 5.0)
    assert gone is not None, (where, "a process of the run outlived it", describe(group_members(proc.pid)))
    assert _left_over(out, command) == [], (where, "left behind")
