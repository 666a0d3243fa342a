"""Event-accurate pulses (issue 20): the stepper lands a step on the pulse's breakpoints and on its
crossings of the initiation map, so initiation is decided by k(t) and ``classify`` alone -- the same
for every duration and every step; categories follow the phases; unfinished runs say so."""

from __future__ import annotations

import json

import numpy as np
import pytest

import regimemap
from regimemap.dynamics import (
    CATEGORY_LABELS,
    OVERTURN,
    REST,
    ROCK,
    SHAPES,
    SLIDE,
    SLIDE_ROCK,
    STILL_MOVING,
    Block,
    Pulse,
    default_steps,
    simulate,
)
from regimemap.dynamics.events import EVENT_STEP, crossing_times, onset_boundaries
from regimemap.motion.record_simulation import format_simulation

from ..conftest import invoke_cli

# the issue's caisson: classify puts the SL/SRO- boundary at k = 0.8557 (mu = 0.6)
CAISSON = {"B": 7.5, "gamma": 0.7, "kprime": -0.02, "buoyancy": 0.32, "uplift_ratio": 0.52}
CAISSON_CLI = ["--gamma", "0.7", "--half-width", "7.5", "--kprime", "-0.02", "--buoyancy", "0.32",
               "--uplift-ratio", "0.52", "--pulse", "breaking", "--k-peak", "0.86"]
_ROCKING = {"RO", "SRO-", "SRO+", "SRO'-", "RO'", "SRO'+", "FLIGHT"}
_SLIDING = {"SL", "SRO-", "SRO+", "SRO'-", "SRO'+"}


def _labels(phases: list[tuple[str, float]]) -> set[str]:
    return {label for label, _ in phases}


# -- breakpoints -------------------------------------------------------------------------------------

@pytest.mark.parametrize("pulse", [Pulse.make(s, 1.0, 2.0) for s in SHAPES]
                         + [Pulse.triangular(1.0, 2.0, peak_at=0.0), Pulse.triangular(1.0, 2.0, peak_at=0.3),
                            Pulse.breaking(1.0, 2.0, peak_ratio=0.9, impulsive_fraction=0.6),
                            Pulse.breaking(1.0, 2.0, peak_ratio=0.7, impulsive_fraction=1.0)],
                         ids=lambda p: f"{p.shape}-{p.peak_at}-{p.peak_ratio}-{p.impulsive_fraction}")
def test_k_is_monotone_between_breakpoints(pulse: Pulse) -> None:
    b = pulse.breakpoints([2.0, 3.0])
    assert b.shape[0] == 2 and b[0, 0] == 0.0 and b[0, -1] == 2.0 and b[1, -1] == 3.0
    assert np.all(np.diff(b, axis=1) > 0)
    for row, T in zip(b, (2.0, 3.0), strict=True):
        for a, c in zip(row[:-1], row[1:], strict=True):
            k = pulse.k(np.linspace(a, c, 2001)[:-1], 1.0, T)
            d = np.diff(k)
            assert np.all(d >= -1e-12) or np.all(d <= 1e-12), (pulse.shape, a, c)


def test_breakpoints_hold_the_peaks_and_the_samples() -> None:
    assert Pulse.half_sine(1.0, 2.0).breakpoints().tolist() == [[0.0, 1.0, 2.0]]
    assert Pulse.one_sine(1.0, 2.0).breakpoints().tolist() == [[0.0, 0.5, 1.5, 2.0]]
    assert Pulse.triangular(1.0, 2.0, peak_at=0.25).breakpoints().tolist() == [[0.0, 0.5, 2.0]]
    b = Pulse.breaking(1.0, 1.0).breakpoints()[0]  # triangle's peak and end, the half-sine's peak, a kink
    assert {0.0, 0.05, 0.1, 0.5, 1.0} <= set(b.tolist()) and b.size == 6
    kink = b[(b > 0.05) & (b < 0.1)][0]
    tri = 2.0 - 2.0 * kink / 0.1
    assert tri == pytest.approx(0.4 * np.sin(np.pi * kink), abs=1e-12)
    t = [0.0, 0.1, 0.3, 0.35]
    assert Pulse.from_arrays(t, [0.0, 1.0, 0.5, 0.0]).breakpoints().tolist() == [t]


