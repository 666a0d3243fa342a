"""An outcome map's record as files (``regimemap outcome``, ``regimemap dynamics-figures``).

* :func:`write_outcome` -- an outcome map, ``.npz``, ``.csv`` or ``.json`` (with its refined
  boundaries, :func:`outcome_record`), :func:`write_outcome_record` that of a workflow's
  record, :func:`outcome_summary` what it took, in words;
* :func:`cached_outcome` -- computed outcome maps kept in ``.npz`` files (``make figures``).

A run's record (its text, JSON and time history) is :mod:`regimemap.motion.record_simulation`'s;
the figures are :mod:`regimemap.motion.figures`'.  Every file is written atomically (a temporary
file in the same folder, then a rename).
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..dynamics.outcome import OutcomeMap
from ..io.csv import write_csv
from ..io.formats import format_for, record_formats
from ..io.json import write_json
from ..io.npz import write_npz
from ..records.numbers import rounded

if TYPE_CHECKING:  # pragma: no cover
    from .record import OutcomeRecord

__all__ = [
    "OUTCOME_DATA_FORMATS",
    "cached_outcome",
    "outcome_record",
    "outcome_summary",
    "write_outcome",
    "write_outcome_record",
]

#: Formats of an outcome map's data, by file suffix (:data:`~regimemap.io.formats.RECORDS`).
OUTCOME_DATA_FORMATS: tuple[str, ...] = record_formats("outcome data")


# -- files ----------------------------------------------------------------------------------------


def write_outcome(path: str | os.PathLike[str], m: OutcomeMap, first: str, second: str,
                  inputs: Mapping[str, Any] | None = None,
                  axes: Mapping[str, NDArray[np.float64]] | None = None) -> str:
    """Write an outcome map's data, atomically; the format (npz or csv) from the suffix.

    Parameters
    ----------
    m : OutcomeMap
    first, second : str
        Names of the swept inputs (columns, rows), e.g. ``k_peak`` and ``duration``.
    inputs : mapping, optional
        The fixed inputs (written as 0-d arrays in ``.npz``).
    axes : mapping, optional
        More 1-D arrays (e.g. the dimensionless values of the axes), written to ``.npz``.

    ``.npz``: 1-D arrays ``first`` and ``second`` (the swept values), 2-D arrays ``category``
    (int8 codes), ``overturned``, ``max_rotation`` (rad) and ``residual_slide`` (m, positive
    towards O) of shape (len(second), len(first)), ``labels`` (category names by code) and the
    inputs.  ``.csv``: header ``first,second,category,overturned,max_rotation,residual_slide``,
    one row per cell (second outer, first inner), the category as its name.  ``.json``: one
    object, :func:`outcome_record`, with the refined boundaries.
    Returns the format.
    """
    fmt = format_for(path, "outcome data")
    if first == second:
        raise ValueError("the two swept inputs must differ")
    if fmt == "json":
        write_json(path, outcome_record(m, first, second, inputs, axes), indent=None, ascii_only=False)
        return fmt
    if fmt == "npz":
        arrays: dict[str, NDArray[Any]] = {
            first: np.asarray(m.first_values, dtype=np.float64),
            second: np.asarray(m.second_values, dtype=np.float64),
            "category": np.asarray(m.category, dtype=np.int8),
            "overturned": np.asarray(m.overturned, dtype=bool),
            "max_rotation": np.asarray(m.max_rotation, dtype=np.float64),
            "residual_slide": np.asarray(m.residual_slide, dtype=np.float64),
            "labels": np.array(m.labels),
        }
        for key, arr in (axes or {}).items():
            arrays[key] = np.asarray(arr, dtype=np.float64)
        write_npz(path, arrays, inputs)
        return fmt
    write_csv(path, (first, second, "category", "overturned", "max_rotation", "residual_slide"),
              _csv_rows(m))
    return fmt


def _csv_rows(m: OutcomeMap) -> Iterator[str]:
    """The CSV lines of ``m``, a text of several lines for each value of the second input (the
    numbers as ``repr``, to read back exactly)."""
    xs = [repr(float(v)) for v in m.first_values]
    labels = list(m.labels)
    for i, yv in enumerate(m.second_values):
        yt = repr(float(yv))
        cat = m.category[i].tolist()
        over = m.overturned[i].tolist()
        rot = m.max_rotation[i].tolist()
        sl = m.residual_slide[i].tolist()
        yield "\n".join(f"{xs[j]},{yt},{labels[cat[j]]},{'true' if over[j] else 'false'},"
                        f"{rot[j] + 0.0!r},{sl[j] + 0.0!r}" for j in range(len(xs)))


def write_outcome_record(path: str | os.PathLike[str], record: OutcomeRecord) -> str:
    """Write the data of an outcome map (:class:`~regimemap.motion.record.OutcomeRecord`) with
    :func:`write_outcome`: its fixed inputs, and its dimensionless axes when it has them; the format."""
    m = record.outcome
    return write_outcome(path, m, m.first_name, m.second_name, inputs=record.inputs, axes=record.extra_axes)


def outcome_summary(record: OutcomeRecord) -> list[str]:
    """What an outcome map took, in words: its runs, their time and the count of each category
    found; the runs and batches of the refined boundaries."""
    m = record.outcome
    lines = [f"{record.n_runs} runs in {m.seconds:.1f} s: "
             + ", ".join(f"{lab} {c}" for lab, c in record.counts.items() if c)]
    if m.crossings is not None:
        lines.append(f"boundaries refined to 1/1000 of each axis: {m.crossings.runs} runs in "
                     f"{m.crossings.batches} batches, {m.refine_seconds:.1f} s")
    return lines


def outcome_record(m: OutcomeMap, first: str, second: str, inputs: Mapping[str, Any] | None = None,
                   axes: Mapping[str, NDArray[np.float64]] | None = None) -> dict[str, Any]:
    """An outcome map as a JSON-ready dict (numbers rounded to 12 significant digits,
    :data:`regimemap.records.numbers.DIGITS`).

    Keys: ``first`` and ``second`` (the swept inputs' names: x and y), ``axes`` (their values,
    and any ``axes`` given, e.g. dimensionless ones), ``labels`` (the categories by code),
    ``category`` (the category of every cell by name, a list of rows: ``category[i][j]`` at
    ``second[i]``, ``first[j]``), ``max_rotation`` (rad) and ``residual_slide`` (m) likewise,
    ``refined`` (whether the boundaries were refined), ``boundaries`` (a list of
    ``{"between": [category, category], "points": [[x, y], ...]}`` in the swept inputs' units,
    x the first; empty when not refined), ``min_rotation`` (rad) and ``inputs``.
    """
    labels = list(m.labels)
    names = np.asarray(labels, dtype=object)[np.asarray(m.category, dtype=np.int64)]
    ax = {first: m.first_values, second: m.second_values, **(axes or {})}
    return rounded({
        "first": first,
        "second": second,
        "axes": {key: np.asarray(arr, dtype=np.float64) for key, arr in ax.items()},
        "labels": labels,
        "category": names.tolist(),
        "max_rotation": np.asarray(m.max_rotation, dtype=np.float64),
        "residual_slide": np.asarray(m.residual_slide, dtype=np.float64),
        "refined": m.refined,
        "boundaries": [{"between": [a, b], "points": np.asarray(p, dtype=np.float64)}
                       for a, b, p in m.boundaries()],
        "min_rotation": float(m.min_rotation),
        "inputs": dict(inputs or {}),
    })


# -- a cache of computed outcome maps (make figures) ----------------------------------------------


#: The layout of a cached map: a new one makes every older cache file out of date (2: the
#: refined boundaries, ``crossings_*``).
_CACHE_FORMAT = "outcome-map 2 (refined boundaries)"


def _numpy_dispatch() -> str:
    """The CPU dispatch targets numpy runs here, e.g. ``"X86_V3 X86_V4 AVX512_ICL"``.

    numpy picks at import, for each loop (exp, log, sin, power ...), the highest of its compiled
    targets that the CPU has and ``NPY_DISABLE_CPU_FEATURES`` leaves; the targets' loops differ
    in the last bits, so numbers computed under one set are not those of another, bit for bit.
    ``""`` on a CPU with none above numpy's baseline, or a numpy that does not tell.
    """
    import importlib

    try:
        umath = importlib.import_module("numpy._core._multiarray_umath")
    except ImportError:  # numpy 1.x
        umath = importlib.import_module("numpy.core._multiarray_umath")
    dispatch: Sequence[str] = getattr(umath, "__cpu_dispatch__", ())
    found: Mapping[str, bool] = getattr(umath, "__cpu_features__", {})
    return " ".join(t for t in dispatch if found.get(t))


def _cache_key(spec: str) -> str:
    """A digest of ``spec``, the cache's layout, regimemap's and numpy's versions, numpy's CPU
    dispatch targets (:func:`_numpy_dispatch`) and the source of regimemap.dynamics: any change to
    the stepper, or a map computed on other loops, makes a new key."""
    import hashlib

    from .. import __version__
    from ..dynamics import stepper

    h = hashlib.sha256()
    h.update(f"{_CACHE_FORMAT}\n{spec}\n{__version__}\n{np.__version__}\n{_numpy_dispatch()}\n".encode())
    for src in sorted(Path(stepper.__file__).parent.glob("*.py")):
        h.update(src.name.encode())
        h.update(src.read_bytes())
    return h.hexdigest()[:20]


_CACHED = ("first_values", "second_values", "category", "overturned", "max_rotation", "residual_slide")


def cached_outcome(folder: str | os.PathLike[str] | None, name: str, spec: str,
                   compute: Any) -> tuple[OutcomeMap, NDArray[np.float64], NDArray[np.float64], bool]:
    """``compute()`` -> (OutcomeMap, x, y), through a cache of ``.npz`` files in ``folder``.

    The file ``<name>-<key>.npz`` holds the map's arrays and its refined crossings exactly
    (float64), so a figure drawn from it is byte-identical to one drawn from a fresh
    computation on the same machine.  The key (:func:`_cache_key`) covers ``spec`` (the
    figure's definition), the layout of the file, the versions of regimemap and numpy, numpy's
    CPU dispatch targets (a cache shared between machines, or filled under another
    ``NPY_DISABLE_CPU_FEATURES``, is computed again) and the source of
    :mod:`regimemap.dynamics`.  ``folder`` None: no cache.
    Returns the map, x, y and whether it came from the cache.
    """
    if folder is None:
        m, x, y = compute()
        return m, x, y, False
    path = Path(folder) / f"{name}-{_cache_key(spec)}.npz"
    for old in Path(folder).glob(f"{name}-*.npz"):  # the same figure's out-of-date maps
        if old != path:
            old.unlink(missing_ok=True)
    if path.is_file():
        try:
            with np.load(path, allow_pickle=False) as z:
                crossings = None
                if bool(z["refined"]):
                    from ..dynamics.boundaries import Crossings

                    crossings = Crossings.from_arrays({k[len("crossings_"):]: z[k] for k in z.files
                                                       if k.startswith("crossings_")})
                m = OutcomeMap(first_name=str(z["first_name"]), second_name=str(z["second_name"]),
                               labels=tuple(str(v) for v in z["labels"]),
                               seconds=float(z["seconds"]), crossings=crossings,
                               refine_seconds=float(z["refine_seconds"]),
                               min_rotation=float(z["min_rotation"]), **{k: z[k] for k in _CACHED})
                return m, z["x"], z["y"], True
        except (OSError, ValueError, KeyError):  # a damaged cache file: compute again
            pass
    m, x, y = compute()
    Path(folder).mkdir(parents=True, exist_ok=True)
    arrays = {k: np.asarray(getattr(m, k)) for k in _CACHED}
    if m.crossings is not None:
        arrays.update({f"crossings_{k}": v for k, v in m.crossings.arrays().items()})
    write_npz(path, {"first_name": np.array(m.first_name), "second_name": np.array(m.second_name),
                     "labels": np.array(m.labels), "seconds": np.float64(m.seconds), "x": np.asarray(x),
                     "y": np.asarray(y), "refined": np.bool_(m.refined),
                     "refine_seconds": np.float64(m.refine_seconds),
                     "min_rotation": np.float64(m.min_rotation), **arrays})
    return m, x, y, False
