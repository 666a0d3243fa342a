"""The figures of a caisson's sliding over its design life, and panel (g) of the design sheet.

Figures build for a normal result, a result where no lifetime slid, design charts where no
width / every width meets the target; their SVG is the same bytes from run to run and at any
PNG resolution; their PDF embeds no Type 3 font; no text meets another or leaves the figure
(boxes measured by the renderer, with tests/drawing/test_legible.py's check), and the labels of the
lines stay off the curves.  The sheet without a lifetime has no panel (g); with one, panel (g) is
placed the same way twice (the same SVG bytes).
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from regimemap.drawing.save import print_figure  # noqa: E402
from regimemap.drawing.text.labelplacer import figure_texts  # noqa: E402
from regimemap.drawing.text.tidy import MEASURE_DPI  # noqa: E402
from regimemap.lifetime import (  # noqa: E402
    Caisson,
    Climate,
    DesignChart,
    LifetimeModel,
    LifetimeResult,
    design_chart,
    lifetime_sliding,
)
from regimemap.lifetime.figures.chart import chart_figure  # noqa: E402
from regimemap.lifetime.figures.exceedance import lifetime_figure  # noqa: E402
from tests.drawing.test_legible import _check_boxes  # noqa: E402

pytestmark = pytest.mark.render

ROOT = Path(__file__).resolve().parents[2]

GODA = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1, crest=3.4,
               friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)
MODEL = LifetimeModel(Climate.from_return_values(5.0, 6.3))


@pytest.fixture(scope="module")
def goda_result() -> LifetimeResult:
    return lifetime_sliding(GODA, MODEL, trials=1000, seed=1)


@pytest.fixture(scope="module")
def wide() -> LifetimeResult:
    """20 m wide: a handful of lifetimes slide, the ESD near the 0.1 m line."""
    return lifetime_sliding(GODA.with_width(20.0), MODEL, trials=1000, seed=3)


def _zero(n: int = 400) -> LifetimeResult:
    return LifetimeResult(sliding=np.zeros(n), max_storm=np.zeros(n), storms=np.ones(n, dtype=np.int64),
                          seed=7, years=50, thresholds=(0.1, 0.3), width=40.0)


@pytest.fixture(scope="module")
def chart() -> DesignChart:
    return design_chart(GODA, MODEL, np.linspace(10.0, 25.0, 11), trials=400, seed=2)


def _chart(w0: float, w1: float, n: int) -> DesignChart:
    return design_chart(GODA, MODEL, np.linspace(w0, w1, n), trials=200, seed=5)


# -- what the figures say ------------------------------------------------------------------------


def _all_text(fig) -> str:
    return " | ".join(t.get_text() for t in figure_texts(fig))


def test_lifetime_figure_of_a_normal_result(goda_result: LifetimeResult) -> None:
    fig = lifetime_figure(goda_result)
    axes = {ax.get_label(): ax for ax in fig.axes}
    assert set(axes) == {"exceedance", "histogram"}
    ax = axes["exceedance"]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert axes["histogram"].get_xscale() == "log"
    text = _all_text(fig)
    assert "ESD = " in text and "\u00b1" in text
    assert "0.1 m" in text and "0.3 m" in text
    assert "Goda & Takagi 2000" in text and "Shimosako & Takahashi 1999" in text
    assert "Kim & Suh 2013" in text
    share = f"{100 * goda_result.never_slides:.1f} %"
    assert share in text and "did not" in text
    # the lifetime curve: a step line from P(S > 0) down to 1/n at the largest slide
    life = max(ax.get_lines(), key=lambda ln: len(ln.get_xdata()))
    y = np.asarray(life.get_ydata())
    assert y[0] == pytest.approx(1.0 - goda_result.never_slides)
    assert y[-1] == pytest.approx(1.0 / goda_result.trials)
    assert np.all(np.diff(y) <= 0.0)
    assert float(np.max(life.get_xdata())) == pytest.approx(float(goda_result.sliding.max()))
    # the ESD line, and the tolerable limits, are drawn at their values
    xs = {round(float(ln.get_xdata()[0]), 12) for ln in ax.get_lines() if len(ln.get_xdata()) == 2}
    assert {0.1, 0.3, round(goda_result.expected_sliding, 12)} <= xs
    # the histogram counts every lifetime that slid (here none slid less than the axis starts)
    bars = axes["histogram"].patches
    assert bars


def test_lifetime_figure_when_no_lifetime_slid() -> None:
    z = _zero()
    fig = lifetime_figure(z, title="a caisson that never slides")
    text = _all_text(fig)
    assert "no lifetime slid" in text
    assert "ESD = 0 m" in text
    assert "all 400" in text
    ax = next(a for a in fig.axes if a.get_label() == "exceedance")
    # no curve (only the two limit lines), the limits still labelled, sensible axes
    assert all(len(ln.get_xdata()) == 2 for ln in ax.get_lines())
    assert "0.1 m" in text and "0.3 m" in text
    lo, hi = ax.get_xlim()
    assert lo < 0.1 < 0.3 < hi
    assert ax.get_ylim()[1] == 1.0
    _check_figure(fig)


def test_chart_figure(chart: DesignChart) -> None:
    fig = chart_figure(chart)
    (ax,) = fig.axes
    assert ax.get_label() == "chart" and ax.get_yscale() == "log"
    text = _all_text(fig)
    assert chart.width_for_target is not None
    assert f"b = {chart.width_for_target:.3g} m" in text
    assert "no width of" not in text  # the note is for charts without a width for the target
    assert f"b = {chart.sf_width:.3g} m" in text
    assert "SF = 1.2 under the 50-year wave" in text
    assert "0.1 m: target" in text and "0.3 m" in text
    assert "Goda & Takagi 2000" in text and "Shimosako & Takahashi 1999" in text
    # the two vertical lines are different styles: solid for the target, dashed for SF
    verticals = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 2
                 and ln.get_xdata()[0] == ln.get_xdata()[1]]
    styles = {round(float(ln.get_xdata()[0]), 9): ln.get_linestyle() for ln in verticals}
    assert styles[round(chart.width_for_target, 9)] == "-"
    assert styles[round(chart.sf_width, 9)] != "-"
    # ESD drawn where positive, nowhere <= 0 on the log axis
    curve = max(ax.get_lines(), key=lambda ln: len(ln.get_xdata()))
    y = np.asarray(curve.get_ydata(), dtype=float)
    assert np.all((y > 0) | np.isnan(y))


def test_chart_where_no_width_meets_the_target() -> None:
    c = _chart(6.0, 10.0, 5)
    assert c.width_for_target is None
    fig = chart_figure(c, title="too narrow")
    text = _all_text(fig)
    assert "no width of 6\u201310 m" in text and "ESD \u2264 0.1 m" in text
    assert "off the chart" in text  # the SF width (about 15 m) is beyond the widths
    _check_figure(fig)


def test_chart_where_every_width_meets_the_target() -> None:
    c = _chart(20.0, 30.0, 6)
    assert c.width_for_target == pytest.approx(20.0)
    assert np.any(c.expected_sliding == 0.0)  # the widest never slide: drawn as triangles
    fig = chart_figure(c)
    text = _all_text(fig)
    assert "every width meets it" in text.replace("\n", " ")
    assert "ESD = 0 (no lifetime slid)" in text
    (ax,) = fig.axes
    lo, hi = ax.get_ylim()
    assert lo > 0 and hi > 0.3
    _check_figure(fig)


def test_chart_with_a_target_off_the_limits(chart: DesignChart) -> None:
    import dataclasses

    c = dataclasses.replace(chart, target=0.05, width_for_target=None)
    fig = chart_figure(c)
    text = _all_text(fig)
    assert "target 0.05 m" in text and "target ESD 0.05 m" in text
    _check_figure(fig)


# -- legible: no text meets another, none leaves the figure, labels off the curves ----------------


def _boxes(fig) -> dict[str, list]:
    """Every text of the figure (a key as one box) for tests/drawing/test_legible.py's check."""
    renderer = fig.canvas.get_renderer()
    legends = [leg for leg in [*fig.legends, *(ax.get_legend() for ax in fig.axes)] if leg is not None]
    in_key = {id(t) for leg in legends for t in leg.get_texts()}
    fixed = []
    for t in figure_texts(fig):
        if id(t) not in in_key:
            b = t.get_window_extent(renderer)
            fixed.append((repr(t.get_text()), (b.x0, b.y0, b.x1, b.y1)))
    for leg in legends:
        b = leg.get_window_extent(renderer)
        fixed.append(("key", (b.x0, b.y0, b.x1, b.y1)))
    return {"fixed": fixed, "labels": [], "markers": []}


