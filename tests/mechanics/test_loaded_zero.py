"""At zero loads the generalised closed forms are the report's, bit for bit.

The oracle here is the report's formulas written out literally, with the
operations the library used before the loads were added: every threshold,
constant, label and curve must be identical to the last bit.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify, label_grid
from regimemap.mechanics import constants as C
from regimemap.mechanics.curves import map_curves, mu_star, named_points, upper_line
from regimemap.mechanics.modes import PRIORITY, SELECTION_ORDER
from regimemap.mechanics.solver import admissible, choose, least_constraint

from .._sweep import sample_points, sweep

_RE, _SL, _RO, _SM, _SP, _SPM = (np.uint8(m) for m in (
    Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS, Mode.SRO_PRIME_MINUS))


def report_rule(k, mu, g, kp):
    """The report's final map (README, "The rule behind every map"), written literally."""
    g2 = g * g
    a, b, c, d = 4.0 + g2 - 3.0 * g2 * kp, 3.0 * g, 3.0 * g * (1.0 + kp), 1.0 + 4.0 * g2
    f = a * k + b
    mu_s = np.abs(f) / (c * k + d)
    upper, lower = 1.0 / g - k * kp, -1.0 / g - k * kp
    rest_ok = k * (g * (1.0 + kp)) <= 1.0
    out = np.where(f >= 0.0, _SM, _SP)
    np.copyto(out, _RO, where=mu >= mu_s)
    np.copyto(out, _SL, where=mu <= upper)
    np.copyto(out, _SPM, where=mu < lower)
    np.copyto(out, _RE, where=(mu >= k) & rest_ok)
    return out


def test_lift_off_is_a_mode():
    assert Mode.LO == 8 and Mode.LO.label == "LO" and Mode.LO.tex == "$LO$"
    assert Mode.LO.description == "lift-off (no contact)"
    assert SELECTION_ORDER == (Mode.LO,) + PRIORITY


def test_constants_are_the_report_bit_for_bit():
    for g, kp in sweep(21):
        p = Parameters(g, kp)
        c = p.constants
        assert not p.loaded and c.extra == 0.0
        g2 = g * g
        abcd = (4.0 + g2 - 3.0 * g2 * kp, 3.0 * g, 3.0 * g * (1.0 + kp), 1.0 + 4.0 * g2)
        assert (p.a, p.b, p.c, p.d) == abcd
        assert (c.aO, c.bO, c.cO, c.dO) == abcd == (c.aP, c.bP, c.cP, c.dP)
        den = g * (1.0 + kp)
        assert p.k_A == (math.inf if den == 0.0 else 1.0 / den) == p.mu_A
        assert p.mu_Bprime == (4.0 + g**2) / (3.0 * g)
        assert p.k_Bprime == (math.inf if kp >= 0 else (1.0 + g**2) / (3.0 * g * abs(kp)))
        assert p.k_D == (math.inf if kp == 0 else 1.0 / (g * abs(kp)))
        assert p.k_F == (abcd[1] / abcd[0] if abcd[0] > 0 else math.inf)
        assert p.lift_off is None and p.k_L == math.inf


def test_crossing_C_prime_is_the_report_quadratic_bit_for_bit():
    for g, kp in sweep(21):
        if kp >= 0 or kp == -1.0:
            continue
        a, b, c, d = Parameters(g, kp).constants[8:12]
        q = abs(kp)
        A2, A1, A0 = c * q, d * q - c / g - a, -(d / g + b)
        root = (-A1 + math.sqrt(A1 * A1 - 4.0 * A2 * A0)) / (2.0 * A2)
        assert Parameters(g, kp).k_Cprime == root


@pytest.mark.parametrize("gamma,kprime", sweep(21))
def test_thresholds_are_the_report_bit_for_bit(gamma, kprime):
    k, _ = sample_points(gamma, kprime, 4000, seed=5)
    k = np.concatenate([k, [0.0, 1.0]])
    t = C.thresholds(k, Parameters(gamma, kprime).constants)
    assert np.array_equal(t.upper, 1.0 / gamma - k * kprime)
    assert np.array_equal(t.lower, -1.0 / gamma - k * kprime)
    assert np.array_equal(t.mu_rest, k) and np.array_equal(t.W, np.ones_like(k))
    assert t.regular.all() and not t.lift_off.any()


