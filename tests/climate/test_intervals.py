"""The return-value intervals (grid posterior, profile likelihood, bootstrap) against exact answers,
their seeds, and the guards of a fit that breaks."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy import optimize, stats

from regimemap.climate import ClimateOptions, analyse, fit, make_record
from regimemap.climate.file import read_record
from regimemap.climate.guards import XI_NONREGULAR, endpoint, fit_notices, limit_notices
from regimemap.climate.intervals import POSTERIOR_DRAWS, interval_band, likelihood_grid, profile_interval

DATA = Path(__file__).parent / "data"


def _gpd(xi, n, rng, u=3.0, sigma=1.0):
    p = rng.random(n)
    return u + (sigma / xi * (p ** -xi - 1.0) if xi != 0 else -sigma * np.log(p))


def test_posterior_draws_seeded_and_the_replicates_are_their_first():
    x = _gpd(-0.2, 45, np.random.default_rng(4))
    est = fit(x, "gpd", 3.0, 4.5)
    a = interval_band(x, est, "posterior", 30, seed=9, years=10.0)
    b = interval_band(x, est, "posterior", 30, seed=9, years=10.0)
    c = interval_band(x, est, "posterior", 30, seed=10, years=10.0)
    assert a.draws["rate"].size == POSTERIOR_DRAWS and len(a.fits) == 30
    np.testing.assert_array_equal(a.return_values(50), b.return_values(50))
    assert not np.array_equal(a.return_values(50), c.return_values(50))
    assert [f.parameters["xi"] for f in a.fits] == a.draws["xi"][:30].tolist()
    assert [f.rate for f in a.fits] == a.draws["rate"][:30].tolist()
    # the rate's posterior Gamma(N + 1/2, rate = years): its mean (N + 1/2)/T
    assert a.draws["rate"].mean() == pytest.approx(45.5 / 10.0, rel=0.03)
    assert a.label(0.9) == "90 % posterior interval"


def test_weibull_posterior_is_the_exact_one():
    """With k fixed and the prior 1/A, A^-k | y ~ Gamma(n, rate = sum y^k) and lambda | N ~
    Gamma(N + 1/2, rate = T): the grid posterior's interval of H_50 is that of exact draws."""
    rng = np.random.default_rng(12)
    k, u, years = 1.4, 2.0, 12.0
    y = stats.weibull_min.rvs(k, scale=0.8, size=40, random_state=rng)
    x = u + y
    est = fit(x, "weibull", u, 40 / years, shape=k)
    band = interval_band(x, est, "posterior", 10, seed=1, years=years, shape=k)
    m = 400_000
    a = rng.gamma(40.0, 1.0 / np.sum(y ** k), m) ** (-1.0 / k)
    lam = rng.gamma(40.5, 1.0 / years, m)
    exact = u + a * np.log(lam * 50.0) ** (1.0 / k)
    lo, hi = band.interval(50.0, 0.9)
    e_lo, e_hi = np.quantile(exact, [0.05, 0.95])
    assert lo == pytest.approx(e_lo, rel=0.01) and hi == pytest.approx(e_hi, rel=0.01)


def test_gumbel_profile_interval_against_a_direct_profile():
    """The grid's image of the likelihood region equals the interval where the profile
    likelihood of H_R (maximised over A with B = H_R + A ln y) crosses the chi-square cut."""
    rng = np.random.default_rng(3)
    x = stats.gumbel_r.rvs(loc=5.0, scale=0.6, size=18, random_state=rng)
    est = fit(x, "gumbel")
    grid = likelihood_grid(x, est)
    R, level = 50.0, 0.9
    ly = math.log(-math.log1p(-1.0 / R))

    def ll(b, a):
        z = (x - b) / a
        return float(-x.size * math.log(a) - z.sum() - np.exp(-z).sum())

    top = ll(est.parameters["B"], est.parameters["A"])

    def profile(h):
        r = optimize.minimize_scalar(lambda la: -ll(h + math.exp(la) * ly, math.exp(la)),
                                     bounds=(math.log(0.05), math.log(5.0)), method="bounded",
                                     options={"xatol": 1e-10})
        return -float(r.fun) - top + 0.5 * stats.chi2.ppf(level, 1)

    h = est.return_value(R)
    lo = optimize.brentq(profile, h - 5.0, h)
    hi = optimize.brentq(profile, h, h + 10.0)
    g_lo, g_hi = profile_interval(grid, R, level)
    assert g_lo == pytest.approx(lo, rel=2e-3) and g_hi == pytest.approx(hi, rel=2e-3)


