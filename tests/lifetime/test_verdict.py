"""A record's climate judged with its uncertainty: the requirements on the band, the default replicates,
the report ending with its verdict, the chart's width at the band's upper level and its CSV columns."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text, read_design
from regimemap.lifetime import Climate, LifetimeResult, Requirements, judge_lifetime, lifetime_sliding
from regimemap.lifetime.replicates import DEFAULT_REPLICATES, ClimateBand, climate_band
from regimemap.lifetime.requirements import WITH_CLIMATE, lifetime_checks
from regimemap.lifetime.run import run_chart, run_lifetime

EXCERPT = Path(__file__).parents[1] / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"
_CLIMATE_KEYS = ("H0_10", "H0_50", "distribution", "shape", "storms_per_year", "annual_maxima")


def record_design(tmp_path: Path, lifetime_extra: str = "climate_replicates = 4", width: float = 24.0) -> Path:
    """The example caisson, ``width`` wide (its weight in proportion), under a year of 44007 (95 %
    threshold, T1/3 = 1.2 Tz fitted): a cheap record climate whose point ESD at 24 m is far below the
    ESD including the climate's uncertainty (the one-year fit is very uncertain)."""
    shutil.copy(EXCERPT, tmp_path / "buoy.txt.gz")
    text = example_design_text()
    i, j = text.index("[lifetime]"), text.index("[lifetime.errors]")
    head = text[:i].replace("width = 15.0 ", f"width = {width:g} ").replace(
        "buoyant_weight = 2312", f"buoyant_weight = {round(2312 * width / 15.0)}")
    kept = [line for line in text[i:j].splitlines() if line.split("=")[0].strip() not in _CLIMATE_KEYS]
    life = ("\n".join(kept) + f"\n{lifetime_extra}\n\n[lifetime.record]\npath = \"buoy.txt.gz\"\n"
            'threshold = "95%"\nperiod_ratio = 1.2\n\n')
    p = tmp_path / "site.toml"
    p.write_text(head + life + text[j:])
    return p


def _result(sliding: list[float]) -> LifetimeResult:
    s = np.asarray(sliding, dtype=np.float64)
    return LifetimeResult(sliding=s, max_storm=s, storms=np.ones(s.size, dtype=np.int64), seed=1, years=50,
                          thresholds=(0.1,), width=20.0)


def _band(esd: list[float], exceed: list[list[float]], thresholds: tuple[float, ...]) -> ClimateBand:
    return ClimateBand(esd=np.asarray(esd), level=0.9, seed=1, trials=10, thresholds=thresholds,
                       exceed=np.asarray(exceed), curve=np.zeros((len(esd), 161)))


def test_the_band_flips_the_verdict_and_each_line_says_so():
    result = _result([0.0, 0.0, 0.0, 0.2])  # ESD 0.05 m, P(S > 0.1 m) = 25 %
    band = _band([0.02, 0.05, 0.35], [[0.1, 0.0], [0.2, 0.0], [0.6, 0.3]], (0.1, 2.0))
    req = Requirements(target=0.1, allowed={0.1: 0.28}, failure_sliding=2.0)
    alone = lifetime_checks(result, req)
    assert [c.passed for c in alone] == [True, True]
    judged = judge_lifetime(result, req, band)
    esd, p01 = judged.checks
    assert not esd.passed and esd.value == pytest.approx(0.14) and esd.name == f"ESD {WITH_CLIMATE}"
    assert not p01.passed and p01.value == pytest.approx(0.3)
    assert p01.name == f"P(S > 0.1 m) {WITH_CLIMATE}"
    assert judged.failure is not None and judged.failure.probability == pytest.approx(0.1)
    assert judged.failure.std_error == pytest.approx(np.std([0.0, 0.0, 0.3], ddof=1) / np.sqrt(3))
    # the band below the target passes where the point estimate alone would fail
    low = _band([0.01, 0.02, 0.03], [[0.0, 0.0]] * 3, (0.1, 2.0))
    assert all(c.passed for c in judge_lifetime(_result([0.0, 0.3]), req, low).checks)
    with pytest.raises(KeyError, match="not at 0.3 m"):
        low.exceedance(0.3)


def test_each_replicate_keeps_its_exceedance_from_its_own_lifetimes():
    from regimemap.caisson.file import parse_design

    d = parse_design(example_design_text())
    caisson, model = d.lifetime_caisson(), d.lifetime_model()
    climates = [Climate.from_return_values(5.0, h) for h in (5.9, 6.8)]
    band = climate_band(caisson, model, climates, 120, seed=4, thresholds=(0.1, 1.0))
    seeds = [int(s.generate_state(1, np.uint32)[0]) for s in np.random.SeedSequence(4).spawn(2)]
    for i, (c, s) in enumerate(zip(climates, seeds)):
        one = lifetime_sliding(caisson, model.with_(climate=c), 120, s)
        assert band.esd[i] == one.expected_sliding
        assert band.exceed[i].tolist() == [one.exceedance(0.1), one.exceedance(1.0)]
    assert band.exceedance(1.0) == pytest.approx(np.mean(band.exceed[:, 1]))
    x, lo, mean, hi = band.curve_band()
    assert np.all(lo <= mean + 1e-15) and np.all(mean <= hi + 1e-15) and np.all(np.diff(mean) <= 1e-15)


