"""Curves and named points lie where the report says they do."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Parameters
from regimemap.mechanics.curves import (
    dotted_line,
    line_OA,
    lower_line,
    mu_star,
    mu_star_star,
    named_points,
    upper_line,
)
from regimemap.mechanics.solver import Hypothesis, solve


def test_mu_star_is_friction_needed_to_rock():
    """mu*(k) = |f_x|/f_y of rocking about O, from the solver (3.24), (4.40)."""
    for g, kp in [(1.0, 0.2), (3.0, 0.4), (3.0, 0.95), (2.0, -0.5)]:
        p = Parameters(g, kp)
        k = np.linspace(p.k_A * 1.01, p.k_A * 5, 50)
        r = solve(Hypothesis.ROCK_O, k, 10.0, g, kp)
        assert np.allclose(mu_star(p, k), np.abs(r.fx) / r.fy)


def test_mu_star_limits():
    p = Parameters(2.0, 0.3)
    assert float(mu_star(p, 1e12)) == pytest.approx(p.a / p.c)  # k -> infinity
    assert float(mu_star(p, 0.0)) == pytest.approx(p.b / p.d)


def test_mu_star_star_pole_and_root():
    p = Parameters(2.0, -0.4)
    assert float(mu_star_star(p, p.k_F)) == pytest.approx(0, abs=1e-12)
    assert float(mu_star_star(p, p.k_pole * (1 - 1e-9))) > 1e6
    assert float(mu_star_star(p, 0.0)) == pytest.approx(-p.b / p.d)
    # F lies to the left of D (Section IV.6)
    assert p.k_F < p.k_D


def test_lines():
    p = Parameters(2.0, -0.5)
    k = np.array([0.0, 1.0, 2.0])
    assert np.allclose(upper_line(p, k), 0.5 + 0.5 * k)  # AB (4.21)
    assert np.allclose(lower_line(p, k), -0.5 + 0.5 * k)  # DC (4.20)
    assert np.allclose(dotted_line(p, k), 0.5 * k)  # (4.22)
    assert np.allclose(line_OA(p, k), k)
    q = Parameters(2.0, 0.5)
    assert np.allclose(upper_line(q, k), 0.5 - 0.5 * k)  # CD (Section III.2)


def test_named_points_above_and_below():
    above = named_points(Parameters(3.0, 0.9))
    assert {"O", "A", "C", "D", "G"} <= set(above)
    assert above["G"].k == pytest.approx(Parameters(3.0, 0.9).b_over_abs_a)
    below = named_points(Parameters(1.0, -0.3))
    assert {"O", "A", "E", "B'", "D", "F", "C'"} <= set(below)
    p = Parameters(1.0, -0.3)
    c1 = below["C'"]
    assert float(mu_star(p, c1.k)) == pytest.approx(c1.mu)
    assert float(lower_line(p, c1.k)) == pytest.approx(c1.mu)
    # D right of A iff |k'| < 1/2 (Section IV.2)
    assert below["D"].k > below["A"].k
    pts = named_points(Parameters(1.0, -0.7))
    assert pts["D"].k < pts["A"].k