def _check_figure(fig) -> None:
    _check_boxes(fig, lambda: _boxes(fig))


def _dense(q: np.ndarray, step: float = 0.5) -> np.ndarray:
    parts = [q[:1]]
    for a, b in zip(q[:-1], q[1:]):
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            continue
        n = max(1, int(np.ceil(np.hypot(*(b - a)) / step)))
        parts.append(a + (np.arange(1, n + 1) / n)[:, None] * (b - a))
    return np.concatenate(parts)


def _labels_off_the_lines(fig, only: str | None = None) -> None:
    """Every label written in the axes (``only`` those so labelled) keeps off every line drawn in
    them (curves and rules)."""
    fig.set_dpi(MEASURE_DPI)
    fig.draw_without_rendering()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        if only is not None and ax.get_label() != only:
            continue
        pts = []
        for ln in ax.get_lines():
            x = np.asarray(ln.get_xdata(), dtype=float)
            y = np.asarray(ln.get_ydata(), dtype=float)
            if ln.get_linestyle() in ("None", "none", "", " "):
                continue
            if ln.get_drawstyle() == "steps-post":
                x, y = np.repeat(x, 2)[1:], np.repeat(y, 2)[:-1]
            with np.errstate(divide="ignore", invalid="ignore"):
                q = ln.get_transform().transform(np.column_stack([x, y]))
            pts.append(_dense(q))
        if not pts:
            continue
        dense = np.concatenate(pts)
        for t in ax.texts:
            if not t.get_visible():
                continue
            b = t.get_window_extent(renderer)
            inside = ((dense[:, 0] > b.x0 + 0.5) & (dense[:, 0] < b.x1 - 0.5)
                      & (dense[:, 1] > b.y0 + 0.5) & (dense[:, 1] < b.y1 - 0.5))
            assert not np.any(inside), f"{t.get_text()!r} is written on a line of {ax.get_label()}"


