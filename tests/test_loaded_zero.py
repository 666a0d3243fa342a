"""The loaded closed forms and solver at zero loads: the report's problem, bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify, label_grid
from regimemap.mechanics.constants import thresholds as _thresholds
from regimemap.mechanics.curves import mu_star, named_points, upper_line
from regimemap.mechanics.loaded import (
    LO,
    classify_loaded,
    label_grid_loaded,
    loaded_constants,
    named_points_loaded,
    thresholds,
)
from regimemap.mechanics.loaded_solver import LIFT_OFF, SELECTION_ORDER, least_constraint
from regimemap.mechanics.modes import PRIORITY
from regimemap.mechanics.solver import admissible, choose

from ._sweep import sample_points, sweep


def test_lift_off_code_is_shared():
    assert LO == LIFT_OFF == 8
    assert LO not in {int(m) for m in Mode}


def test_selection_order_is_section_4_7_after_lift_off():
    assert SELECTION_ORDER[0] == LIFT_OFF
    assert SELECTION_ORDER[1:] == tuple(int(m) for m in PRIORITY)


def test_constants_reduce_to_parameters_bit_for_bit():
    for g, kp in sweep(21):
        p, c = Parameters(g, kp), loaded_constants(g, kp)
        assert (c.a, c.b, c.c, c.d) == (p.a, p.b, p.c, p.d)
        assert (c.aO, c.bO, c.cO, c.dO) == (p.a, p.b, p.c, p.d)
        assert (c.aP, c.bP, c.cP, c.dP) == (p.a, p.b, p.c, p.d)
        assert c.k_A == p.k_A
        assert math.isclose(c.mu_Bprime, p.mu_Bprime, rel_tol=1e-15)


@pytest.mark.parametrize("gamma,kprime", sweep(21))
def test_thresholds_equal_classify_bit_for_bit(gamma, kprime):
    k, _ = sample_points(gamma, kprime, 4000, seed=5)
    k = np.concatenate([k, [0.0, 1.0]])
    rest_ok, lower, upper, mu_s, f_pos = _thresholds(k, gamma, kprime)
    t = thresholds(k, loaded_constants(gamma, kprime))
    for mine, theirs in ((t.rest_ok, rest_ok), (t.lower, lower), (t.upper, upper), (t.mu_star, mu_s),
                         (t.f_pos, f_pos), (t.mu_rest, k)):
        assert np.array_equal(mine, theirs)
    assert t.regular.all() and not t.lift_off.any()


@pytest.mark.parametrize("gamma,kprime", sweep(21))
def test_classify_loaded_equals_classify_bit_for_bit(gamma, kprime):
    k, mu = sample_points(gamma, kprime, 20000, seed=1)
    assert np.array_equal(classify_loaded(k, mu, gamma, kprime), classify(k, mu, gamma, kprime))


def test_classify_loaded_equals_classify_on_big_random_sets():
    rng = np.random.default_rng(42)
    n = 0
    for _ in range(200):
        g = float(np.exp(rng.uniform(np.log(0.05), np.log(50))))
        kp = float(rng.choice([rng.uniform(-1, 1), 0.0, 1.0, -1.0]))
        k = rng.uniform(0, rng.choice([0.5, 3.0, 30.0]), 10000)
        mu = rng.uniform(0, rng.choice([0.5, 3.0, 30.0]), 10000)
        assert np.array_equal(classify_loaded(k, mu, g, kp), classify(k, mu, g, kp)), (g, kp)
        n += k.size
    assert n == 2_000_000


def test_on_exact_thresholds_bit_for_bit():
    for g, kp in sweep(9):
        p = Parameters(g, kp)
        k = np.array([0.0, p.k_A, p.k_Bprime, p.k_D, p.k_F, p.k_pole, p.b_over_abs_a, 1.0, 2.0])
        k = k[np.isfinite(k)]
        mu = np.concatenate([k, upper_line(p, k), mu_star(p, k), [p.mu_Bprime]])
        mu = np.unique(mu[np.isfinite(mu) & (mu >= 0)])
        K, M = np.meshgrid(k, mu)
        assert np.array_equal(classify_loaded(K, M, g, kp), classify(K, M, g, kp))
        assert np.array_equal(label_grid_loaded(k, mu, g, kp), label_grid(k, mu, g, kp))


@pytest.mark.parametrize("gamma,kprime", sweep(5))
def test_label_grid_loaded_equals_label_grid(gamma, kprime):
    k = np.linspace(0, 6, 211)
    mu = np.linspace(0, 4, 173)
    assert np.array_equal(label_grid_loaded(k, mu, gamma, kprime), label_grid(k, mu, gamma, kprime))
    rev = mu[::-1]
    assert np.array_equal(label_grid_loaded(k, rev, gamma, kprime), label_grid(k, rev, gamma, kprime))


def test_least_constraint_is_section_4_7_wherever_several_modes_are_admissible():
    multi = 0
    for g, kp in sweep(9):
        k, mu = sample_points(g, kp, 3000, seed=9)
        adm = admissible(k, mu, g, kp)
        codes, adm_l, _ = least_constraint(k, mu, g, kp)
        for m in Mode:  # the generalised solver is the old one at zero loads
            assert np.array_equal(adm[m], adm_l[int(m)])
        assert not adm_l[LIFT_OFF].any()
        many = np.stack(list(adm.values())).sum(axis=0) > 1
        multi += int(many.sum())
        assert np.array_equal(codes[many], choose(adm)[many])
        assert np.array_equal(codes, choose(adm))
    assert multi > 5000, multi


def test_named_points_reduce_to_the_report():
    for g, kp in sweep(21):
        a = named_points(Parameters(g, kp))
        b = named_points_loaded(loaded_constants(g, kp))
        assert "L" not in b
        assert set(a) == set(b), (g, kp)
        for n in a:
            assert math.isclose(a[n].k, b[n].k, rel_tol=1e-12), (g, kp, n)
            assert math.isclose(a[n].mu, b[n].mu, rel_tol=1e-12, abs_tol=1e-15), (g, kp, n)


def test_curves_reduce_to_the_report_bit_for_bit():
    from regimemap.mechanics.curves import mu_star_signed, mu_star_star
    from regimemap.mechanics.loaded import mu_star_signed_loaded, mu_star_star_loaded

    for g, kp in sweep(11):
        k, _ = sample_points(g, kp, 2000, seed=8)
        p, c = Parameters(g, kp), loaded_constants(g, kp)
        assert np.array_equal(mu_star_signed_loaded(k, c), mu_star_signed(p, k))
        with np.errstate(divide="ignore", invalid="ignore"):
            assert np.array_equal(mu_star_star_loaded(k, c), mu_star_star(p, k), equal_nan=True)
