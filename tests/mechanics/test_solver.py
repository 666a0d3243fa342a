"""The equations-of-motion solver: its own physics, independent of the report's inequalities."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Mode
from regimemap.mechanics.solver import Hypothesis, admissible, admissible_hypotheses, solve

from .._sweep import sample_points, sweep


def residuals(r, k, mu, gamma, kprime):
    """Residuals of the three equations of motion (dimensionless)."""
    I = (1 + gamma**2) / 3
    return (
        r.xdd - (r.fx - k),
        r.ydd - (r.fy - 1),
        I * r.thdd - (gamma * r.fx + r.xi * r.fy + gamma * k * kprime),
    )


@pytest.mark.parametrize("hyp", list(Hypothesis))
def test_solutions_satisfy_equations_of_motion(hyp):
    rng = np.random.default_rng(1)
    k, mu = rng.uniform(0, 3, 500), rng.uniform(0, 3, 500)
    gamma, kprime = rng.uniform(0.2, 6, 500), rng.uniform(-1, 1, 500)
    r = solve(hyp, k, mu, gamma, kprime)
    good = r.solvable & (np.abs(r.fy) > 1e-9)
    for res in residuals(r, k, mu, gamma, kprime):
        assert np.allclose(res[good], 0, atol=1e-9)
    if hyp.contact == "O":
        assert np.allclose(r.xi[good], -1)
        assert np.allclose(r.ydd - r.thdd, 0)  # pivot O does not move vertically
    elif hyp.contact == "O'":
        assert np.allclose(r.xi[good], 1)
        assert np.allclose(r.ydd + r.thdd, 0)
    elif hyp.contact == "none":  # lift-off: free flight, no reaction
        assert np.allclose(r.fx, 0) and np.allclose(r.fy, 0) and np.allclose(r.ydd, -1)
    else:
        assert np.allclose(r.ydd, 0) and np.allclose(r.thdd, 0)
    if hyp.sigma:
        assert np.allclose(r.fx, hyp.sigma * mu * r.fy)


def test_rest_matches_statics():
    # (3.1)-(3.3): f_x = F, f_y = mg, xi = -k(1+k')H
    k, gamma, kprime = 0.2, 2.0, 0.5
    r = solve(Hypothesis.REST, k, 1.0, gamma, kprime)
    assert r.fx == pytest.approx(k) and r.fy == pytest.approx(1.0)
    assert r.xi * 1.0 == pytest.approx(-k * (1 + kprime) * gamma)  # xi/B = -k(1+k')gamma
    assert bool(r.ok)


def test_rock_about_O_matches_hand_calculation():
    # gamma = 1, k' = 0, k = 2: I = 2/3 m B^2; theta'' = 3g/(8B) (2 - 1) (3.14)
    r = solve(Hypothesis.ROCK_O, 2.0, 5.0, 1.0, 0.0)
    assert r.thdd == pytest.approx(3 / 8)
    assert r.xdd == pytest.approx(-3 / 8) and r.ydd == pytest.approx(3 / 8)
    assert r.fx == pytest.approx(2 - 3 / 8) and r.fy == pytest.approx(1 + 3 / 8)
    assert bool(r.ok)


def test_rock_about_O_prime_never_admissible():
    # (4.57): theta'' > 0 while lifting O needs theta'' < 0
    for g, kp in sweep(9):
        k, mu = sample_points(g, kp, 2000)
        assert not solve(Hypothesis.ROCK_O_PRIME, k, mu, g, kp).ok.any()


# The two sweeps below: k' every 0.25 and at every case threshold of the report (tests/_sweep.py),
# for the 12 aspect ratios (149 pairs; the modes change only at the thresholds, which are all in).
# They share one solve of every hypothesis at 3000 random points a pair (a module fixture: the
# solve is the cost, the properties hold at any sample of the map).
@pytest.fixture(scope="module")
def swept_hypotheses():
    """``[(gamma, kprime, k, mu, admissible_hypotheses(k, mu, gamma, kprime)), ...]`` over the sweep."""
    out = []
    for g, kp in sweep(9):
        k, mu = sample_points(g, kp, 3000, seed=2)
        out.append((g, kp, k, mu, admissible_hypotheses(k, mu, g, kp)))
    return out


@pytest.mark.slow
@pytest.mark.deep
def test_admissible_set_never_empty(swept_hypotheses):
    for g, kp, k, mu, hyp in swept_hypotheses:
        assert np.stack(list(hyp.values())).any(axis=0).all(), (g, kp)
        # admissible() is that: each mode admissible where one of its hypotheses is (checked on
        # the first 200 points of the pair)
        adm = admissible(k[:200], mu[:200], g, kp)
        assert set(adm) == set(Mode)
        for m in Mode:
            expected = np.zeros(200, bool)
            for h, ok in hyp.items():
                if h.mode is m:
                    expected |= ok[:200]
            assert np.array_equal(adm[m], expected), (g, kp, m)


@pytest.mark.slow
def test_slide_right_and_slide_rock_prime_plus_never_admissible(swept_hypotheses):
    for _g, _kp, _k, _mu, hyp in swept_hypotheses:
        assert not hyp[Hypothesis.SLIDE_RIGHT].any()
        assert not hyp[Hypothesis.SLIDE_ROCK_O_PRIME_RIGHT].any()


def test_singular_slide_rock_is_not_admissible():
    # 4 + g^2 - 3 mu g = 0 makes (3.30) singular: the system has no unique solution
    g = 2.0
    mu = (4 + g * g) / (3 * g)
    r = solve(Hypothesis.SLIDE_ROCK_O_LEFT, 1.0, mu, g, -0.5)
    assert not bool(r.solvable) and not bool(r.ok)


def test_modes_mapping_covers_all_modes():
    adm = admissible(0.1, 0.5, 1.0, 0.0)
    assert set(adm) == set(Mode)


def test_the_elimination_solves_the_system_as_a_general_solver_does():
    """The solver eliminates the accelerations (the diagonal block of the dynamic rows) and
    solves the 3x3 system of the reactions by Cramer's rule: its determinants and solutions
    are numpy.linalg's for every hypothesis's rows, and for random systems of that shape."""
    from regimemap.mechanics import solver

    rng = np.random.default_rng(7)
    n = 2000
    A = rng.normal(size=(n, 6, 6))
    A[:, :3, :3] = 0.0
    A[:, [0, 1, 2], [0, 1, 2]] = rng.uniform(0.5, 2.0, size=(n, 3)) * rng.choice([-1, 1], size=(n, 3))
    rhs = rng.normal(size=(n, 6))
    det, u = solver._solve_system(A, rhs)
    np.testing.assert_allclose(det, np.linalg.det(A), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(u, np.linalg.solve(A, rhs[..., None])[..., 0], rtol=1e-8, atol=1e-10)
    mu, gamma = rng.uniform(0.01, 1.5, n), rng.uniform(0.2, 5.0, n)
    for hypothesis in Hypothesis:
        A = np.zeros((n, 6, 6))
        A[:, :3] = solver.dynamic_rows(gamma, solver.default_i2(gamma))
        A[:, 3:], _ = solver.contact_rows(hypothesis, mu, gamma)
        det, u = solver._solve_system(A, rhs)
        np.testing.assert_allclose(det, np.linalg.det(A), rtol=1e-9, atol=1e-12)
        ok = np.abs(np.linalg.det(A)) > 1e-9
        np.testing.assert_allclose(u[ok], np.linalg.solve(A[ok], rhs[ok, :, None])[..., 0],
                                   rtol=1e-7, atol=1e-9)
