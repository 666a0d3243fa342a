"""The figures of ``regimemap climate``: the record, the return levels with their band, the QQ plot;
and the threshold diagnostics (mean residual life, parameter stability with their intervals, the
50-year value across thresholds).

Draws what :func:`regimemap.climate.analysis.curves` and
:func:`regimemap.climate.analysis.diagnostics` computed.  Paul Tol's colour-blind-safe colours;
the band is a light fill with hatching, so that it reads in grey too.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..drawing.save import DEFAULT_DPI
from ..drawing.style import agg_figure, label_axes, style_context
from .analysis import ClimateResult, Curves, Diagnostics, Sensitivity

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["climate_figure", "diagnostics_figure"]

RECORD = "#6699CC"     # the record's heights (Tol medium-contrast light blue)
PEAK = "#994455"       # storm peaks and observations (Tol dark red)
FIT = "#004488"        # the fitted curve (Tol high-contrast dark blue)
BAND_FILL = "#BBCCEE"  # the band (Tol light blue)
BAND_EDGE = "#6699CC"
THRESHOLD = "#997700"  # the threshold (Tol dark yellow)
FS = 8.0


def _draw_record(ax: Axes, result: ClimateResult) -> None:
    r = result.record
    # a break in the line wherever the record has a gap (no line drawn across missing months)
    hours = r.hours()
    cut = np.flatnonzero(np.diff(hours) > 1.5 * r.step_hours) + 1
    t = np.insert(r.time.astype("datetime64[m]"), cut, np.datetime64("NaT")).astype("O")
    ax.plot(t, np.insert(r.hs, cut, np.nan), color=RECORD, lw=0.4, label="$H_s$")
    if result.storms is not None:
        s = result.storms
        ax.axhline(s.threshold, color=THRESHOLD, lw=1.0, dashes=(5.0, 2.5),
                   label=f"threshold $u$ = {s.threshold:.2f} m")
        ax.plot(s.peak_time.astype("datetime64[m]").astype("O"), s.peak, "v", ms=3.5, mfc="none",
                mec=PEAK, mew=0.9, ls="none", label=f"{s.count} storm peaks")
    else:
        m = result.maxima
        assert m is not None
        t = np.array([np.datetime64(f"{y}-07-01") for y in m.years]).astype("O")
        ax.plot(t, m.maxima, "v", ms=3.5, mfc="none", mec=PEAK, mew=0.9, ls="none",
                label=f"{m.years.size} annual maxima")
    spikes = result.record.quality.spikes
    if spikes:
        ax.plot(np.array([np.datetime64(t[:-1]) for t, _ in spikes]).astype("O"), [h for _, h in spikes],
                "x", color="k", ms=4, ls="none", label=f"{len(spikes)} spikes flagged")
    ax.set_ylim(0.0, 1.3 * float(np.nanmax(r.hs)))  # head room for the key
    ax.legend(fontsize=FS - 1, loc="upper left", ncols=4, frameon=False)
    label_axes(ax, None, "$H_s$ [m]", FS, f"(a) the record: {r.years:.1f} years observed, step "
               f"{r.step_hours:g} h", title_larger=0.5)


def _draw_return_levels(ax: Axes, result: ClimateResult, c: Curves) -> None:
    level = result.options.confidence
    if c.lower is not None and c.upper is not None and result.band is not None:
        ax.fill_between(c.periods, c.lower, c.upper, facecolor=BAND_FILL, edgecolor=BAND_EDGE, hatch="////",
                        lw=0.0, label=result.band.label(level))
    ax.plot(c.periods, c.level, color=FIT, lw=1.5, label=f"{result.fit.distribution.upper()} fit")
    what = "storm peaks" if result.storms is not None else "annual maxima"
    ax.plot(c.observed_periods, c.observed, "o", ms=3.0, mfc="none", mec=PEAK, mew=0.9, ls="none",
            label=f"{what} (Weibull positions)")
    for rv in result.return_values:
        if rv["period"] == 50.0 and rv["value"] is not None:
            ax.plot([50.0], [rv["value"]], "s", color=FIT, ms=4)
            band = ("" if rv["lower"] is None or rv["upper"] is None
                    else f"\n({rv['lower']:.2f} to {rv['upper']:.2f} m)")
            ax.annotate(f"$H_{{50}}$ = {rv['value']:.2f} m{band}", (50.0, rv["value"]), xytext=(-6, 10),
                        textcoords="offset points", ha="right", va="bottom", fontsize=FS - 1)
    ax.set_xscale("log")
    ax.legend(fontsize=FS - 1, loc="lower right", frameon=False)
    label_axes(ax, "return period $R$ [years]", "return level $H_R$ [m]", FS, "(b) return levels",
               title_larger=0.5)


def _draw_qq(ax: Axes, c: Curves) -> None:
    lo = float(min(c.model_quantiles.min(), c.observed.min()))
    hi = float(max(c.model_quantiles.max(), c.observed.max()))
    pad = 0.05 * (hi - lo)
    ax.plot([lo - pad, hi + pad], [lo - pad, hi + pad], color="0.4", lw=0.8, dashes=(4.0, 2.0))
    ax.plot(c.model_quantiles, c.observed, "o", ms=3.0, mfc="none", mec=PEAK, mew=0.9, ls="none")
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(lo - pad, hi + pad)
    ax.set_aspect("equal", adjustable="box")
    label_axes(ax, "fitted quantile [m]", "observed [m]", FS, "(c) QQ plot", title_larger=0.5)


def climate_figure(result: ClimateResult, curves: Curves, title: str | None = None, *,
                   dpi: float = DEFAULT_DPI) -> Figure:
    """The record with its storms, the return-level plot with the band and the observations at
    their plotting positions, and the QQ plot.

    Parameters
    ----------
    result : ClimateResult
        The analysis (:func:`regimemap.climate.analyse`).
    curves : Curves
        Its return-level curve, band and observations (:func:`regimemap.climate.analysis.curves`).
    title : str, optional
    dpi : float

    Returns
    -------
    Figure
        Axes labelled ``record``, ``return levels`` and ``qq`` (Agg canvas, no pyplot).
    """

    c = curves
    with style_context():
        fig = agg_figure(figsize=(7.0, 6.0), dpi=dpi)
        top = 0.06 if title else 0.0
        ax_r = fig.add_axes((0.08, 0.64 - top, 0.89, 0.30), label="record")
        ax_l = fig.add_axes((0.08, 0.08, 0.52, 0.44 - top), label="return levels")
        ax_q = fig.add_axes((0.68, 0.08, 0.29, 0.44 - top), label="qq")
        _draw_record(ax_r, result)
        _draw_return_levels(ax_l, result, c)
        _draw_qq(ax_q, c)
        if title:
            fig.suptitle(title, fontsize=FS + 1.5, y=0.985)
    return fig


def _draw_mrl(ax: Axes, d: Diagnostics, used: float | None) -> None:
    ax.fill_between(d.thresholds, d.mean_excess - d.mean_excess_ci, d.mean_excess + d.mean_excess_ci,
                    facecolor=BAND_FILL, edgecolor=BAND_EDGE, hatch="////", lw=0.0, label="90 % interval")
    ax.plot(d.thresholds, d.mean_excess, color=FIT, lw=1.3, label="mean excess")
    if used is not None:
        ax.axvline(used, color=THRESHOLD, lw=1.0, dashes=(5.0, 2.5), label="threshold used")
    ax.legend(fontsize=FS - 1.5, frameon=False, loc="lower left")
    label_axes(ax, "threshold $u$ [m]", "mean of peak $-$ $u$ [m]", FS, "(a) mean residual life",
               title_larger=0.5)


def _draw_stability(ax: Axes, d: Diagnostics, used: float | None, which: str) -> None:
    values, iv, label, title = (
        (d.xi, d.xi_interval, r"GPD shape $\xi$", "(b) shape") if which == "xi" else
        (d.sigma_star, d.sigma_star_interval, r"$\sigma^* = \sigma - \xi u$ [m]", "(c) modified scale"))
    ax.fill_between(d.thresholds, iv[:, 0], iv[:, 1], facecolor=BAND_FILL, edgecolor=BAND_EDGE, hatch="////",
                    lw=0.0, label=f"{100 * d.confidence:g} % posterior interval")
    ax.plot(d.thresholds, values, "o-", color=FIT, ms=3, lw=1.0, label="maximum likelihood")
    if which == "xi":
        ax.legend(fontsize=FS - 1.5, frameon=False, loc="best")
    if which == "xi":
        ax.axhline(0.0, color="0.5", lw=0.6)
    if used is not None:
        ax.axvline(used, color=THRESHOLD, lw=1.0, dashes=(5.0, 2.5))
    label_axes(ax, "threshold $u$ [m]", label, FS, title, title_larger=0.5)


def _draw_sensitivity(ax: Axes, s: Sensitivity, used: float | None) -> None:
    ok = np.isfinite(s.value)
    name = {"posterior": "posterior", "profile": "profile-likelihood", "bootstrap": "bootstrap"}[s.interval]
    # the interval as a bar of its own (a degenerate fit's value may lie outside it)
    ax.vlines(s.thresholds[ok], s.lower[ok], s.upper[ok], color=BAND_EDGE, lw=3.0,
              label=f"{100 * s.confidence:g} % {name} interval")
    ax.plot(s.thresholds[ok], s.value[ok], "s", color=FIT, ms=3.5, ls="none",
            label=f"$H_{{{s.period:g}}}$, maximum likelihood")
    for u, q, n in zip(s.thresholds, s.quantiles, s.storms):
        ax.annotate(f"{100 * q:g} %\n{n}", (u, 0.0), xycoords=("data", "axes fraction"), xytext=(0, 3),
                    textcoords="offset points", ha="center", va="bottom", fontsize=FS - 2.5, color="0.35")
    if used is not None:
        ax.axvline(used, color=THRESHOLD, lw=1.0, dashes=(5.0, 2.5), label="threshold used")
    if ok.any():
        lo, hi = float(np.min(s.lower[ok])), float(np.max(s.upper[ok]))
        pad = 0.1 * (hi - lo)
        ax.set_ylim(lo - 2.5 * pad, hi + 2.5 * pad)  # room for the quantiles below, the key above
    ax.legend(fontsize=FS - 1.5, frameon=False, loc="upper left")
    label_axes(ax, "threshold $u$ [m] (quantile of $H_s$; storms)", f"$H_{{{s.period:g}}}$ [m]", FS,
               f"(d) the {s.period:g}-year value across thresholds", title_larger=0.5)


def diagnostics_figure(d: Diagnostics, used: float | None = None, title: str | None = None, *,
                       sensitivity: Sensitivity | None = None, dpi: float = DEFAULT_DPI) -> Figure:
    """Mean residual life and parameter stability (the GPD shape and modified scale, with their
    posterior intervals) over thresholds (Coles 2001, Sect. 4.3.1): straight, and flat, above a
    valid threshold; with ``sensitivity``, the return value and its interval refitted above the
    98 to 99.7 % quantiles.

    Returns
    -------
    Figure
        Axes labelled ``mean residual life``, ``shape``, ``modified scale`` (and ``sensitivity``).
    """

    with style_context():
        two = sensitivity is not None
        fig = agg_figure(figsize=(7.0, 5.2 if two else 2.6), dpi=dpi)
        top = (0.04 if two else 0.08) if title else 0.0
        if two:
            y0, h = 0.585, 0.36 - top
        else:
            y0, h = 0.17, 0.72 - top
        ax_a = fig.add_axes((0.075, y0, 0.25, h), label="mean residual life")
        ax_b = fig.add_axes((0.41, y0, 0.25, h), label="shape")
        ax_c = fig.add_axes((0.74, y0, 0.25, h), label="modified scale")
        _draw_mrl(ax_a, d, used)
        _draw_stability(ax_b, d, used, "xi")
        _draw_stability(ax_c, d, used, "sigma")
        if sensitivity is not None:
            ax_d = fig.add_axes((0.075, 0.085, 0.915, 0.36), label="sensitivity")
            _draw_sensitivity(ax_d, sensitivity, used)
        if title:
            fig.suptitle(title, fontsize=FS + 1.5, y=0.985)
    return fig
