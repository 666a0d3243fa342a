"""The ``[lifetime]`` table of the design file: the example, the defaults, and every refusal
with the file, the key, its line, the value and what is accepted."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import pytest

from regimemap.caisson.file import (
    ERROR_FACTORS,
    LIFETIME_KEYS,
    MAX_TRIALS,
    DesignFileError,
    check_lifetime_option,
    example_design_text,
    key_line,
    parse_design,
    read_design,
)
from regimemap.climate.life import climate_of_maxima
from regimemap.lifetime import DEFAULT_ERRORS, DEFAULT_THRESHOLDS, Climate, ErrorFactor

from ._cases import GODA

EXAMPLE = example_design_text()
SOURCE = "breakwater.toml"


def edit(text: str, old: str, new: str) -> str:
    """Replace the one whole line ``old`` (up to its comment) by ``new``."""
    pattern = re.compile(rf"^{re.escape(old)}[ \t]*(#.*)?$", re.MULTILINE)
    out, n = pattern.subn(lambda _: new, text)
    assert n == 1, old
    return out


def line_of(text: str, start: str) -> int:
    """The line (from 1) of the one line that starts with ``start``, past the keys of [caisson]."""
    lines = text.splitlines()
    first = max(i for i, ln in enumerate(lines, 1) if ln.startswith("buoyant_weight ="))
    found = [i for i, ln in enumerate(lines, 1) if ln.startswith(start) and i > first]
    assert len(found) == 1, (start, found)
    return found[0]


def error_of(text: str) -> str:
    with pytest.raises(DesignFileError) as info:
        parse_design(text, SOURCE)
    msg = str(info.value)
    assert "\n" not in msg
    return msg


# -- the example ------------------------------------------------------------------------------------


def test_the_example_has_goda_s_climate_and_the_default_errors(tmp_path: Path) -> None:
    path = tmp_path / "goda.toml"
    path.write_text(EXAMPLE, encoding="utf-8")
    d = read_design(path)
    spec = d.lifetime
    assert spec is not None
    assert (spec.years, spec.trials, spec.seed, spec.H0_10, spec.H0_50) == (50, 5000, 2026, 5.0, 6.3)
    assert spec.distribution == "weibull" and spec.shape == 2.0 and spec.annual_maxima is None
    model = d.lifetime_model()
    assert model.climate == Climate.from_return_values(5.0, 6.3)
    assert round(model.climate.return_value(10), 12) == 5.0
    assert round(model.climate.return_value(50), 12) == 6.3
    assert model.errors == DEFAULT_ERRORS  # written out in the example, equal to the defaults
    assert model.years == 50 and model.storm_hours == 2.0 and model.period is None
    assert model.steepness is None and model.tide_range == 0.0 and model.truncate is None
    assert model.impulsive is False and model.thresholds == DEFAULT_THRESHOLDS
    assert d.lifetime_caisson() == GODA  # W' in N/m, the berm, the wave angle
    # the options the file leaves to the command line
    assert d.lifetime_model(years=20).years == 20
    with pytest.raises(ValueError, match=r"years must be .*1 <= years <= 1000.*got 0"):
        d.lifetime_model(years=0)


def test_every_key_of_the_example_is_commented() -> None:
    body = EXAMPLE[EXAMPLE.index("[lifetime]"):]
    for key in [*LIFETIME_KEYS, *ERROR_FACTORS]:
        if key == "errors":
            continue
        lines = [ln for ln in body.splitlines() if re.match(rf"^#? ?{key} = ", ln)]
        assert len(lines) == 1, key
        assert "#" in lines[0].split("=", 1)[1], key


def test_the_example_s_errors_follow_the_library_s_defaults(monkeypatch: pytest.MonkeyPatch) -> None:
    import regimemap.lifetime as lifetime

    changed = lifetime.Errors(force=ErrorFactor(0.8, 0.2))
    monkeypatch.setattr(lifetime, "DEFAULT_ERRORS", changed)
    assert "force = [0.8, 0.2]" in example_design_text()


def test_a_file_without_lifetime_is_read_and_says_where_to_find_one() -> None:
    text = EXAMPLE[:EXAMPLE.index("# Optional: the sliding")]
    d = parse_design(text, SOURCE)
    assert d.lifetime is None
    assert d.analysis_inputs() == parse_design(EXAMPLE).analysis_inputs()
    with pytest.raises(DesignFileError, match=r"breakwater.toml: no \[lifetime\] table.*"
                                               r"`regimemap caisson --example`"):
        d.lifetime_model()


def test_only_the_climate_is_required() -> None:
    d = parse_design(EXAMPLE[:EXAMPLE.index("# Optional: the sliding")] + "[lifetime]\nH0_10 = 5\nH0_50 = 6.3\n")
    spec = d.lifetime
    assert spec is not None and spec.trials == 5000 and spec.years == 50 and spec.seed is None
    m = d.lifetime_model()
    assert m.errors == DEFAULT_ERRORS and m.thresholds == DEFAULT_THRESHOLDS and not m.impulsive


def test_defaults_fill_the_factors_left_out() -> None:
    text = edit(EXAMPLE, "force = [0.91, 0.17]", "")
    text = edit(text, "deepwater = [1.0, 0.1]", "deepwater = [1.1, 0.3]")
    errors = parse_design(text).lifetime_model().errors
    assert errors.deepwater == ErrorFactor(1.1, 0.3)
    assert errors.force == DEFAULT_ERRORS.force
    assert errors.transformation == DEFAULT_ERRORS.transformation
    assert errors.friction == DEFAULT_ERRORS.friction
    # no [lifetime.errors] at all: every default
    bare = EXAMPLE[:EXAMPLE.index("[lifetime.errors]")]
    assert parse_design(bare).lifetime_model().errors == DEFAULT_ERRORS


def test_the_other_options_reach_the_model() -> None:
    text = edit(EXAMPLE, "storm_hours = 2.0", "storm_hours = 3\nperiod = 11.4\nthresholds = [1, 0.1, 0.1]")
    text = edit(text, "thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]", "truncate = 2.5")
    text = edit(text, "tide_range = 0.0", "tide_range = 1.5")
    text = edit(text, "impulsive = false", "impulsive = true")
    m = parse_design(text).lifetime_model()
    assert (m.storm_hours, m.period, m.tide_range, m.truncate, m.impulsive) == (3.0, 11.4, 1.5, 2.5, True)
    assert m.thresholds == (0.1, 1.0)  # sorted, each once
    text = edit(EXAMPLE, "storm_hours = 2.0", "steepness = 0.04")
    assert parse_design(text).lifetime_model().steepness == 0.04


def test_annual_maxima_and_other_climates() -> None:
    maxima = [4.1, 3.6, 5.2, 4.4, 3.9, 4.8]
    text = edit(EXAMPLE, "H0_10 = 5.0", f"annual_maxima = {maxima}")
    text = edit(text, "H0_50 = 6.3", "")
    c = parse_design(text).lifetime_model().climate
    assert c == climate_of_maxima(maxima, "weibull", 2.0)
    gumbel = edit(text, 'distribution = "weibull"', 'distribution = "gumbel"')
    assert parse_design(gumbel).lifetime_model().climate == climate_of_maxima(maxima, "gumbel")
    poisson = edit(EXAMPLE, "H0_10 = 5.0", "H0_10 = 5.0\nstorms_per_year = 4")
    c = parse_design(poisson).lifetime_model().climate
    assert c.storms_per_year == 4.0 and round(c.return_value(50), 12) == 6.3


# -- refusals: the key, its table, its line, the value, what is accepted ------------------------------

#: (line of the example, its replacement, the start of the reported line, expected parts of the message)
REFUSED = [
    ("shape = 2.0", "shape = 0", "shape =", ["[lifetime] shape = 0", "out of range", "Weibull shape 0.5 <= k <= 5"]),
    ("shape = 2.0", "shape = -1.5", "shape =", ["[lifetime] shape = -1.5", "0.5 <= k <= 5"]),
    ("shape = 2.0", "shape = 1e308", "shape =", ["[lifetime] shape = 1e308", "out of range", "0.5 <= k <= 5"]),
    ("shape = 2.0", "shape = 1e-300", "shape =", ["[lifetime] shape = 1e-300", "out of range"]),
    # one sliding twice (as 0.30 and 0.3): one of its two requirements would be dropped unsaid
    ('# allowed = {"0.1" = 0.2, "0.3" = 0.05}', 'allowed = {"0.1" = 0.2, "0.30" = 0.05, "0.3" = 0.1}', "allowed =",
     ["[lifetime] allowed = ", "the sliding '0.3' is given twice (also as '0.30')"]),
    ("shape = 2.0", 'shape = "2"', "shape =", ['[lifetime] shape = "2"', "expected a number, found a string"]),
    ("H0_50 = 6.3", "H0_50 = 5.0", "H0_50 =",
     ["[lifetime] H0_50 = 5.0", "not above [lifetime] H0_10 = 5.0", "H0_10 < H0_50"]),
    ("H0_50 = 6.3", "H0_50 = 4", "H0_50 =", ["[lifetime] H0_50 = 4", "not above"]),
    ("H0_10 = 5.0", "H0_10 = -5.0", "H0_10 =", ["[lifetime] H0_10 = -5.0", "not > 0", "0 < H0_10 <= 30 m"]),
    # hard physical limits: errors without --strict, naming the limit and why
    ("H0_50 = 6.3", "H0_50 = 1e300", "H0_50 =",
     ["[lifetime] H0_50 = 1e300:", "above 30 m, higher than any sea measured", "about 20 m"]),
    ("H0_50 = 6.3", "H0_50 = 630", "H0_50 =",
     ["[lifetime] H0_50 = 630", "above 30 m", "6.3 m in centimetres for metres?"]),
    ("H0_10 = 5.0", "H0_10 = 500", "H0_10 =", ["[lifetime] H0_10 = 500", "above 30 m"]),
    ("H0_10 = 5.0", "annual_maxima = [4.1, 36.0, 5.2]", "annual_maxima =",
     ["[lifetime] annual_maxima = [4.1, 36.0, 5.2]", "36.0 in the list is above 30 m"]),
    ("storm_hours = 2.0", "period = 114", "period =",
     ["[lifetime] period = 114", "above 30 s", "11.4 s in tenths of a second?", "1 <= T1/3 <= 30 s"]),
    ("storm_hours = 2.0", "period = 0.09", "period =", ["[lifetime] period = 0.09", "below 1 s"]),
    ("tide_range = 0.0", "tide_range = 150", "tide_range =", ["[lifetime] tide_range = 150", "Bay of Fundy"]),
    ("H0_10 = 5.0", "H0_10 = 5.0\nstorms_per_year = 1000", "storms_per_year =",
     ["[lifetime] storms_per_year = 1000", "<= 365"]),
    ("storm_hours = 2.0", "storm_hours = 1000", "storm_hours =", ["[lifetime] storm_hours = 1000", "<= 168"]),
    # the requirements
    ("target = 0.1", "target = 0", "target =", ["[lifetime] target = 0", "ESD <= target"]),
    ("target = 0.1", "allowed = 0.2", "allowed =", ["[lifetime] allowed = 0.2", "expected a table"]),
    ("target = 0.1", 'allowed = {"0.1" = 1.5}', "allowed =", ["the probability 1.5 of 0.1 m is not in [0, 1]"]),
    ("target = 0.1", 'allowed = {"-1" = 0.5}', "allowed =", ["the sliding '-1' is not > 0 m"]),
    ("target = 0.1", 'allowed = {"a" = 0.5}', "allowed =", ["the key 'a' is not a sliding distance"]),
    ("target = 0.1", "failure_sliding = -2", "failure_sliding =", ["[lifetime] failure_sliding = -2", "off its mound"]),
    ("trials = 5000", "trials = 0", "trials =", ["[lifetime] trials = 0", "out of range", "1 <= trials"]),
    ("trials = 5000", f"trials = {MAX_TRIALS + 1}", "trials =", [f"trials = {MAX_TRIALS + 1}", "out of range"]),
    ("trials = 5000", "trials = 5000.0", "trials =", ["expected a whole number, found a float"]),
    ("trials = 5000", 'trials = "5000"', "trials =", ["expected a whole number, found a string"]),
    ("years = 50", "years = 0", "years =", ["[lifetime] years = 0", "1 <= years <= 1000"]),
    ("years = 50", "years = true", "years =", ["[lifetime] years = true", "expected a whole number, found a boolean"]),
    ("seed = 2026", "seed = -1", "seed =", ["[lifetime] seed = -1", "a whole number >= 0"]),
    ("seed = 2026", "seed = 1.5", "seed =", ["[lifetime] seed = 1.5", "expected a whole number"]),
    ('distribution = "weibull"', 'distribution = "normal"', "distribution =",
     ['[lifetime] distribution = "normal"', "not one of the accepted values", '"weibull" or "gumbel"']),
    ('distribution = "weibull"', "distribution = 1", "distribution =", ["expected a string, found an integer"]),
    ("storm_hours = 2.0", "storm_hours = 0", "storm_hours =", ["[lifetime] storm_hours = 0", "hours"]),
    ("storm_hours = 2.0", "storm_hours = inf", "storm_hours =", ["storm_hours = inf", "not a finite number"]),
    ("tide_range = 0.0", "tide_range = -1", "tide_range =", ["[lifetime] tide_range = -1", "0 <= tide_range"]),
    ("tide_range = 0.0", "tide_range = nan", "tide_range =", ["tide_range = nan", "not a finite number"]),
    ("thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]", "thresholds = [0.1, -3]", "thresholds =",
     ["[lifetime] thresholds = [0.1, -3]", "-3 in the list is out of range", "each > 0 in metres"]),
    ("thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]", "thresholds = []", "thresholds =", ["the list is empty"]),
    ("thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]", "thresholds = 0.1", "thresholds =",
     ["expected a list of numbers, found a float"]),
    ("thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]", 'thresholds = [0.1, "1 m"]', "thresholds =",
     ["expected numbers, found '1 m' in the list is a string"]),
    ("impulsive = false", "impulsive = 0", "impulsive =", ["[lifetime] impulsive = 0", "expected true or false"]),
    ("storm_hours = 2.0", "truncate = 0", "truncate =", ["[lifetime] truncate = 0", "standard deviations"]),
    ("storm_hours = 2.0", "steepness = 0.2", "steepness =", ["[lifetime] steepness = 0.2", "0 < H0'/L0 <= 0.142"]),
    ("storm_hours = 2.0", "period = -3", "period =", ["[lifetime] period = -3", "1 <= T1/3 <= 30 s"]),
    ("storm_hours = 2.0", "period = 10\nsteepness = 0.03", "steepness =",
     ["[lifetime] steepness = 0.03 together with [lifetime] period = 10"]),
    ("H0_10 = 5.0", "H0_10 = 5.0\nstorms_per_year = 0.05", "storms_per_year =",
     ["[lifetime] storms_per_year = 0.05", "0.1 < storms_per_year"]),
    ("H0_10 = 5.0", "H0_10 = 5.0\nannual_maxima = [4.1, 3.6, 5.2]", "annual_maxima =",
     ["[lifetime] annual_maxima together with H0_10", "either H0_10 and H0_50"]),
    ("H0_50 = 6.3", "", "H0_10 =", ["[lifetime] H0_50 is missing (H0_10 = 5.0 is given)"]),
    ("years = 50", "yeras = 50", "yeras =",
     ["unknown key [lifetime] yeras (did you mean 'years'?)", "accepted keys in [lifetime]: years, trials"]),
    ("years = 50", "colour = 3", "colour =", ["unknown key [lifetime] colour;", "accepted keys in [lifetime]"]),
    ("years = 50", "h0_10 = 3", "h0_10 =", ["unknown key [lifetime] h0_10 (did you mean 'H0_10'?)"]),
    # [lifetime.errors]
    ("force = [0.91, 0.17]", "force = [0.91, -0.1]", "force =",
     ["[lifetime.errors] force = [0.91, -0.1]", "the cov -0.1 is < 0", "ratio > 0 and cov >= 0"]),
    ("friction = [1.06, 0.15]", "friction = [0, 0.1]", "friction =",
     ["[lifetime.errors] friction = [0, 0.1]", "the ratio 0 is not > 0"]),
    ("deepwater = [1.0, 0.1]", "deepwater = [1.0]", "deepwater =",
     ["[lifetime.errors] deepwater = [1.0]", "expected [ratio, cov], found a list of 1"]),
    ("deepwater = [1.0, 0.1]", "deepwater = 1.0", "deepwater =", ["expected [ratio, cov], found a float"]),
    ("deepwater = [1.0, 0.1]", 'deepwater = [1.0, "0.1"]', "deepwater =", ["'0.1' is not a finite number"]),
    ("force = [0.91, 0.17]", "forse = [0.91, 0.17]", "forse =",
     ["unknown key [lifetime.errors] forse (did you mean 'force'?)",
      "accepted keys in [lifetime.errors]: deepwater, transformation, force, friction"]),
    ("[lifetime.errors]", "[lifetime.error]", "[lifetime.error]",
     ["unknown key [lifetime] error (did you mean 'errors'?)"]),
]


@pytest.mark.parametrize(("old", "new", "at", "parts"), REFUSED, ids=[r[1].split("\n")[-1] for r in REFUSED])
def test_refused_with_the_key_and_its_line(old: str, new: str, at: str, parts: list[str]) -> None:
    text = edit(EXAMPLE, old, new)
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, at)}: "), msg
    for part in parts:
        assert part in msg, (part, msg)
    if "unknown key" not in msg and "together with" not in msg and "missing" not in msg:
        assert "; accepted: " in msg, msg


def test_the_requirements_are_read() -> None:
    spec = parse_design(EXAMPLE).lifetime_spec()
    assert (spec.target, dict(spec.allowed), spec.failure_sliding) == (0.1, {}, None)
    # TOML reads a bare key 0.1 as the dotted key 0 . 1: read back as 0.1
    text = edit(EXAMPLE, "target = 0.1", "target = 0.05\nallowed = {0.1 = 0.2, \"3\" = 0.01}\nfailure_sliding = 5")
    spec = parse_design(text).lifetime_spec()
    assert spec.target == 0.05 and dict(spec.allowed) == {0.1: 0.2, 3.0: 0.01}
    assert spec.failure_sliding == 5.0


def test_the_climate_is_echoed_as_written() -> None:
    assert parse_design(EXAMPLE).lifetime_spec().climate_as_written() == "H0_10 = 5.0 m, H0_50 = 6.3 m"
    text = edit(edit(EXAMPLE, "H0_10 = 5.0", "H0_10 = 5"), "H0_50 = 6.3", "H0_50 = 6.30")
    assert parse_design(text).lifetime_spec().climate_as_written() == "H0_10 = 5 m, H0_50 = 6.3 m"


def test_a_climate_fit_that_overflows_is_named() -> None:
    from regimemap.lifetime.file import LifetimeSpec, lifetime_model

    spec = LifetimeSpec(H0_10=1e-300, H0_50=30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no numpy RuntimeWarning on the way
        try:
            lifetime_model(spec)
        except ValueError as exc:
            assert "cannot be computed" in str(exc)


def test_a_file_with_a_bad_lifetime_is_refused_by_caisson_too(tmp_path: Path) -> None:
    path = tmp_path / "goda.toml"
    path.write_text(edit(EXAMPLE, "shape = 2.0", "shape = -1"), encoding="utf-8")
    with pytest.raises(DesignFileError, match=rf"^{re.escape(str(path))}, line \d+: \[lifetime\] shape = -1"):
        read_design(path)


def test_no_climate_names_the_table_s_line() -> None:
    text = edit(edit(EXAMPLE, "H0_10 = 5.0", ""), "H0_50 = 6.3", "")
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, '[lifetime]')}: [lifetime] has no wave climate")
    assert "either H0_10 and H0_50" in msg and "or annual_maxima" in msg


@pytest.mark.parametrize(("maxima", "why"), [
    ("[4.0, 5.0]", "2 values, fewer than three"),
    ("[4.0, 4.0, 4.0]", "the values are all equal"),
    ("[4.0, 0, 5.0]", "0 in the list is not > 0"),
])
def test_refused_annual_maxima(maxima: str, why: str) -> None:
    text = edit(edit(EXAMPLE, "H0_10 = 5.0", f"annual_maxima = {maxima}"), "H0_50 = 6.3", "")
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, 'annual_maxima')}: [lifetime] annual_maxima = ")
    assert why in msg and "at least three annual maxima" in msg


def test_annual_maxima_with_storms_per_year_or_a_small_shape() -> None:
    text = edit(edit(EXAMPLE, "H0_10 = 5.0", "annual_maxima = [4.1, 3.6, 5.2]\nstorms_per_year = 3"),
                "H0_50 = 6.3", "")
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, 'storms_per_year')}: [lifetime] storms_per_year = 3 "
                          "together with annual_maxima")
    text = edit(edit(EXAMPLE, "H0_10 = 5.0", "annual_maxima = [4.1, 3.6, 5.2]"), "H0_50 = 6.3", "")
    text = edit(text, "shape = 2.0", "shape = 1.0")
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, 'shape')}: [lifetime] shape = 1.0: fitting")
    assert "needs k > 1" in msg


def test_lines_of_dotted_and_inline_keys() -> None:
    base = EXAMPLE[:EXAMPLE.index("# Optional: the sliding")]
    text = base + "[lifetime]\nH0_10 = 5\nH0_50 = 6\nerrors.force = [0.9, -1]\n"
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, 'errors.force')}: [lifetime.errors] force")
    text = base + "[lifetime]\nH0_10 = 5\nH0_50 = 6\nerrors = { friction = [0.9, -1] }\n"
    msg = error_of(text)
    assert msg.startswith(f"{SOURCE}, line {line_of(text, 'errors =')}: [lifetime.errors] friction")
    text = "lifetime.shape = -2\nlifetime.H0_10 = 5\nlifetime.H0_50 = 6\n" + base
    assert error_of(text).startswith(f"{SOURCE}, line 1: [lifetime] shape = -2")
    text = base + '[ "lifetime" ]\n"H0_10" = 5\nH0_50 = 6\n  shape   =   -3  # comment\n'
    assert error_of(text).startswith(f"{SOURCE}, line {line_of(text, '  shape')}: [lifetime] shape = -3")


def test_key_line_helper() -> None:
    text = "[site]\nshape = 1\n[lifetime]\n# shape = 2\nyears = 3\n\n[lifetime.errors]\nforce = [1, 2]\n"
    assert key_line(text, "lifetime", "years") == 5
    assert key_line(text, "lifetime", "shape") == 3  # not set in [lifetime]: its header
    assert key_line(text, "lifetime", "errors") == 7
    assert key_line(text, "lifetime.errors", "force") == 8
    assert key_line(text, "lifetime") == 3
    assert key_line("[site]\n", "lifetime", "years") is None


def test_command_line_values_are_checked_as_the_file_s() -> None:
    assert check_lifetime_option("trials", "300") == 300
    assert check_lifetime_option("seed", 7) == 7
    assert check_lifetime_option("years", "20") == 20
    for name, text, why in (("trials", "0", "1 <= trials <= 10000000"), ("trials", "abc", "not a whole number"),
                            ("trials", "1e3", "not a whole number"), ("seed", "-1", "whole number >= 0"),
                            ("years", "nan", "not a whole number"), ("years", "1001", "years <= 1000")):
        with pytest.raises(ValueError, match=re.escape(why)) as info:
            check_lifetime_option(name, text)
        assert str(info.value).startswith(f"{name} must be ") and repr(text) in str(info.value)


def test_each_lifetime_key_is_declared_once_as_a_field():
    """LIFETIME_KEYS is read from LifetimeSpec's fields (every field but ``written``, in order), each
    key's default is its field's, and where its words name a default they name that one
    (``climate_replicates`` says 50, the default with a [lifetime.record]: without one it is 0)."""
    import dataclasses
    import re

    from regimemap.io.toml_keys import default_of
    from regimemap.lifetime.file_keys import LifetimeSpec

    names = [f.name for f in dataclasses.fields(LifetimeSpec)]
    assert names == [*LIFETIME_KEYS, "written"]
    plain = LifetimeSpec()
    said = 0
    for key, spec in LIFETIME_KEYS.items():
        assert default_of(LifetimeSpec, key) == getattr(plain, key), key
        m = re.search(r"default ([0-9.]+)\b", spec.accepted)
        if m and key != "climate_replicates":
            assert float(m.group(1)) == default_of(LifetimeSpec, key), key
            said += 1
    assert said >= 6  # years, trials, shape, storm_hours, tide_range, target
    # the example's [lifetime] is the keys' lines, each naming its key, in the order declared
    from regimemap.io.toml_keys import example_table

    text = example_table("lifetime", LifetimeSpec)
    assert text in example_design_text()
    shown = [key for key, spec in LIFETIME_KEYS.items() if spec.example]
    assert [re.match(r"(?:# )?([A-Za-z0-9_]+) = ", line).group(1)
            for line in text.splitlines()[1:] if not line.startswith(" ")] == shown
    assert set(LIFETIME_KEYS) - set(shown) == {"errors"}  # its own table, [lifetime.errors]
