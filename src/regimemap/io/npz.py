"""NumPy's ``.npz``: the one writer of every record's arrays, compressed and atomically."""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

import numpy as np

from .atomic import atomic_open

__all__ = ["write_npz"]


def write_npz(path: str | os.PathLike[str], arrays: Mapping[str, Any],
              inputs: Mapping[str, Any] | None = None) -> None:
    """Write ``arrays`` to ``path`` as a compressed ``.npz`` (:func:`numpy.savez_compressed`),
    atomically (:func:`~regimemap.io.atomic.atomic_open`: nothing half-written is ever left).

    ``inputs`` (a run's inputs) follow, each as a 0-d array, except those that are None or
    already the name of an array.  Read back with ``numpy.load(path)`` (no pickle needed).
    """
    out = dict(arrays)
    for key, v in (inputs or {}).items():
        if v is not None and key not in out:
            out[key] = np.asarray(v)
    with atomic_open(path, "wb") as fh:
        np.savez_compressed(fh, **out)
