"""``[lifetime.record]`` of the design file: the site's wave climate from a measured record.

``path`` (relative to the design file) names a record that :func:`regimemap.climate.file.read_record`
reads; ``method``, ``threshold``, ``gap_hours``, ``distribution``, ``shape`` and ``coverage`` are
the options of ``regimemap climate``.  The record is the site's deep-water (offshore) sea state:
its fit becomes the lifetime's climate of ``H0'`` (:func:`regimemap.climate.life.climate_of`), the
storm rate the record's.  With ``climate_replicates = N`` in ``[lifetime]`` the bootstrap of the
fit gives N replicate climates (:func:`regimemap.lifetime.replicates.climate_band`).
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from regimemap.climate.wave_record import HS_MAX

from ..io.toml_keys import Key, KeyReader, key, keys_of, number_of
from .climate import WEIBULL_SHAPE_RANGE

if TYPE_CHECKING:
    from regimemap.climate import ClimateResult
    from regimemap.lifetime import Climate

    from ..io.toml_errors import DesignFileError

__all__ = ["MAX_REPLICATES", "RECORD_KEYS", "RecordSpec", "analysis_fault", "read_record_table",
           "record_analysis", "record_climate", "record_period_law"]

#: Most replicate climates of ``climate_replicates``.
MAX_REPLICATES = 10_000

#: The option of the analysis (a field of :class:`regimemap.climate.ClimateOptions`) that a
#: ValueError of :func:`regimemap.climate.analyse` blames, told by its message.
_FAULTS: tuple[tuple[re.Pattern[str], str], ...] = (
    (re.compile(r"threshold \S+ m is at or above every height"), "threshold"),
    (re.compile(r"\d+ storm\(s\) above the threshold"), "threshold"),
    (re.compile(r"\d+ annual maxima: a fit needs"), "coverage"),
    (re.compile(r"return period \S+ years is shorter|no \S+-year return value"), "return_periods"),
)


def analysis_fault(message: str) -> str | None:
    """The option of the analysis that an error of :func:`regimemap.climate.analyse` blames:
    ``"threshold"`` (above every height, too few storms over it), ``"coverage"`` (too few annual
    maxima), ``"return_periods"``; None when it is the record itself (too short, all equal).

    Examples
    --------
    >>> analysis_fault("4 storm(s) above the threshold 6.5 m: a fit needs at least 10")
    'threshold'
    """
    return next((key for pattern, key in _FAULTS if pattern.search(message)), None)


@dataclass(frozen=True)
class RecordSpec:
    """``[lifetime.record]`` as the file gives it, ``path`` resolved against the design file."""

    path: str = key("the record's file, relative to the design file (CSV, the semicolon text, NDBC "
                    "standard meteorological, NetCDF)", kind="text")
    method: str = key('"pot" (peaks over a threshold, the default) or "annual-maxima"',
                      lambda x: x in ("pot", "annual-maxima"), kind="text", default="pot")
    threshold: tuple[str, float] = key('a height > 0 in metres or a quantile such as "99.5%" (the default)',
                                       kind="text", default=("quantile", 0.995))
    gap_hours: float = key("a declustering gap > 0 in hours (default 48)", lambda x: 0.0 < x <= 8760.0,
                           default=48.0)
    distribution: str | None = key('"gpd" or "weibull" (pot; default gpd), "gumbel" or "gev" '
                                   "(annual-maxima; default gumbel)", kind="text", default=None)
    shape: float = key(f"the fixed Weibull shape k, {WEIBULL_SHAPE_RANGE[0]:g} to {WEIBULL_SHAPE_RANGE[1]:g} "
                       "(default 2)", lambda x: WEIBULL_SHAPE_RANGE[0] <= x <= WEIBULL_SHAPE_RANGE[1],
                       default=2.0)
    coverage: float = key("the least share of a calendar year observed for its annual maximum, in (0, 1] "
                          "(default 0.8)", lambda x: 0.0 < x <= 1.0, default=0.8)
    period_ratio: float | None = key(
        "T1/3 over the record's period, 0.5 to 2 (about 0.95 for a peak period Tp, 1.2 to 1.35 for a "
        "zero-crossing Tz): T1/3 = a H0'^b is then fitted on the storm peaks (default: none, Goda's "
        "T1/3 = 3.3 H0'^0.63)", lambda x: 0.5 <= x <= 2.0, default=None)


#: The keys of ``[lifetime.record]`` and what each accepts.
RECORD_KEYS: dict[str, Key] = keys_of(RecordSpec)
#: The distributions of each method of ``[lifetime.record]``.
_DISTRIBUTIONS = {"pot": ("gpd", "weibull"), "annual-maxima": ("gumbel", "gev")}


def _threshold(v: Any, bad: Callable[[str, str], DesignFileError]) -> tuple[str, float]:
    """``threshold``: a height in metres (a number; at most :data:`HS_MAX`, so ``99.5`` is the
    quantile ``"99.5%"`` mistyped) or a quantile (a string such as ``"99.5%"``)."""
    from regimemap.climate.peaks import parse_threshold

    try:
        kind, u = parse_threshold(v if isinstance(v, str) else repr(number_of(v)))
    except ValueError:
        raise bad("threshold", "neither a height > 0 nor a percentage") from None
    if kind == "value" and u > HS_MAX:
        hint = f'; did you mean "{u:g}%"?' if u < 100.0 else ""
        raise bad("threshold", f"above any sea state (Hs at most {HS_MAX:g} m){hint}")
    return kind, u


def read_record_table(r: KeyReader, table: Mapping[str, Any]) -> RecordSpec:
    """The checked ``[lifetime.record]`` table (``r`` the design file's reader).

    Raises
    ------
    DesignFileError
        Naming the file, the line, the key, the value and what is accepted.
    """
    t = "lifetime.record"

    def bad(key: str, why: str) -> DesignFileError:
        return r.bad(t, key, table[key], why)

    r.check_keys(t, table)
    if "path" not in table:
        raise r.fail(f"[{t}] has no path; accepted: {RECORD_KEYS['path'].accepted}", t)
    if not isinstance(table["path"], str) or not table["path"].strip():
        raise bad("path", "expected a file name")
    got: dict[str, Any] = {"path": str(Path(r.source).parent / table["path"])}
    if "method" in table:
        if not RECORD_KEYS["method"].check(table["method"]):
            raise bad("method", "not one of the accepted values")
        got["method"] = table["method"]
    if "threshold" in table:
        got["threshold"] = _threshold(table["threshold"], bad)
    for name in ("gap_hours", "shape", "coverage", "period_ratio"):
        if name in table:
            got[name] = r.number(t, table, name, table[name])
    if "distribution" in table:
        method = got.get("method", "pot")
        if table["distribution"] not in _DISTRIBUTIONS[method]:
            raise bad("distribution", f"not a distribution of {method}")
        got["distribution"] = table["distribution"]
    spec = RecordSpec(**got)
    _check_analysis(r, table, spec)
    return spec


def _check_analysis(r: KeyReader, table: Mapping[str, Any], spec: RecordSpec) -> None:
    """The record read and fitted (once: :func:`record_analysis` keeps it), and ``period_ratio``'s
    law; an error names the line of the key it blames -- ``path`` for a record that cannot be
    read, ``threshold``, ``coverage``, ``period_ratio`` -- or of ``[lifetime.record]``."""
    from ..climate.file import RecordError

    try:
        record_analysis(spec)
        record_period_law(spec)
    except RecordError as exc:
        raise r.fail(f"[lifetime.record] path = {r.written('lifetime.record', 'path', table['path'])}: {exc}",
                     "lifetime.record", "path") from None
    except ValueError as exc:
        message = str(exc)
        law = message.startswith("[lifetime.record] period_ratio")
        key = "period_ratio" if law else analysis_fault(message)
        if key is None or key not in table:
            raise r.fail(message if message.startswith("[lifetime.record]")
                         else f"[lifetime.record]: {message}", "lifetime.record") from None
        shown = r.written("lifetime.record", key, table[key])
        message = message.removeprefix(f"[lifetime.record] {key}: ")
        message = message.replace("lower --coverage", "lower coverage")  # the key, not the option
        raise r.fail(f"[lifetime.record] {key} = {shown}: {message}", "lifetime.record", key) from None


@functools.lru_cache(maxsize=8)
def record_analysis(spec: RecordSpec, replicates: int = 0, seed: int = 0) -> ClimateResult:
    """The record's analysis (read, storms, fit; ``replicates`` bootstrap fits from ``seed``).

    Raises
    ------
    ValueError
        The record cannot be read or analysed (the message names it).
    """
    from regimemap.climate import ClimateOptions, analyse

    from ..climate.file import read_record

    options = ClimateOptions(method=spec.method, threshold=spec.threshold, gap_hours=spec.gap_hours,
                             distribution=spec.distribution, shape=spec.shape, coverage=spec.coverage,
                             return_periods=(10.0, 50.0), replicates=replicates, seed=seed)
    return analyse(read_record(spec.path), options)


def record_climate(spec: RecordSpec) -> Climate:
    """The lifetime's climate of ``H0'`` fitted to the record."""
    from regimemap.climate.life import climate_of

    return climate_of(record_analysis(spec).fit)


def record_period_law(spec: RecordSpec) -> tuple[float, float] | None:
    """``(a, b)`` of ``T1/3 = a H0'^b`` fitted on the storm peaks with ``T1/3 = period_ratio x`` the
    record's period; None without ``period_ratio`` (Goda's relation).

    Raises
    ------
    ValueError
        ``period_ratio`` is given but the record has no period, or too few storm peaks with one
        (or the method is annual maxima).
    """
    from regimemap.climate.life import MIN_PERIODS, period_law

    if spec.period_ratio is None:
        return None
    result = record_analysis(spec)
    law = None if result.storms is None else period_law(result.storms)
    if law is None:
        raise ValueError(f"[lifetime.record] period_ratio: {spec.path} gives no period at {MIN_PERIODS} "
                         "or more storm peaks (a period column and peaks over a threshold are needed)")
    return spec.period_ratio * law[0], law[1]
