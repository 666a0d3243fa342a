"""Library validation: every bad input is a ValueError naming the parameter, the value and the range.

Covers :mod:`regimemap.mechanics.validation`, :class:`regimemap.Parameters`,
:func:`regimemap.maps.classify` and :func:`regimemap.label_grid`.
"""

from __future__ import annotations

import math
import time
import tracemalloc
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

from regimemap import Parameters, classify, label_grid
from regimemap.mechanics.validation import (
    GAMMA_MAX,
    GAMMA_MIN,
    MAX_AXIS,
    MAX_GRID_POINTS,
    MAX_RESOLUTION,
    MAX_VALUE,
    MIN_AXIS,
    check_axis,
    check_axis_end,
    check_gamma,
    check_kprime,
    check_nonnegative_array,
    check_positive,
    check_resolution,
    check_weight,
)

NAN = math.nan
INF = math.inf

# values that are not numbers where a scalar is expected
NOT_NUMBERS = ["3", "abc", "", b"3", None, True, False, np.True_, [1.0], [1.0, 2.0], (2.0,),
               np.array([3.0]), 1 + 0j, {"gamma": 3}, object()]


def _value_id(value: object) -> str:
    """repr without a memory address: every pytest-xdist worker must collect the same ids."""
    return "object()" if type(value) is object else repr(value)


# -- gamma -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bad", [0, 0.0, -0.0, -1, -1e-300, 5e-324, GAMMA_MIN / 2, GAMMA_MAX * 2,
                                 1e308, NAN, INF, -INF, np.float64(NAN), np.float32(-2.0)])
def test_gamma_out_of_range(bad):
    with pytest.raises(ValueError, match=r"^gamma must be a finite number in \[0\.001, 1000\], got ") as e:
        check_gamma(bad)
    assert repr(float(bad)) in str(e.value) or repr(bad) in str(e.value)


@pytest.mark.parametrize("bad", NOT_NUMBERS, ids=_value_id)
def test_gamma_not_a_number(bad):
    with pytest.raises(ValueError, match=r"^gamma must be a finite number in \[0\.001, 1000\], got .*not a number"):
        check_gamma(bad)


@pytest.mark.parametrize("good,expected", [(1, 1.0), (3.0, 3.0), (np.float32(2.0), 2.0),
                                           (np.int64(3), 3.0), (np.array(2.5), 2.5),
                                           (Fraction(3, 2), 1.5), (GAMMA_MIN, GAMMA_MIN),
                                           (GAMMA_MAX, GAMMA_MAX), (math.sqrt(2), math.sqrt(2))])
def test_gamma_accepted(good, expected):
    out = check_gamma(good)
    assert type(out) is float and out == expected


# -- kprime ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bad", [-1.0000001, 1.0000001, 2, -2, 1e308, NAN, INF, -INF, np.float64(NAN)])
def test_kprime_out_of_range(bad):
    with pytest.raises(ValueError, match=r"^kprime must be a number in \[-1, 1\], got "):
        check_kprime(bad)


@pytest.mark.parametrize("bad", NOT_NUMBERS, ids=_value_id)
def test_kprime_not_a_number(bad):
    with pytest.raises(ValueError, match=r"^kprime must be a number in \[-1, 1\], got .*not a number"):
        check_kprime(bad)


@pytest.mark.parametrize("good", [-1, -1.0, 1, 1.0, 0, 0.4, np.float32(0.5), np.int64(-1)])
def test_kprime_accepted(good):
    assert check_kprime(good) == float(good)


@pytest.mark.parametrize("tiny", [-0.0, 5e-324, -5e-324, 1e-310, -1e-301])
def test_kprime_negative_zero_and_subnormals_fold_to_zero(tiny):
    kp = check_kprime(tiny)
    assert kp == 0.0 and math.copysign(1.0, kp) == 1.0
    # and the derived quantities that divide by gamma*|k'| stay defined
    p = Parameters(0.5, tiny)
    assert p.k_D == math.inf and p.above


# -- Parameters --------------------------------------------------------------------------------------

