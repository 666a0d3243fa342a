"""A run and an outcome map from flat options (regimemap.motion.file) and the step-count
checks (regimemap.dynamics.limits), without click."""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap.dynamics import Block, Pulse, simulate
from regimemap.dynamics.limits import (
    MAX_MAP_RUNS,
    MAX_STEPS,
    check_map_steps,
    check_run_steps,
    estimated_steps,
)
from regimemap.motion.file import (
    MAP_INPUTS,
    OptionError,
    block_from_options,
    check_loads_and_gyration,
    map_options,
    pulse_from_options,
)

from ..conftest import invoke_cli

# -- the pulse of a run ------------------------------------------------------------------------------


def test_a_shape_with_peak_and_duration() -> None:
    p = pulse_from_options("half-sine", 0.5, 0.4, kprime=0.0)
    assert p.shape == "half-sine" and float(p.k_peak) == 0.5 and float(p.duration) == 0.4


@pytest.mark.parametrize("shape, k, T, missing", [
    (None, 0.5, 0.4, "--pulse"), ("half-sine", None, 0.4, "--k-peak"),
    ("half-sine", 0.5, None, "--duration"), (None, None, None, "--pulse, --k-peak, --duration"),
])
def test_missing_pulse_options_are_named(shape, k, T, missing: str) -> None:
    with pytest.raises(OptionError, match=f"missing option\\(s\\) {missing}: give --pulse KIND") as e:
        pulse_from_options(shape, k, T, kprime=0.0)
    assert e.value.options == ()  # the command line as a whole


def _reader(pulse: Pulse):
    def read(path: str) -> Pulse:
        if path == "bad.csv":
            raise ValueError("bad.csv, line 3: t must increase")
        return pulse

    return read


def test_a_pulse_file_excludes_the_shape_options_and_names_its_problems() -> None:
    sampled = Pulse.from_arrays([0.0, 0.1, 0.3], [0.0, 0.8, 0.0])
    p = pulse_from_options(None, None, None, pulse_file="p.csv", read=_reader(sampled), kprime=0.2)
    assert p is sampled
    with pytest.raises(OptionError, match="^--pulse, --duration and --pulse-file exclude each other"):
        pulse_from_options("half-sine", None, 0.4, pulse_file="p.csv", read=_reader(sampled), kprime=0.2)
    with pytest.raises(OptionError, match="line 3: t must increase") as e:
        pulse_from_options(None, None, None, pulse_file="bad.csv", read=_reader(sampled), kprime=0.2)
    assert e.value.options == ("--pulse-file",)


def test_kprime_is_required_unless_the_file_has_it_and_excluded_if_it_does() -> None:
    with pytest.raises(OptionError, match="missing option --kprime"):
        pulse_from_options("half-sine", 0.5, 0.4)
    with_kprime = Pulse.from_arrays([0.0, 0.2], [0.5, 0.0], [0.1, 0.2])
    assert pulse_from_options(None, None, None, pulse_file="k.csv", read=_reader(with_kprime)) is with_kprime
    with pytest.raises(OptionError, match="--kprime and the kprime column of k.csv exclude each other"):
        pulse_from_options(None, None, None, pulse_file="k.csv", read=_reader(with_kprime), kprime=0.0)


# -- the block ------------------------------------------------------------------------------------------


def test_block_from_options() -> None:
    values = {"half_width": 0.2, "gamma": 3.0, "mu": 0.5, "kprime": None, "gyration": 1.5,
              "buoyancy": 0.1, "uplift": 0.2, "uplift_ratio": 0.3, "uplift_arm": 0.25}
    b = block_from_options(values)
    assert (b.B, b.gamma, b.mu, b.kprime, b.i2, b.buoyancy, b.uplift, b.uplift_ratio, b.uplift_arm) == (
        0.2, 3.0, 0.5, 0.0, 2.25, 0.1, 0.2, 0.3, 0.25)
    assert block_from_options({**values, "gyration": None, "kprime": -0.4}).i2 is None


def test_loads_must_leave_weight_and_gyration_must_fit() -> None:
    check_loads_and_gyration([3.0], [0.3], [0.2], None)
    with pytest.raises(OptionError, match="buoyancy \\+ uplift must be < 1") as e:
        check_loads_and_gyration([3.0], [0.3, 0.6], [0.5], None)
    assert e.value.options == ("--uplift", "--buoyancy")
    with pytest.raises(OptionError, match="gyration must be .* for gamma = 1") as e:
        check_loads_and_gyration([1.0, 3.0], [0.0], [0.0], [1.2, 2.0])
    assert e.value.options == ("--gyration",)


