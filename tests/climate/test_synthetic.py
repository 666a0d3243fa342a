"""The synthetic records of known truth: their storms are Poisson with GPD peaks, the declustering
finds exactly them, and the truth's closed form agrees with a brute-force root."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, stats

from regimemap.climate import storms
from regimemap.climate.peaks import resolve_threshold
from regimemap.climate.synthetic import (
    DEFAULT_STORM_HOURS,
    HOURS_PER_YEAR,
    SyntheticClimate,
    record_seeds,
    synthetic_hs,
    synthetic_record,
)

CLIMATES = [SyntheticClimate(sigma=1.0, xi=-0.3, rate=8.0, base=3.0),
            SyntheticClimate(sigma=0.6, xi=0.0, rate=8.0, base=3.0),
            SyntheticClimate(sigma=0.3, xi=0.4, rate=5.0, base=2.0)]


@pytest.mark.parametrize("c", CLIMATES, ids=lambda c: f"xi={c.xi:g}")
def test_peaks_are_gpd_over_the_base(c):
    """A KS test of 200 years' excesses (about 1,600) against GPD(sigma, xi): a false alarm once
    in 1,000 seeds (the seed is fixed: the test is deterministic)."""
    _, peaks = synthetic_hs(c, 200.0, seed=11)
    assert peaks.size > 500
    p = stats.kstest(peaks - c.base, stats.genpareto(c.xi, scale=c.sigma).cdf).pvalue
    assert p > 1e-3


def test_a_wrong_shape_fails_the_same_test():
    """The KS test above can fail: the excesses of xi = 0 are no GPD of xi = 0.3."""
    c = CLIMATES[1]
    _, peaks = synthetic_hs(c, 200.0, seed=11)
    assert stats.kstest(peaks - c.base, stats.genpareto(0.3, scale=c.sigma).cdf).pvalue < 1e-6


def test_counts_are_poisson():
    """300 one-year records: the mean count is lambda within 4 standard errors, and the dispersion
    index sum (N - mean)^2 / mean is chi-square with 299 degrees of freedom (two-sided 1e-3)."""
    c = CLIMATES[0]
    n = np.array([synthetic_hs(c, 1.0, s)[1].size for s in record_seeds(5, 300)])
    assert abs(n.mean() - c.rate) < 4.0 * math.sqrt(c.rate / n.size)
    d = float(np.sum((n - n.mean()) ** 2) / n.mean())
    assert stats.chi2(n.size - 1).ppf(5e-4) < d < stats.chi2(n.size - 1).ppf(1 - 5e-4)


@pytest.mark.parametrize("c", CLIMATES, ids=lambda c: f"xi={c.xi:g}")
def test_declustering_finds_exactly_the_storms(c):
    """At the base level, at the default 99.5 % quantile and above, with gaps of 1 to 48 h, the
    storms of :func:`regimemap.climate.storms` are the simulated peaks above the threshold; the
    background stays below the base and each storm is above it 2 K + 1 hours."""
    hs, peaks = synthetic_hs(c, 10.0, seed=3)
    record = synthetic_record(c, 10.0, seed=3)
    np.testing.assert_array_equal(record.hs, hs)
    assert np.count_nonzero(hs > c.base) == (2 * DEFAULT_STORM_HOURS + 1) * peaks.size
    q = resolve_threshold(record, "quantile", 0.995)
    assert q > c.base
    for u in (c.base, q, q + 0.3 * c.sigma):
        for gap in (1.0, 48.0):
            s = storms(record, u, gap)
            np.testing.assert_array_equal(s.peak, peaks[peaks > u])
    assert record.years == pytest.approx(10.0, abs=0.5 / HOURS_PER_YEAR)


def test_same_seed_same_bytes_and_children_differ():
    c = CLIMATES[1]
    a, b = record_seeds(7, 2)
    again = record_seeds(7, 2)[1]
    assert synthetic_hs(c, 3.0, b)[0].tobytes() == synthetic_hs(c, 3.0, again)[0].tobytes()
    assert synthetic_hs(c, 3.0, a)[0].tobytes() != synthetic_hs(c, 3.0, b)[0].tobytes()


def _brute_return_value(c: SyntheticClimate, years: float) -> float:
    """``lambda R P(peak > H) = 1`` solved by a root finder on scipy's GPD survival function."""
    g = stats.genpareto(c.xi, loc=c.base, scale=c.sigma)
    top = c.base - c.sigma / c.xi if c.xi < 0 else c.base + 1e4 * c.sigma
    return float(optimize.brentq(lambda h: c.rate * years * g.sf(h) - 1.0, c.base, top - 1e-12, xtol=1e-12))


@pytest.mark.parametrize("c", CLIMATES + [SyntheticClimate(sigma=0.3, xi=0.2, rate=8.0, base=3.0)],
                         ids=lambda c: f"xi={c.xi:g}")
@pytest.mark.parametrize("years", [2.0, 10.0, 50.0, 100.0])
def test_truth_against_brute_force_and_threshold_stability(c, years):
    truth = c.return_value(years)
    assert truth == pytest.approx(_brute_return_value(c, years), rel=1e-9)
    for d in (0.2, 1.0):  # the same H_R from the peaks above u = u0 + d
        u = c.base + d * c.sigma
        sigma_u, rate_u = c.at_threshold(u)
        above = SyntheticClimate(sigma=sigma_u, xi=c.xi, rate=rate_u, base=u)
        if rate_u * years > 1.0:
            assert above.return_value(years) == pytest.approx(truth, rel=1e-12)


def test_the_rate_above_a_threshold_is_what_a_long_record_counts():
    """lambda_u of :meth:`at_threshold` against the storms counted above u in 60 years (4 se)."""
    c = CLIMATES[0]
    record = synthetic_record(c, 60.0, seed=2)
    u = c.base + 0.5
    expected = c.at_threshold(u)[1] * 60.0
    assert abs(storms(record, u).count - expected) < 4.0 * math.sqrt(expected)


def test_impossible_settings_are_errors():
    c = CLIMATES[0]
    with pytest.raises(ValueError, match="below the base"):
        c.at_threshold(2.0)
    with pytest.raises(ValueError, match="end point"):
        c.at_threshold(c.base - c.sigma / c.xi + 0.1)
    with pytest.raises(ValueError, match="separation_hours"):
        synthetic_hs(c, 1.0, 0, separation_hours=10)
    with pytest.raises(ValueError, match="storms do not fit"):
        synthetic_hs(SyntheticClimate(sigma=1.0, xi=0.0, rate=200.0, base=3.0), 1.0, 0)
    with pytest.raises(ValueError, match="sigma"):
        SyntheticClimate(sigma=0.0, xi=0.0, rate=1.0, base=1.0)
    with pytest.raises(ValueError, match="no 0.1-year"):
        c.return_value(0.1)
