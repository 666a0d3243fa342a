"""No wrong number written: a lifetime result that is not finite is an error, and numpy stays quiet."""

from __future__ import annotations

import warnings
from dataclasses import replace

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text
from regimemap.lifetime.finite import NonFiniteResult, quiet_arithmetic, require_finite


def test_require_finite_names_what_where_and_how_many():
    require_finite("the ESD", np.zeros((2, 3)))
    require_finite("the ESD", [])
    with pytest.raises(NonFiniteResult) as err:
        require_finite("the lifetime sliding", [1.0, np.inf, np.nan, np.inf], "section 'a'")
    assert str(err.value) == ("section 'a': the lifetime sliding is not finite (inf in 2 of 4 values, nan in 1): "
                              "the model is outside the range of its formulas; nothing is written")
    assert isinstance(err.value, ValueError)


def test_quiet_arithmetic_silences_numpy_and_restores_its_state():
    before = np.geterr()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with quiet_arithmetic():
            x = np.array([1.0, 0.0]) / np.array([0.0, 0.0])
            big = np.array([1e308]) * 10.0
        assert np.isinf(x[0]) and np.isnan(x[1]) and np.isinf(big[0])
        with pytest.raises(RuntimeWarning):
            np.array([1.0]) / np.array([0.0])
    assert np.geterr() == before


@pytest.fixture
def goda_60_trials(tmp_path):
    path = tmp_path / "goda.toml"
    path.write_text(example_design_text().replace("trials = 5000", "trials = 60"))
    return path


def _broken_lifetimes(monkeypatch):
    import regimemap.lifetime as lifetime

    real = lifetime.lifetime_sliding

    def broken(*args, **kw):
        r = real(*args, **kw)
        sliding = r.sliding.copy()
        sliding[3] = np.inf
        return replace(r, sliding=sliding)

    monkeypatch.setattr(lifetime, "lifetime_sliding", broken)


def test_the_lifetime_command_refuses_a_non_finite_result_and_writes_nothing(run_cli, goda_60_trials, monkeypatch):
    _broken_lifetimes(monkeypatch)
    out = run_cli(["lifetime", str(goda_60_trials), "--jobs", "1", "-q", "-o", str(goda_60_trials.with_suffix(".csv"))])
    assert out.code == 1, out.output
    assert out.stderr.strip() == (f"regimemap: error: {goda_60_trials}: the lifetime sliding is not finite (inf in 1 of 60 "
                                  "values, nan in 0): the model is outside the range of its formulas; nothing "
                                  "is written")
    assert out.stdout == "" and not goda_60_trials.with_suffix(".csv").exists()


def test_the_design_chart_refuses_a_non_finite_esd(goda_60_trials, monkeypatch):
    import regimemap.lifetime as lifetime
    from regimemap.lifetime.run import run_chart

    real = lifetime.design_chart

    def broken(*args, **kw):
        chart = real(*args, **kw)
        esd = np.array(chart.expected_sliding, dtype=float)
        esd[0] = np.nan
        return replace(chart, expected_sliding=esd)

    monkeypatch.setattr(lifetime, "design_chart", broken)
    with pytest.raises(NonFiniteResult, match=r"the design chart's ESD is not finite \(inf in 0 of 2 values, "
                                              r"nan in 1\)"):
        run_chart(goda_60_trials, [12.0, 18.0], trials=40, seed=1)
