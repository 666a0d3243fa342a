"""One way for every command to report a file it cannot write."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator

from ._common import RunError

__all__ = ["writing"]


@contextlib.contextmanager
def writing(path: str | os.PathLike[str] | None, what: str | None = None) -> Iterator[None]:
    """Write ``path`` inside the block: an :class:`OSError` becomes the one-line :class:`RunError`
    ``cannot write PATH: reason`` (exit 1), with no traceback.

    Parameters
    ----------
    path : str, path-like or None
        The file (or folder) written.
    what : str, optional
        What the message says is being written, instead of ``path`` (e.g. ``to the cache DIR``).

    Examples
    --------
    >>> with writing("/no/such/folder/x.csv"):
    ...     open("/no/such/folder/x.csv", "w")
    Traceback (most recent call last):
    ...
    regimemap.cli._common.RunError: cannot write /no/such/folder/x.csv: No such file or directory
    """
    try:
        yield
    except OSError as exc:
        raise RunError(f"cannot write {path if what is None else what}: {exc.strerror or exc}") from None
