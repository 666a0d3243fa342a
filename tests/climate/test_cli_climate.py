"""``regimemap climate``: the report, the JSON keys, the figures, and bad input as one line, exit 2."""

from __future__ import annotations

import gzip
import json
from pathlib import Path

import pytest

DATA = Path(__file__).parent / "data"
EXCERPT = str(DATA / "ndbc44007_1996_hs_tz.txt.gz")
OREGON = str(DATA / "oregon_hindcast_1990_hs.csv.gz")

JSON_KEYS = {"record", "method", "threshold", "gap_hours", "storms", "rate_per_year", "distribution",
             "parameters", "return_values", "confidence", "interval", "replicates", "replicates_fitted", "seed",
             "warnings"}
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


@pytest.mark.slow
def test_json_keys_and_bands(run_cli):
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--interval", "bootstrap", "--bootstrap", "40",
                    "--seed", "3", "--json"]))
    obj = json.loads(r.stdout)
    assert JSON_KEYS <= set(obj) and RECORD_KEYS <= set(obj["record"])
    assert obj["method"] == "pot" and obj["distribution"] == "gpd" and obj["gap_hours"] == 48
    assert [v["period"] for v in obj["return_values"]] == [10, 50, 100]
    for v in obj["return_values"]:
        assert v["lower"] <= v["upper"]
    assert obj["interval"] == "bootstrap" and obj["replicates"] == 40 and obj["seed"] == 3
    if obj["replicates_fitted"] < 38:
        assert any("bootstrap replicates had too few values" in w for w in obj["warnings"])
    assert obj["rate_per_year"] == pytest.approx(obj["storms"] / obj["record"]["years"], rel=1e-9)
    again = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--interval", "bootstrap", "--replicates", "40",
                        "--seed", "3", "--json"]))
    assert again.stdout == r.stdout  # --bootstrap is the old spelling of --replicates


@pytest.mark.slow
def test_the_default_replicates_are_enough_for_the_bootstrap_s_level(run_cli):
    # 200 by default; a 99 % bootstrap needs 4/(1 - 0.99) = 400, and the default gives them
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--interval", "bootstrap", "--confidence",
                    "0.99", "--json"]))
    assert json.loads(r.stdout)["replicates"] == 400
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--replicates", "0", "--json"]))
    assert json.loads(r.stdout)["replicates"] == 0
    r = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--json"]))
    assert json.loads(r.stdout)["replicates"] == 200
    failed(run_cli(["climate", EXCERPT, "--interval", "bootstrap", "--confidence", "0.99", "--replicates", "200"]),
           "'--replicates'", "at least 400")


def test_text_report_annual_maxima_needs_years(run_cli):
    failed(run_cli(["climate", OREGON, "--method", "annual-maxima"]), "annual maxima", "at least 5 years")
    r = ok(run_cli(["climate", OREGON, "--threshold", "4.5", "--gap", "24", "--bootstrap", "20"]))
    assert "peaks over threshold: u = 4.500 m (given), gap 24 h" in r.stdout
    assert "90 % interval" in r.stdout and "50 years" in r.stdout
    assert "posterior draws (a grid posterior" in r.stdout


@pytest.mark.render
@pytest.mark.deep
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


@pytest.mark.slow
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
    assert f"regimemap: warning: {rec}: 1 isolated spike(s) kept and flagged: 2000-02-11T16:00Z" in r.stderr
    assert "warning:" not in r.stdout and "isolated spike" not in r.stdout
    failed(run_cli(["climate", str(rec), "--bootstrap", "0", "--threshold", "97%", "--strict"]),
           "isolated spike", "--strict refuses")
    r = ok(run_cli(["climate", str(rec), "--bootstrap", "0", "--threshold", "97%", "--drop-spikes", "--json"]))
    assert json.loads(r.stdout)["record"]["spikes_dropped"] is True


