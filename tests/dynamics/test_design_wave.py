"""``simulate --design FILE.toml``: the caisson's equivalent block under its design wave (issue 18).

The library (:mod:`regimemap.dynamics.design_wave`) builds the block and the half-sine pulse from
Goda's analysis; the command reads the design file, runs it and says where the numbers came from.
The physics check compares a pure slide with the lifetime model's closed form
(:func:`regimemap.lifetime.half_sine_slide`) with the added mass left out.
"""

from __future__ import annotations

import doctest
import json
import math
import re

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.dynamics import (
    DESIGN_INPUTS,
    Block,
    Pulse,
    design_wave_inputs,
    design_wave_numbers,
    design_wave_run,
    simulate,
)
from regimemap.waves import analyse_caisson, wave_duration

from ..conftest import invoke_cli

EXAMPLE = example_design_text()


def edited(old: str, new: str, text: str = EXAMPLE) -> str:
    """The example design file with the line starting with ``old`` starting with ``new`` instead."""
    out, n = re.subn(rf"(?m)^{re.escape(old)}", lambda _: new, text, count=1)
    assert n == 1, old
    return out


def with_friction(mu: float) -> str:
    """Goda's worked caisson with another friction coefficient."""
    return edited("friction = 0.6 ", f"friction = {mu} ")


def one_error(r, pattern: str) -> str:
    assert "Traceback" not in r.output, r.output
    assert r.code == 2, (r.code, r.output)
    lines = r.error_lines()
    assert len(lines) == 1, r.stderr
    assert re.search(pattern, lines[0]), lines[0]
    return lines[0]


# -- the library --------------------------------------------------------------------------------------

def test_block_and_pulse_are_those_of_the_analysis():
    d = parse_design(EXAMPLE)
    a = d.analyse()
    block, pulse = design_wave_run(a, d.site.depth, d.wave.period)
    b = a.block
    assert isinstance(block, Block) and isinstance(pulse, Pulse)
    for got, want in ((block.B, b.B), (block.gamma, b.gamma), (block.mu, b.mu), (block.kprime, b.kprime),
                      (block.buoyancy, b.buoyancy), (block.uplift, 0.0), (block.uplift_ratio, b.uplift_ratio), (block.uplift_arm, b.uplift_arm),
                      (block.i2, b.gyration ** 2)):
        assert float(np.asarray(got)) == float(np.asarray(want))
    assert block.g == 9.81
    # the caisson's numbers: B = 15/2, k = P/(m g), nu = U/P, e_u = 1/3 (Goda's triangle)
    assert float(block.B) == 7.5 and float(block.gamma) == pytest.approx(0.7)
    assert float(b.k) == pytest.approx(float(a.loads.P) / (float(a.section.mass) * 9.81), rel=1e-15)
    assert float(block.uplift_ratio) == pytest.approx(float(a.loads.U / a.loads.P), rel=1e-15)
    assert float(block.uplift_arm) == pytest.approx(1.0 / 3.0, rel=1e-12)
    # the pulse: a half-sine of peak k lasting tau0 = (0.5 - Hmax/(8 h)) T1/3
    tau0 = (0.5 - float(a.heights.Hmax) / (8.0 * 10.1)) * 11.4
    assert pulse.shape == "half-sine"
    assert float(pulse.k_peak) == float(b.k)
    assert float(pulse.duration) == pytest.approx(tau0, rel=1e-15)
    assert float(pulse.duration) == pytest.approx(4.5643, abs=5e-5)
    t = np.linspace(0.0, tau0, 7)
    np.testing.assert_allclose(pulse.k(t), float(b.k) * np.sin(np.pi * t / tau0), atol=1e-15)
    # the uplift in phase: U(t)/(m g) = nu k(t), nothing at zero push (u = 0)
    assert float(block.uplift) == 0.0 and block.loaded


def test_wave_duration_is_the_lifetime_models():
    """One formula for both users; lifetime's own copy (until it imports this one) agrees."""
    H = np.array([1.0, 8.05, 20.0, 40.4])
    np.testing.assert_allclose(wave_duration(H, 10.1, 11.4), (0.5 - H / 80.8) * 11.4, rtol=1e-15)
    assert float(wave_duration(40.4, 10.1, 11.4)) == 0.0  # H = 4 h: no push
    from regimemap import lifetime

    np.testing.assert_array_equal(lifetime.wave_duration(H, 10.1, 11.4), wave_duration(H, 10.1, 11.4))


