"""The figures of a study: what each draws, the refusals, legible texts, the same SVG bytes twice.

Records are built by hand (:func:`tests.study.test_record_netcdf.hand_record`): three sections (two
with fixed widths, one with a target) under two scenarios, and a 20-section breakwater whose
section names stand upright above the axes.  Each figure is checked for its lines (one per
scenario, a point per section or per service year), its labels and key, texts that neither meet
nor leave the figure (tests/drawing/test_legible.py's check) and its SVG bytes drawn twice.
"""

from __future__ import annotations

import io

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from regimemap.drawing.save import print_figure  # noqa: E402
from regimemap.drawing.text.labelplacer import figure_texts  # noqa: E402
from regimemap.study.figures import FIGURE_KINDS, study_figure  # noqa: E402
from regimemap.study.run import StudyRecord  # noqa: E402
from tests.drawing.test_legible import _check_boxes  # noqa: E402
from tests.study.test_record_netcdf import YEARS, _row, hand_record  # noqa: E402

pytestmark = pytest.mark.render

SCENARIOS = ("today", "rise 1 m", "rise + storms")


def breakwater(sections: int = 20, band: bool = True) -> StudyRecord:
    """``sections`` sections 50 m apart under three scenarios, one width each."""
    rows, names = [], []
    for i in range(sections):
        name = f"S{i + 1:02d} trunk"
        names.append((name, 50.0 * i))
        for j, sc in enumerate(SCENARIOS):
            rows.append(_row(name, 50.0 * i, sc, 15.0 + i, 0.02 * (1 + i % 5) * (1 + j), band=band, years=50))
    return StudyRecord(source=None, study_hash="0" * 64, seed=11, trials=1000, years=50, sections=tuple(names),
                       scenarios=SCENARIOS, target=None, rows=tuple(rows), notices=())


def _text(fig) -> str:
    return " | ".join(t.get_text() for t in figure_texts(fig))


def _axes(fig, label: str = "study"):
    return next(ax for ax in fig.axes if ax.get_label() == label)


def _boxes(fig) -> dict[str, list]:
    """Every text of the figure (the key as one box) for tests/drawing/test_legible.py's check."""
    renderer = fig.canvas.get_renderer()
    in_key = {id(t) for leg in fig.legends for t in leg.get_texts()}
    fixed = []
    for t in figure_texts(fig):
        if id(t) not in in_key:
            b = t.get_window_extent(renderer)
            fixed.append((repr(t.get_text()), (b.x0, b.y0, b.x1, b.y1)))
    for leg in fig.legends:
        b = leg.get_window_extent(renderer)
        fixed.append(("key", (b.x0, b.y0, b.x1, b.y1)))
    return {"fixed": fixed, "labels": [], "markers": []}


def _lines_of(ax, n: int) -> list:
    """The lines of ``ax`` with ``n`` points and a line style (the scenarios' curves)."""
    return [ln for ln in ax.get_lines() if len(ln.get_xdata()) == n and ln.get_linestyle() not in ("None", "")]


# -- what the figures draw -----------------------------------------------------------------------


