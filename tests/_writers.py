"""The commands that write one file, and a harness that makes their writes fail half-way.

Shared by the atomicity tests: ``tests/io/test_atomic.py`` proves every failure
kind once; ``tests/cli/test_cli_errors.py`` checks each writer goes through the
atomic path and survives one real failure.
"""

from __future__ import annotations

import builtins
import contextlib
import errno
import io
import os
import stat
import threading
import zipfile
from pathlib import Path
from xml.etree import ElementTree

G = ["--gamma", "3", "--kprime", "0.4"]

#: A command line for each command that writes one file; {out} is the output path.
SINGLE_FILE_WRITERS = {
    "plot-png": ["plot", *G, "--resolution", "40", "--dpi", "30", "-o", "{out}.png"],
    "plot-svg": ["plot", *G, "--resolution", "40", "-o", "{out}.svg"],
    "plot-pdf": ["plot", "--gamma", "3", "--kprime", "-0.6", "--resolution", "40", "-o", "{out}.pdf"],
    "figure-svg": ["figure", "3.9a", "-o", "{out}.svg"],
    "figure-png": ["figure", "4.7b", "--dpi", "30", "-o", "{out}.png"],
    "classify-csv": ["classify", "--points", "{inputs}/good.csv", *G, "-o", "{out}.csv"],
    "classify-json": ["classify", "--points", "{inputs}/good.csv", *G, "-o", "{out}.json"],
    "export-npz": ["export", *G, "--resolution", "20", "-o", "{out}.npz"],
    "export-csv": ["export", *G, "--resolution", "20", "-o", "{out}.csv"],
    "export-json": ["export", "--gamma", "3", "--kprime", "-0.6", "-o", "{out}.json"],
    "atlas-png": ["atlas", "--gamma", "1,3", "--kprime", "-0.5,0.4", "--dpi", "30", "-o", "{out}.png"],
    "atlas-pdf": ["atlas", "--gamma", "2", "--kprime", "0.4", "-o", "{out}.pdf"],
    "animate-gif": ["animate", "--gamma", "3", "--kprime", "-1:1:3", "--dpi", "30", "-o", "{out}.gif"],
}
SAVEFIG_WRITERS = ["plot-png", "plot-svg", "plot-pdf", "figure-svg", "atlas-png"]


def writer_args(key: str, out: Path, inputs: Path) -> tuple[list[str], Path]:
    args = [a.replace("{inputs}", str(inputs)) for a in SINGLE_FILE_WRITERS[key]]
    target = None
    for i, a in enumerate(args):
        if "{out}" in a:
            args[i] = a.replace("{out}", str(out))
            target = Path(args[i])
    assert target is not None
    return args, target


def check_complete(path: Path) -> None:
    """The file is a whole file of its kind (not cut short)."""
    data = path.read_bytes()
    suffix = path.suffix
    if suffix == ".png":
        assert data.startswith(b"\x89PNG\r\n\x1a\n") and data.endswith(b"IEND\xaeB`\x82")
    elif suffix == ".svg":
        ElementTree.fromstring(data)
    elif suffix == ".pdf":
        assert data.startswith(b"%PDF") and data.rstrip().endswith(b"%%EOF")
    elif suffix == ".gif":
        assert data.startswith(b"GIF8") and data.endswith(b";")
    elif suffix == ".npz":
        with zipfile.ZipFile(io.BytesIO(data)) as z:
            assert z.testzip() is None and "mode.npy" in z.namelist()
    elif suffix == ".json":
        import json

        json.loads(data)
    elif suffix == ".csv":
        text = data.decode("utf-8")
        assert text.endswith("\n") and len(text.splitlines()) >= 2
    else:  # pragma: no cover
        raise AssertionError(f"unknown kind {suffix}")


# -- a write that fails half-way ------------------------------------------------------------

OLD = b"the previous, complete version of this file\n"


class WriteFailure:
    """Make writing to files under ``folder`` fail: the ``nth`` file opened for writing
    takes ``after`` bytes and then its ``write`` raises ``exc()``.

    Patches ``builtins.open`` and ``io.open`` (used by _atomic, matplotlib, PIL,
    zipfile ...); the wrapper hides ``fileno`` so that C writers (PIL) go
    through ``write`` too.
    """

    def __init__(self, folder: Path, exc, nth: int = 1, after: int = 64):
        self.folder = str(folder.resolve())
        self.exc = exc
        self.nth = nth
        self.after = after
        self.opened = 0
        self.fired = False
        self._real_open = builtins.open

    def install(self, monkeypatch) -> WriteFailure:
        monkeypatch.setattr(builtins, "open", self.open)
        monkeypatch.setattr(io, "open", self.open)
        return self

    def open(self, file, mode="r", *args, **kwargs):
        fh = self._real_open(file, mode, *args, **kwargs)
        if isinstance(file, (str, os.PathLike)) and any(c in mode for c in "wax+") \
                and os.path.realpath(file).startswith(self.folder + os.sep):
            self.opened += 1
            if self.opened == self.nth:
                return _FailingFile(fh, self)
        return fh


class _FailingFile:
    def __init__(self, fh, ctl: WriteFailure):
        self._fh = fh
        self._ctl = ctl
        self._left = ctl.after

    def write(self, data):
        if len(data) <= self._left:
            self._left -= len(data)
            return self._fh.write(data)
        self._fh.write(data[:self._left])
        self._fh.flush()
        self._left = 0
        self._ctl.fired = True
        raise self._ctl.exc()

    def writelines(self, lines):
        for line in lines:
            self.write(line)

    def fileno(self):
        raise io.UnsupportedOperation("fileno")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return self._fh.__exit__(*exc)

    def __iter__(self):
        return iter(self._fh)

    def __getattr__(self, name):
        return getattr(self._fh, name)


