"""A wave record -- times, significant wave heights, periods -- and its quality control.

numpy only.  The readers of :mod:`regimemap.climate.file` parse a file into
arrays and call :func:`make_record`, which sorts the times, drops repeated
times, finds the sampling step, the gaps, the isolated spikes and the
coverage of each calendar year, and reports all of it in a :class:`Quality`:
nothing is changed silently.  A spike is flagged and listed, and dropped only
when asked (``drop_spikes``).  A time given twice with the same values is a
counted drop; with values that differ (:class:`Conflicts`) it is a warning that
names the first such time, its copies and how far apart the copies are.
"""

from __future__ import annotations

import decimal
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

__all__ = ["HS_MAX", "PERIOD_MAX", "SPIKE_JUMP", "SPIKE_RATIO", "Conflicts", "Quality", "Record",
           "find_spikes", "make_record"]

FloatArray = NDArray[np.float64]
TimeArray = NDArray[np.datetime64]

#: Largest physically possible significant wave height [m] (the largest measured are about 19 m;
#: a value above this is an error in the file, not a storm).
HS_MAX = 30.0
#: Largest plausible wave period [s].
PERIOD_MAX = 40.0
#: An isolated spike: a value ``SPIKE_RATIO`` times the larger of its two neighbours ...
SPIKE_RATIO = 1.8
#: ... and at least ``SPIKE_JUMP`` metres above it.
SPIKE_JUMP = 1.5

_HOUR = np.timedelta64(3600, "s")


@dataclass(frozen=True)
class Conflicts:
    """Repeated times whose copies give different values (the first observed copy of each is kept).

    Two copies conflict when both have a height and the heights differ, or both have a period
    and the periods differ; a missing copy (a missing code, an empty field) gives no value and
    conflicts with none.

    Attributes
    ----------
    count : int
        Times with copies that differ.
    time : str
        The first (earliest) of them (ISO, UTC).
    hs : tuple of float
        Its copies' heights [m] (NaN: missing), the kept one first, then the others in file order.
    lines : tuple of int
        The copies' lines in the file, in the order of ``hs`` (empty when the reader gave none).
    period : tuple of float
        The copies' periods [s], in the order of ``hs`` (empty without a period).
    hs_spread : float
        The largest difference between the heights of the copies of one time [m].
    period_spread : float
        The largest difference between their periods [s] (0 without a period or a difference).
    """

    count: int
    time: str
    hs: tuple[float, ...]
    lines: tuple[int, ...] = ()
    period: tuple[float, ...] = ()
    hs_spread: float = 0.0
    period_spread: float = 0.0

    def message(self, period_name: str | None = None) -> str:
        """What the quality report says of them, e.g. ``1 repeated time(s) with differing copies,
        the first observed of each kept: 2003-12-07T05:00Z (lines 67644, 67645) Hs 12.10 m kept,
        7.10 m dropped; copies differ by up to 5.00 m in Hs``."""
        h = np.asarray(self.hs)
        agree = bool(np.all(h == h[0]) or not np.any(np.isfinite(h)))
        by_period = agree and len(self.period) == len(self.hs)  # the heights agree: show the periods
        values, unit = (self.period, "s") if by_period else (self.hs, "m")

        def m(v: float) -> str:
            return "missing" if not np.isfinite(v) else f"{v:.2f} {unit}"

        more = ", ..." if len(self.lines) > 4 else ""
        where = f" (lines {', '.join(str(n) for n in self.lines[:4])}{more})" if self.lines else ""
        dropped = ", ".join(m(v) for v in values[1:4]) + (", ..." if len(values) > 4 else "")
        name = (period_name or "period") if by_period else "Hs"
        spread = [f"{self.hs_spread:.2f} m in Hs"] if self.hs_spread > 0.0 else []
        if self.period_spread > 0.0:
            spread.append(f"{self.period_spread:.2f} s in {period_name or 'the period'}")
        return (f"{self.count} repeated time(s) with differing copies, the first observed of each kept: "
                f"{self.time}{where} {name} {m(values[0])} kept, {dropped} dropped; "
                f"copies differ by up to {', '.join(spread)}")


