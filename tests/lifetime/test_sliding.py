"""The slide of one wave: closed form against an event-driven integration and against `simulate`."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from regimemap.dynamics import Block, Pulse, simulate
from regimemap.lifetime import ADDED_MASS_COEFFICIENT, added_mass, half_sine_slide, wave_duration


def _integrated(F: float, R: float, M: float, tau: float) -> float:
    """Event-driven integration of M x'' = F sin(pi t/tau) - R while x' > 0 (rtol 1e-12)."""
    w = math.pi / tau
    t1 = math.asin(R / F) / w

    def rhs(t: float, y: list[float]) -> list[float]:
        push = F * math.sin(w * t) if t < tau else 0.0
        return [y[1], (push - R) / M]

    def stops(t: float, y: list[float]) -> float:
        return y[1] if t > t1 + 1e-9 * tau else 1.0

    stops.terminal = True  # type: ignore[attr-defined]
    stops.direction = -1  # type: ignore[attr-defined]
    r = solve_ivp(rhs, (t1, tau), [0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-18, events=stops)
    if r.status == 1:
        return float(r.y[0, -1])
    x, v = float(r.y[0, -1]), float(r.y[1, -1])
    return x + v * v / (2.0 * R / M)  # after the wave: uniform deceleration R/M


@pytest.mark.parametrize("ratio", [1.002, 1.01, 1.05, 1.2, 1.5, 2.0, 3.0, 6.0, 20.0])
@pytest.mark.parametrize("tau", [0.7, 4.0])
def test_closed_form_matches_integration(ratio, tau):
    R, M = 1.3e6, 2.4e5
    got = float(half_sine_slide(ratio * R, R, M, tau))
    ref = _integrated(ratio * R, R, M, tau)
    assert got > 0.0
    assert got == pytest.approx(ref, rel=1e-6)


def test_both_branches_of_the_stop_are_exercised():
    # ratio 1.2 stops within the wave, ratio 3 after it (v(pi) >= 0 above ~ F/R = 1.38)
    R, M, tau = 1.0, 1.0, 1.0
    for ratio, late in ((1.2, False), (3.0, True)):
        s1 = math.asin(1.0 / ratio)
        v_pi = ratio * (math.cos(s1) + 1.0) - (math.pi - s1)
        assert (v_pi >= 0.0) is late
        assert float(half_sine_slide(ratio * R, R, M, tau)) == pytest.approx(_integrated(ratio, R, M, tau),
                                                                              rel=1e-6)


def test_no_slide_at_or_below_friction_and_vectorised():
    F = np.array([0.0, 0.5, 1.0, 1.0 + 1e-12, 2.0])
    x = half_sine_slide(F, 1.0, 1.0, 1.0)
    assert x.shape == (5,)
    assert np.all(x[:3] == 0.0)
    assert 0.0 <= x[3] < 1e-12
    assert x[4] > 0.0
    # broadcasting: one force, several durations; distance scales with tau^2
    y = half_sine_slide(2.0, 1.0, 1.0, np.array([1.0, 2.0]))
    assert y[1] == pytest.approx(4.0 * y[0], rel=1e-12)


def test_slide_grows_with_the_push():
    F = np.linspace(1.0, 5.0, 401)
    x = half_sine_slide(F, 1.0, 1.0, 1.0)
    assert np.all(np.diff(x) > 0.0)


def test_added_mass_is_the_series_of_westergaard():
    odd = np.arange(1, 200001, 2, dtype=np.float64)
    per_face = 16.0 / math.pi**3 * np.sum(1.0 / odd**3)
    assert ADDED_MASS_COEFFICIENT == pytest.approx(2.0 * per_face, rel=1e-10)
    assert round(ADDED_MASS_COEFFICIENT, 4) == 1.0855
    assert float(added_mass(7.1, 1030.0)) == pytest.approx(1.0855 * 1030.0 * 7.1**2, rel=1e-4)


def test_wave_duration():
    assert float(wave_duration(8.0, 10.0, 12.0)) == pytest.approx((0.5 - 0.1) * 12.0)


@pytest.mark.slow
@pytest.mark.parametrize("k_peak,duration", [(0.45, 2.0), (0.8, 1.0)])
@pytest.mark.deep
def test_closed_form_matches_simulate_for_a_block_that_only_slides(k_peak, duration):
    """The loaded block of `simulate` with the lifetime model's loads, no added mass.

    m x'' = m g k(t) - mu m g (1 - beta - nu k(t)): F = m g k_peak (1 + mu nu), R = mu m g (1 - beta).
    A squat block pushed low (gamma 0.3, k' = -0.5) slides without rocking.
    """
    mu, beta, nu, g = 0.5, 0.3, 0.4, 9.81
    block = Block(B=5.0, gamma=0.3, mu=mu, kprime=-0.5, buoyancy=beta, uplift_ratio=nu, g=g)
    sim = simulate(block, Pulse.half_sine(k_peak, duration), dt=duration / 2000)
    assert not bool(sim.rocked[0]) and bool(sim.slid[0]) and bool(sim.settled[0])
    m = 1.0  # per unit mass
    expected = float(half_sine_slide(m * g * k_peak * (1.0 + mu * nu), mu * m * g * (1.0 - beta), m, duration))
    # the stepper's error comes from the start and the stop of the slide, within a step:
    # 1e-3 relative at 2000 steps over the pulse (measured: a few 1e-5)
    assert float(sim.residual_slide[0]) == pytest.approx(expected, rel=1e-3)
