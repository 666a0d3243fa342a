"""The command line never crashes and never leaves a broken file (GitHub issue 5).

* every bad argument is one line on stderr, no traceback; usage errors exit 2,
  failures while running exit 1, an interrupt exits 130;
* every command that writes a file writes it atomically: when the writer fails
  half-way (disk full, an exception in savefig, Ctrl-C) the target is the old
  file, byte for byte, or absent, and no temporary file is left in the folder;
* random arguments (hypothesis) to every registered command give exit 0, 1 or
  2 and never a traceback.

The commands are run in-process through :func:`regimemap.cli._main.run_main`
(what the ``regimemap`` console script does), see ``tests/conftest.py``.
"""

from __future__ import annotations

import builtins
import contextlib
import errno
import math
import os
import re
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from regimemap.cli import cli, main

from .._writers import (
    FAILURES,
    OLD,
    SINGLE_FILE_WRITERS,
    FifoReader,
    WriteFailure,
    WriteSpy,
    check_complete,
    folder_state,
    guarded_dev_null,
    make_device,
    writer_args,
    writer_params,
)
from ..conftest import invoke_cli

# Where each command is defined (for the skip message while it is being written).
COMMAND_MODULES = {"plot": "plot", "figure": "plot", "figures": "plot", "classify": "query",
                   "export": "export", "atlas": "atlas", "animate": "atlas"}


def needs(command: str) -> None:
    if command not in cli.commands:
        pytest.skip(f"command {command!r} is not registered yet "
                    f"(src/regimemap/cli/{COMMAND_MODULES.get(command, '?')}.py)")


def assert_clean_failure(r, code: int, pattern: str | None = None) -> str:
    """Exit ``code``, exactly one error line on stderr (matching ``pattern``), no traceback."""
    assert "Traceback" not in r.output, r.output
    assert r.code == code, (r.code, r.output)
    lines = r.error_lines()
    assert len(lines) == 1, r.stderr
    line = lines[0]
    assert line.startswith("regimemap"), line
    if pattern is not None:
        assert re.search(pattern, line), line
    return line


# -- inputs ---------------------------------------------------------------------------------------------

@pytest.fixture
def inputs(tmp_path):
    folder = tmp_path / "inputs"
    folder.mkdir()
    (folder / "good.csv").write_text("k,mu,name\n0.1,0.5,a\n0.5,0.8,b\n")
    (folder / "bad.csv").write_text("k,mu\n0.1,0.5\n0.2,lots\n")
    (folder / "neg.csv").write_text("k,mu\n-0.1,0.5\n")
    (folder / "nomu.csv").write_text("k,nu\n0.1,0.5\n")
    (folder / "gamma0.csv").write_text("k,mu,gamma\n0.1,0.5,0\n")
    (folder / "kprime2.csv").write_text("k,mu,kprime\n0.1,0.5,2\n")
    (folder / "empty.csv").write_text("")
    (folder / "binary.csv").write_bytes(bytes(range(256)) * 4)
    (folder / "a-file").write_text("I am a file")
    return folder


# -- usage errors: exit 2, one line naming the option ---------------------------------------------------

G = ["--gamma", "3", "--kprime", "0.4"]

