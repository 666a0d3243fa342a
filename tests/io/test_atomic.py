"""Atomic output (:mod:`regimemap.io.atomic`): a failed or interrupted write leaves the old file or none."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from regimemap.io.atomic import atomic_open, atomic_path, check_output_path

OLD = b"old content\n\x00\xff binary too\n"


class Boom(Exception):
    pass


def _listing(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@pytest.fixture(params=["absent", "present"])
def target(request, tmp_path):
    path = tmp_path / "out.dat"
    if request.param == "present":
        path.write_bytes(OLD)
    return path


def _expect_unchanged(path: Path, before: bytes | None):
    if before is None:
        assert not path.exists()
    else:
        assert path.read_bytes() == before
    assert _listing(path.parent) == ([path.name] if before is not None else []), \
        "a temporary file was left behind"


@pytest.mark.parametrize("exc", [Boom("disk on fire"), OSError(28, "No space left on device"),
                                 KeyboardInterrupt(), SystemExit(3), MemoryError()],
                         ids=lambda e: type(e).__name__)
@pytest.mark.parametrize("mode", ["w", "wb"])
def test_atomic_open_failure_half_way(target, exc, mode):
    before = target.read_bytes() if target.exists() else None
    with pytest.raises(type(exc)):
        with atomic_open(target, mode) as fh:
            fh.write("half of the new content" if mode == "w" else b"half of the new content")
            fh.flush()
            raise exc
    _expect_unchanged(target, before)


@pytest.mark.parametrize("exc", [Boom("writer failed"), KeyboardInterrupt()], ids=lambda e: type(e).__name__)
def test_atomic_path_failure_half_way(target, exc):
    before = target.read_bytes() if target.exists() else None
    with pytest.raises(type(exc)):
        with atomic_path(target) as tmp:
            assert tmp.parent == target.parent and tmp.name.startswith(".out.dat.")
            assert tmp.name.endswith(".part")
            tmp.write_bytes(b"partial")
            raise exc
    _expect_unchanged(target, before)


def test_atomic_path_writer_that_removes_its_own_temp(target):
    """A writer that deletes the temp file and then fails: still no exception from cleanup."""
    before = target.read_bytes() if target.exists() else None
    with pytest.raises(Boom):
        with atomic_path(target) as tmp:
            tmp.unlink()
            raise Boom()
    _expect_unchanged(target, before)


def test_rename_failure_keeps_old_file(target, monkeypatch):
    before = target.read_bytes() if target.exists() else None

    def no_replace(src, dst):
        raise OSError(18, "Invalid cross-device link")

    monkeypatch.setattr(os, "replace", no_replace)
    with pytest.raises(OSError, match="cross-device"):
        with atomic_open(target, "wb") as fh:
            fh.write(b"complete new content")
    _expect_unchanged(target, before)


def test_success_replaces(target):
    with atomic_open(target, "w", encoding="utf-8") as fh:
        fh.write("new ✓")
    assert target.read_text(encoding="utf-8") == "new ✓"
    assert _listing(target.parent) == ["out.dat"]


def test_new_file_gets_default_permissions(tmp_path):
    path = tmp_path / "f.txt"
    with atomic_open(path) as fh:
        fh.write("x")
    mask = os.umask(0)
    os.umask(mask)
    # mkstemp creates 0600; the result must not stay private
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~mask


def test_replaced_file_keeps_its_permissions(tmp_path):
    path = tmp_path / "f.txt"
    path.write_text("old")
    path.chmod(0o640)
    with atomic_open(path) as fh:
        fh.write("new")
    assert path.read_text() == "new"
    assert stat.S_IMODE(path.stat().st_mode) == 0o640


def test_symlink_target_is_replaced_and_link_kept(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(real)
    with atomic_open(link) as fh:
        fh.write("new")
    assert link.is_symlink() and real.read_text() == "new"


def test_long_file_name(tmp_path):
    """A 250-character name is valid; the temporary name beside it must be too."""
    path = tmp_path / ("n" * 246 + ".svg")
    with atomic_open(path) as fh:
        fh.write("ok")
    assert path.read_text() == "ok"
    assert _listing(tmp_path) == [path.name]


def test_missing_folder_is_an_oserror_naming_the_target(tmp_path):
    path = tmp_path / "no" / "such" / "out.png"
    with pytest.raises(OSError) as e:
        with atomic_path(path):
            pass  # pragma: no cover
    assert e.value.filename == str(path)
    assert "cannot create a file in" in str(e.value)
    assert not (tmp_path / "no").exists()


def test_atomic_open_refuses_read_modes(tmp_path):
    with pytest.raises(ValueError, match="mode must start with 'w'"):
        with atomic_open(tmp_path / "x", "r"):
            pass  # pragma: no cover
    assert _listing(tmp_path) == []


# -- check_output_path -------------------------------------------------------------------------------

def test_check_output_path_ok(tmp_path):
    assert check_output_path(tmp_path / "a.svg") == tmp_path / "a.svg"


def test_check_output_path_relative_name_uses_cwd(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert check_output_path("a.svg") == Path("a.svg")


@pytest.mark.parametrize("make,match", [
    (lambda t: t / "missing" / "a.svg", r"^output folder '.*missing' does not exist$"),
    (lambda t: t / "file.txt" / "a.svg", r"^output folder '.*file.txt' is a file, not a folder$"),
    (lambda t: t, r"^output '.*' is a folder, not a file$"),
    (lambda t: t / ("x" * 300 + ".svg"), r"^output file name is too long"),
    (lambda t: "", r"^output must be a file name, got ''$"),
    (lambda t: "a\x00b.svg", "NUL"),
])
def test_check_output_path_refuses(tmp_path, make, match):
    (tmp_path / "file.txt").write_text("I am a file")
    with pytest.raises(ValueError, match=match):
        check_output_path(make(tmp_path))


@pytest.mark.parametrize("folder", ["/proc", "/sys"])
def test_check_output_path_read_only_folder(folder):
    # tests run as root, so chmod does not stop writes: /proc and /sys refuse new files for everyone
    if not os.path.isdir(folder):
        pytest.skip(f"no {folder} here")
    with pytest.raises(ValueError, match=rf"^output folder '{folder}' is not writable"):
        check_output_path(f"{folder}/regimemap-test.svg")


def test_check_output_path_leaves_nothing_behind(tmp_path):
    check_output_path(tmp_path / "a.svg")
    assert _listing(tmp_path) == []


def test_check_output_path_unwritable_by_access(tmp_path, monkeypatch):
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: False)
    with pytest.raises(ValueError, match=r"^-o folder '.*' is not writable$"):
        check_output_path(tmp_path / "a.svg", "-o")


# -- every failure kind through a command, once --------------------------------------------------------
#
# The commands write through atomic_path/atomic_open (tests/cli/test_cli_errors.py checks each writer
# does, and survives one real failure); here every kind of failure -- the disk full before the first
# byte with no old file, the disk full half-way with an old file, Ctrl-C half-way -- through two
# writers of different kinds (zipfile's npz, matplotlib's png): the old file or none, nothing else
# in the folder, one error line and the exit code of the failure.

from .._writers import FAILURES, WriteFailure, folder_state, writer_args, writer_params  # noqa: E402
from ..conftest import invoke_cli  # noqa: E402


@pytest.mark.parametrize("failure", sorted(FAILURES))
@pytest.mark.parametrize("key", writer_params(["export-npz", "plot-png"]))
@pytest.mark.slow
def test_every_failure_kind_through_a_command(tmp_path, monkeypatch, key, failure):
    exc, after, old_present, code = FAILURES[failure]
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    (out_dir / "neighbour.txt").write_bytes(b"not to be touched")
    args, target = writer_args(key, out_dir / "result", tmp_path)
    if old_present:
        target.write_bytes(OLD)
    before = folder_state(out_dir)
    ctl = WriteFailure(out_dir, exc, after=after).install(monkeypatch)
    r = invoke_cli(args)
    monkeypatch.undo()
    assert ctl.fired, f"the write never reached the failing file ({ctl.opened} opened): {r.output}"
    assert "Traceback" not in r.output and r.code == code, (r.code, r.output)
    assert len(r.error_lines()) == 1 and r.error_lines()[0].startswith("regimemap"), r.stderr
    assert folder_state(out_dir) == before  # old file byte-identical (or absent), no temp file left


# -- devices and FIFOs: written into, never replaced -----------------------------------------------------
#
# A rename would put a regular file in the place of /dev/null or of a FIFO.  The devices here are made in
# tmp_path (make_device), so that a failing test never replaces the real /dev/full; /dev/null itself is
# written to once, and put back if it ever is replaced.

from .._writers import FifoReader, guarded_dev_null, make_device  # noqa: E402


def _no_temp_left(tmp_path: Path, monkeypatch) -> Path:
    """The system's temporary folder, made ``tmp_path/tmp`` (empty), to see nothing is left there."""
    import tempfile

    temp = tmp_path / "tmp"
    temp.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(temp))
    return temp


