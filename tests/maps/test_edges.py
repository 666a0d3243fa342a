"""Edge parameters, tested one by one: k' = 0, +-1, the case thresholds, gamma = sqrt 2, 2,
0.05, 50 (and the limits 0.001, 1000), the axes k = 0 and mu = 0.

At each: the label of classify is admissible in the solver, label_grid, the
region polygons and the curves are finite and raise no RuntimeWarning (every
test here runs with warnings turned into errors), and Parameters.case follows
its documented tie rule (the lower case at a threshold).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap import MAP_MODES, Case, Mode, Parameters, classify, label_grid
from regimemap.maps.geometry import breakpoints, region_polygons
from regimemap.mechanics.curves import (
    dotted_line,
    lower_line,
    mu_star,
    mu_star_signed,
    mu_star_star,
    named_points,
    upper_line,
)
from regimemap.mechanics.solver import admissible
from regimemap.mechanics.validation import GAMMA_MAX, GAMMA_MIN, MAX_VALUE

pytestmark = pytest.mark.filterwarnings("error")  # any warning fails the test

SQRT2 = math.sqrt(2.0)
GAMMAS = [0.05, 1.0, SQRT2, 2.0, 3.0, 50.0]
MAP_CODES = {int(m) for m in MAP_MODES}


def thresholds(g: float) -> list[tuple[str, float]]:
    """The edge values of k' for gamma = g, by name."""
    p = Parameters(g, 0.0)
    out = [("0", 0.0), ("-0", -0.0), ("1", 1.0), ("-1", -1.0), ("+1e-9", 1e-9), ("-1e-9", -1e-9),
           ("-kprime_delta", -p.kprime_delta)]
    if p.kprime_1 <= 1.0:
        out.append(("kprime_1", p.kprime_1))
    if p.kprime_2 <= 1.0:
        out.append(("kprime_2", p.kprime_2))
    return out


EDGES = [(g, name, kp) for g in GAMMAS for name, kp in thresholds(g)]
EDGE_IDS = [f"g{g:g}-kp{name}" for g, name, _ in EDGES]


def view(p: Parameters) -> tuple[float, float]:
    marks = [p.k_A, p.k_Bprime, p.b_over_abs_a, p.k_D, p.k_pole, 1.0]
    k_hi = min(3.0 * max(x for x in marks if math.isfinite(x) and x < 1e6), 60.0)
    mu_hi = min(2.0 * max(p.mu_Bprime, 1.0 / p.gamma, 1.0), 60.0)
    return k_hi, mu_hi


def edge_points(p: Parameters) -> tuple[np.ndarray, np.ndarray]:
    """Points on the axes k = 0 and mu = 0, at the named points and on a grid."""
    k_hi, mu_hi = view(p)
    ks = np.linspace(0.0, k_hi, 41)
    mus = np.linspace(0.0, mu_hi, 41)
    k = [np.zeros_like(mus), ks, *np.meshgrid(ks, mus)[0:1]]
    mu = [mus, np.zeros_like(ks), *np.meshgrid(ks, mus)[1:2]]
    named = [pt for pt in named_points(p).values() if pt.k <= 1e6 and pt.mu <= 1e6]
    k.append(np.array([pt.k for pt in named]))
    mu.append(np.array([pt.mu for pt in named]))
    return np.concatenate([a.ravel() for a in k]), np.concatenate([a.ravel() for a in mu])


# -- the label is admissible in the solver --------------------------------------------------------------

@pytest.mark.parametrize("g,name,kp", EDGES, ids=EDGE_IDS)
def test_label_is_admissible_at_edges(g, name, kp):
    p = Parameters(g, kp)
    k, mu = edge_points(p)
    lab = classify(k, mu, g, kp)
    assert set(np.unique(lab).tolist()) <= MAP_CODES
    adm = admissible(k, mu, g, kp)
    ok = np.zeros(k.shape, bool)
    for mode, a in adm.items():
        ok |= a & (lab == int(mode))
    bad = np.flatnonzero(~ok)
    assert bad.size == 0, [(float(k[i]), float(mu[i]), Mode(int(lab[i])).label) for i in bad[:5]]


def test_origin_is_rest_for_every_edge():
    """k = 0 (no force): rest, whatever mu (even mu = 0) and k'."""
    for g, _, kp in EDGES:
        assert classify([0.0, 0.0, 0.0], [0.0, 1e-300, 5.0], g, kp).tolist() == [int(Mode.RE)] * 3


@pytest.mark.parametrize("g", GAMMAS)
def test_mu_zero_slides_or_slide_rocks(g):
    """mu = 0 and k > 0: the base cannot hold the block; it slides (or slide-rocks)."""
    for _, _, kp in [e for e in EDGES if e[0] == g]:
        k = np.geomspace(1e-9, 50.0, 60)
        lab = classify(k, 0.0, g, kp)
        assert int(Mode.RE) not in lab.tolist() and int(Mode.RO) not in lab.tolist()


