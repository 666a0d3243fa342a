"""The sliding of a caisson over its design life, for people (text) and programs (JSON).

:func:`lifetime_json` and :func:`format_lifetime` report a
:class:`~regimemap.lifetime.LifetimeResult` (the expected sliding distance with
its standard error, quantiles, exceedance probabilities, the climate);
:func:`chart_json` and :func:`format_chart` a
:class:`~regimemap.lifetime.DesignChart`; the files of every trial and of the chart's table
(CSV, NPZ) are written by :mod:`regimemap.lifetime.record_files`.  With a wave record's climate band
(:class:`~regimemap.lifetime.replicates.ClimateBand`, :class:`~regimemap.lifetime.replicates.ChartBand`)
the reports add the results with the climate's uncertainty before the requirements, which are
judged on them; every report ends with its requirements and the verdict.  The options of
``regimemap lifetime`` that the
design file does not hold are checked in :mod:`regimemap.lifetime.file_options`.  Lengths
are in metres, probabilities in [0, 1] (per cent in the text); JSON numbers are rounded to
12 significant digits.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from ..records.checks import checks_json, checks_lines
from ..records.numbers import optional_float, rounded
from . import DesignChart, LifetimeModel, LifetimeResult
from .results import STATISTICS, threshold_key

if TYPE_CHECKING:
    from .file_record import RecordSpec
    from .replicates import ChartBand, ClimateBand

__all__ = ["band_json", "chart_band_dict", "chart_json", "format_chart", "format_lifetime",
           "impulsive_text", "lifetime_brief_json", "lifetime_brief_lines", "lifetime_json", "record_words",
           "threshold_key", "verdict_word"]

#: Quantiles of the lifetime sliding that are reported.
_QUANTILES = (0.9, 0.99)


# -- JSON ---------------------------------------------------------------------------------------


def _units() -> dict[str, str]:
    """The units of the statistics that have one: the lengths and probabilities, then the years."""
    with_unit = sorted((s for s in STATISTICS if s.unit), key=lambda s: s.unit == "year")
    return {s.key: s.unit + (", keys in m" if s.per_threshold else "") for s in with_unit}


def _model_dict(model: LifetimeModel) -> dict[str, Any]:
    c = model.climate
    return {
        "years": model.years,
        "storm_hours": float(model.storm_hours),
        "period": optional_float(model.period),
        "period_law": None if model.period_law is None else [float(v) for v in model.period_law],
        "steepness": optional_float(model.steepness),
        "tide_range": float(model.tide_range),
        "impulsive": model.impulsive,
        "truncate": optional_float(model.truncate),
        "errors": {name: {"ratio": float(getattr(model.errors, name).ratio),
                          "cov": float(getattr(model.errors, name).cov)}
                   for name in model.errors.names()},
        "climate": {
            "distribution": c.distribution, "scale": float(c.scale), "location": float(c.location),
            "shape": float(c.shape), "storms_per_year": optional_float(c.storms_per_year),
            "H0_10": float(c.return_value(10)), "H0_50": float(c.return_value(50)),
        },
    }


def impulsive_text(impulsive: bool) -> str:
    """The choice of the wave force's coefficient, named: ``impulsive = false (alpha* = alpha2 ...)``."""
    if impulsive:
        return "impulsive = true (alpha* = max(alpha2, alpha_I), Takahashi's impulsive coefficient)"
    return ("impulsive = false (alpha* = alpha2: no impulsive coefficient on the sine pulse, "
            "docs/lifetime.md Sect. 5.1)")


def verdict_word(checks: Any) -> str:
    """``"PASS"`` when every check passes (or there is none), else ``"FAIL"``."""
    return "PASS" if all(c.passed for c in checks) else "FAIL"


def band_json(band: ClimateBand) -> dict[str, Any]:
    """The climate band of a lifetime for JSON: ``{level, lower, upper, replicates,
    expected_sliding, std_error, trials, seed, exceedance, exceedance_std_error}`` -- the ESD
    and ``P(S > x)`` (threshold in metres as text) with the climate's uncertainty: the means over
    the replicate climates [m, -]."""
    return rounded({
        "level": float(band.level), "lower": float(band.lower), "upper": float(band.upper),
        "replicates": band.replicates, "expected_sliding": float(band.expected_sliding),
        "std_error": float(band.std_error), "trials": band.trials, "seed": band.seed,
        "exceedance": {threshold_key(x): float(band.exceedance(x)) for x in band.thresholds},
        "exceedance_std_error": {threshold_key(x): float(band.exceedance_error(x)) for x in band.thresholds}})


