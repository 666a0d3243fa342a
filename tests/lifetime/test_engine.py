"""The Monte Carlo of lifetimes: reproducibility, exact sampling, and what each option does.

Directions checked here (docs/lifetime.md, Sect. 7 and 9): a larger deep-water,
transformation or force factor slides more, a larger friction factor slides
less, a larger spread (cov) of a factor slides more (sliding grows faster than
linearly with the load), truncating the factors slides less, and a tide range
slides more (the storms at high water slide more than those at low water
slide less).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from regimemap.lifetime import Caisson, Climate, ErrorFactor, Errors, LifetimeModel, lifetime_sliding
from regimemap.lifetime.engine import BLOCK, simulate_block
from regimemap.lifetime.sliding import half_sine_slide, wave_duration
from regimemap.lifetime.storms import sea_states, wave_forces
from regimemap.waves import analyse_caisson

from ._cases import CLIMATE, GODA, MODEL, NARROW, NO_ERRORS


def _run(caisson=GODA, model=MODEL, trials=500, seed=11, **kw):
    return lifetime_sliding(caisson, model, trials=trials, seed=seed, **kw)


# -- reproducibility -----------------------------------------------------------------------------

@pytest.mark.portable
@pytest.mark.subprocess
def test_same_seed_same_bits_for_any_chunk_and_jobs():
    ref = _run(NARROW, trials=450, chunk=100)
    for kw in (dict(chunk=450), dict(chunk=200), dict(chunk=100, jobs=2), dict(chunk=300, jobs=2)):
        r = _run(NARROW, trials=450, **kw)
        assert np.array_equal(r.sliding, ref.sliding), kw
        assert np.array_equal(r.max_storm, ref.max_storm), kw
        assert np.array_equal(r.storms, ref.storms), kw


@pytest.mark.portable
def test_lifetime_i_depends_only_on_seed_and_i():
    a = _run(NARROW, trials=BLOCK + 37)
    b = _run(NARROW, trials=BLOCK)
    assert np.array_equal(a.sliding[:BLOCK], b.sliding)
    c = _run(NARROW, trials=BLOCK, seed=12)
    assert not np.array_equal(c.sliding, b.sliding)


def test_no_seed_draws_one_and_reports_it():
    r = _run(NARROW, trials=10, seed=None)
    again = _run(NARROW, trials=10, seed=r.seed)
    assert np.array_equal(r.sliding, again.sliding)


@pytest.mark.slow
def test_standard_error_falls_like_one_over_root_n():
    # a narrow caisson slides in nearly every lifetime: the spread is tame
    runs = {n: _run(NARROW, trials=n, seed=5) for n in (400, 1600, 6400)}
    se = {n: r.std_error for n, r in runs.items()}
    for n in (400, 1600):
        assert se[n] / se[4 * n] == pytest.approx(2.0, rel=0.25)
    r = runs[6400]
    assert r.std_error == pytest.approx(np.std(r.sliding, ddof=1) / math.sqrt(6400))


# -- the sampling of the sliding waves is exact in distribution ------------------------------------

def _brute_force(caisson: Caisson, model: LifetimeModel, trials: int, seed: int) -> np.ndarray:
    """Every wave of every storm drawn (Rayleigh, capped) and slid: no threshold, no binomial."""
    rng = np.random.default_rng(seed)
    n_storms = trials * model.years
    H0 = model.climate.quantile(rng.random(n_storms))
    one = np.ones(n_storms)
    seas = sea_states((caisson,), model, H0, np.zeros(n_storms), one, one, one)
    out = np.zeros(n_storms)
    for s in range(n_storms):
        n = int(seas.n_waves[s])
        H = np.minimum(seas.H13[s] * np.sqrt(-0.5 * np.log(rng.random(n))), seas.H_cap[s])
        storm = np.full(n, s)
        P, u = wave_forces(caisson, model, seas, storm, H)
        x = half_sine_slide(P + seas.friction[s] * u * caisson.width, seas.resistance[0, s],
                            seas.mass[0, s], wave_duration(H, seas.depth[s], seas.period[s]))
        out[s] = x.sum()
    return out.reshape(trials, model.years).sum(axis=1)


@pytest.mark.slow
def test_sliding_waves_only_is_exact_in_distribution():
    model = LifetimeModel(CLIMATE, years=2, errors=NO_ERRORS)
    fast = _run(NARROW, model, trials=3000, seed=21).sliding
    slow = _brute_force(NARROW, model, trials=600, seed=22)
    assert fast.mean() > 0.05  # the case slides: the comparison can fail
    se = math.hypot(fast.std(ddof=1) / math.sqrt(fast.size), slow.std(ddof=1) / math.sqrt(slow.size))
    assert abs(fast.mean() - slow.mean()) < 4.0 * se
    # and the share of lifetimes that slide at all
    p_fast, p_slow = np.mean(fast > 0), np.mean(slow > 0)
    assert abs(p_fast - p_slow) < 4.0 * math.sqrt(p_slow * (1 - p_slow) / slow.size + p_fast * (1 - p_fast) / fast.size) + 1e-12


# -- no sliding at all when the largest possible wave cannot slide ----------------------------------

def _heaviest_push(caisson: Caisson, model: LifetimeModel) -> tuple[float, float]:
    """P + mu U of the breaker-limited wave (fixed period, flat bed: the cap is a constant) and mu W'."""
    from regimemap.waves import breaker_height, deep_water_wavelength

    T = float(model.period)
    H = float(breaker_height(deep_water_wavelength(T), caisson.depth, caisson.seabed_slope))
    a = analyse_caisson(depth=caisson.depth, armour_depth=caisson.armour_depth, seabed_slope=caisson.seabed_slope,
                        period=T, width=caisson.width, base_depth=caisson.base_depth, crest=caisson.crest,
                        friction=caisson.friction, H13=H, Hmax=H, buoyant_weight=caisson.buoyant_weight,
                        berm_width=caisson.berm_width, angle_deg=caisson.angle_deg, impulsive=False)
    return float(a.loads.P + caisson.friction * a.loads.U), float(caisson.friction * caisson.buoyant_weight)


