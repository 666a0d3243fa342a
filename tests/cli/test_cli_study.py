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

import pytest

from regimemap.io.design import example_design_text
from regimemap.io.study_table import STUDY_COLUMNS

SMALL = """seed = 4
trials = 100
base = "goda.toml"

[[section]]
name = "a"
chainage = 0.0
depth = 8.0
armour_depth = 4.5
base_depth = 5.5
width = 12.0

[[section]]
name = "b"
chainage = 50.0
widths = [14.0, 16.0]

[[scenario]]
name = "today"

[[scenario]]
name = "rise"
rate = 0.01
"""


def _small(tmp_path: Path, text: str = SMALL) -> Path:
    (tmp_path / "goda.toml").write_text(example_design_text())
    path = tmp_path / "study.toml"
    path.write_text(text)
    return path


def test_the_table_the_csv_and_the_json(run_cli, tmp_path):
    path = _small(tmp_path)
    out = run_cli(["study", str(path), "--jobs", "1", "-o", str(tmp_path / "t.csv")])
    assert out.code == 0, out.output
    assert out.stdout.strip() == str(tmp_path / "t.csv")
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
    (["STUDY", "-o", "t.xlsx"], "the table is written as .csv or .nc"),
    (["STUDY", "--scheduler", "tcp://h:1", "--jobs", "2"], "--jobs and --scheduler ADDRESS exclude"),
    (["STUDY", "--section", "nowhere"], "'nowhere' is not a section of the study; accepted: a, b"),
    (["STUDY", "--figure", "map"], "Invalid value for '--figure'"),
    (["STUDY", "--scheduler", "nowhere"], "scheduler must be the address of a Dask scheduler"),
])
def test_usage_errors_exit_2_in_one_line(run_cli, tmp_path, args, says):
    path = _small(tmp_path)
    (tmp_path / "x.toml").write_text("")
    args = [str(path) if a == "STUDY" else str(tmp_path / a) if a in ("x.toml", "t.xlsx") else a for a in args]
    out = run_cli(["study", *args] if "--jobs" in args else ["study", *args, "--jobs", "1"])
    assert out.code == 2, out.output
    assert says in out.stderr and out.stderr.count("\n") == 1


def test_a_bad_study_file_exits_2_naming_its_line(run_cli, tmp_path):
    path = _small(tmp_path, SMALL.replace('name = "b"', 'name = "a"'))
    out = run_cli(["study", str(path)])
    assert out.code == 2
    assert f"{path}, line 14: [[section]] name = 'a': a duplicate" in out.stderr
    assert out.stderr.count("\n") == 1 and not (tmp_path / "study.store").exists()


def test_a_store_is_refused_without_resume_and_a_changed_study_leaves_it_untouched(run_cli, tmp_path):
    path = _small(tmp_path)
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


KILLED = """seed = 8
trials = 1500
base = "goda.toml"
""" + "".join(f"""
[[section]]
name = "s{i}"
chainage = {10.0 * i}
depth = {8.0 + i}
armour_depth = 4.5
base_depth = 5.5
width = 13.0
""" for i in range(5)) + """
[[scenario]]
name = "today"

[[scenario]]
name = "rise"
sea_level_rise = { 50 = 1.0 }
"""


@pytest.mark.subprocess
@pytest.mark.slow
def test_kill_9_halfway_then_resume_gives_the_same_bytes(tmp_path):
    path = _small(tmp_path, KILLED)
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
def test_the_netcdf_table_and_the_figures(run_cli, tmp_path):
    pytest.importorskip("xarray")
    import xarray as xr

    path = _small(tmp_path)
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