@pytest.mark.parametrize("gamma,kprime", sweep(21))
def test_classify_is_the_report_rule_bit_for_bit(gamma, kprime):
    k, mu = sample_points(gamma, kprime, 20000, seed=1)
    assert np.array_equal(classify(k, mu, gamma, kprime), report_rule(k, mu, gamma, kprime))


def test_classify_on_big_random_sets_and_on_exact_thresholds():
    rng = np.random.default_rng(42)
    for _ in range(100):
        g = float(np.exp(rng.uniform(np.log(0.05), np.log(50))))
        kp = float(rng.choice([rng.uniform(-1, 1), 0.0, 1.0, -1.0]))
        k = rng.uniform(0, rng.choice([0.5, 3.0, 30.0]), 10000)
        mu = rng.uniform(0, rng.choice([0.5, 3.0, 30.0]), 10000)
        assert np.array_equal(classify(k, mu, g, kp), report_rule(k, mu, g, kp)), (g, kp)
    for g, kp in sweep(9):
        p = Parameters(g, kp)
        k = np.array([0.0, p.k_A, p.k_Bprime, p.k_D, p.k_F, p.k_pole, p.b_over_abs_a, 1.0, 2.0])
        k = k[np.isfinite(k)]
        mu = np.concatenate([k, upper_line(p, k), mu_star(p, k), [p.mu_Bprime]])
        mu = np.unique(mu[np.isfinite(mu) & (mu >= 0)])
        K, M = np.meshgrid(k, mu)
        assert np.array_equal(classify(K, M, g, kp), report_rule(K, M, g, kp))
        assert np.array_equal(label_grid(k, mu, g, kp), report_rule(K, M, g, kp))


@pytest.mark.slow
@pytest.mark.deep
def test_least_constraint_is_section_4_7_wherever_several_modes_are_admissible():
    multi = 0
    for g, kp in sweep(9):
        k, mu = sample_points(g, kp, 3000, seed=9)
        codes, adm, cons = least_constraint(k, mu, g, kp)
        # its admissible sets are admissible()'s (both solve the same hypotheses: the first 300
        # points of the pair tell; the sets of all 3000 come from least_constraint)
        adm_300 = admissible(k[:300], mu[:300], g, kp)
        for m in Mode:
            assert np.array_equal(adm_300[m], adm[m][:300])
        assert not adm[Mode.LO].any()
        many = np.stack(list(adm.values())).sum(axis=0) > 1
        multi += int(many.sum())
        # Section 4.7's PRIORITY (choose without constraints) is least constraint's choice
        assert np.array_equal(codes, choose(adm))
        assert np.array_equal(codes, choose(adm, cons))
    assert multi > 5000, multi


def test_tiny_loads_change_the_constants_continuously():
    for g, kp in sweep(9):
        p, q = Parameters(g, kp), Parameters(g, kp, buoyancy=1e-12, uplift=1e-12, uplift_ratio=1e-12)
        assert q.loaded
        for name in ("k_A", "mu_Bprime", "k_D", "k_F", "k_pole"):
            a, b = getattr(p, name), getattr(q, name)
            assert (a == math.inf and b > 1e9) or math.isclose(a, b, rel_tol=1e-9), (g, kp, name)
        assert set(named_points(p)) <= set(named_points(q)) | {"C"}


def test_curves_and_points_of_the_report_are_unchanged():
    """Zero-load curve specs and named points as the report writes them (export relies on them)."""
    p = Parameters(3.0, -0.6)
    cur = map_curves(p)
    assert list(cur) == ["OA", "AE", "AB", "DC", "dotted", "mu_star", "mu_star_star"]
    assert cur["AB"].spec == {"type": "line", "c0": 1.0 / 3.0, "c1": 0.6, "text": "mu = c0 + c1*k"}
    assert cur["dotted"].spec["c0"] == 0.0 and cur["dotted"].spec["c1"] == 0.6
    assert cur["mu_star"].spec["p"] == p.a and cur["mu_star_star"].spec["q"] == -p.b
    assert list(named_points(p)) == ["O", "A", "E", "B'", "D", "F", "C'"]
    assert "LO" not in map_curves(Parameters(2.0, 0.5))
