"""The climate workflow: run_climate, a wave record (its file or its arrays) to one record."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from regimemap.climate import ClimateOptions, analyse, make_record
from regimemap.climate.analysis import Diagnostics, curves
from regimemap.climate.file import read_record
from regimemap.climate.record import climate_json
from regimemap.workflows import ClimateRecord, run_climate

DATA = Path(__file__).parents[1] / "climate" / "data"
NDBC = DATA / "ndbc44007_1996_hs_tz.txt.gz"
OPTIONS = ClimateOptions(threshold=("quantile", 0.98), bootstrap=20, seed=1)


@pytest.mark.slow
def test_the_record_holds_the_analysis_and_what_the_figures_draw() -> None:
    rec = run_climate(NDBC, OPTIONS)
    assert isinstance(rec, ClimateRecord) and rec.source == str(NDBC)
    direct = analyse(read_record(NDBC), OPTIONS)
    assert rec.result.return_values == direct.return_values
    np.testing.assert_array_equal(rec.curves.level, curves(direct).level)
    assert rec.diagnostics is None
    assert rec.report_json() == climate_json(direct, source=str(NDBC), sensitivity=rec.sensitivity)
    assert rec.report_json(["a.svg"])["files"] == ["a.svg"]
    assert rec.report_text().startswith(f"wave climate: {NDBC}\n")


@pytest.mark.slow
def test_the_diagnostics_when_asked() -> None:
    rec = run_climate(NDBC, OPTIONS, diagnostics=True)
    assert isinstance(rec.diagnostics, Diagnostics) and rec.diagnostics.thresholds.size == 30


@pytest.mark.slow
def test_a_record_of_arrays_gives_the_numbers_of_its_file() -> None:
    wave = read_record(NDBC)
    made = make_record("buoy", wave.time, wave.hs, wave.period, wave.period_name)
    rec = run_climate(made, OPTIONS)
    assert rec.source == "buoy"
    assert rec.result.return_values == run_climate(NDBC, OPTIONS).result.return_values


@pytest.mark.slow
def test_the_warnings_are_notices_naming_the_record() -> None:
    wave = read_record(NDBC)
    repeated = make_record("dup", np.concatenate([wave.time[:100], wave.time[99:]]),
                           np.concatenate([wave.hs[:100], wave.hs[99:100] + 1.0, wave.hs[100:]]))
    rec = run_climate(repeated, OPTIONS)
    # one year above its 98 % quantile: the fit's own warnings (code fit) follow the record's
    assert [n.code for n in rec.notices if n.code != "fit"] == ["record-quality"]
    assert [n.message for n in rec.notices] == [f"dup: {w}" for w in rec.result.warnings()]
    assert "repeated time" in rec.notices[0].message and "warning: record-quality" in rec._repr_html_()
    assert {n.code for n in run_climate(NDBC, OPTIONS).notices} == {"fit"}


def test_the_field_table() -> None:
    rec = run_climate(NDBC, OPTIONS)
    rows = {label: value for label, value, _, _ in rec.field_rows()}
    assert rows["distribution"] == "gpd" and rows["method"] == "pot"
    assert rows["u"] == pytest.approx(rec.result.fit.threshold)
    assert rows["return values"].startswith("10 years: ")


def test_options_that_do_not_go_together_are_refused() -> None:
    with pytest.raises(ValueError, match="does not fit annual-maxima"):
        run_climate(NDBC, ClimateOptions(method="annual-maxima", distribution="gpd"))
