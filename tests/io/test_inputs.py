"""Input files: a regular file below its size limit, or a refusal at once (regimemap.io.inputs).

Every command argument that names an input goes through the same check; the
library's readers (read_design, read_points_csv, read_pulse_csv) too.
"""

from __future__ import annotations

import builtins
import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from regimemap.caisson.file import DesignFileError, example_design_text, read_design
from regimemap.climate.file import MAX_RECORD_FILE_BYTES, RecordError, read_record
from regimemap.io.inputs import (
    MAX_DESIGN_FILE_BYTES,
    DesignInputError,
    InputFileError,
    check_design_file,
    check_input_file,
    read_design_text,
    read_limited,
)
from regimemap.maps.file_points import MAX_POINTS_FILE_BYTES, read_points_csv
from regimemap.motion.file_pulses import MAX_PULSE_FILE_BYTES, read_pulse_csv

from ..conftest import invoke_cli

BIG = 200 * 1024 * 1024

needs_dev_zero = pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")


def _bad(kind: str, tmp_path: Path) -> tuple[str, str]:
    """A path of ``kind`` that no reader may open, and the words of its reason."""
    if kind == "dev-zero":
        if not os.path.exists("/dev/zero"):
            pytest.skip("no /dev/zero")
        return "/dev/zero", "is a character device, not a regular file"
    if kind == "folder":
        d = tmp_path / "a-folder"
        d.mkdir()
        return str(d), "is a folder, not a file"
    if kind == "fifo":
        if not hasattr(os, "mkfifo"):
            pytest.skip("no FIFOs")
        f = tmp_path / "a-fifo"
        os.mkfifo(f)
        return str(f), "is a named pipe (FIFO), not a regular file"
    assert kind == "sparse"
    f = tmp_path / "huge.dat"
    with open(f, "wb") as fh:  # sparse: no block is written
        fh.truncate(BIG)
    return str(f), f"is {BIG} bytes, more than the limit of"


KINDS = ["dev-zero", "folder", "fifo", "sparse"]


@pytest.fixture
def never_opened(monkeypatch):
    """``never_opened(path)``: from now on, opening ``path`` fails the test (a FIFO would block,
    /dev/zero would never end)."""

    def guard(path: str) -> None:
        real_open, real_os_open = builtins.open, os.open

        def spy_open(file, *args, **kwargs):
            assert os.fspath(file) != path if not isinstance(file, int) else True, f"{path} was opened"
            return real_open(file, *args, **kwargs)

        def spy_os_open(file, *args, **kwargs):
            assert os.fspath(file) != path, f"{path} was opened"
            return real_os_open(file, *args, **kwargs)

        monkeypatch.setattr(builtins, "open", spy_open)
        monkeypatch.setattr(io, "open", spy_open)
        monkeypatch.setattr(os, "open", spy_os_open)

    return guard


# -- the library function ------------------------------------------------------------------------------

@pytest.mark.parametrize("kind", KINDS)
def test_check_input_file_refuses_what_is_not_a_small_regular_file(kind, tmp_path, never_opened):
    path, reason = _bad(kind, tmp_path)
    never_opened(path)
    with pytest.raises(InputFileError) as info:
        check_input_file(path, max_bytes=4 * 1024 * 1024, what="test file")
    exc = info.value
    assert exc.path == path and exc.what == "test file"
    assert str(exc).startswith(f"test file {path!r} {reason}"), str(exc)
    assert reason.removeprefix("is ") in exc.reason


def test_check_input_file_accepts_a_file_at_the_limit_and_a_link_to_it(tmp_path):
    f = tmp_path / "f.txt"
    f.write_bytes(b"x" * 100)
    assert check_input_file(f, max_bytes=100, what="test file") == 100
    link = tmp_path / "link.txt"
    link.symlink_to(f)
    assert check_input_file(link, max_bytes=100, what="test file") == 100
    with pytest.raises(InputFileError, match=r"^test file '.*f.txt' is 100 bytes, more than the limit "
                                             r"of 99 bytes$"):
        check_input_file(f, max_bytes=99, what="test file")
    assert read_limited(link, max_bytes=100, what="test file") == b"x" * 100