@pytest.mark.parametrize("mode", ["w", "wb"])
def test_a_fifo_receives_the_bytes(tmp_path, monkeypatch, mode):
    temp = _no_temp_left(tmp_path, monkeypatch)
    reader = FifoReader(tmp_path / "out.fifo")
    with atomic_open(reader.path, mode) as fh:
        fh.write("new ✓\n" if mode == "w" else b"new\x00\xff\n")
    assert reader.join() == ("new ✓\n".encode() if mode == "w" else b"new\x00\xff\n")
    assert reader.path.is_fifo() and _listing(tmp_path) == ["out.fifo", "tmp"] and _listing(temp) == []


def test_a_link_to_a_fifo_writes_into_the_fifo(tmp_path):
    reader = FifoReader(tmp_path / "out.fifo")
    link = tmp_path / "link"
    link.symlink_to(reader.path)
    with atomic_path(link) as tmp:
        tmp.write_bytes(b"through the link")
    assert reader.join() == b"through the link"
    assert link.is_symlink() and reader.path.is_fifo()


def test_a_writer_that_seeks_works_into_a_fifo(tmp_path):
    """The file is made whole first: a writer that seeks (zipfile, PNG) writes into a FIFO too."""
    reader = FifoReader(tmp_path / "out.fifo")
    with atomic_open(reader.path, "wb") as fh:
        fh.write(b"xxxx tail")
        fh.seek(0)
        fh.write(b"head")
    assert reader.join() == b"head tail"