# -- the boundaries of the initiation map and their crossings ----------------------------------------

@pytest.mark.parametrize("loads", [{}, {"buoyancy": 0.32, "uplift_ratio": 0.52}, {"buoyancy": 0.2, "uplift": 0.15, "uplift_arm": 0.0},
                                   {"uplift_ratio": 0.3, "uplift_arm": 0.5, "i2": 1.2}])
def test_onset_boundaries_are_where_classify_changes(loads: dict[str, float]) -> None:
    mus = np.array([0.0, 0.2, 0.6, 1.5, 5.0])
    blk = Block(B=1.0, gamma=0.9, mu=mus, kprime=-0.3, **loads)
    kb, lo, hi = onset_boundaries(blk, mus.size)
    k = np.linspace(0.0, 4.0, 4001)
    kw = {"buoyancy": loads.get("buoyancy", 0.0), "uplift": loads.get("uplift", 0.0),
          "uplift_ratio": loads.get("uplift_ratio", 0.0), "uplift_arm": loads.get("uplift_arm", 1 / 3),
          "gyration": None if "i2" not in loads else np.sqrt(loads["i2"])}
    for i, mu in enumerate(mus):
        modes = regimemap.classify(k, mu, 0.9, -0.3, **kw)
        fin = np.isfinite(kb[i])
        b = kb[i][fin]
        # every change of mode on the fine grid holds a boundary ...
        for j in np.flatnonzero(modes[1:] != modes[:-1]):
            assert np.any((b >= k[j]) & (b <= k[j + 1])), (mu, k[j])
        # ... and every boundary separates two modes
        for v, a, c in zip(b, lo[i][fin], hi[i][fin], strict=True):
            below = regimemap.classify(max(0.0, 0.5 * (a + v)), mu, 0.9, -0.3, **kw) if v > 0 else \
                regimemap.classify(0.0, mu, 0.9, -0.3, **kw)
            above = regimemap.classify(0.5 * (v + min(c, v + 1.0)), mu, 0.9, -0.3, **kw)
            assert below != above, (mu, v)


def test_the_issue_boundary_is_found() -> None:
    kb, _, _ = onset_boundaries(Block(mu=0.6, **CAISSON), 1)
    assert kb[0, 1] == pytest.approx(0.85565519, abs=1e-8)
    m = regimemap.classify([kb[0, 1] * (1 - 1e-9), kb[0, 1] * (1 + 1e-6)], 0.6, 0.7, -0.02, buoyancy=0.32,
                           uplift_ratio=0.52)
    assert [regimemap.Mode(c).label for c in m] == ["SL", "SRO-"]


def test_crossing_times_are_just_past_the_target() -> None:
    p = Pulse.half_sine(1.0, 2.0)
    kp, T = np.array([1.0, 0.8]), np.array([2.0, 3.0])
    breaks = p.breakpoints(T)
    up = np.array([[0.5, np.nan], [0.5, 0.9]])   # 0.9 is above the second run's peak: no crossing
    down = np.array([[0.25, np.nan], [np.nan, np.nan]])
    t = crossing_times(p, kp, T, breaks, up, down)
    assert np.isfinite(t).sum(axis=1).tolist() == [2, 1]
    t_up = np.arcsin(0.5 / kp) * T / np.pi
    assert t[0, 0] == pytest.approx(t_up[0], abs=1e-12) and t[1, 0] == pytest.approx(t_up[1], abs=1e-12)
    assert p.k(t[0, 0], 1.0, 2.0) >= 0.5 > p.k(t[0, 0] - 1e-11, 1.0, 2.0)
    assert t[0, 1] == pytest.approx(2.0 - np.arcsin(0.25) * 2.0 / np.pi, abs=1e-12)
    assert p.k(t[0, 1], 1.0, 2.0) <= 0.25 < p.k(t[0, 1] - 1e-11, 1.0, 2.0)


