"""run_study: paired scenarios, the same bytes on any executor, the store, resuming, the climate band."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest

from regimemap.lifetime import lifetime_sliding
from regimemap.study.file import read_study
from regimemap.study.record_store import StudyStore, StudyStoreError
from regimemap.study.record_table import study_csv_text, study_json
from regimemap.study.run import run_study
from regimemap.study.run_tasks import task_seed

from ..conftest import band_design
from .conftest import SITE, scenario_table, section_table, study_head

STUDY = (study_head(11, 150) + section_table("shallow", 0.0, *SITE, "width = 12.0")
         + section_table("deep", 300.0, "widths = [13.0, 16.0]")
         + scenario_table("today")
         + scenario_table("no change written out", "sea_level_rise = { 50 = 0.0 }",
                          "wave_height_factor = { 10 = 1.0 }")
         + scenario_table("rise 1 m", "sea_level_rise = { 50 = 1.0 }"))


def _bytes(record) -> tuple[str, str]:
    return study_csv_text(record), json.dumps(study_json(record))


def test_a_scenario_without_change_gives_todays_numbers_bit_for_bit(write_study):
    s = read_study(write_study(STUDY))
    record = run_study(s)
    today = record.rows_for(scenario="today")
    same = record.rows_for(scenario="no change written out")
    assert [(r.width, r.expected_sliding, r.std_error, r.by_year, r.exceedance) for r in today] == \
        [(r.width, r.expected_sliding, r.std_error, r.by_year, r.exceedance) for r in same]
    assert s.model(s.sections[0], s.scenarios[1]).trend is not None  # run through the trend's code
    # and today's numbers are those of regimemap lifetime's lifetime_sliding on the task's seed
    sec = s.sections[0]
    direct = lifetime_sliding(sec.caisson().with_width(12.0), sec.design.lifetime_model(), 150,
                              task_seed(11, 0, 0))
    row = record.rows_for("shallow", "today")[0]
    assert row.expected_sliding == float(direct.expected_sliding)
    assert row.by_year == tuple(float(x) for x in direct.by_year)
    assert row.by_year[-1] == pytest.approx(row.expected_sliding, rel=1e-12, abs=1e-15)


def test_sea_level_rise_in_depth_limited_water_raises_the_esd(write_study):
    record = run_study(write_study(STUDY))
    today = record.rows_for("shallow", "today")[0]
    rise = record.rows_for("shallow", "rise 1 m")[0]
    assert rise.expected_sliding > today.expected_sliding > 0.0
    assert all(b >= a for a, b in zip(today.by_year, rise.by_year))


def test_the_record_holds_the_study_in_order(write_study):
    record = run_study(write_study(STUDY))
    assert record.sections == (("shallow", 0.0), ("deep", 300.0))
    assert record.scenarios == ("today", "no change written out", "rise 1 m")
    assert [(r.section, r.scenario, r.width) for r in record.rows[:4]] == [
        ("shallow", "today", 12.0), ("shallow", "no change written out", 12.0), ("shallow", "rise 1 m", 12.0),
        ("deep", "today", 13.0)]
    assert len(record.rows) == 3 + 3 * 2 and record.years == 50 and len(record.rows[0].by_year) == 50
    assert record.target is None and record.notices == ()
    r = record.rows_for("deep", "today")
    assert r[0].expected_sliding >= r[1].expected_sliding  # wider, on common random numbers
    for row in record.rows:
        year = dict(row.passes)[0.1]
        assert year is None or (row.by_year[year - 1] > 0.1 and (year == 1 or row.by_year[year - 2] <= 0.1))


@pytest.mark.subprocess
def test_jobs_do_not_change_the_bytes(tmp_path, write_study):
    path = write_study(STUDY)
    one = _bytes(run_study(path, jobs=1))
    assert _bytes(run_study(path, jobs=2)) == one
    assert _bytes(run_study(path, jobs=2, store=tmp_path / "store")) == one


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_a_dask_local_cluster_gives_the_same_bytes(write_study):
    pytest.importorskip("distributed")
    path = write_study(STUDY)
    assert _bytes(run_study(path, jobs=2, scheduler="local")) == _bytes(run_study(path))


@pytest.mark.slow
def test_resuming_a_partial_store_gives_the_same_bytes(tmp_path, write_study):
    path = write_study(STUDY)
    whole = _bytes(run_study(path, store=tmp_path / "a"))
    store = tmp_path / "a" / "tasks"
    files = sorted(store.glob("*.json"))
    assert len(files) == 2 * 3
    for f in files[::2]:
        f.unlink()
    calls = []
    again = run_study(path, store=tmp_path / "a", resume=True, progress=lambda d, t: calls.append((d, t)))
    assert _bytes(again) == whole
    assert calls[0] == (3, 6) and calls[-1] == (6, 6) and len(calls) == 4
    assert _bytes(run_study(path)) == whole  # and without a store at all


def test_a_store_is_refused_without_resume_and_for_a_changed_study(tmp_path, write_study):
    path = write_study(STUDY)
    run_study(path, store=tmp_path / "s")
    before = {p: (p.stat().st_mtime_ns, p.read_bytes()) for p in (tmp_path / "s").rglob("*")
              if p.is_file()}
    with pytest.raises(StudyStoreError, match="give --resume to finish"):
        run_study(path, store=tmp_path / "s")
    path.write_text(STUDY.replace("depth = 8.0", "depth = 8.2"))
    with pytest.raises(StudyStoreError, match="the store of another study .*has changed.*untouched"):
        run_study(path, store=tmp_path / "s", resume=True)
    after = {p: (p.stat().st_mtime_ns, p.read_bytes()) for p in (tmp_path / "s").rglob("*") if p.is_file()}
    assert after == before
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("mine")
    with pytest.raises(StudyStoreError, match="not a study store"):
        StudyStore(tmp_path / "other", "h", "x", 1)
    with pytest.raises(StudyStoreError, match="not a folder"):
        StudyStore(tmp_path / "other" / "notes.txt", "h", "x", 1)


@pytest.mark.slow
def test_a_failed_store_loses_only_the_task_in_flight(tmp_path, write_study, monkeypatch):
    """A task whose store fails (a full disk) stops the run; the tasks before stay, --resume redoes it."""
    path = write_study(STUDY)
    whole = _bytes(run_study(path))
    real = StudyStore.save
    count = [0]

    def failing(self, name, result):
        count[0] += 1
        if count[0] == 3:
            raise OSError(28, "No space left on device")
        real(self, name, result)

    monkeypatch.setattr(StudyStore, "save", failing)
    with pytest.raises(OSError, match="No space"):
        run_study(path, store=tmp_path / "st")
    monkeypatch.setattr(StudyStore, "save", real)
    names = sorted(p.name for p in (tmp_path / "st" / "tasks").glob("*.json"))
    assert names == ["s0000-c00-r0000.json", "s0000-c01-r0000.json"]
    assert _bytes(run_study(path, store=tmp_path / "st", resume=True)) == whole


def test_atomic_save_leaves_no_partial_file_when_interrupted(tmp_path, monkeypatch):
    store = StudyStore(tmp_path / "s", "h", "x", 1)

    def boom(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(json, "dump", boom)
    with pytest.raises(KeyboardInterrupt):
        store.save("s0000-c00-r0000.json", {"a": 1})
    assert os.listdir(tmp_path / "s" / "tasks") == []
    assert store.load("s0000-c00-r0000.json") is None


@pytest.mark.slow
@pytest.mark.deep
def test_a_target_section_finds_its_width_and_the_band_of_a_record(tmp_path):
    band_design(tmp_path, replicates=3)  # tmp_path/site.toml
    study = ('seed = 3\ntrials = 60\nbase = "site.toml"\n\n[[section]]\nname = "fixed"\nchainage = 0\n'
             'widths = [12.0, 16.0]\n\n[[section]]\nname = "target"\nchainage = 10\ntarget = 0.1\n'
             'widths = [16.0, 40.0]\ntolerance = 2.0\n\n[[scenario]]\nname = "today"\n')
    (tmp_path / "study.toml").write_text(study)
    record = run_study(tmp_path / "study.toml")
    fixed = record.rows_for("fixed")
    assert len(fixed) == 2 and all(r.band is not None and r.band[0] <= r.band[1] for r in fixed)
    (row,) = record.rows_for("target")
    assert record.target == 0.1 and row.required_width == row.width
    assert 16.0 <= row.width <= 40.0 and row.expected_sliding <= 0.1
    if row.required_width_interval is not None:
        assert row.required_width_interval[0] <= row.required_width_interval[1]
    assert row.required_width_upper is None or 16.0 <= row.required_width_upper <= 40.0
    assert np.isfinite(row.std_error)
