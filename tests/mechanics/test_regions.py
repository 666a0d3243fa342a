"""Every raw region of the report equals the solver's admissible set of its mode.

Points within a small distance of a boundary are left out: a point is kept only
when the predicate and the solver each give the same answer at the point and at
its four neighbours (k +- h, mu +- h).
"""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Mode, Parameters
from regimemap.mechanics.regions import RAW_REGIONS, raw_region
from regimemap.mechanics.solver import admissible

from .._sweep import sample_points, sweep, tiered

H = 1e-6


def _stable(fn, k, mu):
    base = fn(k, mu)
    ok = np.ones(k.shape, bool)
    for dk, dm in ((H, 0), (-H, 0), (0, H), (0, -H)):
        kk, mm = np.maximum(k + dk, 0), np.maximum(mu + dm, 0)
        ok &= fn(kk, mm) == base
    return base, ok


# k' every 0.25 and at every case threshold of the report (tests/_sweep.py), for the 12 aspect
# ratios: 149 (gamma, k') pairs, 2500 random points each.  The regions change form only at the
# thresholds, which are all in; the grid at 0.125 (243 pairs) added interior k' only.
@pytest.mark.parametrize("gamma,kprime", tiered(sweep(9), every=8, deep=8))
def test_raw_regions_equal_solver(gamma, kprime):
    p = Parameters(gamma, kprime)
    k, mu = sample_points(gamma, kprime, 2500, seed=int(gamma * 100 + kprime * 10) % 997)
    base = admissible(k, mu, gamma, kprime)
    perturbed = [admissible(np.maximum(k + dk, 0), np.maximum(mu + dm, 0), gamma, kprime)
                 for dk, dm in ((H, 0), (-H, 0), (0, H), (0, -H))]
    for mode in Mode:
        pred, ok1 = _stable(lambda a, b, mode=mode: raw_region(mode, p, a, b), k, mu)
        adm = base[mode]
        ok2 = np.logical_and.reduce([q[mode] == adm for q in perturbed])
        keep = ok1 & ok2
        assert keep.mean() > 0.95
        bad = keep & (pred != adm)
        assert not bad.any(), (mode.label, k[bad][:3], mu[bad][:3])


def test_regions_are_not_trivial():
    # the sweep would pass with empty predicates: check each region is somewhere non-empty
    seen = {m: False for m in (Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS,
                               Mode.SRO_PRIME_MINUS)}
    for g, kp in sweep(11):
        p = Parameters(g, kp)
        k, mu = sample_points(g, kp, 2000)
        for m in seen:
            seen[m] |= bool(raw_region(m, p, k, mu).any())
    assert all(seen.values()), seen


def test_points_well_inside_regions():
    # worked by hand from the equations (Chapter III, gamma = 3, k' = 0.4: k_A = 1/(3*1.4))
    p = Parameters(3.0, 0.4)
    assert raw_region(Mode.RE, p, 0.1, 0.5)
    assert raw_region(Mode.SL, p, 0.3, 0.05)
    assert raw_region(Mode.RO, p, 1.0, 0.9)
    assert raw_region(Mode.SRO_MINUS, p, 1.0, 0.1)  # CD(1) < 0 < 0.1 < mu*(1) = 0.226
    q = Parameters(3.0, 0.9)  # a < 0: case 3 beyond k = b/|a|
    assert q.a < 0
    k = 2 * q.b_over_abs_a
    assert raw_region(Mode.SRO_PLUS, q, k, 0.01)
    r = Parameters(1.0, -0.8)  # below C, far below DC
    assert raw_region(Mode.SRO_PRIME_MINUS, r, 5.0, 0.1)


def test_regions_overlap_only_below_C():
    for g, kp in sweep(11):
        p = Parameters(g, kp)
        k, mu = sample_points(g, kp, 3000, seed=5)
        stack = np.stack([RAW_REGIONS[m](p, k, mu) for m in Mode])
        # strict interior: perturbation-stable multiplicity
        many = stack.sum(axis=0) > 1
        if kp >= 0 and many.any():
            # only on boundaries: each such point must change under a tiny perturbation
            kk, mm = k[many], mu[many]
            n_pert = np.stack([RAW_REGIONS[m](p, kk + 1e-7, mm + 1e-7) for m in Mode]).sum(axis=0)
            n_pert2 = np.stack([RAW_REGIONS[m](p, kk - 1e-7, mm - 1e-7) for m in Mode]).sum(axis=0)
            assert ((n_pert == 1) | (n_pert2 == 1)).all(), (g, kp)
