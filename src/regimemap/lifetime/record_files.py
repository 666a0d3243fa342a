"""The files of ``regimemap lifetime`` for programs: every trial (CSV, NPZ) and the chart's table (CSV).

:func:`write_samples` writes every trial of a :class:`~regimemap.lifetime.LifetimeResult`
(the format from the file's suffix, :data:`SAMPLE_FORMATS`), :func:`write_chart` the table of
a :class:`~regimemap.lifetime.DesignChart` (with a record's climate band, its ends at each
width); both atomically.  The reports for people (text) and the JSON are
:mod:`regimemap.lifetime.record`'s.  Lengths are in metres, probabilities in [0, 1]; numbers
are written to 12 significant digits.
"""

from __future__ import annotations

import math
import os
from typing import TYPE_CHECKING, Any

import numpy as np

from ..io.csv import write_csv
from ..io.formats import format_for, record_formats
from ..io.npz import write_npz
from . import DesignChart, LifetimeResult
from .results import threshold_key

if TYPE_CHECKING:
    from .replicates import ChartBand

__all__ = ["SAMPLE_FORMATS", "write_chart", "write_samples"]

#: Formats of :func:`write_samples` (from the file's suffix).
SAMPLE_FORMATS: tuple[str, ...] = record_formats("lifetimes")


# -- the chart's table -----------------------------------------------------------------------------


def _csv_number(x: float) -> str:
    return f"{x + 0.0:.12g}" if math.isfinite(x) else ""


def write_chart(chart: DesignChart, path: str | os.PathLike[str], band: ChartBand | None = None) -> None:
    """Write the chart's table as CSV, atomically: one row per width.

    Columns: ``width_m``, ``expected_sliding_m``, ``std_error_m``, then
    ``p_exceed_<x>m`` for each threshold (``P(S > x)``), then ``p_failure``
    (``P(S > failure_sliding)``) when the chart has a sliding limit, then, with a
    record's climate ``band``, ``band_lower_m`` and ``band_upper_m`` (the ends of
    the ESD's climate band at each width, the curves the chart's figure draws);
    numbers to 12 significant digits.

    Raises
    ------
    OSError
        If the file cannot be written (nothing is left behind).
    """
    head = ["width_m", "expected_sliding_m", "std_error_m"]
    head += [f"p_exceed_{threshold_key(x)}m" for x in chart.thresholds]
    fail = chart.failure_probability
    if fail is not None:
        head.append("p_failure")
    if band is not None:
        if band.widths.size != chart.widths.size or not np.allclose(band.widths, chart.widths):
            raise ValueError("the climate band was run at other widths than the chart's")
        head += ["band_lower_m", "band_upper_m"]
        lower, upper = band.lower, band.upper
    rows = []
    for i, (w, e, se) in enumerate(zip(chart.widths, chart.expected_sliding, chart.std_error)):
        cells = [_csv_number(float(w)), _csv_number(float(e)), _csv_number(float(se))]
        if chart.exceedance is not None:
            cells += [_csv_number(float(p)) for p in chart.exceedance[i]]
        if fail is not None:
            cells.append(_csv_number(float(fail[i])))
        if band is not None:
            cells += [_csv_number(float(lower[i])), _csv_number(float(upper[i]))]
        rows.append(",".join(cells))
    write_csv(path, head, rows)


# -- every trial ---------------------------------------------------------------------------------


def write_samples(result: LifetimeResult, path: str | os.PathLike[str]) -> str:
    """Write every trial of ``result``, atomically; the format (csv or npz) from the suffix.

    ``.csv``: ``trial,sliding_m,max_storm_m,storms``, one row per lifetime
    (``trial`` from 0, the position in the arrays), numbers to 12 significant
    digits.  ``.npz``: the arrays ``sliding`` and ``max_storm`` (m), ``storms``,
    and ``seed`` (as text: a fresh seed has more digits than an int64),
    ``years``, ``width`` (m) and ``thresholds`` (m).

    Returns
    -------
    str
        The format.

    Raises
    ------
    ValueError
        For another suffix.
    OSError
        If the file cannot be written (nothing is left behind).
    """
    fmt = format_for(path, "lifetimes")
    if fmt == "npz":
        arrays: dict[str, np.ndarray[Any, Any]] = {
            "sliding": np.asarray(result.sliding, dtype=np.float64),
            "max_storm": np.asarray(result.max_storm, dtype=np.float64),
            "storms": np.asarray(result.storms, dtype=np.int64),
            "seed": np.array(str(result.seed)),
            "years": np.int64(result.years),
            "width": np.float64(result.width),
            "thresholds": np.asarray(result.thresholds, dtype=np.float64),
        }
        write_npz(path, arrays)
        return fmt
    sliding = result.sliding.tolist()
    storm = result.max_storm.tolist()
    storms = result.storms.tolist()
    write_csv(path, ("trial", "sliding_m", "max_storm_m", "storms"),
              (f"{i},{sliding[i] + 0.0:.12g},{storm[i] + 0.0:.12g},{storms[i]}" for i in range(len(sliding))))
    return fmt