def chart_band_dict(band: ChartBand) -> dict[str, Any]:
    """The design chart's climate band for JSON: ``{level, replicates, trials, seed, target,
    widths, lower, upper, width_for_target}`` -- the band's curves at each width [m] and the
    narrowest width whose ESD at the band's upper level meets the target (``null``: none does)."""
    return rounded({"level": float(band.level), "replicates": band.replicates, "trials": band.trials,
                    "seed": band.seed, "target": float(band.target),
                    "widths": [float(w) for w in band.widths], "lower": [float(x) for x in band.lower],
                    "upper": [float(x) for x in band.upper],
                    "width_for_target": optional_float(band.width_for_target)})


def lifetime_json(result: LifetimeResult, model: LifetimeModel, source: str | None = None,
                  written: str | None = None, band: ClimateBand | None = None) -> dict[str, Any]:
    """One JSON-ready object: the expected sliding distance and the statistics of the lifetimes.

    Parameters
    ----------
    result : LifetimeResult
    model : LifetimeModel
        The model that gave ``result`` (its climate and options are reported).
    source : str, optional
        The design file.
    written : str, optional
        The climate as the design file wrote it (``climate_as_written``).
    band : ClimateBand, optional
        The lifetimes under a record's replicate climates (:func:`band_json`): the
        requirements of ``result.checks`` were judged on them.

    Returns
    -------
    dict
        ``failure`` (``{sliding_limit, probability, std_error}`` or null; with
        the climate's uncertainty when there is a band), ``impulsive``, ``expected_sliding`` and
        ``std_error`` (m), ``std``, ``median``,
        ``quantile_90``, ``quantile_99`` (m), ``exceedance`` and
        ``storm_exceedance`` (threshold in metres as text -> probability),
        ``never_slides``, ``mean_storms``, ``trials``, ``seed``, ``years``,
        ``width`` (m), ``climate`` (one line of text), ``model`` (every option),
        ``units``, ``climate_band`` (with a band), then last ``checks`` (the
        requirements: ``[{name, value, required, relation, unit, pass}]``) and
        ``verdict`` (``"PASS"`` or ``"FAIL"``); numbers rounded to 12
        significant digits (``null`` if not finite).
    """
    out: dict[str, Any] = {}
    if source is not None:
        out["source"] = source
    out.update(result.summary())
    out.update({
        "impulsive": model.impulsive,
        "climate": model.climate.describe(),
        "climate_as_written": written,
        "model": _model_dict(model),
        "units": _units(),
    })
    if band is not None:
        out["climate_band"] = band_json(band)
    out["checks"] = checks_json(result.checks)
    out["verdict"] = verdict_word(result.checks)
    return rounded(out)


def chart_json(chart: DesignChart, model: LifetimeModel | None = None, source: str | None = None,
               written: str | None = None, band: ChartBand | None = None) -> dict[str, Any]:
    """One JSON-ready object: the design chart (ESD against width) and the widths it gives.

    Returns
    -------
    dict
        ``chart`` (a list of ``{width, expected_sliding, std_error}``, m),
        ``target`` (m), ``width_for_target`` (m, ``null`` when no width of the
        chart meets the target), ``width_tolerance`` (m), ``width_interval``
        (``{level, lower, upper, resamples}``, m, or ``null``),
        ``failure_sliding`` (m or ``null``), ``impulsive``, ``required_sf``,
        ``sf_width`` (m), ``trials``, ``seed``; with ``model`` also ``years``,
        ``climate`` and ``model``; ``units``; ``climate_band`` (with a band,
        :func:`chart_band_dict`); then last ``checks`` (the design's width
        against the width for the target -- the band's at its upper level when
        there is a band) and ``verdict``.
    """
    out: dict[str, Any] = {}
    if source is not None:
        out["source"] = source
    out["chart"] = [{k: float(v) for k, v in row.items()} for row in chart.rows()]
    out["target"] = float(chart.target)
    out["width_for_target"] = optional_float(chart.width_for_target)
    out["width_tolerance"] = float(chart.tolerance)
    iv = chart.width_interval
    out["width_interval"] = None if iv is None else {
        "level": float(iv.level), "lower": float(iv.lower), "upper": float(iv.upper),
        "resamples": iv.resamples}
    out["failure_sliding"] = optional_float(chart.failure_sliding)
    out["impulsive"] = chart.impulsive
    out["required_sf"] = float(chart.required_sf)
    out["sf_width"] = float(chart.sf_width)
    out["trials"] = chart.trials
    out["seed"] = chart.seed
    if model is not None:
        out["years"] = model.years
        out["climate"] = model.climate.describe()
        out["climate_as_written"] = written
        out["model"] = _model_dict(model)
    out["units"] = {"width": "m", "expected_sliding": "m", "std_error": "m", "target": "m",
                    "width_for_target": "m", "width_tolerance": "m", "width_interval": "m",
                    "failure_sliding": "m", "sf_width": "m"}
    if band is not None:
        out["climate_band"] = chart_band_dict(band)
    out["checks"] = checks_json(chart.checks)
    out["verdict"] = verdict_word(chart.checks)
    return rounded(out)


