"""``regimemap classify`` through click's CliRunner."""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys

import pytest
from click.testing import CliRunner

from regimemap.cli import cli
from regimemap.maps.file_points import DesignPoint
from regimemap.maps.query import query_point, query_points
from regimemap.maps.record_tables import CSV_COLUMNS, result_json


def run(*args: str):
    return CliRunner().invoke(cli, list(args))


@pytest.mark.parametrize("flag", ["-h", "--help"])
def test_help_has_examples(flag):
    r = run("classify", flag)
    assert r.exit_code == 0
    assert "Examples:" in r.output
    assert "regimemap classify --gamma 3 --kprime 0.4 --k 0.5 --mu 0.8" in r.output
    assert "--points" in r.output and "--json" in r.output


def test_text_output():
    r = run("classify", "--gamma", "3", "--kprime", "-0.6", "--k", "3.5", "--mu", "2.3")
    assert r.exit_code == 0, r.output
    assert "mode      SL  (slide)" in r.output
    assert "admissible (solver): SL, RO, SRO-" in r.output
    assert "Section 4.7" in r.output
    assert "margin" in r.output and "-> RO" in r.output


def test_json_output_equals_library():
    r = run("classify", "--gamma", "3", "--kprime", "0.4", "--k", "0.5", "--mu", "0.8", "--json")
    assert r.exit_code == 0, r.output
    d = json.loads(r.output)
    want = query_point(0.5, 0.8, 3.0, 0.4).as_dict()
    assert d == json.loads(json.dumps(result_json(query_point(0.5, 0.8, 3.0, 0.4))))
    # numbers for people: the library's values to 12 significant digits
    for key in ("fx", "fy", "xi", "xdd", "ydd", "thdd"):
        assert d[key] == pytest.approx(want[key], rel=1e-11, abs=1e-300)
        assert len(repr(d[key]).lstrip("-").replace(".", "").lstrip("0")) <= 13
    for key in ("mode", "fx", "fy", "xi", "xdd", "ydd", "thdd", "slip", "case", "margin",
                "admissible"):
        assert key in d
    assert d["mode"] == "RO" and d["slip"] is None


@pytest.mark.parametrize("args,param", [
    (("--gamma", "0", "--kprime", "0", "--k", "1", "--mu", "1"), "--gamma"),
    (("--gamma", "abc", "--kprime", "0", "--k", "1", "--mu", "1"), "--gamma"),
    (("--gamma", "1", "--kprime", "1.5", "--k", "1", "--mu", "1"), "--kprime"),
    (("--gamma", "1", "--kprime", "0", "--k", "-1", "--mu", "1"), "--k"),
    (("--gamma", "1", "--kprime", "0", "--k", "1", "--mu", "nan"), "--mu"),
    (("--gamma", "1", "--kprime", "0", "--k", "1"), "--mu"),
    (("--kprime", "0", "--k", "1", "--mu", "1"), "--gamma"),
])
def test_bad_input_exits_2_naming_parameter(args, param):
    r = run("classify", *args)
    assert r.exit_code == 2, r.output
    assert param in r.output


def test_kprime_range_in_message():
    r = run("classify", "--gamma", "1", "--kprime", "2", "--k", "1", "--mu", "1")
    assert r.exit_code == 2 and "[-1, 1]" in r.output
    r = run("classify", "--gamma", "1", "--kprime", "0", "--k", "-1", "--mu", "1")
    assert r.exit_code == 2 and "[0, 1e+100]" in r.output


@pytest.fixture()
def points_csv(tmp_path):
    path = tmp_path / "caissons.csv"
    path.write_text('name,k,mu,gamma,kprime\n'
                    'caisson-A,0.5,0.8,,\n'
                    'caisson-B,3.5,2.3,3,-0.6\n'
                    '"quay, east",0.1,0.05,2,\n')
    return path


