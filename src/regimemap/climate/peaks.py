"""Storms of a record (peaks over a threshold, declustered) and its annual maxima.

numpy only.  A storm is a run of exceedances of the threshold ``u``: it ends
when no exceedance follows within ``gap`` hours (runs declustering, Coles
2001, Sect. 5.3.2).  Its peak is the largest height of the run, its period the
record's period at that peak, its duration the hours above the threshold
(exceedances x sampling step).  The annual maxima come from the calendar years
observed at least ``coverage`` of their hours.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .wave_record import Record

__all__ = ["DEFAULT_COVERAGE", "DEFAULT_GAP", "DEFAULT_QUANTILE", "AnnualMaxima", "Storms",
           "annual_maxima", "parse_threshold", "resolve_threshold", "storms"]

FloatArray = NDArray[np.float64]

#: Default threshold: this quantile of the observed heights.
DEFAULT_QUANTILE = 0.995
#: Default declustering gap [h].
DEFAULT_GAP = 48.0
#: Default least share of a calendar year's hours observed for its annual maximum.
DEFAULT_COVERAGE = 0.8

_PERCENT = re.compile(r"^\s*([0-9]*\.?[0-9]+)\s*%\s*$")


def parse_threshold(text: str) -> tuple[str, float]:
    """``"99.5%"`` -> ``("quantile", 0.995)``; ``"4.2"`` -> ``("value", 4.2)``.

    Raises
    ------
    ValueError
        Neither a number > 0 nor a percentage in (0, 100).

    Examples
    --------
    >>> parse_threshold("99.5%"), parse_threshold("4.2")
    (('quantile', 0.995), ('value', 4.2))
    """
    m = _PERCENT.match(text)
    if m:
        q = float(m.group(1)) / 100.0
        if not 0.0 < q < 1.0:
            raise ValueError(f"threshold must be a percentage in (0, 100) or a height in metres > 0, "
                             f"got {text!r}")
        return "quantile", q
    wrong = f"threshold must be a height in metres > 0 or a percentage such as 99.5%, got {text!r}"
    try:
        v = float(text)
    except ValueError:
        raise ValueError(wrong) from None
    if not (v > 0.0 and np.isfinite(v)):
        raise ValueError(wrong)
    return "value", v


def resolve_threshold(record: Record, kind: str = "quantile", value: float = DEFAULT_QUANTILE) -> float:
    """The threshold in metres: ``value`` itself, or that quantile of the observed heights.

    Raises
    ------
    ValueError
        The threshold is at or above every observed height.
    """
    hs = record.hs[np.isfinite(record.hs)]
    u = float(np.quantile(hs, value)) if kind == "quantile" else float(value)
    if not u < float(hs.max()):
        raise ValueError(f"threshold {u:.3g} m is at or above every height of the record "
                         f"(largest {float(hs.max()):.3g} m)")
    return u


@dataclass(frozen=True)
class Storms:
    """The storms of a record above a threshold.

    Attributes
    ----------
    threshold : float
        ``u`` [m].
    gap_hours : float
        The declustering gap [h].
    peak : ndarray
        Storm peak heights [m], in time order.
    peak_time : ndarray of datetime64[s]
        Times of the peaks.
    period : ndarray or None
        The record's period at each peak [s] (NaN where missing), None without periods.
    duration : ndarray
        Hours above the threshold of each storm.
    years : float
        The record's length in years (observed samples x step).
    """

    threshold: float
    gap_hours: float
    peak: FloatArray
    peak_time: NDArray[np.datetime64]
    period: FloatArray | None
    duration: FloatArray
    years: float

    @property
    def count(self) -> int:
        """Number of storms."""
        return int(self.peak.size)

    @property
    def rate(self) -> float:
        """Storms per record year, ``lambda``."""
        return self.count / self.years


def storms(record: Record, threshold: float, gap_hours: float = DEFAULT_GAP) -> Storms:
    """Peaks over ``threshold``, declustered with ``gap_hours``.

    Parameters
    ----------
    record : Record
        The sea states.
    threshold : float
        ``u`` [m]: a sample belongs to a storm when its height exceeds ``u``.
    gap_hours : float
        A storm ends when no exceedance follows within this many hours (> 0).

    Returns
    -------
    Storms

    Examples
    --------
    >>> from regimemap.climate.wave_record import make_record
    >>> t = np.datetime64("2000-01-01T00", "s") + np.arange(8) * np.timedelta64(3600, "s")
    >>> r = make_record("x", t, np.array([1, 3, 1, 3.5, 1, 1, 1, 4.0]))
    >>> s = storms(r, 2.0, gap_hours=2.0)
    >>> s.peak.tolist(), s.duration.tolist()
    ([3.5, 4.0], [2.0, 1.0])
    """
    if not gap_hours > 0.0:
        raise ValueError(f"gap must be a number of hours > 0, got {gap_hours!r}")
    with np.errstate(invalid="ignore"):
        above = np.flatnonzero(record.hs > threshold)
    hours = record.hours()[above]
    starts = np.concatenate([[0], np.flatnonzero(np.diff(hours) > gap_hours) + 1]) if above.size else \
        np.zeros(0, dtype=np.int64)
    values = record.hs[above]
    peak_at = np.array([above[s + int(np.argmax(values[s:e]))]
                        for s, e in zip(starts, np.append(starts[1:], above.size))], dtype=np.int64)
    counts = np.diff(np.append(starts, above.size))
    return Storms(threshold=float(threshold), gap_hours=float(gap_hours), peak=record.hs[peak_at],
                  peak_time=record.time[peak_at],
                  period=None if record.period is None else record.period[peak_at],
                  duration=counts.astype(np.float64) * record.step_hours, years=record.years)


@dataclass(frozen=True)
class AnnualMaxima:
    """The largest height of each well-observed calendar year.

    Attributes
    ----------
    years : ndarray of int
        The calendar years used.
    maxima : ndarray
        Their largest heights [m].
    skipped : list of int
        Calendar years observed less than ``coverage`` of their hours.
    coverage : float
        The least share required.
    """

    years: NDArray[np.int64]
    maxima: FloatArray
    skipped: list[int]
    coverage: float


def annual_maxima(record: Record, coverage: float = DEFAULT_COVERAGE) -> AnnualMaxima:
    """Annual maxima of the calendar years with at least ``coverage`` of their hours observed.

    Raises
    ------
    ValueError
        ``coverage`` outside (0, 1].
    """
    if not 0.0 < coverage <= 1.0:
        raise ValueError(f"coverage must be in (0, 1], got {coverage!r}")
    year_of = record.time.astype("datetime64[Y]").astype(np.int64) + 1970
    used, maxima, skipped = [], [], []
    for y, c in record.quality.coverage.items():
        if c >= coverage:
            used.append(y)
            maxima.append(float(np.nanmax(record.hs[year_of == y])))
        else:
            skipped.append(y)
    return AnnualMaxima(years=np.array(used, dtype=np.int64), maxima=np.array(maxima, dtype=np.float64),
                        skipped=skipped, coverage=float(coverage))