@pytest.mark.parametrize("which", ["goda", "wide", "zero"])
def test_lifetime_figure_is_legible(which: str, goda_result: LifetimeResult, wide: LifetimeResult) -> None:
    result = {"goda": goda_result, "wide": wide, "zero": _zero()}[which]
    fig = lifetime_figure(result, title="Goda's caisson" if which == "wide" else None)
    _check_figure(fig)
    _labels_off_the_lines(fig)
    # every label was placed (none hidden)
    for ax in fig.axes:
        assert all(t.get_visible() for t in ax.texts)


def test_chart_figure_is_legible(chart: DesignChart) -> None:
    fig = chart_figure(chart, title="Goda's caisson")
    _check_figure(fig)
    _labels_off_the_lines(fig)
    assert all(t.get_visible() for t in fig.axes[0].texts)


# -- files: byte-stable SVG, TrueType PDF --------------------------------------------------------


def _bytes(fig, fmt: str, dpi: float | None = None) -> bytes:
    buf = io.BytesIO()
    print_figure(fig, buf, fmt, dpi)
    return buf.getvalue()


@pytest.mark.deep
def test_svg_is_byte_stable(goda_result: LifetimeResult, chart: DesignChart) -> None:
    for make in (lambda dpi: lifetime_figure(goda_result, dpi=dpi), lambda dpi: chart_figure(chart, dpi=dpi)):
        a = _bytes(make(150), "svg")
        b = _bytes(make(150), "svg")
        c = _bytes(make(60), "svg")  # the labels are placed the same at any resolution
        assert a == b == c
        assert b"<dc:date>" not in a