def test_chainage_draws_a_line_per_scenario_through_the_sections() -> None:
    rec = hand_record(band=True)
    fig = study_figure(rec, "chainage")
    ax = _axes(fig)
    assert ax.get_yscale() == "log"
    lines = _lines_of(ax, len(rec.sections))
    assert len(lines) == len(rec.scenarios)
    for ln, sc in zip(lines, rec.scenarios):
        first = [rec.rows_for(section=n, scenario=sc)[0] for n, _ in rec.sections]
        np.testing.assert_allclose(ln.get_ydata(), [r.expected_sliding for r in first])
        # the markers stand beside the sections' chainages (dodged by under 1 % of the span)
        np.testing.assert_allclose(ln.get_xdata(), [c for _, c in rec.sections], atol=5.0)
    # an error bar of +-2 SE for every row, the band a hatched box per section and scenario
    bars = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 2 and ln.get_xdata()[0] == ln.get_xdata()[1]]
    assert len(bars) == len(rec.rows)
    r0 = rec.rows[0]
    assert any(np.allclose(b.get_ydata(), [r0.expected_sliding - 2 * r0.std_error,
                                           r0.expected_sliding + 2 * r0.std_error]) for b in bars)
    assert len(ax.collections) == len(rec.scenarios) * len(rec.sections)
    # the other width of trunk 8 m: an open marker per scenario
    assert len([ln for ln in ax.get_lines() if ln.get_linestyle() == "None"
                and ln.get_markerfacecolor() == "white"]) == len(rec.scenarios)
    text = _text(fig)
    for sc in rec.scenarios:
        assert f"{sc}: ESD \u00b1 2 standard errors" in text and f"{sc}: climate band of the ESD" in text
    assert "0.1 m" in text and "0.3 m" in text and "Goda & Takagi 2000" in text
    assert "seed 2026" in text and "300 lifetimes" in text
    top = _axes(fig, "sections")
    assert [t.get_text() for t in top.get_xticklabels()] == [n for n, _ in rec.sections]


def test_chainage_without_a_band_has_no_fill_and_marks_a_zero_esd() -> None:
    import dataclasses

    rec = hand_record(band=False)
    rows = list(rec.rows)
    rows[1] = dataclasses.replace(rows[1], expected_sliding=0.0, std_error=0.0)
    fig = study_figure(dataclasses.replace(rec, rows=tuple(rows)), "chainage")
    ax = _axes(fig)
    assert len(ax.collections) == 0
    assert "climate band" not in _text(fig) and "ESD = 0 (no lifetime slid)" in _text(fig)
    assert len([ln for ln in ax.get_lines() if ln.get_marker() == "v"]) == 1


def test_years_draws_the_sliding_by_service_year_and_the_passing_years() -> None:
    rec = hand_record()
    fig = study_figure(rec, "years", section="trunk 8 m")
    ax = _axes(fig)
    lines = _lines_of(ax, YEARS)
    assert len(lines) == len(rec.scenarios)
    for ln, sc in zip(lines, rec.scenarios):
        r = rec.rows_for(section="trunk 8 m", scenario=sc)[0]
        assert list(ln.get_xdata()) == list(range(1, YEARS + 1))
        np.testing.assert_allclose(ln.get_ydata(), r.by_year)
    # 'rise 1 m' at 12 m: 0.2 m at year 10, over 0.1 m from year 6; 'today' passes nothing
    r = rec.rows_for(section="trunk 8 m", scenario="rise 1 m")[0]
    assert r.passes == ((0.1, 6), (0.3, None))
    marks = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 1]
    assert [(float(m.get_xdata()[0]), float(m.get_ydata()[0])) for m in marks] == [(6.0, r.by_year[5])]
    text = _text(fig)
    assert "today; passes no limit" in text and "rise 1 m; passes 0.1 m in year 6" in text
    assert "trunk 8 m (chainage 0 m)" in text and "b = 12 m" in text
    assert "first year over 0.1 m" in text and "service year" in text


def test_years_defaults_to_the_first_section_and_names_a_target_section_so() -> None:
    rec = hand_record()
    assert "trunk 8 m" in _text(study_figure(rec, "years"))
    assert "the width for the target under each scenario" in _text(study_figure(rec, "years", "head 18 m"))