@pytest.mark.parametrize("gamma,kprime,name", [(0, 0.4, "gamma"), (-3, 0.4, "gamma"), (NAN, 0, "gamma"),
                                               (INF, 0, "gamma"), ("3", 0, "gamma"), (None, 0, "gamma"),
                                               (True, 0, "gamma"), (3, 1.5, "kprime"),
                                               (3, NAN, "kprime"), (3, "0.4", "kprime"),
                                               (3, None, "kprime"), (3, [0.4], "kprime")])
def test_parameters_refuse(gamma, kprime, name):
    with pytest.raises(ValueError, match=f"^{name} must be"):
        Parameters(gamma, kprime)


# -- k, mu arrays ------------------------------------------------------------------------------------

@pytest.mark.parametrize("bad,shown", [(-1, "-1.0"), (-1e-300, "-1e-300"), (NAN, "nan"), (INF, "inf"),
                                       (-INF, "-inf"), (MAX_VALUE * 10, "1e+101"),
                                       ([0.1, -2.0], "-2.0 at index 1"),
                                       ([[0.1, 0.2], [NAN, 0.3]], "nan at index (1, 0)"),
                                       (np.array([1.0, INF]), "inf at index 1"),
                                       ("a", "'a'"), (None, "None"), (True, "True"),
                                       ([True, False], "True"), ([1, None], "None"),
                                       ([1, "2"], "'2'"), ([1, 2 + 1j], "(1+0j)"),
                                       ([[1, 2], [3]], "[[1, 2], [3]]")])
def test_nonnegative_array_refuses(bad, shown):
    with pytest.raises(ValueError, match=r"^k must be finite numbers >= 0 \(at most 1e\+100\), got ") as e:
        check_nonnegative_array("k", bad)
    assert shown in str(e.value)
    assert "np.float64" not in str(e.value)  # plain numbers in messages


@pytest.mark.parametrize("good", [0, 0.0, -0.0, [0.0, 1.0], [[1, 2], [3, 4]], np.arange(5),
                                  np.array([], dtype=float), [], [Fraction(1, 2), Decimal("0.3")],
                                  np.float32(2.0), np.uint8(3), MAX_VALUE])
def test_nonnegative_array_accepts(good):
    out = check_nonnegative_array("mu", good)
    assert out.dtype == np.float64
    assert out.shape == np.shape(np.asarray(good, dtype=float))


@pytest.mark.parametrize("name", ["k", "mu"])
@pytest.mark.parametrize("bad", [-0.5, NAN, INF, -INF, "x", None, 1e101])
def test_classify_refuses_bad_k_and_mu_naming_them(name, bad):
    args = {"k": 0.5, "mu": 0.5, "gamma": 3.0, "kprime": 0.4}
    args[name] = bad
    with pytest.raises(ValueError, match=f"^{name} must be finite numbers >= 0"):
        classify(**args)
    args[name] = [0.1, bad, 0.2]
    with pytest.raises(ValueError, match=f"^{name} must be finite numbers >= 0"):
        classify(**args)


@pytest.mark.parametrize("gamma,kprime,match", [(0, 0.4, "gamma"), (-1, 0.4, "gamma"), (NAN, 0.4, "gamma"),
                                                ("3", 0.4, "gamma"), (True, 0.4, "gamma"),
                                                (3, 1.5, "kprime"), (3, NAN, "kprime"), (3, -INF, "kprime"),
                                                ([3.0, -1.0], 0.4, "gamma"), ([3.0, NAN], 0.4, "gamma"),
                                                (3.0, [0.4, 1.01], "kprime")])
def test_classify_refuses_bad_parameters(gamma, kprime, match):
    with pytest.raises(ValueError, match=f"^{match} must be"):
        classify([0.1, 0.2], [0.3, 0.4], gamma, kprime)


@pytest.mark.parametrize("gamma,kprime", [(None, 0.4), (3.0, None)])
def test_classify_none_parameter_is_named_as_none(gamma, kprime):
    with pytest.raises(ValueError, match="got None"):
        classify(0.1, 0.2, gamma, kprime)


def test_classify_gamma_array_out_of_range():
    """Array-valued gamma is held to the range of check_gamma (1e-200 would give inf/nan constants)."""
    with pytest.raises(ValueError, match="^gamma must be"):
        classify(0.1, 0.2, [3.0, 1e-200], 0.4)
    with pytest.raises(ValueError, match="^gamma must be"):
        classify(0.1, 0.2, np.array([3.0, 1e300]), 0.4)