def test_missing_file_and_dangling_link(tmp_path):
    with pytest.raises(InputFileError, match=r"^cannot read test file '.*nope': No such file or directory$"):
        check_input_file(tmp_path / "nope", max_bytes=10, what="test file")
    link = tmp_path / "dangling"
    link.symlink_to(tmp_path / "gone")
    with pytest.raises(InputFileError, match="No such file or directory"):
        check_input_file(link, max_bytes=10, what="test file")


def test_limit_in_mib_is_written_both_ways(tmp_path):
    f = tmp_path / "f.toml"
    with open(f, "wb") as fh:
        fh.truncate(MAX_DESIGN_FILE_BYTES + 1)
    with pytest.raises(DesignInputError, match=rf"is {MAX_DESIGN_FILE_BYTES + 1} bytes, more than the "
                                               rf"limit of {MAX_DESIGN_FILE_BYTES} bytes \(4 MiB\)"):
        check_design_file(f)
    assert MAX_DESIGN_FILE_BYTES == 4 * 1024 * 1024


def test_read_limited_refuses_a_file_that_grew_past_the_limit(tmp_path, monkeypatch):
    f = tmp_path / "f.txt"
    f.write_bytes(b"y" * 50)
    import regimemap.io.inputs as inputs

    monkeypatch.setattr(inputs, "check_input_file", lambda *a, **k: 0)  # the file grew after the check
    with pytest.raises(InputFileError, match=r"is more than the limit of 40 bytes"):
        read_limited(f, max_bytes=40, what="test file")


def test_design_text_as_read_text_gives_it(tmp_path):
    text = example_design_text()
    for newline in ("\n", "\r\n"):
        f = tmp_path / "d.toml"
        f.write_bytes(text.replace("\n", newline).encode("utf-8"))
        assert read_design_text(f) == f.read_text(encoding="utf-8") == text


# -- the readers ----------------------------------------------------------------------------------------

READERS = {
    "design": (read_design, DesignFileError),
    "points": (read_points_csv, ValueError),
    "pulse": (read_pulse_csv, ValueError),
    "record": (read_record, RecordError),
}


@pytest.mark.parametrize("reader", sorted(READERS))
@pytest.mark.parametrize("kind", KINDS)
def test_readers_refuse_before_reading(reader, kind, tmp_path, never_opened):
    path, reason = _bad(kind, tmp_path)
    read, error = READERS[reader]
    never_opened(path)
    with pytest.raises(error) as info:
        read(path)
    assert isinstance(info.value, InputFileError) or reader == "record"  # RecordError names it
    assert path in str(info.value) and reason.removeprefix("is ") in str(info.value), str(info.value)


def test_limits_of_the_kinds():
    assert MAX_DESIGN_FILE_BYTES < BIG and MAX_POINTS_FILE_BYTES < BIG and MAX_PULSE_FILE_BYTES < BIG
    assert MAX_RECORD_FILE_BYTES < BIG
    assert issubclass(DesignInputError, DesignFileError) and issubclass(DesignInputError, InputFileError)


# -- the commands ---------------------------------------------------------------------------------------

SIMULATE = ["simulate", "--gamma", "3", "--half-width", "0.2", "--mu", "5"]

#: (command line before the path, the argument's name in the message, kind of input)
COMMANDS = {
    "caisson": (["caisson"], "'DESIGN.toml'", "design"),
    "lifetime": (["lifetime"], "'DESIGN.toml'", "design"),
    "simulate-design": (["simulate", "--design"], "'--design'", "design"),
    "simulate-pulse": ([*SIMULATE, "--pulse-file"], "'--pulse-file'", "pulse"),
    "classify": (["classify", "--points"], "'--points'", "points"),
    "climate": (["climate"], "'RECORD'", "record"),
    "explore-design": (["explore", "--design"], "'--design'", "design"),
    "plot": (["plot", "--gamma", "3", "--kprime", "0.4", "-o", "{tmp}/m.svg", "--points"],
             "'--points'", "points"),
}


