"""Write output files atomically: a temporary file in the same folder, renamed into place.

A failure or an interrupt while writing leaves either the old file or none,
never a half-written one.  The temporary file is named ``.<name>.<random>.part``
(hidden, beside the target, so the final rename never crosses file systems) and
is removed on any exception, including KeyboardInterrupt.  A target that exists
and is not a regular file -- a device such as ``/dev/null``, a FIFO -- is never
replaced (a rename would put a regular file in its place): the whole file is
written into it once it is made (:func:`special_file`).
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import shutil
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

__all__ = ["atomic_path", "atomic_open", "check_output_path", "folder_problem", "special_file"]

#: Longest part of the target's name kept in the temporary file's name (the
#: temporary name adds about 15 characters; most file systems allow 255).
_TMP_NAME_CHARS = 200

_log = logging.getLogger(__name__)


def _folder_of(p: Path) -> Path:
    return p.parent if str(p.parent) else Path(".")


def special_file(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` (its links followed) exists and is neither a regular file nor a folder:
    a device (``/dev/null``, ``/dev/full``, a terminal), a FIFO or a socket -- written into,
    never replaced."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):  # absent, a loop of links, a NUL in the name ...
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def check_output_path(path: str | os.PathLike[str], param: str = "output") -> Path:
    """Return ``path`` as a Path if a file can be written there, else raise ValueError.

    Checks that the name is usable, that ``path`` is not a folder, that its
    folder exists and is a folder, and that a file can be created in it (by
    creating and removing an empty hidden file: permission bits alone do not
    tell, e.g. for root or on read-only and virtual file systems).  A device or
    a FIFO (:func:`special_file`) is written into, not replaced: it needs only
    to be writable, not its folder.  The message starts with ``param`` (e.g.
    ``--output folder 'x' does not exist``).
    """
    text: str | bytes = os.fspath(path)  # bytes from an untyped caller's bytes path
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not text.strip():
        raise ValueError(f"{param} must be a file name, got {text!r}")
    if "\x00" in text:
        raise ValueError(f"{param} {text!r} contains a NUL character")
    p = Path(text)
    name_bytes = len(os.fsencode(p.name))
    if name_bytes > 255:
        raise ValueError(f"{param} file name is too long ({name_bytes} bytes > 255)")
    if special_file(p):
        if not os.access(p, os.W_OK):
            raise ValueError(f"{param} {text!r} is not writable")
        return p
    folder = _folder_of(p)
    try:
        if p.is_dir():
            raise ValueError(f"{param} {str(p)!r} is a folder, not a file")
        if folder.exists() and not folder.is_dir():
            raise ValueError(f"{param} folder {str(folder)!r} is a file, not a folder")
        if not folder.is_dir():
            raise ValueError(f"{param} folder {str(folder)!r} does not exist")
    except OSError as exc:  # e.g. a path too long, or a loop of links
        raise ValueError(f"{param} {text!r} cannot be used: {exc.strerror}") from None
    problem = folder_problem(folder)
    if problem:
        raise ValueError(f"{param} folder {str(folder)!r} {problem}")
    return p


def folder_problem(folder: Path) -> str:
    """Why no file can be created in the existing folder ``folder`` ("" when one can).

    Creates and removes an empty hidden file: permission bits alone do not tell
    (root, read-only or virtual file systems such as /proc).
    """
    if not os.access(folder, os.W_OK | os.X_OK):
        return "is not writable"
    try:
        fd, probe = tempfile.mkstemp(prefix=".regimemap-probe.", dir=folder)
    except OSError as exc:
        return f"is not writable ({_probe_cause(folder, exc)})"
    os.close(fd)
    with contextlib.suppress(OSError):
        os.unlink(probe)
    return ""


#: File systems that hold no files of their own (the kernel's views).
_VIRTUAL_FS = ("proc", "sysfs", "devpts", "cgroup", "cgroup2", "debugfs", "securityfs",
               "tracefs", "configfs", "pstore", "bpf", "efivarfs", "fusectl")


def _fs_type(folder: Path) -> str | None:
    """The type of the file system that holds ``folder`` (from /proc/self/mounts), if known."""
    try:
        real = os.path.realpath(folder)
        with open("/proc/self/mounts", encoding="utf-8", errors="replace") as fh:
            mounts = [line.split()[1:3] for line in fh if len(line.split()) >= 3]
    except OSError:
        return None
    best, kind = "", None
    for point, fstype in mounts:
        point = point.replace("\\040", " ")
        inside = real == point or real.startswith(point.rstrip("/") + "/")
        if inside and len(point) >= len(best):
            best, kind = point, fstype
    return kind


def _probe_cause(folder: Path, exc: OSError) -> str:
    """The real reason why no file could be created in the existing folder ``folder``."""
    kind = _fs_type(folder)
    if kind in _VIRTUAL_FS:
        return f"it is on the kernel's virtual {kind} file system, which holds no files"
    if exc.errno == errno.EROFS:
        return "it is on a read-only file system"
    if exc.errno in (errno.EACCES, errno.EPERM):
        return "permission denied"
    if exc.errno == errno.ENOENT:  # the folder exists: the file system refuses new files
        return "its file system does not accept new files"
    return exc.strerror or str(exc)


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; on success rename it to ``path``.

    On any exception (including KeyboardInterrupt) the temporary file is
    removed and ``path`` is left as it was.  If ``path`` is a symbolic link
    the file it points to is replaced (the link is kept).  The new file gets
    the permissions of the file it replaces, or the default ``0o666 & ~umask``.
    A ``path`` that is (or links to) a device or a FIFO (:func:`special_file`)
    is not replaced: the temporary file is made in the system's temporary
    folder and, on success, copied into ``path`` (so that a writer that seeks
    works, and one that fails sends nothing); a copy that fails half-way
    (``/dev/full``, a reader that went away) cannot be taken back.

    Notes
    -----
    The temporary name ends in ``.part``: writers that choose a format from
    the suffix (``Figure.savefig``) must be given the format explicitly, and
    ``numpy.savez`` must be given an open file (it appends ``.npz`` to names).
    """
    target = Path(path)
    if special_file(target):
        with _copied_into(target) as staged:
            yield staged
        return
    if target.is_symlink():
        target = Path(os.path.realpath(target))
    folder = _folder_of(target)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name[:_TMP_NAME_CHARS]}.", suffix=".part",
                                   dir=folder)
    except OSError as exc:
        raise OSError(exc.errno, f"cannot create a file in {str(folder)!r}: {exc.strerror}",
                      str(target)) from None
    tmp_path = Path(tmp)
    try:
        os.close(fd)
        yield tmp_path
        try:
            mode = stat.S_IMODE(os.stat(target).st_mode)
        except OSError:
            mode = 0o666 & ~_umask()
        os.chmod(tmp_path, mode)
        os.replace(tmp_path, target)
        if _log.isEnabledFor(logging.INFO):
            _log.info("wrote %s (%s bytes)", target, f"{target.stat().st_size:,}")
    except BaseException:
        with contextlib.suppress(OSError):
            tmp_path.unlink()
        raise