# -- text ---------------------------------------------------------------------------------------


def _g(x: float, digits: int = 3) -> str:
    """``x`` to ``digits`` significant digits, as short as possible (``0.053``, ``1.14``, ``2e-05``)."""
    if not math.isfinite(x):
        return "n/a"
    if x == 0.0:
        return "0"
    return f"{x:.{digits}g}"


def _value_pm(value: float, se: float) -> str:
    """``value m ± se m``: the standard error to two significant digits and the value to match."""
    if not math.isfinite(se):
        return f"{_g(value)} m ± n/a"
    if se <= 0.0 or value <= 0.0:
        return f"{_g(value)} m ± {_g(se, 2)} m"
    decimals = max(0, 1 - int(math.floor(math.log10(se))))
    if decimals > 6:  # a tiny error: both to significant digits
        return f"{_g(value)} m ± {_g(se, 2)} m"
    return f"{value:.{decimals}f} m ± {se:.{decimals}f} m"


def _percent(p: float) -> str:
    """A share in per cent: ``89.6 %``, ``0.04 %``, ``100 %``."""
    v = 100.0 * p
    if v in (0.0, 100.0):
        return f"{v:.0f} %"
    return f"{v:.1f} %" if v >= 10.0 else f"{v:.3g} %"


def _band_head(band: ClimateBand | ChartBand) -> str:
    return (f"{band.replicates} replicate climates of the record's fit x {band.trials} lifetimes"
            f"{' per width' if hasattr(band, 'widths') else ''}, seed {band.seed}")


def format_lifetime(result: LifetimeResult, model: LifetimeModel, source: str | None = None,
                    written: str | None = None, band: ClimateBand | None = None) -> str:
    """The sliding over the design life for people.

    The expected sliding distance with its standard error beside it, the
    median and quantiles, the exceedance probabilities of the lifetime sliding
    and of the largest single-storm sliding, the share of lifetimes that never
    slide, and the climate (as the file wrote it, then as fitted) and the
    options, the coefficient of the wave force named; with a record's climate
    ``band``, the ESD and the exceedance probabilities with the climate's
    uncertainty and the ESD's band; the probability of failure, given a
    sliding limit (with the climate's uncertainty when there is a band); last,
    one line per requirement and the verdict.
    """
    n = result.trials
    lines = []
    if source:
        lines.append(f"lifetime sliding: {source}")
    lives = f"{n} lifetime{'' if n == 1 else 's'}"
    lines.append(f"caisson {_g(result.width, 4)} m wide, design life {result.years} years, "
                 f"{lives}, seed {result.seed}")
    if written:
        lines.append(f"  climate (as given): {written}")
    lines.append(f"  climate: {model.climate.describe()}")
    lines.append(f"  wave force: {impulsive_text(model.impulsive)}")
    opts = [f"storms of {_g(model.storm_hours)} h",
            (f"T1/3 = {_g(model.period_law[0])} H0'^{_g(model.period_law[1])} (fitted on the record)"
             if model.period_law is not None else
             "T1/3 = 3.3 H0'^0.63" if model.period is None and model.steepness is None else
             f"T1/3 = {_g(model.period)} s" if model.period is not None else
             f"H0'/L0 = {_g(model.steepness or 0.0)}")]
    if model.tide_range > 0.0:
        opts.append(f"tide range {_g(model.tide_range)} m")
    if model.truncate is not None:
        opts.append(f"errors cut at ±{_g(model.truncate)} sd")
    lines.append(f"  model: {', '.join(opts)}")
    lines.append("  errors [ratio, cov]: " + ", ".join(
        f"{name} [{_g(getattr(model.errors, name).ratio)}, {_g(getattr(model.errors, name).cov)}]"
        for name in model.errors.names()))
    lines.append("")
    fitted = " under the fitted climate" if band is not None else ""
    lines.append(f"ESD {_value_pm(result.expected_sliding, result.std_error)} (standard error, {lives})"
                 f"{fitted}")
    qs = ", ".join(f"{100 * q:g} %: {_g(result.quantile(q))} m" for q in _QUANTILES)
    lines.append(f"  median {_g(result.median)} m; quantiles {qs}")
    lines.append(f"  never slides: {_percent(result.never_slides)} of the lifetimes")
    lines.append("probability that the sliding exceeds x:")
    pooled = band is not None and all(x in band.thresholds for x in result.thresholds)
    extra = f"  {'with the climate':>16}" if pooled else ""
    lines.append(f"  {'x [m]':>8}  {'over the life':>13}  {'in one storm':>12}{extra}")
    for x in result.thresholds:
        extra = f"  {_percent(band.exceedance(x)):>16}" if band is not None and pooled else ""
        lines.append(f"  {_g(x):>8}  {_percent(result.exceedance(x)):>13}  "
                     f"{_percent(result.storm_exceedance(x)):>12}{extra}")
    lines.append("  (in one storm: the largest single-storm sliding of the life, Kim & Suh 2013)")
    if pooled:
        lines.append("  (with the climate: over the life, including the climate's uncertainty, the mean "
                     "over the replicate climates)")
    if band is not None:
        lines += _band_lines(band)
    if result.failure is not None:
        f = result.failure
        which = " including the climate's uncertainty" if band is not None else ""
        lines.append(f"probability of failure (sliding off the mound, S > {_g(f.sliding_limit)} m){which}: "
                     f"{_percent(f.probability)} ± {_percent(f.std_error)} over the life")
    if result.checks:
        judged = " (judged including the climate's uncertainty)" if band is not None else ""
        lines.append(f"requirements{judged}:")
        lines += [f"  {line}" for line in checks_lines(result.checks)]
    return "\n".join(lines)


