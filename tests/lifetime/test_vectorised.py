"""The vectorised engine against the scalar path: the same numbers, to the last bit, in one run.

The engine evaluates the loads of all the storms of a chunk in one numpy call
(the sea states once, then each bisection step on the height), slides every
wave at every width in one call, and lets each wave of the closed-form stop
run its own Newton steps.  Each of these is compared here with the plain
path -- a Python loop over storms, over widths or over waves, calling the
public functions one at a time -- bit for bit (both paths run in this process,
on numpy's loops for this CPU), and the end results with fingerprints of the
engine before it was vectorised (regimemap 2ad9f7f), to a relative 1e-12: the
fingerprints were taken on another CPU, and numpy's exp, log, sin and power
differ in the last bits between CPU feature levels (docs/guide/development.md,
"Reproducibility").  The module is marked ``portable``: ``make test-portable``
runs it again at each of numpy's dispatch levels on this CPU.
"""

from __future__ import annotations

import numpy as np
import pytest

import regimemap.lifetime.engine as engine
from regimemap.lifetime import Climate, LifetimeModel, half_sine_slide
from regimemap.lifetime.engine import simulate_block, simulate_blocks
from regimemap.lifetime.parallel import make_chunks, run_chunks
from regimemap.lifetime.storms import sea_states, sliding_threshold, storm_loads, wave_forces
from regimemap.waves import caisson_loads, goda_pressures

from ._cases import GODA, MODEL

pytestmark = pytest.mark.portable


def _storms(model: LifetimeModel, widths: tuple[float, ...], n: int = 400, seed: int = 3):
    rng = np.random.default_rng(seed)
    H0 = model.climate.quantile(rng.random(n)) * rng.uniform(0.8, 1.3, n)
    H0[:5] = 0.0  # calms
    tide = rng.uniform(-1.0, 1.0, n)
    factors = [rng.uniform(0.7, 1.3, n) for _ in range(3)]
    caissons = tuple(GODA.with_width(w) for w in widths)
    return caissons, sea_states(caissons, model, H0, tide, *factors)


# -- the loads ------------------------------------------------------------------------------------

@pytest.mark.parametrize("impulsive", [False, True])
def test_loads_of_all_storms_at_once_equal_one_call_per_wave(impulsive):
    model = MODEL.with_(impulsive=impulsive)
    caissons, seas = _storms(model, (15.0,))
    live = np.flatnonzero(seas.H13 > 0.0)
    rng = np.random.default_rng(1)
    storm = np.repeat(live, 3)
    H = seas.H_cap[storm] * rng.uniform(0.2, 1.0, storm.size)
    P, u = storm_loads(GODA, model, seas, storm)(H)
    assert np.array_equal((P, u), wave_forces(GODA, model, seas, storm, H))
    for i in range(0, storm.size, 17):  # the public scalar path, one wave at a time
        s = storm[i]
        p = goda_pressures(Hmax=float(H[i]), period=float(seas.period[s]), depth=float(seas.depth[s]),
                           hb=float(seas.hb[s]), armour_depth=float(seas.armour_depth[s]),
                           base_depth=float(seas.base_depth[s]), crest=float(seas.crest[s]),
                           berm_width=GODA.berm_width, angle_deg=GODA.angle_deg, impulsive=impulsive,
                           rho_w=GODA.rho_w, g=GODA.g)
        loads = caisson_loads(p, float(seas.base_depth[s]), 1.0)
        f = float(seas.force_factor[s])
        assert float(P[i]) == float(loads.P) * f and float(u[i]) == float(loads.U) * f, i