@pytest.mark.parametrize("margin,slides", [(1.001, False), (0.97, True)])
def test_no_sliding_when_the_largest_possible_wave_cannot_slide(margin, slides):
    model = LifetimeModel(Climate.from_return_values(8.0, 10.0), years=20, period=12.0, errors=NO_ERRORS)
    flat = replace(GODA, seabed_slope=0.0, angle_deg=0.0)
    push, _ = _heaviest_push(flat, model)
    # the buoyant weight at which friction just holds the breaker-limited wave, times the margin
    weight = push / flat.friction  # the push does not depend on the weight
    caisson = replace(flat, buoyant_weight=margin * weight)
    assert _heaviest_push(caisson, model)[0] == pytest.approx(push)
    r = _run(caisson, model, trials=300)
    assert (r.expected_sliding > 0.0) is slides
    if not slides:
        assert r.never_slides == 1.0 and r.sliding_waves == 0


# -- what each option does -------------------------------------------------------------------------

def _esd(model: LifetimeModel, caisson: Caisson = GODA, trials: int = 3000) -> tuple[float, float]:
    r = _run(caisson, model, trials=trials, seed=31)
    return r.expected_sliding, r.std_error


def _moves(base: LifetimeModel, changed: LifetimeModel, sign: int, caisson: Caisson = NARROW) -> None:
    a, sa = _esd(base, caisson)
    b, sb = _esd(changed, caisson)
    assert sign * (b - a) > 3.0 * math.hypot(sa, sb), (a, b, sa, sb)


ONE = ErrorFactor(1.0, 0.0)
QUIET = Errors(ONE, ONE, ONE, ONE)


@pytest.mark.slow
@pytest.mark.parametrize("name,sign", [("deepwater", +1), ("transformation", +1), ("force", +1),
                                       ("friction", -1)])
@pytest.mark.deep
def test_a_larger_ratio_moves_the_esd(name, sign):
    base = MODEL.with_(errors=replace(QUIET, **{name: ErrorFactor(1.0, 0.05)}))
    up = MODEL.with_(errors=replace(QUIET, **{name: ErrorFactor(1.1, 0.05)}))
    _moves(base, up, sign)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["deepwater", "transformation", "force", "friction"])
@pytest.mark.deep
def test_a_larger_spread_slides_more(name):
    base = MODEL.with_(errors=replace(QUIET, **{name: ErrorFactor(1.0, 0.02)}))
    wide = MODEL.with_(errors=replace(QUIET, **{name: ErrorFactor(1.0, 0.15)}))
    _moves(base, wide, +1)


def test_cov_zero_makes_the_factor_a_constant():
    # with every cov 0, truncation has nothing to cut: the same bits
    model = MODEL.with_(errors=Errors(ErrorFactor(1.0, 0.0), ErrorFactor(0.97, 0.0), ErrorFactor(0.91, 0.0),
                                      ErrorFactor(1.06, 0.0)))
    a = _run(NARROW, model, trials=200)
    b = _run(NARROW, model.with_(truncate=0.5), trials=200)
    assert np.array_equal(a.sliding, b.sliding)
    # a constant factor equals the same ratio given as the nominal value: friction 1.06 mu
    c = _run(replace(NARROW, friction=NARROW.friction * 1.06),
             model.with_(errors=replace(model.errors, friction=ONE)), trials=200)
    assert np.allclose(c.sliding, a.sliding, rtol=1e-9, atol=1e-12)


