"""A non-stationary design life: the climate's trend by service year, and the sliding by year.

Today's climate with or without a stationary trend gives the numbers the engine gave before
trends existed (pinned here, to the relative 1e-12 of docs/guide/development.md across CPUs,
and bit for bit between the two in one run); each part of a trend moves the life the way it
must; the expected cumulative sliding by service year ends at the ESD and does not depend on
the chunks.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
import pytest
from scipy import stats

from regimemap.lifetime import Climate, LifetimeModel, YearTrend, design_chart, lifetime_sliding
from regimemap.lifetime.engine import BLOCK, _draw_storms, _storm_seas
from regimemap.lifetime.parallel import make_chunks, run_chunks
from regimemap.lifetime.results import LifetimeResult, year_passing
from regimemap.waves import design_heights

from ._cases import GODA, MODEL, NO_ERRORS

#: The relative tolerance of the lifetime sums across machines (docs/guide/development.md).
REL = 1e-12

POISSON_TIDE = LifetimeModel(Climate.from_return_values(5.0, 6.3, storms_per_year=3.0), years=20,
                             tide_range=2.0)

#: Taken with the engine before trends existed (regimemap 1d8cfa9): 250 lifetimes, seed 11,
#: chunks of 100, Goda's caisson 12 m wide -- the sum and the largest storm's slide as hex
#: floats, and the number of storms.
BEFORE = {
    "goda": (MODEL, "0x1.d696a0ee017a7p+10", "0x1.a23cabed54170p+7", 12500),
    "poisson-tide": (POISSON_TIDE, "0x1.1c1367cefe6c1p+10", "0x1.c2af438193c50p+8", 14966),
}
#: The same engine's chart of Goda's caisson at 11, 14, 18 m (200 lifetimes, seed 5, target 0.3 m).
BEFORE_CHART = (("0x1.1aae6a5b3b30ap+4", "0x1.c8fe13ace14dfp+0", "0x1.26bed6ebc1fe0p-5"), 16.0625)


def _trend(years: int, sea_level: float = 0.0, wave_height: float = 1.0, storm_rate: float = 1.0) -> YearTrend:
    return YearTrend((sea_level,) * years, (wave_height,) * years, (storm_rate,) * years)


def _run(model: LifetimeModel, width: float = 16.0, trials: int = 1000, seed: int = 2,
         **kw: Any) -> LifetimeResult:
    return lifetime_sliding(GODA.with_width(width), model, trials=trials, seed=seed, **kw)


# -- today's climate ------------------------------------------------------------------------------

@pytest.mark.portable
@pytest.mark.parametrize("name", sorted(BEFORE))
def test_no_trend_and_a_stationary_trend_give_the_numbers_of_before(name):
    model, total, largest, storms = BEFORE[name]
    none = _run(model, width=12.0, trials=250, seed=11, chunk=100)
    flat = _run(model.with_(trend=YearTrend.stationary(model.years)), width=12.0, trials=250, seed=11, chunk=100)
    for a, b in ((none.sliding, flat.sliding), (none.max_storm, flat.max_storm), (none.storms, flat.storms),
                 (none.by_year, flat.by_year), (none.by_year_error, flat.by_year_error)):
        assert np.array_equal(a, b)
    np.testing.assert_allclose(none.sliding.sum(), float.fromhex(total), rtol=REL, atol=0)
    np.testing.assert_allclose(none.max_storm.max(), float.fromhex(largest), rtol=REL, atol=0)
    assert int(none.storms.sum()) == storms


@pytest.mark.portable
@pytest.mark.slow
def test_the_chart_of_today_s_climate_is_the_chart_of_before():
    esd, found = BEFORE_CHART
    for trend in (None, YearTrend.stationary(MODEL.years)):
        c = design_chart(GODA, MODEL.with_(trend=trend), [11.0, 14.0, 18.0], trials=200, seed=5, target=0.3)
        np.testing.assert_allclose(c.expected_sliding, [float.fromhex(x) for x in esd], rtol=REL, atol=0)
        assert c.width_for_target == found
        assert c.by_year.shape == (3, MODEL.years)
        np.testing.assert_allclose(c.by_year[:, -1], c.expected_sliding, rtol=REL, atol=0)


# -- each part of a trend -------------------------------------------------------------------------

def test_the_sea_level_adds_to_the_depth_terms_like_the_tide():
    rise = 0.7
    model = MODEL.with_(errors=NO_ERRORS, trend=_trend(MODEL.years, sea_level=rise))
    ss = np.random.SeedSequence(4).spawn(1)
    caissons = (GODA,)
    seas = _storm_seas(caissons, model, [_draw_storms(model, ss[0], 20, 0)])
    today = _storm_seas(caissons, MODEL.with_(errors=NO_ERRORS, tide_range=0.0),
                        [_draw_storms(MODEL, ss[0], 20, 0)])
    np.testing.assert_array_equal(seas.depth, GODA.depth + rise)
    np.testing.assert_array_equal(seas.base_depth, GODA.base_depth + rise)
    np.testing.assert_array_equal(seas.armour_depth, GODA.armour_depth + rise)
    np.testing.assert_array_equal(seas.crest, GODA.crest - rise)
    np.testing.assert_array_equal(seas.H0, today.H0)  # the rise moves no random number


@pytest.mark.slow
def test_sea_level_rise_in_depth_limited_water_raises_the_esd():
    # Goda's site is in the surf zone: the highest waves at the wall under the 50-year storm break,
    # and their height grows with the depth (Hmax 7.98 m at h = 10.1 m, 8.63 m at 11.1 m)
    T = 3.3 * 6.3**0.63
    shallow = design_heights(6.3, T, GODA.depth, GODA.seabed_slope).Hmax
    deeper = design_heights(6.3, T, GODA.depth + 1.0, GODA.seabed_slope).Hmax
    assert deeper > shallow * 1.05
    base = _run(MODEL)
    esd = [base.expected_sliding]
    for rise in (0.5, 1.0):
        r = _run(MODEL.with_(trend=_trend(MODEL.years, sea_level=rise)))
        assert np.array_equal(r.storms, base.storms)
        esd.append(r.expected_sliding)
    assert esd[0] < esd[1] < esd[2]
    assert esd[2] - esd[0] > 3.0 * math.hypot(base.std_error, r.std_error)


@pytest.mark.slow
def test_a_rise_year_by_year_slides_more_in_the_late_years():
    years = MODEL.years
    rising = YearTrend(tuple(1.0 * y / (years - 1) for y in range(years)), (1.0,) * years, (1.0,) * years)
    r = _run(MODEL.with_(trend=rising), trials=2000)
    base = _run(MODEL, trials=2000)
    half = years // 2
    early = r.by_year[half - 1]
    late = r.by_year[-1] - r.by_year[half - 1]
    assert late > early
    assert r.expected_sliding > base.expected_sliding


def test_a_wave_height_factor_above_one_raises_the_esd():
    base = _run(MODEL)
    up = _run(MODEL.with_(trend=_trend(MODEL.years, wave_height=1.1)))
    down = _run(MODEL.with_(trend=_trend(MODEL.years, wave_height=0.9)))
    assert np.array_equal(up.storms, base.storms)
    assert down.expected_sliding < base.expected_sliding < up.expected_sliding


@pytest.mark.deep
def test_a_storm_rate_factor_of_two_doubles_the_mean_number_of_storms():
    model = LifetimeModel(Climate.from_return_values(5.0, 6.3, storms_per_year=3.0), years=20)
    n = 4000
    base = _run(model, trials=n)
    double = _run(model.with_(trend=_trend(20, storm_rate=2.0)), trials=n)
    assert abs(base.storms.mean() - 60.0) < 4.0 * math.sqrt(60.0 / n)
    assert abs(double.storms.mean() - 120.0) < 4.0 * math.sqrt(120.0 / n)
    # doubled in the last ten years only: 3 (10 + 2 x 10) storms on average
    half = YearTrend((0.0,) * 20, (1.0,) * 20, (1.0,) * 10 + (2.0,) * 10)
    r = _run(model.with_(trend=half), trials=n)
    assert abs(r.storms.mean() - 90.0) < 4.0 * math.sqrt(90.0 / n)
    assert r.by_year[9] < r.by_year[-1] - r.by_year[9]


@pytest.mark.parametrize("f", [2, 3])
def test_an_annual_maximum_rate_factor_is_the_maximum_of_f_annual_maxima(f):
    """The year's peak with factor f is distributed as the largest of f independent annual maxima."""
    years, n = 10, 2000
    model = MODEL.with_(years=years, errors=NO_ERRORS, trend=_trend(years, storm_rate=float(f)))
    stream = np.random.SeedSequence(8).spawn(1)[0]
    peaks = _storm_seas((GODA,), model, [_draw_storms(model, stream, n, 0)]).H0
    assert peaks.size == years * n  # still one storm a year
    rng = np.random.default_rng(9)
    brute = model.climate.quantile(rng.random((f, peaks.size))).max(axis=0)
    assert stats.ks_2samp(peaks, brute).pvalue > 1e-3
    # and not the annual maxima of today (the test can tell them apart)
    today = model.climate.quantile(rng.random(peaks.size))
    assert stats.ks_2samp(peaks, today).pvalue < 1e-6
    # its distribution function is F**f (scipy's one-sample test against it)
    assert stats.kstest(peaks, lambda x: model.climate.cdf(x) ** f).pvalue > 1e-3