# -- the same physics, the same outcome, for any duration and any step ---------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("dt", [None, 0.01, 0.0037])
@pytest.mark.deep
def test_the_issue_peak_starts_slide_rock_for_every_duration(dt: float | None) -> None:
    """The issue's case: the impulsive peak 0.86 is past the SL/SRO- boundary 0.8557, 0.85 is not."""
    T = np.tile(np.linspace(2.0, 5.0, 8), 2)
    kp = np.repeat([0.85, 0.86], 8)
    sim = simulate(Block(mu=0.6, **CAISSON), Pulse.breaking(kp, T), dt=dt, t_max=T + 0.05)
    assert sim.phases is not None
    started = ["SRO-" in _labels(ph) for ph in sim.phases]
    assert started == [False] * 8 + [True] * 8
    assert all("SL" in _labels(ph) for ph in sim.phases)


@pytest.mark.slow
def test_without_events_the_issue_flips_with_the_duration() -> None:
    """What the events fix: the mid-points alone see the peak for some durations only."""
    T = np.linspace(2.0, 5.0, 8)
    sim = simulate(Block(mu=0.6, **CAISSON), Pulse.breaking(0.86, T), t_max=T + 0.05, events=False)
    assert sim.phases is not None
    started = {"SRO-" in _labels(ph) for ph in sim.phases}
    assert started == {True, False}


@pytest.mark.parametrize("shape", ["rectangular", "half-sine", "triangular"])
@pytest.mark.parametrize("dt", [None, 0.0011, 0.0173])
@pytest.mark.slow
@pytest.mark.deep
def test_initiation_is_decided_by_the_peak_alone(shape: str, dt: float | None) -> None:
    """The Makris-Roussos block starts rocking when k passes k_A = 1/3: a peak 3e-6 above it does
    for every duration and step, one 3e-6 below never does (the exact event on the peak)."""
    k_A = 1.0 / 3.0
    T = np.tile([0.05, 0.1, 0.2, 0.35, 0.5], 2)
    kp = np.repeat([k_A * (1 - 3e-6), k_A * (1 + 3e-6)], 5)
    params = {"peak_at": 0.3} if shape == "triangular" else {}
    sim = simulate(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.make(shape, kp, T, **params), dt=dt, t_max=T,
                   record_phases=False)
    assert sim.rocked.tolist() == [False] * 5 + [True] * 5


def test_half_sine_peak_is_missed_without_events() -> None:
    k_A = 1.0 / 3.0
    T = np.array([0.05, 0.1, 0.2, 0.35, 0.5])
    sim = simulate(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(k_A * (1 + 3e-6), T), t_max=T,
                   record_phases=False, events=False)
    assert not sim.rocked.all()  # N = 400 steps: no mid-point on the peak


@pytest.mark.parametrize("T", [0.3, 0.5, 0.77])
def test_a_step_lands_on_the_peak(T: float) -> None:
    blk, pulse = Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.3, T)
    sim = simulate(blk, pulse, history=0, t_max=T)
    hist = sim.history
    assert hist is not None
    assert hist.k.max() == 0.3  # the force of the event step is k(T/2) = k_peak exactly
    # the event step is EVENT_STEP of a regular step, and the regular steps are unchanged
    h = np.diff(hist.t)
    h_reg = float(default_steps(blk, pulse)[0][0])
    assert np.isclose(h, EVENT_STEP * h_reg, rtol=1e-6).sum() >= 2  # the peak and the end
    assert h.min() == pytest.approx(0.5 * EVENT_STEP * h_reg, rel=1e-6)  # the start: [0, delta]
    assert hist.t[-1] == pytest.approx(T + 0.5 * EVENT_STEP * h_reg, abs=1e-12)  # past the end event


