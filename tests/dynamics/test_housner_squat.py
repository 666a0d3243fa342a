"""Housner's impact ratio for a squat block: <= 0, not applicable; the impact ends the rocking."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from regimemap.dynamics import Block, Pulse, simulate

BLOCK = ["--half-width", "0.3", "--kprime", "0", "--mu", "5", "--pulse", "half-sine", "--k-peak", "3", "--duration", "0.05"]


@pytest.mark.parametrize("gamma", [0.3, 0.5, 0.7])
def test_the_ratio_is_not_positive_below_one_over_root_two(gamma: float) -> None:
    blk = Block(B=0.3, gamma=gamma, mu=5.0)
    alpha = math.atan(1.0 / gamma)
    assert float(blk.housner_ratio) == pytest.approx(1.0 - 1.5 * math.sin(alpha) ** 2, rel=1e-12)
    assert float(blk.housner_ratio) <= 0.0


@pytest.mark.slow
@pytest.mark.parametrize("gamma", [0.5, 0.65])
@pytest.mark.deep
def test_a_squat_block_lands_flat_at_its_first_impact(gamma: float) -> None:
    """Released tilted on one corner, it rocks back and stops: no rocking about the other corner."""
    blk = Block(B=0.3, gamma=gamma, mu=5.0)
    alpha = math.atan(1.0 / gamma)
    sim = simulate(blk, Pulse.rectangular(0.0, 0.01), theta0=0.3 * alpha, dt=4e-5, t_max=3.0, history=0)
    assert sim.phases is not None
    modes = [m for m, _ in sim.phases[0]]
    assert modes == ["RO", "RE"] and sim.settled[0]
    assert abs(float(sim.residual_rotation[0])) < 1e-3 * alpha
    h = sim.history
    assert h is not None
    assert np.all(h.theta >= -1e-3 * alpha)  # never past flat onto the other corner


@pytest.mark.slow
def test_simulate_says_not_applicable(run_cli) -> None:
    r = run_cli(["simulate", "--gamma", "0.5", *BLOCK])
    assert r.code == 0, r.stderr
    assert "impact ratio not applicable (a squat block: Housner's" in r.stdout
    assert "= -0.2 <= 0" in r.stdout and "the block lands flat" in r.stdout
    obj = json.loads(run_cli(["simulate", "--gamma", "0.5", *BLOCK, "--json"]).stdout)
    assert obj["derived"]["impact_ratio"] is None
    assert obj["derived"]["housner_ratio"] == pytest.approx(-0.2, rel=1e-11)


@pytest.mark.deep
def test_a_slender_block_keeps_housner(run_cli) -> None:
    r = run_cli(["simulate", "--gamma", "3", *BLOCK])
    eta = 1.0 - 1.5 * math.sin(math.atan(1.0 / 3.0)) ** 2
    assert f"impact ratio {eta:.4g} (Housner)" in r.stdout
    obj = json.loads(run_cli(["simulate", "--gamma", "3", *BLOCK, "--json"]).stdout)
    assert obj["derived"]["impact_ratio"] == pytest.approx(eta, rel=1e-11)
    r = run_cli(["simulate", "--gamma", "0.5", *BLOCK, "--restitution", "0.3"])
    assert "impact ratio 0.3 (--restitution)" in r.stdout
