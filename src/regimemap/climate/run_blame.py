"""The input that a refused run of ``regimemap climate`` blames: a column named by ``--time``,
``--hs`` or ``--period`` that the record lacks, the threshold, the coverage or the return periods
of an analysis that cannot be made (:func:`regimemap.lifetime.file_record.analysis_fault`), or
else the record itself (``RECORD``)."""

from __future__ import annotations

__all__ = ["COLUMN_OPTIONS", "FIELD_OPTIONS", "blamed_option"]

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