def _band_lines(band: ClimateBand) -> list[str]:
    """The ESD with the climate's uncertainty, its standard error and its band."""
    lines = [f"with the climate's uncertainty ({_band_head(band)}):",
             f"  ESD including the climate's uncertainty {_value_pm(band.expected_sliding, band.std_error)} "
             "(the mean over the climates; standard error over the climates)",
             f"  {100 * band.level:g} % climate band: {_g(band.lower)} m to {_g(band.upper)} m "
             "(the ESD's percentiles over the climates)"]
    return lines


def record_words(record: RecordSpec) -> str:
    """A wave record as the design file names it, with its options: ``the record buoy.txt (peaks over
    the 99.5 % quantile, storms 48 h apart; T1/3 = 1.2 x its period)``."""
    kind, value = record.threshold
    if record.method == "pot":
        over = f"{100 * value:g} % quantile" if kind == "quantile" else f"{value:g} m"
        how = f"peaks over the {over}, storms {record.gap_hours:g} h apart"
    else:
        how = f"annual maxima, years at least {100 * record.coverage:g} % observed"
    if record.period_ratio is not None:
        how += f"; T1/3 = {record.period_ratio:g} x its period"
    return f"the record {record.path} ({how})"


def lifetime_brief_lines(result: LifetimeResult, model: LifetimeModel, band: ClimateBand | None = None,
                         record: RecordSpec | None = None) -> list[str]:
    """The sliding over the design life in a few lines (the caisson's report): the lifetimes, the
    climate -- the wave record named with its fit -- the ESD, and with a record's band the ESD
    including the climate's uncertainty and its band."""
    n = result.trials
    lines = [f"sliding over the design life ([lifetime]; `regimemap lifetime` gives the whole report): "
             f"{n} lifetime{'' if n == 1 else 's'} of {result.years} years, seed {result.seed}"]
    if record is not None:
        lines.append(f"  climate: {record_words(record)}, fitted: {model.climate.describe()}")
    else:
        lines.append(f"  climate: {model.climate.describe()}")
    fitted = " under the fitted climate" if record is not None else ""
    lines.append(f"  ESD {_value_pm(result.expected_sliding, result.std_error)} (standard error){fitted}")
    if band is not None:
        lines += [f"  {line}" for line in _band_lines(band)]
    elif record is not None:
        lines.append("  (climate_replicates = 0: the climate's uncertainty not counted)")
    if result.failure is not None:
        f = result.failure
        which = " including the climate's uncertainty" if band is not None else ""
        lines.append(f"  probability of failure (S > {_g(f.sliding_limit)} m){which}: "
                     f"{_percent(f.probability)} ± {_percent(f.std_error)}")
    return lines


