"""The generalised equations-of-motion solver (vertical loads, any inertia, lift-off)."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Mode, admissible
from regimemap.mechanics.solver import Hypothesis, applied_loads, contact_rows, least_constraint, solve

from ._loaded_sweep import loaded_sweep, sample

LOADS = dict(buoyancy=0.3, uplift=0.2, uplift_ratio=0.4, uplift_arm=-0.6, gyration=1.3)


def _random(n, seed):
    rng = np.random.default_rng(seed)
    return dict(
        k=rng.uniform(0, 3, n), mu=rng.uniform(0, 3, n), gamma=rng.uniform(0.2, 6, n),
        kprime=rng.uniform(-1, 1.5, n), buoyancy=rng.uniform(0, 0.99, n), uplift=rng.exponential(0.4, n),
        uplift_ratio=rng.exponential(0.4, n), uplift_arm=rng.uniform(-1, 1, n),
        gyration=rng.uniform(0.2, 3, n),
    )


@pytest.mark.parametrize("hyp", list(Hypothesis))
def test_solutions_satisfy_the_equations_of_motion(hyp):
    p = _random(600, 1)
    r = solve(hyp, p["k"], p["mu"], p["gamma"], p["kprime"], buoyancy=p["buoyancy"],
                     uplift=p["uplift"], uplift_ratio=p["uplift_ratio"], uplift_arm=p["uplift_arm"],
                     gyration=p["gyration"])
    g, k, i2 = p["gamma"], p["k"], p["gyration"] ** 2
    W = 1 - p["buoyancy"] - p["uplift"] - p["uplift_ratio"] * k
    S = g * k * p["kprime"] + p["uplift_arm"] * (p["uplift"] + p["uplift_ratio"] * k)
    good = r.solvable
    M = np.where(np.isfinite(r.xi), r.xi * r.fy, 0.0)
    assert np.allclose((r.xdd - (r.fx - k))[good], 0, atol=1e-9)
    assert np.allclose((r.ydd - (r.fy - W))[good], 0, atol=1e-9)
    assert np.allclose((i2 * r.thdd - (g * r.fx + M + S))[good], 0, atol=1e-8)
    if hyp.contact == "none":
        assert np.allclose(r.fx, 0) and np.allclose(r.fy, 0) and np.allclose(r.constraint, 0)
        assert np.allclose(r.thdd, S / i2)
    elif hyp.contact == "full":
        assert np.allclose(r.ydd[good], 0) and np.allclose(r.thdd[good], 0)
    else:
        side = -1.0 if hyp.contact == "O" else 1.0
        assert np.allclose((r.ydd + side * r.thdd)[good], 0, atol=1e-9)
    if hyp.sigma:
        assert np.allclose(r.fx[good], (hyp.sigma * p["mu"] * r.fy)[good])
    # Gauss's constraint is the reaction's kinetic metric
    assert np.allclose(r.constraint[good], (r.fx**2 + r.fy**2 + (g * r.fx + M) ** 2 / i2)[good])


def test_rest_is_statics_with_loads():
    k, g, kp = 0.1, 2.0, 0.5
    r = solve(Hypothesis.REST, k, 5.0, g, kp, **LOADS)
    W = 1 - 0.3 - 0.2 - 0.4 * k
    U = 0.2 + 0.4 * k
    assert r.fx == pytest.approx(k) and r.fy == pytest.approx(W)
    # moment about C: xi fy = -(gamma fx + gamma k k' + e_u U)
    assert r.xi * W == pytest.approx(-(g * k + g * k * kp - 0.6 * U))
    assert bool(r.ok)


def test_contact_rows_do_not_depend_on_the_loads():
    mu, g = np.array([0.3, 1.0]), np.array([2.0, 0.5])
    for hyp in Hypothesis:
        A, rhs = contact_rows(hyp, mu, g)
        assert A.shape == (2, 3, 6) and not rhs.any()
    fx, fy, mc = applied_loads(np.array([1.0]), 2.0, 0.5, buoyancy=0.1, uplift=0.2, uplift_ratio=0.3,
                               uplift_arm=0.5)
    assert fx[0] == -1.0 and fy[0] == pytest.approx(-(1 - 0.1 - 0.2 - 0.3))
    assert mc[0] == pytest.approx(2.0 * 0.5 + 0.5 * 0.5)


def test_lift_off_when_the_block_floats_level():
    # W < 0 with no moment: free flight, nothing else admissible
    codes, adm, cons = least_constraint(np.array([0.0, 0.0]), np.array([0.1, 2.0]), 2.0, 0.0,
                                        buoyancy=0.5, uplift=0.8, uplift_arm=0.0)
    assert (codes == Mode.LO).all() and (cons[Mode.LO] == 0).all()
    assert not adm[Mode.RE].any() and not adm[Mode.SL].any()


def test_no_lift_off_while_a_corner_would_sink():
    # W < 0 but the free rotation drives O into the base: a pivot mode, not lift-off
    k = np.array([0.0])
    codes, adm, _ = least_constraint(k, np.array([1.0]), 2.0, 0.0, uplift=1.2, uplift_arm=1.0)
    assert not adm[Mode.LO].any() and codes[0] != Mode.LO


@pytest.mark.slow
@pytest.mark.deep
def test_admissible_set_never_empty_on_the_sweep():
    for g, kp, loads in loaded_sweep(80, seed=3):
        k, mu = sample(g, kp, loads, 2000, seed=4)
        adm = admissible(k, mu, g, kp, **loads)
        assert np.stack(list(adm.values())).any(axis=0).all(), (g, kp, loads)


def test_singular_slide_rock_is_not_admissible():
    g, gy = 2.0, 1.1
    mu = (gy * gy + 1) / g  # i^2 + 1 - mu gamma = 0
    r = solve(Hypothesis.SLIDE_ROCK_O_LEFT, 1.0, mu, g, -0.5, gyration=gy, buoyancy=0.2)
    assert not bool(r.solvable) and not bool(r.ok)
