"""Property tests (hypothesis) of the mode engine against its own rules and the solver.

The example counts come from the hypothesis profile (``tests/conftest.py``):
small by default so that the suite stays fast, larger with
``HYPOTHESIS_PROFILE=ci`` or ``thorough``.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, note
from hypothesis import strategies as st

from regimemap import MAP_MODES, Mode, Parameters, classify, label_grid
from regimemap.mechanics.solver import Hypothesis, admissible, solve

MAP_CODES = {int(m) for m in MAP_MODES}

# -- strategies ----------------------------------------------------------------------------------------

#: Aspect ratios 0.05..50, log-uniform.
gammas = st.floats(math.log(0.05), math.log(50.0)).map(math.exp)
#: Aspect ratios for the solver checks (the same range since the Hadamard-bound singularity test).
solver_gammas = gammas


def _thresholds(g: float) -> list[float]:
    g2 = g * g
    out = [0.0, 1.0, -1.0, (1 + g2) / (4 + g2), -(1 + g2) / (4 + g2)]
    out += [t for t in ((1 + g2) / (3 * g2), (4 + g2) / (3 * g2)) if t <= 1.0]
    return out


@st.composite
def params(draw, gamma_strategy=gammas):
    """(gamma, kprime) with kprime uniform in [-1, 1] or exactly at one of the report's thresholds."""
    g = draw(gamma_strategy)
    kp = draw(st.one_of(st.floats(-1.0, 1.0), st.sampled_from(_thresholds(g))))
    return g, kp


def _scale(g: float, kp: float) -> tuple[float, float]:
    """A view that holds every characteristic point of the map (k up to ~3 k_A or so)."""
    p = Parameters(g, kp)
    marks = [p.k_A, p.k_Bprime, p.b_over_abs_a, p.k_D, p.k_pole, 1.0]
    k_hi = min(3.0 * max(x for x in marks if math.isfinite(x)), 60.0)
    mu_hi = 2.0 * max(p.mu_Bprime, p.k_A if math.isfinite(p.k_A) else 0.0, 1.0 / g, 1.0)
    return k_hi, min(mu_hi, 60.0)


@st.composite
def scene(draw, gamma_strategy=gammas, n_min=1, n_max=40):
    """Parameters and points (k, mu) >= 0 in the view of the map, with some exact zeros."""
    g, kp = draw(params(gamma_strategy))
    k_hi, mu_hi = _scale(g, kp)
    n = draw(st.integers(n_min, n_max))
    unit = st.one_of(st.floats(0.0, 1.0), st.sampled_from([0.0, 1.0]))
    k = np.array(draw(st.lists(unit, min_size=n, max_size=n))) * k_hi
    mu = np.array(draw(st.lists(unit, min_size=n, max_size=n))) * mu_hi
    return g, kp, k, mu


def near_boundary(k, mu, g, kp, rel=1e-6):
    """Points whose label changes under a small move of k or mu (relative to the view)."""
    k_hi, mu_hi = _scale(g, kp)
    lab = classify(k, mu, g, kp)
    near = np.zeros(np.shape(lab), bool)
    for dk, dm in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)):
        kk = np.maximum(k + dk * rel * k_hi, 0.0)
        mm = np.maximum(mu + dm * rel * mu_hi, 0.0)
        near |= classify(kk, mm, g, kp) != lab
    return near


# -- classify --------------------------------------------------------------------------------------------

@given(scene())
def test_classify_returns_one_map_mode_per_point(sc):
    g, kp, k, mu = sc
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = classify(k, mu, g, kp)
        scalar = classify(float(k[0]), float(mu[0]), g, kp)
    assert out.dtype == np.uint8 and out.shape == k.shape
    assert set(out.tolist()) <= MAP_CODES
    assert scalar.shape == () and int(scalar) == int(out[0])
    assert all(Mode(c).label in {"RE", "SL", "RO", "SRO-", "SRO+", "SRO'-"} for c in out.tolist())