@pytest.mark.slow
def test_interval_methods_endpoint_sensitivity_and_strict(run_cli):
    """The 1996 excerpt above its 97 % quantile: the GPD fit at its search bound (xi = -1.5) is warned
    with its value in the JSON's notices, --strict refuses it, and each method
    names itself."""
    args = ["climate", EXCERPT, "--threshold", "97%", "--replicates", "20", "--json"]
    obj = json.loads(ok(run_cli(args)).stdout)
    assert obj["interval"] == "posterior" and obj["replicates"] == 20
    assert obj["endpoint"] == pytest.approx(7.0083, abs=1e-3)  # the record's largest height
    bound = [n for n in obj["notices"] if "search bound" in n["message"]]
    assert len(bound) == 1 and bound[0]["quantity"] == "xi" and bound[0]["value"] < -1.0
    s = obj["threshold_sensitivity"]
    assert s["period"] == 50 and [r["quantile"] for r in s["rows"]] == [0.98, 0.985, 0.99, 0.993, 0.995, 0.997]
    assert all(r["lower"] is None or r["lower"] <= r["upper"] for r in s["rows"])
    line = failed(run_cli([*args[:-1], "--strict"]), "search bound")
    assert "--strict" in line
    text = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--interval", "profile", "--replicates", "20"]))
    assert "90 % profile-likelihood interval of the storm count and the peaks" in text.stdout
    assert "50-year value across thresholds (90 % profile interval)" in text.stdout
    failed(run_cli(["climate", EXCERPT, "--interval", "bayes"]), "--interval")


@pytest.mark.parametrize(("args", "option", "parts"), [
    (["--diagnostics", "nodir/d.png"], "'--diagnostics'", ["folder 'nodir' does not exist"]),
    (["--diagnostics", "d.txt"], "'--diagnostics'", ["unknown file suffix .txt in 'd.txt'"]),
    (["-o", "nodir/r.png"], "'--output'", ["folder 'nodir' does not exist"]),
    (["--threshold", "99.5"], "'--threshold'", ["threshold 99.5 m is above any sea state", "did you mean 99.5%?"]),
    (["--threshold", "30"], "'--threshold'", ["threshold 30 m is at or above every height"]),
    (["--threshold", "6.5"], "'--threshold'", ["a fit needs at least 10", "lower the threshold"]),
    (["--threshold", "99.99%"], "'--threshold'", ["a fit needs at least 10"]),
    (["--method", "annual-maxima", "--coverage", "1"], "'--coverage'", ["annual maxima: a fit needs"]),
    (["--time", "when"], "'--time'", ["no column 'when' for the time"]),
    (["--hs", "swell"], "'--hs'", ["no column 'swell' for the significant wave height"]),
    (["--period", "tp"], "'--period'", ["no column 'tp' for the period"]),
])
def test_each_error_names_its_option(run_cli, args, option, parts):
    line = failed(run_cli(["climate", OREGON if "--time" in args or "--hs" in args or "--period" in args
                           else EXCERPT, "--bootstrap", "0", *args]), option, *parts)
    assert "'RECORD'" not in line


@pytest.mark.parametrize(("args", "option", "parts"), [
    (["--gap", "nan"], "'--gap'", ["gap must be a finite number in (0, 8760], got 'nan'"]),
    (["--gap", "abc"], "'--gap'", ["(0, 8760]", "got 'abc' (not a number)"]),
    (["--gap", "0"], "'--gap'", ["(0, 8760]"]),
    (["--coverage", "nan"], "'--coverage'", ["coverage must be a finite number in (0, 1], got 'nan'"]),
    (["--coverage", "abc"], "'--coverage'", ["(0, 1]", "(not a number)"]),
    (["--confidence", "nan"], "'--confidence'", ["confidence must be a finite number in [0.5, 0.999]"]),
    (["--confidence", "inf"], "'--confidence'", ["[0.5, 0.999], got 'inf'"]),
    (["--shape", "nan"], "'--shape'", ["shape must be a finite number in [0.5, 5], got 'nan'"]),  # gpd too
    (["--distribution", "weibull", "--shape", "nan"], "'--shape'", ["[0.5, 5], got 'nan'"]),
    (["--shape", "x"], "'--shape'", ["[0.5, 5], got 'x' (not a number)"]),
    (["--interval", "bootstrap", "--replicates", "1"], "'--replicates'",
     ["replicates must be 0 (no interval) or at least 40 for a 90 % bootstrap interval", "got 1"]),
    (["--interval", "bootstrap", "--replicates", "39"], "'--replicates'", ["at least 40", "got 39"]),
    (["--interval", "bootstrap", "--confidence", "0.99", "--replicates", "200"], "'--replicates'",
     ["at least 400 for a 99 % bootstrap interval", "got 200"]),
    (["--period", "nope"], "'--period'", ["no column 'nope' for the period (columns: time, Hs, Tz"]),
    (["--hs", "WVHT"], "'--hs'", ["no column 'WVHT' for the significant wave height"]),
])
def test_each_number_and_column_names_its_own_option(run_cli, args, option, parts):
    """NaN, a word or too few bootstrap replicates: one line naming the option and its range (no
    longer '--distribution' or RECORD); a column the semicolon text lacks as on a CSV record."""
    line = failed(run_cli(["climate", EXCERPT, "--threshold", "99%", *args]), option, *parts)
    assert "'--distribution'" not in line and "'RECORD'" not in line