@dataclass(frozen=True)
class Quality:
    """What the quality control found in a record.

    Attributes
    ----------
    missing : int
        Samples without a height (missing codes such as NDBC's ``99.00``, empty fields, NaN).
    duplicates : int
        Samples dropped because their time repeats another's (the first observed copy is kept; a
        copy with the same values is a quiet drop).
    unsorted : int
        Samples whose time is earlier than the one before them in the file (the record is sorted).
    gaps : list of (str, str, float)
        Gaps longer than 1.5 sampling steps: start, end (ISO) and length in hours, longest first.
    spikes : list of (str, float)
        Isolated spikes (a value at least :data:`SPIKE_RATIO` times and :data:`SPIKE_JUMP` metres
        above both neighbours): time and height.
    spikes_dropped : bool
        Whether the spikes were removed from the record (else they are kept and flagged).
    coverage : dict of int to float
        Share of each calendar year's hours that are observed (0 to 1).
    conflicts : Conflicts or None
        The repeated times whose copies differ (a warning), None when there are none.
    period_name : str or None
        The period's column, for the messages.
    """

    missing: int
    duplicates: int
    unsorted: int
    gaps: list[tuple[str, str, float]] = field(default_factory=list)
    spikes: list[tuple[str, float]] = field(default_factory=list)
    spikes_dropped: bool = False
    coverage: dict[int, float] = field(default_factory=dict)
    conflicts: Conflicts | None = None
    period_name: str | None = None

    def warnings(self, min_coverage: float | None = None) -> list[str]:
        """The findings a careful user must see (``--strict`` makes them errors); the calendar
        years below ``min_coverage`` too when it is given (annual maxima)."""
        out = []
        if self.conflicts is not None:
            out.append(self.conflicts.message(self.period_name))
        if self.unsorted:
            out.append(f"{self.unsorted} sample(s) out of time order (the record was sorted)")
        if self.spikes:
            what = "dropped" if self.spikes_dropped else "kept and flagged"
            first = ", ".join(f"{t} {h:.2f} m" for t, h in self.spikes[:3])
            more = f" and {len(self.spikes) - 3} more" if len(self.spikes) > 3 else ""
            out.append(f"{len(self.spikes)} isolated spike(s) {what}: {first}{more}")
        short = [] if min_coverage is None else [y for y, c in self.coverage.items() if c < min_coverage]
        if short:
            out.append(f"{len(short)} calendar year(s) below {100 * (min_coverage or 0.0):g} % coverage "
                       "left out of the annual maxima: "
                       + ", ".join(f"{y} ({_percent_below(self.coverage[y], min_coverage or 0.0)} %)"
                                   for y in short))
        return out


def _percent_below(share: float, limit: float) -> str:
    """``share`` (below ``limit``) in per cent, whole unless that reads as the limit (as the warning
    writes it, ``{100 * limit:g}``) or above: then with the fewest decimals that keep it below
    (99.96 % below 100 % reads ``99.96``, not ``100``)."""
    text = f"{100 * share:.0f}"
    with decimal.localcontext() as ctx:
        ctx.prec = 2000  # every digit of a float: the products below are exact
        exact = decimal.Decimal(share) * 100
        top = min(decimal.Decimal(limit) * 100, decimal.Decimal(f"{100 * limit:g}"))
        digits = 0
        while decimal.Decimal(text) >= top and exact < top:
            digits += 1
            text = f"{exact:.{digits}f}"
    return text