@pytest.mark.deep
def test_pdf_embeds_truetype_fonts(goda_result: LifetimeResult, chart: DesignChart) -> None:
    for fig in (lifetime_figure(goda_result), chart_figure(chart), lifetime_figure(_zero())):
        data = _bytes(fig, "pdf")
        assert data.startswith(b"%PDF")
        assert b"/Type3" not in data and b"/Subtype /Type3" not in data
        assert b"/TrueType" in data or b"/CIDFontType2" in data
        assert b"/CreationDate" not in data


# -- panel (g) of the design sheet ------------------------------------------------------------


def _goda_report():
    from regimemap.caisson.file import example_design_text, parse_design
    from regimemap.caisson.report import caisson_report

    return caisson_report(parse_design(example_design_text(), "goda.toml").analysis_inputs())


def test_sheet_without_a_lifetime_has_no_lifetime_panel() -> None:
    from regimemap.caisson.figures.page import LIFETIME_PANEL, PANELS
    from tests.conftest import draw_sheet

    fig = draw_sheet(_goda_report(), title="goda.toml")
    labels = [ax.get_label() for ax in fig.axes]
    assert LIFETIME_PANEL not in labels
    assert [lab for lab in labels if lab in PANELS] == list(PANELS)


@pytest.mark.deep
def test_sheet_with_a_lifetime_adds_panel_g_and_stays_legible(goda_result: LifetimeResult) -> None:
    from regimemap.caisson.figures.page import LIFETIME_PANEL, PANELS
    from tests.conftest import draw_sheet

    report = _goda_report()
    fig = draw_sheet(report, title="goda.toml", lifetime=goda_result)
    labels = [ax.get_label() for ax in fig.axes]
    assert LIFETIME_PANEL in labels and all(p in labels for p in PANELS)
    texts = _all_text(fig)
    assert "(g)" in texts and f"{goda_result.trials} lifetimes" in texts
    _labels_off_the_lines(fig, only=LIFETIME_PANEL)
    # the same bytes twice (the panel is placed deterministically)
    import io

    a, b = io.BytesIO(), io.BytesIO()
    print_figure(fig, a, "svg")
    print_figure(draw_sheet(report, title="goda.toml", lifetime=goda_result), b, "svg")
    assert a.getvalue() == b.getvalue()


# -- the verdict, the title, the zone off the mound, the width's interval ---------------------------


def _judged(result: LifetimeResult, target: float, failure: float | None = None) -> LifetimeResult:
    from regimemap.lifetime import Requirements, judge_lifetime

    return judge_lifetime(result, Requirements(target=target, failure_sliding=failure))


def _fig_texts(fig) -> list:
    return [t for t in fig.texts] + [t for ax in fig.axes for t in ax.texts]