def test_enough_bootstrap_replicates_or_none_still_run(run_cli):
    for n in ("0", "40"):
        ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--interval", "bootstrap", "--replicates", n]))


def test_return_periods_sorted_each_once_and_told_apart(run_cli):
    out = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--replicates", "0", "--return-periods",
                      "100,10,10,1.0000001,1.0000002,10"])).stdout
    rows = out.split("return period", 1)[1].split("\n\n")[0].splitlines()[1:]
    assert [row.split(" years")[0].strip() for row in rows] == ["1.0000001", "1.0000002", "10", "100"], rows
    again = ok(run_cli(["climate", EXCERPT, "--threshold", "99%", "--replicates", "0"])).stdout
    assert "     10 years" in again and "    100 years" in again  # the usual widths unchanged


def test_a_threshold_far_above_any_sea_state_has_no_percent_hint(run_cli):
    line = failed(run_cli(["climate", EXCERPT, "--threshold", "250"]), "'--threshold'", "above any sea state")
    assert "did you mean" not in line


def test_the_record_itself_is_still_blamed_on_record(run_cli, tmp_path):
    short = tmp_path / "short.csv"
    short.write_text("time,hs\n" + "".join(f"2000-01-{d:02d}T00:00,{1 + d / 10}\n" for d in range(1, 29)))
    failed(run_cli(["climate", str(short), "--threshold", "1.5"]), "'RECORD'", "needs at least 1 year")
    failed(run_cli(["climate", str(tmp_path / "absent.csv")]), "'RECORD'", "No such file")


def _copies(tmp_path: Path, bump: float) -> Path:
    """The excerpt with its largest storm peak given twice: first a copy ``bump`` metres higher."""
    lines = gzip.decompress(Path(EXCERPT).read_bytes()).decode().splitlines()
    top = 1 + max(range(len(lines) - 1), key=lambda i: float(lines[i + 1].split(";")[1]))
    stamp, hs, tz = (x.strip() for x in lines[top].split(";"))
    rows = [*lines[:top], f"{stamp}; {float(hs) + bump:.4f}; {tz}", *lines[top:]]
    p = tmp_path / "copies.txt"
    p.write_text("\n".join(rows) + "\n")
    return p


def test_conflicting_copies_warned_on_stderr_and_refused_by_strict(run_cli, tmp_path):
    p = _copies(tmp_path, 1.0)
    r = ok(run_cli(["climate", str(p), "--bootstrap", "0", "--threshold", "97%"]))
    warning = [ln for ln in r.stderr.splitlines() if "differing copies" in ln]
    assert len(warning) == 1 and warning[0].startswith(f"regimemap: warning: {p}: 1 repeated time(s) with")
    assert "dropped; copies differ by up to 1.00 m in Hs" in warning[0]
    assert "(1 with differing copies)" in r.stdout and "warning:" not in r.stdout
    line = failed(run_cli(["climate", str(p), "--bootstrap", "0", "--threshold", "97%", "--strict"]),
                  "differing copies", "--strict refuses")
    assert "(lines " in line
    assert json.loads(ok(run_cli(["climate", str(p), "--bootstrap", "0", "--threshold", "97%", "--json"])).stdout)[
        "record"]["conflicting"] == 1


def test_identical_copies_change_nothing_not_even_strict(run_cli, tmp_path):
    p = _copies(tmp_path, 0.0)
    same = tmp_path / "excerpt.txt"
    same.write_bytes(gzip.decompress(Path(EXCERPT).read_bytes()))
    for extra in ([], ["--strict"]):
        r = run_cli(["climate", str(p), "--bootstrap", "0", "--threshold", "97%", *extra])
        again = run_cli(["climate", str(same), "--bootstrap", "0", "--threshold", "97%", *extra])
        assert "differing copies" not in r.stderr and "repeated" not in r.stderr
        assert (r.code, r.stderr.replace(str(p), "X")) == (again.code, again.stderr.replace(str(same), "X"))
        if r.code == 0:
            assert "1 repeated," in r.stdout and "0 repeated," in again.stdout
            assert r.stdout.splitlines()[3:] == again.stdout.splitlines()[3:]  # the same analysis
