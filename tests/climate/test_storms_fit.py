"""Storms against a brute force, annual maxima, the fits against scipy.stats, the bootstrap."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from regimemap.climate import ClimateOptions, analyse, annual_maxima, bootstrap, fit, make_record, storms
from regimemap.climate.file import read_record
from regimemap.climate.peaks import parse_threshold, resolve_threshold

DATA = Path(__file__).parent / "data"
HOUR = np.timedelta64(3600, "s")


def _record(hs, step=1, start="2000-01-01T00"):
    t = np.datetime64(start, "s") + np.arange(len(hs)) * step * HOUR
    return make_record("x", t, np.asarray(hs, dtype=float))


def _brute_storms(times, hs, u, gap):
    """Connected components of the exceedances, two joined when at most ``gap`` hours apart."""
    idx = [i for i in range(len(hs)) if np.isfinite(hs[i]) and hs[i] > u]
    parent = list(range(len(idx)))

    def root(a):
        while parent[a] != a:
            a = parent[a]
        return a

    for a in range(len(idx)):
        for b in range(a + 1, len(idx)):
            if abs(times[idx[b]] - times[idx[a]]) <= gap:
                parent[root(b)] = root(a)
    groups = {}
    for a, i in enumerate(idx):
        groups.setdefault(root(a), []).append(i)
    return sorted((max(hs[i] for i in g), len(g)) for g in groups.values())


@pytest.mark.parametrize("seed", range(6))
def test_declustering_matches_brute_force(seed):
    rng = np.random.default_rng(seed)
    n = 400
    hs = np.abs(np.cumsum(rng.normal(0, 0.3, n))) + rng.random(n)
    hs[rng.random(n) < 0.05] = np.nan
    step = [1, 3][seed % 2]
    r = _record(hs, step)
    gap = float(rng.integers(1, 30))
    u = float(np.nanquantile(hs, 0.8))
    s = storms(r, u, gap)
    brute = _brute_storms(np.arange(n) * step, hs, u, gap)
    assert sorted(zip(s.peak.tolist(), (s.duration / step).astype(int).tolist())) == brute
    assert s.rate == pytest.approx(s.count / r.years)


def test_storm_period_and_peak_time():
    hs = [1, 3, 5, 3, 1, 1, 1, 1, 4, 1]
    t = np.datetime64("2000-01-01T00", "s") + np.arange(10) * HOUR
    r = make_record("x", t, np.array(hs, float), period=np.arange(10.0) + 5, period_name="Tp")
    s = storms(r, 2.0, gap_hours=2)
    assert s.peak.tolist() == [5.0, 4.0]
    assert s.period.tolist() == [7.0, 13.0]
    assert str(s.peak_time[1]) == "2000-01-01T08:00:00"
    with pytest.raises(ValueError, match="gap must be a number of hours > 0"):
        storms(r, 2.0, gap_hours=0)


def test_threshold_parsing_and_resolving():
    assert parse_threshold("99%") == ("quantile", 0.99)
    for bad in ("0%", "100%", "-1", "abc", "nan"):
        with pytest.raises(ValueError, match="threshold must be"):
            parse_threshold(bad)
    r = _record(np.linspace(0.5, 3.0, 100))
    assert resolve_threshold(r, "quantile", 0.9) == pytest.approx(np.quantile(np.linspace(0.5, 3, 100), 0.9))
    with pytest.raises(ValueError, match="at or above every height"):
        resolve_threshold(r, "value", 3.0)


def test_annual_maxima_skip_poor_years():
    t = np.datetime64("2000-01-01T00", "s") + np.arange(8784 + 2 * 8760) * HOUR
    hs = 1.0 + (np.arange(t.size) % 1000) / 1000.0
    year = t.astype("datetime64[Y]").astype(int) + 1970
    hs[(year == 2001) & (np.arange(t.size) % 2 == 0)] = np.nan  # 2001 half observed
    am = annual_maxima(make_record("x", t, hs), coverage=0.8)
    assert am.years.tolist() == [2000, 2002]
    assert am.skipped == [2001]
    assert am.maxima.tolist() == [float(np.nanmax(hs[year == y])) for y in (2000, 2002)]


def _loglik(dist, x):
    return float(np.sum(dist.logpdf(x)))


@pytest.mark.parametrize("xi", [-0.4, -0.1, 0.0, 0.2, 0.5])
def test_gpd_against_scipy(xi):
    rng = np.random.default_rng(11)
    u = 3.0
    x = stats.genpareto.rvs(xi, loc=u, scale=1.2, size=60, random_state=rng)
    ours = fit(x, "gpd", u, rate=6.0)
    c, loc, scale = stats.genpareto.fit(x, floc=u)
    assert loc == u
    # the same maximum (ours never lower), the same parameters to the optimiser's tolerance
    assert _loglik(ours.frozen(), x) >= _loglik(stats.genpareto(c, loc=u, scale=scale), x) - 1e-9
    assert ours.parameters["xi"] == pytest.approx(c, abs=2e-3)
    assert ours.parameters["sigma"] == pytest.approx(scale, rel=2e-3)
    # H_R = u + sigma/xi ((lambda R)^xi - 1)
    s, k = ours.parameters["sigma"], ours.parameters["xi"]
    closed = u + s * math.log(6 * 50) if k == 0 else u + s / k * ((6 * 50) ** k - 1)
    assert ours.return_value(50) == pytest.approx(closed, rel=1e-10)


def test_weibull_gumbel_against_scipy():
    rng = np.random.default_rng(5)
    u = 2.0
    x = stats.weibull_min.rvs(1.4, loc=u, scale=0.9, size=50, random_state=rng)
    w = fit(x, "weibull", u, rate=4.0, shape=1.4)
    _, _, scale = stats.weibull_min.fit(x, fc=1.4, floc=u)
    assert w.parameters["A"] == pytest.approx(scale, rel=1e-4)  # scipy's optimiser
    assert w.parameters["A"] == pytest.approx(np.mean((x - u) ** 1.4) ** (1 / 1.4), rel=1e-12)
    assert _loglik(w.frozen(), x) >= _loglik(stats.weibull_min(1.4, loc=u, scale=scale), x)
    assert w.return_value(100) == pytest.approx(u + w.parameters['A'] * math.log(400) ** (1 / 1.4), rel=1e-10)
    g = stats.gumbel_r.rvs(loc=5, scale=0.7, size=25, random_state=rng)
    gf = fit(g, "gumbel")
    loc, sc = stats.gumbel_r.fit(g)
    assert (gf.parameters["B"], gf.parameters["A"]) == pytest.approx((loc, sc), rel=1e-9)
    assert gf.return_value(50) == pytest.approx(loc - sc * math.log(-math.log(1 - 1 / 50)), rel=1e-10)


@pytest.mark.parametrize("xi", [-0.3, 0.0, 0.2])
@pytest.mark.slow
def test_gev_against_scipy_sign_convention(xi):
    rng = np.random.default_rng(8)
    x = stats.genextreme.rvs(-xi, loc=5, scale=0.8, size=40, random_state=rng)
    ours = fit(x, "gev")
    c, loc, scale = stats.genextreme.fit(x)
    assert ours.parameters["xi"] == pytest.approx(-c, abs=2e-3)  # scipy's c = -xi
    assert _loglik(ours.frozen(), x) >= _loglik(stats.genextreme(c, loc=loc, scale=scale), x) - 1e-7
    p = ours.parameters
    closed = p["mu"] + p["sigma"] / p["xi"] * ((-math.log(1 - 1 / 50)) ** -p["xi"] - 1)
    assert ours.return_value(50) == pytest.approx(closed, rel=1e-9)


def test_fit_refuses_too_few():
    with pytest.raises(ValueError, match="a fit needs at least 10"):
        fit([3.1, 3.5, 4.0], "gpd", 3.0)
    with pytest.raises(ValueError, match="at least 5 years"):
        fit([3.1, 3.5, 4.0], "gumbel")
    with pytest.raises(ValueError, match="distribution must be one of"):
        fit([3.1] * 12, "lognormal")


def test_bootstrap_seeded_and_order_free():
    rng = np.random.default_rng(2)
    x = stats.genpareto.rvs(-0.1, loc=3, scale=1, size=40, random_state=rng)
    est = fit(x, "gpd", 3.0, rate=4.0)
    a = bootstrap(x, est, 30, seed=7, years=10.0)
    b = bootstrap(x, est, 30, seed=7, years=10.0)
    np.testing.assert_array_equal(a.return_values(50), b.return_values(50))
    # replicate i depends only on the i-th child seed: the first 10 of 30 are the 10 of a run of 10
    c = bootstrap(x, est, 10, seed=7, years=10.0)
    np.testing.assert_array_equal(a.return_values(50)[:10], c.return_values(50))
    # Poisson storm counts: the rates vary around N/years
    rates = [f.rate for f in a.fits]
    assert len(set(rates)) > 3 and np.mean(rates) == pytest.approx(4.0, rel=0.2)
    lo, hi = a.interval(50, 0.9)
    assert lo < est.return_value(50) < hi


def test_analyse_real_excerpt():
    r = read_record(DATA / "ndbc44007_1996_hs_tz.txt.gz")
    res = analyse(r, ClimateOptions(threshold=("quantile", 0.99), bootstrap=20, seed=1))
    assert res.storms is not None and res.storms.count >= 10
    assert [v["period"] for v in res.return_values] == [10.0, 50.0, 100.0]
    assert all(v["lower"] <= v["upper"] for v in res.return_values)
    with pytest.raises(ValueError, match="a fit needs at least 10"):
        analyse(r, ClimateOptions(threshold=("value", 6.0), bootstrap=0))
    with pytest.raises(ValueError, match="needs at least 1 year"):
        analyse(make_record("short", r.time[:2000], r.hs[:2000]), ClimateOptions())


@pytest.mark.parametrize(("dist", "params", "u", "rate"), [
    ("gpd", {"sigma": 1.3, "xi": -0.3}, 4.0, 6.0), ("gpd", {"sigma": 1.3, "xi": 0.0}, 4.0, 6.0),
    ("gpd", {"sigma": 0.9, "xi": 0.25}, 2.0, 3.0), ("weibull", {"A": 0.9, "k": 1.3}, 2.0, 5.0),
    ("gumbel", {"A": 0.7, "B": 5.7}, None, 1.0), ("gev", {"mu": 6.0, "sigma": 0.9, "xi": -0.2}, None, 1.0),
    ("gev", {"mu": 6.0, "sigma": 0.9, "xi": 0.15}, None, 1.0),
])
def test_closed_form_return_values_equal_scipy_isf(dist, params, u, rate):
    from regimemap.climate.fits import Fit

    f = Fit(distribution=dist, parameters=params, threshold=u, rate=rate, n=20)
    for R in (2.0, 10.0, 50.0, 1000.0):
        assert f.return_value(R) == pytest.approx(float(f.frozen().isf(1.0 / (rate * R))), rel=1e-12)