@pytest.mark.slow
def test_truncating_the_factors_slides_less():
    wide = MODEL.with_(errors=Errors(ErrorFactor(1.0, 0.15), ErrorFactor(1.0, 0.1), ErrorFactor(1.0, 0.2),
                                     ErrorFactor(1.0, 0.15)))
    _moves(wide, wide.with_(truncate=1.0), -1, caisson=GODA.with_width(13.0))


@pytest.mark.slow
def test_a_tide_slides_more():
    model = MODEL.with_(errors=QUIET)
    _moves(model, model.with_(tide_range=3.0), +1)


def test_the_tide_changes_the_sea_state_the_documented_way():
    model = MODEL.with_(tide_range=2.0)
    one = np.ones(3)
    seas = sea_states((GODA,), model, np.full(3, 6.0), np.array([-1.0, 0.0, 1.0]), one, one, one)
    assert np.all(np.diff(seas.depth) > 0) and np.all(np.diff(seas.base_depth) > 0)
    assert np.all(np.diff(seas.armour_depth) > 0) and np.all(np.diff(seas.crest) < 0)
    assert np.all(np.diff(seas.H13) >= 0) and np.all(np.diff(seas.H_cap) > 0)  # higher breakers
    # W' follows the submerged volume: rho g b per metre of water level
    rw = seas.resistance[0] / seas.friction
    assert rw[0] - rw[2] == pytest.approx(2.0 * GODA.rho_w * GODA.g * GODA.width)


def test_a_friction_factor_that_can_reach_zero_is_refused():
    with pytest.raises(ValueError, match="friction"):
        MODEL.with_(errors=replace(QUIET, friction=ErrorFactor(1.0, 0.2)))
    with pytest.raises(ValueError, match="truncation at 5"):
        MODEL.with_(errors=replace(QUIET, friction=ErrorFactor(1.0, 0.25)), truncate=5.0)
    MODEL.with_(errors=replace(QUIET, friction=ErrorFactor(1.0, 0.25)), truncate=3.0)  # accepted


def test_factors_never_turn_negative():
    from regimemap.lifetime.engine import _factor

    u = np.array([1e-12, 0.5])
    f = _factor(ErrorFactor(0.9, 0.5), u, None)
    assert f[0] == 0.0 and f[1] == pytest.approx(0.9)


def test_storms_per_year_gives_poisson_counts():
    model = LifetimeModel(Climate.from_return_values(5.0, 6.3, storms_per_year=3.0), years=10)
    r = _run(GODA, model, trials=2000)
    assert r.storms.mean() == pytest.approx(30.0, rel=0.02)
    assert r.storms.var() == pytest.approx(30.0, rel=0.15)
    assert np.all(_run(GODA, MODEL, trials=100).storms == 50)


def test_period_and_steepness_options():
    one = np.ones(2)
    H0 = np.array([4.0, 6.0])
    goda_rel = sea_states((GODA,), MODEL, H0, np.zeros(2), one, one, one).period
    assert goda_rel == pytest.approx(3.3 * H0**0.63)
    fixed = sea_states((GODA,), MODEL.with_(period=9.0), H0, np.zeros(2), one, one, one).period
    assert np.all(fixed == 9.0)
    steep = sea_states((GODA,), MODEL.with_(steepness=0.04), H0, np.zeros(2), one, one, one).period
    assert H0 / (9.81 * steep**2 / (2 * np.pi)) == pytest.approx([0.04, 0.04])


def test_block_result_shapes_and_the_largest_storm():
    r = simulate_block((NARROW, NARROW.with_width(12.0)), MODEL.with_(years=5), np.random.SeedSequence(1), n=7)
    assert r.sliding.shape == (2, 7) and r.max_storm.shape == (2, 7) and r.storms.shape == (7,)
    assert np.all(r.max_storm <= r.sliding + 1e-15)
    assert np.all(r.sliding[1] <= r.sliding[0] + 1e-12)  # the wider caisson, the same waves


def test_summary_and_statistics():
    r = _run(NARROW, trials=300)
    s = r.summary()
    assert s["expected_sliding"] == pytest.approx(r.sliding.mean())
    assert set(s["exceedance"]) == {"0.03", "0.1", "0.3", "1", "3"}
    assert s["exceedance"]["0.1"] == pytest.approx(np.mean(r.sliding > 0.1))
    assert r.median == pytest.approx(np.median(r.sliding))
    x, p = r.exceedance_curve()
    assert np.all(np.diff(p) <= 0) and np.all(x > 0)
    assert "ESD=" in repr(r)
