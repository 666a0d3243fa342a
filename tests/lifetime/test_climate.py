"""Storm-peak distributions: fits through return values (maximum likelihood: tests/climate/test_life.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap.lifetime import Climate


@pytest.mark.parametrize("distribution,shape", [("weibull", 2.0), ("weibull", 1.4), ("weibull", 0.75),
                                                ("gumbel", 2.0)])
@pytest.mark.parametrize("lam", [None, 1.0, 3.5])
def test_fit_reproduces_the_return_values(distribution, shape, lam):
    c = Climate.from_return_values(5.0, 6.3, distribution, shape, lam)
    assert c.return_value(10) == pytest.approx(5.0, abs=1e-12)
    assert c.return_value(50) == pytest.approx(6.3, abs=1e-12)
    # and the definition: lambda (1 - F(H_R)) = 1/R
    for R in (10, 50, 200):
        assert c.rate * (1.0 - float(c.cdf(c.return_value(R)))) == pytest.approx(1.0 / R, rel=1e-9)


def test_weibull_poisson_form_of_the_issue():
    lam, k = 4.0, 2.0
    c = Climate.from_return_values(5.0, 6.3, "weibull", k, lam)
    for R in (10, 50, 100):
        assert c.return_value(R) == pytest.approx(c.location + c.scale * math.log(lam * R) ** (1 / k))


def test_annual_and_one_storm_a_year_agree():
    a = Climate.from_return_values(5.0, 6.3, "gumbel")
    b = Climate.from_return_values(5.0, 6.3, "gumbel", storms_per_year=1.0)
    assert (a.scale, a.location) == pytest.approx((b.scale, b.location), rel=1e-15)


def test_quantile_inverts_the_cdf():
    for c in (Climate.from_return_values(5.0, 6.3), Climate.from_return_values(5.0, 6.3, "gumbel")):
        u = np.linspace(0.001, 0.999, 101)
        assert c.cdf(c.quantile(u)) == pytest.approx(u, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("bad,match", [
    (dict(H0_10=6.3, H0_50=5.0), "must exceed"),
    (dict(H0_10=5.0, H0_50=6.3, storms_per_year=0.05), "too few"),
])
def test_refusals(bad, match):
    with pytest.raises(ValueError, match=match):
        Climate.from_return_values(**bad)


def test_fit_refusals():
    with pytest.raises(ValueError, match="scale"):
        Climate("weibull", 0.0, 1.0)