def test_inputs_and_numbers_say_where_the_run_comes_from():
    d = parse_design(EXAMPLE)
    a = d.analyse()
    block, pulse = design_wave_run(a, d.site.depth, d.wave.period)
    inp = design_wave_inputs(a, d.site.depth, d.wave.period)
    assert list(inp) == list(DESIGN_INPUTS)
    assert inp["pulse"] == "half-sine" and inp["uplift"] == 0.0
    assert inp["k_peak"] == float(pulse.k_peak) and inp["duration"] == float(pulse.duration)
    assert inp["gyration"] ** 2 == pytest.approx(float(np.asarray(block.i2)), rel=1e-15)
    n = design_wave_numbers(a, d.site.depth, d.wave.period)
    assert n["Hmax"] == pytest.approx(8.05, abs=5e-3) and n["depth"] == 10.1 and n["period"] == 11.4
    assert n["tau0"] == inp["duration"] and n["k"] == inp["k_peak"] and n["added_mass"] == 0.0
    assert n["P"] == pytest.approx(940.6, abs=0.05) and n["U"] == pytest.approx(493.0, abs=0.05)
    assert n["W"] == pytest.approx(2312.0) and n["weight"] == pytest.approx(n["mass"] * 9.81)
    assert n["P"] == pytest.approx(n["k"] * n["weight"], rel=1e-14)  # k = P/(m g), m g the dry weight


def test_arrays_give_one_run_each():
    inputs = parse_design(EXAMPLE).analysis_inputs()
    inputs["friction"] = np.array([0.6, 0.4, 0.3])
    a = analyse_caisson(**inputs)
    block, pulse = design_wave_run(a, 10.1, 11.4)
    np.testing.assert_array_equal(block.mu, [0.6, 0.4, 0.3])
    assert np.shape(pulse.k_peak) == (3,)  # the same wave: one k, one tau0 (broadcast)
    np.testing.assert_array_equal(np.broadcast_to(pulse.k_peak, 3), float(a.block.k[0]))
    assert float(pulse.duration) == float(wave_duration(a.heights.Hmax, 10.1, 11.4))
    with pytest.raises(ValueError, match="one caisson"):
        design_wave_inputs(a, 10.1, 11.4)


def test_a_design_wave_with_no_push_is_refused():
    d = parse_design(edited("H0 = 6.3 ", "H13 = 30\nHmax = 45 "))
    with pytest.raises(ValueError, match=r"tau0 = \(0\.5 - Hmax/\(8 h\)\) T1/3 = -0\.649.*Hmax = 45 m.*"
                                         r"depth = 10\.1 m.*period = 11\.4 s.*Hmax >= 4 h"):
        design_wave_run(d.analyse(), d.site.depth, d.wave.period)


def test_docstring_examples():
    import regimemap.dynamics.design_wave as dw
    import regimemap.waves.timing as timing

    for mod in (dw, timing):
        res = doctest.testmod(mod)
        assert res.failed == 0 and res.attempted > 0, mod.__name__


# -- physics: a pure slide is the lifetime model's closed form without the added mass -------------------