def test_classify_shape_mismatch_names_the_arguments():
    with pytest.raises(ValueError, match=r"k .*mu|k, mu"):
        classify([0.1, 0.2, 0.3], [0.5, 0.6], 3.0, 0.4)


def test_classify_scalar_and_empty():
    assert classify(0.1, 0.5, 3.0, 0.4).shape == ()
    assert classify([], [], 3.0, 0.4).shape == (0,)
    assert classify(np.empty((0, 3)), 0.5, 3.0, 0.4).shape == (0, 3)


# -- label_grid axes ---------------------------------------------------------------------------------

@pytest.mark.parametrize("axis,match", [
    ([[0.1, 0.2]], r"k_axis must be a 1-D array, got an array of shape \(1, 2\)"),
    (np.zeros((2, 2)), r"k_axis must be a 1-D array, got an array of shape \(2, 2\)"),
    (0.5, r"k_axis must be a 1-D array, got an array of shape \(\)"),
    ([0.1, NAN], r"k_axis must be finite numbers >= 0 .*got nan at index 1"),
    ([0.1, INF], r"k_axis must be finite numbers >= 0 .*got inf at index 1"),
    ([0.1, -0.2], r"k_axis must be finite numbers >= 0 .*got -0.2 at index 1"),
    (["a", "b"], r"k_axis must be finite numbers >= 0 .*not a number"),
])
def test_label_grid_bad_k_axis(axis, match):
    with pytest.raises(ValueError, match=match):
        label_grid(axis, [0.1, 0.2], 3.0, 0.4)
    with pytest.raises(ValueError, match=match.replace("k_axis", "mu_axis")):
        label_grid([0.1, 0.2], axis, 3.0, 0.4)


@pytest.mark.parametrize("gamma,kprime,match", [(0, 0.4, "gamma"), ([3.0], 0.4, "gamma"),
                                                (3.0, 2.0, "kprime"), (3.0, [0.4], "kprime")])
def test_label_grid_bad_parameters(gamma, kprime, match):
    with pytest.raises(ValueError, match=f"^{match} must be"):
        label_grid([0.1], [0.1], gamma, kprime)


def _refused_fast(k_axis, mu_axis, match):
    tracemalloc.start()
    t0 = time.process_time()  # CPU time: another process keeping the cores busy does not count
    try:
        with pytest.raises(ValueError, match=match):
            label_grid(k_axis, mu_axis, 3.0, 0.4)
        elapsed = time.process_time() - t0
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert elapsed < 0.5, f"took {elapsed:.2f} s to refuse"
    assert peak < 20_000_000, f"allocated {peak / 1e6:.0f} MB before refusing"


def test_label_grid_huge_axis_refused_before_allocating():
    huge = np.broadcast_to(np.float64(0.5), (10**9,))  # 8 GB if it were real; costs nothing
    _refused_fast(huge, [0.1, 0.2], r"k_axis has 1000000000 values, more than the limit of 25000000")
    _refused_fast([0.1, 0.2], huge, r"mu_axis has 1000000000 values")


def test_label_grid_too_many_points_refused_before_allocating():
    # each axis is fine on its own, the grid is not: 10^4 x 10^4 = 10^8 > MAX_GRID_POINTS
    side = np.broadcast_to(np.float64(0.5), (10**4,))
    _refused_fast(side, side, r"grid of 10000 x 10000 points exceeds the limit of 25000000 points")