# -- the sliding by service year ------------------------------------------------------------------

def test_by_year_rises_to_the_esd_with_its_error():
    model = MODEL.with_(trend=_trend(MODEL.years, sea_level=0.5))
    r = _run(model, trials=730, chunk=200)
    assert r.by_year.shape == r.by_year_error.shape == (MODEL.years,)
    assert np.all(np.diff(r.by_year) >= 0.0)
    assert r.by_year[0] >= 0.0
    np.testing.assert_allclose(r.by_year[-1], r.expected_sliding, rtol=REL, atol=0)
    np.testing.assert_allclose(r.by_year_error[-1], r.std_error, rtol=1e-9, atol=0)


def test_year_passing_is_the_first_year_over_the_limit():
    r = _run(MODEL.with_(trend=_trend(MODEL.years, sea_level=0.5)))
    limit = 0.5 * r.expected_sliding
    y = r.year_passing(limit)
    assert y is not None and 1 <= y <= MODEL.years
    assert r.by_year[y - 1] > limit
    assert y == 1 or r.by_year[y - 2] <= limit
    assert r.year_passing(2.0 * r.expected_sliding) is None
    assert r.year_passing(-1.0) == 1
    assert year_passing(np.array([0.0, 0.1, 0.1, 0.3]), 0.1) == 4
    bare = LifetimeResult(sliding=np.zeros(3), max_storm=np.zeros(3), storms=np.ones(3, dtype=np.int64),
                          seed=1, years=1, thresholds=(), width=10.0)
    with pytest.raises(ValueError, match="by service year"):
        bare.year_passing(0.1)