USAGE_ERRORS = [
    # (command, args, regex the error line must match)
    ("plot", ["--gamma", "0", "--kprime", "0.4"], r"'--gamma': gamma must be a finite number in \[0.001, 1000\], got '0'"),
    ("plot", ["--gamma", "-3", "--kprime", "0.4"], r"'--gamma': .*got '-3'"),
    ("plot", ["--gamma", "nan", "--kprime", "0.4"], r"'--gamma': .*got 'nan'"),
    ("plot", ["--gamma", "inf", "--kprime", "0.4"], r"'--gamma': .*got 'inf'"),
    ("plot", ["--gamma", "-inf", "--kprime", "0.4"], r"'--gamma': .*got '-inf'"),
    ("plot", ["--gamma", "1e308", "--kprime", "0.4"], r"'--gamma': .*got '1e308'"),
    ("plot", ["--gamma", "three", "--kprime", "0.4"], r"'--gamma': .*got 'three' \(not a number\)"),
    ("plot", ["--gamma", "", "--kprime", "0.4"], r"'--gamma': .*got ''"),
    ("plot", ["--kprime", "0.4"], r"Missing option '--gamma'"),
    ("plot", ["--gamma", "3"], r"Missing option '--kprime'"),
    ("plot", ["--gamma", "3", "--kprime", "1.5"], r"'--kprime': kprime must be a number in \[-1, 1\], got '1.5'"),
    ("plot", ["--gamma", "3", "--kprime", "-1.0001"], r"'--kprime': .*got '-1.0001'"),
    ("plot", ["--gamma", "3", "--kprime", "nan"], r"'--kprime': .*got 'nan'"),
    ("plot", ["--gamma", "3", "--kprime", "x"], r"'--kprime': .*not a number"),
    ("plot", G + ["--k-max", "0"], r"'--k-max': .*in \[1e-06, 1e\+06\].*got '0'"),
    ("plot", G + ["--mu-max", "1e-20"], r"'--mu-max': .*in \[1e-06, 1e\+06\].*got '1e-20'"),
    ("plot", G + ["--k-max", "-1"], r"'--k-max': .*got '-1'"),
    ("plot", G + ["--mu-max", "0"], r"'--mu-max': .*got '0'"),
    ("plot", G + ["--mu-max", "nan"], r"'--mu-max': .*got 'nan'"),
    ("plot", G + ["--k-max", "1e308"], r"'--k-max': .*1e\+06\].*got '1e308'"),
    ("plot", G + ["--resolution", "5001"], r"'--resolution': resolution must be a whole number in \[2, 5000\]"),
    ("plot", G + ["--resolution", "1"], r"'--resolution'"),
    ("plot", G + ["--resolution", "2.5"], r"'--resolution'"),
    ("plot", G + ["--dpi", "0"], r"'--dpi'"),
    ("plot", G + ["--dpi", "1e9"], r"'--dpi'"),
    ("plot", G + ["--format", "bmp"], r"'--format': unknown format 'bmp'"),
    ("plot", G + ["-o", "map.bmp"], r"unknown file suffix \.bmp"),
    ("plot", G + ["-o", "map.svg", "--format", "pdf"], r"does not match --format"),
    ("plot", G + ["--modes", "XX"], r"'--modes': unknown mode 'XX'"),
    ("plot", G + ["--modes", "RO'"], r"'--modes': mode RO' appears only on the map of a loaded block"),
    ("plot", G + ["--point", "a,b"], r"'--point': point 'a,b': k must be"),
    ("plot", G + ["--point", "-1,2"], r"'--point': .*got '-1'"),
    ("plot", G + ["--point", "1"], r"'--point': point '1' must be K,MU"),
    ("plot", G + ["--bogus"], r"No such option '--bogus'"),
    ("figure", ["9.9"], r"no figure '9.9' in the report\. Did you mean 3\.9"),
    ("figure", ["3.9"], r"no figure '3.9' in the report\. Did you mean .*3\.9[ab]"),
    ("figure", ["4.7"], r"Did you mean .*4\.7[ab]"),
    ("figure", ["fig"], r"no figure 'fig' in the report"),
    ("figure", [], r"Missing argument 'FIGURE_ID'"),
    ("figure", ["3.9a", "--format", "gif"], r"'--format': unknown format 'gif'"),
    ("figures", ["--format", "bmp"], r"'--format': unknown format 'bmp'"),
    ("figures", ["--format", ","], r"'--format': no format given"),
    ("classify", ["--gamma", "3", "--kprime", "0.4", "--k", "-1", "--mu", "0.5"], r"'--k': k must be a finite number in \[0, 1e\+100\], got '-1'"),
    ("classify", ["--gamma", "3", "--kprime", "0.4", "--k", "0.5", "--mu", "nan"], r"'--mu': mu must be"),
    ("classify", ["--gamma", "3", "--kprime", "0.4", "--k", "0.5"], r"missing option\(s\) --mu"),
    ("classify", ["--gamma", "0", "--kprime", "0.4", "--k", "0.5", "--mu", "1"], r"'--gamma'"),
    ("export", G + ["-o", "map.txt"], r"unknown file suffix \.txt in 'map\.txt'; use \.npz, \.csv or \.json"),
    ("export", G + ["-o", "map.npz", "--format", "xyz"], r"'--format'"),
    ("export", G, r"Missing option '-o' / '--output'"),
    ("export", G + ["--k-max", "0", "-o", "m.npz"], r"'--k-max'"),
    ("export", G + ["--resolution", "100000", "-o", "m.npz"], r"'--resolution'"),
    ("atlas", ["--gamma", "1,0", "--kprime", "0", "-o", "a.png"], r"'--gamma'"),
    ("atlas", ["--gamma", "1", "--kprime", "0,2", "-o", "a.png"], r"'--kprime'"),
    ("atlas", ["--gamma", "1:2:7", "--kprime", "-1:1:7", "-o", "a.png"], r"49 panels exceed the limit of 48"),
    ("atlas", ["--gamma", "1", "--kprime", "0", "-o", "a.gif"], r"unknown file suffix \.gif"),
    ("animate", ["--gamma", "3", "--kprime", "0:1:3", "-o", "a.png"], r"unknown file suffix \.png.*use \.gif for the animation"),
    ("animate", ["--gamma", "3", "--kprime", "0:1:100000", "-o", "a.gif"], r"'--kprime'"),
    ("animate", ["--gamma", "3", "--kprime", "0:1:3", "--fps", "0", "-o", "a.gif"], r"'--fps'"),
    ("classify", G + ["--k", "1e308", "--mu", "0.5"], r"'--k': k must be a finite number in \[0, 1e\+100\], got '1e308'"),
    ("classify", G + ["--k", "0.5", "--mu", "-1"], r"'--mu': mu must be a finite number in \[0, 1e\+100\], got '-1'"),
    # a block that weighs nothing at every push (buoyancy + uplift = 1, no uplift ratio) has no map
    ("plot", G + ["--uplift", "1"], r"'--uplift': uplift must not be 1 - buoyancy when uplift_ratio is 0"),
    ("export", G + ["--buoyancy", "0.3", "--uplift", "0.7", "-o", "m.json"],
     r"'--uplift': .*got buoyancy 0\.3 \+ uplift 0\.7 = 1"),
    ("classify", G + ["--uplift", "0.5", "--buoyancy", "0.5", "--k", "0.1", "--mu", "0.5"], r"'--uplift'"),
    ("atlas", ["--gamma", "3", "--kprime", "0.4", "--uplift", "0:1:3", "-o", "a.png"],
     r"uplift must not be 1 - buoyancy"),
    ("animate", ["--gamma", "3", "--kprime", "0.4", "--uplift", "0:1:3", "-o", "a.gif"],
     r"uplift must not be 1 - buoyancy"),
    # outcome's required inputs: left out, each is named (not a numpy message from the step count)
    ("outcome", ["--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--pulse", "half-sine",
                 "--k-peak", "0.2:1.2:6", "--duration", "0.1:1:6", "-o", "o.svg"], r"Missing option '--mu'"),
    ("outcome", ["--gamma", "3", "--mu", "0.5", "--kprime", "0", "--pulse", "half-sine",
                 "--k-peak", "0.2:1.2:6", "--duration", "0.1:1:6", "-o", "o.svg"],
     r"Missing option '--half-width'"),
]


@pytest.mark.parametrize("command,args,pattern", USAGE_ERRORS,
                         ids=[f"{c}-{i}" for i, (c, _, _) in enumerate(USAGE_ERRORS)])
def test_usage_errors(tmp_path, monkeypatch, command, args, pattern):
    needs(command)
    monkeypatch.chdir(tmp_path)
    r = invoke_cli([command, *args])
    line = assert_clean_failure(r, 2, pattern)
    assert line.startswith(f"regimemap {command}: error: ") and line.endswith(f"(see 'regimemap {command} --help')")
    assert list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize("args,pattern", [
    (["bogus"], r"No such command 'bogus'"),
    (["--bogus"], r"No such option"),
    (["plot", "--gamma"], r"^regimemap plot: error: Option '--gamma' requires an argument"),
    (["export", "--gamma", "3", "--kprime"], r"^regimemap export: error: Option '--kprime' requires"),
    (["plot", "--help"], None),
])
def test_group_usage_errors(args, pattern):
    r = invoke_cli(args)
    if pattern is None:
        assert r.code == 0 and "Usage" in r.stdout
    else:
        assert_clean_failure(r, 2, pattern)


