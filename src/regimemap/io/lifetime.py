"""The sliding of a caisson over its design life, for people (text) and programs (JSON, CSV, NPZ).

:func:`lifetime_json` and :func:`format_lifetime` report a
:class:`~regimemap.lifetime.LifetimeResult` (the expected sliding distance with
its standard error, quantiles, exceedance probabilities, the climate);
:func:`chart_json` and :func:`format_chart` a
:class:`~regimemap.lifetime.DesignChart`; :func:`write_samples` writes every
trial (CSV or NPZ, atomically).  The options of ``regimemap lifetime`` that the
design file does not hold are checked in :mod:`regimemap.io.lifetime_options`.  Lengths
are in metres, probabilities in [0, 1] (per cent in the text); JSON numbers are rounded to
12 significant digits.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

from ..lifetime import DesignChart, LifetimeModel, LifetimeResult
from ..lifetime.results import STATISTICS, threshold_key
from ._numbers import json_number
from .atomic import atomic_open
from .checks import checks_json, checks_lines
from .formats import format_for, record_formats

__all__ = ["SAMPLE_FORMATS", "chart_json", "format_chart", "format_lifetime", "impulsive_text",
           "lifetime_json", "threshold_key", "write_chart", "write_samples"]

#: Formats of :func:`write_samples` (from the file's suffix).
SAMPLE_FORMATS: tuple[str, ...] = record_formats("lifetimes")
#: Quantiles of the lifetime sliding that are reported.
_QUANTILES = (0.9, 0.99)


# -- JSON ---------------------------------------------------------------------------------------


def _json_value(v: Any) -> Any:
    """A value of :meth:`LifetimeResult.summary` for JSON: floats rounded (``null`` if not finite),
    ints kept, dicts value by value."""
    if isinstance(v, dict):
        return {k: _json_value(x) for k, x in v.items()}
    if v is None or isinstance(v, int):
        return v
    return json_number(v)


def _units() -> dict[str, str]:
    """The units of the statistics that have one: the lengths and probabilities, then the years."""
    with_unit = sorted((s for s in STATISTICS if s.unit), key=lambda s: s.unit == "year")
    return {s.key: s.unit + (", keys in m" if s.per_threshold else "") for s in with_unit}


def _model_dict(model: LifetimeModel) -> dict[str, Any]:
    c = model.climate
    return {
        "years": model.years,
        "storm_hours": json_number(model.storm_hours),
        "period": None if model.period is None else json_number(model.period),
        "period_law": None if model.period_law is None else [json_number(v) for v in model.period_law],
        "steepness": None if model.steepness is None else json_number(model.steepness),
        "tide_range": json_number(model.tide_range),
        "impulsive": model.impulsive,
        "truncate": None if model.truncate is None else json_number(model.truncate),
        "errors": {name: {"ratio": json_number(getattr(model.errors, name).ratio),
                          "cov": json_number(getattr(model.errors, name).cov)}
                   for name in model.errors.names()},
        "climate": {
            "distribution": c.distribution, "scale": json_number(c.scale),
            "location": json_number(c.location), "shape": json_number(c.shape),
            "storms_per_year": None if c.storms_per_year is None else json_number(c.storms_per_year),
            "H0_10": json_number(c.return_value(10)), "H0_50": json_number(c.return_value(50)),
        },
    }


def impulsive_text(impulsive: bool) -> str:
    """The choice of the wave force's coefficient, named: ``impulsive = false (alpha* = alpha2 ...)``."""
    if impulsive:
        return "impulsive = true (alpha* = max(alpha2, alpha_I), Takahashi's impulsive coefficient)"
    return ("impulsive = false (alpha* = alpha2: no impulsive coefficient on the sine pulse, "
            "docs/lifetime.md Sect. 5.1)")


