"""``regimemap study``: the example, the outputs, the exit codes, kill -9 and --resume."""

from __future__ import annotations

import csv
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from regimemap.study.record_table import STUDY_COLUMNS

from .conftest import SITE, scenario_table, section_table, study_head

SMALL = (study_head(4, 100) + section_table("a", 0.0, *SITE, "width = 12.0")
         + section_table("b", 50.0, "widths = [14.0, 16.0]")
         + scenario_table("today") + scenario_table("rise", "rate = 0.01"))


def test_the_table_the_csv_and_the_json(run_cli, tmp_path, write_study):
    path = write_study(SMALL)
    out = run_cli(["study", str(path), "--jobs", "1", "-o", str(tmp_path / "t.csv")])
    assert out.code == 0, out.output
    lines = out.stdout.splitlines()  # the table, then the file written
    assert lines[0] == f"study: {path}" and lines[-1] == str(tmp_path / "t.csv")
    assert sum(line.startswith(("a ", "b ")) for line in lines) == 6
    assert (tmp_path / "study.store" / "manifest.json").is_file()
    rows = list(csv.DictReader(io.StringIO((tmp_path / "t.csv").read_text())))
    assert tuple(rows[0]) == STUDY_COLUMNS
    assert [(r["section"], r["scenario"], r["width"]) for r in rows] == [
        ("a", "today", "12.0"), ("a", "rise", "12.0"), ("b", "today", "14.0"), ("b", "today", "16.0"),
        ("b", "rise", "14.0"), ("b", "rise", "16.0")]
    again = run_cli(["study", str(path), "--resume", "--json", "--store", str(tmp_path / "study.store")])
    assert again.code == 0, again.output
    summary = json.loads(again.stdout)
    assert summary["seed"] == 4 and summary["years"] == 50 and len(summary["rows"]) == 6
    first = summary["rows"][0]
    assert {"section", "scenario", "width", "expected_sliding", "std_error", "exceedance", "by_year"} <= set(first)
    assert len(first["by_year"]) == 50 and set(first["exceedance"]) == {"0.1", "0.3"}
    assert float(rows[0]["expected_sliding"]) == first["expected_sliding"]
    text = run_cli(["study", str(path), "--resume"])
    assert text.code == 0 and "a                today" in text.stdout


@pytest.mark.parametrize(("args", "says"), [
    (["--example", "x.toml"], "--example prints the example study and takes no STUDY.toml"),
    ([], "missing STUDY.toml"),
    (["STUDY", "-o", "t.xlsx"], "t.xlsx'; use .csv or .nc for the table, .png, .svg or .pdf for the figure"),
    (["STUDY", "--scheduler", "tcp://h:1", "--jobs", "2"], "--jobs and --scheduler ADDRESS exclude"),
    (["STUDY", "--section", "nowhere"], "'nowhere' is not a section of the study; accepted: a, b"),
    (["STUDY", "--figure", "map"], "Invalid value for '--figure'"),
    (["STUDY", "--scheduler", "nowhere"], "scheduler must be the address of a Dask scheduler"),
    (["STUDY", "--resume", "--overwrite"], "--resume and --overwrite exclude each other"),
])
def test_usage_errors_exit_2_in_one_line(run_cli, tmp_path, write_study, args, says):
    path = write_study(SMALL)
    (tmp_path / "x.toml").write_text("")
    args = [str(path) if a == "STUDY" else str(tmp_path / a) if a in ("x.toml", "t.xlsx") else a for a in args]
    out = run_cli(["study", *args] if "--jobs" in args else ["study", *args, "--jobs", "1"])
    assert out.code == 2, out.output
    assert says in out.stderr and out.stderr.count("\n") == 1


