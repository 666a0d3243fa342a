"""The design checks designers apply: required safety factors, and implausible values (unit slips)."""

from __future__ import annotations

import json

import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.caisson.file_plausibility import implausible_values

EXAMPLE = example_design_text()
#: Without [lifetime]: the safety factors are the only requirements.
NO_LIFE = EXAMPLE.split("# Optional: the sliding of the caisson")[0]


def _write(tmp_path, text, name="goda.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def test_goda_fails_the_required_sliding_factor(run_cli, tmp_path):
    path = _write(tmp_path, NO_LIFE)
    r = run_cli(["caisson", path])
    assert r.code == 0
    lines = r.stdout.splitlines()
    assert "FAIL  sliding safety factor 1.16 >= 1.2" in lines
    assert "PASS  overturning safety factor 2.559 >= 1.2" in lines
    assert "verdict: FAIL (1 of 2 requirements not met)" in lines
    obj = json.loads(run_cli(["caisson", path, "--json"]).stdout)
    assert obj["design_check"]["sliding"] == {"value": pytest.approx(1.16, abs=0.005), "required": 1.2,
                                              "meets": False}
    assert obj["design_check"]["overturning"]["meets"] is True
    assert obj["at_rest_by_goda"] is True  # SF >= 1: at rest, but short of the margin


def test_required_factors_come_from_the_file(run_cli, tmp_path):
    text = NO_LIFE.replace("# required_sliding = 1.2", "required_sliding = 1.1")
    r = run_cli(["caisson", _write(tmp_path, text)])
    assert "PASS  sliding safety factor 1.16 >= 1.1" in r.stdout.splitlines()
    assert "verdict: PASS (every requirement met)" in r.stdout.splitlines()
    bad = EXAMPLE.replace("# required_sliding = 1.2", "required_sliding = 0.8")
    r = run_cli(["caisson", _write(tmp_path, bad, "bad.toml")])
    assert r.code == 2 and "[caisson] required_sliding = 0.8" in r.stderr


@pytest.mark.render
def test_the_sheet_draws_the_required_line(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from regimemap.caisson.report import caisson_report
    from tests.conftest import draw_sheet

    report = caisson_report(parse_design(EXAMPLE).analysis_inputs())
    fig = draw_sheet(report, required=(1.3, 1.5))
    (ax,) = [a for a in fig.axes if a.get_label() == "path"]
    texts = [t.get_text().strip() for t in ax.texts]
    assert "required 1.3" in texts and "required 1.5" in texts
    levels = sorted({round(float(ln.get_ydata()[0]), 6) for ln in ax.get_lines()
                     if len(set(ln.get_ydata())) == 1})
    assert {1.0, 1.3, 1.5} <= set(levels)


def test_the_example_is_plausible():
    d = parse_design(EXAMPLE)
    assert implausible_values(d, d.analyse()) == []


@pytest.mark.parametrize("old,new,key,slip", [
    ("depth = 10.1", "depth = 80", "[site] depth = 80", "deeper than any caisson breakwater built"),
    ("buoyant_weight = 2312", "buoyant_weight = 2312000", "[caisson] buoyant_weight = 2312000", "N/m for kN/m"),
    ("period = 11.4", "period = 1.5", "[wave] period = 1.5", "a laboratory model's wave"),
    ("width = 15.0", "width = 250", "[caisson] width = 250", "centimetres for metres"),
])
def test_each_unit_slip_is_named(old, new, key, slip):
    text = EXAMPLE.replace(old, new, 1)
    d = parse_design(text)
    try:
        a = d.analyse()
    except ValueError:
        a = None
    found = [str(x) for x in implausible_values(d, a)]
    assert any(m.startswith(key) and slip in m for m in found), found


def test_heel_pressure_over_5_mpa_is_named():
    d = parse_design(EXAMPLE.replace("buoyant_weight = 2312", "buoyant_weight = 2312000"))
    found = [str(x) for x in implausible_values(d, d.analyse())]
    assert any(m.startswith("heel pressure") and "over 5 MPa" in m for m in found)


@pytest.mark.parametrize("command", [["caisson"], ["lifetime", "--trials", "20"], ["simulate", "--design"]])
@pytest.mark.slow
def test_warning_then_strict_error(run_cli, tmp_path, command):
    path = _write(tmp_path, EXAMPLE.replace("buoyant_weight = 2312", "buoyant_weight = 2312000"))
    r = run_cli([*command, path])
    assert "warning:" in r.stderr and "[caisson] buoyant_weight = 2312000" in r.stderr
    assert "N/m for kN/m" in r.stderr
    strict = run_cli([*command, path, "--strict"])
    assert strict.code == 2 and "--strict refuses implausible values" in strict.stderr
    assert "Traceback" not in strict.stderr
    clean = run_cli([*command, _write(tmp_path, EXAMPLE, "ok.toml"), "--strict"])
    assert clean.code == 0 and "warning:" not in clean.stderr


@pytest.mark.slow
def test_simulate_design_names_the_option_and_the_slip(run_cli, tmp_path):
    """The depth in centimetres: beyond the hard limit, an error on --design naming the key and the slip;
    a caisson far wider than any: a warning, and with --strict an error."""
    path = _write(tmp_path, EXAMPLE.replace("depth = 10.1", "depth = 1010"), "deep.toml")
    r = run_cli(["simulate", "--design", path])
    assert r.code == 2 and "'--design'" in r.stderr and "line 8: [site] depth = 1010" in r.stderr
    assert "centimetres for metres" in r.stderr and "Traceback" not in r.stderr
    path = _write(tmp_path, EXAMPLE.replace("width = 15.0", "width = 250"), "wide.toml")
    r = run_cli(["simulate", "--design", path])
    assert "warning:" in r.stderr and "[caisson] width = 250" in r.stderr
    strict = run_cli(["simulate", "--design", path, "--strict"])
    assert strict.code == 2 and "'--design'" in strict.stderr and "[caisson] width = 250" in strict.stderr
    assert "Traceback" not in strict.stderr


def test_simulate_strict_needs_a_design_file(run_cli):
    r = run_cli(["simulate", "--gamma", "3", "--half-width", "0.2", "--mu", "5", "--pulse", "half-sine",
                 "--k-peak", "0.5", "--duration", "0.5", "--strict"])
    assert r.code == 2 and "--strict checks a design file" in r.stderr
