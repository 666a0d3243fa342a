"""``regimemap climate``: the report, the JSON keys, the figures, and bad input as one line, exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

DATA = Path(__file__).parent / "data"
EXCERPT = str(DATA / "ndbc44007_1996_hs_tz.txt.gz")
OREGON = str(DATA / "oregon_hindcast_1990_hs.csv.gz")

JSON_KEYS = {"record", "method", "threshold", "gap_hours", "storms", "rate_per_year", "distribution",
             "parameters", "return_values", "confidence", "bootstrap", "seed", "warnings"}
RECORD_KEYS = {"start", "end", "years", "coverage", "missing", "flagged"}


def ok(r):
    assert "Traceback" not in r.output, r.output
    assert r.code == 0, r.output
    return r


def failed(r, *parts: str) -> str:
    assert "Traceback" not in r.output, r.output
    assert r.code == 2, (r.code, r.output)
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    for part in parts:
        assert part in lines[0], (part, lines[0])
    assert r.stdout == ""
    return lines[0]


def test_json_keys_and_bands(run_cli):
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--bootstrap", "40", "--seed", "3", "--json"]))
    obj = json.loads(r.stdout)
    assert JSON_KEYS <= set(obj) and RECORD_KEYS <= set(obj["record"])
    assert obj["method"] == "pot" and obj["distribution"] == "gpd" and obj["gap_hours"] == 48
    assert [v["period"] for v in obj["return_values"]] == [10, 50, 100]
    for v in obj["return_values"]:
        assert v["lower"] <= v["upper"]
    assert obj["bootstrap"] == 40 and obj["seed"] == 3
    if obj["bootstrap_fitted"] < 38:
        assert any("bootstrap replicates had too few values" in w for w in obj["warnings"])
    assert obj["rate_per_year"] == pytest.approx(obj["storms"] / obj["record"]["years"], rel=1e-9)
    again = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--bootstrap", "40", "--seed", "3", "--json"]))
    assert again.stdout == r.stdout


def test_text_report_annual_maxima_needs_years(run_cli):
    failed(run_cli(["climate", OREGON, "--method", "annual-maxima"]), "annual maxima", "at least 5 years")
    r = ok(run_cli(["climate", OREGON, "--threshold", "4.5", "--gap", "24", "--bootstrap", "20"]))
    assert "peaks over threshold: u = 4.500 m (given), gap 24 h" in r.stdout
    assert "90 % band" in r.stdout and "50 years" in r.stdout


@pytest.mark.render
def test_figures_written(run_cli, tmp_path):
    out, diag = tmp_path / "rl.png", tmp_path / "diag.svg"
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--bootstrap", "20", "-o", str(out),
                    "--diagnostics", str(diag)]))
    assert out.stat().st_size > 10000 and diag.read_text().startswith("<?xml")
    assert str(out) in r.stdout


@pytest.mark.parametrize(("args", "parts"), [
    (["--gap", "0"], ["--gap"]),
    (["--gap", "-3"], ["--gap"]),
    (["--threshold", "30"], ["threshold 30 m is at or above every height"]),
    (["--threshold", "abc"], ["--threshold", "percentage"]),
    (["--threshold", "6.5"], ["a fit needs at least 10"]),
    (["--method", "annual-maxima", "--distribution", "gpd"], ["'gpd' does not fit annual-maxima"]),
    (["--return-periods", "10,x"], ["--return-periods"]),
    (["--confidence", "1.5"], ["--confidence"]),
    (["-o", "x.txt"], ["unknown file suffix .txt in 'x.txt'"]),
])
def test_bad_options(run_cli, args, parts):
    failed(run_cli(["climate", EXCERPT, *args]), *parts)


def test_bad_records(run_cli, tmp_path):
    short = tmp_path / "short.csv"
    short.write_text("time,hs\n" + "".join(f"2000-01-{d:02d}T00:00,{1 + d / 10}\n" for d in range(1, 29)))
    failed(run_cli(["climate", str(short)]), "needs at least 1 year")
    broken = tmp_path / "broken.csv"
    broken.write_text("time,hs\n2000-01-01T00:00,1.0\n2000-01-01T01:00,x\n")
    failed(run_cli(["climate", str(broken)]), "broken.csv, line 3, column 'hs': cannot read 'x' as a number")
    nohs = tmp_path / "nohs.csv"
    nohs.write_text("time,wind\n2000-01-01T00:00,1.0\n")
    failed(run_cli(["climate", str(nohs)]), "no significant wave height column")
    missing = tmp_path / "missing.csv"
    missing.write_text("time,hs\n2000-01-01T00:00,\n2000-01-01T01:00,99.00\n")
    failed(run_cli(["climate", str(missing)]), "every significant wave height is missing")
    out = tmp_path / "never.png"
    failed(run_cli(["climate", str(broken), "-o", str(out)]), "cannot read 'x'")
    assert not out.exists()


def test_strict_refuses_warnings(run_cli, tmp_path):
    import numpy as np

    rng = np.random.default_rng(1)
    t = np.datetime64("2000-01-01T00", "h") + np.arange(2 * 8784)
    hs = 1.5 + np.sin(np.arange(t.size) / 40.0) ** 8 * (2.0 + 3.0 * rng.random(t.size) ** 4)
    hs = np.convolve(hs, np.ones(5) / 5, mode="same")
    hs[1000] = 3.0 * max(hs[999], hs[1001]) + 2.0  # an isolated spike
    rec = tmp_path / "spiky.csv"
    rec.write_text("time,hs\n" + "".join(f"{a},{b:.3f}\n" for a, b in zip(t.astype(str), hs)))
    r = ok(run_cli(["climate", str(rec), "--bootstrap", "0", "--threshold", "97%"]))
    assert "warning: 1 isolated spike(s) kept and flagged: 2000-02-11T16:00Z" in r.stdout
    failed(run_cli(["climate", str(rec), "--bootstrap", "0", "--threshold", "97%", "--strict"]),
           "isolated spike", "--strict refuses")
    r = ok(run_cli(["climate", str(rec), "--bootstrap", "0", "--threshold", "97%", "--drop-spikes", "--json"]))
    assert json.loads(r.stdout)["record"]["spikes_dropped"] is True