# -- k' = -1 and k' = +1 ---------------------------------------------------------------------------------

@pytest.mark.parametrize("g", GAMMAS)
def test_kprime_minus_one_rest_for_every_mu_at_least_k(g):
    """k' = -1 (force at the base): k_A is infinite, the block rests wherever mu >= k."""
    p = Parameters(g, -1.0)
    assert p.k_A == math.inf and p.mu_A == math.inf and p.k_pole == math.inf
    k = np.array([0.0, 1e-6, 0.5, 1.0, 10.0, 1e3, 1e6, MAX_VALUE])
    assert (classify(k, k, g, -1.0) == int(Mode.RE)).all()
    assert (classify(k[:-1], 2 * k[:-1] + 1.0, g, -1.0) == int(Mode.RE)).all()
    # just below mu = k it moves (slides: the force acts at the base, no moment)
    below = classify(k[1:], k[1:] * (1 - 1e-9), g, -1.0)
    assert int(Mode.RE) not in below.tolist()


@pytest.mark.parametrize("g", GAMMAS)
def test_kprime_plus_one(g):
    p = Parameters(g, 1.0)
    assert p.k_A == pytest.approx(1.0 / (2.0 * g))
    k_hi, mu_hi = view(p)
    grid = label_grid(np.linspace(0, k_hi, 101), np.linspace(0, mu_hi, 101), g, 1.0)
    assert set(np.unique(grid).tolist()) <= MAP_CODES
    assert grid[0, 0] == int(Mode.RE)


# -- k' = 0 from both sides ---------------------------------------------------------------------------

@pytest.mark.parametrize("g", GAMMAS)
def test_kprime_zero_same_map_from_both_chapters(g):
    """At k' = 0 the two chapters give one map; -0.0 is +0.0, and +-1e-9 differ only on boundaries."""
    p0, pm = Parameters(g, 0.0), Parameters(g, -0.0)
    assert p0 == pm and math.copysign(1.0, pm.kprime) == 1.0 and pm.case is Case.ABOVE_1A
    k_hi, mu_hi = view(p0)
    k_axis, mu_axis = np.linspace(0, k_hi, 201), np.linspace(0, mu_hi, 201)
    g0 = label_grid(k_axis, mu_axis, g, 0.0)
    assert np.array_equal(g0, label_grid(k_axis, mu_axis, g, -0.0))
    up, down = label_grid(k_axis, mu_axis, g, 1e-9), label_grid(k_axis, mu_axis, g, -1e-9)
    differ = (up != g0) | (down != g0)
    # differences only next to a boundary of the k' = 0 map
    edge = np.zeros_like(differ)
    edge[:-1, :] |= g0[:-1, :] != g0[1:, :]
    edge[1:, :] |= g0[:-1, :] != g0[1:, :]
    edge[:, :-1] |= g0[:, :-1] != g0[:, 1:]
    edge[:, 1:] |= g0[:, :-1] != g0[:, 1:]
    assert not (differ & ~edge).any()


# -- the cases at their thresholds ----------------------------------------------------------------------

@pytest.mark.parametrize("g", GAMMAS + [0.3, 0.7, 1.2, 4.0, 10.0, GAMMA_MIN, GAMMA_MAX])
def test_case_at_thresholds_is_the_lower_case(g):
    p = Parameters(g, 0.0)
    assert Parameters(g, 0.0).case is Case.ABOVE_1A
    assert Parameters(g, -0.0).case is Case.ABOVE_1A
    if p.kprime_1 <= 1.0:
        assert Parameters(g, p.kprime_1).case is Case.ABOVE_1A
        assert Parameters(g, math.nextafter(p.kprime_1, 2.0)).case is Case.ABOVE_1B
    else:  # gamma < 1/sqrt 2: case 1a up to k' = 1
        assert Parameters(g, 1.0).case is Case.ABOVE_1A
    assert Parameters(g, -p.kprime_delta).case is Case.BELOW_DELTA_POS
    assert Parameters(g, math.nextafter(-p.kprime_delta, -2.0)).case is Case.BELOW_DELTA_NEG
    assert Parameters(g, -1.0).case is (Case.BELOW_DELTA_NEG if p.kprime_delta < 1.0 else Case.BELOW_DELTA_POS)


# 42.50448286924489: a = 4+g^2-3g^2k' rounds to -2.3e-13 at k' = kprime_2 (regression)
@pytest.mark.parametrize("g", [2.0, 3.0, 50.0, GAMMA_MAX, 42.50448286924489])
def test_case_at_kprime_2_is_1b(g):
    p = Parameters(g, 0.0)
    assert p.kprime_2 <= 1.0
    assert Parameters(g, p.kprime_2).case is Case.ABOVE_1B
    nxt = math.nextafter(p.kprime_2, 2.0)
    if nxt <= 1.0:
        assert Parameters(g, math.nextafter(nxt, 2.0)).case is Case.ABOVE_2_3


