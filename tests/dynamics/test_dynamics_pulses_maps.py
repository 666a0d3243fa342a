"""Pulse shapes, their parameters and vectorised evaluation; outcome maps and dimensionless axes."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.dynamics import (
    CATEGORY_LABELS,
    Block,
    Pulse,
    from_dimensionless,
    outcome_map,
    simulate,
    to_dimensionless,
)


def test_half_sine_and_one_sine_frequencies() -> None:
    assert Pulse.half_sine(1.0, 0.5).omega_p == pytest.approx(2 * np.pi)
    assert Pulse.one_sine(1.0, 0.5).omega_p == pytest.approx(4 * np.pi)
    assert Pulse.one_cosine(1.0, 0.5).omega_p == pytest.approx(4 * np.pi)
    p = Pulse.from_frequency("half-sine", 1.0, 2 * np.pi)
    assert float(p.duration) == pytest.approx(0.5)
    p = Pulse.from_frequency("one-sine", 1.0, 2 * np.pi)
    assert float(p.duration) == pytest.approx(1.0)


def test_shapes_values() -> None:
    t = np.array([-0.1, 0.0, 0.125, 0.25, 0.375, 0.5, 0.6])
    np.testing.assert_allclose(Pulse.rectangular(2.0, 0.5).k(t), [0, 2, 2, 2, 2, 0, 0])
    np.testing.assert_allclose(Pulse.triangular(2.0, 0.5).k(t), [0, 0, 1, 2, 1, 0, 0])
    np.testing.assert_allclose(Pulse.triangular(2.0, 0.5, peak_at=0.0).k(t), [0, 2, 1.5, 1, 0.5, 0, 0])
    np.testing.assert_allclose(Pulse.half_sine(2.0, 0.5).k(t), [0, 0, np.sqrt(2), 2, np.sqrt(2), 0, 0],
                               atol=1e-12)
    np.testing.assert_allclose(Pulse.one_sine(2.0, 0.5).k(t), [0, 0, 2, 0, -2, 0, 0], atol=1e-12)
    np.testing.assert_allclose(Pulse.one_cosine(2.0, 0.5).k(t), [0, 2, 0, -2, 0, 0, 0], atol=1e-12)


def test_breaking_wave_pulse() -> None:
    p = Pulse.breaking(3.0, 1.0, peak_ratio=0.4, impulsive_fraction=0.1)
    t = np.linspace(0, 1, 100001)
    k = p.k(t)
    assert k.max() == pytest.approx(3.0)
    assert t[np.argmax(k)] == pytest.approx(0.05, abs=1e-4)
    assert p.k(0.5) == pytest.approx(0.4 * 3.0)  # the standing-wave half-sine
    assert p.k(0.0) == 0.0 and p.k(1.0) == 0.0
    assert np.all(k >= 0.4 * 3.0 * np.sin(np.pi * t) - 1e-12)


def test_per_run_parameters_and_arrays() -> None:
    p = Pulse.half_sine([1.0, 2.0, 3.0], [0.5, 1.0, 2.0])
    np.testing.assert_allclose(p.k(np.array([0.25, 0.5, 1.0])), [1.0, 2.0, 3.0])
    s = Pulse.from_arrays([0.0, 1.0, 2.0], [0.0, 1.0, -1.0], kprime=[0.0, 0.5, 1.0])
    assert float(s.duration) == 2.0 and float(s.k_peak) == 1.0
    np.testing.assert_allclose(s.k([0.5, 1.5, 2.5]), [0.5, 0.0, 0.0])
    kp = s.kprime([0.5])
    assert kp is not None and kp[0] == pytest.approx(0.25)


def test_invalid_pulses() -> None:
    with pytest.raises(ValueError):
        Pulse.make("square", 1.0, 1.0)
    with pytest.raises(ValueError):
        Pulse.half_sine(1.0, 0.0)
    with pytest.raises(ValueError):
        Pulse.from_arrays([0.0, 0.0, 1.0], [0.0, 1.0, 0.0])


def test_sampled_pulse_equals_analytic_pulse() -> None:
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    t = np.linspace(0, 0.5, 20001)
    a = simulate(blk, Pulse.half_sine(0.7, 0.5))
    b = simulate(blk, Pulse.from_arrays(t, 0.7 * np.sin(2 * np.pi * t)))
    assert a.overturned[0] == b.overturned[0]
    assert a.max_rotation[0] == pytest.approx(b.max_rotation[0], rel=1e-3)


def test_dimensionless_axes_round_trip() -> None:
    B, gamma = 0.2, 3.0
    w, k = to_dimensionless(0.5, 2 * np.pi, B, gamma)
    R = B * np.hypot(1, gamma)
    assert w == pytest.approx(2 * np.pi / np.sqrt(3 * 9.81 / (4 * R)))
    assert k == pytest.approx(1.5)
    kp, om = from_dimensionless(w, k, B, gamma)
    assert kp == pytest.approx(0.5) and om == pytest.approx(2 * np.pi)


@pytest.mark.slow
@pytest.mark.deep
def test_outcome_map_shapes_and_categories() -> None:
    """The grid of runs: its shapes, categories and cells (refine=False: the refinement adds
    crossings and leaves the grid as it is; tests/dynamics/test_outcome_boundaries.py checks it)."""
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    kp = np.array([0.2, 0.4, 0.6, 1.5, 3.0])
    dur = np.array([0.1, 0.5, 1.0])
    m = outcome_map(blk, "half-sine", ("k_peak", kp), ("duration", dur), refine=False)
    assert not m.refined
    assert m.category.shape == (3, 5) and m.overturned.shape == (3, 5)
    assert m.labels == CATEGORY_LABELS
    assert np.all(m.category[:, 0] == 0) and np.all(m.max_rotation[:, 0] == 0)
    assert np.all(m.category[m.overturned] == 4)
    assert m.overturned[2, 4] and not m.overturned[0, 1]
    # the rows are the second axis: the cell equals a single run
    one = simulate(blk, Pulse.half_sine(1.5, 1.0))
    assert m.max_rotation[2, 3] == pytest.approx(one.max_rotation[0])


@pytest.mark.slow
def test_outcome_map_of_friction() -> None:
    blk = Block(B=1.0, gamma=0.5, mu=0.3)
    m = outcome_map(blk, "rectangular", ("mu", [0.2, 0.4, 0.6]), ("k_peak", [0.3, 0.5]), duration=0.3)
    # sliding when k > mu, rest otherwise (a squat block does not rock)
    np.testing.assert_array_equal(m.category, [[1, 0, 0], [1, 1, 0]])
    assert m.residual_slide[1, 0] == pytest.approx(9.81 * 0.09 * 0.5 * 0.3 / 0.4, rel=2e-3)