@pytest.mark.slow
def test_a_record_climate_is_judged_with_its_uncertainty_and_the_report_ends_with_the_verdict(tmp_path):
    rec = run_lifetime(record_design(tmp_path), trials=60, seed=9)
    assert rec.band is not None and rec.band.replicates == 4
    (esd,) = rec.result.checks
    assert esd.name == f"ESD {WITH_CLIMATE}" and esd.value == rec.band.expected_sliding
    # the case the issue found: the fitted climate alone passes, its uncertainty included fails
    assert rec.result.expected_sliding <= 0.1 < rec.band.expected_sliding and not esd.passed
    lines = rec.report_text().splitlines()
    assert lines[-1].strip().startswith("verdict: FAIL") and "FAIL  ESD including the climate's uncertainty" in lines[-2]
    assert "90 % climate band:" in rec.report_text()
    obj = rec.report_json(["a.csv"])
    assert list(obj)[-3:] == ["files", "checks", "verdict"] and obj["verdict"] == "FAIL"
    assert obj["climate_band"]["expected_sliding"] == pytest.approx(rec.band.expected_sliding)
    assert set(obj["climate_band"]["exceedance"]) == {"0.03", "0.1", "0.3", "1", "3"}


def test_a_record_takes_the_default_replicates_and_zero_is_a_warned_choice(tmp_path):
    spec = read_design(record_design(tmp_path, "")).lifetime_spec()
    assert spec.climate_replicates == DEFAULT_REPLICATES == 50
    rec = run_lifetime(record_design(tmp_path, "climate_replicates = 0"), trials=40, seed=9)
    assert rec.band is None and rec.result.checks[0].name == "expected sliding distance"
    codes = [n.code for n in rec.notices]  # the one-year fit's own warnings come first
    assert codes.count("climate-uncertainty-not-counted") == 1 and set(codes) <= {"fit", "climate-uncertainty-not-counted"}


@pytest.mark.subprocess
def test_check_exits_1_when_only_the_climate_s_uncertainty_fails(run_cli, tmp_path):
    p = record_design(tmp_path)
    out = run_cli(["lifetime", str(p), "--trials", "60", "--seed", "9", "--check", "-q"])
    assert out.code == 1, out.output
    assert out.stdout.rstrip().splitlines()[-1].strip().startswith("verdict: FAIL")
    assert "under the fitted climate" in out.stdout


@pytest.mark.deep
def test_the_chart_is_judged_at_the_band_s_upper_level_and_its_csv_has_the_band(tmp_path):
    rec = run_chart(record_design(tmp_path, "climate_replicates = 3", width=20.0), [16.0, 22.0, 34.0],
                    trials=40, seed=3, tolerance=1.0)
    assert rec.band is not None
    if rec.band.width_for_target is None:  # the band's upper curve not bracketed: refused, not judged
        assert [n.code for n in rec.notices] == ["target-not-bracketed"] and rec.result.checks == ()
        return
    (check,) = rec.result.checks
    assert check.required == rec.band.width_for_target and "upper end of the climate band" in check.name
    rec.write_data(tmp_path / "chart.csv")
    head, *rows = (tmp_path / "chart.csv").read_text().splitlines()
    cols = head.split(",")
    assert cols[-2:] == ["band_lower_m", "band_upper_m"] and len(rows) == 3
    lower = [float(r.split(",")[-2]) for r in rows]
    upper = [float(r.split(",")[-1]) for r in rows]
    assert np.all(np.isfinite(lower + upper))
    np.testing.assert_allclose(upper, rec.band.upper, rtol=1e-11)
    assert all(lo <= hi for lo, hi in zip(lower, upper))
    obj = rec.report_json()
    assert list(obj)[-2:] == ["checks", "verdict"] and "climate_band" in obj
    assert json.loads(json.dumps(obj))["climate_band"]["replicates"] == 3


@pytest.mark.subprocess
@pytest.mark.deep
def test_caisson_names_the_record_and_judges_the_band_as_lifetime_does(run_cli, tmp_path):
    p = record_design(tmp_path)  # the lifetime tests' run: trials 60, seed 9, 4 replicates
    p.write_text(p.read_text().replace("trials = 5000", "trials = 60").replace("seed = 2026", "seed = 9"))
    text = run_cli(["caisson", str(p), "--check"])
    assert text.code == 1, text.output
    lines = text.stdout.rstrip().splitlines()
    assert "buoy.txt.gz (peaks over the 95 % quantile" in text.stdout and "fitted: GPD" in text.stdout
    assert "90 % climate band:" in text.stdout
    assert lines[-2].startswith("FAIL  ESD including the climate's uncertainty")
    assert lines[-1].startswith("verdict: FAIL (1 of 3")
    obj = json.loads(run_cli(["caisson", str(p), "--check", "--json"]).stdout)
    assert list(obj)[-3:] == ["design_check", "checks", "verdict"]
    assert obj["lifetime"]["record"]["path"] == str(tmp_path / "buoy.txt.gz")
    band = obj["lifetime"]["climate_band"]
    assert band["replicates"] == 4 and obj["checks"][-1]["value"] == band["expected_sliding"]
    assert obj["lifetime"]["expected_sliding"] <= 0.1 < band["expected_sliding"]