# (B, gamma, mu, kprime, beta, nu, k_peak, duration) of tests/dynamics/test_batch.py, and what the
# stepper gave for them before events (pinned, restitution None): steps, end time, residual slide
_BATCH = np.array([
    (0.2, 3.0, 0.5, 0.0, 0.0, 0.0, 0.2, 0.5),
    (1.0, 0.5, 0.3, 0.0, 0.0, 0.0, 0.5, 0.4),
    (0.2, 3.0, 5.0, 0.0, 0.0, 0.0, 0.5, 0.5),
    (0.2, 2.0, 0.6, 0.0, 0.0, 0.0, 1.2, 0.3),
    (0.2, 3.0, 5.0, 0.0, 0.0, 0.0, 0.9, 0.6),
    (5.0, 1.1, 0.6, -0.1, 0.35, 0.25, 1.2, 3.0),
])
_PINNED_STEPS = [427, 441, 2848, 561, 512, 1716]
_PINNED_END = [0.5000000000000004, 0.4639302224966935, 3.3392565948894233, 0.45877357765928156,
               0.6000000000000004, 6.89584530376169]
_PINNED_SLIDE = [-0.0, 0.06376574494529223, -4.04575600558875e-06, 0.026374484283329752,
                 0.048524618300561706, 52.08241994058089]


@pytest.mark.portable
@pytest.mark.slow
@pytest.mark.deep
def test_without_events_the_stepper_is_unchanged() -> None:
    B, gamma, mu, kprime, beta, nu, k, T = _BATCH.T
    blk = Block(B=B, gamma=gamma, mu=mu, kprime=kprime, buoyancy=beta, uplift_ratio=nu)
    sim = simulate(blk, Pulse.half_sine(k, T), events=False)
    assert sim.steps.tolist() == _PINNED_STEPS
    np.testing.assert_allclose(sim.end_time, _PINNED_END, rtol=1e-13)
    np.testing.assert_allclose(sim.residual_slide, _PINNED_SLIDE, rtol=1e-9, atol=1e-15)
    with_events = simulate(blk, Pulse.half_sine(k, T))
    assert np.all(with_events.steps > sim.steps)  # events only add steps
    np.testing.assert_allclose(with_events.residual_slide, _PINNED_SLIDE, rtol=1e-4, atol=1e-7)


# -- categories from the motion ----------------------------------------------------------------------

@pytest.mark.slow
@pytest.mark.deep
def test_categories_agree_with_the_phases() -> None:
    B, gamma, mu, kprime, beta, nu, k, T = _BATCH.T
    blk = Block(B=B, gamma=gamma, mu=mu, kprime=kprime, buoyancy=beta, uplift_ratio=nu)
    sim = simulate(blk, Pulse.half_sine(k, T))
    assert sim.phases is not None
    for cat, ph, over, moving in zip(sim.category, sim.phases, sim.overturned, sim.still_moving, strict=True):
        labels = _labels(ph)
        rocked, slid = bool(labels & _ROCKING), bool(labels & _SLIDING)
        want = (OVERTURN if over else STILL_MOVING if moving else
                SLIDE_ROCK if rocked and slid else ROCK if rocked else SLIDE if slid else REST)
        assert cat == want, (CATEGORY_LABELS[cat], labels)
    assert set(sim.category.tolist()) >= {REST, SLIDE, ROCK, OVERTURN}