FAILURES = {
    # name: (exception factory, bytes written before it, old file present, expected exit code)
    "disk-full-at-once": (lambda: OSError(errno.ENOSPC, "No space left on device"), 0, False, 1),
    "disk-full-half-way": (lambda: OSError(errno.ENOSPC, "No space left on device"), 64, True, 1),
    "ctrl-c-half-way": (KeyboardInterrupt, 64, True, 130),
}


def folder_state(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir()}


class WriteSpy:
    """Record what a run does to files under ``folder``: the files opened for writing (through
    ``open``), and the renames (``os.replace``) into place."""

    def __init__(self, folder: Path):
        self.folder = str(folder.resolve())
        self.opened: list[Path] = []
        self.replaced: list[tuple[Path, Path]] = []
        self._real_open = builtins.open
        self._real_replace = os.replace

    def install(self, monkeypatch) -> WriteSpy:
        monkeypatch.setattr(builtins, "open", self.open)
        monkeypatch.setattr(io, "open", self.open)
        monkeypatch.setattr(os, "replace", self.replace)
        return self

    def _inside(self, file) -> bool:
        return isinstance(file, (str, os.PathLike)) and os.path.realpath(file).startswith(self.folder + os.sep)

    def open(self, file, mode="r", *args, **kwargs):
        if self._inside(file) and any(c in mode for c in "wax+"):
            self.opened.append(Path(file))
        return self._real_open(file, mode, *args, **kwargs)

    def replace(self, src, dst, **kwargs):
        if self._inside(dst):
            self.replaced.append((Path(src), Path(dst)))
        return self._real_replace(src, dst, **kwargs)

    def assert_atomic(self, target: Path) -> None:
        """``target`` was renamed into place from a hidden ``.part`` file beside it, and nothing
        in the folder was opened for writing but such temporary files."""
        temps = [src for src, dst in self.replaced if Path(os.path.realpath(dst)) == Path(os.path.realpath(target))]
        assert len(temps) == 1, (target, self.replaced)
        tmp = temps[0]
        assert tmp.parent.resolve() == target.parent.resolve(), tmp
        assert tmp.name.startswith(f".{target.name}.") and tmp.name.endswith(".part"), tmp
        direct = [f for f in self.opened if not f.name.endswith(".part")]
        assert not direct, f"opened for writing directly, not through the atomic path: {direct}"


#: The commands that draw (their tests are marked ``render``).
DRAWING_COMMANDS = {"plot", "figure", "figures", "atlas", "animate"}


def writer_params(keys=None) -> list:
    """The writers' keys as pytest parameters, those that draw marked ``render``."""
    import pytest

    return [pytest.param(k, marks=pytest.mark.render) if SINGLE_FILE_WRITERS[k][0] in DRAWING_COMMANDS else k
            for k in sorted(SINGLE_FILE_WRITERS if keys is None else keys)]


# -- devices and FIFOs ----------------------------------------------------------------------

def make_device(folder: Path, name: str, minor: int) -> Path:
    """A character device of the kernel's memory driver in ``folder`` (``minor`` 3: a null, 7: a
    full one), so that a test never writes to /dev/full itself; skips where mknod is refused."""
    import pytest

    path = folder / name
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, minor))
    except (OSError, AttributeError) as exc:
        pytest.skip(f"no device can be made here ({exc})")
    return path


class FifoReader:
    """A FIFO at ``path`` and a thread that reads it to the end (``data``, after ``join``)."""

    def __init__(self, path: Path):
        os.mkfifo(path)
        self.path = path
        self.data = b""
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    def _read(self) -> None:
        with open(self.path, "rb") as fh:
            self.data = fh.read()

    def join(self) -> bytes:
        """The bytes read; a reader left waiting (nothing opened the FIFO) is released first.
        A FIFO replaced by a file fails at once (its reader waits on the FIFO for ever)."""
        assert self.path.is_fifo(), f"{self.path} is no longer a FIFO"
        if self._thread.is_alive():
            with contextlib.suppress(OSError):  # a writer that never came: open it, so the read ends
                fd = os.open(self.path, os.O_WRONLY | os.O_NONBLOCK)
                os.close(fd)
        self._thread.join(10)
        assert not self._thread.is_alive(), "the FIFO's reader never finished"
        return self.data


@contextlib.contextmanager
def guarded_dev_null():
    """Around a write to /dev/null: skip where there is none; should the write replace it by a
    file (or leave ``/dev/null.*`` beside it), the device is made again and the test fails."""
    import pytest

    if not os.path.exists("/dev/null") or not stat.S_ISCHR(os.stat("/dev/null").st_mode):
        pytest.skip("no /dev/null device here")
    before = set(os.listdir("/dev"))
    try:
        yield Path("/dev/null")
    finally:
        broken = [f"/dev/{n}" for n in sorted(set(os.listdir("/dev")) - before)]
        for extra in broken:
            os.unlink(extra)
        if not stat.S_ISCHR(os.stat("/dev/null").st_mode):
            os.unlink("/dev/null")
            os.mknod("/dev/null", 0o666 | stat.S_IFCHR, os.makedev(1, 3))
            os.chmod("/dev/null", 0o666)
            broken.append("/dev/null replaced by a file (made again)")
        assert not broken, broken