# -- the steps ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("shape, k, T", [("half-sine", 0.6, 0.5), ("rectangular", 0.2, 0.3),
                                         ("one-sine", 1.2, 0.8)])
def test_estimated_steps_bound_the_steps_taken(shape: str, k: float, T: float) -> None:
    blk = Block(B=0.2, gamma=3.0, mu=0.5)
    sim = simulate(blk, Pulse.make(shape, k, T), record_phases=False)
    assert 0 < sim.steps[0] <= estimated_steps(blk, T) == check_run_steps(blk, T)


def test_a_run_over_the_step_limit_says_why() -> None:
    blk = Block(B=0.01, gamma=3.0, mu=5.0)
    steps = estimated_steps(blk, 100.0)
    assert steps > MAX_STEPS
    p = float(blk.p)
    with pytest.raises(ValueError) as e:
        check_run_steps(blk, 100.0)
    assert str(e.value) == (
        f"the run needs up to {steps} time steps (the pulse of 100 s at a step of at most 0.004/p = "
        f"{0.004 / p:.3g} s, then 60/p s of free motion), more than the limit of {MAX_STEPS}; give a "
        "shorter pulse (or a larger block: p grows as the half-width shrinks)")


def test_a_map_takes_the_block_of_smallest_p() -> None:
    blocks = Block(B=np.array([0.01, 0.01]), gamma=np.array([3.0, 5.0]), mu=0.0)
    assert check_map_steps(blocks, 1.0) == estimated_steps(Block(B=0.01, gamma=5.0, mu=0.0), 1.0)
    with pytest.raises(ValueError, match="^the longest run needs up to [0-9]+ time steps, more than "
                                         "the limit of 200000; give shorter pulses$"):
        check_map_steps(blocks, 100.0)


# -- an outcome map ---------------------------------------------------------------------------------------

BASE: dict[str, list[float] | None] = {n: None for n in MAP_INPUTS}
BASE.update(gamma=[3.0], half_width=[0.2], kprime=[0.0], mu=[0.5])


def opts(order: list[str] | None = None, shape: str | None = "half-sine", dimensionless: bool = False,
         **given: list[float] | None):
    values = {**BASE, **given}
    return map_options(values, order or list(given) + list(BASE), shape, dimensionless=dimensionless)


def test_the_two_swept_inputs_in_command_line_order_sorted() -> None:
    o = opts(duration=[1.2, 0.2, 0.5], k_peak=[0.3, 0.9])
    assert o.swept == ("duration", "k_peak")
    assert o.values["duration"] == [0.2, 0.5, 1.2]
    assert o.n_runs == 6
    assert o.fixed == {"omega_p": None, "mu": 0.5, "kprime": 0.0, "gamma": 3.0, "half_width": 0.2,
                       "gyration": None, "buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0,
                       "uplift_arm": 1.0 / 3.0}
    assert o.fixed_duration() is None and o.longest_duration() == 1.2
    name, values = o.sweep(0)
    assert name == "duration" and values.tolist() == [0.2, 0.5, 1.2]


@pytest.mark.parametrize("given, message, options", [
    ({"k_peak": [0.3, 0.9], "duration": [0.2, 0.5], "mu": None},
     "^missing option\\(s\\) --mu: give the block", ()),
    ({"k_peak": [0.3, 0.9], "duration": [0.2, 0.5], "half_width": None, "gamma": None},
     "^missing option\\(s\\) --gamma, --half-width: ", ()),
    ({"k_peak": [0.3, 0.9]}, "give exactly two swept inputs .*; swept: --k-peak$", ()),
    ({"k_peak": [0.3, 0.9], "duration": [0.2, 0.5], "mu": [0.1, 0.2]},
     "swept: --k-peak, --duration, --mu$", ()),
    ({"k_peak": [0.3, 0.3], "duration": [0.2, 0.5]}, "^a value appears twice$", ("--k-peak",)),
    ({"k_peak": None, "mu": [0.2, 0.5], "duration": [0.2, 0.5]}, "^missing option --k-peak", ()),
    ({"k_peak": [0.3, 0.9], "mu": [0.2, 0.5]}, "^give one of --duration \\(s\\) or --omega-p", ()),
    ({"k_peak": [0.3, 0.9], "duration": [0.2, 0.5], "omega_p": [3.0]},
     "^--duration and --omega-p exclude each other$", ()),
    ({"k_peak": [0.3, 0.9], "duration": [0.2, 0.5], "kprime": None}, "^missing option --kprime", ()),
    ({"k_peak": [0.3, 0.9], "duration": [0.5], "buoyancy": [0.2, 0.7], "uplift": [0.4]},
     "buoyancy \\+ uplift must be < 1", ("--uplift", "--buoyancy")),
])
def test_map_option_problems(given: dict[str, list[float] | None], message: str,
                             options: tuple[str, ...]) -> None:
    with pytest.raises(OptionError, match=message) as e:
        opts(**given)
    assert e.value.options == options