@dataclass(frozen=True)
class Record:
    """A record of sea states (sorted, times unique).

    Attributes
    ----------
    source : str
        The file it came from.
    time : ndarray of datetime64[s]
        Times (UTC).
    hs : ndarray
        Significant wave height [m] (NaN: missing).
    period : ndarray or None
        A wave period [s] (NaN: missing), or None when the record has none.
    period_name : str or None
        The period's column as the file names it (``Tz``, ``DPD`` ...).
    step_hours : float
        The sampling step [h]: the most common spacing of the times.
    quality : Quality
        What the quality control found.
    """

    source: str
    time: TimeArray
    hs: FloatArray
    period: FloatArray | None
    period_name: str | None
    step_hours: float
    quality: Quality

    @property
    def observed(self) -> int:
        """Samples with a height."""
        return int(np.count_nonzero(np.isfinite(self.hs)))

    @property
    def years(self) -> float:
        """Record length in years: observed samples x sampling step / 365.25 days."""
        return self.observed * self.step_hours / (24.0 * 365.25)

    @property
    def start(self) -> str:
        """The first time (ISO, UTC)."""
        return _iso(self.time[0])

    @property
    def end(self) -> str:
        """The last time (ISO, UTC)."""
        return _iso(self.time[-1])

    @property
    def coverage(self) -> float:
        """Observed samples over the samples the span from start to end would hold."""
        span = (self.time[-1] - self.time[0]) / _HOUR / self.step_hours + 1.0
        return float(self.observed / span)

    def hours(self) -> FloatArray:
        """Times as hours since the first sample."""
        return np.asarray((self.time - self.time[0]) / _HOUR, dtype=np.float64)


def _iso(t: np.datetime64) -> str:
    return str(np.datetime_as_string(t, unit="m")) + "Z"


def _step_hours(time: TimeArray) -> float:
    d = np.diff(time) / np.timedelta64(1, "s")
    d = d[d > 0]
    if d.size == 0:
        raise ValueError("the record has fewer than two distinct times")
    values, counts = np.unique(d, return_counts=True)
    return float(values[int(np.argmax(counts))]) / 3600.0


def _gaps(time: TimeArray, observed: NDArray[np.bool_], step: float) -> list[tuple[str, str, float]]:
    t = time[observed]
    if t.size < 2:
        return []
    d = np.diff(t) / _HOUR
    where = np.flatnonzero(d > 1.5 * step)
    order = where[np.argsort(-d[where], kind="stable")]
    return [(_iso(t[i]), _iso(t[i + 1]), float(d[i])) for i in order]


def find_spikes(hs: FloatArray, hours: FloatArray, step: float) -> NDArray[np.bool_]:
    """Isolated spikes: a height at least :data:`SPIKE_RATIO` times and :data:`SPIKE_JUMP` metres
    above both its neighbours, the neighbours observed and at most 1.5 steps away.

    Parameters
    ----------
    hs : ndarray
        Heights [m] (NaN: missing), in time order.
    hours : ndarray
        Their times [h].
    step : float
        The sampling step [h].

    Returns
    -------
    ndarray of bool
        True at the spikes.

    Examples
    --------
    >>> hs = np.array([1.0, 1.1, 4.0, 1.2, 1.3])
    >>> find_spikes(hs, np.arange(5.0), 1.0).tolist()
    [False, False, True, False, False]
    """
    out = np.zeros(hs.shape, dtype=bool)
    if hs.size < 3:
        return out
    mid, before, after = hs[1:-1], hs[:-2], hs[2:]
    close = (np.diff(hours)[:-1] <= 1.5 * step) & (np.diff(hours)[1:] <= 1.5 * step)
    with np.errstate(invalid="ignore"):
        top = np.fmax(before, after)
        spike = (close & np.isfinite(before) & np.isfinite(after) & (mid >= SPIKE_RATIO * top)
                 & (mid - top >= SPIKE_JUMP))
    out[1:-1] = spike
    return out


def _coverage(time: TimeArray, observed: NDArray[np.bool_], step: float) -> dict[int, float]:
    years = time.astype("datetime64[Y]").astype(np.int64) + 1970
    out: dict[int, float] = {}
    for y in range(int(years[0]), int(years[-1]) + 1):
        start = np.datetime64(f"{y:04d}-01-01T00:00:00", "s")
        end = np.datetime64(f"{y + 1:04d}-01-01T00:00:00", "s")
        hours_in_year = float((end - start) / _HOUR)
        n = int(np.count_nonzero(observed[years == y]))
        out[y] = min(n * step / hours_in_year, 1.0)
    return out


def _spread(x: FloatArray, starts: NDArray[np.intp]) -> FloatArray:
    """The largest minus the smallest observed value of each group (NaN: none observed)."""
    with np.errstate(invalid="ignore"):
        return np.fmax.reduceat(x, starts) - np.fmin.reduceat(x, starts)


