"""Numbers for people (regimemap.records.numbers), against Python's own formatting and by brute force."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from regimemap.records.numbers import (
    format_significant,
    json_number,
    number,
    number_range,
    optional_float,
    round_sig,
    rounded,
    short,
    significant,
    text,
)

FINITE = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300)


@given(FINITE)
def test_round_sig_is_python_s_twelve_digits_and_never_a_negative_zero(v: float) -> None:
    r = round_sig(v)
    assert r == float(f"{v:.12g}")
    assert not (r == 0.0 and math.copysign(1.0, r) < 0)  # no -0.0
    assert str(round_sig(-0.0)) == "0.0"
    assert float(text(v)) == r


def test_the_examples_of_the_module() -> None:
    assert text(-0.5999999999999999) == "-0.6" and text(0.08250000000000002) == "0.0825"
    assert json_number(float("inf")) is None and json_number(float("nan")) is None
    assert round_sig(float("inf")) == float("inf") and math.isnan(round_sig(float("nan")))
    assert rounded({"a": [0.1 + 0.2, 3], "b": (True, None)}) == {"a": [0.3, 3], "b": [True, None]}


@pytest.mark.parametrize(("x", "digits", "written"), [
    (0.52, 4, "0.5200"), (26210.4, 4, "26210"), (1.0e12, 4, "1.000e+12"), (0.000123456, 3, "0.000123"),
    (-2.5, 2, "-2.5"), (1e-30, 4, "1.000e-30"), (0.0, 4, "0"), (-1e-300, 2, "-1.0e-300"),
    (float("inf"), 4, "n/a"), (float("-inf"), 4, "n/a"), (float("nan"), 4, "n/a"), (9999.7, 4, "10000"), (-99.996, 4, "-100.0"),
])
def test_format_significant_keeps_the_digits_it_states(x: float, digits: int, written: str) -> None:
    assert format_significant(x, digits) == written


@given(FINITE.filter(lambda v: v != 0.0 and 1e-200 < abs(v)), st.integers(1, 8))
def test_format_significant_is_within_half_a_unit_of_its_last_digit(x: float, digits: int) -> None:
    s = format_significant(x, digits)
    if s == "0":
        return
    unit = 10.0 ** (math.floor(math.log10(abs(x))) - digits + 1)
    assert abs(float(s) - x) <= 0.5 * unit * (1 + 1e-9) or abs(x) >= 10.0 ** digits


@given(FINITE, st.integers(1, 6))
def test_significant_is_format_significant_with_a_true_minus(x: float, digits: int) -> None:
    s = significant(x, digits)
    assert "-" not in s
    assert s.replace("\u2212", "-") == format_significant(x, digits)


def test_number_and_its_range_are_plain() -> None:
    assert number(0.25252) == "0.2525" and number(1.2e5, 2) == "1.2e+05" and number(1e-20, 2) == "1e-20"
    assert number(float("nan")) == "n/a" and number(float("-inf")) == "n/a" and number(float("inf")) == "n/a" and number(0.0) == "0"
    assert number_range([1.0, 1.00001]) == "1" and number_range([1.0, 2.0]) == "1 \u2026 2"
    assert number_range([float("nan")]) == "n/a"
    assert short(0.5) == "0.5" and short(1e-05) == "1e-05" and short(3.0) == "3"


def test_optional_float_makes_a_whole_number_a_float_and_keeps_none():
    import json

    import numpy as np

    assert optional_float(None) is None
    for v in (10, np.int64(10), np.float64(10.0), True):
        out = optional_float(v)
        assert type(out) is float and out == float(v)
    # the JSON of a file's whole number reads as a float, as the records write it
    assert json.dumps(rounded({"storms": optional_float(10), "kept": 10})) == '{"storms": 10.0, "kept": 10}'