@pytest.mark.parametrize(("target", "word"), [(0.1, "FAIL (1 of 1)"), (100.0, "PASS")])
def test_the_lifetime_figure_says_pass_or_fail_and_colours_a_failing_esd(goda_result: LifetimeResult, target: float,
                                                                         word: str) -> None:
    from matplotlib.colors import to_hex

    from regimemap.drawing.verdict import FAIL_COLOUR
    from regimemap.lifetime.figures.exceedance import lifetime_title

    result = _judged(goda_result, target, failure=5.0)
    fig = lifetime_figure(result, lifetime_title("goda", result))
    _check_figure(fig)
    texts = _fig_texts(fig)
    assert [t.get_text() for t in fig.texts if t.get_text() in ("PASS", "FAIL (1 of 1)")] == [word]
    esd = next(t for t in texts if t.get_text().startswith("ESD = "))
    assert (to_hex(esd.get_color()) == FAIL_COLOUR.lower()) == (word != "PASS")
    title = " ".join(t.get_text() for t in fig.texts)
    for part in ("goda: caisson $b$ = 15 m", "1000 lifetimes", "seed 1", "impulsive = false"):
        assert part in title, (part, title)
    # the zone off the mound: a hatched span from 5 m in both panels, and the failure in the key
    for ax in fig.axes:
        spans = [p for p in ax.patches if p.get_hatch()]
        assert len(spans) == 1 and spans[0].get_x() == pytest.approx(5.0)
    key = " ".join(t.get_text() for t in fig.legends[0].get_texts())
    assert f"off the mound ($S$ > 5 m): failure {100 * result.failure.probability:.3g} %" in key


def test_no_zone_off_the_mound_without_a_lifetime_beyond_it(wide: LifetimeResult) -> None:
    result = _judged(wide, 0.1, failure=1e6)
    fig = lifetime_figure(result)
    assert not any(p.get_hatch() for ax in fig.axes for p in ax.patches)
    assert "no lifetime slid off the mound" in " ".join(t.get_text() for t in fig.legends[0].get_texts())


def test_the_chart_draws_the_interval_the_design_width_and_the_verdict(chart: DesignChart) -> None:
    from matplotlib.colors import to_hex

    from regimemap.drawing.verdict import FAIL_COLOUR
    from regimemap.lifetime import judge_chart
    from regimemap.lifetime.figures.chart import chart_title

    judged = judge_chart(chart, 15.0)
    assert judged.checks and not judged.checks[0].passed  # 15 m is narrower than the width found
    fig = chart_figure(judged, chart_title("goda", judged))
    _check_figure(fig)
    ax = fig.axes[0]
    iv = judged.width_interval
    assert iv is not None
    bars = [ln for ln in ax.lines if list(ln.get_xdata()) == [iv.lower, iv.upper]]
    assert len(bars) == 1 and list(bars[0].get_ydata()) == [judged.target] * 2
    design = next(t for t in ax.texts if t.get_text().startswith("design b = 15"))
    assert to_hex(design.get_color()) == FAIL_COLOUR.lower()
    assert "FAIL (1 of 1)" in [t.get_text() for t in fig.texts]
    passed = judge_chart(chart, 24.0)
    assert passed.checks[0].passed
    assert "PASS" in [t.get_text() for t in chart_figure(passed, "goda").texts]


def test_the_chart_draws_the_climate_bands_upper_curve_and_its_width(chart: DesignChart) -> None:
    from regimemap.lifetime.figures.chart import BAND_LINE
    from regimemap.lifetime.replicates import ChartBand

    w = np.asarray(chart.widths)
    esd = np.vstack([chart.expected_sliding * f for f in (0.5, 1.0, 3.0)])
    band = ChartBand(widths=w, esd=esd, level=0.9, target=0.1, seed=1, trials=chart.trials)
    assert band.width_for_target is not None and band.width_for_target > chart.width_for_target
    fig = chart_figure(chart, "goda", band=band)
    _check_figure(fig)
    ax = fig.axes[0]
    upper = [ln for ln in ax.lines if len(ln.get_xdata()) == w.size and ln.get_color() == BAND_LINE]
    assert len(upper) == 1
    np.testing.assert_allclose(np.asarray(upper[0].get_ydata(), dtype=float),
                               np.where(band.upper > 0, band.upper, np.nan))  # 0 is off the log axis
    text = _all_text(fig)
    assert f"b = {band.width_for_target:.3g} m (band)" in text
    assert "upper end of the 90 % climate band (3 climates)" in text
    never = ChartBand(widths=w, esd=esd * 1e6 + 1.0, level=0.9, target=0.1, seed=1, trials=chart.trials)
    assert never.width_for_target is None
    assert "(band)" not in _all_text(chart_figure(chart, "goda", band=never))
