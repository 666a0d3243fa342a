"""The equivalent loaded block: its parameters, and its rest check against Goda's safety factors."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from regimemap.waves import (
    CaissonAnalysis,
    Densities,
    analyse_caisson,
    equivalent_block,
    section_from_weight,
    stability,
    static_rest_check,
)

GODA = dict(H0=6.3, period=11.4, seabed_slope=0.01, depth=10.1, armour_depth=5.6, base_depth=7.1, crest=3.4,
            berm_width=8.0, angle_deg=15.0, width=15.0, friction=0.6, buoyant_weight=2312e3)


def random_designs(n: int, seed: int, densities: Densities | None = None) -> CaissonAnalysis:
    rng = np.random.default_rng(seed)
    depth = rng.uniform(6, 30, n)
    base = depth * rng.uniform(0.5, 0.95, n)
    cond = dict(H0=rng.uniform(1, 9, n), period=rng.uniform(5, 16, n), depth=depth,
                seabed_slope=rng.uniform(0.0, 0.08, n), base_depth=base,
                armour_depth=base * rng.uniform(0.5, 1.0, n), crest=rng.uniform(0.0, 8.0, n),
                berm_width=rng.uniform(0, 25, n), angle_deg=rng.uniform(0, 40, n),
                width=rng.uniform(6, 35, n), friction=rng.uniform(0.4, 0.8, n))
    if densities is None:
        # buoyant weight between a fifth and five times the weight needed for SF = 1
        probe = analyse_caisson(**cond, buoyant_weight=1.0)
        need = np.maximum(probe.loads.P / cond["friction"] + probe.loads.U,
                          (probe.loads.Mp + probe.loads.Mu) / (0.5 * cond["width"]))
        return analyse_caisson(**cond, buoyant_weight=need * 10 ** rng.uniform(-0.7, 0.7, n))
    return analyse_caisson(**cond, densities=densities)


def test_block_of_worked_example() -> None:
    a = analyse_caisson(**GODA)
    b = a.block
    mg = 2312e3 + 1030 * 9.81 * 15.0 * 7.1
    assert float(b.B) == 7.5
    assert float(b.H) == pytest.approx((7.1 + 3.4) / 2)
    assert float(b.gamma) == pytest.approx(5.25 / 7.5)
    assert float(b.k) == pytest.approx(float(a.loads.P) / mg, rel=1e-14)
    assert float(b.buoyancy) == pytest.approx(1030 * 9.81 * 15.0 * 7.1 / mg, rel=1e-14)
    assert float(b.uplift_ratio) == pytest.approx(float(a.loads.U / a.loads.P), rel=1e-14)
    assert float(b.uplift_arm) == pytest.approx(1 / 3, rel=1e-14)     # Goda's triangle
    assert float(b.kprime) == pytest.approx((float(a.loads.Mp / a.loads.P) - 5.25) / 5.25, rel=1e-14)
    assert float(b.gyration) == pytest.approx(np.sqrt((1 + float(b.gamma) ** 2) / 3), rel=1e-14)
    assert float(b.uplift) == 0.0
    rc = b.rest_check()
    assert bool(rc.at_rest)


def test_static_rest_check_simple_cases() -> None:
    # no force: at rest unless buoyancy lifts it
    rc = static_rest_check(k=0.0, mu=0.6, gamma=1.0, kprime=0.0, buoyancy=[0.5, 1.2])
    np.testing.assert_array_equal(rc.at_rest, [True, False])
    # dry block, no uplift: slides at k > mu, tips at k > 1/(gamma (1 + k'))
    rc = static_rest_check(k=[0.2, 0.4, 0.6], mu=0.5, gamma=2.0, kprime=0.0)
    np.testing.assert_array_equal(rc.no_sliding, [True, True, False])
    np.testing.assert_array_equal(rc.no_overturning, [True, True, False])
    np.testing.assert_allclose(rc.overturning_margin, [1 - 0.4, 1 - 0.8, 1 - 1.2])


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_safety_factors_and_rest_check_agree_uniform_caisson(seed: int) -> None:
    a = random_designs(4000, seed)
    st, rc = a.stability, a.block.rest_check()
    # away from the boundary (round-off), SF >= 1 exactly when the block is at rest, both ways
    far_s = np.abs(st.sliding - 1) > 1e-12
    far_o = np.abs(st.overturning - 1) > 1e-12
    np.testing.assert_array_equal((st.sliding >= 1)[far_s], rc.no_sliding[far_s])
    np.testing.assert_array_equal((st.overturning >= 1)[far_o], rc.no_overturning[far_o])
    # both directions are exercised: stable and unstable designs for each mode
    for ok in (rc.no_sliding, rc.no_overturning):
        assert 0.1 < ok.mean() < 0.9
    assert rc.at_rest.any() and (~rc.at_rest).any()
    # the margins are the safety factors rewritten: same sign, and zero together
    b = a.block
    np.testing.assert_allclose(rc.sliding_margin, b.k * (st.sliding - 1), rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(rc.overturning_margin,
                               b.k * (1 + b.kprime) * b.gamma * (st.overturning - 1), rtol=1e-10, atol=1e-14)


def test_safety_factor_one_is_on_the_boundary() -> None:
    a = random_designs(500, 11)
    ld, w, mu = a.loads, a.section.width, a.block.mu
    for which in ("sliding", "overturning"):
        wp = ld.P / mu + ld.U if which == "sliding" else (ld.Mp + ld.Mu) / (0.5 * w)
        sec = section_from_weight(wp, w, a.section.base_depth, a.section.crest)
        st = stability(sec, ld, mu)
        np.testing.assert_allclose(getattr(st, which), 1.0, rtol=1e-13)
        rc = equivalent_block(sec, ld, mu).rest_check()
        margin = rc.sliding_margin if which == "sliding" else rc.overturning_margin
        assert np.abs(margin).max() < 1e-13
        # a hair lighter: the block moves; a hair heavier: it stays
        for factor, expected in ((1 - 1e-9, False), (1 + 1e-9, True)):
            sec2 = section_from_weight(wp * factor, w, a.section.base_depth, a.section.crest)
            rc2 = equivalent_block(sec2, ld, mu).rest_check()
            ok = rc2.no_sliding if which == "sliding" else rc2.no_overturning
            assert (ok == expected).all()


def test_densities_caisson_agrees_too() -> None:
    a = random_designs(2000, 5, Densities(0.25, 2400.0, 2000.0, 1700.0))
    st, rc = a.stability, a.block.rest_check()
    far_s = np.abs(st.sliding - 1) > 1e-12
    far_o = np.abs(st.overturning - 1) > 1e-12
    np.testing.assert_array_equal((st.sliding >= 1)[far_s], rc.no_sliding[far_s])
    np.testing.assert_array_equal((st.overturning >= 1)[far_o], rc.no_overturning[far_o])
    # layered section: C below mid-height, i from the section
    assert (a.block.H < 0.5 * (a.section.base_depth + a.section.crest)).all()
    i_uniform = np.sqrt((1 + a.block.gamma**2) / 3)
    assert not np.allclose(a.block.gyration, i_uniform)


def test_block_fields_are_arrays_of_the_broadcast_shape() -> None:
    a = analyse_caisson(**{**GODA, "width": np.array([12.0, 15.0, 18.0])})
    for f in dataclasses.fields(a.block):
        assert np.shape(getattr(a.block, f.name)) == (3,), f.name