def lifetime_json(result: LifetimeResult, model: LifetimeModel, source: str | None = None,
                  written: str | None = None) -> dict[str, Any]:
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

    Returns
    -------
    dict
        ``checks`` (the requirements: ``[{name, value, required, relation,
        unit, pass}]``), ``failure`` (``{sliding_limit, probability,
        std_error}`` or null), ``impulsive``, ``expected_sliding`` and
        ``std_error`` (m), ``std``, ``median``,
        ``quantile_90``, ``quantile_99`` (m), ``exceedance`` and
        ``storm_exceedance`` (threshold in metres as text -> probability),
        ``never_slides``, ``mean_storms``, ``trials``, ``seed``, ``years``,
        ``width`` (m), ``climate`` (one line of text), ``model`` (every option)
        and ``units``; numbers rounded to 12 significant digits (``null`` if
        not finite).
    """
    out: dict[str, Any] = {}
    if source is not None:
        out["source"] = source
    out["checks"] = checks_json(result.checks)
    out.update(_json_value(result.summary()))
    out.update({
        "impulsive": model.impulsive,
        "climate": model.climate.describe(),
        "climate_as_written": written,
        "model": _model_dict(model),
        "units": _units(),
    })
    return out


def chart_json(chart: DesignChart, model: LifetimeModel | None = None, source: str | None = None,
               written: str | None = None) -> dict[str, Any]:
    """One JSON-ready object: the design chart (ESD against width) and the widths it gives.

    Returns
    -------
    dict
        ``checks`` (the design's width against the width for the target),
        ``chart`` (a list of ``{width, expected_sliding, std_error}``, m),
        ``target`` (m), ``width_for_target`` (m, ``null`` when no width of the
        chart meets the target), ``width_tolerance`` (m), ``width_interval``
        (``{level, lower, upper, resamples}``, m, or ``null``),
        ``failure_sliding`` (m or ``null``), ``impulsive``, ``required_sf``,
        ``sf_width`` (m), ``trials``, ``seed``; with ``model`` also ``years``,
        ``climate`` and ``model``.
    """
    out: dict[str, Any] = {}
    if source is not None:
        out["source"] = source
    out["checks"] = checks_json(chart.checks)
    out["chart"] = [{k: json_number(v) for k, v in row.items()} for row in chart.rows()]
    out["target"] = json_number(chart.target)
    out["width_for_target"] = (None if chart.width_for_target is None
                               else json_number(chart.width_for_target))
    out["width_tolerance"] = json_number(chart.tolerance)
    iv = chart.width_interval
    out["width_interval"] = None if iv is None else {
        "level": json_number(iv.level), "lower": json_number(iv.lower), "upper": json_number(iv.upper),
        "resamples": iv.resamples}
    out["failure_sliding"] = None if chart.failure_sliding is None else json_number(chart.failure_sliding)
    out["impulsive"] = chart.impulsive
    out["required_sf"] = json_number(chart.required_sf)
    out["sf_width"] = json_number(chart.sf_width)
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
    return out


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


def format_lifetime(result: LifetimeResult, model: LifetimeModel, source: str | None = None,
                    written: str | None = None) -> str:
    """The sliding over the design life for people.

    The expected sliding distance with its standard error beside it, the
    median and quantiles, the exceedance probabilities of the lifetime sliding
    and of the largest single-storm sliding, the share of lifetimes that never
    slide, and the climate (as the file wrote it, then as fitted) and the
    options, the coefficient of the wave force named; the probability of
    failure, given a sliding limit; one line per requirement and the verdict.
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
    lines.append(f"ESD {_value_pm(result.expected_sliding, result.std_error)} (standard error, {lives})")
    qs = ", ".join(f"{100 * q:g} %: {_g(result.quantile(q))} m" for q in _QUANTILES)
    lines.append(f"  median {_g(result.median)} m; quantiles {qs}")
    lines.append(f"  never slides: {_percent(result.never_slides)} of the lifetimes")
    lines.append("probability that the sliding exceeds x:")
    lines.append(f"  {'x [m]':>8}  {'over the life':>13}  {'in one storm':>12}")
    for x in result.thresholds:
        lines.append(f"  {_g(x):>8}  {_percent(result.exceedance(x)):>13}  "
                     f"{_percent(result.storm_exceedance(x)):>12}")
    lines.append("  (in one storm: the largest single-storm sliding of the life, Kim & Suh 2013)")
    if result.failure is not None:
        f = result.failure
        lines.append(f"probability of failure (sliding off the mound, S > {_g(f.sliding_limit)} m): "
                     f"{_percent(f.probability)} ± {_percent(f.std_error)} over the life")
    if result.checks:
        lines.append("requirements:")
        lines += [f"  {line}" for line in checks_lines(result.checks)]
    return "\n".join(lines)


def format_chart(chart: DesignChart, model: LifetimeModel | None = None, source: str | None = None,
                 written: str | None = None) -> str:
    """The design chart for people: ESD with its standard error at each width, and the widths.

    The width for the target with its tolerance and its Monte Carlo interval,
    the width of Goda's deterministic design, the requirement and the verdict.
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
    if chart.checks:
        lines.append("requirements:")
        lines += [f"  {line}" for line in checks_lines(chart.checks)]
    return "\n".join(lines)


# -- the chart's table -----------------------------------------------------------------------------


def _csv_number(x: float) -> str:
    return f"{x + 0.0:.12g}" if math.isfinite(x) else ""


def write_chart(chart: DesignChart, path: str | os.PathLike[str]) -> None:
    """Write the chart's table as CSV, atomically: one row per width.

    Columns: ``width_m``, ``expected_sliding_m``, ``std_error_m``, then
    ``p_exceed_<x>m`` for each threshold (``P(S > x)``), then ``p_failure``
    (``P(S > failure_sliding)``) when the chart has a sliding limit; numbers to
    12 significant digits.

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
    rows = []
    for i, (w, e, se) in enumerate(zip(chart.widths, chart.expected_sliding, chart.std_error)):
        cells = [_csv_number(float(w)), _csv_number(float(e)), _csv_number(float(se))]
        if chart.exceedance is not None:
            cells += [_csv_number(float(p)) for p in chart.exceedance[i]]
        if fail is not None:
            cells.append(_csv_number(float(fail[i])))
        rows.append(",".join(cells))
    with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
        fh.write(",".join(head) + "\n")
        for row in rows:
            fh.write(row + "\n")


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
        with atomic_open(path, "wb") as fh:
            np.savez_compressed(fh, **arrays)  # type: ignore[arg-type]
        return fmt
    sliding = result.sliding.tolist()
    storm = result.max_storm.tolist()
    storms = result.storms.tolist()
    with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
        fh.write("trial,sliding_m,max_storm_m,storms\n")
        for i in range(len(sliding)):
            fh.write(f"{i},{sliding[i] + 0.0:.12g},{storm[i] + 0.0:.12g},{storms[i]}\n")
    return fmt