@contextlib.contextmanager
def _copied_into(target: Path) -> Iterator[Path]:
    """Yield a temporary path in the system's temporary folder; on success copy it into
    ``target`` (a device or a FIFO, opened as it is, links followed); remove it in any case."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name[:_TMP_NAME_CHARS]}.", suffix=".part")
    except OSError as exc:
        raise OSError(exc.errno, f"cannot create a temporary file: {exc.strerror}", str(target)) from None
    tmp_path = Path(tmp)
    try:
        os.close(fd)
        yield tmp_path
        with open(tmp_path, "rb") as src, open(target, "wb") as dst:
            shutil.copyfileobj(src, dst)
        _log.info("wrote %s", target)
    finally:
        with contextlib.suppress(OSError):
            tmp_path.unlink()


@contextlib.contextmanager
def atomic_open(path: str | os.PathLike[str], mode: str = "w", **kwargs: Any) -> Iterator[IO[Any]]:
    """Open a temporary file beside ``path`` for writing; rename it into place on success.

    ``mode`` must be a writing mode (``"w"``, ``"wb"``, ``"x"`` is not
    supported).  On any exception inside the ``with`` block the target is
    untouched.
    """
    if not mode.startswith("w"):
        raise ValueError(f"atomic_open mode must start with 'w', got {mode!r}")
    with atomic_path(path) as tmp:
        with open(tmp, mode, **kwargs) as fh:
            yield fh


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