def test_help_and_version():
    for args in (["--help"], ["-h"], ["--version"], *[[c, "--help"] for c in cli.commands]):
        r = invoke_cli(args)
        assert r.code == 0 and r.stderr == "" and r.stdout, args


# -- output paths --------------------------------------------------------------------------------------

@pytest.mark.parametrize("key", writer_params())
@pytest.mark.slow
def test_writer_goes_through_the_atomic_path_and_leaves_only_its_file(tmp_path, inputs, monkeypatch, key):
    """Each writer's file is renamed into place from a temporary file beside it (what
    tests/io/test_atomic.py proves safe against every failure), and is whole."""
    needs(SINGLE_FILE_WRITERS[key][0])
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    args, target = writer_args(key, out_dir / "result", inputs)
    spy = WriteSpy(out_dir).install(monkeypatch)
    r = invoke_cli(args)
    monkeypatch.undo()
    assert r.code == 0, r.output
    assert "Traceback" not in r.output
    assert sorted(p.name for p in out_dir.iterdir()) == [target.name]
    check_complete(target)
    spy.assert_atomic(target)


BAD_OUTPUTS = [
    # (how to make the output path from tmp_path, regex)
    ("missing folder", lambda t: t / "missing" / "result", r"folder '.*missing' does not exist"),
    ("parent is a file", lambda t: t / "inputs" / "a-file" / "result", r"folder '.*a-file' is a file, not a folder"),
    ("read-only /proc", lambda t: Path("/proc/regimemap-test-result"), r"folder '/proc' is not writable"),
    ("read-only /sys", lambda t: Path("/sys/regimemap-test-result"), r"folder '/sys' is not writable"),
]


@pytest.mark.parametrize("key", ["plot-png", "figure-svg", "classify-csv", "export-npz", "atlas-png",
                                 "animate-gif"])
@pytest.mark.parametrize("what,make,pattern", BAD_OUTPUTS, ids=[b[0] for b in BAD_OUTPUTS])
def test_bad_output_folder_is_a_usage_error(tmp_path, inputs, key, what, make, pattern):
    needs(SINGLE_FILE_WRITERS[key][0])
    out = make(tmp_path)
    if str(out).startswith(("/proc", "/sys")) and not out.parent.is_dir():
        pytest.skip(f"no {out.parent} here")
    args, _ = writer_args(key, out, inputs)
    r = invoke_cli(args)
    assert_clean_failure(r, 2, pattern)


@pytest.mark.parametrize("key", ["plot-svg", "export-json", "classify-csv"])
def test_output_is_a_folder(tmp_path, inputs, key):
    needs(SINGLE_FILE_WRITERS[key][0])
    args, target = writer_args(key, tmp_path / "result", inputs)
    target.mkdir()
    r = invoke_cli(args)
    assert_clean_failure(r, 2, r"is a (folder|directory)")
    assert target.is_dir() and list(target.iterdir()) == []


def test_unwritable_folder_by_access(tmp_path, inputs, monkeypatch):
    """Permission bits (as seen by os.access) refusing writes: a usage error, nothing written."""
    needs("export")
    out = tmp_path / "out"
    out.mkdir()
    real_access = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: False if Path(p) == out else real_access(p, mode, **kw))
    args, _ = writer_args("export-npz", out / "map", inputs)
    assert_clean_failure(invoke_cli(args), 2, r"folder '.*out' is not writable")
    assert list(out.iterdir()) == []


@pytest.mark.parametrize("make,pattern", [
    (lambda t: t / "missing" / "deeper", r"'--out': folder '.*deeper' does not exist"),
    (lambda t: t / "inputs" / "a-file", r"'--out': .*a-file"),
])
def test_figures_bad_out_folder(tmp_path, inputs, make, pattern):
    needs("figures")
    assert_clean_failure(invoke_cli(["figures", "--out", str(make(tmp_path)), "--format", "svg"]), 2, pattern)


@pytest.mark.render
def test_figures_creates_a_missing_out_folder_whose_parent_exists(tmp_path, monkeypatch):
    needs("figures")
    import regimemap.maps.figures.presets as figs

    # two of the report's figures are enough to see the folder made and filled (test_cli_plot.py
    # draws all of them)
    monkeypatch.setattr(figs, "PRESETS", dict(list(figs.PRESETS.items())[:2]))
    out = tmp_path / "new"
    r = invoke_cli(["figures", "--out", str(out), "--format", "svg", "--jobs", "1"])
    assert r.code == 0, r.output
    assert r.stderr == ""
    written = r.stdout.splitlines()
    assert len(written) == len(list(out.iterdir())) and all(Path(p).is_file() for p in written)


def test_proc_message_names_the_real_cause():
    assert_clean_failure(invoke_cli(["plot", "--gamma", "3", "--kprime", "0.4", "-o", "/proc/x.png"]),
                         2, r"virtual proc file system")


def test_figures_out_read_only_folder_is_a_usage_error():
    needs("figures")
    assert_clean_failure(invoke_cli(["figures", "--out", "/proc", "--format", "svg"]), 2, "not writable")


def test_figures_out_unwritable_by_access(tmp_path, monkeypatch):
    needs("figures")
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: False)
    assert_clean_failure(invoke_cli(["figures", "--out", str(tmp_path), "--format", "svg"]), 2,
                         r"'--out': folder .* is not writable")
    assert list(tmp_path.iterdir()) == []


# -- devices and FIFOs: written into, never replaced ---------------------------------------------------

@pytest.mark.parametrize("key", ["export-csv", "export-npz", "export-json", "plot-png", "plot-svg"])
def test_output_into_a_fifo(tmp_path, inputs, key):
    """A FIFO gets the whole file (a PNG and an npz are made whole first: both seek) and stays one."""
    needs(SINGLE_FILE_WRITERS[key][0])
    args, target = writer_args(key, tmp_path / "result", inputs)
    reader = FifoReader(target)
    r = invoke_cli(args)
    data = reader.join()
    assert r.code == 0 and "Traceback" not in r.output, r.output
    assert target.is_fifo() and sorted(p.name for p in tmp_path.iterdir()) == ["inputs", target.name]
    copy = tmp_path / f"copy{target.suffix}"
    copy.write_bytes(data)
    check_complete(copy)