def test_label_grid_at_the_limit_is_accepted():
    # exactly MAX_GRID_POINTS would be 25 MB: check the boundary with a cheap count instead
    k = np.linspace(0, 1, 5000)
    mu = np.linspace(0, 1, MAX_GRID_POINTS // 5000 + 1)
    with pytest.raises(ValueError, match="exceeds the limit"):
        label_grid(k, mu, 3.0, 0.4)
    out = label_grid(k[:10], mu, 3.0, 0.4)
    assert out.shape == (mu.size, 10)


def test_label_grid_empty_axes():
    assert label_grid([], [0.1], 3.0, 0.4).shape == (1, 0)
    assert label_grid([0.1], [], 3.0, 0.4).shape == (0, 1)


def test_check_axis_accepts_lists_and_views():
    assert check_axis("k", [0, 1, 2]).tolist() == [0.0, 1.0, 2.0]
    v = np.broadcast_to(np.float64(1.0), (7,))
    assert check_axis("k", v).shape == (7,)
    with pytest.raises(ValueError, match="more than the limit of 3"):
        check_axis("k", [1, 2, 3, 4], max_size=3)


# -- positive numbers and resolutions ----------------------------------------------------------------

@pytest.mark.parametrize("bad", [0, -0.0, -1, NAN, INF, -INF, 1e101, 1e308, "1", None, True, [1.0]])
def test_check_positive(bad):
    with pytest.raises(ValueError, match=r"^k_max must be a finite number > 0 \(at most 1e\+100\), got "):
        check_positive("k_max", bad)


@pytest.mark.parametrize("good", [1e-300, 1, 2.5, np.float32(3), MAX_VALUE])
def test_check_positive_accepts(good):
    assert check_positive("mu_max", good) == float(good)


@pytest.mark.parametrize("bad", [0, 1e-20, np.nextafter(MIN_AXIS, 0), np.nextafter(MAX_AXIS, INF), NAN, INF,
                                 "1", None])
def test_check_axis_end(bad):
    with pytest.raises(ValueError, match=r"^mu_max must be a finite number in \[1e-06, 1e\+06\], got "):
        check_axis_end("mu_max", bad)


@pytest.mark.parametrize("good", [MIN_AXIS, 1e-3, 1, MAX_AXIS])
def test_check_axis_end_accepts_its_ends(good):
    assert check_axis_end("k_max", good) == good


# -- a block that weighs nothing at every push -------------------------------------------------------

@pytest.mark.parametrize("buoyancy,uplift", [(0.0, 1.0), (0.5, 0.5), (0.3, 0.7), (0.25, 0.75)])
def test_a_weightless_block_is_refused_naming_the_sum(buoyancy, uplift):
    assert 1.0 - buoyancy - uplift == 0.0
    with pytest.raises(ValueError, match=r"^uplift must not be 1 - buoyancy when uplift_ratio is 0: .* = 1$"):
        Parameters(3.0, 0.4, buoyancy=buoyancy, uplift=uplift)


@pytest.mark.parametrize("loads", [dict(uplift=1.0, uplift_ratio=0.1), dict(uplift=np.nextafter(1.0, 0)),
                                   dict(uplift=2.0), dict(buoyancy=0.5, uplift=0.4)])
def test_a_block_with_some_weight_or_an_uplift_ratio_is_mapped(loads):
    p = Parameters(3.0, 0.4, **loads)
    check_weight(p.buoyancy, p.uplift, p.uplift_ratio)
    from regimemap.mechanics.curves import map_curves

    assert map_curves(p)  # the curves of the map (mu = (q0 + q1 k)/W) exist
    grid = label_grid(np.linspace(0.0, 2.0, 9), np.linspace(0.0, 2.0, 9), p.gamma, p.kprime, **p.loads)
    assert grid.shape == (9, 9)


@pytest.mark.parametrize("bad", [1, 0, -5, MAX_RESOLUTION + 1, 10**12, 2.5, NAN, INF, 1e300, "1e3", "2.0",
                                 "", "abc", "٣", None, True, [100], np.float64(3.5)])
def test_check_resolution_refuses(bad):
    with pytest.raises(ValueError, match=rf"^resolution must be a whole number in \[2, {MAX_RESOLUTION}\], got "):
        check_resolution("resolution", bad)


@pytest.mark.parametrize("good,n", [(2, 2), (MAX_RESOLUTION, MAX_RESOLUTION), (401.0, 401), ("401", 401),
                                    (" 7 ", 7), ("+7", 7), (np.int64(9), 9), (np.float64(9.0), 9)])
def test_check_resolution_accepts(good, n):
    out = check_resolution("resolution", good)
    assert type(out) is int and out == n


def test_messages_are_one_line_and_short():
    for f, v in ((check_gamma, "x" * 10_000), (check_kprime, list(range(10_000))),
                 (lambda v: check_nonnegative_array("k", v), "y" * 10_000)):
        with pytest.raises(ValueError) as e:
            f(v)
        msg = str(e.value)
        assert "\n" not in msg and len(msg) < 200, msg
