"""classify and label_grid against the solver, Section 4.7 and Shenton (1996)."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import PRIORITY, Mode, Parameters, classify, label_grid
from regimemap.mechanics.curves import lower_line, mu_star, upper_line
from regimemap.mechanics.regions import RAW_REGIONS
from regimemap.mechanics.solver import admissible, choose

from .._sweep import sample_points, sweep, tiered

H = 1e-6


def _near_boundary(k, mu, gamma, kprime):
    lab = classify(k, mu, gamma, kprime)
    near = np.zeros(k.shape, bool)
    for dk, dm in ((H, 0), (-H, 0), (0, H), (0, -H)):
        near |= classify(np.maximum(k + dk, 0), np.maximum(mu + dm, 0), gamma, kprime) != lab
    return near


@pytest.mark.parametrize("gamma,kprime", tiered(sweep(17), deep=4))
def test_classify_equals_solver_choice(gamma, kprime):
    k, mu = sample_points(gamma, kprime, 5000, seed=7)
    keep = ~_near_boundary(k, mu, gamma, kprime)
    assert keep.mean() > 0.95
    lab = classify(k, mu, gamma, kprime)
    chosen = choose(admissible(k, mu, gamma, kprime))
    bad = keep & (lab != chosen)
    assert not bad.any(), (k[bad][:3], mu[bad][:3], lab[bad][:3], chosen[bad][:3])


@pytest.mark.parametrize("gamma,kprime", tiered(sweep(11), deep=4))
def test_boundary_labels_are_admissible(gamma, kprime):
    """On every boundary curve the documented label is one the solver admits."""
    p = Parameters(gamma, kprime)
    rng = np.random.default_rng(11)
    k = rng.uniform(0, 3 * min(p.k_A, 20), 400)
    curves = [k.copy(), upper_line(p, k), lower_line(p, k), mu_star(p, k)]
    ks, mus = [], []
    for c in curves:
        ok = c >= 0
        ks.append(k[ok])
        mus.append(c[ok])
    if np.isfinite(p.k_A):  # the vertical through A
        ks.append(np.full(200, p.k_A))
        mus.append(rng.uniform(0, 4, 200))
    kk, mm = np.concatenate(ks), np.concatenate(mus)
    lab = classify(kk, mm, gamma, kprime)
    adm = admissible(kk, mm, gamma, kprime, tol=1e-7)
    for m in Mode:
        sel = lab == m
        assert adm[m][sel].all(), (m.label, kk[sel & ~adm[m]][:3], mm[sel & ~adm[m]][:3])


@pytest.mark.parametrize("gamma", [0.3, 1.0, 2.0, 3.0, 6.0])
def test_kprime_zero_is_shenton(gamma):
    """k' = 0 is Shenton (1996)'s map for base acceleration A = k."""
    k, mu = sample_points(gamma, 0.0, 20000, seed=3)
    keep = ~_near_boundary(k, mu, gamma, 0.0)
    g = gamma
    ms = ((4 + g * g) * k + 3 * g) / (3 * g * k + 1 + 4 * g * g)
    rest = (k <= mu) & (k <= 1 / g)
    slide = (mu < 1 / g) & (k > mu)
    rock = (k > 1 / g) & (mu >= ms)
    sliderock = ~(rest | slide | rock)
    expect = np.select([rest, slide, rock, sliderock], [Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS])
    lab = classify(k, mu, gamma, 0.0)
    assert (lab[keep] == expect[keep]).all()
    # and both chapters' formulas agree at k' = 0: -0.0 is folded to +0.0
    assert (classify(k, mu, gamma, -0.0) == lab).all()


def test_kprime_zero_limit_from_both_sides():
    for g in (0.5, 1.0, 3.0):
        k, mu = sample_points(g, 0.0, 5000, seed=4)
        keep = ~_near_boundary(k, mu, g, 0.0)
        a, b = classify(k, mu, g, 1e-9), classify(k, mu, g, -1e-9)
        assert (a[keep] == b[keep]).all()


@pytest.mark.slow
@pytest.mark.deep
def test_painleve_non_uniqueness_matches_section_4_7():
    """The solver admits several modes at once only below C with mu > (4+g^2)/(3g);
    there the raw regions overlap, and classify picks Section 4.7's mode."""
    found = set()
    for g, kp in sweep(9):
        p = Parameters(g, kp)
        k, mu = sample_points(g, kp, 2000, seed=9)
        keep = ~_near_boundary(k, mu, g, kp)
        adm = admissible(k, mu, g, kp)
        many = (np.stack(list(adm.values())).sum(axis=0) > 1) & keep
        # robustly inside: the multiplicity survives perturbations (admissible is pointwise: only
        # the points still in question are perturbed)
        for dk, dm in ((H, H), (-H, -H), (H, -H), (-H, H)):
            sel = np.flatnonzero(many)
            if sel.size == 0:
                break
            adm2 = admissible(k[sel] + dk, np.maximum(mu[sel] + dm, 0), g, kp)
            many[sel] = np.stack(list(adm2.values())).sum(axis=0) > 1
        if not many.any():
            continue
        assert kp < 0, (g, kp)
        assert (mu[many] > p.mu_Bprime).all()
        raw = {m: RAW_REGIONS[m](p, k, mu) for m in Mode}
        for i in np.flatnonzero(many):
            sset = {m for m in Mode if adm[m][i]}
            assert sset == {m for m in Mode if raw[m][i]}  # the report's regions overlap there
            first = next(m for m in PRIORITY if m in sset)
            assert classify(k[i], mu[i], g, kp) == first
            found.add(frozenset(x.label for x in sset))
    # the overlaps Section 4.7 resolves: inside the slide region (BB'C'C, BAC'C) and
    # below DC (CC'C''), each with SRO- of the branch mu >= mu_B' (Fig 4.5b)
    assert frozenset({"SL", "RO", "SRO-"}) in found, found
    assert frozenset({"SRO'-", "RO", "SRO-"}) in found, found