def test_the_same_output_twice_exits_2_before_the_run(run_cli, tmp_path, write_study, monkeypatch):
    """As lifetime and climate refuse it (the one check, cli._writing.distinct_files), however spelt."""
    path = write_study(SMALL)
    monkeypatch.chdir(tmp_path)
    out = run_cli(["study", str(path), "--jobs", "1", "-q", "-o", "t.csv", "-o", str(tmp_path / "t.csv")])
    assert out.code == 2, out.output
    assert "Invalid value for '-o' / '--output': the same file is given twice" in out.stderr
    assert out.stderr.count("\n") == 1 and not (tmp_path / "study.store").exists()
    assert not (tmp_path / "t.csv").exists()


def _store_refused(run_cli, tmp_path, path, *args: str) -> str:
    """A study refused, exit 2 in one line naming --store, before any store or file is made."""
    (tmp_path / "out").mkdir(exist_ok=True)  # -o's folder, refused by none of the tests
    before = sorted(p.name for p in tmp_path.rglob("*"))
    out = run_cli(["study", str(path), "--jobs", "1", "-q", "-o", str(tmp_path / "out" / "t.csv"), *args])
    assert out.code == 2, out.output
    assert "Traceback" not in out.output and out.stderr.count("\n") == 1 and out.stdout == ""
    assert "Invalid value for '--store': " in out.stderr, out.stderr
    assert sorted(p.name for p in tmp_path.rglob("*")) == before
    return out.stderr


def test_a_store_whose_parent_is_missing_exits_2_and_makes_nothing(run_cli, tmp_path, write_study):
    """As -o does for a file in a missing folder: the store itself is made, not its parents."""
    path = write_study(SMALL)
    err = _store_refused(run_cli, tmp_path, path, "--store", str(tmp_path / "no" / "such" / "s"))
    assert f"folder '{tmp_path / 'no' / 'such'}' does not exist" in err
    err = _store_refused(run_cli, tmp_path, path, "--store", str(path / "s"))
    assert f"folder '{path}' is a file, not a folder" in err


@pytest.mark.parametrize("folder", ["/proc", "/sys"])
def test_a_store_in_a_read_only_folder_exits_2(run_cli, tmp_path, write_study, folder):
    """As -o in the same folder: 'folder is not writable', not the run's OSError (exit 1)."""
    if not os.path.isdir(folder):
        pytest.skip(f"no {folder} here")
    path = write_study(SMALL)
    err = _store_refused(run_cli, tmp_path, path, "--store", f"{folder}/regimemap-test-store")
    assert f"folder '{folder}' is not writable" in err


def test_a_store_that_accepts_no_file_exits_2(run_cli, tmp_path, write_study, monkeypatch):
    """An existing store (or, by default, the study's folder) that accepts no new file: exit 2
    naming --store; with --resume an existing store is only read, and is not asked to."""
    path = write_study(SMALL)
    store = tmp_path / "s"
    assert run_cli(["study", str(path), "--jobs", "1", "-q", "--store", str(store)]).code == 0
    real_access = os.access
    refused: set[Path] = {store}
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: False if Path(p) in refused
                        else real_access(p, mode, **kw))
    assert f"folder '{store}' is not writable" in _store_refused(run_cli, tmp_path, path, "--store", str(store))
    resumed = run_cli(["study", str(path), "--jobs", "1", "-q", "--resume", "--store", str(store)])
    assert resumed.code == 0, resumed.output
    refused.clear()
    refused.add(tmp_path)  # the store accepts new files, its folder (the new run's, beside it) none
    err = _store_refused(run_cli, tmp_path, path, "--store", str(store), "--overwrite")
    assert f"folder '{tmp_path}' is not writable" in err
    err = _store_refused(run_cli, tmp_path, path)
    assert f"(the default store, '{tmp_path / 'study.store'}': give --store DIR)" in err


def test_a_bad_study_file_exits_2_naming_its_line(run_cli, tmp_path, write_study):
    path = write_study(SMALL.replace('name = "b"', 'name = "a"'))
    out = run_cli(["study", str(path)])
    assert out.code == 2
    assert f"{path}, line 14: [[section]] name = 'a': a duplicate" in out.stderr
    assert out.stderr.count("\n") == 1 and not (tmp_path / "study.store").exists()


