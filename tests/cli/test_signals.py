"""SIGINT and SIGTERM while a command runs in this process (regimemap.cli._signals.stop_signals).

The real process (a Monte Carlo run killed from outside) is tested in
tests/lifetime/test_interrupts.py; here the signal is sent to this process
from inside a command, and the handlers are checked to be put back.
"""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path

import pytest

import regimemap.caisson.file
from regimemap.caisson.file import example_design_text
from regimemap.cli._signals import Terminated, stop_signals

from ..conftest import invoke_cli

pytestmark = pytest.mark.skipif(not hasattr(signal, "SIGTERM") or os.name != "posix", reason="POSIX signals")


def _signal_while_reading(monkeypatch, sig: int, times: int = 1) -> list[str]:
    """Make reading the design file send ``sig`` to this process ``times`` times; what ran after."""
    after: list[str] = []

    def read(path):
        for _ in range(times):
            os.kill(os.getpid(), sig)
            time.sleep(0.01)  # the handler runs here, at the latest
        after.append("not interrupted")
        raise AssertionError("the signal did not stop the command")

    monkeypatch.setattr(regimemap.caisson.file, "read_design", read)
    return after


@pytest.fixture
def design(tmp_path: Path) -> Path:
    f = tmp_path / "goda.toml"
    f.write_text(example_design_text(), encoding="utf-8")
    return f


@pytest.mark.parametrize("sig,code,message", [(signal.SIGTERM, 143, "regimemap: terminated"),
                                              (signal.SIGINT, 130, "regimemap: interrupted")])
def test_a_signal_ends_the_command_with_its_code(monkeypatch, tmp_path, design, sig, code, message):
    # as a terminal's Ctrl-C reaches an interactive process (a background job's SIGINT is ignored,
    # and stays so: test_an_ignored_sigint_stays_ignored)
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _run_and_check(monkeypatch, tmp_path, design, sig, code, message)
    finally:
        signal.signal(signal.SIGINT, old)


def _run_and_check(monkeypatch, tmp_path, design, sig, code, message):
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    after = _signal_while_reading(monkeypatch, sig, times=3)
    out = tmp_path / "life.csv"
    r = invoke_cli(["lifetime", str(design), "--trials", "100", "-o", str(out)])
    assert r.code == code, r.output
    assert [ln for ln in r.stderr.splitlines() if ln.strip()] == [message]
    assert "Traceback" not in r.output and after == []
    assert not out.exists()
    # the second and third signals were swallowed while the first was handled; the handlers are back
    assert {s: signal.getsignal(s) for s in before} == before


@pytest.mark.parametrize("sig,code,message", [(signal.SIGTERM, 143, "regimemap: terminated"),
                                              (signal.SIGINT, 130, "regimemap: interrupted")])
def test_a_signal_that_became_another_error_still_ends_the_command_as_the_signal(
        monkeypatch, design, sig, code, message):
    """Ctrl-C landing in a C extension's module initialization comes back as ``ImportError:
    initialization failed`` (seen under load in the stress test): still the signal's exit."""
    def read(path):
        try:
            os.kill(os.getpid(), sig)
            time.sleep(1.0)
        except BaseException:
            raise ImportError("initialization failed") from None

    monkeypatch.setattr(regimemap.caisson.file, "read_design", read)
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        r = invoke_cli(["lifetime", str(design), "--trials", "100"])
    finally:
        signal.signal(signal.SIGINT, old)
    assert r.code == code, r.output
    assert [ln for ln in r.stderr.splitlines() if ln.strip()] == [message]


class _SignalledWhenCollected:
    """An object whose finalizer gets a signal (as matplotlib's weakref callbacks did under load)."""

    def __init__(self, sig: int) -> None:
        self.sig = sig

    def __del__(self) -> None:
        os.kill(os.getpid(), self.sig)  # its handler runs here, inside the finalizer


@pytest.mark.parametrize("sig,kind", [(signal.SIGINT, KeyboardInterrupt), (signal.SIGTERM, Terminated)])
def test_a_signal_lost_in_a_finalizer_is_raised_in_the_code_that_runs_next(capfd, sig, kind):
    """Python prints "Exception ignored in" and carries on when a handler raises in a finalizer:
    the signal is sent again, and the command's code stops without a word on stderr.  SIGINT is
    handled as in a terminal's foreground even when the suite runs as a background job (where
    it starts ignored, and :func:`stop_signals` rightly keeps it so)."""
    carried_on = False
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    start = time.monotonic()
    try:
        with pytest.raises(kind), stop_signals():
            _SignalledWhenCollected(sig)
            time.sleep(5.0)
            carried_on = True
    finally:
        signal.signal(signal.SIGINT, old)
    assert not carried_on and time.monotonic() - start < 4.0
    err = capfd.readouterr().err
    assert "Exception ignored" not in err and "Traceback" not in err, err


def test_an_error_without_a_signal_is_that_error():
    with pytest.raises(ImportError, match="initialization failed"), stop_signals():
        raise ImportError("initialization failed")


def test_exiting_leaves_both_signals_ignored():
    """The console process, once interrupted, ignores further signals until it has exited."""
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        with pytest.raises(Terminated), stop_signals(exiting=True):
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(1.0)
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
        assert signal.getsignal(signal.SIGTERM) is signal.SIG_IGN
    finally:
        for s, h in before.items():
            signal.signal(s, h)


def test_without_a_signal_the_handlers_are_restored_even_when_exiting():
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    with stop_signals(exiting=True):
        assert signal.getsignal(signal.SIGTERM) is not before[signal.SIGTERM]
    assert {s: signal.getsignal(s) for s in before} == before


def test_an_ignored_sigint_stays_ignored():
    """A command started with SIGINT ignored (nohup, a script's background job) keeps it so."""
    old = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with stop_signals():
            assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, old)


@pytest.mark.parametrize("argv,console", [
    (["/venv/bin/python", "/venv/bin/regimemap", "lifetime", "x.toml"], True),
    (["python", "-m", "regimemap", "plot"], True),
    (["python", "-X", "importtime", "-mregimemap"], True),
    (["python", "-m", "pytest", "tests"], False),
    (["python", "-c", "import regimemap"], False),
    (["python", "script.py", "regimemap"], False),
    (["python"], False),
])
def test_only_the_regimemap_process_exits_on_a_signal_at_start(monkeypatch, argv, console):
    """regimemap.process acts in the command's own process only, never in a program importing it."""
    from regimemap import process

    monkeypatch.setattr(sys, "orig_argv", argv, raising=False)
    assert process.is_console() is console
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    if not console:
        process.exit_on_signal_at_start()
        assert {s: signal.getsignal(s) for s in before} == before
