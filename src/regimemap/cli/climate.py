"""``regimemap climate``: return values of the significant wave height, with their bands, from a record.

Parses the options, reads the record (:func:`regimemap.io.records.read_record`), runs
:func:`regimemap.climate.analyse` and writes the report (:mod:`regimemap.io.climate`) and the
figures (:mod:`regimemap.drawing.climate`) atomically.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from ._common import ParamType, import_matplotlib, output_path, report_written
from ._inputs import RECORD_FILE
from ._writing import writing

__all__ = ["climate_cmd"]

FIGURE_FORMATS = ("png", "svg", "pdf")


class _Threshold(ParamType):
    name = "threshold"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return value
        from ..climate.peaks import parse_threshold

        try:
            return parse_threshold(value)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


class _Periods(ParamType):
    name = "periods"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return value
        try:
            out = tuple(float(v) for v in value.split(","))
        except ValueError:
            self.fail(f"return periods must be numbers of years > 1, comma-separated, got {value!r}",
                      param, ctx)
        if not out or any(not (1.0 < v <= 1e5) for v in out):
            self.fail(f"return periods must be numbers of years in (1, 100000], got {value!r}", param, ctx)
        return out


def _figures(outputs: tuple[str, ...], diagnostics: str | None) -> None:
    """The ``-o`` and ``--diagnostics`` files, checked before any work."""
    every = [*outputs, *([diagnostics] if diagnostics else [])]
    if len({str(Path(p).resolve()) for p in every}) < len(every):
        raise click.BadParameter("the same file is given twice", param_hint="'-o' / '--diagnostics'")
    for path in every:
        kind = Path(path).suffix.lower().lstrip(".")
        if kind not in FIGURE_FORMATS:
            got = f".{kind}" if kind else "no suffix"
            raise click.BadParameter(f"{path!r} has {got}; the figures are written as .png, .svg or .pdf",
                                     param_hint="'-o' / '--diagnostics'")
        output_path(path, "--output")


@click.command("climate", short_help="Return values of Hs with confidence bands from a wave record.")
@click.argument("record", type=RECORD_FILE, metavar="RECORD")
@click.option("--method", type=click.Choice(["pot", "annual-maxima"]), default="pot", show_default=True,
              help="Peaks over a threshold (storms) or the maxima of the calendar years.")
@click.option("--threshold", type=_Threshold(), default="99.5%", show_default=True, metavar="U",
              help="Storm threshold: a height in metres, or a quantile of the heights such as 99.5%.")
@click.option("--gap", "gap_hours", type=click.FloatRange(min=0.0, min_open=True, max=8760.0), default=48.0,
              show_default=True, metavar="HOURS",
              help="A storm ends when no exceedance follows within this many hours (> 0).")
@click.option("--distribution", type=click.Choice(["gpd", "weibull", "gumbel", "gev"]), default=None,
              help="gpd or weibull for storm peaks (default gpd); gumbel or gev for annual maxima "
                   "(default gumbel).")
@click.option("--shape", type=click.FloatRange(min=0.5, max=5.0), default=2.0, show_default=True,
              metavar="K", help="The fixed Weibull shape k (Goda: 0.75 to 2), 0.5 to 5.")
@click.option("--coverage", type=click.FloatRange(min=0.0, min_open=True, max=1.0), default=0.8,
              show_default=True, metavar="SHARE",
              help="Least share of a calendar year's hours observed for its annual maximum, (0, 1].")
@click.option("--return-periods", type=_Periods(), default="10,50,100", show_default=True, metavar="R,R",
              help="Return periods in years (> 1), comma-separated.")
@click.option("--confidence", type=click.FloatRange(min=0.5, max=0.999), default=0.9, show_default=True,
              metavar="LEVEL", help="Level of the bootstrap bands, 0.5 to 0.999.")
@click.option("--bootstrap", type=click.IntRange(min=0, max=100000), default=200, show_default=True,
              metavar="N", help="Bootstrap replicates for the bands (0: none).")
@click.option("--seed", type=click.IntRange(min=0), default=0, show_default=True, metavar="S",
              help="Root seed of the bootstrap (the same seed, the same bands).")
@click.option("--time", "time_col", default=None, metavar="NAME", help="The time column (CSV, NetCDF).")
@click.option("--hs", "hs_col", default=None, metavar="NAME", help="The significant-wave-height column.")
@click.option("--period", "period_col", default=None, metavar="NAME",
              help="The period column (NDBC: DPD, the default, or APD).")
@click.option("--drop-spikes", is_flag=True, help="Remove the isolated spikes (else flagged and kept).")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object instead of text.")
@click.option("-o", "--output", "outputs", type=click.Path(dir_okay=False), metavar="FILE", multiple=True,
              help="Figure (repeatable; .png, .svg or .pdf): the record, the return levels with the "
                   "band and the observations, the QQ plot.")
@click.option("--diagnostics", type=click.Path(dir_okay=False), default=None, metavar="FILE",
              help="Threshold diagnostics figure: mean residual life and parameter stability.")
@click.option("--strict", is_flag=True, help="Quality-control and fit warnings are errors (exit 2).")
def climate_cmd(record: str, method: str, threshold: tuple[str, float], gap_hours: float,
                distribution: str | None, shape: float, coverage: float, return_periods: tuple[float, ...],
                confidence: float, bootstrap: int, seed: int, time_col: str | None, hs_col: str | None,
                period_col: str | None, drop_spikes: bool, as_json: bool, outputs: tuple[str, ...],
                diagnostics: str | None, strict: bool) -> None:
    """Return values of the significant wave height, with bootstrap bands, from a wave RECORD.

    RECORD is CSV (an ISO time column and an Hs column found by their usual names), the
    semicolon text 'YYYY-MM-DD-HH; Hs; Tz', an NDBC standard meteorological file, or NetCDF
    (the 'metocean' extra); gzip-compressed text too.  The quality control (missing values,
    repeated or unsorted times, gaps, spikes, coverage per year) is reported.  Storms are the
    peaks over --threshold, declustered with --gap; the fit is by maximum likelihood; the bands
    are percentile intervals of a non-parametric bootstrap (storm counts Poisson).

    \b
    Examples:
      regimemap climate ndbc44007_1996-2005_hs_tz.txt
      regimemap climate buoy.csv --threshold 4.5 --gap 72 -o return-levels.png
      regimemap climate buoy.csv --method annual-maxima --distribution gev --json
    """
    from ..climate import ClimateOptions

    _figures(outputs, diagnostics)
    options = ClimateOptions(method=method, threshold=threshold, gap_hours=gap_hours,
                             distribution=distribution, shape=shape, coverage=coverage,
                             return_periods=return_periods, confidence=confidence, bootstrap=bootstrap,
                             seed=seed)
    try:
        options.check()
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="'--distribution'") from None
    result = _analyse(record, options, time_col, hs_col, period_col, drop_spikes)
    warnings = result.warnings()
    if strict and warnings:
        more = f" (and {len(warnings) - 1} more)" if len(warnings) > 1 else ""
        raise click.BadParameter(f"{record}: {warnings[0]}{more}; --strict refuses quality-control warnings",
                                 param_hint="'RECORD'")
    written = _write(result, outputs, diagnostics, Path(record).name)
    from ..io.climate import climate_json, format_climate

    if as_json:
        obj = climate_json(result, source=record)
        if written:
            obj["files"] = written
        click.echo(json.dumps(obj, indent=2, allow_nan=False))
        return
    click.echo(format_climate(result, source=record))
    for path in written:
        report_written(path)


def _analyse(record: str, options: Any, time_col: str | None, hs_col: str | None, period_col: str | None,
             drop_spikes: bool) -> Any:
    """Read and analyse: an unreadable record or an impossible analysis is a usage error naming it."""
    from ..climate import analyse
    from ..io.records import read_record

    try:
        rec = read_record(record, time=time_col, hs=hs_col, period=period_col, drop_spikes=drop_spikes)
        return analyse(rec, options)
    except ValueError as exc:
        message = str(exc)
        if not message.startswith(record):
            message = f"{record}: {message}"
        raise click.BadParameter(message, param_hint="'RECORD'") from None


def _write(result: Any, outputs: tuple[str, ...], diagnostics: str | None, title: str) -> list[str]:
    """The figures, each drawn once and written atomically."""
    written: list[str] = []
    if not outputs and diagnostics is None:
        return written
    import_matplotlib()
    from ..drawing.climate.figures import climate_figure, diagnostics_figure
    from ..drawing.save import save_figure

    if outputs:
        from ..climate.analysis import curves

        fig = climate_figure(result, curves(result), title)
        for path in outputs:
            with writing(path):
                save_figure(fig, path)
            written.append(path)
    if diagnostics is not None:
        from ..climate.analysis import diagnostics as compute

        found = compute(result.record, result.options.gap_hours)
        fig = diagnostics_figure(found, result.fit.threshold, title)
        with writing(diagnostics):
            save_figure(fig, diagnostics)
        written.append(diagnostics)
    return written