@pytest.mark.slow
@pytest.mark.deep
def test_pure_slide_matches_the_closed_form_without_added_mass():
    """With less friction Goda's caisson slides under its design wave and does not rock.

    Then the block's equation is the lifetime model's, m x'' = P(t) - mu (W' - U(t)), with M = m:
    the residual slide must be ``half_sine_slide(P + mu U, mu W', m, tau0)``.  The only difference
    is the time step (the mid-point rule, h = tau0/N <= 0.004/p = 4.5 ms here): its error is
    O(h^2) at the start and at the stop of the slide, 2.5e-5 relative for the shortest slide
    (mu = 0.5, 1 s, 2.3 cm) and 2.3e-6 for the others at the default step, 1.2e-6 and less
    at h = 1 ms (measured); 1e-4 is the honest tolerance at the default step.  mu = 0.5 and 0.4
    stop within the wave, 0.3 after it (both branches of the closed form).
    """
    from regimemap.lifetime import added_mass, half_sine_slide

    mus = np.array([0.5, 0.4, 0.3])
    inputs = parse_design(EXAMPLE).analysis_inputs()
    inputs["friction"] = mus
    a = analyse_caisson(**inputs)
    block, pulse = design_wave_run(a, 10.1, 11.4)
    sim = simulate(block, pulse)
    assert not sim.rocked.any() and not sim.overturned.any() and sim.settled.all()
    assert sim.category.tolist() == [1, 1, 1]  # slide only
    np.testing.assert_array_equal(sim.max_rotation, 0.0)

    m = float(a.section.mass[0])
    P, U, Wb = float(a.loads.P[0]), float(a.loads.U[0]), float(a.section.buoyant_weight[0])
    tau0 = float(wave_duration(a.heights.Hmax, 10.1, 11.4))
    F, R = P + mus * U, mus * Wb
    ref = half_sine_slide(F, R, m, tau0)
    assert ref.min() > 0.02
    np.testing.assert_allclose(sim.residual_slide, ref, rtol=1e-4)
    # it starts when the push first beats friction, sin(pi t1/tau0) = R/F, within a step
    assert sim.phases is not None
    p = float(np.min(block.p))  # the same block in every run: only mu differs
    h = tau0 / math.ceil(tau0 / min(tau0 / 400, 0.004 / p) - 1e-9)
    for i, ph in enumerate(sim.phases):
        assert [lab for lab, _ in ph] == ["RE", "SL", "RE"]
        assert ph[1][1] == pytest.approx(tau0 / np.pi * np.arcsin(R[i] / F[i]), abs=h)
    assert sim.phases[0][2][1] < tau0 < sim.phases[2][2][1]  # stops within / after the wave
    # a finer step: the error shrinks as h^2
    fine = simulate(block, pulse, dt=1e-3)
    np.testing.assert_allclose(fine.residual_slide, ref, rtol=1e-5)
    # the lifetime model adds the water's mass: it slides less
    lt = half_sine_slide(F, R, m + float(added_mass(7.1, 1030.0)), tau0)
    assert (lt < 0.9 * sim.residual_slide).all()


# -- the command ---------------------------------------------------------------------------------------

@pytest.mark.slow
def test_simulate_design_runs_and_says_where_the_numbers_came_from(goda):
    r = invoke_cli(["simulate", "--design", str(goda)])
    assert r.code == 0, r.output
    first = r.stdout.splitlines()[0]
    assert first.startswith(f"design     {goda}: design wave Hmax = 8.050 m (h = 10.1 m, T1/3 = 11.4 s): "
                            "k = P/(m g) = 0.277621, tau0 = (0.5 - Hmax/(8 h)) T1/3 = 4.5643 s"), first
    assert "no added mass" in first
    out = r.stdout
    for piece in ("block      B = 7.5 m, H = 5.25 m (gamma = 0.7), mu = 0.6, k' = -0.0180155",
                  "loads      buoyancy = 0.317613, uplift ratio = 0.524144, uplift arm = 0.333333 B",
                  "pulse      half-sine, k_peak = 0.277621, duration = 4.5643 s",
                  "outcome    rest: not overturned"):
        assert piece in out, (piece, out)


@pytest.mark.slow
def test_simulate_design_json_k_peak_is_the_caissons_k(goda):
    r = invoke_cli(["simulate", "--design", str(goda), "--json"])
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    c = json.loads(invoke_cli(["caisson", str(goda), "--json"]).stdout)
    assert d["inputs"]["k_peak"] == c["k"]
    for key in ("gamma", "kprime", "buoyancy", "uplift_ratio", "uplift_arm", "gyration", "mu"):
        assert d["inputs"][key] == c[key], key
    assert d["inputs"]["half_width"] == c["B"] and d["inputs"]["pulse"] == "half-sine"
    assert d["inputs"]["design"] == str(goda) and d["inputs"]["pulse_file"] is None
    des = d["design"]
    assert des["file"] == str(goda)
    for key in ("Hmax", "H13", "P", "U", "W", "k", "kprime", "mu"):
        assert des[key] == c[key], key
    assert des["depth"] == 10.1 and des["period"] == 11.4 and des["added_mass"] == 0.0
    assert des["tau0"] == d["inputs"]["duration"] == d["derived"]["duration"]
    assert des["units"]["P"] == "kN/m" and "no added mass" in des["added_mass_note"]
    assert "sin(pi t/tau0)" in des["profile"]
    # Goda: SF >= 1 <=> rest on the map; the run under the design wave rests too
    assert c["mode"] == "RE" and d["category"] == "rest" and d["residual_slide"] == 0.0


