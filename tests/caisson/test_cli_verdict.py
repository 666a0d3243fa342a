"""The caisson's design check as data: ``--check`` exit codes, the PASS/FAIL lines, the JSON
``checks``, and the verdict on the design sheet (badge, failing numbers in the fail colour)."""

from __future__ import annotations

import json

import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.caisson.report import caisson_checks, caisson_report
from regimemap.records.checks import Check

EXAMPLE = example_design_text()
NO_LIFE = EXAMPLE.split("# Optional: the sliding of the caisson")[0]
#: Goda's caisson, wider and heavier in proportion (the same unit weight): both factors pass.
WIDE = NO_LIFE.replace("width = 15.0", "width = 22.0").replace("buoyant_weight = 2312",
                                                                 "buoyant_weight = 3390")


def _write(tmp_path, text, name="goda.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def _sf(text):
    a = parse_design(text).analyse()
    return float(a.stability.sliding), float(a.stability.overturning)


def test_the_checks_are_goda_safety_factors_against_the_required_ones():
    d = parse_design(NO_LIFE)
    r = caisson_report(d.analysis_inputs())
    sliding, overturning = caisson_checks(r, (1.2, 1.5))
    # Goda's SF recomputed from the loads: mu (W' - U) / P and (W' t - M_U) / M_P with t = B = 7.5 m
    a = r.analysis
    W, U, P = float(a.section.buoyant_weight), float(a.loads.U), float(a.loads.P)
    assert sliding.value == pytest.approx(0.6 * (W - U) / P, rel=1e-12)
    assert overturning.value == pytest.approx((W * 7.5 - float(a.loads.Mu)) / float(a.loads.Mp), rel=1e-12)
    assert (sliding.required, sliding.relation, sliding.passed) == (1.2, ">=", False)
    assert (overturning.required, overturning.passed) == (1.5, True)


@pytest.mark.parametrize(("text", "check", "code"), [
    (NO_LIFE, True, 1), (NO_LIFE, False, 0), (WIDE, True, 0), (WIDE, False, 0)])
def test_check_exit_status(run_cli, tmp_path, text, check, code):
    path = _write(tmp_path, text)
    args = ["caisson", path, *(["--check"] if check else [])]
    r = run_cli(args)
    assert r.code == code, r.stderr
    sliding, overturning = _sf(text)
    verdict = "PASS" if sliding >= 1.2 else "FAIL"
    assert f"{verdict}  sliding safety factor {sliding:.4g} >= 1.2" in r.stdout.splitlines()
    assert f"PASS  overturning safety factor {overturning:.4g} >= 1.2" in r.stdout.splitlines()
    obj = json.loads(run_cli([*args, "--json"]).stdout)
    assert [(c["name"], c["pass"]) for c in obj["checks"]] == [
        ("sliding safety factor", sliding >= 1.2), ("overturning safety factor", True)]
    assert obj["checks"][0]["value"] == pytest.approx(sliding, rel=1e-11)
    assert obj["checks"][0]["required"] == 1.2 and obj["checks"][0]["relation"] == ">="
    assert obj["verdict"] == verdict and obj["impulsive"] is True
    assert obj["design_check"]["sliding"]["meets"] is (sliding >= 1.2)  # the older form, kept


@pytest.mark.render
@pytest.mark.deep
def test_check_writes_everything_before_exit_1(run_cli, tmp_path):
    sheet = tmp_path / "sheet.png"
    r = run_cli(["caisson", _write(tmp_path, NO_LIFE), "--check", "-o", str(sheet)])
    assert r.code == 1 and sheet.is_file() and r.stdout.splitlines()[-1] == str(sheet)
    assert r.stderr == ""


def test_usage_errors_still_exit_2_under_check(run_cli, tmp_path):
    r = run_cli(["caisson", _write(tmp_path, NO_LIFE.replace("period = 11.4", "period = 40")), "--check"])
    assert r.code == 2


@pytest.mark.slow
def test_required_factors_from_the_file_decide_the_verdict(run_cli, tmp_path):
    text = NO_LIFE.replace("# required_sliding = 1.2", "required_sliding = 1.1")
    assert run_cli(["caisson", _write(tmp_path, text), "--check"]).code == 0
    text = WIDE.replace("# required_overturning = 1.2", "required_overturning = 3")
    r = run_cli(["caisson", _write(tmp_path, text), "--check"])
    assert r.code == 0 == (not _sf(WIDE)[1] >= 3.0)  # 5.5 >= 3
    text = WIDE.replace("# required_sliding = 1.2", "required_sliding = 2")
    r = run_cli(["caisson", _write(tmp_path, text), "--check", "--json"])
    assert r.code == 1 and json.loads(r.stdout)["verdict"] == "FAIL"


def test_the_impulsive_setting_is_named(run_cli, tmp_path):
    r = run_cli(["caisson", _write(tmp_path, NO_LIFE)])
    assert "with Takahashi's impulsive coefficient alpha_I ([caisson] impulsive = true, the default)" in r.stdout
    off = NO_LIFE.replace("# impulsive = true", "impulsive = false")
    r = run_cli(["caisson", _write(tmp_path, off, "off.toml")])
    assert "without Takahashi's impulsive coefficient ([caisson] impulsive = false)" in r.stdout
    assert json.loads(run_cli(["caisson", str(tmp_path / "off.toml"), "--json"]).stdout)["impulsive"] is False


def test_the_inputs_are_echoed_as_written(run_cli, tmp_path):
    text = NO_LIFE.replace("depth = 10.1", "depth = 10.10").replace("H0 = 6.3", "H0 = 6.30")
    r = run_cli(["caisson", _write(tmp_path, text)])
    lines = r.stdout.splitlines()
    assert lines[1].startswith("  [site] depth = 10.10, armour_depth = 5.6,")
    assert lines[2].startswith("  [wave] H0 = 6.30, period = 11.4")
    assert "wave length of T1/3 at h = 10.10 m" in r.stdout


# -- the sheet --------------------------------------------------------------------------------


def _texts(fig):
    out = list(fig.texts)
    for ax in fig.axes:
        out.extend(ax.texts)
        out.append(ax.title)
        out.append(ax._left_title)  # noqa: SLF001 - the panel titles are loc="left"
    return out


@pytest.mark.render
@pytest.mark.parametrize("text", [NO_LIFE, WIDE])
@pytest.mark.deep
def test_the_sheet_shows_the_verdict(text):
    import matplotlib.colors as mcolors

    from regimemap.drawing.verdict import FAIL_COLOUR, PASS_COLOUR
    from tests.conftest import draw_sheet

    r = caisson_report(parse_design(text).analysis_inputs())
    checks = caisson_checks(r)
    fig = draw_sheet(r, checks=checks)
    fails = not checks[0].passed
    badge = [t for t in fig.texts if t.get_text().startswith(("PASS", "FAIL"))]
    assert len(badge) == 1
    assert badge[0].get_text() == ("FAIL (1 of 2)" if fails else "PASS")
    box = badge[0].get_bbox_patch()
    assert box is not None
    assert mcolors.same_color(box.get_facecolor(), FAIL_COLOUR if fails else PASS_COLOUR)
    (table,) = [a for a in fig.axes if a.get_label() == "table"]
    value = f"{checks[0].value:.4g}".ljust(5, "0")
    (number,) = [t for t in table.texts if t.get_text() == value]
    assert mcolors.same_color(number.get_color(), FAIL_COLOUR if fails else "black")
    (over,) = [t for t in table.texts if t.get_text() == f"{checks[1].value:.4g}"]
    assert mcolors.same_color(over.get_color(), "black")
    heads = [t.get_text() for t in fig.texts]
    assert any("Takahashi's \u03b1$_I$ (impulsive = true)" in h for h in heads)


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_the_sheet_flags_the_lifetime_esd(tmp_path):
    import matplotlib.colors as mcolors

    from regimemap.caisson.figures.page import LIFETIME_PANEL
    from regimemap.drawing.verdict import FAIL_COLOUR
    from regimemap.lifetime import Requirements, judge_lifetime, lifetime_sliding
    from tests.conftest import draw_sheet

    d = parse_design(EXAMPLE.replace("trials = 5000", "trials = 200"))
    r = caisson_report(d.analysis_inputs())
    life = judge_lifetime(lifetime_sliding(d.lifetime_caisson(), d.lifetime_model(), 200, 2026),
                          Requirements(target=0.1))
    checks = [*caisson_checks(r), *life.checks]
    assert checks[2].value > 0.1  # Goda's caisson slides about a metre in 50 years
    fig = draw_sheet(r, lifetime=life, checks=checks, lifetime_impulsive=False)
    (ax,) = [a for a in fig.axes if a.get_label() == LIFETIME_PANEL]
    (esd,) = [t for t in ax.texts if t.get_text().startswith("ESD")]
    assert mcolors.same_color(esd.get_color(), FAIL_COLOUR)
    assert ax.get_title(loc="left").endswith("without \u03b1$_I$")
    assert [t.get_text() for t in fig.texts if t.get_text().startswith("FAIL")] == ["FAIL (2 of 3)"]
    assert any("(g) without it ([lifetime] impulsive = false)" in t.get_text() for t in fig.texts)


def test_check_dataclass_is_what_the_sheet_reads():
    assert Check.at_least("sliding safety factor", 1.16, 1.2).verdict == "FAIL"


# -- simulate --design ------------------------------------------------------------------------


@pytest.mark.parametrize(("text", "check", "code"), [(NO_LIFE, True, 1), (NO_LIFE, False, 0), (WIDE, True, 0)])
@pytest.mark.slow
@pytest.mark.deep
def test_simulate_design_check(run_cli, tmp_path, text, check, code):
    path = _write(tmp_path, text)
    args = ["simulate", "--design", path, *(["--check"] if check else [])]
    r = run_cli(args)
    assert r.code == code, r.stderr
    sliding, _ = _sf(text)
    verdict = "PASS" if sliding >= 1.2 else "FAIL"
    assert f"{verdict}  sliding safety factor {sliding:.4g} >= 1.2" in r.stdout.splitlines()
    obj = json.loads(run_cli([*args, "--json"]).stdout)
    assert [c["name"] for c in obj["checks"]] == ["sliding safety factor", "overturning safety factor"]
    assert obj["checks"][0]["pass"] is (sliding >= 1.2)


def test_simulate_check_needs_a_design_file(run_cli):
    r = run_cli(["simulate", "--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--mu", "5", "--pulse",
                 "half-sine", "--k-peak", "0.5", "--duration", "0.5", "--check"])
    assert r.code == 2 and "--check checks a design file's requirements" in r.stderr


@pytest.mark.render
@pytest.mark.parametrize("text", [NO_LIFE, WIDE])
def test_the_onset_label_stays_inside_panel_e(text):
    from tests.conftest import draw_sheet

    fig = draw_sheet(caisson_report(parse_design(text).analysis_inputs()))
    (ax,) = [a for a in fig.axes if a.get_label() == "path"]
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    (label,) = [t for t in ax.texts if "from" in t.get_text()]
    box, inside = label.get_window_extent(renderer), ax.get_window_extent(renderer)
    assert inside.x0 <= box.x0 and box.x1 <= inside.x1


@pytest.mark.render
def test_the_sheet_header_echoes_the_file():
    from tests.conftest import draw_sheet

    d = parse_design(NO_LIFE.replace("H0 = 6.3 ", "H0 = 6.30 ").replace("friction = 0.6 ", "friction = 0.60 "))
    fig = draw_sheet(caisson_report(d.analysis_inputs()), written=d.written)
    (head,) = [t.get_text() for t in fig.texts if "T\u2081/\u2083" in t.get_text()]
    assert head.startswith("H\u2080\u2032 = 6.30 m, T\u2081/\u2083 = 11.4 s,") and "\u03bc = 0.60," in head


@pytest.mark.render
@pytest.mark.deep
def test_the_requirements_do_not_depend_on_the_sheet(run_cli, tmp_path):
    path = _write(tmp_path, EXAMPLE.replace("trials = 5000", "trials = 100"))
    plain = run_cli(["caisson", path, "--check", "--json"])
    sheet = run_cli(["caisson", path, "--check", "--json", "-o", str(tmp_path / "sheet.png")])
    assert plain.code == sheet.code == 1, plain.stderr + sheet.stderr
    checks = json.loads(plain.stdout)["checks"]
    assert [c["name"] for c in checks] == ["sliding safety factor", "overturning safety factor",
                                           "expected sliding distance"]
    assert json.loads(sheet.stdout)["checks"] == checks
    text = run_cli(["caisson", path, "--check"]).stdout.splitlines()
    assert "FAIL  expected sliding distance" in text[-3] and text[-1].startswith("verdict: FAIL (2 of 3")
