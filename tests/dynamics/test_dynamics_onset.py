"""The motion at t = 0+ of the stepper is the mode of regimemap.classify (zero loads), and the
loaded block starts moving at our own closed-form static thresholds."""

from __future__ import annotations

import numpy as np
import pytest

import regimemap
from regimemap import Mode
from regimemap.dynamics import Block, Phase, Pulse, simulate

CASES = [(2.0, 0.0), (3.0, 0.0), (2.0, 0.5), (3.0, 0.5), (2.0, -0.5), (3.0, -0.5), (2.0, 1.0), (3.0, 1.0)]
MODES = (Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS, Mode.SRO_PRIME_MINUS)


def _interior_points(mode: Mode, per_case: int = 3) -> list[tuple[float, float, float, float]]:
    """(k, mu, gamma, kprime) inside the region of ``mode`` (all 8 neighbours on a fine grid agree)."""
    out = []
    for gamma, kprime in CASES:
        k = np.linspace(0.02, 3.0, 150)
        mu = np.linspace(0.02, 2.0, 150)
        K, M = np.meshgrid(k, mu)
        c = np.asarray(regimemap.classify(K, M, gamma, kprime)).astype(int)
        inside = c == mode
        core = inside.copy()
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                core[1:-1, 1:-1] &= inside[1 + di:c.shape[0] - 1 + di, 1 + dj:c.shape[1] - 1 + dj]
        core[0, :] = core[-1, :] = core[:, 0] = core[:, -1] = False
        idx = np.argwhere(core)
        if len(idx):
            pick = idx[np.linspace(0, len(idx) - 1, per_case).astype(int)]
            out += [(float(K[i, j]), float(M[i, j]), gamma, kprime) for i, j in pick]
    return out


@pytest.mark.parametrize("mode", MODES, ids=lambda m: m.label)
def test_initial_motion_is_the_mode_of_classify(mode: Mode) -> None:
    pts = _interior_points(mode)
    assert len(pts) >= 3
    k, mu, gamma, kprime = (np.array(v) for v in zip(*pts, strict=True))
    blk = Block(B=0.5, gamma=gamma, mu=mu, kprime=kprime)
    sim = simulate(blk, Pulse.rectangular(k, 0.05), t_max=0.004, record_phases=False)
    assert np.all(sim.initial_mode == int(mode)), [(p, Phase(int(c)).label)
                                                   for p, c in zip(pts, sim.initial_mode, strict=True)]


def test_every_map_mode_is_reached() -> None:
    for mode in MODES:
        assert _interior_points(mode, per_case=1), mode.label


@pytest.mark.parametrize("beta, u, nu, e_u, kprime", [
    (0.0, 0.0, 0.0, 1 / 3, 0.0), (0.3, 0.0, 0.0, 1 / 3, 0.0), (0.2, 0.15, 0.0, 1 / 3, 0.4),
    (0.1, 0.1, 0.3, 0.5, -0.3), (0.4, 0.2, 0.2, 1 / 3, 0.8),
])
def test_loaded_block_starts_at_closed_form_thresholds(beta: float, u: float, nu: float, e_u: float,
                                                       kprime: float) -> None:
    gamma = 2.5
    # rocking about O (friction high): moment about O of push, weight-buoyancy and uplift vanishes
    k_rock = ((1 - beta) - u * (1 + e_u)) / ((1 + kprime) * gamma + nu * (1 + e_u))
    blk = Block(B=0.5, gamma=gamma, mu=5.0, kprime=kprime, buoyancy=beta, uplift=u, uplift_ratio=nu, uplift_arm=e_u)
    sim = simulate(blk, Pulse.rectangular(np.array([0.99, 1.01]) * k_rock, 0.05), t_max=0.004,
                   record_phases=False)
    assert list(sim.initial_mode) == [Phase.RE, Phase.RO]
    # sliding (friction low, squat block): k = mu (1 - beta - u - nu k)
    mu = 0.2
    k_slide = mu * (1 - beta - u) / (1 + mu * nu)
    blk = Block(B=2.0, gamma=0.3, mu=mu, kprime=kprime, buoyancy=beta, uplift=u, uplift_ratio=nu, uplift_arm=e_u)
    sim = simulate(blk, Pulse.rectangular(np.array([0.99, 1.01]) * k_slide, 0.05), t_max=0.004,
                   record_phases=False)
    assert list(sim.initial_mode) == [Phase.RE, Phase.SL]


def test_phase_codes_are_the_modes() -> None:
    """A phase and a mode with one code name one state; flight is the map's lift-off."""
    for ph in Phase:
        mode = Mode(int(ph))
        assert ph.label == ("FLIGHT" if mode is Mode.LO else mode.label)
    assert Phase.FLIGHT == Mode.LO