def test_a_store_is_refused_without_resume_and_a_changed_study_leaves_it_untouched(run_cli, tmp_path,
                                                                                   write_study):
    path = write_study(SMALL)
    assert run_cli(["study", str(path), "--jobs", "1", "-q"]).code == 0
    store = tmp_path / "study.store"
    before = {p: p.read_bytes() for p in store.rglob("*") if p.is_file()}
    out = run_cli(["study", str(path), "--jobs", "1"])
    assert out.code == 2 and "give --resume to finish" in out.stderr
    path.write_text(SMALL.replace("rate = 0.01", "rate = 0.02"))
    out = run_cli(["study", str(path), "--jobs", "1", "--resume"])
    assert out.code == 2 and "the store of another study" in out.stderr and out.stderr.count("\n") == 1
    assert {p: p.read_bytes() for p in store.rglob("*") if p.is_file()} == before


def _command(*args: str) -> list[str]:
    return [sys.executable, "-m", "regimemap", *args]


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_the_example_runs(tmp_path):
    example = subprocess.run(_command("study", "--example"), capture_output=True, text=True, check=True)
    path = tmp_path / "breakwater.toml"
    path.write_text(example.stdout)
    run = subprocess.run(_command("study", str(path), "--jobs", "2", "-o", str(tmp_path / "t.csv")),
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    rows = list(csv.DictReader((tmp_path / "t.csv").open()))
    assert len({r["section"] for r in rows}) == 3 and len({r["scenario"] for r in rows}) == 2
    head = [r for r in rows if r["section"] == "head 18 m"]
    assert all(r["required_width"] for r in head)


KILLED = (study_head(8, 1500)
          + "".join(section_table(f"s{i}", 10.0 * i, f"depth = {8.0 + i}", *SITE[1:], "width = 13.0")
                    for i in range(5))
          + scenario_table("today") + scenario_table("rise", "sea_level_rise = { 50 = 1.0 }"))


@pytest.mark.subprocess
@pytest.mark.slow
def test_kill_9_halfway_then_resume_gives_the_same_bytes(tmp_path, write_study):
    path = write_study(KILLED)
    whole = subprocess.run(_command("study", str(path), "--jobs", "1", "-q", "--store", str(tmp_path / "w"),
                                    "-o", str(tmp_path / "whole.csv")), capture_output=True, text=True)
    assert whole.returncode == 0, whole.stderr
    store = tmp_path / "k"
    proc = subprocess.Popen(_command("study", str(path), "--jobs", "2", "-q", "--store", str(store),
                                     "-o", str(tmp_path / "resumed.csv")),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and len(list((store / "tasks").glob("*.json"))) < 3:
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)  # the command and its workers, at once
    proc.wait()
    done = len(list((store / "tasks").glob("*.json")))
    assert 3 <= done < 10, done
    assert not (tmp_path / "resumed.csv").exists()
    resumed = subprocess.run(_command("study", str(path), "--jobs", "2", "-q", "--store", str(store), "--resume",
                                      "-o", str(tmp_path / "resumed.csv")), capture_output=True, text=True)
    assert resumed.returncode == 0, resumed.stderr
    assert (tmp_path / "resumed.csv").read_bytes() == (tmp_path / "whole.csv").read_bytes()


@pytest.mark.render
def test_the_netcdf_table_and_the_figures(run_cli, tmp_path, write_study):
    pytest.importorskip("xarray")
    import xarray as xr

    path = write_study(SMALL)
    out = run_cli(["study", str(path), "--jobs", "1", "-q", "-o", str(tmp_path / "t.nc"),
                   "-o", str(tmp_path / "esd.svg")])
    assert out.code == 0, out.output
    assert out.stdout.split() == [str(tmp_path / "t.nc"), str(tmp_path / "esd.svg")]
    with xr.open_dataset(tmp_path / "t.nc") as ds:
        assert ds.sizes["row"] == 6 and ds.sizes["year"] == 50
        csv_out = run_cli(["study", str(path), "--resume", "-q", "-o", str(tmp_path / "t.csv")])
        rows = list(csv.DictReader((tmp_path / "t.csv").open()))
        assert [float(r["expected_sliding"]) for r in rows] == ds["expected_sliding"].values.tolist()
    assert csv_out.code == 0
    assert (tmp_path / "esd.svg").read_text().lstrip().startswith("<?xml")
    years = run_cli(["study", str(path), "--resume", "-q", "--figure", "years", "--section", "b",
                     "-o", str(tmp_path / "years.svg")])
    assert years.code == 0, years.output
    assert (tmp_path / "years.svg").stat().st_size > 1000


def _quiet_table(run_cli, path: Path, *args: str):
    return run_cli(["study", str(path), "--jobs", "1", *args])


def test_with_o_quiet_prints_only_the_files(run_cli, tmp_path, write_study):
    path = write_study(SMALL)
    out = _quiet_table(run_cli, path, "-q", "-o", str(tmp_path / "t.csv"))
    assert out.code == 0, out.output
    assert out.stdout.strip() == str(tmp_path / "t.csv")


def test_millimetres_for_metres_exit_2_in_one_line_before_any_store(run_cli, tmp_path, write_study):
    path = write_study(SMALL.replace("rate = 0.01", "sea_level_rise = { 50 = 1000 }"))
    out = _quiet_table(run_cli, path, "-o", str(tmp_path / "t.csv"))
    assert out.code == 2, out.output
    assert f"{path}, line 23: [[scenario]] 'rise' sea_level_rise: service year 1 = 20 m puts the crest of " \
           "section 'a' under water" in out.stderr
    assert out.stderr.count("\n") == 1 and "RuntimeWarning" not in out.stderr and out.stdout == ""
    assert not (tmp_path / "study.store").exists() and not (tmp_path / "t.csv").exists()


def test_a_falling_sea_level_is_warned_on_stderr(run_cli, write_study):
    path = write_study(SMALL.replace("rate = 0.01", "sea_level_rise = { 20 = 0.5, 50 = 0.2 }"))
    out = _quiet_table(run_cli, path, "-q")
    assert out.code == 0, out.output
    warnings = [line for line in out.stderr.splitlines() if line.startswith("regimemap: warning:")]
    assert len(warnings) == 1 and "the sea level falls, from 0.5 m (service year 20)" in warnings[0]
    assert "falls" not in out.stdout


def test_a_non_finite_result_is_an_error_and_the_tasks_stored_stay(run_cli, tmp_path, write_study,
                                                                   monkeypatch):
    import regimemap.lifetime.parallel as parallel

    real = parallel.run_chunks

    def broken(caissons, model, chunks, **kw):  # the sliding of the scenario with a trend: inf
        out = real(caissons, model, chunks, **kw)
        if model.trend is None:
            return out
        sliding = out.sliding.copy()
        sliding[:, 0] = np.inf
        return type(out)(**{**out.__dict__, "sliding": sliding})

    monkeypatch.setattr(parallel, "run_chunks", broken)
    path = write_study(SMALL)
    out = _quiet_table(run_cli, path, "-q", "-o", str(tmp_path / "t.csv"))
    assert out.code == 1, out.output
    assert out.stderr.strip() == (f"regimemap: error: {path}: section 'a', scenario 'rise', width 12 m: the "
                                  "lifetime sliding is not finite (inf in 1 of 100 values, nan in 0): the model "
                                  "is outside the range of its formulas; nothing is written")
    assert out.stdout == "" and not (tmp_path / "t.csv").exists()
    tasks = sorted(p.name for p in (tmp_path / "study.store" / "tasks").iterdir())
    assert tasks == ["s0000-c00-r0000.json"]
    assert all(np.isfinite(json.loads((tmp_path / "study.store" / "tasks" / t).read_text())["esd"]).all()
               for t in tasks)
    monkeypatch.setattr(parallel, "run_chunks", real)
    resumed = _quiet_table(run_cli, path, "-q", "--resume", "-o", str(tmp_path / "t.csv"))
    assert resumed.code == 0, resumed.output
    whole = _quiet_table(run_cli, path, "-q", "--store", str(tmp_path / "w"), "-o", str(tmp_path / "w.csv"))
    assert whole.code == 0 and (tmp_path / "t.csv").read_bytes() == (tmp_path / "w.csv").read_bytes()


def test_overwrite_runs_the_tour_again_and_replaces_only_a_study_store(run_cli, tmp_path, write_study):
    path = write_study(SMALL)
    store = tmp_path / "study.store"
    assert _quiet_table(run_cli, path, "-q").code == 0
    again = _quiet_table(run_cli, path, "-q")
    assert again.code == 2 and "give --resume to finish" in again.stderr and "--overwrite" in again.stderr
    (store / "tasks" / "stale.json").write_text("{}")  # not a task of this run: gone after --overwrite
    first = (store / "tasks" / "s0000-c00-r0000.json").read_bytes()
    out = _quiet_table(run_cli, path, "-q", "--overwrite")
    assert out.code == 0, out.output
    assert sorted(p.name for p in (store / "tasks").iterdir()) == [
        "s0000-c00-r0000.json", "s0000-c01-r0000.json", "s0001-c00-r0000.json", "s0001-c01-r0000.json"]
    assert (store / "tasks" / "s0000-c00-r0000.json").read_bytes() == first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["goda.toml", "study.store", "study.toml"]
    other = tmp_path / "notes"
    other.mkdir()
    (other / "mine.txt").write_text("keep")
    refused = _quiet_table(run_cli, path, "-q", "--overwrite", "--store", str(other))
    assert refused.code == 2 and "not a study store" in refused.stderr and refused.stderr.count("\n") == 1
    assert [p.name for p in other.iterdir()] == ["mine.txt"]


def test_an_interrupted_overwrite_leaves_the_old_store_whole(run_cli, tmp_path, write_study,
                                                            monkeypatch):
    import regimemap.study.run as study

    path = write_study(SMALL)
    store = tmp_path / "study.store"
    assert _quiet_table(run_cli, path, "-q").code == 0
    before = {p: p.read_bytes() for p in store.rglob("*") if p.is_file()}
    calls = []

    def interrupted(task):
        calls.append(task)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return study.run_task(task)

    monkeypatch.setattr(study, "_serial", lambda todo: ((n, interrupted(t)) for n, t in todo))
    out = _quiet_table(run_cli, path, "-q", "--overwrite")
    assert out.code == 130, out.output
    assert {p: p.read_bytes() for p in store.rglob("*") if p.is_file()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["goda.toml", "study.store", "study.toml"]


@pytest.mark.parametrize(("module", "args", "says"), [
    ("distributed", ["--scheduler", "local"], "Invalid value for '--scheduler': --scheduler needs Dask's "
                                              "distributed package: pip install 'regimemap[cluster]'"),
    ("xarray", ["-o", "t.csv", "-o", "bw.nc"], "pip install 'regimemap[metocean]'"),
])
def test_a_missing_extra_exits_2_before_anything_is_made(run_cli, tmp_path, write_study, monkeypatch, module,
                                                         args, says):
    monkeypatch.setitem(sys.modules, module, None)  # as if not installed: import and find_spec fail
    path = write_study(SMALL)
    args = [str(tmp_path / a) if a.endswith((".csv", ".nc")) else a for a in args]
    out = run_cli(["study", str(path), *args])
    assert out.code == 2, out.output
    assert says in out.stderr and out.stderr.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["goda.toml", "study.toml"]


def test_check_prints_a_line_per_section_and_scenario_and_exits_1_on_a_fail(run_cli, tmp_path,
                                                                            write_study):
    path = write_study(SMALL)
    out = _quiet_table(run_cli, path, "-q", "--check", "-o", str(tmp_path / "t.csv"))
    assert out.code == 1, out.output
    lines = out.stdout.splitlines()
    assert lines[0] == "requirements:" and lines[-1] == str(tmp_path / "t.csv") and len(lines) == 7
    rows = {(r["section"], r["scenario"], float(r["width"])): float(r["expected_sliding"])
            for r in csv.DictReader((tmp_path / "t.csv").open())}
    assert lines[1:6] == [
        f"  PASS  a / today: the ESD of the design's climate at 12 m: {rows['a', 'today', 12.0]:.4g} m <= 0.1 m",
        f"  PASS  a / rise: the ESD of the design's climate at 12 m: {rows['a', 'rise', 12.0]:.4g} m <= 0.1 m",
        "  FAIL  b / today: the ESD of the design's climate at 16 m, the widest of 14, 16 m; none meets it: "
        f"{rows['b', 'today', 16.0]:.4g} m <= 0.1 m",
        "  FAIL  b / rise: the ESD of the design's climate at 16 m, the widest of 14, 16 m; none meets it: "
        f"{rows['b', 'rise', 16.0]:.4g} m <= 0.1 m",
        "  verdict: FAIL (2 of 4 requirements not met)"]
    assert rows["b", "today", 16.0] > 0.1 > rows["a", "rise", 12.0]
    # the narrowest width that meets the section's own target ([lifetime] target, overridden)
    lax = SMALL.replace('widths = [14.0, 16.0]', 'widths = [14.0, 16.0]\nlifetime.target = 1.0')
    ok = _quiet_table(run_cli, write_study(lax), "--check", "--overwrite", "--json")
    assert ok.code == 1, ok.output
    data = json.loads(ok.stdout)
    assert [(c["section"], c["scenario"], c["pass"]) for c in data["checks"]] == [
        ("a", "today", True), ("a", "rise", True), ("b", "today", True), ("b", "rise", False)]
    assert data["checks"][2]["basis"] == ("the ESD of the design's climate at 16 m, the narrowest of 14, 16 m "
                                          "that meets it") and data["checks"][2]["required"] == 1.0
    none = _quiet_table(run_cli, write_study(SMALL.replace('widths = [14.0, 16.0]', 'widths = [30.0]')),
                        "--check", "--overwrite", "-q")
    assert none.code == 0, none.output
    assert none.stdout.count("  PASS  ") == 4 and "verdict: PASS (every requirement met)" in none.stdout


def test_the_study_is_in_the_help_of_regimemap_and_its_help_says_what_it_prints(run_cli):
    top = run_cli(["--help"])
    assert top.code == 0
    assert "regimemap study --example > breakwater.toml" in top.stdout
    assert "regimemap study breakwater.toml --jobs 2 -o table.csv" in top.stdout
    own = run_cli(["study", "--help"])
    flat = " ".join(own.stdout.split())
    assert "also with -o, unless --quiet" in flat and "--overwrite" in flat and "--check" in flat


def test_a_stored_task_that_is_not_finite_is_refused_not_printed(run_cli, tmp_path, write_study):
    path = write_study(SMALL)
    assert _quiet_table(run_cli, path, "-q").code == 0
    task = tmp_path / "study.store" / "tasks" / "s0001-c00-r0000.json"
    task.write_text(task.read_text().replace('"esd":[', '"esd":[Infinity,', 1))
    out = _quiet_table(run_cli, path, "-q", "--resume")
    assert out.code == 1 and out.stdout == ""
    assert out.stderr.strip() == (f"regimemap: error: {task}: the stored esd is not finite (inf in 1 of 3 values, "
                                  "nan in 0): the model is outside the range of its formulas; nothing is written")