def test_label_grid_equals_classify_exactly():
    for g, kp in [(3.0, 0.4), (3.0, 0.9), (1.0, -0.3), (3.0, -0.8), (0.5, 0.0), (2.0, -1.0), (2.0, 1.0)]:
        k = np.linspace(0, 4, 301)
        mu = np.linspace(0, 3, 257)
        grid = label_grid(k, mu, g, kp)
        K, M = np.meshgrid(k, mu)
        assert grid.shape == (mu.size, k.size)
        assert grid.flags["C_CONTIGUOUS"]
        assert (grid == classify(K, M, g, kp)).all()
        # any order of the mu axis
        assert (label_grid(k, mu[::-1], g, kp) == grid[::-1]).all()
        perm = np.random.default_rng(0).permutation(mu.size)
        assert (label_grid(k, mu[perm], g, kp) == grid[perm]).all()


def test_label_grid_on_exact_thresholds():
    # axes that contain the threshold values themselves: the grid still equals classify
    p = Parameters(2.0, -0.3)
    k = np.array([0.0, p.k_A, p.k_Bprime, p.k_D, 1.0, 2.0])
    mu = np.unique(np.concatenate([k, upper_line(p, k), mu_star(p, k), [p.mu_Bprime]]))
    mu = mu[mu >= 0]
    K, M = np.meshgrid(k, mu)
    assert (label_grid(k, mu, 2.0, -0.3) == classify(K, M, 2.0, -0.3)).all()


def test_classify_broadcasts_like_a_ufunc():
    k = np.linspace(0, 2, 5)[:, None]
    mu = np.linspace(0, 2, 4)[None, :]
    out = classify(k, mu, 3.0, 0.4)
    assert out.shape == (5, 4) and out.dtype == np.uint8
    gam = np.array([1.0, 3.0])[:, None, None]
    out2 = classify(k, mu, gam, 0.4)
    assert out2.shape == (2, 5, 4)
    assert (out2[1] == out).all()
    assert (out2[0] == classify(k, mu, 1.0, 0.4)).all()
    assert classify(0.1, 0.5, 3.0, 0.4).shape == ()
    assert Mode(classify(0.1, 0.5, 3.0, 0.4)) is Mode.RE


def test_hand_worked_examples():
    # gamma = 3, k' = 0.4 (case 1b): k_A = 0.238
    cases = {
        (0.1, 0.5): Mode.RE,
        (0.3, 0.05): Mode.SL,
        (1.0, 0.9): Mode.RO,
        (1.0, 0.1): Mode.SRO_MINUS,  # CD(1) = -0.067, mu*(1) = 11.2/49.6 = 0.226
    }
    for (k, mu), mode in cases.items():
        assert classify(k, mu, 3.0, 0.4) == mode
    # below C, gamma = 1, k' = -0.8: k_A = 5, D at k = 1.25
    assert classify(3.0, 0.1, 1.0, -0.8) == Mode.SRO_PRIME_MINUS
    assert classify(3.0, 2.0, 1.0, -0.8) == Mode.SL
    assert classify(3.0, 3.5, 1.0, -0.8) == Mode.RE


def test_only_map_modes_are_produced():
    for g, kp in sweep(7):
        k, mu = sample_points(g, kp, 3000)
        lab = classify(k, mu, g, kp)
        assert set(np.unique(lab)) <= {int(m) for m in (Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS,
                                                        Mode.SRO_PLUS, Mode.SRO_PRIME_MINUS)}
