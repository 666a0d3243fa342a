"""The normal quantile (scipy.special.ndtri, wrapped) and the exact truncation."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import special, stats

from regimemap.lifetime.normal import normal_quantile, truncated_normal


def test_quantile_matches_scipy_to_1e_15():
    u = np.concatenate([np.linspace(1e-300, 1e-10, 50), np.linspace(1e-10, 1 - 1e-10, 2001),
                        1.0 - np.logspace(-16, -10, 20)])
    z = normal_quantile(u)
    ref = special.ndtri(u)
    assert np.allclose(z, ref, rtol=2e-15, atol=1e-15)
    assert normal_quantile(0.0) == -np.inf and normal_quantile(1.0) == np.inf


@pytest.mark.parametrize("n", [0.5, 1.0, 2.0, 3.0])
def test_truncated_is_the_truncated_distribution(n):
    u = (np.arange(20000) + 0.5) / 20000
    z = truncated_normal(u, n)
    assert z.min() >= -n and z.max() <= n
    ref = stats.truncnorm.ppf(u, -n, n)
    assert np.allclose(z, ref, atol=1e-9)


def test_same_uniform_same_rank_and_no_infinity():
    u = np.array([0.0, 0.1, 0.5, 0.9])
    a, b = truncated_normal(u), truncated_normal(u, 1.0)
    assert np.all(np.isfinite(a))
    assert np.all(np.diff(a) > 0) and np.all(np.diff(b) > 0)
