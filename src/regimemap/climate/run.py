"""The climate workflow: return values of the significant wave height, with their intervals, from a record.

:func:`run_climate` reads a wave record (:func:`regimemap.climate.file.read_record`; or takes a
:class:`regimemap.climate.wave_record.Record` made from arrays with
:func:`regimemap.climate.make_record`), runs the extreme-value analysis
(:func:`regimemap.climate.analyse`: quality control, storms or annual maxima, the maximum
likelihood fit, the intervals, the fit's warnings) and computes what its figures draw (the return-level
curve, the observations at their plotting positions and, when asked, the threshold
diagnostics).  It returns one :class:`ClimateRecord`; ``regimemap climate`` is this call
followed by writing the record.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from ..records.fields import Field, Record
from ..records.notices import Notice
from ..records.numbers import shortest

if TYPE_CHECKING:
    from .analysis import ClimateOptions, ClimateResult, Curves, Diagnostics, Sensitivity
    from .wave_record import Record as WaveRecord

__all__ = ["ClimateRecord", "run_climate"]


@dataclass(frozen=True)
class ClimateRecord(Record):
    """The analysis of a wave record, with what its figures draw (:func:`run_climate`).

    Attributes
    ----------
    source : str
        The record's file (or the source the record names).
    options : ClimateOptions
        The method, threshold, gap, distribution, return periods, bootstrap.
    notices : tuple of Notice
        The quality control's warnings (code ``record-quality``) and the fit's notes (code
        ``fit``), each naming the record.
    result : ClimateResult
        The record, its storms or annual maxima, the fit, the band, the return values.
    curves : Curves
        The return-level curve with its band and the observations (the figure's data).
    diagnostics : Diagnostics or None
        Mean residual life and parameter stability over thresholds; None unless asked for.
    sensitivity : Sensitivity or None
        The 50-year value and its interval refitted above the 98 to 99.7 % quantiles (peaks over
        a threshold with an interval; else None).
    """

    CAPTION: ClassVar[str] = "Wave climate"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("result.record.years", "record", "years", "observed"),
        Field("result.record.coverage", "coverage", "", "share of the span observed"),
        Field("options.method", "method", "", "peaks over a threshold or annual maxima"),
        Field("result.fit.threshold", "u", "m", "the storm threshold (peaks over a threshold)"),
        Field("result.fit.rate", "storms a year", "1/year", "the rate of the values fitted"),
        Field("result.fit.n", "values fitted", "", "storm peaks or annual maxima"),
        Field("result.fit.distribution", "distribution", "", "fitted by maximum likelihood"),
        Field("return_value_text", "return values", "m", "Hs at the return periods, with the band"))

    source: str
    options: ClimateOptions
    notices: tuple[Notice, ...]
    result: ClimateResult
    curves: Curves
    diagnostics: Diagnostics | None
    sensitivity: Sensitivity | None = None

    @property
    def return_value_text(self) -> str:
        """``10 years: 7.01 m (6.65 to 7.25 m); ...``: the return values and their bands."""
        parts = []
        for rv in self.result.return_values:
            band = ("" if rv["lower"] is None or rv["upper"] is None
                    else f" ({rv['lower']:.2f} to {rv['upper']:.2f} m)")
            assert rv["period"] is not None
            parts.append(f"{shortest(rv['period'])} years: {rv['value']:.2f} m{band}")
        return "; ".join(parts)

    def report_text(self) -> str:
        """The report for people (:func:`regimemap.climate.record.format_climate`)."""
        from .record import format_climate

        return format_climate(self.result, source=self.source, sensitivity=self.sensitivity)

    def report_json(self, files: list[str] | tuple[str, ...] = ()) -> dict[str, Any]:
        """The JSON-ready report (:func:`~regimemap.climate.record.climate_json`), with the ``files``
        written."""
        from .record import climate_json

        out = climate_json(self.result, source=self.source, sensitivity=self.sensitivity)
        if files:
            out["files"] = list(files)
        return out


def run_climate(record: WaveRecord | str | Path, options: ClimateOptions | None = None, *,
                time: str | None = None, hs: str | None = None, period: str | None = None,
                drop_spikes: bool = False, diagnostics: bool = False) -> ClimateRecord:
    """Return values of the significant wave height, with their intervals, from a wave record.

    Parameters
    ----------
    record : Record, str or Path
        A wave record's file (CSV, the semicolon text, NDBC, NetCDF; gzip too) or a
        :class:`regimemap.climate.wave_record.Record` made from arrays.
    options : ClimateOptions, optional
        How to analyse it (default :class:`~regimemap.climate.ClimateOptions`: peaks over the
        99.5 % quantile, a 48-hour gap, a GPD, the posterior interval with 200 replicate fits).
    time, hs, period : str, optional
        The columns of a file (CSV, NetCDF; NDBC: the period column).
    drop_spikes : bool, optional
        Remove the isolated spikes of a file (else flagged and kept).
    diagnostics : bool, optional
        Compute the threshold diagnostics (Coles 2001, Sect. 4.3.1) too.

    Returns
    -------
    ClimateRecord

    Raises
    ------
    ValueError
        The options do not go together, or the record cannot be read or analysed (the
        message names the file).
    """
    from . import ClimateOptions, analyse
    from .analysis import curves, sensitivity
    from .analysis import diagnostics as threshold_diagnostics

    opts = ClimateOptions() if options is None else options
    opts.check()
    if isinstance(record, (str, Path)):
        from .file import read_record

        source = str(record)
        wave = read_record(record, time=time, hs=hs, period=period, drop_spikes=drop_spikes)
    else:
        source, wave = record.source, record
    result = analyse(wave, opts)
    am = opts.method == "annual-maxima"
    notices = tuple(Notice("record-quality", f"{source}: {w}")
                    for w in wave.quality.warnings(opts.coverage if am else None))
    notices += tuple(Notice(n.code, f"{source}: {n.message}", n.quantity, n.value) for n in result.notices)
    found = threshold_diagnostics(wave, opts.gap_hours, confidence=opts.confidence) if diagnostics else None
    return ClimateRecord(source=source, options=opts, notices=notices, result=result, curves=curves(result),
                         diagnostics=found, sensitivity=sensitivity(wave, opts))
