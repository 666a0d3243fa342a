"""run_outcome and run_dynamics_figure: an outcome map's record, its counts, axes, files and cache."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from regimemap.dynamics.outcome import dimensionless_values
from regimemap.dynamics.presets import DYNAMICS_FIGURES
from regimemap.motion.file import OptionError, map_options
from regimemap.motion.record_outcome import outcome_summary, write_outcome_record
from regimemap.workflows import OutcomeRecord, run_dynamics_figure, run_outcome

VALUES = {"gamma": [3.0], "half_width": [0.2], "kprime": [0.0], "mu": [0.5], "k_peak": [0.3, 0.9, 1.5],
          "duration": [0.2, 1.2]}


def _options(dimensionless: bool = False, **values: list[float]):
    vals = {**VALUES, **values}
    return map_options(vals, list(vals), "half-sine", dimensionless=dimensionless)


@pytest.fixture(scope="module")
def record() -> OutcomeRecord:
    return run_outcome(_options(), refine=False)


@pytest.mark.deep
def test_the_record_holds_the_map_named_after_the_swept_inputs_and_its_counts(record) -> None:
    m = record.outcome
    assert (m.first_name, m.second_name) == ("k_peak", "duration")
    assert m.first_values.tolist() == [0.3, 0.9, 1.5] and m.second_values.tolist() == [0.2, 1.2]
    assert m.category.shape == (2, 3) and not m.refined
    assert list(record.counts) == list(m.labels) and sum(record.counts.values()) == record.n_runs == 6
    for code, label in enumerate(m.labels):
        assert record.counts[label] == int(np.count_nonzero(m.category == code))
    assert record.counts["rest"] >= 1 and record.dimensionless_axes == {}
    assert record.inputs == {"pulse": "half-sine", "gamma": 3.0, "half_width": 0.2, "kprime": 0.0,
                             "mu": 0.5, "buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0,
                             "uplift_arm": pytest.approx(1 / 3)}


def test_the_summary_says_the_runs_and_the_categories_found(record) -> None:
    (line,) = outcome_summary(record)
    assert line.startswith("6 runs in ") and f"rest {record.counts['rest']}" in line
    assert all(f"{lab} 0" not in line for lab in record.counts)


@pytest.mark.deep
def test_restitution_and_min_rotation_are_recorded_as_given() -> None:
    r = run_outcome(_options(), refine=False, restitution=0.8, min_rotation=2.0)
    assert r.inputs["restitution"] == 0.8 and r.inputs["min_rotation"] == 2.0
    assert r.outcome.min_rotation == pytest.approx(np.radians(2.0))


@pytest.mark.deep
def test_dimensionless_axes_of_the_swept_pulse_inputs() -> None:
    r = run_outcome(_options(dimensionless=True), refine=False, dimensionless=True)
    assert set(r.dimensionless_axes) == {"k_peak", "duration"}
    np.testing.assert_array_equal(r.dimensionless_axes["k_peak"],
                                  dimensionless_values("k_peak", [0.3, 0.9, 1.5], r.block, "half-sine"))
    assert set(r.extra_axes) == {"k_peak_dimensionless", "duration_dimensionless"}


def test_too_many_steps_is_an_option_error_naming_the_duration() -> None:
    with pytest.raises(OptionError) as err:
        run_outcome(_options(half_width=[0.001], duration=[50.0, 100.0]), refine=False)
    assert err.value.options == ("--duration",)


def test_the_data_of_a_record_are_written_with_its_inputs(record, tmp_path) -> None:
    write_outcome_record(tmp_path / "m.json", record)
    d = json.loads((tmp_path / "m.json").read_text())
    assert (d["first"], d["second"]) == ("k_peak", "duration") and d["inputs"]["pulse"] == "half-sine"
    assert sum(row.count("rest") for row in d["category"]) == record.counts["rest"]
    write_outcome_record(tmp_path / "m.npz", record)
    with np.load(tmp_path / "m.npz") as z:
        assert z["category"].shape == (2, 3) and float(z["mu"]) == 0.5


@pytest.mark.deep
def test_a_dynamics_figure_is_computed_once_then_read_from_the_cache(tmp_path) -> None:
    small = dataclasses.replace(DYNAMICS_FIGURES["D.3"], first=("k_peak", 0.1, 1.6, 4),
                                second=("duration", 0.5, 6.0, 3))
    fresh = run_dynamics_figure(small, cache=tmp_path)
    again = run_dynamics_figure(small, cache=tmp_path)
    assert not fresh.from_cache and again.from_cache
    np.testing.assert_array_equal(fresh.outcome.category, again.outcome.category)
    np.testing.assert_array_equal(fresh.x, np.linspace(0.1, 1.6, 4))
    assert fresh.refine_runs == again.refine_runs > 0 and fresh.data[0] is fresh.outcome