def test_gamma_sqrt2_cases():
    """gamma = sqrt 2 is where cases 2/3 appear: kprime_2 = 1 (up to rounding)."""
    p = Parameters(SQRT2, 1.0)
    assert p.kprime_2 == pytest.approx(1.0, abs=1e-15)
    assert abs(p.a) < 1e-14  # a = 0 at k' = 1: b/|a| is astronomically far
    # just below: case 1 throughout, never 2/3
    assert Parameters(SQRT2 * (1 - 1e-9), 1.0).case is Case.ABOVE_1B
    assert Parameters(SQRT2 * (1 + 1e-9), 1.0).case is Case.ABOVE_2_3
    assert Parameters(2.0, 1.0).case is Case.ABOVE_2_3  # kprime_2(2) = 2/3


# -- finite output, no RuntimeWarning -----------------------------------------------------------------

def _all_finite_polygons(polys) -> bool:
    return all(np.isfinite(poly).all() for lst in polys.values() for poly in lst)


EDGES_AND_LIMITS = EDGES + [(g, name, kp) for g in (GAMMA_MIN, GAMMA_MAX)
                            for name, kp in thresholds(g)]


def _edge_param(e, ident):
    return pytest.param(*e, id=ident)


@pytest.mark.parametrize("g,name,kp", [_edge_param(e, i) for e, i in zip(
    EDGES_AND_LIMITS, EDGE_IDS + [f"g{g:g}-kp{n}" for g in (GAMMA_MIN, GAMMA_MAX) for n, _ in thresholds(g)])])
def test_engine_output_finite_without_warnings(g, name, kp):
    p = Parameters(g, kp)
    # a floating-point error outside an explicit errstate raises (underflow is harmless)
    with np.errstate(over="raise", divide="raise", invalid="raise"):
        d = p.as_dict()
        assert all(isinstance(v, str) or not math.isnan(v) for v in d.values()), d
        k_hi, mu_hi = view(p)
        k_axis = np.concatenate([[0.0], np.geomspace(1e-12, k_hi, 60), [p.k_A] if p.k_A < 1e6 else []])
        mu_axis = np.concatenate([[0.0], np.geomspace(1e-12, mu_hi, 60)])
        grid = label_grid(k_axis, mu_axis, g, kp)
        assert set(np.unique(grid).tolist()) <= MAP_CODES
        K, MU = np.meshgrid(k_axis, mu_axis)
        assert np.array_equal(grid, classify(K, MU, g, kp))
        for f in (mu_star, mu_star_signed, upper_line, lower_line, dotted_line):
            assert np.isfinite(f(p, k_axis)).all(), f.__name__
        mss = mu_star_star(p, k_axis)
        assert not np.isnan(mss).any()
        for pt in named_points(p).values():
            assert math.isfinite(pt.k) and math.isfinite(pt.mu), pt
        assert all(math.isfinite(x) for x in breakpoints(p))
        for raw in (False, True):
            polys = region_polygons(p, k_hi, mu_hi, raw=raw, samples=101)
            assert _all_finite_polygons(polys)
            assert set(polys) == set(MAP_MODES)
        assert any(polys[m] for m in MAP_MODES)


@pytest.mark.parametrize("g", [GAMMA_MIN, 0.05, SQRT2, 50.0, GAMMA_MAX])
@pytest.mark.parametrize("kp", [-1.0, -0.5, 0.0, 0.5, 1.0])
def test_extreme_k_and_mu_without_warnings(g, kp):
    """k, mu from 0 up to MAX_VALUE (1e100): labels, no overflow warning."""
    vals = np.array([0.0, 5e-324, 1e-300, 1e-9, 1.0, 1e9, 1e50, MAX_VALUE])
    K, MU = np.meshgrid(vals, vals)
    with np.errstate(over="raise", divide="raise", invalid="raise"):
        lab = classify(K, MU, g, kp)
        assert np.array_equal(label_grid(vals, vals, g, kp), lab)
    assert set(np.unique(lab).tolist()) <= MAP_CODES
    # far out along the k axis with moderate mu the force wins: the block moves
    assert (lab[3:5, -1] != int(Mode.RE)).all() or kp == -1.0


@pytest.mark.parametrize("k_max,mu_max", [(1e-12, 1e-12), (1e-6, 5.0), (5.0, 1e-6), (1e6, 1e6)])
def test_polygons_for_extreme_views(k_max, mu_max):
    for g, kp in [(3.0, 0.4), (3.0, -0.6), (0.05, -1.0), (50.0, 1.0), (SQRT2, 1.0)]:
        with np.errstate(over="raise", divide="raise", invalid="raise"):
            polys = region_polygons(Parameters(g, kp), k_max, mu_max, samples=51)
        assert _all_finite_polygons(polys)