@given(scene(n_max=10))
def test_classify_broadcasts_gamma_and_kprime_arrays(sc):
    g, kp, k, mu = sc
    one = classify(k, mu, g, kp)
    many = classify(k, mu, np.full(k.shape, g), np.full(k.shape, kp))
    assert np.array_equal(one, many)
    col = classify(k[:, None], mu[:, None], g, kp)
    assert col.shape == (k.size, 1) and np.array_equal(col[:, 0], one)


# -- label_grid ------------------------------------------------------------------------------------------

@st.composite
def grid_scene(draw):
    g, kp = draw(params())
    k_hi, mu_hi = _scale(g, kp)
    unit = st.one_of(st.floats(0.0, 1.0), st.sampled_from([0.0, 0.5, 1.0]))
    k_axis = np.array(draw(st.lists(unit, min_size=0, max_size=25))) * k_hi
    mu_axis = np.array(draw(st.lists(unit, min_size=0, max_size=25))) * mu_hi
    order = draw(st.sampled_from(["as drawn", "sorted", "reversed"]))
    if order == "sorted":
        mu_axis = np.sort(mu_axis)
    elif order == "reversed":
        mu_axis = np.sort(mu_axis)[::-1]
    return g, kp, k_axis, mu_axis


@given(grid_scene())
def test_label_grid_equals_classify_exactly(gs):
    g, kp, k_axis, mu_axis = gs
    grid = label_grid(k_axis, mu_axis, g, kp)
    assert grid.shape == (mu_axis.size, k_axis.size) and grid.dtype == np.uint8
    K, MU = np.meshgrid(k_axis, mu_axis)
    assert np.array_equal(grid, classify(K, MU, g, kp))


@pytest.mark.parametrize("mu_axis", [[0.0, 0.5, 1.0], [0.5, 0.0, 1.0], [1.0, 0.5, 0.0]])
def test_label_grid_is_c_contiguous(mu_axis):
    grid = label_grid([0.0, 0.3, 1.0], mu_axis, 1.0, 0.0)
    assert grid.flags.c_contiguous and grid.flags.owndata


@given(grid_scene(), st.data())
def test_refining_a_grid_keeps_the_labels_of_shared_points(gs, data):
    g, kp, k_axis, mu_axis = gs
    assume(k_axis.size and mu_axis.size)
    k_hi, mu_hi = _scale(g, kp)
    unit = st.floats(0.0, 1.0)
    extra_k = np.array(data.draw(st.lists(unit, max_size=15))) * k_hi
    extra_mu = np.array(data.draw(st.lists(unit, max_size=15))) * mu_hi
    coarse = label_grid(k_axis, mu_axis, g, kp)
    k_fine = np.sort(np.concatenate([k_axis, extra_k]))
    mu_fine = np.sort(np.concatenate([mu_axis, extra_mu]))
    fine = label_grid(k_fine, mu_fine, g, kp)
    jk = np.searchsorted(k_fine, k_axis)
    imu = np.searchsorted(mu_fine, mu_axis)
    assert np.array_equal(fine[np.ix_(imu, jk)], coarse)


# -- continuity across k' = 0 ----------------------------------------------------------------------------

@given(st.tuples(gammas, st.integers(1, 40)), st.data())
def test_labels_agree_just_above_and_below_kprime_zero(gn, data):
    g, n = gn
    k_hi, mu_hi = _scale(g, 0.0)
    unit = st.floats(0.0, 1.0)
    k = np.array(data.draw(st.lists(unit, min_size=n, max_size=n))) * k_hi
    mu = np.array(data.draw(st.lists(unit, min_size=n, max_size=n))) * mu_hi
    above = classify(k, mu, g, 1e-9)
    below = classify(k, mu, g, -1e-9)
    at_zero = classify(k, mu, g, 0.0)
    far = ~(near_boundary(k, mu, g, 1e-9) | near_boundary(k, mu, g, -1e-9))
    note(f"gamma={g!r} k={k[far & (above != below)]} mu={mu[far & (above != below)]}")
    assert np.array_equal(above[far], below[far])
    assert np.array_equal(above[far], at_zero[far])


