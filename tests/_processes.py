"""Helpers of the tests that start ``regimemap`` in its own process group and signal or kill it.

Linux only (/proc).  A command is started as a shell starts a job: in a new session (its own
process group), SIGINT at its default action (the test runner may have it ignored).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

#: Seconds to wait for a run to start (the interpreter, numpy, a design file) on a busy machine.
START_WITHIN = 120.0


def _default_sigint() -> None:
    """In the child: Ctrl-C as a terminal delivers it."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def start(args: list[str], cwd: Path) -> subprocess.Popen[bytes]:
    """``python -m regimemap ARGS`` in ``cwd``, in its own session, its output piped."""
    return subprocess.Popen([sys.executable, "-m", "regimemap", *args], cwd=cwd,
                            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True, preexec_fn=_default_sigint)


def _stat(pid: int | str) -> tuple[str, int, int] | None:
    """(state, parent pid, process group) of a process from /proc, None if it is gone."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = text[text.rindex(")") + 2:].split()
    return fields[0], int(fields[1]), int(fields[2])


def alive(pid: int) -> bool:
    """Whether ``pid`` is a live process (not gone, not a zombie)."""
    st = _stat(pid)
    return st is not None and st[0] not in ("Z", "X")


def group_members(pgid: int) -> list[int]:
    """Live processes of process group ``pgid``."""
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            st = _stat(entry)
            if st is not None and st[2] == pgid and st[0] not in ("Z", "X"):
                out.append(int(entry))
    return out


def descendants(pid: int) -> list[int]:
    """Live descendants of ``pid`` (children, their children ...)."""
    parents: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            st = _stat(entry)
            if st is not None and st[0] not in ("Z", "X"):
                parents.setdefault(st[1], []).append(int(entry))
    out, todo = [], [pid]
    while todo:
        kids = parents.get(todo.pop(), [])
        out += kids
        todo += kids
    return out


def describe(pids: list[int]) -> list[str]:
    """``pid state (name)`` of each live pid, for a failure's message."""
    out = []
    for pid in pids:
        try:
            text = Path(f"/proc/{pid}/stat").read_text()
        except OSError:
            continue
        out.append(text[:text.rindex(")") + 1] + " " + text[text.rindex(")") + 2:].split()[0])
    return out


def wait_until(condition, within: float, step: float = 0.05) -> float | None:  # type: ignore[no-untyped-def]
    """Poll ``condition()`` until true; the seconds it took, or None after ``within`` seconds."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < within:
        if condition():
            return time.monotonic() - t0
        time.sleep(step)
    return time.monotonic() - t0 if condition() else None


def kill_group(pgid: int) -> None:
    """SIGKILL every process of the group (a test's cleanup)."""
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