def _conflicts(t: TimeArray, h: FloatArray, p: FloatArray | None, first: NDArray[np.bool_],
               lines: NDArray[np.int64] | None) -> Conflicts | None:
    """The repeated times of ``t`` (sorted; ``first`` marks the first copy of each time) whose
    observed heights, or periods, differ; None when every repeated copy agrees."""
    starts = np.flatnonzero(first)
    dh = _spread(h, starts)
    dp = np.zeros_like(dh) if p is None else _spread(p, starts)
    with np.errstate(invalid="ignore"):
        differ = (dh > 0.0) | (dp > 0.0)
    if not np.any(differ):
        return None
    g = int(np.flatnonzero(differ)[0])
    end = int(starts[g + 1]) if g + 1 < starts.size else t.size
    copies = slice(int(starts[g]), end)
    return Conflicts(count=int(np.count_nonzero(differ)), time=_iso(t[copies.start]),
                     hs=tuple(float(v) for v in h[copies]),
                     lines=() if lines is None else tuple(int(n) for n in lines[copies]),
                     period=() if p is None else tuple(float(v) for v in p[copies]),
                     hs_spread=float(np.max(dh[differ], initial=0.0, where=np.isfinite(dh[differ]))),
                     period_spread=float(np.max(dp[differ], initial=0.0, where=np.isfinite(dp[differ]))))


def make_record(source: str, time: TimeArray, hs: FloatArray, period: FloatArray | None = None,
                period_name: str | None = None, drop_spikes: bool = False,
                lines: NDArray[np.int64] | None = None) -> Record:
    """A :class:`Record` from parsed arrays, with its quality control.

    Parameters
    ----------
    source : str
        The file (for the messages).
    time : ndarray of datetime64
        Times as read (any order; repeats allowed and reported).
    hs : ndarray
        Heights [m], NaN where missing; no negative value (the readers refuse them).
    period : ndarray, optional
        Periods [s], NaN where missing.
    period_name : str, optional
        The period's column name.
    drop_spikes : bool, optional
        Remove the isolated spikes (:func:`find_spikes`) instead of only flagging them.
    lines : ndarray of int, optional
        The line of each sample in its file, for the messages (the copies of a repeated time).

    Returns
    -------
    Record

    Raises
    ------
    ValueError
        No sample with a height, or fewer than two distinct times.
    """
    t = np.asarray(time, dtype="datetime64[s]")
    h = np.asarray(hs, dtype=np.float64)
    p = None if period is None else np.asarray(period, dtype=np.float64)
    unsorted = int(np.count_nonzero(np.diff(t) < np.timedelta64(0, "s")))
    order = np.argsort(t, kind="stable")
    keep = np.ones(t.size, dtype=bool)
    keep[1:] = t[order][1:] != t[order][:-1]
    duplicates = int(t.size - np.count_nonzero(keep))
    conflicts = None
    if duplicates:  # the observed copies of a time first, each in file order
        order = np.lexsort((~np.isfinite(h), t))
        conflicts = _conflicts(t[order], h[order], None if p is None else p[order], keep,
                               None if lines is None else np.asarray(lines)[order])
    t, h = t[order], h[order]
    p = None if p is None else p[order]
    t, h = t[keep], h[keep]
    p = None if p is None else p[keep]
    missing = int(np.count_nonzero(~np.isfinite(h)))
    if missing == h.size:
        raise ValueError(f"{source}: every significant wave height is missing")
    step = _step_hours(t)
    hours = np.asarray((t - t[0]) / _HOUR, dtype=np.float64)
    spikes = find_spikes(h, hours, step)
    spike_list = [(_iso(t[i]), float(h[i])) for i in np.flatnonzero(spikes)]
    if drop_spikes and spike_list:
        h = np.where(spikes, np.nan, h)
    observed = np.isfinite(h)
    quality = Quality(missing=missing, duplicates=duplicates, unsorted=unsorted,
                      gaps=_gaps(t, observed, step), spikes=spike_list, spikes_dropped=drop_spikes,
                      coverage=_coverage(t, observed, step), conflicts=conflicts,
                      period_name=period_name if p is not None else None)
    if p is not None and not np.any(np.isfinite(p)):
        p, period_name = None, None
    return Record(source=source, time=t, hs=h, period=p, period_name=period_name, step_hours=step,
                  quality=quality)