@pytest.mark.slow
@pytest.mark.deep
def test_min_rotation_moves_a_small_rocking_run_from_slide_rock_to_slide() -> None:
    sim = simulate(Block(mu=0.6, **CAISSON), Pulse.breaking(0.86, [2.0, 2.75]), t_max=[2.2, 2.95])
    assert sim.category.tolist() == [SLIDE_ROCK, SLIDE_ROCK]
    assert np.all(sim.max_rotation > 0) and np.all(sim.max_rotation < 1e-6)
    assert sim.categories(1e-6).tolist() == [SLIDE, SLIDE]
    assert sim.categories(0.0).tolist() == sim.category.tolist()
    with pytest.raises(ValueError, match="min_rotation"):
        sim.categories(-1.0)
    rock = simulate(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.5, 0.5))
    assert rock.category.tolist() == [ROCK] and rock.categories(1.0).tolist() == [REST]


# -- unfinished runs -------------------------------------------------------------------------------------

@pytest.mark.slow
def test_a_run_still_moving_at_the_time_limit_is_its_own_category() -> None:
    sim = simulate(Block(mu=0.0, **CAISSON), Pulse.breaking(0.86, 2.0), t_max=5.0)
    assert not sim.settled[0] and not sim.overturned[0] and sim.still_moving[0]
    assert 5.0 <= sim.end_time[0] < 5.01
    assert sim.category.tolist() == [STILL_MOVING] and CATEGORY_LABELS[STILL_MOVING] == "still moving"


@pytest.mark.slow
@pytest.mark.deep
def test_simulate_mu_0_says_still_moving() -> None:
    r = invoke_cli(["simulate", *CAISSON_CLI, "--mu", "0", "--duration", "2", "--json"])
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    assert d["settled"] is False and d["overturned"] is False and d["category"] == "still moving"
    assert d["residual_slide"] is None and d["residual_rotation"] is None and d["residual_rotation_deg"] is None
    assert "warning" in r.stderr and "still moving at t = 68.92" in r.stderr
    text = format_simulation(d)
    assert "still moving at t = 68.92" in text and "residual slide      none: still moving" in text
    assert "27.8" not in text


@pytest.mark.slow
def test_simulate_json_category_agrees_with_phases_and_min_rotation() -> None:
    r = invoke_cli(["simulate", *CAISSON_CLI, "--mu", "0.6", "--duration", "2.75", "--json"])
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    labels = {p["mode"] for p in d["phases"]}
    assert "SRO-" in labels and d["category"] == "slide-rock" and d["settled"] is True
    assert d["residual_slide"] is not None
    r = invoke_cli(["simulate", *CAISSON_CLI, "--mu", "0.6", "--duration", "2.75", "--min-rotation", "0.001"])
    assert r.code == 0, r.output
    assert "outcome    slide only" in r.stdout and "above a max rotation of 0.001 deg" in r.stdout
    r = invoke_cli(["simulate", *CAISSON_CLI, "--mu", "0.6", "--duration", "2.75", "--min-rotation", "-1"])
    assert r.code == 2 and "--min-rotation" in r.stderr


@pytest.mark.parametrize("T", [0.07, 0.2, 0.45])
@pytest.mark.slow
def test_a_push_to_the_right_starts_rocking_about_o_prime_at_the_mirror_boundary(T: float) -> None:
    """k < 0: the crossings of the mirror image's boundaries (k_A = 1/3 about O')."""
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    started = []
    for f in (1 - 3e-6, 1 + 3e-6):
        sim = simulate(blk, Pulse.from_arrays([0.0, 0.3 * T, T], [0.0, -f / 3.0, 0.0]), t_max=T)
        assert sim.phases is not None
        started.append("RO'" in _labels(sim.phases[0]))
    assert started == [False, True]


def test_a_densely_sampled_pulse_lands_on_its_turning_samples_only() -> None:
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    t = np.linspace(0.0, 0.5, 20001)
    sampled = simulate(blk, Pulse.from_arrays(t, 0.7 * np.sin(2 * np.pi * t)), t_max=0.5)
    analytic = simulate(blk, Pulse.half_sine(0.7, 0.5), t_max=0.5)
    assert abs(int(sampled.steps[0]) - int(analytic.steps[0])) <= 4
