"""Cross-validation of the loaded block, through the public API, against the generalised solver.

Every raw region (:func:`regimemap.mechanics.regions.raw_region` with a loaded
:class:`~regimemap.Parameters`) equals the admissible set of its solver
hypotheses, and :func:`regimemap.classify` with load keywords equals the
solver's least-constraint choice, over sweeps of gamma, k' (up to the crest),
buoyancy, uplift (fixed and growing with the push), its arm, the inertia, k and
mu.  Points within ~1e-6 (relative to the view) of a boundary are left out and
tested separately: there the label must be admissible.
"""

from __future__ import annotations

import collections
import functools

import numpy as np
import pytest

from regimemap import SELECTION_ORDER, Mode, Parameters, classify, label_grid
from regimemap.mechanics.constants import thresholds
from regimemap.mechanics.curves import named_points
from regimemap.mechanics.regions import RAW_REGIONS
from regimemap.mechanics.solver import least_constraint

from .._sweep import tiered
from ._loaded_sweep import loaded_sweep, sample, view

SWEEP = loaded_sweep(100, seed=0)


@functools.cache
def _solved(i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict]:
    """The sample of ``SWEEP[i]`` (1500 points, seed 7) and the solver's least-constraint choice
    there: (k, mu, codes, admissible), computed once per process for the two tests that use it
    (about 6 MB for the whole sweep).  Read-only."""
    gamma, kprime, loads = SWEEP[i]
    k, mu = sample(gamma, kprime, loads, 1500, seed=7)
    codes, adm, _ = least_constraint(k, mu, gamma, kprime, **loads)
    return k, mu, codes, adm


def near_boundary(k, mu, g, kp, loads, codes, adm, rel=1e-6):
    """Points where the solver's admissible sets or choice change under a small move."""
    k_hi, mu_hi = view(g, kp, loads)
    near = np.zeros(k.shape, bool)
    for dk, dm in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1)):
        c2, a2, _ = least_constraint(np.maximum(k + dk * rel * k_hi, 0), np.maximum(mu + dm * rel * mu_hi, 0),
                                     g, kp, **loads)
        near |= c2 != codes
        for c in adm:
            near |= a2[c] != adm[c]
    return near


@pytest.mark.parametrize(("i",), tiered([(i,) for i in range(len(SWEEP))], every=8, deep=8),
                         ids=[f"{g:.3g}-{kp:.3g}-{n}" for n, (g, kp, _) in enumerate(SWEEP)])
def test_raw_regions_and_classify_equal_the_solver(i):
    gamma, kprime, loads = SWEEP[i]
    k, mu, codes, adm = _solved(i)
    keep = ~near_boundary(k, mu, gamma, kprime, loads, codes, adm)
    assert keep.mean() > 0.9
    p = Parameters(gamma, kprime, **loads)
    for mode, region in RAW_REGIONS.items():
        raw = region(p, k, mu)
        bad = keep & (raw != adm[mode])
        assert not bad.any(), (mode.label, k[bad][:3], mu[bad][:3], raw[bad][:3])
    lab = classify(k, mu, gamma, kprime, **loads)
    bad = keep & (lab != codes)
    assert not bad.any(), (k[bad][:3], mu[bad][:3], lab[bad][:3], codes[bad][:3])
    # the fixed selection order is least constraint (also on the boundaries left out)
    stack = np.stack([adm[c] for c in SELECTION_ORDER])
    first = np.array([int(m) for m in SELECTION_ORDER])[np.argmax(stack, axis=0)]
    assert np.array_equal(first[keep], codes[keep])


def _boundary_points(gamma, kprime, loads, rng):
    """Points on every threshold curve of the column rule and on the verticals of the named points."""
    p = Parameters(gamma, kprime, **loads)
    k_hi, mu_hi = view(gamma, kprime, loads)
    k = rng.uniform(0, k_hi, 300)
    t = thresholds(k, p.constants)
    ks, mus = [], []
    for curve in (t.mu_rest, t.upper, t.lower, t.mu_star, np.full(k.shape, p.mu_Bprime)):
        ok = np.isfinite(curve) & (curve >= 0)
        ks.append(k[ok])
        mus.append(curve[ok])
    for pt in named_points(p).values():
        ks.append(np.full(60, pt.k))
        mus.append(rng.uniform(0, mu_hi, 60))
    return np.concatenate(ks), np.concatenate(mus)