@pytest.mark.slow
def test_simulate_design_slide_agrees_with_the_library(tmp_path):
    path = tmp_path / "slide.toml"
    path.write_text(with_friction(0.4), encoding="utf-8")
    r = invoke_cli(["simulate", "--design", str(path), "--json", "-o", str(tmp_path / "run.npz")])
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    dsn = parse_design(with_friction(0.4))
    sim = simulate(*design_wave_run(dsn.analyse(), dsn.site.depth, dsn.wave.period))
    assert d["category"] == "slide only"
    assert d["residual_slide"] == float(f"{sim.residual_slide[0]:.12g}")
    assert d["files"] == [str(tmp_path / "run.npz")]
    with np.load(tmp_path / "run.npz") as z:
        assert str(z["design"]) == str(path) and float(z["mu"]) == 0.4


@pytest.mark.slow
def test_restitution_may_be_given_with_a_design(goda):
    r = invoke_cli(["simulate", "--design", str(goda), "--restitution", "0.5", "--json"])
    assert r.code == 0, r.output
    assert json.loads(r.stdout)["inputs"]["restitution"] == 0.5


GIVEN_TOO = {"gamma": "3", "half_width": "1", "kprime": "0", "mu": "0.5", "buoyancy": "0", "uplift": "0",
             "uplift_ratio": "0", "uplift_arm": "0.3", "gyration": "0.7", "pulse": "half-sine",
             "k_peak": "0.3", "duration": "1", "pulse_file": "record.csv"}


@pytest.mark.parametrize("name", sorted(GIVEN_TOO))
def test_an_option_the_design_gives_is_refused(goda, name):
    flag = "--" + name.replace("_", "-")
    r = invoke_cli(["simulate", "--design", str(goda), flag, GIVEN_TOO[name]])
    one_error(r, rf"{flag} and --design exclude each other: the design file gives the block and the pulse")


def test_conflicts_are_named_together(goda):
    assert set(GIVEN_TOO) == set(DESIGN_INPUTS) | {"pulse_file"}
    r = invoke_cli(["simulate", "--mu", "0.5", "--design", str(goda), "--gamma", "2"])
    one_error(r, r"--gamma, --mu and --design exclude each other")


@pytest.mark.parametrize("edit,pattern", [
    (("friction = 0.6 ", "friction = 3 "), r"\[caisson\] friction = 3: out of range"),
    (("base_depth = 7.1 ", "base_depth = -7.1 "), r"\[caisson\] base_depth = -7\.1"),
    (("period = 11.4 ", "period = 'long' "), r"\[wave\] period = 'long': expected a number"),  # as written
    (("friction = 0.6 ", "fricton = 0.6 "), r"unknown key \[caisson\] fricton"),
    (("[site]", "[site"), r"TOML syntax error at line \d+"),
])
def test_a_broken_design_file_is_reported_as_caisson_reports_it(tmp_path, edit, pattern):
    path = tmp_path / "bad.toml"
    path.write_text(edited(*edit), encoding="utf-8")
    line = one_error(invoke_cli(["simulate", "--design", str(path)]),
                     rf"'--design': {re.escape(str(path))}(, line \d+)?: " + pattern)
    caisson = one_error(invoke_cli(["caisson", str(path)]), pattern)
    # the same message, after the option's name
    assert line.split("'--design': ", 1)[1].split(" (see ")[0] == caisson.split("'DESIGN.toml': ", 1)[1].split(
        " (see ")[0]


def test_a_missing_design_file_and_a_derived_value_out_of_range(tmp_path):
    one_error(invoke_cli(["simulate", "--design", str(tmp_path / "none.toml")]),
              r"'--design': .*none\.toml: cannot read the design file")
    path = tmp_path / "tall.toml"
    path.write_text(edited("H0 = 6.3 ", "H13 = 30\nHmax = 45 "), encoding="utf-8")
    one_error(invoke_cli(["simulate", "--design", str(path)]),
              r"'--design': .*tall\.toml: the design wave's duration tau0 = .*\(Hmax >= 4 h")


def test_without_a_design_the_block_is_required():
    one_error(invoke_cli(["simulate", "--kprime", "0", "--pulse", "half-sine", "--k-peak", "1",
                          "--duration", "1"]),
              r"missing option\(s\) --gamma, --half-width, --mu: give the block .* or --design FILE\.toml")
    one_error(invoke_cli(["simulate", "--gamma", "3", "--half-width", "0.2", "--kprime", "0",
                          "--pulse", "half-sine", "--k-peak", "1", "--duration", "1"]),
              r"missing option\(s\) --mu")


def test_help_documents_the_option():
    r = invoke_cli(["simulate", "--help"])
    assert r.code == 0
    text = " ".join(r.stdout.split())
    assert "--design FILE.toml" in text and "regimemap simulate --design goda.toml" in text
    assert "No added mass of water" in text