def test_a_writer_that_fails_sends_nothing_into_a_fifo(tmp_path, monkeypatch):
    temp = _no_temp_left(tmp_path, monkeypatch)
    reader = FifoReader(tmp_path / "out.fifo")
    with pytest.raises(Boom):
        with atomic_open(reader.path, "wb") as fh:
            fh.write(b"half")
            raise Boom()
    assert reader.join() == b"" and reader.path.is_fifo() and _listing(temp) == []


def test_a_null_device_is_written_into(tmp_path, monkeypatch):
    temp = _no_temp_left(tmp_path, monkeypatch)
    null = make_device(tmp_path, "null", 3)
    with atomic_open(null, "w") as fh:
        fh.write("gone")
    assert stat.S_ISCHR(null.stat().st_mode) and _listing(tmp_path) == ["null", "tmp"]
    assert _listing(temp) == []


def test_a_full_device_is_the_disk_full_error_and_stays(tmp_path, monkeypatch):
    temp = _no_temp_left(tmp_path, monkeypatch)
    full = make_device(tmp_path, "full", 7)
    with pytest.raises(OSError) as e:
        with atomic_open(full, "w") as fh:
            fh.write("no room")
    assert e.value.errno == 28  # ENOSPC: No space left on device
    assert stat.S_ISCHR(full.stat().st_mode) and _listing(tmp_path) == ["full", "tmp"]
    assert _listing(temp) == []


def test_dev_null_is_written_into_not_replaced():
    with guarded_dev_null() as null, atomic_open(null, "w") as fh:
        fh.write("gone")


def test_check_output_path_takes_a_device_in_a_folder_it_cannot_write(monkeypatch):
    """-o /dev/null is fine where /dev accepts no new file (as for anyone but root)."""
    import regimemap.io.atomic as atomic

    monkeypatch.setattr(atomic, "folder_problem", lambda folder: "is not writable")
    assert check_output_path("/dev/null", "-o") == Path("/dev/null")
    with pytest.raises(ValueError, match=r"^-o folder '/dev' is not writable$"):
        check_output_path("/dev/regimemap-test.csv", "-o")


def test_check_output_path_refuses_a_device_it_cannot_write(tmp_path, monkeypatch):
    null = make_device(tmp_path, "null", 3)
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: False)
    with pytest.raises(ValueError, match=r"^-o '.*null' is not writable$"):
        check_output_path(null, "-o")