@pytest.mark.slow
def test_by_year_is_the_same_bits_for_any_chunks_and_jobs_with_a_trend():
    years = 30
    trend = YearTrend(tuple(0.02 * y for y in range(years)), tuple(1.0 + 0.004 * y for y in range(years)),
                      tuple(1.0 + 0.02 * y for y in range(years)))
    model = POISSON_TIDE.with_(years=years, trend=trend)
    trials = 2 * BLOCK + 37
    ref = _run(model, width=14.0, trials=trials, chunk=100)
    for kw in (dict(chunk=300), dict(chunk=200, jobs=2)):
        r = _run(model, width=14.0, trials=trials, **kw)
        for a, b in ((r.sliding, ref.sliding), (r.max_storm, ref.max_storm), (r.storms, ref.storms),
                     (r.by_year, ref.by_year), (r.by_year_error, ref.by_year_error)):
            assert np.array_equal(a, b), kw
    widths = tuple(GODA.with_width(w) for w in (12.0, 16.0))
    a = run_chunks(widths, model, make_chunks(trials, 3, 100))
    b = run_chunks(widths, model, make_chunks(trials, 3, 1000))
    assert np.array_equal(a.years.mean(), b.years.mean())
    assert a.years.sums.shape == (math.ceil(trials / BLOCK), 2, years)  # per block, never per lifetime


# -- bad input ------------------------------------------------------------------------------------

@pytest.mark.parametrize("kw, words", [
    (dict(sea_level=(0.0, math.nan, 0.0)), "sea_level of service year 2 (of 1..3)"),
    (dict(wave_height=(1.0, 1.0, 0.0)), "wave_height of service year 3 (of 1..3) must be a finite factor > 0"),
    (dict(storm_rate=(-1.0, 1.0, 1.0)), "storm_rate of service year 1 (of 1..3)"),
    (dict(storm_rate=(1.0, math.inf, 1.0)), "storm_rate of service year 2"),
    (dict(wave_height=(1.0, 1.0)), "wave_height has 2 service years, sea_level 3"),
])
def test_a_bad_trend_is_refused_naming_field_year_and_range(kw, words):
    fields = dict(sea_level=(0.0,) * 3, wave_height=(1.0,) * 3, storm_rate=(1.0,) * 3)
    fields.update(kw)
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")):
        YearTrend(**fields)


def test_a_trend_must_cover_the_design_life():
    with pytest.raises(ValueError, match="trend covers 3 service years, the design life is 50 years"):
        MODEL.with_(trend=YearTrend.stationary(3))
    with pytest.raises(ValueError, match="at least one service year"):
        YearTrend((), (), ())
    with pytest.raises(ValueError, match="whole number >= 1"):
        YearTrend.stationary(0)
    assert YearTrend([0.1, 0.2], [1, 1], [1, 2]).sea_level == (0.1, 0.2)  # any sequence, kept as floats


@pytest.mark.parametrize("level, words", [
    (-6.0, r"sea_level of service year 1 = -6 m leaves the mound dry: the sea level must be in "
           r"\(-5\.6, 3\.4\) m \(armour depth d = 5\.6 m, crest hc = 3\.4 m\)"),
    (3.5, r"= 3\.5 m puts the crest under water"),
])
def test_a_sea_level_off_the_structure_is_refused_before_any_storm(level, words):
    model = MODEL.with_(trend=_trend(MODEL.years, sea_level=level))
    with pytest.raises(ValueError, match=words):
        lifetime_sliding(GODA, model, trials=10, seed=1)
    with pytest.raises(ValueError, match=words):
        design_chart(GODA, model, [12.0, 14.0], trials=10, seed=1)
    _trend(MODEL.years, sea_level=3.3).check_site(GODA)  # inside: no error
    YearTrend.stationary(3).check_site(replace(GODA, crest=-1.0))  # today's level: today's site
