"""regimemap.dynamics against closed forms: sliding, exact rest, Housner's impact ratio, energy."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.dynamics import Block, Phase, Pulse, simulate

G = 9.81


@pytest.mark.parametrize("k, mu, td", [(0.5, 0.3, 0.4), (0.35, 0.2, 1.0), (0.9, 0.6, 0.05)])
@pytest.mark.slow
def test_pure_sliding_rectangular_pulse(k: float, mu: float, td: float) -> None:
    # squat block (tan(alpha) = 2): slides, never rocks
    blk = Block(B=1.0, gamma=0.5, mu=mu)
    sim = simulate(blk, Pulse.rectangular(k, td))
    expected = G * td**2 * k * (k - mu) / (2 * mu)
    assert sim.residual_slide[0] == pytest.approx(expected, rel=2e-3)
    assert sim.max_rotation[0] == 0.0
    assert sim.phases is not None
    assert [label for label, _ in sim.phases[0]] == ["SL", "RE"]
    # the block stops at t_d + v/(mu g) = t_d k/mu
    assert sim.phases[0][1][1] == pytest.approx(td * k / mu, rel=5e-3)
    assert sim.category[0] == 1 and sim.settled[0]


@pytest.mark.slow
def test_pure_sliding_batch_matches_closed_form() -> None:
    k = np.array([0.4, 0.5, 0.6, 0.7])
    td = np.array([0.2, 0.3, 0.5, 0.8])
    sim = simulate(Block(B=2.0, gamma=0.4, mu=0.3), Pulse.rectangular(k, td))
    np.testing.assert_allclose(sim.residual_slide, G * td**2 * k * (k - 0.3) / 0.6, rtol=2e-3)


@pytest.mark.parametrize("pulse", [
    Pulse.rectangular(0.3, 0.5), Pulse.triangular(0.3, 0.5), Pulse.half_sine(0.3, 0.5),
    Pulse.one_sine(0.3, 0.5), Pulse.one_cosine(0.3, 0.5), Pulse.breaking(0.3, 0.5),
    Pulse.from_arrays([0.0, 0.1, 0.2, 0.4], [0.0, 0.3, -0.3, 0.1]),
])
def test_below_every_threshold_stays_exactly_at_rest(pulse: Pulse) -> None:
    # k <= 0.3 < mu = 0.5 and < tan(alpha) = 1/3
    sim = simulate(Block(B=0.2, gamma=3.0, mu=0.5), pulse, history=0)
    h = sim.history
    assert h is not None
    assert np.all(h.x == 0.0) and np.all(h.y == 0.0) and np.all(h.theta == 0.0)
    assert np.all(h.vx == 0.0) and np.all(h.omega == 0.0)
    assert sim.residual_slide[0] == 0.0 and sim.residual_rotation[0] == 0.0
    assert sim.phases == [[("RE", 0.0)]]
    assert sim.category[0] == 0 and sim.settled[0]


def _first_impact_ratio(sim_hist: object) -> float:
    h = sim_hist
    ph = h.phase.astype(int)  # type: ignore[attr-defined]
    j = int(np.flatnonzero((ph[1:] == Phase.RO_PRIME) & (ph[:-1] == Phase.RO))[0])
    return float(h.omega[j + 1] / h.omega[j])  # type: ignore[attr-defined]


def _impact_ratio_at_dt_zero(blk: Block, theta0: float, t_max: float, restitution: float | None = None) -> float:
    """The first impact's ratio omega+/omega-, extrapolated to dt -> 0 (Richardson).

    The ratio the stepper records converges to the impact law at first order in dt (its error is
    -1.3e-4 at dt = 4e-5, -6.5e-4 at 2e-4, -3.3e-3 at 1e-3): two runs at dt = 2e-4 and 4e-4 give
    2 r(dt) - r(2 dt), within a few 1e-6 of the law, at a fifth of the steps of one run at 4e-5.
    The two ratios must differ by first-order amounts (under 2e-3), else they are not yet in the
    asymptotic range and the extrapolation proves nothing.
    """
    r1, r2 = (_first_impact_ratio(simulate(blk, Pulse.rectangular(0.0, 0.01), theta0=theta0, dt=dt, t_max=t_max,
                                           history=0, restitution=restitution).history)
              for dt in (2e-4, 4e-4))
    assert 0 < r1 - r2 < 2e-3, (r1, r2)  # the error falls with dt, at first order
    return 2 * r1 - r2


@pytest.mark.slow
@pytest.mark.parametrize("gamma", [2.0, 3.0, 5.0])
@pytest.mark.deep
def test_plastic_impact_gives_housner_ratio(gamma: float) -> None:
    blk = Block(B=0.3, gamma=gamma, mu=5.0)
    alpha = np.arctan(1 / gamma)
    t1 = np.arccosh(1 / 0.4) / float(blk.p) + 0.05  # just after the first impact
    ratio = _impact_ratio_at_dt_zero(blk, 0.6 * alpha, t1)
    assert ratio == pytest.approx(1 - 1.5 * np.sin(alpha) ** 2, abs=5e-5)


@pytest.mark.slow
@pytest.mark.deep
def test_plastic_impact_ratio_of_a_non_uniform_block() -> None:
    blk = Block(B=0.3, gamma=3.0, mu=5.0, i2=2.0)
    B, H, J = 0.3, 0.9, 2.0 * 0.09
    assert _impact_ratio_at_dt_zero(blk, 0.2, 0.6) == pytest.approx((J + H * H - B * B) / (J + H * H + B * B),
                                                                    abs=5e-5)


@pytest.mark.slow
@pytest.mark.parametrize("r", [0.5, 0.7, 0.95])
@pytest.mark.deep
def test_restitution_sets_the_rocking_ratio(r: float) -> None:
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    assert _impact_ratio_at_dt_zero(blk, 0.2, 0.6, restitution=r) == pytest.approx(r, abs=5e-5)


def _energy(h: object, J: float) -> np.ndarray:
    return 0.5 * (h.vx**2 + h.vy**2 + J * h.omega**2) + G * h.y  # type: ignore[attr-defined]


@pytest.mark.slow
@pytest.mark.parametrize("restitution", [None, 0.9, 1.0])
@pytest.mark.deep
def test_energy_never_grows_in_free_rocking(restitution: float | None) -> None:
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    sim = simulate(blk, Pulse.rectangular(0.0, 0.01), theta0=0.25, restitution=restitution, history=0,
                   t_max=8.0)
    h = sim.history
    assert h is not None
    E = _energy(h, float(blk.gyration2) * 0.04)
    assert np.diff(E).max() <= 1e-7 * E[0]
    assert E[-1] < E[0]


def test_energy_never_grows_after_a_slide_rock_pulse() -> None:
    # low friction, push above C: slide, slide-rock about O then O', slide, rest
    blk = Block(B=0.5, gamma=2.0, mu=0.15, kprime=0.5)
    sim = simulate(blk, Pulse.half_sine(2.0, 0.1), history=0)
    h = sim.history
    assert h is not None and sim.slid[0] and sim.rocked[0] and not sim.overturned[0]
    assert sim.phases is not None and "SRO-" in [label for label, _ in sim.phases[0]]
    after = h.t >= 0.1
    E = _energy(h, float(blk.gyration2) * 0.25)[after]
    assert np.diff(E).max() <= 1e-7 * abs(E).max()


def test_initial_rotation_with_velocity_starts_on_the_corner() -> None:
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    sim = simulate(blk, Pulse.rectangular(0.0, 0.01), theta0=0.1, omega0=0.5, history=0, t_max=0.05)
    h = sim.history
    assert h is not None
    # corner O stays on the base while rotating about it
    gap = 0.6 + h.y - 0.2 * np.sin(h.theta) - 0.6 * np.cos(h.theta)
    assert np.abs(gap).max() < 1e-9
    assert h.omega[1] == pytest.approx(0.5, rel=1e-2)