def test_width_draws_the_required_width_its_interval_and_the_band_level() -> None:
    rec = hand_record(band=True)
    fig = study_figure(rec, "width")
    ax = _axes(fig)
    fixed = [ln for ln in ax.get_lines() if ln.get_marker() == "_" and ln.get_linestyle() == "None"]
    assert len(fixed) == 1 and list(fixed[0].get_ydata()) == [12.0, 15.0, 20.0]
    drawn = [ln for ln in ax.get_lines() if ln not in fixed]
    marks = [ln for ln in drawn if len(ln.get_xdata()) == 1]
    # per scenario: the width (one target section), its upper-level width
    assert sorted(float(m.get_ydata()[0]) for m in marks) == [30.0, 34.0, 34.0, 38.0]
    bars = [ln for ln in drawn if len(ln.get_xdata()) == 2]
    assert sorted(tuple(b.get_ydata()) for b in bars) == [(28.0, 33.0), (32.0, 37.0)]
    text = _text(fig)
    assert "Width for an expected sliding distance of 0.1 m" in text
    assert "today: at the climate band's upper level" in text
    assert "the fixed widths of the other sections" in text
    assert [t.get_text() for t in _axes(fig, "sections").get_xticklabels()] == ["head 18 m"]


def test_refusals() -> None:
    rec = hand_record()
    with pytest.raises(ValueError, match="kind = 'map': accepted: chainage, years, width"):
        study_figure(rec, "map")
    with pytest.raises(ValueError, match="section = 'pier': not a section of the study; accepted: trunk 8 m"):
        study_figure(rec, "years", section="pier")
    with pytest.raises(ValueError, match="no section of this study has one"):
        study_figure(hand_record(target=False), "width")


# -- legible and byte-stable ---------------------------------------------------------------------

CASES = [("hand", kind) for kind in FIGURE_KINDS] + [("hand-no-band", "chainage"), ("breakwater", "chainage"),
                                                     ("breakwater", "years")]


def _record(name: str) -> StudyRecord:
    return {"hand": lambda: hand_record(band=True), "hand-no-band": lambda: hand_record(band=False),
            "breakwater": breakwater}[name]()


@pytest.mark.parametrize(("name", "kind"), CASES)
def test_no_text_meets_another_nor_leaves_the_figure(name: str, kind: str) -> None:
    fig = study_figure(_record(name), kind)
    _check_boxes(fig, lambda: _boxes(fig))


def test_twenty_sections_stand_upright_above_the_axes() -> None:
    fig = study_figure(breakwater(), "chainage")
    labels = _axes(fig, "sections").get_xticklabels()
    assert len(labels) == 20 and all(t.get_rotation() == 90.0 for t in labels)
    few = study_figure(hand_record(), "chainage")
    assert all(t.get_rotation() == 0.0 for t in _axes(few, "sections").get_xticklabels())


@pytest.mark.parametrize("kind", FIGURE_KINDS)
def test_the_same_svg_bytes_twice(kind: str) -> None:
    out = []
    for _ in range(2):
        buf = io.BytesIO()
        print_figure(study_figure(hand_record(band=True), kind), buf, "svg")
        out.append(buf.getvalue())
    assert out[0] == out[1] and len(out[0]) > 10_000


def _band_boxes(ax) -> list:
    return [c for c in ax.collections if c.get_gid() == "climate-band"]


def test_chainage_draws_the_band_at_every_banded_section_a_lone_one_too() -> None:
    from dataclasses import replace

    rec = hand_record(band=True)
    ax = _axes(study_figure(rec, "chainage"))
    boxes = _band_boxes(ax)
    assert len(boxes) == len(rec.sections) * len(rec.scenarios)  # each section's first width, each scenario
    lone = replace(rec, rows=tuple(r if r.section == "trunk 12 m" else replace(r, band=None) for r in rec.rows))
    ax = _axes(study_figure(lone, "chainage"))
    boxes = _band_boxes(ax)
    assert len(boxes) == len(rec.scenarios)
    row = next(r for r in lone.rows if r.section == "trunk 12 m" and r.scenario == "today")
    assert row.band is not None
    ys = boxes[0].get_paths()[0].vertices[:, 1]
    xs = boxes[0].get_paths()[0].vertices[:, 0]
    assert min(ys) == pytest.approx(row.band[0]) and max(ys) == pytest.approx(row.band[1])
    assert min(xs) < 250.0 < max(xs)
    assert not _band_boxes(_axes(study_figure(hand_record(band=False), "chainage")))
