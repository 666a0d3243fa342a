"""The ``[lifetime]`` table of the design file: the climate and the options of the lifetime simulation.

:class:`LifetimeSpec` is the table as the file gives it; the keys it accepts,
with what each accepts, are in :mod:`regimemap.lifetime.file_keys`;
:func:`read_lifetime` reads the table with the line of every key refused
(:func:`regimemap.io.toml_lines.key_line`); :func:`lifetime_model` turns it into
a :class:`regimemap.lifetime.LifetimeModel`.  :mod:`regimemap.caisson.file` reads
the whole file and re-exports the public names.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from ..io.toml_keys import KeyReader, default_of
from .file_keys import ERROR_FACTORS, LIFETIME_KEYS, LIFETIME_TABLES, LifetimeSpec

if TYPE_CHECKING:
    from regimemap.lifetime import LifetimeModel

    from .file_record import RecordSpec

__all__ = ["LifetimeSpec", "lifetime_model", "lifetime_reader", "read_lifetime"]

_CLIMATE = ("either H0_10 and H0_50 (the 10- and 50-year return values of H0', metres) or "
            "annual_maxima (a list of annual maxima of H0', metres)")


def _check_climate(r: KeyReader, got: Mapping[str, Any], data: Mapping[str, Any]) -> None:
    """The climate of return values or annual maxima: complete, consistent."""
    t = "lifetime"
    h10, h50, maxima = got["H0_10"], got["H0_50"], got["annual_maxima"]
    if maxima is not None and (h10 is not None or h50 is not None):
        raise r.fail("[lifetime] annual_maxima together with "
                     f"{'H0_10' if h10 is not None else 'H0_50'}; accepted: {_CLIMATE}", t, "annual_maxima")
    if maxima is None:
        if h10 is None or h50 is None:
            if h10 is None and h50 is None:
                raise r.fail(f"[lifetime] has no wave climate; accepted: {_CLIMATE}", t)
            given, missing = ("H0_10", "H0_50") if h50 is None else ("H0_50", "H0_10")
            raise r.fail(f"[lifetime] {missing} is missing ({given} = {data[given]!r} is given); "
                         f"accepted: {_CLIMATE}", t, given)
        if not h50 > h10:
            raise r.bad(t, "H0_50", data["H0_50"], f"not above [lifetime] H0_10 = {data['H0_10']!r}")
    else:
        if len(maxima) < 3:
            raise r.bad(t, "annual_maxima", data["annual_maxima"],
                        f"{len(maxima)} value{'s' if len(maxima) != 1 else ''}, fewer than three")
        if min(maxima) == max(maxima):
            raise r.bad(t, "annual_maxima", data["annual_maxima"], "the values are all equal")
        if got["storms_per_year"] is not None:
            raise r.fail(f"[lifetime] storms_per_year = {data['storms_per_year']!r} together with "
                         "annual_maxima; accepted: annual maxima are one storm a year: give H0_10 and H0_50 "
                         "of the peaks over a threshold with storms_per_year, or annual_maxima alone",
                         t, "storms_per_year")
        if got["distribution"] != "gumbel" and got["shape"] is not None and not got["shape"] > 1.0:
            raise r.bad(t, "shape", data["shape"], "fitting annual_maxima with a Weibull "
                        "distribution needs k > 1 (the likelihood is unbounded for k <= 1)")


def _read(r: KeyReader, data: Mapping[str, Any]) -> LifetimeSpec:
    """``[lifetime]`` (``data``) read and checked."""
    t = "lifetime"
    r.check_keys(t, data)
    got = {key: r.value(t, data, key) for key in LIFETIME_KEYS}
    errors: dict[str, tuple[float, float]] = {}
    if got["errors"] is not None:
        r.check_keys("lifetime.errors", got["errors"])
        for key in ERROR_FACTORS:
            pair = r.value("lifetime.errors", got["errors"], key)
            if pair is not None:
                errors[key] = pair

    record = _record_table(r, got, data)
    if record is None:
        _check_climate(r, got, data)
    if got["period"] is not None and got["steepness"] is not None:
        raise r.fail(f"[lifetime] steepness = {data['steepness']!r} together with [lifetime] period = "
                     f"{data['period']!r}; accepted: one of them, or neither (Goda's T1/3 = 3.3 H0'^0.63)",
                     t, "steepness")
    # every key as given, else its declared default; then those read with others
    values = {key: default_of(LifetimeSpec, key) if got[key] is None else got[key] for key in LIFETIME_KEYS}
    values.update(
        thresholds=None if got["thresholds"] is None else tuple(sorted(set(got["thresholds"]))),
        errors=errors, record=record, climate_replicates=_replicates(got["climate_replicates"], record),
        written={key: _written(data[key]) for key in ("H0_10", "H0_50", "annual_maxima") if key in data})
    spec = LifetimeSpec(**values)
    try:  # anything the checks above missed, said the library's way
        lifetime_model(spec)
    except ValueError as exc:
        raise r.fail(f"[lifetime]: {exc}", t) from None
    return spec


def _replicates(given: int | None, record: RecordSpec | None) -> int:
    """``climate_replicates`` as given; with a record and none given,
    :data:`regimemap.lifetime.replicates.DEFAULT_REPLICATES` (a record's climate is judged with its
    uncertainty); 0 without a record."""
    from .replicates import DEFAULT_REPLICATES

    if given is not None:
        return int(given)
    return DEFAULT_REPLICATES if record is not None else 0


def _record_table(r: KeyReader, got: Mapping[str, Any], data: Mapping[str, Any]) -> RecordSpec | None:
    """``[lifetime.record]`` read by :func:`regimemap.lifetime.file_record.read_record_table`; refused
    beside another climate; ``climate_replicates`` only with it."""
    from .file_record import read_record_table

    if got["record"] is None:
        if got["climate_replicates"] is not None:
            raise r.fail("[lifetime] climate_replicates needs a [lifetime.record] table (the replicates are "
                         "the bootstrap of the record's fit)")
        return None
    others = [k for k in ("H0_10", "H0_50", "annual_maxima", "storms_per_year", "distribution", "shape")
              if k in data]
    if others:
        raise r.fail(f"[lifetime] {others[0]} together with [lifetime.record]; accepted: the record alone "
                     "(its fit gives the climate and the storm rate)", "lifetime", others[0])
    return read_record_table(r, got["record"])


def _written(value: Any) -> str:
    """A parsed TOML value as the file wrote it (the shortest text that reads back the same)."""
    if isinstance(value, list):
        return "[" + ", ".join(_written(x) for x in value) + "]"
    return repr(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)


def lifetime_model(spec: LifetimeSpec, years: int | None = None) -> LifetimeModel:
    """The :class:`regimemap.lifetime.LifetimeModel` of a ``[lifetime]`` table (``years`` instead of its own).

    ``years`` is not checked here (:func:`check_lifetime_option` does).
    """
    import numpy as np

    from regimemap.lifetime import DEFAULT_ERRORS, DEFAULT_THRESHOLDS, Climate, ErrorFactor, LifetimeModel

    law = None
    if spec.record is not None:
        from .file_record import record_climate, record_period_law

        climate = record_climate(spec.record)
        if spec.period is None and spec.steepness is None:
            law = record_period_law(spec.record)
    else:
        try:  # an overflow of the fit is named here, not printed by numpy
            with np.errstate(all="raise"):
                if spec.annual_maxima is not None:
                    from regimemap.climate.life import climate_of_maxima

                    climate = climate_of_maxima(spec.annual_maxima, spec.distribution, spec.shape)
                else:
                    assert spec.H0_10 is not None and spec.H0_50 is not None
                    climate = Climate.from_return_values(spec.H0_10, spec.H0_50, spec.distribution,
                                                         spec.shape, spec.storms_per_year)
                climate.return_value(50.0)
        except (FloatingPointError, OverflowError) as exc:
            what = "annual_maxima" if spec.annual_maxima is not None else "H0_10 and H0_50"
            raise ValueError(f"the {spec.distribution} climate of {what} cannot be computed ({exc}): "
                             "the values are too far apart or too close together") from None
    errors = replace(DEFAULT_ERRORS, **{name: ErrorFactor(*pair) for name, pair in spec.errors.items()})
    return LifetimeModel(climate, years=spec.years if years is None else years,
                         storm_hours=spec.storm_hours, period=spec.period, steepness=spec.steepness,
                         tide_range=spec.tide_range, impulsive=spec.impulsive, truncate=spec.truncate,
                         period_law=law,
                         errors=errors,
                         thresholds=DEFAULT_THRESHOLDS if spec.thresholds is None else spec.thresholds)


def lifetime_reader(source: str, text: str) -> KeyReader:
    """The reader of a design file's ``[lifetime]``, ``[lifetime.errors]`` and ``[lifetime.record]``."""
    from .file_record import RECORD_KEYS

    return KeyReader(source, text, {**LIFETIME_TABLES, "lifetime.record": RECORD_KEYS})


def read_lifetime(text: str, source: str, table: Mapping[str, Any]) -> LifetimeSpec:
    """The checked ``[lifetime]`` table (``table``, as tomllib parsed it from ``text``).

    Raises
    ------
    DesignFileError
        Naming ``source``, the line of the key (from ``text``), the key, the
        value and what is accepted.
    """
    return _read(lifetime_reader(source, text), table)