def test_the_pulse_shape_is_required() -> None:
    with pytest.raises(OptionError, match="^missing option --pulse: the shape of the force pulse "
                                          "\\(rectangular, triangular, half-sine"):
        opts(shape=None, k_peak=[0.3, 0.9], duration=[0.2, 0.5])


def test_dimensionless_axes_need_one_block_and_a_pulse_axis() -> None:
    assert opts(dimensionless=True, k_peak=[0.3, 0.9], omega_p=[3.0, 6.0]).swept == ("k_peak", "omega_p")
    with pytest.raises(OptionError, match="need one block, but --gamma is swept") as e:
        opts(dimensionless=True, gamma=[1.0, 2.0], k_peak=[0.3, 0.9], duration=[0.5])
    assert e.value.options == ("--dimensionless",)
    with pytest.raises(OptionError, match="sweep --k-peak, --duration or --omega-p"):
        opts(dimensionless=True, mu=[0.2, 0.5], kprime=[0.0, 0.5], k_peak=[0.5], duration=[0.5])


def test_too_many_runs() -> None:
    n = int(math.isqrt(MAX_MAP_RUNS)) + 1
    with pytest.raises(OptionError, match=f"^{n * n} runs exceed the limit of {MAX_MAP_RUNS}; give fewer"):
        opts(k_peak=list(np.linspace(0.1, 2.0, n)), duration=list(np.linspace(0.1, 2.0, n)))


def test_a_frequency_sets_the_duration_and_the_longest_pulse() -> None:
    o = opts(shape="one-sine", k_peak=[0.3, 0.9], mu=[0.2, 0.5], omega_p=[5.0])
    assert o.fixed_duration() == 2.0 * math.pi / 5.0
    o = opts(shape="half-sine", k_peak=[0.3, 0.9], omega_p=[5.0, 2.0])
    assert o.longest_duration() == math.pi / 2.0


def test_swept_block_fields_and_gyration() -> None:
    o = opts(half_width=[0.4, 0.2], gyration=[1.0, 1.2], k_peak=[0.5], duration=[0.5])
    assert o.sweep(0)[0] == "B" and o.sweep(1)[0] == "i2"
    assert o.sweep(1)[1].tolist() == [1.0, 1.2 ** 2]
    b = o.block()  # the swept fields hold their first value; outcome_map replaces them
    assert float(np.asarray(b.B)) == 0.2 and b.i2 == 1.0


def test_the_steps_of_a_map_name_the_pulse_option() -> None:
    assert opts(k_peak=[0.3, 0.9], duration=[0.2, 0.5]).check_steps() > 0
    with pytest.raises(OptionError, match="the longest run needs up to") as e:
        opts(half_width=[0.01], k_peak=[0.3, 0.9], duration=[50.0, 100.0]).check_steps()
    assert e.value.options == ("--duration",)
    with pytest.raises(OptionError) as e:
        opts(half_width=[0.01], k_peak=[0.3, 0.9], omega_p=[0.02, 0.03]).check_steps()
    assert e.value.options == ("--omega-p",)


@pytest.mark.slow
@pytest.mark.parametrize("swept", [["--half-width", "0.2,0.4"], ["--mu", "0.3,5"], ["--gamma", "2,3"]])
@pytest.mark.deep
def test_outcome_sweeps_the_required_block_fields(tmp_path, swept: list[str]) -> None:
    """--gamma, --half-width and --mu can be swept like the others (they used to fail with an
    internal error: the map's block lacked the swept required field)."""
    args = {"--gamma": "3", "--half-width": "0.2", "--mu": "0.5"}
    args.pop(swept[0])
    out = tmp_path / "m.npz"
    r = invoke_cli(["outcome", *[a for kv in args.items() for a in kv], "--kprime", "0", *swept,
                    "--pulse", "half-sine", "--k-peak", "0.3,1.5", "--duration", "0.5", "-o", str(out)])
    assert r.code == 0, r.output
    name = swept[0].lstrip("-").replace("-", "_")
    with np.load(out) as z:
        assert z[name].tolist() == [float(v) for v in swept[1].split(",")]
        assert z["category"].shape == (2, 2)
