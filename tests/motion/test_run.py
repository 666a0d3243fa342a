"""run_simulation: a run from objects, from options and from a design file, its record and its notices."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from regimemap.caisson.file_example import example_design_text
from regimemap.dynamics import Block, Pulse, simulate
from regimemap.motion.file import OptionError
from regimemap.motion.record_simulation import (
    format_simulation,
    simulation_json,
    simulation_record,
    write_simulation_history,
)
from regimemap.motion.run import IMPLAUSIBLE, STILL_MOVING, _run_notices
from regimemap.workflows import SimulationRecord, run_simulation

OPTIONS = {"gamma": 3.0, "half_width": 0.2, "kprime": 0.0, "mu": 5.0, "pulse": "half-sine",
           "k_peak": 0.5, "duration": 0.5}


@pytest.mark.deep
def test_a_block_and_a_pulse_give_the_quantities_a_designer_checks() -> None:
    block, pulse = Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.5, 0.5)
    r = run_simulation(block, pulse)
    assert isinstance(r, SimulationRecord)
    assert r.p == pytest.approx(float(block.p)) and r.alpha == pytest.approx(math.atan(1 / 3))
    assert r.H == pytest.approx(0.6) and r.omega_p == pytest.approx(math.pi / 0.5)
    assert r.impact_ratio == r.housner_ratio == pytest.approx(1 - 1.5 * math.sin(math.atan(1 / 3)) ** 2)
    assert (r.k_peak, r.duration) == (0.5, 0.5)
    assert r.inputs["pulse"] == "half-sine" and r.inputs["design"] is None and r.inputs["gyration"] is None
    sim = simulate(block, pulse)
    assert r.max_rotation == float(sim.max_rotation[0]) and r.notices == ()
    assert r.simulation.history is None and r.design_numbers is None and r.checks == ()


@pytest.mark.deep
def test_options_give_the_run_of_the_same_block_recorded_as_given() -> None:
    by_options = run_simulation(OPTIONS)
    by_objects = run_simulation(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.5, 0.5))
    assert by_options.max_rotation == by_objects.max_rotation
    assert by_options.category == by_objects.category
    assert list(by_options.inputs) == ["gamma", "half_width", "kprime", "mu", "pulse", "k_peak", "duration",
                                       "pulse_file", "restitution", "buoyancy", "uplift", "uplift_ratio",
                                       "uplift_arm", "gyration", "design", "min_rotation"]
    assert by_options.inputs["uplift_arm"] == pytest.approx(1 / 3)


def test_options_that_do_not_go_together_name_the_option() -> None:
    with pytest.raises(OptionError, match=r"missing option\(s\) --gamma, --mu") as err:
        run_simulation({"half_width": 0.2})
    assert err.value.options == ()
    with pytest.raises(OptionError, match="missing option") as err:
        run_simulation({**OPTIONS, "duration": None})
    with pytest.raises(OptionError, match="more than the limit") as err:
        run_simulation({**OPTIONS, "duration": 100.0, "half_width": 0.001})
    assert err.value.options == ("--duration",)
    with pytest.raises(TypeError, match="pulse"):
        run_simulation(Block(B=0.2, gamma=3.0, mu=5.0))


@pytest.mark.slow
def test_a_squat_block_has_no_impact_ratio_unless_given() -> None:
    squat = {**OPTIONS, "gamma": 0.5, "half_width": 1.0, "k_peak": 1.5}
    r = run_simulation(squat)
    assert r.housner_ratio <= 0.0 and r.impact_ratio is None
    assert "impact ratio not applicable" in format_simulation(r)
    assert run_simulation(squat, restitution=0.5).impact_ratio == 0.5


@pytest.mark.deep
def test_a_run_still_moving_at_the_time_limit_is_a_notice() -> None:
    caisson = Block(B=7.5, gamma=0.7, kprime=-0.02, buoyancy=0.32, uplift_ratio=0.52, mu=0.0)
    sim = simulate(caisson, Pulse.breaking(0.86, 2.0), t_max=5.0)
    (notice,) = _run_notices(sim, 2.0)
    assert notice.code == STILL_MOVING and notice.quantity == "end_time"
    assert notice.value == pytest.approx(float(sim.end_time[0]))
    assert "still moving at t = 5" in notice.message and "the pulse's 2 s" in notice.message
    settled = simulate(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.5, 0.5))
    assert _run_notices(settled, 0.5) == []


@pytest.mark.deep
def test_min_rotation_counts_rocking_only_above_it() -> None:
    r = run_simulation({**OPTIONS, "mu": 0.35, "k_peak": 0.6})
    assert r.category == "slide-rock"
    above = math.degrees(r.max_rotation) * 1.01
    assert run_simulation({**OPTIONS, "mu": 0.35, "k_peak": 0.6}, min_rotation=above).category == "slide only"


@pytest.fixture
def design_file(tmp_path):
    def write(text: str = example_design_text(), name: str = "goda.toml"):
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return str(path)
    return write


@pytest.mark.slow
def test_a_design_file_gives_the_block_the_pulse_and_the_checks(design_file) -> None:
    path = design_file()
    r = run_simulation(path)
    assert r.design == path and r.inputs["design"] == path and r.inputs["pulse"] == "half-sine"
    assert r.design_numbers is not None and r.design_numbers["Hmax"] == pytest.approx(8.05, abs=1e-3)
    assert r.k_peak == pytest.approx(r.design_numbers["k"]) and r.duration == pytest.approx(r.design_numbers["tau0"])
    assert [c.name for c in r.checks] == ["sliding safety factor", "overturning safety factor"]
    assert r.checks[0].value == pytest.approx(1.16, abs=0.01) and not r.checks[0].passed
    assert r.notices == ()
    text = format_simulation(r)
    assert text.startswith("design     " + path) and "FAIL" in text and "sliding safety factor" in text
    d = json.loads(simulation_json(r, ["a.csv"]))
    assert d["files"] == ["a.csv"] and d["design"]["file"] == path and len(d["checks"]) == 2


@pytest.mark.slow
def test_implausible_values_are_notices_or_refused_under_strict(design_file) -> None:
    path = design_file(example_design_text().replace("buoyant_weight = 2312", "buoyant_weight = 4800"))
    r = run_simulation(path)
    (notice,) = r.notices
    assert notice.code == IMPLAUSIBLE and notice.quantity == "[caisson] buoyant_weight"
    assert notice.value == 4800 and notice.message.startswith(f"{path}: [caisson] buoyant_weight = 4800")
    with pytest.raises(OptionError, match="--strict refuses implausible values") as err:
        run_simulation(path, strict=True)
    assert err.value.options == ("--design",)


def test_a_bad_design_file_is_an_option_error_naming_the_key(design_file) -> None:
    path = design_file(example_design_text().replace("depth = 10.1", "depth = 150.0"))
    with pytest.raises(OptionError, match=r"\[site\] depth = 150") as err:
        run_simulation(path)
    assert err.value.options == ("--design",)


@pytest.mark.deep
def test_the_json_of_a_run_rounds_and_says_what_is_not_residual() -> None:
    r = run_simulation({**OPTIONS, "mu": 0.35, "k_peak": 0.6})
    d = simulation_record(r)
    assert d["category"] == r.category and d["derived"]["p"] == pytest.approx(r.p, rel=1e-11)
    assert d["residual_slide"] == pytest.approx(r.residual_slide, rel=1e-11)
    assert d["inputs"]["k_peak"] == 0.6 and "design" not in d


@pytest.mark.deep
def test_the_history_is_kept_only_when_asked(tmp_path) -> None:
    with pytest.raises(ValueError, match="history=True"):
        write_simulation_history(tmp_path / "h.csv", run_simulation(OPTIONS))
    r = run_simulation(OPTIONS, history=True)
    write_simulation_history(tmp_path / "h.npz", r)
    with np.load(tmp_path / "h.npz") as z:
        assert z["t"].size == r.simulation.history.t.size and float(z["k_peak"]) == 0.5


@pytest.mark.slow
def test_the_html_display_reads_the_field_table_and_the_notices(design_file) -> None:
    path = design_file(example_design_text().replace("buoyant_weight = 2312", "buoyant_weight = 4800"))
    html = run_simulation(path)._repr_html_()
    assert "Housner" in html and "impact ratio" in html and "warning: implausible-value" in html