def lifetime_brief_json(result: LifetimeResult, model: LifetimeModel, band: ClimateBand | None = None,
                        record: RecordSpec | None = None) -> dict[str, Any]:
    """The sliding over the design life for the caisson's JSON: ``{trials, years, seed,
    expected_sliding, std_error, climate, record, failure, climate_band}`` (``record``: ``{path,
    method, threshold, gap_hours, period_ratio}`` or null; ``climate_band`` as :func:`band_json`
    or null)."""
    rec = None if record is None else {
        "path": record.path, "method": record.method,
        "threshold": {"kind": record.threshold[0], "value": float(record.threshold[1])},
        "gap_hours": float(record.gap_hours), "period_ratio": optional_float(record.period_ratio)}
    f = result.failure
    return rounded({
        "trials": result.trials, "years": result.years, "seed": result.seed,
        "expected_sliding": float(result.expected_sliding), "std_error": float(result.std_error),
        "climate": model.climate.describe(), "record": rec,
        "failure": None if f is None else {"sliding_limit": float(f.sliding_limit),
                                           "probability": float(f.probability),
                                           "std_error": float(f.std_error)},
        "climate_band": None if band is None else band_json(band)})


def format_chart(chart: DesignChart, model: LifetimeModel | None = None, source: str | None = None,
                 written: str | None = None, band: ChartBand | None = None) -> str:
    """The design chart for people: ESD with its standard error at each width, and the widths.

    The width for the target with its tolerance and its Monte Carlo interval,
    the width of Goda's deterministic design; with a record's climate ``band``,
    the band's curves at each width and the width for the target at its upper
    level; last, the requirement and the verdict.
    """
    lines = []
    if source:
        lines.append(f"design chart: {source}")
    head = f"expected sliding distance against width ({chart.trials} lifetimes"
    if model is not None:
        head += f" of {model.years} years"
    lines.append(head + f" at every width, the same random numbers; seed {chart.seed})")
    if model is not None:
        if written:
            lines.append(f"  climate (as given): {written}")
        lines.append(f"  climate: {model.climate.describe()}")
    lines.append(f"  wave force: {impulsive_text(chart.impulsive)}")
    lines.append(f"  {'width [m]':>10}  ESD with its standard error")
    for row in chart.rows():
        lines.append(f"  {_g(row['width'], 5):>10}  {_value_pm(row['expected_sliding'], row['std_error'])}")
    if chart.width_for_target is None:
        lines.append(f"width for ESD <= {_g(chart.target)} m: none of the chart's widths meets it "
                     "(give wider widths)")
    else:
        lines.append(f"width for ESD <= {_g(chart.target)} m: {_g(chart.width_for_target, 4)} m "
                     f"(bisected to {_g(chart.tolerance)} m)")
        iv = chart.width_interval
        if iv is not None:
            lines.append(f"  {100 * iv.level:g} % interval {_g(iv.lower, 4)} - {_g(iv.upper, 4)} m "
                         f"(Monte Carlo: bootstrap of the {chart.trials} lifetimes, {iv.resamples} "
                         "resamples)")
    sf = _g(chart.sf_width, 4) + " m" if math.isfinite(chart.sf_width) else "none up to 10 km"
    lines.append(f"width for SF_sliding = {_g(chart.required_sf)} under the 50-year wave "
                 f"(Goda's deterministic design): {sf}")
    if band is not None:
        lines += _chart_band_lines(band)
    if chart.checks:
        judged = " (judged at the climate band's upper level)" if band is not None else ""
        lines.append(f"requirements{judged}:")
        lines += [f"  {line}" for line in checks_lines(chart.checks)]
    return "\n".join(lines)


def _chart_band_lines(band: ChartBand) -> list[str]:
    """The chart's climate band for people: its curves at each width, then the width for the target
    at the band's upper level."""
    top = f"{100 * (0.5 + 0.5 * band.level):g} %"
    lines = [f"with the climate's uncertainty ({_band_head(band)}):",
             f"  {'width [m]':>10}  {100 * band.level:g} % climate band of the ESD"]
    for w, lo, hi in zip(band.widths, band.lower, band.upper):
        lines.append(f"  {_g(float(w), 5):>10}  {_g(float(lo))} m to {_g(float(hi))} m")
    w_t = band.width_for_target
    where = (f"at the upper end of the {100 * band.level:g} % climate band ({top} quantile of "
             f"{band.replicates} climates)")
    if w_t is None:
        lines.append(f"width for ESD <= {_g(band.target)} m {where}: no width of the chart meets it")
    else:
        lines.append(f"width for ESD <= {_g(band.target)} m {where}: {w_t:.2f} m (interpolated in "
                     "log ESD between the chart's widths)")
    return lines