def test_output_to_a_full_device_is_one_line(tmp_path, inputs):
    """A device that refuses the bytes (a /dev/full, made in tmp_path): the write failure's one line,
    exit 1, and the device is still there."""
    full = make_device(tmp_path, "full", 7)
    r = invoke_cli(["export", "--gamma", "3", "--kprime", "0.4", "--resolution", "5", "-o", str(full),
                    "--format", "csv"])
    assert_clean_failure(r, 1, r"^regimemap: error: cannot write .*full: No space left on device$")
    assert stat.S_ISCHR(full.stat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["full", "inputs"]


@pytest.mark.parametrize("args", [
    ["export", "--gamma", "3", "--kprime", "0.4", "--resolution", "5", "-o", "/dev/null", "--format", "csv"],
    ["plot", "--gamma", "3", "--kprime", "0.4", "--resolution", "20", "-o", "/dev/null"],  # no .png added
    ["plot", "--gamma", "3", "--kprime", "0.4", "--resolution", "20", "-o", "/dev/null", "--format", "svg"],
], ids=["export", "plot", "plot-format"])
def test_output_to_dev_null(args, monkeypatch):
    """-o /dev/null: the command runs and /dev/null stays the device, even where /dev accepts no new
    file (os.access says no for it, as for anyone but root)."""
    real_access = os.access
    monkeypatch.setattr(os, "access",
                        lambda p, mode, **kw: False if str(p) == "/dev" else real_access(p, mode, **kw))
    with guarded_dev_null():
        r = invoke_cli(args)
    assert r.code == 0 and "Traceback" not in r.output, r.output
    assert r.stdout.splitlines()[-1] == "/dev/null"


# -- points files --------------------------------------------------------------------------------------

POINTS_ERRORS = [
    ("bad.csv", r"bad\.csv, line 3, column mu: mu must be a finite number >= 0 \(at most 1e\+100\), got 'lots'"),
    ("neg.csv", r"neg\.csv, line 2, column k: k must be a finite number >= 0 \(at most 1e\+100\), got '-0.1'"),
    ("nomu.csv", r"nomu\.csv, line 1: missing column\(s\) mu"),
    ("gamma0.csv", r"gamma0\.csv, line 2, column gamma: gamma must be"),
    ("kprime2.csv", r"kprime2\.csv, line 2, column kprime: kprime must be a number in \[-1, 1\]"),
    ("empty.csv", r"empty\.csv: empty file"),
    ("binary.csv", r"binary\.csv: not a UTF-8 text file \(byte 0x80; save it as UTF-8\)"),
    ("missing.csv", r"missing\.csv"),
    ("", r"'--points'"),
]


@pytest.mark.parametrize("command", ["classify", "plot"])
@pytest.mark.parametrize("name,pattern", POINTS_ERRORS, ids=[p[0] or "folder" for p in POINTS_ERRORS])
def test_bad_points_file(tmp_path, inputs, monkeypatch, command, name, pattern):
    needs(command)
    monkeypatch.chdir(tmp_path)
    path = str(inputs / name) if name else str(inputs)  # "" -> the folder itself
    args = [command, "--points", path, *G]
    if command == "plot":
        args += ["-o", str(tmp_path / "map.svg")]
    line = assert_clean_failure(invoke_cli(args), 2, pattern)
    assert "'--points'" in line
    assert not (tmp_path / "map.svg").exists()


# -- how run_main reports failures ----------------------------------------------------------------------

def _break(monkeypatch, exc: BaseException):
    """Make the library call of 'export' raise ``exc``."""
    import regimemap.maps.record_export

    def boom(*a, **k):
        raise exc

    monkeypatch.setattr(regimemap.maps.record_export, "export_map", boom)


@pytest.mark.parametrize("exc,code,pattern", [
    (RuntimeError("a bug\nover two lines"), 1, r"^regimemap: internal error: RuntimeError: a bug over two lines"),
    (ZeroDivisionError("float division by zero"), 1, r"^regimemap: internal error: ZeroDivisionError"),
    (ValueError("bad value"), 1, r"^regimemap: error: bad value$"),
    (OSError(errno.ENOSPC, "No space left on device"), 1, r"No space left on device"),
    (MemoryError(), 1, r"internal error: MemoryError"),
    (KeyboardInterrupt(), 130, r"^regimemap: interrupted$"),
])
def test_run_main_failures_are_one_line(tmp_path, inputs, monkeypatch, exc, code, pattern):
    needs("export")
    _break(monkeypatch, exc)
    args, target = writer_args("export-npz", tmp_path / "map", inputs)
    assert_clean_failure(invoke_cli(args), code, pattern)
    assert not target.exists()


def test_broken_pipe_exits_1_silently(monkeypatch, tmp_path, inputs):
    needs("export")
    _break(monkeypatch, BrokenPipeError(errno.EPIPE, "Broken pipe"))
    args, _ = writer_args("export-npz", tmp_path / "map", inputs)
    r = invoke_cli(args)
    assert r.code == 1 and "Traceback" not in r.output


def test_debug_env_shows_the_traceback(monkeypatch, tmp_path, inputs):
    needs("export")
    _break(monkeypatch, RuntimeError("a bug"))
    args, _ = writer_args("export-npz", tmp_path / "map", inputs)
    with pytest.raises(RuntimeError, match="a bug"):
        invoke_cli(args, env={"REGIMEMAP_DEBUG": "1"})


def test_main_exits_with_the_code(capsys):
    with pytest.raises(SystemExit) as e:
        main(["plot", "--gamma", "0", "--kprime", "0"])
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0


@pytest.mark.subprocess
def test_console_script_in_a_subprocess(tmp_path):
    """The installed entry point, as a user runs it: one line on stderr, exit 2."""
    exe = Path(sys.executable).with_name("regimemap")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-c", "from regimemap.cli import main; main()"]
    env = {k: v for k, v in os.environ.items() if k != "REGIMEMAP_DEBUG"}
    p = subprocess.run([*cmd, "export", "--gamma", "nan", "--kprime", "0", "-o", str(tmp_path / "m.npz")],
                       capture_output=True, text=True, env=env, timeout=120)
    assert p.returncode == 2
    assert p.stdout == "" and p.stderr.count("\n") == 1 and "Traceback" not in p.stderr
    assert "'--gamma'" in p.stderr


# -- no partial files -----------------------------------------------------------------------------------

@pytest.mark.parametrize("key", writer_params())
@pytest.mark.slow
def test_writer_failing_half_way_keeps_the_old_file(tmp_path, inputs, monkeypatch, key):
    """One real failure per writer: the disk fills up half-way through the file.  The old file is
    byte-identical, nothing else in the folder changed, and the one error line names the file.
    (Every kind of failure, once: tests/io/test_atomic.py.)"""
    needs(SINGLE_FILE_WRITERS[key][0])
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    (out_dir / "neighbour.txt").write_bytes(b"not to be touched")
    args, target = writer_args(key, out_dir / "result", inputs)
    target.write_bytes(OLD)
    before = folder_state(out_dir)
    ctl = WriteFailure(out_dir, lambda: OSError(errno.ENOSPC, "No space left on device"), after=64)
    ctl.install(monkeypatch)
    r = invoke_cli(args)
    monkeypatch.undo()
    assert ctl.fired, f"the write never reached the failing file ({ctl.opened} opened): {r.output}"
    line = assert_clean_failure(r, 1, "No space left on device")
    assert target.name in line
    assert folder_state(out_dir) == before  # old file byte-identical, no temp file left


@pytest.mark.render
@pytest.mark.parametrize("exc", [lambda: OSError(errno.EIO, "Input/output error"), RuntimeError,
                                 KeyboardInterrupt], ids=["OSError", "RuntimeError", "KeyboardInterrupt"])
def test_savefig_failing_half_way(tmp_path, inputs, monkeypatch, exc, key="plot-png"):
    """An exception inside matplotlib's savefig (not only in a write): old file kept, exit 1 or 130.
    One writer for the three kinds; every savefig writer goes through the atomic path (above)."""
    needs(SINGLE_FILE_WRITERS[key][0])
    from matplotlib.figure import Figure

    calls = []

    def broken_savefig(self, fname, *args, **kwargs):
        calls.append(fname)
        data = b"\x89PNG half a figure" * 10
        if hasattr(fname, "write"):
            fname.write(data if "b" in getattr(fname, "mode", "b") else data.decode("latin-1"))
        else:
            with builtins.open(fname, "wb") as fh:
                fh.write(data)
        raise exc()

    out_dir = tmp_path / "out"
    out_dir.mkdir()
    args, target = writer_args(key, out_dir / "result", inputs)
    target.write_bytes(OLD)
    monkeypatch.setattr(Figure, "savefig", broken_savefig)
    r = invoke_cli(args)
    monkeypatch.undo()
    assert calls, r.output
    assert "Traceback" not in r.output
    assert r.code == (130 if exc is KeyboardInterrupt else 1), r.output
    assert len(r.error_lines()) == 1, r.stderr
    assert folder_state(out_dir) == {target.name: OLD}


@pytest.mark.render
@pytest.mark.parametrize("failure", sorted(FAILURES))
def test_figures_failing_on_the_third_file(tmp_path, monkeypatch, failure):
    """'figures' writes many files: those finished before the failure are whole, the one
    being written is the old file or absent, and nothing else is in the folder."""
    needs("figures")
    exc, after, old_present, code = FAILURES[failure]
    out_dir = tmp_path / "gallery"
    out_dir.mkdir()
    if old_present:
        (out_dir / "fig-3.2.svg").write_bytes(OLD)  # the third figure (2.1, 3.1, 3.2)
    ctl = WriteFailure(out_dir, exc, nth=3, after=after).install(monkeypatch)
    # one process, so that "the third file" is well defined
    r = invoke_cli(["figures", "--out", str(out_dir), "--format", "svg", "--dpi", "30", "--jobs", "1"])
    monkeypatch.undo()
    assert ctl.fired, r.output
    assert_clean_failure(r, code)
    state = folder_state(out_dir)
    assert sorted(state) == ["fig-2.1.svg", "fig-3.1.svg"] + (["fig-3.2.svg"] if old_present else [])
    check_complete(out_dir / "fig-2.1.svg")
    check_complete(out_dir / "fig-3.1.svg")
    if old_present:
        assert state["fig-3.2.svg"] == OLD


# -- random arguments never give a traceback ------------------------------------------------------------

NUMBERS = ["0", "-0", "-0.0", "1", "3", "0.4", "-0.6", "-1", "1.0000001", "2", "nan", "NaN", "inf",
           "-inf", "1e308", "-1e308", "1e-308", "5e-324", "1e100", "1e6", "0.05", "50", "1e3", "x", "",
           " ", "1,2", "0x10", "1_0", "١"]
VALUE_CHOICES = {
    # by click type name; a few valid values are small so that drawing stays cheap
    "gamma": ["3", "0.5", "0.05", "50", "1.41421356"] + NUMBERS,
    "kprime": ["0.4", "-0.6", "0", "1", "-1"] + NUMBERS,
    "k_max": ["2", "0.5"] + NUMBERS, "k-max": ["2", "0.5"] + NUMBERS,
    "mu_max": ["2", "0.5"] + NUMBERS, "mu-max": ["2", "0.5"] + NUMBERS,
    "number": ["0.5", "0", "1e-9", "12"] + NUMBERS,
    "integer": ["2", "3", "20", "1", "0", "-5", "5001", "99999999999999999999", "2.5", "x", "nan"],
    "dpi": ["20", "30", "19", "1201", "0", "nan", "inf", "-1", "x", "1e308"],
    "integer range": ["30", "31", "29", "601", "0", "x", "nan"],
    "float range": ["8", "0.5", "50", "0.49", "51", "nan", "inf", "x"],
    "png|svg|pdf": ["png", "svg", "pdf", "PDF", ".svg", "bmp", "", "gif"],
    "FORMATS": ["svg", "png,svg", "pdf", ",", "", "bmp", "svg,bmp"],
    "MODES": ["RE", "RO,SRO-", "SRO'-", "sro+", "RO'", "XX", "", ","],
    "K,MU[:NAME]": ["0.45,0.6:A", "1,2", "a,b", "-1,2", "nan,1", "", "1", "1,2,3", "1e400,1"],
    "gamma-list": ["1,2", "3", "0.5:3:2", "1:2:49", "a,b", "0,1", "", "1:2", "1e308", "1:2:1000000000",
                   "1:2:-1", "3,nan"],
    "kprime-list": ["0,0.4", "-1:1:3", "0", "-1:1:401", "0:1:0", "a", "2", "", "-1:1", "0:1:1e9",
                    "nan,0"],
    # the loads (issue 10)
    "buoyancy": ["0", "0.3", "0.99", "1", "-0.1"] + NUMBERS,
    "uplift": ["0", "0.2", "0.5"] + NUMBERS,
    "uplift_ratio": ["0", "0.5", "1"] + NUMBERS,
    "uplift_arm": ["0.333333", "0", "-1", "1", "1.01"] + NUMBERS,
    "gyration": ["0.7", "1", "0"] + NUMBERS,
    "crest": ["1", "1.2", "0.5", "0"] + NUMBERS,
    **{f"{name}-list": ["0,0.3", "0:0.5:3", "0", "0,2", "a", "", "0:1", "0:1:1e9"]
       for name in ("buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration", "crest")},
    "text": ["{out}.png", "{out}.svg", "{out}.pdf", "{out}", "{out}.bmp", "", "{missing}/x.png",
             "{inputs}/a-file/x.png", "/proc/x.png", "{inputs}", "$\\frac{", "α β", "$x^2$"],
    "file": ["{out}.csv", "{out}.json", "{out}.npz", "{out}.gif", "{out}.png", "{out}.txt", "",
             "{missing}/x.csv", "/proc/x.json", "{inputs}/good.csv", "{inputs}/bad.csv", "{inputs}"],
    # regimemap climate
    "threshold": ["99.5%", "99%", "4.5", "0%", "100%", "101%", "-1", "0", "%", "50", "1e400"] + NUMBERS,
    "periods": ["10,50,100", "50", "1", "0.5", "10,,50", "10,x", "", "1e6", "-5", "nan"],
}
# the inputs 'outcome' sweeps (lists and ranges)
VALUE_CHOICES.update({f"{name}-list": ["0.5", "0.1,0.2", "0.1:1:3", "1:2", "a,b", "", "nan", "-1", "0:1:1e9"]
                      for name in ("k_peak", "duration", "omega_p", "mu", "half_width", "gyration",
                                   "buoyancy", "uplift", "uplift_ratio", "uplift_arm")})
ARGUMENT_CHOICES = {"figure_id": ["3.9a", "4.7b", "3.1", "3.9", "9.9", "", "3.9A", "fig", "--", "-1"]}

# Valid values, small so that drawing stays cheap: half of the examples use only these
# (otherwise nearly every random command line is a usage error and the running code is
# never reached).
VALID_BY_TYPE = {
    "gamma": ["3", "0.5", "1.41421356", "50", "0.05", "2"],
    "kprime": ["0.4", "-0.6", "0", "1", "-1", "-0.0", "1e-9", "-1e-9"],
    "k_max": ["2", "0.5", "1e-6", "1e6", "5"], "k-max": ["2", "0.5", "1e-6", "1e6", "5"],
    "mu_max": ["2", "0.5", "1e-6", "1e6"], "mu-max": ["2", "0.5", "1e-6", "1e6"],
    "number": ["0.5", "0", "12", "1e-9", "1e6"],
    "integer": ["2", "3", "20", "60"],
    "dpi": ["20", "30"],
    "integer range": ["30", "40"],
    "float range": ["8", "0.5", "50"],
    "png|svg|pdf": ["png", "svg", "pdf"],
    "FORMATS": ["svg", "png", "pdf,svg"],
    "MODES": ["RE", "RO,SRO-", "SRO'-,SL", "sro+"],
    "K,MU[:NAME]": ["0.45,0.6:A", "1,2", "0,0", "100,100:far"],
    "gamma-list": ["1,2", "3", "0.5:3:2", "50"],
    "kprime-list": ["0,0.4", "-1:1:3", "0", "-1,1"],
    "buoyancy": ["0", "0.3"], "uplift": ["0", "0.2"], "uplift_ratio": ["0", "0.5"],
    "uplift_arm": ["0.333333", "0"], "gyration": ["0.7", "1.5"], "crest": ["1", "1.2"],
    "buoyancy-list": ["0", "0,0.3"], "uplift-list": ["0"], "uplift_ratio-list": ["0", "0.2,0.5"],
    "uplift_arm-list": ["0.333333"], "gyration-list": ["0.8"], "crest-list": ["1"],
    "threshold": ["99.5%", "99%", "4.5"], "periods": ["10,50,100", "50"],
}
VALID_BY_NAME = {
    "points_files": ["{inputs}/good.csv"], "points_file": ["{inputs}/good.csv"],
    "title": ["", "$x^2$", "α β", "$\\frac{", "a_b", "%s {}"],
    "out_dir": ["{outdir}"],
    ("plot", "output"): ["{out}.png", "{out}.svg", "{out}.pdf", "{out}"],
    ("figure", "output"): ["{out}.png", "{out}.svg", "{out}.pdf"],
    ("export", "output"): ["{out}.npz", "{out}.csv", "{out}.json"],
    ("atlas", "output"): ["{out}.png", "{out}.svg", "{out}.pdf"],
    ("animate", "output"): ["{out}.gif"],
    ("classify", "output"): ["{out}.csv", "{out}.json"],
    "figure_id": ["3.9a", "4.7b", "3.1"],
}


def _valid_choices(command: str, param):
    for key in ((command, param.name), param.name):
        if key in VALID_BY_NAME:
            return VALID_BY_NAME[key]
    if param.type.name == "choice":
        return list(param.type.choices)
    return VALID_BY_TYPE.get(param.type.name)


def _value_strategy(command: str, param, valid: bool):
    good = _valid_choices(command, param)
    if valid and good:
        return st.sampled_from(good)
    if param.type.name == "choice":
        return st.sampled_from([*param.type.choices, "bogus", ""])
    choices = VALUE_CHOICES.get(param.type.name, ["x", "", "1", "nan"]) + (good or [])
    return st.one_of(st.sampled_from(choices),
                     st.floats(allow_nan=True, allow_infinity=True).map(repr),
                     st.text(max_size=8))


@st.composite
def command_lines(draw, name: str):
    """Options of ``name`` in random order with random values: all valid, or anything."""
    command = cli.commands[name]
    valid = draw(st.booleans())
    args: list[str] = []
    for param in command.params:
        if param.param_type_name == "argument":
            if valid or draw(st.integers(0, 9)):  # sometimes missing
                choices = VALID_BY_NAME.get(param.name) if valid else None
                args.append(draw(st.sampled_from(choices or ARGUMENT_CHOICES.get(param.name, ["x"]))))
            continue
        needed = param.required or (valid and name == "classify" and param.name in ("points_file",))
        if param.name == "help" or param.name == "list_only" and valid:
            continue
        if param.name == "show_ambiguity" or not (needed and (valid or draw(st.integers(0, 9)))
                                                  or draw(st.booleans())):
            continue
        opt = draw(st.sampled_from(param.opts))
        if getattr(param, "is_flag", False):
            args.append(opt)
        else:
            n = 2 if getattr(param, "multiple", False) and draw(st.booleans()) else 1
            for _ in range(n):
                args += [opt, draw(_value_strategy(name, param, valid))]
    if not valid and draw(st.integers(0, 9)) == 0:
        args.append(draw(st.sampled_from(["--bogus", "-x", "extra", "--help", "--gamma"])))
    return [name, *args]


@contextlib.contextmanager
def _chdir(path: Path):
    old = os.getcwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(old)


_FUZZ_EXAMPLES = max(4, settings.default.max_examples // 3)


#: The fuzzed commands that draw; 'figures' also starts worker processes (--jobs).
_FUZZ_MARKS = {"figures": [pytest.mark.render, pytest.mark.subprocess, pytest.mark.slow],
               "figure": [pytest.mark.render, pytest.mark.slow], "animate": [pytest.mark.render, pytest.mark.slow],
               "atlas": [pytest.mark.render, pytest.mark.slow], "plot": [pytest.mark.render, pytest.mark.slow]}


@pytest.mark.parametrize("name", [pytest.param(n, marks=_FUZZ_MARKS.get(n, ())) for n in sorted(COMMAND_MODULES)])
@pytest.mark.deep
def test_random_arguments_never_crash(name, tmp_path_factory, monkeypatch):
    needs(name)
    if name == "figures":
        # keep a valid 'figures' run short: of the report's 24 figures and of the worked figures
        # (--set worked, --set all: W.4 is an atlas), one each -- with the model's figure, still two
        # figures, so that --jobs starts a pool
        import regimemap.maps.figures.presets as figs
        import regimemap.maps.figures.worked as worked

        monkeypatch.setattr(figs, "PRESETS", dict(list(figs.PRESETS.items())[:1]))
        monkeypatch.setattr(worked, "WORKED", dict(list(worked.WORKED.items())[:1]))

    @settings(max_examples=_FUZZ_EXAMPLES)
    @given(command_lines(name))
    def run(argv):
        work = tmp_path_factory.mktemp("fuzz")
        inputs = work / "inputs"
        inputs.mkdir()
        (inputs / "good.csv").write_text("k,mu\n0.1,0.5\n0.5,0.8\n")
        (inputs / "bad.csv").write_text("k,mu\n0.1,x\n")
        (inputs / "a-file").write_text("x")
        (work / "gallery").mkdir()
        argv = [a.replace("{out}", str(work / "out")).replace("{inputs}", str(inputs))
                 .replace("{missing}", str(work / "missing")).replace("{outdir}", str(work / "gallery"))
                for a in argv]
        with _chdir(work):
            r = invoke_cli(argv)
        assert r.code in (0, 1, 2), (argv, r.code, r.output)
        assert "Traceback" not in r.output, (argv, r.output)
        if r.code != 0:
            assert len(r.error_lines()) == 1, (argv, r.stderr)
            assert "internal error" not in r.stderr, (argv, r.stderr)
        leftovers = [p.name for p in work.rglob("*") if p.name.endswith(".part")
                     or p.name.startswith(".regimemap-probe")]
        assert not leftovers, (argv, leftovers)

    run()


def test_fuzz_value_tables_cover_every_option_type():
    """A new option type gets plausible values in VALUE_CHOICES (not only random text)."""
    missing = set()
    for name, command in cli.commands.items():
        for p in command.params:
            if p.param_type_name == "option" and not getattr(p, "is_flag", False) \
                    and p.type.name not in VALUE_CHOICES and p.type.name not in ("choice", "boolean"):
                missing.add(f"{name} {p.opts[-1]} ({p.type.name})")
    assert not missing, sorted(missing)


def test_nan_is_not_silently_accepted_anywhere(tmp_path):
    """Every numeric option refuses nan (exit 2), for every command."""
    numeric = {"gamma", "kprime", "k_max", "k-max", "mu_max", "mu-max", "number", "integer", "dpi",
               "integer range", "float range"}
    checked = 0
    for name, command in cli.commands.items():
        for p in command.params:
            if p.param_type_name == "option" and p.type.name in numeric:
                r = invoke_cli([name, p.opts[-1], "nan"])
                assert r.code == 2 and "Traceback" not in r.output, (name, p.opts, r.output)
                checked += 1
    assert checked >= 10 or len(cli.commands) < 7
    assert math.isnan(float("nan"))


def test_the_harness_catches_a_writer_that_is_not_atomic(tmp_path, inputs, monkeypatch):
    """Sanity check of WriteFailure: with a naive (non-atomic) writer the old file is lost."""
    needs("export")
    import regimemap.io.atomic as atomic

    @contextlib.contextmanager
    def naive_path(path):
        yield Path(path)

    monkeypatch.setattr(atomic, "atomic_path", naive_path)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    args, target = writer_args("export-csv", out_dir / "result", inputs)
    target.write_bytes(OLD)
    WriteFailure(out_dir, lambda: OSError(errno.ENOSPC, "No space left on device")).install(monkeypatch)
    r = invoke_cli(args)
    monkeypatch.undo()
    assert r.code == 1
    assert target.read_bytes() != OLD and len(target.read_bytes()) == 64  # cut short: what we prevent


@pytest.mark.parametrize("args", [
    pytest.param(["plot", "--gamma", "2", "--kprime", "0.6666666666666666", "--resolution", "40",
                  "-o", "{out}.svg"], id="plot", marks=pytest.mark.render),
    pytest.param(["export", "--gamma", "2", "--kprime", "0.6666666666666666", "-o", "{out}.json"], id="export"),
    pytest.param(["atlas", "--gamma", "2", "--kprime", "0.6666666666666666", "--dpi", "30",
                  "-o", "{out}.png"], id="atlas", marks=pytest.mark.render),
    pytest.param(["classify", "--gamma", "2", "--kprime", "0.6666666666666666", "--k", "1", "--mu", "0.1"],
                 id="classify"),
])
@pytest.mark.slow
def test_case_threshold_a_zero_runs(tmp_path, args):
    """At k' = (4+g^2)/(3g^2) the constant a of (3.18) is exactly 0: every command still works."""
    needs(args[0])
    r = invoke_cli([a.replace("{out}", str(tmp_path / "out")) for a in args])
    assert r.code == 0 and "error" not in r.stderr, r.output


# -- warnings on standard error, every command ---------------------------------------------------------

def _slipped_design(folder: Path) -> str:
    """The example design with its weight in N/m (an implausible value: a warning, not an error)."""
    from regimemap.caisson.file import example_design_text

    p = folder / "slip.toml"
    p.write_text(example_design_text().replace("buoyant_weight = 2312", "buoyant_weight = 2312000"))
    return str(p)


def _record_with_copies(folder: Path) -> str:
    """The one-year excerpt of 44007 with its largest height given twice, the first copy 1 m higher."""
    import gzip

    excerpt = Path(__file__).parents[1] / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"
    lines = gzip.decompress(excerpt.read_bytes()).decode().splitlines()
    top = 1 + max(range(len(lines) - 1), key=lambda i: float(lines[i + 1].split(";")[1]))
    stamp, hs, tz = (x.strip() for x in lines[top].split(";"))
    p = folder / "copies.txt"
    p.write_text("\n".join([*lines[:top], f"{stamp}; {float(hs) + 1.0:.4f}; {tz}", *lines[top:]]) + "\n")
    return str(p)


def _record_design(folder: Path) -> str:
    """The example design whose climate is ``[lifetime.record]`` of :func:`_record_with_copies`."""
    from regimemap.caisson.file import example_design_text

    _record_with_copies(folder)
    text = example_design_text()
    i, j = text.index("[lifetime]"), text.index("[lifetime.errors]")
    climate = ("H0_10", "H0_50", "annual_maxima", "distribution", "shape", "storms_per_year")
    kept = [line for line in text[i:j].splitlines() if line.split("=")[0].strip() not in climate]
    p = folder / "site.toml"
    p.write_text(text[:i] + "\n".join(kept) + '\nclimate_replicates = 2\n\n[lifetime.record]\npath = "copies.txt"\n'
                 'threshold = "97%"\n\n' + text[j:])
    return str(p)


def _study_not_bracketed(folder: Path) -> str:
    """A study of one section whose widths all meet the target (a warning: give narrower widths)."""
    from regimemap.caisson.file import example_design_text

    (folder / "goda.toml").write_text(example_design_text())
    p = folder / "study.toml"
    p.write_text('seed = 1\ntrials = 20\nbase = "goda.toml"\n[[section]]\nname = "a"\nchainage = 0.0\n'
                 'widths = [40.0, 45.0]\ntarget = 0.1\n\n[[scenario]]\nname = "today"\n')
    return str(p)


def _points(folder: Path, sep: str = ",") -> str:
    """Points of the block gamma = 3, k' = 0.4, and one (C) of another block."""
    p = folder / ("pts.csv" if sep == "," else "pts.tsv")
    p.write_text("\n".join(sep.join(r) for r in [("k", "mu", "name", "gamma", "kprime"),
                                                    ("0.45", "0.6", "A", "3", "0.4"),
                                                    ("0.3", "0.3", "C", "2", "0.4")]) + "\n")
    return str(p)


WARNING_RUNS = {
    "caisson": (lambda d: ["caisson", _slipped_design(d)], "[caisson] buoyant_weight = 2312000"),
    "lifetime": (lambda d: ["lifetime", _slipped_design(d), "--trials", "20", "-q"],
                 "[caisson] buoyant_weight = 2312000"),
    "lifetime-record": (lambda d: ["lifetime", _record_design(d), "--trials", "20", "-q"],
                        "copies.txt: 1 repeated time(s) with differing copies"),
    "simulate": (lambda d: ["simulate", "--design", _slipped_design(d)], "[caisson] buoyant_weight = 2312000"),
    "climate": (lambda d: ["climate", _record_with_copies(d), "--threshold", "97%", "--bootstrap", "0"],
                "copies.txt: 1 repeated time(s) with differing copies"),
    "climate-json": (lambda d: ["climate", _record_with_copies(d), "--threshold", "97%", "--bootstrap", "0",
                                "--json"], "copies.txt: 1 repeated time(s) with differing copies"),
    "study": (lambda d: ["study", _study_not_bracketed(d), "--jobs", "1", "--store", str(d / "store")],
              "section 'a', scenario 'today': the target ESD 0.1 m is not between"),
    "classify": (lambda d: ["classify", "--gamma", "3", "--kprime", "0.4", "--points", _points(d, "\t")],
                 "pts.tsv is tab-separated"),
    "plot": (lambda d: ["plot", "--gamma", "3", "--kprime", "0.4", "--points", _points(d), "-o",
                        str(d / "m.png"), "--dpi", "40"], "1 point(s) have another gamma or kprime"),
}


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.render) if n == "plot" else n
                                  for n in sorted(WARNING_RUNS)])
@pytest.mark.slow
def test_warnings_go_to_stderr_and_stdout_stays_clean(run_cli, tmp_path, name):
    args, warning = WARNING_RUNS[name]
    r = run_cli(args(tmp_path))
    assert r.code == 0 and "Traceback" not in r.stderr, r.stderr
    assert r.stdout.strip(), "the report is on stdout"
    found = [line for line in r.stderr.splitlines() if warning in line]
    assert len(found) == 1 and found[0].startswith(("regimemap: warning: ", "regimemap: note: ")), r.stderr
    assert warning not in r.stdout and "warning:" not in r.stdout.replace('"warnings":', "")