def test_points_csv_to_stdout(points_csv):
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0.4")
    assert r.exit_code == 0, r.output
    rows = list(csv.DictReader(io.StringIO(r.output)))
    assert list(rows[0]) == list(CSV_COLUMNS)
    assert [row["name"] for row in rows] == ["caisson-A", "caisson-B", "quay, east"]
    assert [row["mode"] for row in rows] == ["RO", "SL", "SL"]
    assert [(row["gamma"], row["kprime"]) for row in rows] == [
        ("3.0", "0.4"), ("3.0", "-0.6"), ("2.0", "0.4")]
    want = query_points([DesignPoint(0.5, 0.8, "caisson-A")], gamma=3.0, kprime=0.4)[0]
    assert float(rows[0]["fx"]) == pytest.approx(want.fx, rel=1e-11)
    assert float(rows[0]["thdd"]) == pytest.approx(want.thdd, rel=1e-11)
    assert rows[1]["admissible"] == "SL RO SRO-"


def test_points_to_json_file(points_csv, tmp_path):
    out = tmp_path / "res.json"
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0.4",
            "-o", str(out))
    assert r.exit_code == 0, r.output
    d = json.loads(out.read_text())
    assert d["count"] == 3
    assert [p["name"] for p in d["points"]] == ["caisson-A", "caisson-B", "quay, east"]
    assert d["points"][1]["chosen_by"] == "Section 4.7"


def test_points_json_flag_and_csv_file(points_csv, tmp_path):
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0.4", "--json")
    assert r.exit_code == 0 and json.loads(r.output)["count"] == 3
    out = tmp_path / "res.csv"
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0.4",
            "-o", str(out))
    assert r.exit_code == 0
    assert out.read_text().startswith("name,k,mu,gamma,kprime,case,mode")


def test_points_missing_default_is_usage_error(points_csv):
    r = run("classify", "--points", str(points_csv), "--gamma", "3")
    assert r.exit_code == 2
    assert "--kprime is required" in r.output and "caisson-A" in r.output


def test_points_with_own_parameters_need_no_defaults(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("k,mu,gamma,kprime\n0.5,0.8,3,0.4\n")
    r = run("classify", "--points", str(path))
    assert r.exit_code == 0, r.output
    assert ",RO," in r.output


def test_bad_points_file(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("k,mu\n1,x\n")
    r = run("classify", "--points", str(bad), "--gamma", "1", "--kprime", "0")
    assert r.exit_code == 2 and "--points" in r.output and "line 2" in r.output
    r = run("classify", "--points", str(tmp_path / "nope.csv"), "--gamma", "1", "--kprime", "0")
    assert r.exit_code == 2 and "--points" in r.output
    nocol = tmp_path / "nocol.csv"
    nocol.write_text("k,friction\n1,1\n")
    r = run("classify", "--points", str(nocol), "--gamma", "1", "--kprime", "0")
    assert r.exit_code == 2 and "mu" in r.output


def test_point_and_points_exclusive(points_csv):
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0",
            "--k", "1", "--mu", "1")
    assert r.exit_code == 2 and "--points" in r.output
    r = run("classify", "--gamma", "3", "--kprime", "0", "--k", "1", "--mu", "1", "-o", "x.csv")
    assert r.exit_code == 2 and "--output" in r.output


def test_output_folder_missing(points_csv, tmp_path):
    r = run("classify", "--points", str(points_csv), "--gamma", "3", "--kprime", "0",
            "-o", str(tmp_path / "no" / "x.csv"))
    assert r.exit_code == 2 and "--output" in r.output


@pytest.mark.subprocess
def test_no_matplotlib_at_import_or_in_classify():
    code = (
        "import sys\n"
        "import regimemap.cli.query, regimemap.cli.export, regimemap.cli.atlas\n"
        "assert 'matplotlib' not in sys.modules, 'imported at import time'\n"
        "from click.testing import CliRunner\n"
        "from regimemap.cli import cli\n"
        "r = CliRunner().invoke(cli, ['classify', '--gamma', '3', '--kprime', '0.4', "
        "'--k', '0.5', '--mu', '0.8', '--json'])\n"
        "assert r.exit_code == 0, r.output\n"
        "assert 'matplotlib' not in sys.modules, 'imported by classify'\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