def test_profile_includes_the_storm_count():
    """With the rate profiled the interval is wider than with the rate fixed at N/T."""
    x = _gpd(0.0, 30, np.random.default_rng(8))
    est = fit(x, "gpd", 3.0, 3.0)
    grid = likelihood_grid(x, est, 10.0)
    lo, hi = profile_interval(grid, 100.0, 0.9)
    ok = grid.loglik >= -0.5 * stats.chi2.ppf(0.9, 1)
    from regimemap.climate.fits import return_levels

    params = {k: v[ok] for k, v in grid.parameters.items()}
    h = return_levels("gpd", params, 3.0, np.full(int(ok.sum()), 3.0), 100.0)  # the rate fixed at N/T
    assert lo < h.min() < h.max() < hi


@pytest.mark.parametrize("method", ["posterior", "profile", "bootstrap"])
def test_each_method_brackets_the_estimate_of_a_regular_fit(method):
    x = _gpd(0.1, 60, np.random.default_rng(21))
    est = fit(x, "gpd", 3.0, 6.0)
    band = interval_band(x, est, method, 60, seed=2, years=10.0)
    for R in (10.0, 50.0):
        lo, hi = band.interval(R, 0.9)
        lo95, hi95 = band.interval(R, 0.95)
        assert lo < est.return_value(R) < hi
        assert lo95 <= lo and hi <= hi95
    assert band.method == method and len(band.fits) <= 60


def test_options_old_spelling_and_unknown_method():
    assert ClimateOptions(bootstrap=40).replicates == 40 and ClimateOptions(bootstrap=40).bootstrap == 40
    assert ClimateOptions().bootstrap == 200  # read back, the old name is the replicates
    assert ClimateOptions().interval == "posterior"
    with pytest.raises(ValueError, match="interval must be one of posterior, profile, bootstrap"):
        ClimateOptions(interval="bayes").check()


# -- the guards ---------------------------------------------------------------------------------------

def test_the_thirteen_month_reproduction_warns():
    """One year of 44007 above its 97 % quantile: xi = -1.5 at the search bound, H10 = H50 = H100 = the
    record's maximum; now warned, and the posterior's interval does not collapse onto the maximum."""
    record = read_record(DATA / "ndbc44007_1996_hs_tz.txt.gz")
    r = analyse(record, ClimateOptions(threshold=("quantile", 0.97)))
    assert r.fit.parameters["xi"] < -1.0
    bound = [n for n in r.notices if "search bound" in n.message]
    assert len(bound) == 1 and bound[0].quantity == "xi" and bound[0].value == r.fit.parameters["xi"]
    assert r.endpoint == pytest.approx(float(r.sample.max()), abs=1e-6)
    fifty = r.return_values[1]
    assert fifty["upper"] > fifty["value"] + 1.0
    assert any(n.quantity == "H50" and "above the largest height" in n.message for n in r.notices)


@pytest.mark.slow
def test_gev_at_its_search_bound_and_above_a_limit():
    x = [3.0, 3.05, 3.1, 3.02, 3.0, 3.08, 12.0, 3.04, 3.1, 3.03, 3.01, 3.06, 14.0]
    g = fit(x, "gev")
    found = fit_notices(g, x, 13.0, 100.0)
    assert any("GEV shape reached its search bound xi = 1.5" in n.message for n in found)
    rv = [{"period": 100.0, "value": g.return_value(100.0), "lower": 5.0, "upper": 40.0}]
    flagged = limit_notices(rv, 20.0, "the depth-limited breaker height")
    assert [n.quantity for n in flagged] == ["H100", "H100"]
    assert "depth-limited breaker height (20 m)" in flagged[0].message
    assert limit_notices(rv, 50.0, "x") == []


@pytest.mark.parametrize(("xi", "words"), [(-0.6, "non-regular"), (-0.9, "approaches -1")])
def test_gpd_shape_warnings(xi, words):
    from regimemap.climate.fits import Fit

    x = np.linspace(3.1, 3.0 - 1.0 / xi - 0.3, 40)  # the end point 0.3 m above the largest
    f = Fit("gpd", {"sigma": 1.0, "xi": xi}, 3.0, 4.0, 40)
    found = fit_notices(f, x, 10.0, 50.0)
    assert xi < XI_NONREGULAR
    assert any(words in n.message and n.value == xi for n in found)
    close = [n for n in found if n.quantity == "endpoint"]
    assert len(close) == 1 and close[0].value == pytest.approx(endpoint(f))
    # a record as long as the return period is not short: no end-point warning
    assert not [n for n in fit_notices(f, x, 60.0, 50.0) if n.quantity == "endpoint"]


def test_endpoint_reported_only_for_a_bounded_tail():
    from regimemap.climate.fits import Fit

    assert endpoint(Fit("gpd", {"sigma": 1.2, "xi": 0.1}, 3.0, 4.0, 40)) is None
    assert endpoint(Fit("gpd", {"sigma": 1.2, "xi": -0.3}, 3.0, 4.0, 40)) == pytest.approx(7.0)


