"""Property tests (hypothesis) of the loaded column rule and solver."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, note
from hypothesis import strategies as st

from regimemap import Mode, Parameters, classify, label_grid
from regimemap.mechanics.solver import least_constraint

from ._loaded_sweep import view

CODES = {int(m) for m in Mode}

gammas = st.floats(math.log(0.3), math.log(6.0)).map(math.exp)


@st.composite
def loaded_params(draw):
    g = draw(gammas)
    crest = draw(st.one_of(st.just(1.0), st.floats(0.3, 2.0)))
    kp = draw(st.one_of(st.floats(-1.0, crest), st.sampled_from([-1.0, 0.0, crest])))
    loads = dict(
        buoyancy=draw(st.one_of(st.just(0.0), st.floats(0.0, 0.99))),
        uplift=draw(st.one_of(st.just(0.0), st.floats(0.0, 2.0))),
        uplift_ratio=draw(st.one_of(st.just(0.0), st.floats(0.0, 2.0))),
        uplift_arm=draw(st.one_of(st.just(1 / 3), st.floats(-1.0, 1.0))),
        gyration=draw(st.one_of(st.none(), st.floats(0.2, 3.0))),
        crest=crest,
    )
    return g, kp, loads


@st.composite
def loaded_scene(draw, n_max=40):
    g, kp, loads = draw(loaded_params())
    k_hi, mu_hi = view(g, kp, loads)
    n = draw(st.integers(1, n_max))
    unit = st.one_of(st.floats(0.0, 1.0), st.sampled_from([0.0, 1.0]))
    k = np.array(draw(st.lists(unit, min_size=n, max_size=n))) * k_hi
    mu = np.array(draw(st.lists(unit, min_size=n, max_size=n))) * mu_hi
    return g, kp, loads, k, mu


def _solver_kw(loads):
    return {key: v for key, v in loads.items() if key != "crest"}


@given(loaded_scene())
@pytest.mark.slow
def test_exactly_one_mode_per_point(sc):
    g, kp, loads, k, mu = sc
    lab = classify(k, mu, g, kp, **loads)
    assert lab.shape == k.shape and lab.dtype == np.uint8
    assert set(np.unique(lab).tolist()) <= CODES  # never 255: some rule always applies


@given(loaded_scene())
@pytest.mark.slow
def test_solver_admissible_set_never_empty_and_label_admissible(sc):
    g, kp, loads, k, mu = sc
    codes, adm, _ = least_constraint(k, mu, g, kp, tol=1e-7, **_solver_kw(loads))
    assert (codes != 255).all()
    lab = classify(k, mu, g, kp, **loads)
    for c in CODES:
        sel = lab == c
        note(f"{c}: k={k[sel & ~adm[c]]}, mu={mu[sel & ~adm[c]]}")
        assert adm[c][sel].all()


@given(loaded_scene(n_max=20), st.floats(1e-12, 1e-9))
@pytest.mark.slow
def test_continuity_at_zero_loads(sc, eps):
    """Tiny loads (and a tiny change of inertia) change no label away from the boundaries."""
    g, kp, _, k, mu = sc
    kp = min(kp, 1.0)
    base = classify(k, mu, g, kp)
    k_hi, mu_hi = view(g, kp, {})
    near = np.zeros(k.shape, bool)
    for dk, dm in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        near |= classify(np.maximum(k + dk * 1e-6 * k_hi, 0), np.maximum(mu + dm * 1e-6 * mu_hi, 0),
                                g, kp) != base
    assume((~near).any())
    i = math.sqrt((1 + g * g) / 3) * (1 + eps)
    for loads in (dict(buoyancy=eps), dict(uplift=eps), dict(uplift_ratio=eps),
                  dict(uplift=eps, uplift_arm=-1.0), dict(gyration=i),
                  dict(buoyancy=eps, uplift=eps, uplift_ratio=eps, uplift_arm=0.7)):
        lab = classify(k, mu, g, kp, **loads)
        assert np.array_equal(lab[~near], base[~near]), loads


@given(loaded_params(), st.integers(1, 30), st.integers(1, 30))
def test_grid_equals_pointwise(p, nk, nm):
    g, kp, loads = p
    k_hi, mu_hi = view(g, kp, loads)
    rng = np.random.default_rng(nk * 31 + nm)
    kk = rng.uniform(0, k_hi, nk)
    mu = rng.uniform(0, mu_hi, nm)
    grid = label_grid(kk, mu, g, kp, **loads)
    K, M = np.meshgrid(kk, mu)
    assert np.array_equal(grid, classify(K, M, g, kp, **loads))


def test_parameters_are_validated():
    import pytest

    for kw, msg in ((dict(buoyancy=1.0), r"buoyancy must be a number in \[0, 1\), got 1.0"),
                    (dict(buoyancy=-0.1), r"buoyancy must be a number in \[0, 1\), got -0.1"),
                    (dict(uplift=-1.0), r"uplift must be a number in \[0, 1e\+06\], got -1.0"),
                    (dict(uplift_ratio=float("nan")), r"uplift_ratio must be a number in \[0, 1e\+06\], got nan"),
                    (dict(uplift_arm=1.5), r"uplift_arm must be a number in \[-1, 1\], got 1.5"),
                    (dict(gyration=0.0), r"gyration must be a number in \[0.001, 1000\], got 0.0"),
                    (dict(gyration="1"), r"gyration must be .*got '1' \(not a number\)"),
                    (dict(crest=0.0), r"crest must be a number in \(0, 1000\], got 0.0")):
        with pytest.raises(ValueError, match=msg):
            Parameters(2.0, 0.5, **kw)
        with pytest.raises(ValueError, match=msg):
            classify(0.1, 0.5, 2.0, 0.5, **kw)
        with pytest.raises(ValueError, match=msg):
            label_grid([0.1], [0.5], 2.0, 0.5, **kw)
    with pytest.raises(ValueError, match=r"kprime must be a number in \[-1, 1\], got 1.2"):
        Parameters(2.0, 1.2)
    with pytest.raises(ValueError, match=r"kprime must be a number in \[-1, 1.5\], got 1.7"):
        classify(0.1, 0.5, 2.0, 1.7, crest=1.5)
    assert Parameters(2.0, 1.2, crest=1.5).kprime == 1.2
    with pytest.raises(ValueError):
        classify(-1.0, 0.5, 2.0, 0.5)
