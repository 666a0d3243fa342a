"""The lifetime workflows: run_lifetime and run_chart, one call to one record."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text, read_design
from regimemap.lifetime import lifetime_sliding
from regimemap.lifetime.record import lifetime_json
from regimemap.lifetime.results import STATISTICS
from regimemap.workflows import ChartRecord, LifetimeRecord, read_lifetime_design, run_chart, run_lifetime


def test_the_record_holds_the_library_call_and_the_section(goda: Path) -> None:
    rec = run_lifetime(goda, trials=150, seed=3)
    assert isinstance(rec, LifetimeRecord)
    d = read_design(goda)
    direct = lifetime_sliding(d.lifetime_caisson(), d.lifetime_model(), 150, 3)
    np.testing.assert_array_equal(rec.result.sliding, direct.sliding)
    assert rec.result.checks and rec.result.checks[0].name == "expected sliding distance"
    assert (rec.width, rec.friction, rec.design_H0) == (15.0, 0.6, 6.3)
    assert rec.buoyant_weight == pytest.approx(2312e3)
    assert (rec.H0_10, rec.H0_50) == (pytest.approx(5.0), pytest.approx(6.3))
    assert (rec.trials, rec.seed, rec.used_seed, rec.processes, rec.band) == (150, 3, 3, 1, None)
    assert rec.notices == () and rec.source == str(goda)


def test_a_design_object_and_its_file_give_the_same_numbers(goda: Path) -> None:
    by_path = run_lifetime(goda, trials=100, seed=5, years=20)
    by_object = run_lifetime(read_design(goda), trials=100, seed=5, years=20)
    np.testing.assert_array_equal(by_path.result.sliding, by_object.result.sliding)
    assert by_object.model.years == 20 and by_object.source is None


def test_the_report_is_the_io_serializer_of_the_result(goda: Path) -> None:
    rec = run_lifetime(goda, trials=100, seed=1)
    got = rec.report_json(["life.csv"])
    assert got["files"] == ["life.csv"]
    del got["files"]
    assert got == lifetime_json(rec.result, rec.model, source=str(goda), written=rec.climate_as_written)
    json.dumps(got, allow_nan=False)
    assert rec.report_text().startswith(f"lifetime sliding: {goda}\n")


def test_the_statistics_table_gives_the_dict_the_json_and_the_html(goda: Path) -> None:
    rec = run_lifetime(goda, trials=100, seed=1)
    keys = [s.key for s in STATISTICS]
    assert list(rec.result.summary()) == keys
    js = lifetime_json(rec.result, rec.model)
    assert [k for k in js if k in keys] == keys  # in the table's order
    assert set(js["units"]) == {s.key for s in STATISTICS if s.unit}
    html = rec.result._repr_html_()
    assert all(s.label.format(x="0.1").replace(">", "&gt;") in html for s in STATISTICS
               if s.key != "failure" and s.key not in {t.beside for t in STATISTICS})
    # the record's own table: its section, then the scalar statistics
    rows = {label: value for label, value, _, _ in rec.field_rows()}
    assert rows["W'"] == pytest.approx(2312e3) and rows["mu"] == 0.6
    assert rows["expected sliding (ESD)"] == rec.result.expected_sliding
    assert "W&#x27;" in rec._repr_html_()


def test_no_seed_is_a_fresh_one_reported(goda: Path, tmp_path: Path) -> None:
    p = tmp_path / "fresh.toml"
    p.write_text(goda.read_text().replace("seed = 2026", "# no seed"))
    rec = run_lifetime(p, trials=20)
    assert rec.seed is None and rec.used_seed == rec.result.seed


@pytest.mark.slow
def test_an_implausible_value_is_a_notice(goda: Path, tmp_path: Path) -> None:
    p = tmp_path / "wide.toml"
    p.write_text(goda.read_text().replace("width = 15.0", "width = 150.0", 1))
    inputs = read_lifetime_design(p)
    assert [n.code for n in inputs.notices] == ["implausible-value"]
    assert inputs.notices[0].quantity == "[caisson] width" and inputs.notices[0].value == 150.0
    assert inputs.notices[0].message.startswith(f"{p}: [caisson] width = 150")
    rec = run_lifetime(inputs, trials=10, seed=1)
    assert rec.notices == inputs.notices


def test_progress_is_asked_for_every_lifetime(goda: Path) -> None:
    import contextlib

    done: dict[str, list[int]] = {}

    @contextlib.contextmanager
    def bars(total: int, what: str):  # type: ignore[no-untyped-def]
        done[what] = [total, 0]

        def step(n: int) -> None:
            done[what][1] += n

        yield step

    run_lifetime(goda, trials=120, seed=2, progress=bars)
    assert done == {"lifetimes": [120, 120]}


def test_jobs_and_a_scheduler_exclude_each_other(goda: Path) -> None:
    with pytest.raises(ValueError, match="jobs and scheduler exclude each other"):
        run_lifetime(goda, trials=10, jobs=2, scheduler="tcp://127.0.0.1:1")


@pytest.mark.slow
def test_the_chart_record_judges_the_design_width(goda: Path) -> None:
    rec = run_chart(goda, [10.0, 25.0], target=0.1, tolerance=1.0, trials=100, seed=4)
    assert isinstance(rec, ChartRecord)
    assert rec.notices == () and rec.widths == (10.0, 25.0) and rec.target == 0.1
    assert rec.result.width_for_target is not None and 10.0 < rec.result.width_for_target < 25.0
    assert rec.result.checks and rec.result.design_width == 15.0
    rows = dict((label, value) for label, value, _, _ in rec.field_rows())
    assert rows["width for the target"] == rec.result.width_for_target
    assert rows["width with the climate's band"] is None


def test_a_chart_that_does_not_bracket_the_target_is_a_notice(goda: Path) -> None:
    rec = run_chart(goda, [30.0, 40.0], target=0.1, trials=50, seed=4)
    assert [n.code for n in rec.notices] == ["target-not-bracketed"]
    assert "not between the ESD at the ends of the widths" in rec.notices[0].message
    assert rec.result.checks == () and rec.band is None


@pytest.mark.slow
def test_a_record_climate_adds_the_band(tmp_path: Path) -> None:
    import shutil

    data = Path(__file__).parents[1] / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"
    shutil.copy(data, tmp_path / "buoy.txt.gz")
    text = example_design_text()
    i, j = text.index("[lifetime]"), text.index("[lifetime.errors]")
    kept = [line for line in text[i:j].splitlines()
            if line.split("=")[0].strip() not in ("H0_10", "H0_50", "distribution", "shape")]
    life = "\n".join(kept) + "\nclimate_replicates = 3\n[lifetime.record]\npath = \"buoy.txt.gz\"\n" \
        "threshold = \"98%\"\n\n"
    p = tmp_path / "site.toml"
    p.write_text(text[:i] + life + text[j:])
    rec = run_lifetime(p, trials=60, seed=9)
    assert rec.band is not None and rec.band.replicates == 3 and rec.band_seconds is not None
    assert rec.report_json()["climate_band"]["replicates"] == 3
    assert "90 % climate band:" in rec.report_text()
