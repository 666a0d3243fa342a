"""The options of ``regimemap climate`` as typed: the threshold (a height in metres, or a quantile
``99.5%``) and the return periods (``10,50,100``), each checked with a message that names the
slip; and the input that a refused run blames -- a column named by ``--time``, ``--hs`` or
``--period`` that the record lacks, the threshold, the coverage or the return periods of an
analysis that cannot be made (:func:`regimemap.lifetime.file_record.analysis_fault`), or else the
record itself (``RECORD``)."""

from __future__ import annotations

__all__ = ["COLUMN_OPTIONS", "FIELD_OPTIONS", "blamed_option", "return_periods_option", "threshold_option"]

#: The option of each field of :class:`~regimemap.climate.ClimateOptions` that an analysis's error
#: may blame.
FIELD_OPTIONS = {"threshold": "--threshold", "coverage": "--coverage", "return_periods": "--return-periods"}
#: The option that names each column of a record.
COLUMN_OPTIONS = {"time": "--time", "significant wave height": "--hs", "period": "--period"}


def blamed_option(exc: ValueError, record: str, *, time: str | None = None, hs: str | None = None,
                  period: str | None = None) -> tuple[str, str]:
    """The message of an error of :func:`regimemap.climate.run.run_climate` on the file ``record``
    (starting with the file's name) and the option it blames (``RECORD`` when none); ``time``,
    ``hs`` and ``period`` are the columns the options named.

    Examples
    --------
    >>> blamed_option(ValueError("4 storm(s) above the threshold 6.5 m: a fit needs at least 10"), "b.csv")
    ('b.csv: 4 storm(s) above the threshold 6.5 m: a fit needs at least 10', '--threshold')
    """
    from ..lifetime.file_record import analysis_fault
    from .file import RecordError

    message = str(exc)
    if not message.startswith(record):
        message = f"{record}: {message}"
    if isinstance(exc, RecordError):  # a column named by --time, --hs or --period that is not there
        given = {"time": time, "significant wave height": hs, "period": period}
        option = next((COLUMN_OPTIONS[what] for what, col in given.items()
                       if col is not None and f" for the {what} (columns: " in message), "RECORD")
    else:
        option = FIELD_OPTIONS.get(analysis_fault(str(exc)) or "", "RECORD")
    return message, option


def threshold_option(text: str) -> tuple[str, float]:
    """``--threshold``: ``("value", metres)`` or ``("quantile", share)``
    (:func:`regimemap.climate.peaks.parse_threshold`); ValueError for a bare number above any sea
    state (``99.5``: did you mean ``99.5%``?).

    Examples
    --------
    >>> threshold_option("99.5%")
    ('quantile', 0.995)
    """
    from .peaks import parse_threshold
    from .wave_record import HS_MAX

    kind, u = parse_threshold(text)
    if kind == "value" and u > HS_MAX:  # a bare number is metres: 99.5 is above any sea state
        hint = (f"did you mean {text.strip()}%? (a quantile of the heights is written with %)"
                if u < 100.0 else "give a height in metres or a quantile such as 99.5%")
        raise ValueError(f"threshold {u:g} m is above any sea state (Hs at most {HS_MAX:g} m); {hint}")
    return kind, u


def return_periods_option(text: str) -> tuple[float, ...]:
    """``--return-periods``: years, comma-separated, each in (1, 100000]; ValueError otherwise.
    Sorted, each period once (as ``[lifetime] thresholds`` are).

    Examples
    --------
    >>> return_periods_option("10,50,100")
    (10.0, 50.0, 100.0)
    >>> return_periods_option("100,10,10")
    (10.0, 100.0)
    """
    try:
        out = tuple(float(v) for v in text.split(","))
    except ValueError:
        raise ValueError(f"return periods must be numbers of years > 1, comma-separated, got {text!r}"
                         ) from None
    if not out or any(not (1.0 < v <= 1e5) for v in out):
        raise ValueError(f"return periods must be numbers of years in (1, 100000], got {text!r}")
    return tuple(sorted(set(out)))