def _args(command: str, tmp_path: Path, path: str) -> list[str]:
    head, _, _ = COMMANDS[command]
    return [a.replace("{tmp}", str(tmp_path)) for a in head] + [path]


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize("kind", KINDS)
def test_commands_refuse_with_exit_2_at_once(command, kind, tmp_path, never_opened):
    path, reason = _bad(kind, tmp_path)
    never_opened(path)
    r = invoke_cli(_args(command, tmp_path, path))
    assert "Traceback" not in r.output
    assert r.code == 2, r.output
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    name = COMMANDS[command][1]
    assert f"Invalid value for {name}" in lines[0] and path in lines[0], lines[0]
    assert reason.removeprefix("is ") in lines[0], lines[0]
    assert {p.name for p in tmp_path.iterdir()} <= {"a-folder", "a-fifo", "huge.dat"}  # no output


def _good(kind: str, tmp_path: Path) -> Path:
    f = tmp_path / f"real-{kind}"
    if kind == "design":
        f.write_text(example_design_text(), encoding="utf-8")
    elif kind == "record":
        f = tmp_path / "real-record.txt.gz"
        f.write_bytes((Path(__file__).parents[1] / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz").read_bytes())
    elif kind == "points":
        f.write_text("k,mu\n0.1,0.5\n", encoding="utf-8")
    else:
        f.write_text("t,k,kprime\n0,0,0\n0.1,0.05,0\n0.2,0,0\n", encoding="utf-8")
    link = tmp_path / f"link-{kind}"
    link.symlink_to(f)
    return link


#: What each command needs to run quickly once its input is accepted.
_TAIL = {"caisson": ["--json"], "lifetime": ["--trials", "200", "--json", "--seed", "1", "--jobs", "1"],
         "simulate-design": ["--json"], "simulate-pulse": ["--json"], "classify": ["--gamma", "3", "--kprime", "0.4"],
         "plot": [], "climate": ["--bootstrap", "0", "--threshold", "98%", "--json"],
         "explore-design": ["-o", "{tmp}/e.svg"]}


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.deep
def test_commands_accept_a_link_to_a_regular_file(command, tmp_path):
    if command in ("plot", "explore-design"):
        pytest.importorskip("matplotlib")
    link = _good(COMMANDS[command][2], tmp_path)
    tail = [a.replace("{tmp}", str(tmp_path)) for a in _TAIL[command]]
    r = invoke_cli(_args(command, tmp_path, str(link)) + tail)
    assert r.code == 0, r.output
    assert "error" not in r.stderr


@pytest.mark.subprocess
@needs_dev_zero
def test_lifetime_on_dev_zero_end_to_end(tmp_path):
    """The command as installed refuses /dev/zero (reading it would never end: the timeout fails)."""
    proc = subprocess.run([sys.executable, "-m", "regimemap", "lifetime", "/dev/zero"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout == "" and "Traceback" not in proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    assert "'DESIGN.toml'" in proc.stderr and "/dev/zero" in proc.stderr
    assert "character device" in proc.stderr


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_commands_refuse_a_missing_file_with_exit_2(command, tmp_path):
    path = str(tmp_path / "absent.dat")
    r = invoke_cli(_args(command, tmp_path, path) + [a.replace("{tmp}", str(tmp_path)) for a in _TAIL[command]])
    assert r.code == 2, r.output
    assert "Traceback" not in r.output and r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert f"Invalid value for {COMMANDS[command][1]}" in lines[0] and path in lines[0], lines[0]
    assert "No such file or directory" in lines[0], lines[0]