@pytest.mark.slow
def test_threshold_sensitivity_refits_each_quantile():
    from regimemap.climate.analysis import SENSITIVITY_QUANTILES, sensitivity

    rng = np.random.default_rng(5)
    t = np.datetime64("2000-01-01T00", "s") + np.arange(4 * 8760) * np.timedelta64(3600, "s")
    hs = 1.0 + np.convolve(rng.gamma(0.6, 1.0, t.size), np.ones(12) / 6.0, mode="same")
    rec = make_record("synthetic", t, hs)
    opts = ClimateOptions(threshold=("quantile", 0.99), return_periods=(10.0, 50.0), replicates=20, seed=3)
    s = sensitivity(rec, opts)
    assert s is not None and s.period == 50.0 and s.interval == "posterior"
    assert np.all(np.diff(s.thresholds) > 0) and np.all(np.diff(s.storms) <= 0)
    at = SENSITIVITY_QUANTILES.index(0.99)
    main = analyse(rec, opts)
    assert s.value[at] == pytest.approx(main.return_values[1]["value"], rel=1e-12)
    ok = np.isfinite(s.value)
    assert ok.sum() >= 4 and np.all(s.lower[ok] < s.upper[ok])
    assert sensitivity(rec, ClimateOptions(replicates=0)) is None


def test_stability_panels_have_their_intervals():
    from regimemap.climate.analysis import diagnostics

    d = diagnostics(read_record(DATA / "ndbc44007_1996_hs_tz.txt.gz"), points=6, confidence=0.9)
    assert d.xi_interval.shape == (6, 2) and d.sigma_star_interval.shape == (6, 2)
    fitted = np.isfinite(d.xi)
    assert fitted.sum() >= 3
    assert np.all(np.isnan(d.xi_interval[~fitted]))
    lo, hi = d.xi_interval[fitted].T
    assert np.all(lo < hi) and np.all(lo >= -1.0) and np.all(hi <= 1.5)
    s_lo, s_hi = d.sigma_star_interval[fitted].T
    assert np.all(s_lo < s_hi)


@pytest.mark.render
@pytest.mark.parametrize(("method", "label"), [("posterior", "90 % posterior interval"),
                                               ("profile", "90 % profile-likelihood interval"),
                                               ("bootstrap", "90 % bootstrap interval")])
def test_the_figure_names_the_method(method, label):
    from regimemap.climate.analysis import curves
    from regimemap.climate.figures import climate_figure

    r = analyse(read_record(DATA / "ndbc44007_1996_hs_tz.txt.gz"),
                ClimateOptions(threshold=("quantile", 0.99), interval=method,
                               replicates=40 if method == "bootstrap" else 20))  # 40: a 90 % bootstrap's least
    fig = climate_figure(r, curves(r))
    ax = next(a for a in fig.axes if a.get_label() == "return levels")
    assert label in [t.get_text() for t in ax.get_legend().get_texts()]


def test_gev_posterior_on_a_three_dimensional_grid():
    rng = np.random.default_rng(6)
    x = stats.genextreme.rvs(0.1, loc=6.0, scale=0.8, size=25, random_state=rng)  # xi = -0.1
    est = fit(x, "gev")
    band = interval_band(x, est, "posterior", 10, seed=4)
    assert band.grid is not None and band.grid.names == ("mu", "ln_sigma", "xi")
    assert np.all(band.draws["rate"] == 1.0)  # annual maxima: no storm rate to draw
    lo, hi = band.interval(50.0, 0.9)
    assert lo < est.return_value(50.0) < hi
    assert np.all((band.draws["xi"] >= -1.0) & (band.draws["xi"] <= 1.5))


def test_the_lifetimes_replicate_climates_are_the_posterior_draws():
    from regimemap.climate.life import replicate_climates

    r = analyse(read_record(DATA / "ndbc44007_1996_hs_tz.txt.gz"),
                ClimateOptions(threshold=("quantile", 0.99), replicates=12, seed=8))
    assert r.band is not None and r.band.method == "posterior"
    climates = replicate_climates(r)
    assert len(climates) == 12
    assert [c.shape for c in climates] == r.band.draws["xi"][:12].tolist()
    assert [c.storms_per_year for c in climates] == r.band.draws["rate"][:12].tolist()


def test_a_bootstrap_interval_needs_two_replicates_in_each_tail():
    from regimemap.climate.intervals import bootstrap_minimum

    assert [bootstrap_minimum(c) for c in (0.5, 0.9, 0.95, 0.99, 0.999)] == [8, 40, 80, 400, 4000]
    ClimateOptions(interval="bootstrap", replicates=40).check()
    ClimateOptions(interval="bootstrap", replicates=0).check()  # no interval
    ClimateOptions(interval="posterior", replicates=1).check()  # the posterior draws its own
    with pytest.raises(ValueError, match=r"^replicates must be 0 \(no interval\) or at least 80 for a 95 %"):
        ClimateOptions(interval="bootstrap", replicates=79, confidence=0.95).check()
    with pytest.raises(ValueError, match=r"^shape must be a Weibull k > 0, got nan"):
        ClimateOptions(shape=float("nan")).check()  # whatever the distribution
