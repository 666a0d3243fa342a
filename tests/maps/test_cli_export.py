"""``regimemap export`` through click's CliRunner."""

from __future__ import annotations

import csv
import json
import subprocess
import sys

import numpy as np
import pytest
from click.testing import CliRunner

from regimemap import Mode, classify
from regimemap.cli import cli


def run(*args: str):
    return CliRunner().invoke(cli, list(args))


@pytest.mark.parametrize("flag", ["-h", "--help"])
def test_help(flag):
    r = run("export", flag)
    assert r.exit_code == 0
    assert "Examples:" in r.output and "regimemap export --gamma 3 --kprime 0.4 -o map.npz" in r.output
    assert ".npz" in r.output and ".csv" in r.output and ".json" in r.output


def test_npz(tmp_path):
    out = tmp_path / "m.npz"
    r = run("export", "--gamma", "3", "--kprime", "-0.6", "--resolution", "64", "-o", str(out))
    assert r.exit_code == 0, r.output
    with np.load(out) as z:
        K, M = np.meshgrid(z["k"], z["mu"])
        assert z["mode"].shape == (64, 64)
        assert np.array_equal(z["mode"], classify(K, M, 3.0, -0.6))


def test_csv_with_extent(tmp_path):
    out = tmp_path / "m.csv"
    r = run("export", "--gamma", "2", "--kprime", "0.4", "--k-max", "3", "--mu-max", "2",
            "--resolution", "11", "-o", str(out))
    assert r.exit_code == 0, r.output
    rows = list(csv.DictReader(out.read_text(encoding="utf-8").splitlines()))
    assert len(rows) == 121
    assert max(float(r["k"]) for r in rows) == 3.0 and max(float(r["mu"]) for r in rows) == 2.0
    for row in rows:
        code = classify(float(row["k"]), float(row["mu"]), 2.0, 0.4)
        assert row["mode"] == Mode(int(code)).label


def test_json_and_format_override(tmp_path):
    out = tmp_path / "geometry.txt"
    r = run("export", "--gamma", "3", "--kprime", "0.9", "--format", "json", "-o", str(out))
    assert r.exit_code == 0, r.output
    d = json.loads(out.read_text())
    assert d["case"]["value"] == "2/3" and "mu_star" in d["curves"]


@pytest.mark.parametrize("args,param", [
    (("--gamma", "3", "--kprime", "0.4", "-o", "m.png"), "--output"),
    (("--gamma", "3", "--kprime", "0.4", "-o", "m"), "--output"),
    (("--gamma", "3", "--kprime", "0.4", "--resolution", "5001", "-o", "m.npz"), "--resolution"),
    (("--gamma", "3", "--kprime", "0.4", "--resolution", "1", "-o", "m.npz"), "--resolution"),
    (("--gamma", "3", "--kprime", "0.4", "--resolution", "2.5", "-o", "m.npz"), "--resolution"),
    (("--gamma", "3", "--kprime", "0.4", "--k-max", "-1", "-o", "m.npz"), "--k-max"),
    (("--gamma", "3", "--kprime", "0.4", "--mu-max", "0", "-o", "m.npz"), "--mu-max"),
    (("--gamma", "3", "--kprime", "-2", "-o", "m.npz"), "--kprime"),
    (("--gamma", "3", "--kprime", "0.4"), "--output"),
    (("--kprime", "0.4", "-o", "m.npz"), "--gamma"),
])
def test_bad_input_exits_2(tmp_path, monkeypatch, args, param):
    monkeypatch.chdir(tmp_path)
    r = run("export", *args)
    assert r.exit_code == 2, r.output
    assert param in r.output
    assert list(tmp_path.iterdir()) == []


def test_resolution_message_names_range(tmp_path):
    r = run("export", "--gamma", "3", "--kprime", "0.4", "--resolution", "99999", "-o",
            str(tmp_path / "m.npz"))
    assert r.exit_code == 2 and "[2, 5000]" in r.output


def test_missing_folder(tmp_path):
    r = run("export", "--gamma", "3", "--kprime", "0.4", "-o", str(tmp_path / "no" / "m.npz"))
    assert r.exit_code == 2 and "--output" in r.output and "does not exist" in r.output


@pytest.mark.subprocess
def test_export_imports_no_matplotlib(tmp_path):
    code = (
        "import sys\n"
        "from click.testing import CliRunner\n"
        "from regimemap.cli import cli\n"
        f"r = CliRunner().invoke(cli, ['export', '--gamma', '3', '--kprime', '-0.6', '-o', "
        f"{str(tmp_path / 'm.json')!r}])\n"
        "assert r.exit_code == 0, r.output\n"
        "assert 'matplotlib' not in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