@pytest.mark.render
def test_the_exceedance_figure_draws_the_climate_band():
    from regimemap.lifetime.figures.exceedance import lifetime_figure
    from regimemap.lifetime.replicates import CURVE_X

    rng = np.random.default_rng(3)
    result = _result(list(np.where(rng.random(400) < 0.3, rng.lognormal(-2.0, 1.5, 400), 0.0)))
    curves = np.array([[float(np.mean(result.sliding * f > x)) for x in CURVE_X] for f in (0.5, 1.0, 3.0)])
    band = ClimateBand(esd=result.expected_sliding * np.array([0.5, 1.0, 3.0]), level=0.9, seed=1, trials=400,
                       thresholds=(), exceed=np.zeros((3, 0)), curve=curves)
    req = Requirements(target=0.1)
    fig = lifetime_figure(judge_lifetime(result, req, band), band=band)
    (ax,) = [a for a in fig.axes if a.get_label() == "exceedance"]
    gids = {a.get_gid() for a in [*ax.collections, *ax.lines]}
    assert {"climate-band", "climate-mean", "climate-esd"} <= gids
    esd = next(a for a in ax.lines if a.get_gid() == "climate-esd")
    assert esd.get_xdata()[0] == pytest.approx(band.expected_sliding)
    names = [t.get_text() for t in fig.legends[0].get_texts()]
    assert any("band over 3 climates of the record" in n for n in names)
    plain = lifetime_figure(judge_lifetime(result, req))
    (ax,) = [a for a in plain.axes if a.get_label() == "exceedance"]
    assert not {a.get_gid() for a in [*ax.collections, *ax.lines]} & {"climate-band", "climate-esd"}


def test_esd_at_the_width_found_carries_each_climate_s_ratio_to_the_design_chart():
    from regimemap.study.run import _esd_at

    widths = np.array([16.0, 22.0, 28.0])
    design = np.array([1.0, 0.1, 0.0])
    # twice the design climate's ESD at 16 m, three times at 22 m: 2.5 times half-way, of the ESD found
    assert _esd_at(widths, design, np.array([2.0, 0.3, 0.05]), 19.0, 0.4) == pytest.approx(1.0)
    assert _esd_at(widths, design, np.array([2.0, 0.3, 0.05]), 25.0, 0.01) == pytest.approx(0.03)
    assert _esd_at(widths, np.zeros(3), np.array([2.0, 0.3, 0.05]), 19.0, 0.4) == 0.4


@pytest.mark.slow
@pytest.mark.deep
def test_a_study_target_section_with_a_record_has_its_band_and_width_at_the_upper_level(tmp_path):
    from regimemap.study.run import run_study

    record_design(tmp_path, "climate_replicates = 3", width=20.0)
    (tmp_path / "study.toml").write_text(
        'seed = 3\ntrials = 40\nbase = "site.toml"\n\n[[section]]\nname = "target"\nchainage = 10\n'
        'target = 0.1\nwidths = [16.0, 22.0, 34.0]\ntolerance = 2.0\n\n[[scenario]]\nname = "today"\n')
    (row,) = run_study(tmp_path / "study.toml").rows
    assert row.required_width == row.width and row.band is not None
    assert 0.0 <= row.band[0] <= row.band[1] and np.isfinite(row.band[1])
    assert row.required_width_upper is not None and 16.0 <= row.required_width_upper <= 34.0


@pytest.mark.slow
@pytest.mark.deep
def test_strict_refuses_the_record_s_warnings_before_the_run(run_cli, tmp_path):
    """``--strict`` of ``lifetime`` and ``caisson`` refuses what ``climate --strict`` refuses: the
    warnings of the ``[lifetime.record]`` (here the one-year fit's end point close to its largest
    storm); without it they are warnings on standard error and the run goes on."""
    p = record_design(tmp_path)
    warned = run_cli(["lifetime", str(p), "--trials", "20", "--jobs", "1", "-q"])
    assert warned.code == 0 and "warning:" in warned.stderr and "upper end point" in warned.stderr
    for command in (["lifetime", str(p), "--trials", "20", "--jobs", "1", "-q"], ["caisson", str(p)]):
        out = run_cli([*command, "--strict"])
        assert out.code == 2 and out.stdout == "", (command, out.output)
        (line,) = out.error_lines()
        assert "upper end point" in line and "--strict refuses the record's warnings" in line, line
        assert "'DESIGN.toml'" in line
