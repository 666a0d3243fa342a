"""The extreme-value analysis of a record as JSON and as text (``regimemap climate``)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..records.numbers import optional_float, rounded, shortest
from .analysis import ClimateResult, Sensitivity

__all__ = ["climate_json", "format_climate", "parameter_text",
           "sensitivity_json"]

_NAMES = {"gpd": "generalised Pareto", "weibull": "Weibull (shape fixed)", "gumbel": "Gumbel",
          "gev": "generalised extreme value"}


_METHOD_TEXT = {
    "posterior": "{level} equal-tailed interval of {draws} posterior draws (a grid posterior: prior flat "
                 "in {prior}; {n} kept as replicate fits)",
    "profile": "{level} profile-likelihood interval of {what} ({n} replicate fits drawn from the "
               "normalised likelihood)",
    "bootstrap": "{level} percentile interval of {n} non-parametric bootstrap replicates",
}
_PRIOR_TEXT = {"gpd": "ln sigma and in xi on [-1, 1.5], the storm rate's Jeffreys posterior",
               "weibull": "ln A with k fixed, the storm rate's Jeffreys posterior",
               "gumbel": "B and ln A", "gev": "mu, ln sigma and xi on [-1, 1.5]"}


def sensitivity_json(s: Sensitivity | None) -> dict[str, Any] | None:
    """``{period, confidence, interval, rows: [{quantile, threshold, storms, value, lower, upper}]}``
    (null where too few storms to fit)."""
    if s is None:
        return None
    rows = [{"quantile": float(q), "threshold": float(u), "storms": int(n), "value": float(v),
             "lower": float(lo), "upper": float(hi)}
            for q, u, n, v, lo, hi in zip(s.quantiles, s.thresholds, s.storms, s.value, s.lower, s.upper)]
    return rounded({"period": float(s.period), "confidence": float(s.confidence), "interval": s.interval,
                    "rows": rows})


def climate_json(result: ClimateResult, source: str | None = None,
                 sensitivity: Sensitivity | None = None) -> dict[str, Any]:
    """The analysis as one JSON object.

    Keys: ``record`` {``source``, ``start``, ``end``, ``years``, ``step_hours``, ``coverage``,
    ``coverage_by_year``, ``missing``, ``duplicates``, ``conflicting`` (the repeated times whose
    copies differ), ``unsorted``, ``gaps``, ``flagged`` (the
    spikes: ``[{time, hs}]``), ``spikes_dropped``, ``period``}, ``method``, ``threshold`` (m;
    null for annual maxima), ``gap_hours``, ``storms`` (count; for annual maxima the years used),
    ``rate_per_year``, ``distribution``, ``parameters``, ``return_values`` [{``period``,
    ``value``, ``lower``, ``upper``}], ``confidence``, ``interval`` (the method: ``posterior``,
    ``profile`` or ``bootstrap``; null without replicates), ``replicates`` (replicate fits asked
    for), ``replicates_fitted`` (those made: a bootstrap replicate with too few values is not),
    ``seed``, ``endpoint`` (the fitted upper end point ``u - sigma/xi`` of a bounded tail, m;
    null for ``xi >= 0``), ``threshold_sensitivity`` (:func:`sensitivity_json`; null unless
    given), ``warnings`` (the messages) and ``notices`` (``[{code, message, quantity, value}]``).
    """
    r, o, q = result.record, result.options, result.record.quality
    pot = result.storms is not None
    return rounded({
        "record": {
            "source": source if source is not None else r.source,
            "start": r.start, "end": r.end, "years": float(r.years),
            "step_hours": float(r.step_hours), "coverage": float(r.coverage),
            "coverage_by_year": {str(y): float(c) for y, c in q.coverage.items()},
            "missing": q.missing, "duplicates": q.duplicates,
            "conflicting": 0 if q.conflicts is None else q.conflicts.count, "unsorted": q.unsorted,
            "gaps": len(q.gaps),
            "flagged": [{"time": t, "hs": float(h)} for t, h in q.spikes],
            "spikes_dropped": q.spikes_dropped, "period": r.period_name,
        },
        "method": o.method,
        "threshold": optional_float(result.fit.threshold),
        "gap_hours": float(o.gap_hours) if pot else None,
        "storms": result.fit.n,
        "rate_per_year": float(result.fit.rate),
        "distribution": result.fit.distribution,
        "parameters": {k: float(v) for k, v in result.fit.parameters.items()},
        "return_values": [{k: optional_float(v) for k, v in rv.items()} for rv in result.return_values],
        "confidence": float(o.confidence),
        "interval": None if result.band is None else result.band.method,
        "replicates": 0 if result.band is None else result.band.requested,
        "replicates_fitted": 0 if result.band is None else len(result.band.fits),
        "seed": o.seed,
        "endpoint": optional_float(result.endpoint),
        "threshold_sensitivity": sensitivity_json(sensitivity),
        "warnings": result.warnings(),
        "notices": [{**n.as_dict(), "value": optional_float(n.value)} for n in result.notices],
    })


def parameter_text(result: ClimateResult) -> str:
    """``sigma = 1.28 m, xi = -0.317`` (the shapes without a unit)."""
    return ", ".join(f"{k} = {v:.4g}" + ("" if k in ("xi", "k") else " m")
                     for k, v in result.fit.parameters.items())


def format_climate(result: ClimateResult, source: str | None = None,
                   sensitivity: Sensitivity | None = None) -> str:
    """The analysis for people: the record and its quality, the extremes, the fit, the return values
    with their bands.

    The warnings are not in it: they are the analysis's (:meth:`ClimateResult.warnings`), which the
    command line prints on standard error."""
    r, o, q, f = result.record, result.options, result.record.quality, result.fit
    lines = [f"wave climate: {source if source is not None else r.source}"]
    period = f", period {r.period_name}" if r.period_name else ", no period"
    lines.append(f"  record {r.start} to {r.end}: {r.years:.2f} years observed, step {r.step_hours:g} h, "
                 f"coverage {100 * r.coverage:.1f} %{period}")
    differing = "" if q.conflicts is None else f" ({q.conflicts.count} with differing copies)"
    lines.append(f"  quality: {q.missing} missing, {q.duplicates} repeated{differing}, "
                 f"{q.unsorted} out of order, {len(q.gaps)} gaps, {len(q.spikes)} spikes flagged"
                 + (" (dropped)" if q.spikes_dropped and q.spikes else ""))
    if result.storms is not None:
        s = result.storms
        threshold = (f"{100 * o.threshold[1]:g} % quantile" if o.threshold[0] == "quantile" else "given")
        lines.append(f"  peaks over threshold: u = {s.threshold:.3f} m ({threshold}), gap {o.gap_hours:g} h: "
                     f"{s.count} storms, {s.rate:.3g} a year; largest {s.peak.max():.2f} m")
    else:
        assert result.maxima is not None
        m = result.maxima
        skipped = f"; skipped {', '.join(str(y) for y in m.skipped)}" if m.skipped else ""
        lines.append(f"  annual maxima: {m.years.size} years with >= {100 * m.coverage:g} % coverage"
                     f"{skipped}; largest {m.maxima.max():.2f} m")
    lines.append(f"  fit: {_NAMES[f.distribution]}, maximum likelihood: {parameter_text(result)}")
    if result.endpoint is not None:
        lines.append(f"  fitted upper end point (xi < 0): {result.endpoint:.2f} m")
    if result.band is not None:
        b = result.band
        fitted = f", {len(b.fits)} fitted" if b.failed else ""
        draws = len(b.draws["rate"]) if "rate" in b.draws else b.requested
        what = "the storm count and the peaks" if result.storms is not None else "the annual maxima"
        method = _METHOD_TEXT[b.method].format(level=f"{100 * o.confidence:g} %", n=b.requested, draws=draws,
                                               prior=_PRIOR_TEXT[f.distribution], what=what)
        lines.append(f"  interval: {method}{fitted} (seed {b.seed})")
    lines.append("")
    lines.append("return period    Hs       " + (f"{100 * o.confidence:g} % interval" if result.band else ""))
    for rv in result.return_values:
        years, value = rv["period"], rv["value"]
        assert years is not None and value is not None
        band = ("" if rv["lower"] is None or rv["upper"] is None
                else f"{rv['lower']:.2f} to {rv['upper']:.2f} m")
        lines.append(f"  {shortest(years):>5} years  {value:6.2f} m  {band}")
    if sensitivity is not None:
        lines.append("")
        level = f"{100 * sensitivity.confidence:g} %"
        lines.append(f"{shortest(sensitivity.period)}-year value across thresholds ({level} "
                     f"{sensitivity.interval} interval):")
        for q, u, n, v, lo, hi in zip(sensitivity.quantiles, sensitivity.thresholds, sensitivity.storms,
                                      sensitivity.value, sensitivity.lower, sensitivity.upper):
            got = (f"{v:6.2f} m  {lo:.2f} to {hi:.2f} m" if np.isfinite(v) and np.isfinite(lo)
                   else "too few storms to fit")
            lines.append(f"  u = {u:6.3f} m {f'({100 * q:g} %)':10s}{n:5d} storms  {got}")
    return "\n".join(lines)