# -- against the equations-of-motion solver --------------------------------------------------------------

def _solvable_everywhere(k, mu, g, kp):
    ok = np.ones(np.shape(k), bool)
    for h in Hypothesis:
        ok &= solve(h, k, mu, g, kp).solvable | (h.sigma != 0)  # sliding ones are singular on a curve
    return ok


@given(scene(gamma_strategy=solver_gammas))
@pytest.mark.slow
def test_solver_admits_something_everywhere(sc):
    g, kp, k, mu = sc
    adm = admissible(k, mu, g, kp)
    some = np.stack(list(adm.values())).any(axis=0)
    note(f"nothing admissible at k={k[~some]}, mu={mu[~some]}")
    assert some.all()


@given(scene(gamma_strategy=solver_gammas))
@pytest.mark.slow
def test_chosen_mode_is_admissible_and_its_reactions_check_out(sc):
    g, kp, k, mu = sc
    lab = classify(k, mu, g, kp)
    tol = 1e-7
    for i in range(k.size):
        mode = Mode(int(lab[i]))
        ok_hyps = [h for h in Hypothesis if h.mode is mode
                   and bool(solve(h, k[i], mu[i], g, kp).ok)]
        note(f"point {i}: k={k[i]!r}, mu={mu[i]!r}, mode {mode.label}")
        assert ok_hyps, f"{mode.label} is not admissible at k={k[i]!r}, mu={mu[i]!r}"
        h = ok_hyps[0]
        r = solve(h, k[i], mu[i], g, kp)
        fx, fy, xi = float(r.fx), float(r.fy), float(r.xi)
        # the equations of motion hold with these reactions
        inertia = (1.0 + g * g) / 3.0
        assert float(r.xdd) == pytest.approx(fx - k[i], abs=tol * (1 + k[i]))
        assert float(r.ydd) == pytest.approx(fy - 1.0, abs=tol)
        assert inertia * float(r.thdd) == pytest.approx(g * fx + xi * fy + g * k[i] * kp,
                                                         abs=tol * (1 + g) * (1 + k[i]))
        assert fy >= -tol  # the base pushes, never pulls
        if h.sigma == 0:  # sticking: friction within the cone
            assert abs(fx) <= mu[i] * fy + tol * (1 + k[i])
        else:  # slipping: friction at the cone, opposite to the slip
            assert fx == pytest.approx(h.sigma * mu[i] * fy, abs=tol * (1 + k[i]))
            assert h.sigma * float(r.slip) <= tol
        if h.contact == "full":
            assert abs(xi) <= 1.0 + tol  # the reaction acts inside the base
            assert abs(float(r.thdd)) <= tol and abs(float(r.ydd)) <= tol  # no rotation, no lift
        else:
            side = -1.0 if h.contact == "O" else 1.0
            assert xi == pytest.approx(side)
            assert float(r.lift) >= -tol  # the other corner lifts (or just stays)


@pytest.mark.parametrize("k,mu,g,kp", [(0.01, 1.0, 30.0, 0.5), (1.0, 1.0, 50.0, -0.5),
                                       (547.65, 374.79, 0.05, -1.0), (0.001, 5.0, 1000.0, 1.0),
                                       (100.0, 0.1, 0.001, -0.5)])
def test_solver_well_conditioned_for_large_gamma_k_and_mu(k, mu, g, kp):
    """Regression: the singularity test once compared |det A| with max|A|^6, so every system
    was 'unsolvable' for gamma >= ~20 or mu ~ 10^2 (fixed by Hadamard's bound)."""
    adm = admissible(k, mu, g, kp)
    assert any(bool(v) for v in adm.values())
    assert bool(adm[Mode(int(classify(k, mu, g, kp)))])
