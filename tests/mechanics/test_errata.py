"""Each entry of docs/errata.md, settled by the equations-of-motion solver."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify
from regimemap.mechanics.curves import lower_line, mu_star_signed, mu_star_star
from regimemap.mechanics.solver import Hypothesis, admissible, solve


def test_E1_moment_of_inertia_is_one_third():
    """(3.30): the Chinese text states I = m(H^2+B^2)/2; (3.30) itself follows from I/3."""
    g, kp, k = 2.5, 0.3, 0.8
    mu = np.linspace(0.05, 1.2, 30)
    r = solve(Hypothesis.SLIDE_ROCK_O_LEFT, k, mu, g, kp)
    printed_330 = 3 * (mu * g - 1 + k * kp * g) / (4 + g * g - 3 * mu * g)
    with_half = 2 * (mu * g - 1 + k * kp * g) / (3 + g * g - 2 * mu * g)
    assert np.allclose(r.thdd, printed_330)
    assert not np.allclose(r.thdd, with_half, rtol=1e-3)


def test_E2_case_2_slope_of_mu_star():
    """Section III.3, case 2: the slope's numerator is 4(1+g^2)(1+g^2-3g^2k'), not (1+g-3g^2k')."""
    p = Parameters(3.0, 0.9)
    assert p.a < 0
    k = np.linspace(0.01, 0.9 * p.b_over_abs_a, 20)
    h = 1e-6
    numeric = (mu_star_signed(p, k + h) - mu_star_signed(p, k - h)) / (2 * h)
    g2 = p.gamma**2
    den = (p.c * k + p.d) ** 2
    derived = 4 * (1 + g2) * (1 + g2 - 3 * g2 * p.kprime) / den
    printed = 4 * (1 + g2) * (1 + p.gamma - 3 * g2 * p.kprime) / den
    assert np.allclose(numeric, derived, rtol=1e-6)
    assert not np.allclose(numeric, printed, rtol=1e-3)


def _slip_sign_change(hyp, k, g, kp, mus):
    r = solve(hyp, k, mus, g, kp)
    s = np.sign(r.slip)
    i = np.flatnonzero(np.diff(s) != 0)
    assert i.size == 1
    return 0.5 * (mus[i[0]] + mus[i[0] + 1])


@pytest.mark.slow
def test_E3_mu_star_star_coefficient():
    """(4.96): the coefficient of k is 4+g^2+3g^2|k'| (as in (4.42), (4.97)), not 3g|k'|."""
    g, kp = 2.0, -0.6
    p = Parameters(g, kp)
    k = 0.5 * p.k_pole
    mus = np.linspace(0, 3 * float(mu_star_star(p, k)), 200001)
    where = _slip_sign_change(Hypothesis.SLIDE_ROCK_O_PRIME_LEFT, k, g, kp, mus)
    derived = float(mu_star_star(p, k))
    q = abs(kp)
    printed = ((4 + g * g + 3 * g * q) * k - 3 * g) / (1 + 4 * g * g - 3 * g * (1 - q) * k)
    step = mus[1] - mus[0]
    assert abs(where - derived) < 2 * step
    assert abs(where - printed) > 100 * step


def test_E4_slide_rock_about_O_prime_beyond_the_pole():
    """(4.96): for k > d/c, x''_O' <= 0 holds for every mu; the region is all of mu <= DC."""
    g, kp = 1.0, -0.9
    p = Parameters(g, kp)
    k = np.linspace(1.05 * p.k_pole, 3 * p.k_pole, 50)
    mu = 0.5 * lower_line(p, k)
    assert (mu > 0).all() and (mu_star_star(p, k) < 0).all()  # the printed rule would exclude them
    r = solve(Hypothesis.SLIDE_ROCK_O_PRIME_LEFT, k, mu, g, kp)
    assert r.ok.all()
    assert (classify(k, mu, g, kp) == Mode.SRO_PRIME_MINUS).all()


def test_E5_moment_of_F_below_C_uses_kprime():
    """(4.3), (4.13): the moment of F about C is F|k'|H, giving xi = -kH(1-|k'|) (4.8)."""
    g, kp, k = 1.5, -0.4, 0.3
    r = solve(Hypothesis.REST, k, 1.0, g, kp)
    assert float(r.xi) == pytest.approx(-k * g * (1 - abs(kp)))  # xi/B = -k gamma (1-|k'|)


def test_E6_rest_reaction_left_of_C():
    """Section III.1: in rest mode xi <= 0 (printed: |xi| <= 0)."""
    k = np.linspace(0.01, 0.3, 10)
    r = solve(Hypothesis.REST, k, 1.0, 2.0, 0.5)
    assert (r.xi < 0).all()


def test_E7_case_2_threshold():
    """After (3.42): case 2 is k' >= (4+g^2)/(3g^2), not (4+g)/(3g^2)."""
    g = 3.0
    assert Parameters(g, (4 + g * g) / (3 * g * g)).a == pytest.approx(0, abs=1e-12)
    assert Parameters(g, (4 + g) / (3 * g * g)).a != pytest.approx(0, abs=1e-3)


def test_E8_rocking_possible_for_stocky_blocks():
    """Section III.3: 'for gamma <= sqrt 2 no rocking motion can be initiated' — only cases 2/3
    cannot arise (a > 0); rocking (case 1) starts for every gamma."""
    for g in (0.5, 1.0, 1.4):
        k = 2.0 / g
        assert bool(admissible(k, 5.0, g, 0.5)[Mode.RO])
        assert Parameters(g, 1.0).a > 0


def test_E9_slip_of_O_below_C():
    """(4.76) is the slip of O in slide-rock about O (the text says 'about O'')."""
    g, kp = 2.0, -0.3
    p = Parameters(g, kp)
    k, mu = 0.9, 0.6
    r = solve(Hypothesis.SLIDE_ROCK_O_LEFT, k, mu, g, kp)
    x_o = (mu * (p.c * k + p.d) - (p.a * k + p.b)) / (4 + g * g - 3 * mu * g)
    assert float(r.slip) == pytest.approx(x_o)


def test_E10_mu_B_prime():
    """(4.68): the bound is mu_B' = (4+g^2)/(3g), the ordinate of B' where mu* meets AB."""
    p = Parameters(2.0, -0.2)
    assert float(mu_star_signed(p, p.k_Bprime)) == pytest.approx(p.mu_Bprime)


def test_E11_slip_of_O_in_SRO_plus():
    """(3.45): x''_O = -g[mu(ck+d) + (ak+b)]/(4+g^2+3mu g) (a parenthesis is missing)."""
    g, kp = 3.0, 0.9
    p = Parameters(g, kp)
    k, mu = 2 * p.b_over_abs_a, 0.02
    r = solve(Hypothesis.SLIDE_ROCK_O_RIGHT, k, mu, g, kp)
    expect = -(mu * (p.c * k + p.d) + (p.a * k + p.b)) / (4 + g * g + 3 * mu * g)
    assert float(r.slip) == pytest.approx(expect)


def test_E12_centre_moves_left_in_SRO_plus():
    """Section III.4 calls SRO+ 'x'' >= 0 (body moving to the right)': it is the corner O
    that slips right (x''_O >= 0); the centre of mass accelerates to the left."""
    g, kp = 3.0, 0.9
    p = Parameters(g, kp)
    k, mu = 2 * p.b_over_abs_a, 0.02
    r = solve(Hypothesis.SLIDE_ROCK_O_RIGHT, k, mu, g, kp)
    assert bool(r.ok) and float(r.slip) > 0 and float(r.xdd) < 0


def test_E13_dotted_line_is_k_abs_kprime():
    """Section IV.2: 'the region below line mu = k|k|' is below mu = k|k'| (4.22): xi changes sign there."""
    g, kp, k = 1.0, -0.5, 2.0
    mu = np.array([k * 0.5 - 0.05, k * 0.5 + 0.05])
    r = solve(Hypothesis.SLIDE_LEFT, k, mu, g, kp)
    assert r.xi[0] > 0 > r.xi[1]
