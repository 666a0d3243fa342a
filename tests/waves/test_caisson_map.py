"""A caisson on the loaded map: Goda's safety factors agree with rest on the map (through the adapter).

The map is reached only through :mod:`regimemap.maps.loadedmap`, as the
``caisson`` command and its sheet reach it.
"""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.caisson.report import PATH_FACTORS, caisson_report, loaded_map_of, map_view
from regimemap.maps.loadedmap import LO, LoadedMap, classify_at, margins, mode_grid, mode_label
from regimemap.mechanics.modes import Mode
from regimemap.waves import Densities, analyse_caisson

from .test_waves_block import random_designs

RE = int(Mode.RE)


def _modes(a) -> np.ndarray:
    k = np.asarray(a.block.k)
    mu = np.asarray(a.block.mu)
    return np.array([int(classify_at(k[i], mu[i], loaded_map_of(a, i))) for i in range(k.size)])


@pytest.mark.parametrize("seed", [11, 12])
@pytest.mark.slow
def test_safety_factors_agree_with_rest_on_the_map_uniform_caissons(seed: int) -> None:
    a = random_designs(2500, seed)
    st = a.stability
    modes = _modes(a)
    safe = (st.sliding >= 1.0) & (st.overturning >= 1.0)
    far = (np.abs(st.sliding - 1.0) > 1e-9) & (np.abs(st.overturning - 1.0) > 1e-9)
    assert far.sum() > 2400
    np.testing.assert_array_equal(safe[far], (modes == RE)[far])
    # both outcomes, and both ways of failing, are present
    assert safe[far].sum() > 300 and (~safe[far]).sum() > 300
    assert ((st.sliding < 1) & (st.overturning >= 1)).sum() > 50
    assert (st.overturning < 1).sum() > 50
    # uniform caissons: the gyration is the uniform block's
    np.testing.assert_allclose(a.block.gyration, np.sqrt((1 + a.block.gamma ** 2) / 3), rtol=1e-12)


def test_safety_factors_agree_with_rest_on_the_map_filled_caissons() -> None:
    a = random_designs(600, 13, Densities(0.25, 2400.0, 2000.0, 1700.0))
    st = a.stability
    modes = _modes(a)
    safe = (st.sliding >= 1.0) & (st.overturning >= 1.0)
    far = (np.abs(st.sliding - 1.0) > 1e-9) & (np.abs(st.overturning - 1.0) > 1e-9)
    np.testing.assert_array_equal(safe[far], (modes == RE)[far])


@pytest.mark.slow
def test_moving_modes_of_the_map_match_the_failing_factor() -> None:
    """A caisson that fails only in sliding slides on the map."""
    a = random_designs(1500, 14)
    st = a.stability
    modes = _modes(a)
    only_sliding = (st.sliding < 1 - 1e-9) & (st.overturning > 1 + 1e-9)
    assert only_sliding.sum() > 50
    assert set(modes[only_sliding].tolist()) <= {int(Mode.SL)}


def test_worked_example_on_the_map() -> None:
    r = caisson_report(parse_design(example_design_text()).analysis_inputs())
    assert mode_label(r.mode) == "RE" and r.consistent and r.safe_by_goda
    m = r.map
    assert f"{m.gamma:.3g}" == "0.7" and f"{m.kprime:.2g}" == "-0.018"
    assert f"{m.buoyancy:.3g}" == "0.318" and f"{m.uplift_ratio:.3g}" == "0.524"
    assert m.uplift_arm == pytest.approx(1 / 3, abs=1e-12) and m.crest == pytest.approx(1.0)
    # margins: more k (mu fixed) slides at k = mu W = mu (1 - beta - nu k), i.e.
    # k = mu (1 - beta) / (1 + mu nu); less mu slides at mu = k / W
    k_slide = r.mu * (1 - m.buoyancy) / (1 + r.mu * m.uplift_ratio)
    m_mu = r.k / (1 - m.buoyancy - m.uplift_ratio * r.k)
    assert r.margin_k.up is not None and r.margin_k.down is None
    assert r.margin_k.up.at == pytest.approx(k_slide, rel=1e-12) and r.margin_k.up.to == int(Mode.SL)
    assert r.margin_mu.down is not None and r.margin_mu.up is None
    assert r.margin_mu.down.at == pytest.approx(m_mu, rel=1e-12) and r.margin_mu.down.to == int(Mode.SL)
    # Goda's SF against sliding in the map's terms
    assert float(r.analysis.stability.sliding) == pytest.approx(
        r.mu * (1 - m.buoyancy - m.uplift_ratio * r.k) / r.k, rel=1e-12)


def test_wave_path_recomputes_the_loads_and_finds_the_onset() -> None:
    inputs = parse_design(example_design_text()).analysis_inputs()
    r = caisson_report(inputs)
    p = r.path
    np.testing.assert_array_equal(p.factors, PATH_FACTORS)
    i1 = int(np.argmin(np.abs(p.factors - 1.0)))
    assert p.k[i1] == pytest.approx(r.k, rel=1e-12)
    # the map's parameters move with the wave: k' and U/P are not constant
    assert np.ptp(p.kprime) > 0.01 and np.ptp(p.uplift_ratio) > 0.1
    assert (np.diff(p.k) > 0).all()
    # each point on its own map agrees with Goda's factors at that wave
    st = p.analysis.stability
    np.testing.assert_array_equal((st.sliding >= 1) & (st.overturning >= 1), p.modes == RE)
    # the onset is where the first safety factor reaches 1
    assert p.onset is not None and 1.0 < p.onset < 1.2 and p.onset_mode == int(Mode.SL)
    for s, rest in ((p.onset - 1e-7, True), (p.onset + 1e-7, False)):
        one = dict(inputs, H0=None, H13=s * float(r.analysis.heights.H13),
                   Hmax=s * float(r.analysis.heights.Hmax))
        a = analyse_caisson(**one)
        assert (bool(a.stability.sliding >= 1) and bool(a.stability.overturning >= 1)) == rest


def test_path_of_a_caisson_that_already_moves_and_one_that_never_does() -> None:
    base = parse_design(example_design_text()).analysis_inputs()
    light = caisson_report(dict(base, buoyant_weight=500e3))
    assert light.path.onset == PATH_FACTORS[0] and light.mode != RE and light.consistent
    heavy = caisson_report(dict(base, buoyant_weight=20000e3))
    assert heavy.path.onset is None and heavy.mode == RE and (heavy.path.modes == RE).all()


def test_margins_bisect_to_the_boundary() -> None:
    m = LoadedMap(gamma=2.0, kprime=0.3, buoyancy=0.2, uplift_ratio=0.3)
    mk, mm = margins(0.1, 0.5, m)
    assert mk.up is not None
    at = mk.up.at
    assert int(classify_at(at, 0.5, m)) != RE
    assert int(classify_at(np.nextafter(at, 0.0), 0.5, m)) == RE
    assert mm.up is None  # more friction never moves a resting block


def test_map_view_and_grid() -> None:
    r = caisson_report(parse_design(example_design_text()).analysis_inputs())
    v = map_view(r, samples=101)
    assert v.grid.shape == (101, 101)
    assert v.k_max >= float(np.max(r.path.k)) and v.mu_max > r.mu
    np.testing.assert_array_equal(v.grid, mode_grid(v.k_axis, v.mu_axis, r.map))
    assert "A" in v.points
    assert {mode_label(c) for c in np.unique(v.grid)} >= {"RE", "SL"}
    assert mode_label(LO) == "LO"
