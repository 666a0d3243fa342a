"""The caisson workflow: run_caisson's record, its notices, its errors, and the command that calls it."""

from __future__ import annotations

from pathlib import Path

import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.caisson.record import caisson_numbers
from regimemap.caisson.report import caisson_checks, caisson_report
from regimemap.workflows import (
    CaissonError,
    CaissonRecord,
    ImplausibleDesignError,
    Notice,
    run_caisson,
)

EXAMPLE = example_design_text()
NO_LIFE = EXAMPLE[:EXAMPLE.index("[lifetime]")]
SLIP = NO_LIFE.replace("buoyant_weight = 2312", "buoyant_weight = 2312000")
DEEP = NO_LIFE.replace("depth = 10.1 ", "depth = 80 ")


def _write(tmp_path: Path, text: str, name: str = "goda.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _fail_analysis(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make Goda's analysis fail, as a caisson outside the loaded map's ranges does."""
    def refuse(inputs: object) -> None:
        raise ValueError("gamma must be a finite number in [0.001, 1000], got 2000")

    monkeypatch.setattr("regimemap.caisson.run.caisson_report", refuse)


@pytest.mark.slow
def test_the_record_holds_what_the_report_prints(tmp_path: Path) -> None:
    path = _write(tmp_path, NO_LIFE)
    r = run_caisson(path)
    report = caisson_report(parse_design(NO_LIFE).analysis_inputs())
    assert isinstance(r, CaissonRecord) and r.design.source == str(path)
    assert vars(r.numbers) == caisson_numbers(report)
    assert list(r.checks) == caisson_checks(report, (1.2, 1.2))
    assert (r.mode, r.verdict, r.passed) == ("RE", "FAIL", False)  # SF sliding 1.16 < 1.2
    assert (r.design_point.k, r.design_point.mu) == (report.k, report.mu)
    assert r.parameters == report.map.parameters()
    assert r.notices == () and r.view is None and r.map_data is None and r.lifetime is None
    assert r.lifetime_impulsive is None
    # a path and the design it holds give the same record
    same = run_caisson(r.design)
    assert same.numbers == r.numbers and same.checks == r.checks


def test_a_file_that_is_no_design_is_refused(tmp_path: Path) -> None:
    from regimemap.caisson.file import DesignFileError

    with pytest.raises(DesignFileError, match="line 22: unknown key"):
        run_caisson(_write(tmp_path, NO_LIFE.replace("width = 15.0", "widht = 15.0")))
    with pytest.raises(DesignFileError, match="cannot read the design file"):
        run_caisson(tmp_path / "missing.toml")


def test_the_required_factors_of_the_file_decide_the_verdict() -> None:
    text = NO_LIFE.replace("friction = 0.6", "friction = 0.6\nrequired_sliding = 1.1")
    r = run_caisson(parse_design(text))
    assert r.required == (1.1, 1.2) and r.verdict == "PASS" and r.checks[0].required == 1.1


def test_implausible_values_are_notices() -> None:
    r = run_caisson(parse_design(SLIP, source="slip.toml"))
    assert [(n.code, n.quantity) for n in r.notices] == [
        ("implausible-value", "caisson.buoyant_weight"), ("implausible-value", "heel_pressure")]
    assert r.notices[0].value == 2312000.0 and "N/m for kN/m?" in r.notices[0].message
    assert all(isinstance(n, Notice) for n in r.notices)


def test_strict_refuses_them() -> None:
    with pytest.raises(ImplausibleDesignError) as info:
        run_caisson(parse_design(SLIP, source="slip.toml"), strict=True)
    assert isinstance(info.value, ValueError)
    assert [n.quantity for n in info.value.notices] == ["caisson.buoyant_weight", "heel_pressure"]
    assert str(info.value).startswith("slip.toml: [caisson] buoyant_weight = 2312000: ")
    assert str(info.value).endswith(" (and 1 more); strict refuses implausible values")
    assert run_caisson(parse_design(NO_LIFE), strict=True).notices == ()


def test_a_failed_analysis_carries_the_inputs_notices(monkeypatch: pytest.MonkeyPatch) -> None:
    _fail_analysis(monkeypatch)
    with pytest.raises(CaissonError) as info:
        run_caisson(parse_design(DEEP))
    assert not isinstance(info.value, ImplausibleDesignError)
    assert str(info.value).startswith("gamma must be")
    assert [n.quantity for n in info.value.notices] == ["site.depth"]
    with pytest.raises(ImplausibleDesignError):  # strict: the implausible input is the answer
        run_caisson(parse_design(DEEP), strict=True)
    with pytest.raises(CaissonError) as plain:  # strict, nothing implausible: the failure itself
        run_caisson(parse_design(NO_LIFE), strict=True)
    assert not isinstance(plain.value, ImplausibleDesignError) and plain.value.notices == ()


def test_the_sheet_map_without_a_lifetime() -> None:
    r = run_caisson(parse_design(NO_LIFE), sheet=True)
    assert r.view is not None and r.map_data is not None and r.lifetime is None
    assert (r.map_data.k_max, r.map_data.mu_max) == (r.view.k_max, r.view.mu_max)
    assert len(r.checks) == 2


def test_the_sheet_lifetime_joins_the_checks() -> None:
    text = EXAMPLE.replace("trials = 5000", "trials = 100")
    r = run_caisson(parse_design(text), sheet=True, jobs=1)
    assert r.lifetime is not None and r.lifetime.trials == 100
    assert [c.name for c in r.checks][:3] == ["sliding safety factor", "overturning safety factor",
                                              "expected sliding distance"]
    assert r.lifetime_impulsive is False and r.verdict == "FAIL"
    plain = run_caisson(parse_design(text), jobs=1)  # the requirements do not depend on the sheet
    assert plain.checks == r.checks and plain.lifetime is not None


def test_the_html_display_reads_the_field_table() -> None:
    r = run_caisson(parse_design(SLIP))
    html = r._repr_html_()
    for f in CaissonRecord.FIELDS:
        assert f">{f.label.replace(chr(39), '&#x27;')}</th>" in html
    assert "warning: implausible-value" in html
    rows = dict((label, value) for label, value, _, _ in r.field_rows())
    assert rows["mode"] == "RE" and rows["k'"] == r.numbers.kprime


@pytest.mark.render
def test_the_sheet_needs_the_sheet_map() -> None:
    from regimemap.caisson.figures.page import caisson_sheet

    with pytest.raises(ValueError, match="sheet=True"):
        caisson_sheet(run_caisson(parse_design(NO_LIFE)))


# -- the command line: the record's notices and errors as lines and exit statuses --------------------

def test_cli_a_failed_analysis_warns_then_fails(run_cli, tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    _fail_analysis(monkeypatch)
    path = str(_write(tmp_path, DEEP, "deep.toml"))
    run = run_cli(["caisson", path])
    assert run.code == 1 and run.stdout == ""
    assert run.stderr.splitlines() == [
        f"regimemap: warning: {path}: [site] depth = 80: deeper than 70 m, deeper than any caisson "
        "breakwater built (Kamaishi's stands in 63 m)",
        f"regimemap: error: {path}: gamma must be a finite number in [0.001, 1000], got 2000"]
    strict = run_cli(["caisson", path, "--strict"])
    assert strict.code == 2 and "warning" not in strict.stderr
    assert f"'DESIGN.toml': {path}: [site] depth = 80: " in strict.stderr
    explore = run_cli(["explore", "--design", path, "-o", str(tmp_path / "x.png")])
    assert explore.code == 2 and "'--design': " + path + ": gamma must be" in explore.stderr
    assert "warning: " + path + ": [site] depth = 80" in explore.stderr


def test_cli_strict_names_the_first_and_counts_the_rest(run_cli, tmp_path: Path) -> None:
    path = str(_write(tmp_path, SLIP, "slip.toml"))
    run = run_cli(["caisson", path, "--strict", "--json"])
    assert run.code == 2 and run.stdout == ""
    assert (f"Invalid value for 'DESIGN.toml': {path}: [caisson] buoyant_weight = 2312000: implies"
            in run.stderr)
    assert "(and 1 more); --strict refuses implausible values" in run.stderr
    warned = run_cli(["caisson", path, "--json"])
    assert warned.code == 0 and warned.stderr.count("regimemap: warning: ") == 2


def test_each_number_is_declared_once_and_every_output_reads_the_declaration() -> None:
    """The text's rows, the JSON's numbers and units, and the notebook's table come from the fields
    of CaissonNumbers: a row the text prints between its first heading and the mode is a declared
    number, in the declared order, with its declared unit and words."""
    from dataclasses import fields

    from regimemap.caisson.record import NUMBERS, UNITS, CaissonNumbers, caisson_json, format_caisson
    from regimemap.caisson.report import caisson_report as report_of

    report = report_of(parse_design(NO_LIFE).analysis_inputs())
    assert list(caisson_numbers(report)) == [f.name for f in fields(CaissonNumbers)] == list(NUMBERS)
    assert UNITS == {name: s.unit for name, s in NUMBERS.items() if s.unit} and UNITS["Mp"] == "kN*m/m"
    out = caisson_json(report)
    assert all(name in out for name in NUMBERS) and out["units"] == UNITS
    text = format_caisson(report).splitlines()
    body = text[text.index("design wave at the wall (Goda 2000)"):
                next(i for i, line in enumerate(text) if line.startswith("mode on the loaded map"))]
    rows = [line for line in body if line.startswith("  ") and not line.startswith("  alpha1")]
    shown = [s for s in NUMBERS.values() if s.label]
    assert [r[2:16].rstrip() for r in rows] == [s.label for s in shown]
    assert all(r[27:35].rstrip() == s.unit.replace("*", " ") for r, s in zip(rows, shown, strict=True))
    assert "  k'            -0.0180155          (Mp/P - H_C)/H_C: P acts 0.0946 m below the centre of mass" in text
    record = run_caisson(parse_design(NO_LIFE))
    table = [row[0] for row in record.field_rows()]
    assert table == [s.label for s in shown] + ["mode", "verdict"]
    assert record.field_rows()[2][3] == "wave length of T1/3 at h = 10.1 m"


def test_a_heel_pressure_with_no_equilibrium_reads_n_a_and_why_never_inf() -> None:
    # W' far below U: the resultant falls outside the base, Goda's heel pressure is infinite
    from regimemap.caisson.record import caisson_json, format_caisson

    light = parse_design(NO_LIFE.replace("buoyant_weight = 2312", "buoyant_weight = 1"))
    record = run_caisson(light)
    assert record.numbers.heel_pressure == float("inf")
    text = format_caisson(record.report, "goda.toml")
    (row,) = [ln for ln in text.splitlines() if ln.lstrip().startswith("heel pressure")]
    assert row.split()[2:4] == ["n/a", "kPa"] and "the resultant falls outside the base" in row
    assert "inf" not in text.replace("infinite", "")
    assert caisson_json(record.report)["heel_pressure"] is None
    # a caisson in equilibrium keeps the words of its number
    normal = format_caisson(run_caisson(parse_design(NO_LIFE)).report, "goda.toml")
    assert "bearing pressure at the heel" in normal and "n/a" not in normal
