"""``regimemap lifetime``: text and JSON, the files, the same numbers everywhere (processes, chunks,
a Dask cluster), and clean refusals (exit 2 naming the option, exit 1 for a cluster out of reach)."""

from __future__ import annotations

import io
import json
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text
from regimemap.lifetime import DEFAULT_ERRORS
from regimemap.lifetime.file_options import check_chunk, check_scheduler, check_target, parse_widths

EXAMPLE = example_design_text()
TRIALS = "300"

#: Keys of the JSON object of one width.
JSON_KEYS = {"expected_sliding", "std_error", "median", "quantile_90", "quantile_99", "exceedance",
             "storm_exceedance", "never_slides", "trials", "seed", "years", "width", "climate"}


def ok(r):
    assert "Traceback" not in r.output, r.output
    assert r.code == 0, r.output
    assert "error" not in r.stderr, r.stderr
    return r


def failed(r, code: int, *parts: str) -> str:
    """Exit ``code`` with one line on stderr containing every part; no traceback, nothing on stdout."""
    assert "Traceback" not in r.output, r.output
    assert r.code == code, (r.code, r.output)
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    for part in parts:
        assert part in lines[0], (part, lines[0])
    assert r.stdout == "", r.stdout
    return lines[0]


def files_in(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


# -- a run --------------------------------------------------------------------------------------------


def test_text_report(run_cli, goda: Path) -> None:
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--jobs", "1"]))
    out = r.stdout
    assert re.search(r"^ESD \d\S* m ± \d\S* m \(standard error, 300 lifetimes\)$", out, re.M), out
    assert "design life 50 years, 300 lifetimes, seed 2026" in out
    assert "H0'_10 = 5.000 m, H0'_50 = 6.300 m" in out  # the climate
    assert re.search(r"median \S+ m; quantiles 90 %: \S+ m, 99 %: \S+ m", out)
    assert re.search(r"never slides: [\d.]+ % of the lifetimes", out)
    for x in ("0.03", "0.1", "0.3", "1", "3"):  # the exceedance table: over the life, in one storm
        assert re.search(rf"^\s+{re.escape(x)}\s+[\d.]+ %\s+[\d.]+ %$", out, re.M), x
    # notes on stderr, and only notes
    assert r.stderr.startswith("regimemap: 300 lifetimes of 50 years in ")
    assert all(ln.startswith("regimemap: ") for ln in r.stderr.splitlines())


def test_quiet_keeps_stderr_empty(run_cli, goda: Path) -> None:
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--quiet"]))
    assert r.stderr == "" and r.stdout.count("ESD ") == 1


def test_json_is_one_object_with_the_statistics(run_cli, goda: Path) -> None:
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--json", "--jobs", "1"]))
    j = json.loads(r.stdout)
    assert JSON_KEYS <= set(j)
    assert j["trials"] == 300 and j["seed"] == 2026 and j["years"] == 50 and j["width"] == 15.0
    assert set(j["exceedance"]) == {"0.03", "0.1", "0.3", "1", "3"} == set(j["storm_exceedance"])
    assert 0.0 <= j["never_slides"] <= 1.0 and j["std_error"] >= 0.0
    assert j["quantile_90"] <= j["quantile_99"]
    assert "Weibull" in j["climate"] and "H0'_50 = 6.300 m" in j["climate"]
    force = DEFAULT_ERRORS.force
    assert j["model"]["errors"]["force"] == {"ratio": force.ratio, "cov": force.cov}
    assert "files" not in j
    # the numbers of the JSON are those of the text
    t = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--jobs", "1"]))
    assert f"{100 * j['never_slides']:.1f} %" in t.stdout


def test_options_override_the_file(run_cli, goda: Path) -> None:
    j = json.loads(ok(run_cli(["lifetime", str(goda), "--trials", "200", "--seed", "5", "--years", "20",
                               "--json"])).stdout)
    assert (j["trials"], j["seed"], j["years"], j["model"]["years"]) == (200, 5, 20, 20)


def test_no_seed_gives_a_fresh_one_and_says_it(run_cli, tmp_path: Path) -> None:
    path = tmp_path / "fresh.toml"
    path.write_text(EXAMPLE.replace("\nseed = 2026", "\n# seed = 2026"), encoding="utf-8")
    r = ok(run_cli(["lifetime", str(path), "--trials", "100", "--json"]))
    seed = json.loads(r.stdout)["seed"]
    assert f"this run's seed is {seed} (--seed {seed} repeats it)" in r.stderr
    again = ok(run_cli(["lifetime", str(path), "--trials", "100", "--json", "--seed", str(seed)]))
    assert json.loads(again.stdout)["expected_sliding"] == json.loads(r.stdout)["expected_sliding"]


@pytest.mark.render
def test_files_are_written_and_reported(run_cli, goda: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    paths = [str(out / name) for name in ("life.csv", "life.npz", "life.png")]
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, *sum((["-o", p] for p in paths), [])]))
    assert r.stdout.splitlines()[-3:] == paths  # after the report, one line each
    assert files_in(out) == ["life.csv", "life.npz", "life.png"]
    csv = (out / "life.csv").read_text(encoding="utf-8").splitlines()
    assert csv[0] == "trial,sliding_m,max_storm_m,storms" and len(csv) == 301
    assert csv[1].startswith("0,") and csv[-1].startswith("299,")
    with np.load(out / "life.npz") as f:
        assert f["sliding"].shape == f["max_storm"].shape == f["storms"].shape == (300,)
        assert int(str(f["seed"])) == 2026 and int(f["years"]) == 50 and float(f["width"]) == 15.0
        sliding = f["sliding"]
    column = np.array([float(row.split(",")[1]) for row in csv[1:]])
    assert np.allclose(column, sliding, rtol=1e-11, atol=0.0)
    assert (out / "life.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.render
def test_json_lists_the_written_files(run_cli, goda: Path, tmp_path: Path) -> None:
    csv, svg = str(tmp_path / "a.csv"), str(tmp_path / "a.svg")
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--json", "-o", csv, "-o", svg]))
    j = json.loads(r.stdout)  # exactly one object: no paths after it
    assert j["files"] == [csv, svg]
    assert Path(svg).read_text(encoding="utf-8").lstrip().startswith("<?xml")


# -- the same numbers everywhere ------------------------------------------------------------------------


def _csv(run_cli, goda: Path, path: Path, *args: str) -> bytes:
    ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--seed", "11", "-q", "-o", str(path), *args]))
    return path.read_bytes()


@pytest.mark.portable
@pytest.mark.subprocess
def test_the_same_seed_gives_the_same_bytes_with_any_jobs_and_chunk(run_cli, goda: Path,
                                                                    tmp_path: Path) -> None:
    one = _csv(run_cli, goda, tmp_path / "one.csv", "--jobs", "1")
    assert _csv(run_cli, goda, tmp_path / "two.csv", "--jobs", "2", "--chunk", "100") == one
    assert _csv(run_cli, goda, tmp_path / "default.csv") == one
    assert _csv(run_cli, goda, tmp_path / "chunk.csv", "--jobs", "1", "--chunk", "200") == one
    other = _csv(run_cli, goda, tmp_path / "other.csv", "--seed", "12")
    assert other != one


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_a_dask_cluster_gives_the_same_bytes(run_cli, goda: Path, tmp_path: Path) -> None:
    pytest.importorskip("distributed")
    from distributed import LocalCluster

    one = _csv(run_cli, goda, tmp_path / "one.csv", "--jobs", "1")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster:
        address = cluster.scheduler_address
        assert _csv(run_cli, goda, tmp_path / "dask.csv", "--scheduler", address, "--chunk", "100") == one
        r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--scheduler", address, "--json"]))
        assert json.loads(r.stdout)["trials"] == 300 and f"on the Dask cluster at {address}" in r.stderr


@pytest.mark.slow
def test_an_unreachable_scheduler_is_one_line(run_cli, goda: Path, tmp_path: Path) -> None:
    pytest.importorskip("distributed")
    import socket

    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    out = tmp_path / "never.csv"
    # a refused connection is retried until the timeout: 1 s instead of the default 10 s
    r = run_cli(["lifetime", str(goda), "--trials", TRIALS, "--scheduler", f"tcp://127.0.0.1:{port}",
                 "-o", str(out)], env={"REGIMEMAP_DASK_TIMEOUT": "1"})
    failed(r, 1, "regimemap: error: cannot reach the Dask scheduler", f"127.0.0.1:{port}")
    assert not out.exists() and files_in(tmp_path) == ["goda.toml"]


def test_without_distributed_is_one_line(run_cli, goda: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed -> ImportError
    r = run_cli(["lifetime", str(goda), "--trials", TRIALS, "--scheduler", "tcp://127.0.0.1:8786"])
    failed(r, 1, "regimemap: error: --scheduler needs Dask's distributed package",
           "pip install 'regimemap[cluster]'")


# -- the design chart ---------------------------------------------------------------------------------


@pytest.mark.render
@pytest.mark.slow
def test_design_chart(run_cli, goda: Path, tmp_path: Path) -> None:
    png = str(tmp_path / "chart.png")
    r = ok(run_cli(["lifetime", str(goda), "--trials", "200", "--width", "12:24:4", "-o", png]))
    rows = re.findall(r"^\s+(\d+)\s+(\S+) m ± (\S+) m$", r.stdout, re.M)
    assert [w for w, _, _ in rows] == ["12", "16", "20", "24"]
    esd = [float(e) for _, e, _ in rows]
    assert esd == sorted(esd, reverse=True)  # wider slides less (the same random numbers)
    assert re.search(r"^width for ESD <= 0.1 m: \S+ m \(bisected to 0.05 m\)$", r.stdout, re.M)
    assert re.search(r"^  95 % interval \S+ - \S+ m \(Monte Carlo: bootstrap of the 200 lifetimes", r.stdout, re.M)
    assert "wave force: impulsive = false" in r.stdout
    assert "width for SF_sliding = 1.2 under the 50-year wave" in r.stdout
    assert r.stdout.splitlines()[-1] == png and Path(png).read_bytes()[:4] == b"\x89PNG"

    j = json.loads(ok(run_cli(["lifetime", str(goda), "--trials", "200", "--width", "12:24:4",
                               "--target", "0.3", "--json"])).stdout)
    assert [row["width"] for row in j["chart"]] == [12.0, 16.0, 20.0, 24.0]
    assert set(j["chart"][0]) == {"width", "expected_sliding", "std_error"}
    assert j["target"] == 0.3 and 16.0 <= j["width_for_target"] <= 24.0
    assert 14.0 < j["sf_width"] < 16.0 and j["trials"] == 200 and j["seed"] == 2026
    iv = j["width_interval"]
    assert iv["level"] == 0.95 and iv["lower"] <= j["width_for_target"] <= iv["upper"]
    assert j["width_tolerance"] == 0.05 and j["impulsive"] is False
    # the design's 15 m against the width for the target: one check
    assert j["checks"] == [{"name": "width for ESD <= 0.3 m", "value": 15.0,
                            "required": j["width_for_target"], "relation": ">=", "unit": "m",
                            "pass": False}]


@pytest.mark.parametrize(("widths", "where"), [("8:10:2", "no width meets it"),
                                                ("40:50:2", "every width meets it")])
def test_a_chart_that_does_not_bracket_the_target_exits_2_with_both_ends(run_cli, goda: Path, widths: str,
                                                                         where: str) -> None:
    r = run_cli(["lifetime", str(goda), "--trials", "100", "--width", widths, "--target", "0.1"])
    line = failed(r, 2, "'--width'", "the target ESD 0.1 m is not between the ESD at the ends", where)
    lo, hi = widths.split(":")[:2]
    assert re.search(rf"\S+ m at {lo} m and \S+ m at {hi} m", line), line


def test_widths_beyond_those_of_caissons_are_refused(run_cli, goda: Path) -> None:
    # the 1:1e6:5, which once answered 977.6 m
    failed(run_cli(["lifetime", str(goda), "--width", "1:1e6:5", "--target", "0.1"]), 2,
           "'--width'", "outside the 1-100 m of caisson widths", "1 <= A < B <= 100")


@pytest.mark.slow
def test_the_width_tolerance_sets_the_bisection(run_cli, goda: Path) -> None:
    base = ["lifetime", str(goda), "--trials", "200", "--width", "12:24:4", "--json"]
    fine = json.loads(ok(run_cli([*base, "--width-tolerance", "0.01"])).stdout)
    coarse = json.loads(ok(run_cli([*base, "--width-tolerance", "1"])).stdout)
    assert fine["width_tolerance"] == 0.01 and coarse["width_tolerance"] == 1.0
    # the same bisection path: the coarse answer is within 1 m above the fine one
    assert 0.0 <= coarse["width_for_target"] - fine["width_for_target"] <= 1.0
    failed(run_cli([*base, "--width-tolerance", "0"]), 2, "'--width-tolerance'", "0.001 <= tolerance <= 10")
    failed(run_cli(["lifetime", str(goda), "--width-tolerance", "0.1"]), 2, "--width-tolerance", "--width")


@pytest.mark.slow
def test_the_chart_s_table_as_csv(run_cli, goda: Path, tmp_path: Path) -> None:
    text = EXAMPLE.replace("# failure_sliding = 5.0", "failure_sliding = 5.0")
    goda.write_text(text, encoding="utf-8")
    csv = tmp_path / "chart.csv"
    j = json.loads(ok(run_cli(["lifetime", str(goda), "--trials", "200", "--width", "12:24:4", "--json",
                               "-o", str(csv)])).stdout)
    lines = csv.read_text(encoding="utf-8").splitlines()
    assert lines[0] == ("width_m,expected_sliding_m,std_error_m,p_exceed_0.03m,p_exceed_0.1m,"
                        "p_exceed_0.3m,p_exceed_1m,p_exceed_3m,p_failure")
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    assert [r[0] for r in rows] == [12.0, 16.0, 20.0, 24.0]
    for r, c in zip(rows, j["chart"]):
        assert r[1] == pytest.approx(c["expected_sliding"], rel=1e-11)
        assert r[2] == pytest.approx(c["std_error"], rel=1e-11)
        assert r[3] >= r[4] >= r[5] >= r[6] >= r[7] >= r[8] >= 0.0  # P(S > 5 m) <= P(S > 3 m)
    assert j["failure_sliding"] == 5.0


# -- the requirements and --check ---------------------------------------------------------------------


def test_check_exits_1_on_a_failed_requirement_after_the_report_and_the_files(run_cli, goda: Path,
                                                                                tmp_path: Path) -> None:
    csv = tmp_path / "life.csv"
    r = run_cli(["lifetime", str(goda), "--trials", TRIALS, "--check", "-o", str(csv)])
    assert r.code == 1 and "Traceback" not in r.output
    assert csv.exists()
    assert re.search(r"^  FAIL  expected sliding distance \S+ m <= 0.1 m$", r.stdout, re.M)
    assert "  verdict: FAIL (1 of 1 requirements not met)" in r.stdout
    # without --check the same report exits 0
    assert ok(run_cli(["lifetime", str(goda), "--trials", TRIALS])).stdout == r.stdout.replace(
        f"{csv}\n", "")


def test_check_exits_0_when_every_requirement_passes(run_cli, goda: Path) -> None:
    goda.write_text(EXAMPLE.replace("target = 0.1 ", "target = 1000 "), encoding="utf-8")
    r = ok(run_cli(["lifetime", str(goda), "--trials", TRIALS, "--check"]))
    assert "  PASS  expected sliding distance" in r.stdout and "verdict: PASS" in r.stdout


def test_check_keeps_usage_errors_at_2(run_cli, goda: Path) -> None:
    goda.write_text(EXAMPLE.replace("H0_50 = 6.3", "H0_50 = 630"), encoding="utf-8")
    failed(run_cli(["lifetime", str(goda), "--check"]), 2, "H0_50 = 630", "above 30 m")


def test_json_checks_allowed_exceedances_and_the_failure_probability(run_cli, goda: Path) -> None:
    text = EXAMPLE.replace("target = 0.1 ", 'target = 5\nallowed = {0.1 = 0.5, "3" = 0.001}\n')
    text = text.replace("# failure_sliding = 5.0", "failure_sliding = 5.0")
    goda.write_text(text, encoding="utf-8")
    r = run_cli(["lifetime", str(goda), "--trials", TRIALS, "--json", "--check"])
    assert r.code == 1, r.output
    j = json.loads(r.stdout)
    names = [c["name"] for c in j["checks"]]
    assert names == ["expected sliding distance", "P(S > 0.1 m)", "P(S > 3 m)"]
    by = {c["name"]: c for c in j["checks"]}
    assert by["P(S > 0.1 m)"]["value"] == j["exceedance"]["0.1"] and by["P(S > 0.1 m)"]["pass"] is True
    assert by["P(S > 3 m)"]["value"] == j["exceedance"]["3"] > 0.001 and by["P(S > 3 m)"]["pass"] is False
    assert by["expected sliding distance"] == {"name": "expected sliding distance",
                                               "value": j["expected_sliding"], "required": 5.0,
                                               "relation": "<=", "unit": "m",
                                               "pass": j["expected_sliding"] <= 5.0}
    # the failure probability: the share of lifetimes beyond 5 m, from the lifetimes themselves
    f = j["failure"]
    assert f["sliding_limit"] == 5.0
    p = f["probability"]
    assert j["exceedance"]["3"] >= p > 0.0
    assert f["std_error"] == pytest.approx(np.sqrt(p * (1 - p) / int(TRIALS)), rel=1e-9)
    assert j["impulsive"] is False and j["climate_as_written"] == "H0_10 = 5.0 m, H0_50 = 6.3 m"


@pytest.mark.parametrize("value", ["1e300", "630"])
def test_absurd_climates_are_refused_without_strict(run_cli, goda: Path, value: str) -> None:
    goda.write_text(EXAMPLE.replace("H0_50 = 6.3", f"H0_50 = {value}"), encoding="utf-8")
    r = run_cli(["lifetime", str(goda)])
    failed(r, 2, "[lifetime] H0_50 =", "above 30 m, higher than any sea measured")
    assert "RuntimeWarning" not in r.output


# -- refusals -----------------------------------------------------------------------------------------


@pytest.mark.parametrize(("args", "parts"), [
    (["--width", "25:10:5"], ["'--width'", "1 <= A < B <= 100", "(need A < B)"]),
    (["--width", "10:25:1"], ["'--width'", "N a whole number from 2 to 200", "(N = 1)"]),
    (["--width", "0:25:5"], ["'--width'", "(outside the 1-100 m of caisson widths)"]),
    (["--width", "a:b:c"], ["'--width'", "A or B is not a number"]),
    (["--width", "10:25"], ["'--width'", "A:B:N"]),
    (["--width", "10:25:2.5"], ["'--width'", "N is not a whole number"]),
    (["--width", "10:25:201"], ["'--width'", "(N = 201)"]),
    (["--trials", "0"], ["'--trials'", "1 <= trials <= 10000000", "got '0'"]),
    (["--trials", "many"], ["'--trials'", "not a whole number"]),
    (["--trials", "nan"], ["'--trials'"]),
    (["--seed", "-1"], ["'--seed'", "a whole number >= 0", "got '-1'"]),
    (["--years", "0"], ["'--years'", "1 <= years <= 1000"]),
    (["--chunk", "0"], ["'--chunk'", "1 <= chunk <= 10000000"]),
    (["--jobs", "0"], ["'--jobs'", "1<=x<=256"]),
    (["--target", "0.1"], ["--target is the tolerable ESD of a design chart", "--width"]),
    (["--width", "10:20:3", "--target", "-1"], ["'--target'", "> 0 in metres"]),
    (["--width", "10:20:3", "--target", "inf"], ["'--target'", "> 0 in metres"]),
    (["--jobs", "2", "--scheduler", "tcp://127.0.0.1:8786"], ["--jobs and --scheduler exclude each other"]),
    (["--scheduler", "somewhere"], ["'--scheduler'", "[tcp://]host:port", "got 'somewhere'"]),
    (["--scheduler", "tcp://host:99999"], ["'--scheduler'", "got 'tcp://host:99999'"]),
    (["-o", "{tmp}/life.txt"], ["'--output'", ".txt", ".png, .svg or .pdf", ".csv or .npz"]),
    (["-o", "{tmp}/life"], ["'--output'", "no file suffix"]),
    (["--width", "10:20:3", "-o", "{tmp}/chart.npz"], ["'--output'", "not with --width"]),
    (["-o", "{tmp}/missing/life.png"], ["'--output'", "does not exist"]),
    (["-o", "{tmp}/a.csv", "-o", "{tmp}/a.csv"], ["the same file is given twice"]),
])
def test_bad_options_exit_2_naming_the_option(run_cli, goda: Path, tmp_path: Path, args: list[str],
                                             parts: list[str]) -> None:
    argv = ["lifetime", str(goda), "--trials", "100", *[a.replace("{tmp}", str(tmp_path)) for a in args]]
    line = failed(run_cli(argv), 2, *parts)
    assert line.startswith("regimemap lifetime: error: ") and "(see 'regimemap lifetime --help')" in line
    assert files_in(tmp_path) == ["goda.toml"]


def test_a_file_without_lifetime_is_a_usage_error(run_cli, tmp_path: Path) -> None:
    path = tmp_path / "plain.toml"
    path.write_text(EXAMPLE[:EXAMPLE.index("# Optional: the sliding")], encoding="utf-8")
    failed(run_cli(["lifetime", str(path)]), 2, "'DESIGN.toml'", "no [lifetime] table",
           "`regimemap caisson --example`")


def test_a_bad_lifetime_table_names_the_line(run_cli, tmp_path: Path) -> None:
    path = tmp_path / "bad.toml"
    text = EXAMPLE.replace("\nshape = 2.0 ", "\nshape = -2 ")
    path.write_text(text, encoding="utf-8")
    line = 1 + text.splitlines().index(next(ln for ln in text.splitlines() if ln.startswith("shape = -2")))
    failed(run_cli(["lifetime", str(path), "-o", str(tmp_path / "x.png")]), 2,
           f"{path}, line {line}: [lifetime] shape = -2: out of range; accepted: a Weibull shape 0.5 <= k <= 5")
    assert files_in(tmp_path) == ["bad.toml"]


def test_missing_or_unreadable_design(run_cli, tmp_path: Path) -> None:
    failed(run_cli(["lifetime"]), 2, "Missing argument 'DESIGN.toml'")
    failed(run_cli(["lifetime", str(tmp_path / "absent.toml")]), 2, "cannot read the design file")
    failed(run_cli(["lifetime", str(tmp_path)]), 2, "'DESIGN.toml'")


def test_help(run_cli) -> None:
    r = run_cli(["lifetime", "--help"])
    assert r.code == 0 and "Examples:" in r.stdout and "regimemap lifetime goda.toml --width" in r.stdout
    assert "regimemap lifetime goda.toml --width 10:25:16" in run_cli(["--help"]).stdout


# -- the helpers --------------------------------------------------------------------------------------


def test_option_checks() -> None:
    assert parse_widths("10:25:4") == [10.0, 15.0, 20.0, 25.0]
    assert check_target("0.1") == 0.1 and check_chunk("250") == 250
    assert check_scheduler(" tcp://127.0.0.1:8786 ") == "tcp://127.0.0.1:8786"
    assert check_scheduler("[::1]:8786") == "[::1]:8786" and check_scheduler("inproc://x") == "inproc://x"
    for bad in ("", "10:25", "25:10:3", "10:25:x", "nan:25:3", "10:inf:3"):
        with pytest.raises(ValueError, match="widths must be A:B:N"):
            parse_widths(bad)


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_bar_only_on_a_terminal_and_not_when_quiet(monkeypatch: pytest.MonkeyPatch) -> None:
    import regimemap.cli._progress as progress

    terminal = _Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    monkeypatch.setattr(progress, "DELAY", 0.0)
    with progress.progress_bar(300, "lifetimes", quiet=True) as step:
        step(300)
    assert terminal.getvalue() == ""
    with progress.progress_bar(300, "lifetimes", unit="lifetime") as step:
        step(100)
        step(200)
    drawn = terminal.getvalue()
    assert drawn.startswith("\rlifetimes:") and "/300 [" in drawn and "lifetime/s" in drawn
    assert drawn.endswith("\r")  # the bar is removed at the end: stderr keeps only the notes
    plain = io.StringIO()  # not a terminal: nothing, whatever the delay
    monkeypatch.setattr(sys, "stderr", plain)
    with progress.progress_bar(None, "lifetimes") as step:
        step(5)
    assert plain.getvalue() == ""
