"""A record's fit, and observed annual maxima, as the lifetime's climate; the ESD's climate band;
[lifetime.record] in the design file."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from regimemap.caisson.file import DesignFileError, example_design_text, read_design
from regimemap.climate.fits import Fit
from regimemap.climate.life import climate_of, climate_of_maxima
from regimemap.lifetime import Climate
from regimemap.lifetime.replicates import climate_band

DATA = Path(__file__).parent / "data"
EXCERPT = DATA / "ndbc44007_1996_hs_tz.txt.gz"
CLIMATE_KEYS = ("H0_10", "H0_50", "distribution", "shape", "storms_per_year", "annual_maxima")


def test_gumbel_maximum_likelihood_matches_scipy():
    x = stats.gumbel_r.rvs(loc=3.0, scale=0.8, size=40, random_state=np.random.default_rng(3))
    c = climate_of_maxima(x, "gumbel")
    loc, scale = stats.gumbel_r.fit(x)
    assert (c.location, c.scale) == pytest.approx((loc, scale), rel=1e-5)


@pytest.mark.parametrize("k", [1.5, 2.0, 3.0])
def test_weibull_maximum_likelihood_matches_scipy(k):
    x = stats.weibull_min.rvs(k, loc=1.5, scale=2.0, size=60, random_state=np.random.default_rng(7))
    c = climate_of_maxima(x, "weibull", k)
    _, loc, scale = stats.weibull_min.fit(x, fc=k)

    def nll(loc_: float, scale_: float) -> float:
        return float(-stats.weibull_min.logpdf(x, k, loc=loc_, scale=scale_).sum())

    # the same optimum, or a better one than scipy's numerical search
    assert nll(c.location, c.scale) <= nll(loc, scale) + 1e-6
    assert (c.location, c.scale) == pytest.approx((loc, scale), rel=1e-3, abs=1e-3)


def test_maxima_fit_refusals():
    with pytest.raises(ValueError, match="at least three"):
        climate_of_maxima([1.0, 2.0])
    with pytest.raises(ValueError, match="all equal"):
        climate_of_maxima([2.0, 2.0, 2.0])
    with pytest.raises(ValueError, match="k > 1"):
        climate_of_maxima([1.0, 2.0, 3.0], "weibull", 1.0)


@pytest.mark.parametrize("fit", [
    Fit("gpd", {"sigma": 1.3, "xi": -0.3}, 4.0, 6.0, 60), Fit("gpd", {"sigma": 0.8, "xi": 0.2}, 3.0, 2.5, 30),
    Fit("gpd", {"sigma": 1.1, "xi": 0.0}, 3.0, 4.0, 30), Fit("weibull", {"A": 0.9, "k": 1.4}, 3.0, 5.0, 50),
    Fit("gumbel", {"A": 0.7, "B": 5.7}, None, 1.0, 10), Fit("gev", {"mu": 6.0, "sigma": 0.9, "xi": -0.2}, None, 1.0, 10),
])
def test_climate_of_fit_same_distribution(fit):
    c = climate_of(fit)
    frozen = fit.frozen()
    for R in (10.0, 50.0, 200.0):
        assert c.return_value(R) == pytest.approx(fit.return_value(R), rel=1e-12)
    u = np.array([0.01, 0.3, 0.5, 0.9, 0.999])
    np.testing.assert_allclose(c.quantile(u), frozen.ppf(u), rtol=1e-12)
    np.testing.assert_allclose(c.cdf(frozen.ppf(u)), u, rtol=1e-10)
    assert c.rate == pytest.approx(fit.rate)


def test_gpd_cdf_outside_support():
    c = Climate("gpd", scale=1.0, location=4.0, shape=-0.5, storms_per_year=3.0)
    np.testing.assert_allclose(c.cdf([3.0, 4.0, 6.0, 7.0]), [0.0, 0.0, 1.0, 1.0])
    np.testing.assert_allclose(c.cdf([5.0]), stats.genpareto.cdf(5.0, -0.5, loc=4.0, scale=1.0))
    with pytest.raises(ValueError, match="shape xi must be finite"):
        Climate("gpd", scale=1.0, location=4.0, shape=float("nan"))


def _goda():
    d = read_design_text(example_design_text())
    return d.lifetime_caisson(), d.lifetime_model()


def read_design_text(text, tmp=None):
    import tempfile

    folder = Path(tmp or tempfile.mkdtemp())
    p = folder / "d.toml"
    p.write_text(text)
    return read_design(p)


def test_climate_band_seeded_and_same_with_any_chunking():
    caisson, model = _goda()
    climates = [Climate.from_return_values(5.0, h) for h in (5.9, 6.3, 6.8)]
    a = climate_band(caisson, model, climates, 200, seed=5, chunk=100)
    b = climate_band(caisson, model, climates, 200, seed=5, chunk=200)
    np.testing.assert_array_equal(a.esd, b.esd)
    assert a.esd[0] < a.esd[2]  # a larger 50-year wave slides further
    assert a.lower <= a.expected_sliding <= a.upper
    assert a.expected_sliding == pytest.approx(a.esd.mean())
    with pytest.raises(ValueError, match="at least two"):
        climate_band(caisson, model, climates[:1], 10, seed=1)


def _record_design(tmp_path: Path, record_lines: str, lifetime_extra: str = "") -> Path:
    shutil.copy(EXCERPT, tmp_path / "buoy.txt.gz")
    text = example_design_text()
    i, j = text.index("[lifetime]"), text.index("[lifetime.errors]")
    kept = [line for line in text[i:j].splitlines() if line.split("=")[0].strip() not in CLIMATE_KEYS]
    life = "\n".join(kept) + "\n" + lifetime_extra + "\n[lifetime.record]\n" + record_lines + "\n\n"
    p = tmp_path / "site.toml"
    p.write_text(text[:i] + life + text[j:])
    return p


def test_design_record_gives_the_fitted_climate(tmp_path):
    from regimemap.climate import ClimateOptions, analyse
    from regimemap.climate.file import read_record

    p = _record_design(tmp_path, 'path = "buoy.txt.gz"\nthreshold = "98%"\ngap_hours = 36')
    model = read_design(p).lifetime_model()
    direct = analyse(read_record(tmp_path / "buoy.txt.gz"),
                     ClimateOptions(threshold=("quantile", 0.98), gap_hours=36.0, bootstrap=0))
    assert model.climate.distribution == "gpd"
    assert model.climate.storms_per_year == pytest.approx(direct.fit.rate)
    assert model.climate.return_value(50) == pytest.approx(direct.fit.return_value(50), rel=1e-12)


@pytest.mark.parametrize(("record", "extra", "match"), [
    ('path = "buoy.txt.gz"\nthresold = 3', "", r"line \d+: unknown key \[lifetime.record\] thresold \(did you mean 'threshold'\?\)"),
    ('method = "pot"', "", r"\[lifetime.record\] has no path"),
    ('path = "buoy.txt.gz"\ngap_hours = 0', "", r"line \d+: \[lifetime.record\] gap_hours = 0: out of range"),
    ('path = "buoy.txt.gz"\nthreshold = "200%"', "", r'threshold = "200%": neither a height'),
    ('path = "buoy.txt.gz"\nmethod = "annual-maxima"\ndistribution = "gpd"', "", r"not a distribution of annual-maxima"),
    ('path = "buoy.txt.gz"', "H0_10 = 5.0", r"\[lifetime\] H0_10 together with \[lifetime.record\]"),
    ('path = "absent.csv"', "", r"absent.csv: cannot read the wave record: No such file"),
    ('path = "buoy.txt.gz"\nthreshold = 6.5', "", r"a fit needs at least 10"),
])
def test_design_record_refused(tmp_path, record, extra, match):
    p = _record_design(tmp_path, record, extra)
    with pytest.raises(DesignFileError, match=match):
        read_design(p).lifetime_model()


def test_replicates_need_a_record(tmp_path):
    text = example_design_text().replace("[lifetime.errors]", "climate_replicates = 5\n\n[lifetime.errors]", 1)
    with pytest.raises(DesignFileError, match="climate_replicates needs a \\[lifetime.record\\]"):
        read_design_text(text, tmp_path)


@pytest.mark.subprocess
@pytest.mark.deep
def test_lifetime_command_climate_band_same_bytes_any_jobs(run_cli, tmp_path):
    p = _record_design(tmp_path, 'path = "buoy.txt.gz"\nthreshold = "98%"', "climate_replicates = 4")
    args = ["lifetime", str(p), "--trials", "200", "--seed", "9", "--json", "-q"]
    one = run_cli([*args, "--jobs", "1"])
    assert one.code == 0, one.output
    two = run_cli([*args, "--jobs", "2", "--chunk", "100"])
    assert one.stdout == two.stdout
    band = json.loads(one.stdout)["climate_band"]
    assert band["replicates"] == 4 and band["level"] == 0.9
    assert band["lower"] <= band["expected_sliding"] <= band["upper"]
    text = run_cli(["lifetime", str(p), "--trials", "200", "--seed", "9", "-q"])
    assert "90 % climate band:" in text.stdout


def test_period_law_fitted_only_with_period_ratio(tmp_path):
    from regimemap.climate import storms
    from regimemap.climate.file import read_record
    from regimemap.climate.peaks import resolve_threshold

    plain = _record_design(tmp_path, 'path = "buoy.txt.gz"\nthreshold = "98%"')
    assert read_design(plain).lifetime_model().period_law is None  # Goda's relation
    p = _record_design(tmp_path, 'path = "buoy.txt.gz"\nthreshold = "98%"\nperiod_ratio = 1.25')
    law = read_design(p).lifetime_model().period_law
    r = read_record(tmp_path / "buoy.txt.gz")
    s = storms(r, resolve_threshold(r, "quantile", 0.98), 48.0)
    ok = np.isfinite(s.period)
    b, ln_a = np.polyfit(np.log(s.peak[ok]), np.log(1.25 * s.period[ok]), 1)
    assert law == pytest.approx((np.exp(ln_a), b), rel=1e-9)
    # scipy's regression of the same logs
    reg = stats.linregress(np.log(s.peak[ok]), np.log(s.period[ok]))
    assert law[1] == pytest.approx(reg.slope, rel=1e-9)


def test_period_ratio_needs_a_period(tmp_path):
    t = np.datetime64("2000-01-01T00", "h") + np.arange(24 * 400)
    lines = ["time,hs"] + [f"{a},{1 + (h % 97) / 20:.2f}" for h, a in enumerate(t.astype(str))]
    p = _record_design(tmp_path, 'path = "nop.csv"\nthreshold = "90%"\ngap_hours = 1\nperiod_ratio = 1.2')
    (tmp_path / "nop.csv").write_text("\n".join(lines) + "\n")
    with pytest.raises(DesignFileError, match="period_ratio = 1.2: .*nop.csv gives no period"):
        read_design(p).lifetime_model()


def test_model_refuses_period_law_with_period():
    from regimemap.lifetime import LifetimeModel

    with pytest.raises(ValueError, match="period_law"):
        LifetimeModel(Climate.from_return_values(5.0, 6.3), period=10.0, period_law=(3.0, 0.6))


@pytest.mark.subprocess
@pytest.mark.deep
def test_the_chart_gains_the_width_at_the_bands_upper_level(run_cli, tmp_path):
    p = _record_design(tmp_path, 'path = "buoy.txt.gz"\nthreshold = "95%"', "climate_replicates = 3")
    args = ["lifetime", str(p), "--trials", "60", "--seed", "3", "--width", "16:64:3", "--json", "-q"]
    one = run_cli([*args, "--jobs", "1"])
    assert one.code in (0, 1), one.output  # 1: the design's width may fail its requirement
    two = run_cli([*args, "--jobs", "2", "--chunk", "50"])
    assert one.stdout == two.stdout
    band = json.loads(one.stdout)["climate_band"]
    assert band["replicates"] == 3 and band["widths"] == [16, 40, 64]
    assert all(lo <= hi for lo, hi in zip(band["lower"], band["upper"]))
    text = run_cli([*args[:-2], "-q"]).stdout
    assert "at the upper end of the 90 % climate band" in text
    w = band["width_for_target"]
    assert (f"{w:.2f} m" in text) if w is not None else "no width of the chart" in text