def _threshold_one_storm(model: LifetimeModel, seas, s: int) -> float:
    """The bisection of :func:`sliding_threshold` for one storm, with scalar arithmetic."""
    mu, widths, R = float(seas.friction[s]), seas.widths, seas.resistance[:, s]
    one = np.array([s])

    def excess(H: float) -> float:
        P, u = wave_forces(GODA, model, seas, one, np.array([H]))
        return max(float(P[0]) + mu * float(u[0]) * float(b) - float(r) for b, r in zip(widths, R))

    if not (seas.n_waves[s] > 0 and seas.H13[s] > 0.0) or excess(float(seas.H_cap[s])) <= 0.0:
        return np.inf
    lo, hi = 0.0, float(seas.H_cap[s])
    for _ in range(48):
        mid = 0.5 * (lo + hi)
        if excess(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    return lo


def test_sliding_threshold_of_all_storms_equals_one_storm_at_a_time():
    caissons, seas = _storms(MODEL, (11.0, 15.0, 22.0), n=120)
    H_s = sliding_threshold(caissons[0], MODEL, seas)
    assert 0 < np.isfinite(H_s).sum() < H_s.size  # some storms slide a width, some none
    for s in range(H_s.size):
        assert H_s[s] == _threshold_one_storm(MODEL, seas, s), s


# -- the slides -----------------------------------------------------------------------------------

def _stop_reference(ratio: float, s1: float, c1: float) -> float:
    """The safeguarded Newton of the engine before vectorising, for one wave."""
    lo, hi = np.array([max(s1, np.pi - s1)]), np.array([np.pi])
    s = hi.copy()
    for _ in range(60):
        v = ratio * (c1 - np.cos(s)) - (s - s1)
        dv = ratio * np.sin(s) - 1.0
        lo = np.where(v > 0.0, s, lo)
        hi = np.where(v <= 0.0, s, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = s - v / dv
        s_new = np.where((step > lo) & (step < hi) & np.isfinite(step), step, 0.5 * (lo + hi))
        if np.array_equal(s_new, s):
            break
        s = s_new
    return float(s[0])


@pytest.mark.slow
def test_every_wave_runs_its_own_newton_steps():
    from regimemap.lifetime.sliding import _stop_within

    rng = np.random.default_rng(5)
    # F/R from just above 1 (the stop right after the start) to the late limit
    ratio = np.concatenate([1.0 + 10.0 ** rng.uniform(-12, -1, 400), rng.uniform(1.1, 1.37, 400)])
    q = 1.0 / ratio
    s1, c1 = np.arcsin(q), np.sqrt((1.0 - q) * (1.0 + q))
    early = ratio * (c1 + 1.0) - (np.pi - s1) < 0.0
    ratio, s1, c1 = ratio[early], s1[early], c1[early]
    assert ratio.size > 500
    s = _stop_within(ratio, s1, c1)
    ref = np.array([_stop_reference(*a) for a in zip(ratio, s1, c1)])
    assert np.array_equal(s, ref)
    # and whatever the other waves in the call: reversed, or alone
    assert np.array_equal(_stop_within(ratio[::-1].copy(), s1[::-1].copy(), c1[::-1].copy()), ref[::-1])
    assert np.array_equal(_stop_within(ratio[:1], s1[:1], c1[:1]), ref[:1])


def test_half_sine_slide_over_widths_and_waves_equals_one_wave_at_a_time():
    rng = np.random.default_rng(8)
    R = np.array([[1.0e6], [1.3e6], [-1.0], [2.0e6]])  # one resistance per row (a width), one < 0
    F = rng.uniform(0.5e6, 2.8e6, (1, 300))
    M, tau = np.array([[2.0e5], [2.5e5], [2.2e5], [3.0e5]]), rng.uniform(-0.5, 6.0, 300)
    x = half_sine_slide(F, R, M, tau)
    assert x.shape == (4, 300) and np.any(np.isinf(x)) and np.any((x > 0) & np.isfinite(x)) and np.any(x == 0)
    for j in range(4):
        for i in range(300):
            assert x[j, i] == float(half_sine_slide(F[0, i], R[j, 0], M[j, 0], tau[i]))


# -- the engine ------------------------------------------------------------------------------------

TIDE_POISSON = LifetimeModel(Climate.from_return_values(5.0, 6.3, storms_per_year=3.0), years=20,
                             tide_range=2.0, impulsive=True)


@pytest.mark.parametrize("model", [MODEL, TIDE_POISSON], ids=["goda", "tide-poisson-impulsive"])
def test_blocks_together_equal_blocks_alone(model):
    caissons = (GODA.with_width(11.0), GODA.with_width(16.0))
    streams = np.random.SeedSequence(4).spawn(3)
    together = simulate_blocks(caissons, model, streams, n=30)
    for stream, r in zip(streams, together):
        alone = simulate_block(caissons, model, stream, n=30)
        assert r.sliding_waves == alone.sliding_waves > 0
        for a, b in ((r.sliding, alone.sliding), (r.max_storm, alone.max_storm), (r.storms, alone.storms)):
            assert np.array_equal(a, b)


def test_pieces_and_width_groups_do_not_change_a_bit(monkeypatch):
    caissons = tuple(GODA.with_width(w) for w in (11.0, 13.0, 17.0))
    streams = np.random.SeedSequence(9).spawn(2)
    ref = simulate_blocks(caissons, MODEL, streams, n=40)
    monkeypatch.setattr(engine, "_PIECE", 7)           # a few storms per piece
    monkeypatch.setattr(engine, "_SLIDE_ELEMENTS", 1)  # one width at a time
    small = simulate_blocks(caissons, MODEL, streams, n=40)
    assert sum(r.sliding_waves for r in ref) > 100
    for a, b in zip(ref, small):
        assert np.array_equal(a.sliding, b.sliding) and np.array_equal(a.max_storm, b.max_storm)


def test_a_guide_width_chooses_the_waves_but_is_not_slid():
    pair = (GODA.with_width(11.0), GODA.with_width(18.0))
    chunks = make_chunks(250, 6, 100)
    both = run_chunks(pair, MODEL, chunks)
    guided = run_chunks(pair, MODEL, chunks, guides=1)
    assert guided.sliding.shape == (1, 250)
    assert np.array_equal(guided.sliding[0], both.sliding[1])
    assert np.array_equal(guided.max_storm[0], both.max_storm[1])
    assert guided.sliding_waves == both.sliding_waves
    alone = run_chunks(pair[1:], MODEL, chunks)  # without the guide: fewer waves, other numbers
    assert alone.sliding_waves < both.sliding_waves
    with pytest.raises(ValueError, match="guides"):
        run_chunks(pair, MODEL, chunks, guides=2)


# fingerprints of the engine before vectorising (2ad9f7f): sum and largest of each width's
# lifetime slides, and the sliding waves, of 300 lifetimes of seed 7 in chunks of 200; taken on an
# AVX-512 CPU (numpy's X86_V4 loops).  With numpy's X86_V3 or baseline loops they move by up to
# 9 units in the last place (1.7e-15 relative): REL is the documented bound, with room to spare.
BEFORE = {
    "goda": (MODEL, (11.0, 15.0, 19.0),
             ("0x1.703bf4d9bd536p+12", "0x1.165361935a1f4p+8", "0x1.e99e4a226d556p+0"),
             ("0x1.f0b6f18c52277p+8", "0x1.1e74a6a5541aep+6", "0x1.35f07d381d42fp+0"), 9573),
    "impulsive-tide": (MODEL.with_(impulsive=True, tide_range=2.0), (12.0, 16.0),
                       ("0x1.28870fd779681p+12", "0x1.b7b0891d6e47bp+7"),
                       ("0x1.7bf30a6a12f3ep+8", "0x1.0f6d2b995abafp+6"), 10359),
    "poisson": (LifetimeModel(Climate.from_return_values(5.0, 6.3, storms_per_year=3.0), years=20), (13.0,),
                ("0x1.34f02bc85853ep+9",), ("0x1.7048bc1f07b2ap+7",), 1159),
}

#: The relative tolerance of the lifetime sums across machines (docs/guide/development.md).
REL = 1e-12


@pytest.mark.parametrize("name", sorted(BEFORE))
def test_the_same_numbers_as_before_vectorising(name):
    model, widths, sums, largest, waves = BEFORE[name]
    r = run_chunks(tuple(GODA.with_width(w) for w in widths), model, make_chunks(300, 7, 200))
    np.testing.assert_allclose(r.sliding.sum(axis=1), [float.fromhex(x) for x in sums], rtol=REL, atol=0)
    np.testing.assert_allclose(r.max_storm.max(axis=1), [float.fromhex(x) for x in largest], rtol=REL, atol=0)
    assert r.sliding_waves == waves


@pytest.mark.parametrize("name", sorted(BEFORE))
def test_the_same_bits_for_any_chunks_in_one_run(name):
    """What holds bit for bit on one machine: the chunks do not change a lifetime."""
    model, widths, _, _, _ = BEFORE[name]
    caissons = tuple(GODA.with_width(w) for w in widths)
    ref = run_chunks(caissons, model, make_chunks(300, 7, 200))
    other = run_chunks(caissons, model, make_chunks(300, 7, 100))
    assert other.sliding_waves == ref.sliding_waves
    for a, b in ((ref.sliding, other.sliding), (ref.max_storm, other.max_storm), (ref.storms, other.storms)):
        assert np.array_equal(a, b)