@pytest.mark.parametrize("gamma,kprime,loads", SWEEP[::3])
def test_boundary_labels_are_admissible(gamma, kprime, loads):
    kk, mm = _boundary_points(gamma, kprime, loads, np.random.default_rng(11))
    lab = classify(kk, mm, gamma, kprime, **loads)
    _, adm, _ = least_constraint(kk, mm, gamma, kprime, tol=1e-7, **loads)
    for mode in Mode:
        sel = lab == mode
        assert adm[mode][sel].all(), (mode.label, kk[sel & ~adm[mode]][:3], mm[sel & ~adm[mode]][:3])


@pytest.mark.parametrize("gamma,kprime,loads", SWEEP[::4])
def test_label_grid_equals_classify_exactly(gamma, kprime, loads):
    k_hi, mu_hi = view(gamma, kprime, loads)
    kk = np.linspace(0, k_hi, 157)
    mu = np.linspace(0, mu_hi, 131)
    p = Parameters(gamma, kprime, **loads)
    # axes through the thresholds themselves
    t = thresholds(kk[::13], p.constants)
    extra = np.concatenate([t.mu_rest, t.upper, t.lower, t.mu_star, [p.mu_Bprime]])
    mu = np.unique(np.concatenate([mu, extra[np.isfinite(extra) & (extra >= 0)]]))
    kk = np.unique(np.concatenate([kk, [pt.k for pt in named_points(p).values()]]))
    grid = label_grid(kk, mu, gamma, kprime, **loads)
    K, M = np.meshgrid(kk, mu)
    assert grid.shape == (mu.size, kk.size) and grid.flags["C_CONTIGUOUS"]
    assert np.array_equal(grid, classify(K, M, gamma, kprime, **loads))
    perm = np.random.default_rng(0).permutation(mu.size)
    assert np.array_equal(label_grid(kk, mu[perm], gamma, kprime, **loads), grid[perm])
    assert np.array_equal(label_grid(kk, mu[::-1], gamma, kprime, **loads), grid[::-1])


@pytest.mark.slow
def test_lift_off_is_a_whole_column():
    seen = 0
    for g, kp, loads in SWEEP:
        k_hi, mu_hi = view(g, kp, loads)
        kk = np.linspace(0, k_hi, 301)
        grid = label_grid(kk, np.linspace(0, mu_hi, 101), g, kp, **loads)
        lo = grid == Mode.LO
        assert np.array_equal(lo.any(axis=0), lo.all(axis=0))
        # and it starts at L
        p = Parameters(g, kp, **loads)
        if lo.any():
            seen += 1
            assert np.isfinite(p.k_L) and (kk[lo.any(axis=0)] >= p.k_L).all()
    assert seen


@pytest.mark.slow
@pytest.mark.deep
def test_loads_create_new_modes_and_overlaps():
    """Which modes win and which overlaps occur with loads (least constraint decides them)."""
    won, overlaps = collections.Counter(), collections.Counter()
    for case in range(len(SWEEP)):
        _, _, codes, adm = _solved(case)
        won.update(Mode(c).label for c in np.unique(codes))
        stack = np.stack([adm[c] for c in SELECTION_ORDER])
        for i in np.flatnonzero(stack.sum(axis=0) > 1):
            overlaps[frozenset(m.label for m in SELECTION_ORDER if adm[m][i])] += 1
    assert won["LO"] and won["RO'"] and won["SRO+"]
    assert not won["SRO'+"]  # hence LOADED_MAP_MODES
    assert frozenset({"LO", "RO", "SRO-"}) in overlaps
    assert frozenset({"SL", "RO", "SRO-"}) in overlaps
    assert frozenset({"SRO'-", "RO", "SRO-"}) in overlaps
