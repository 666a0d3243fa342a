"""Parameters: validation, the report's constants and the case of (gamma, kprime)."""

from __future__ import annotations

import math

import pytest

from regimemap import Case, Parameters
from regimemap.mechanics.curves import mu_star, upper_line


def test_constants_match_report_both_chapters():
    p = Parameters(2.0, 0.5)  # (3.18)-(3.21)
    assert (p.a, p.b, p.c, p.d) == pytest.approx((4 + 4 - 6, 6, 9, 17))
    q = Parameters(2.0, -0.5)  # (4.42)-(4.45) with |k'| = 0.5
    assert (q.a, q.b, q.c, q.d) == pytest.approx((4 + 4 + 6, 6, 3, 17))


def test_point_A_and_B_prime():
    for g, kp in [(1.0, 0.2), (3.0, 0.6), (0.5, -0.3), (2.0, -0.1)]:
        p = Parameters(g, kp)
        assert p.k_A == pytest.approx(1 / (g * (1 + kp))) == pytest.approx(3 / p.c)
        assert float(mu_star(p, p.k_A)) == pytest.approx(p.k_A)  # mu* passes A
        assert float(upper_line(p, p.k_A)) == pytest.approx(p.k_A)  # CD / AB pass A
        if kp < 0:
            assert float(mu_star(p, p.k_Bprime)) == pytest.approx(p.mu_Bprime)  # (4.48)-(4.49)
            assert float(upper_line(p, p.k_Bprime)) == pytest.approx(p.mu_Bprime)
    assert math.isinf(Parameters(1.0, -1.0).k_A)
    assert math.isinf(Parameters(1.0, 0.3).k_Bprime)


def test_delta_and_slope_at_A():
    for g, kp in [(1.0, -0.2), (3.0, -0.7), (2.0, 0.0)]:
        p = Parameters(g, kp)
        h = 1e-6
        slope = (float(mu_star(p, p.k_A + h)) - float(mu_star(p, p.k_A - h))) / (2 * h)
        assert slope == pytest.approx(p.slope_at_A, rel=1e-5)
        assert p.delta == pytest.approx(slope - abs(kp), rel=1e-5, abs=1e-9)


@pytest.mark.parametrize(
    "gamma,kprime,case",
    [
        (3.0, 0.1, Case.ABOVE_1A),
        (3.0, 0.0, Case.ABOVE_1A),
        (3.0, 0.4, Case.ABOVE_1B),
        (3.0, 0.9, Case.ABOVE_2_3),
        (1.0, 1.0, Case.ABOVE_1B),  # (1+g^2)/(3g^2) = 2/3 <= 1 <= 5/3
        (3.0, -0.2, Case.BELOW_DELTA_POS),
        (3.0, -0.9, Case.BELOW_DELTA_NEG),
    ],
)
def test_case(gamma, kprime, case):
    p = Parameters(gamma, kprime)
    g2 = gamma**2
    # check the expected case by the report's definitions, not by the implementation
    if kprime >= 0:
        if kprime <= (1 + g2) / (3 * g2):
            expect = Case.ABOVE_1A
        elif kprime <= (4 + g2) / (3 * g2):
            expect = Case.ABOVE_1B
        else:
            expect = Case.ABOVE_2_3
    else:
        expect = Case.BELOW_DELTA_POS if -kprime <= (1 + g2) / (4 + g2) else Case.BELOW_DELTA_NEG
    assert p.case is expect
    assert p.case is case
    assert p.case.above == (kprime >= 0)


def test_cases_2_3_only_for_slender_blocks():
    for g in (0.5, 1.0, math.sqrt(2) - 1e-9):
        assert Parameters(g, 1.0).case is not Case.ABOVE_2_3
    assert Parameters(1.5, 1.0).case is Case.ABOVE_2_3


def test_threshold_ties_go_to_the_lower_case():
    g = 3.0
    p = Parameters(g, 0.0)
    assert Parameters(g, p.kprime_1).case is Case.ABOVE_1A
    assert Parameters(g, p.kprime_2).case is Case.ABOVE_1B
    assert Parameters(g, -p.kprime_delta).case is Case.BELOW_DELTA_POS


@pytest.mark.parametrize("gamma", [0, -1, float("nan"), float("inf"), "x", None, True])
def test_bad_gamma(gamma):
    with pytest.raises(ValueError, match="gamma"):
        Parameters(gamma, 0.1)


@pytest.mark.parametrize("kprime", [-1.01, 1.5, float("nan"), float("-inf"), "a"])
def test_bad_kprime(kprime):
    with pytest.raises(ValueError, match=r"kprime must be a number in \[-1, 1\]|kprime must be a number"):
        Parameters(1.0, kprime)


def test_negative_zero_is_zero():
    assert math.copysign(1, Parameters(1.0, -0.0).kprime) == 1.0


def test_as_dict_has_everything():
    d = Parameters(3.0, 0.4).as_dict()
    for key in ("gamma", "kprime", "case", "a", "b", "c", "d", "k_A", "mu_A", "k_Bprime",
                "mu_Bprime", "b_over_abs_a", "delta"):
        assert key in d
