"""Reading a design file's text: a UTF-8 byte order mark accepted in every TOML the tool reads (design,
study, a study's base), and the errors of ``[lifetime.record]`` on the line of the key they blame."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from regimemap.caisson.file import DesignFileError, example_design_text, read_design
from regimemap.lifetime.file_record import analysis_fault
from regimemap.study.file import read_study
from regimemap.study.file_example import example_study_text

EXAMPLE = example_design_text()
BOM = "\ufeff"
EXCERPT = Path(__file__).parents[1] / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"
CLIMATE_KEYS = ("H0_10", "H0_50", "annual_maxima", "distribution", "shape", "storms_per_year")


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_a_design_file_with_a_bom_reads_as_without(tmp_path):
    plain = read_design(_write(tmp_path / "plain.toml", EXAMPLE))
    marked = read_design(_write(tmp_path / "bom.toml", BOM + EXAMPLE))
    assert (tmp_path / "bom.toml").read_bytes()[:3] == b"\xef\xbb\xbf"
    assert (marked.site, marked.wave, marked.caisson, marked.lifetime) == (
        plain.site, plain.wave, plain.caisson, plain.lifetime)


def test_a_bom_keeps_the_lines_of_the_errors(tmp_path):
    text = EXAMPLE.replace("depth = 10.1", "depth = 1010", 1)
    with pytest.raises(DesignFileError) as plain:
        read_design(_write(tmp_path / "plain.toml", text))
    with pytest.raises(DesignFileError) as marked:
        read_design(_write(tmp_path / "bom.toml", BOM + text))
    assert ", line 8: [site] depth = 1010" in str(plain.value)
    assert str(marked.value) == str(plain.value).replace("plain.toml", "bom.toml")


@pytest.mark.slow
def test_the_commands_accept_a_design_file_with_a_bom(run_cli, tmp_path):
    plain = run_cli(["caisson", str(_write(tmp_path / "goda.toml", EXAMPLE))])
    marked = run_cli(["caisson", str(_write(tmp_path / "bom.toml", BOM + EXAMPLE))])
    assert marked.code == 0, marked.stderr
    assert marked.stdout == plain.stdout.replace("goda.toml", "bom.toml")


def test_a_study_and_its_base_with_a_bom(tmp_path):
    plain = read_study(_write(tmp_path / "plain.toml", example_study_text()))
    marked = read_study(_write(tmp_path / "bom.toml", BOM + example_study_text()))
    assert marked.study_hash == plain.study_hash
    assert [s.design.caisson for s in marked.sections] == [s.design.caisson for s in plain.sections]
    _write(tmp_path / "goda.toml", BOM + EXAMPLE)
    study = _write(tmp_path / "study.toml", 'base = "goda.toml"\n[[section]]\nname = "a"\nchainage = 0.0\n'
                   '[[scenario]]\nname = "today"\n')
    assert read_study(study).sections[0].design.site.depth == 10.1


def _record_design(tmp_path: Path, record: str) -> tuple[Path, list[str]]:
    """The example design with its climate as ``[lifetime.record]`` (lines ``record``), beside the
    excerpt of 44007 (one year)."""
    shutil.copy(EXCERPT, tmp_path / "buoy.txt.gz")
    i, j = EXAMPLE.index("[lifetime]"), EXAMPLE.index("[lifetime.errors]")
    kept = [line for line in EXAMPLE[i:j].splitlines() if line.split("=")[0].strip() not in CLIMATE_KEYS]
    text = EXAMPLE[:i] + "\n".join(kept) + "\n\n[lifetime.record]\n" + record + "\n\n" + EXAMPLE[j:]
    return _write(tmp_path / "site.toml", text), text.splitlines()


@pytest.mark.parametrize(("record", "line_of", "message"), [
    ('path = "buoy.txt.gz"\nthreshold = 6.5', "threshold = 6.5",
     "[lifetime.record] threshold = 6.5: 1 storm(s) above the threshold 6.5 m: a fit needs at least 10"),
    ('path = "buoy.txt.gz"\nthreshold = "99.99%"', 'threshold = "99.99%"',
     '[lifetime.record] threshold = "99.99%": '),
    ('path = "buoy.txt.gz"\nthreshold = 99.5', "threshold = 99.5",
     '[lifetime.record] threshold = 99.5: above any sea state (Hs at most 30 m); did you mean "99.5%"?'),
    ('path = "absent.csv"', 'path = "absent.csv"', '[lifetime.record] path = "absent.csv": '),
    ('path = "buoy.txt.gz"\nmethod = "annual-maxima"\ncoverage = 0.9', "coverage = 0.9",
     "[lifetime.record] coverage = 0.9: 1 annual maxima: a fit needs at least 5 years (lower coverage,"),
    ('path = "buoy.txt.gz"\nmethod = "annual-maxima"', "[lifetime.record]",
     "[lifetime.record]: 1 annual maxima: a fit needs at least 5 years"),
])
def test_record_errors_name_the_line_of_their_key(tmp_path, record, line_of, message):
    path, lines = _record_design(tmp_path, record)
    line = 1 + next(n for n, text in enumerate(lines) if text.startswith(line_of))
    with pytest.raises(DesignFileError) as err:
        read_design(path)
    assert str(err.value).startswith(f"{path}, line {line}: {message}"), str(err.value)
    assert "[lifetime]:" not in str(err.value)


def test_the_period_ratio_error_names_its_line(tmp_path):
    csv = tmp_path / "noperiod.csv"
    hours = np.arange(400 * 24)
    times = np.datetime64("2000-01-01T00", "h") + hours
    csv.write_text("time,hs\n" + "".join(f"{t},{1.0 + (k % 97) / 30:.3f}\n" for t, k in zip(times.astype(str), hours)))
    path, lines = _record_design(tmp_path, 'path = "noperiod.csv"\nthreshold = 3.0\nperiod_ratio = 1.2')
    line = 1 + lines.index("period_ratio = 1.2")
    with pytest.raises(DesignFileError, match=rf"site.toml, line {line}: \[lifetime.record\] period_ratio = 1.2: "
                       r".*noperiod.csv gives no period"):
        read_design(path)


@pytest.mark.parametrize(("message", "fault"), [
    ("threshold 8 m is at or above every height of the record (largest 7.1 m)", "threshold"),
    ("4 storm(s) above the threshold 6.5 m: a fit needs at least 10", "threshold"),
    ("0 annual maxima: a fit needs at least 5 years", "coverage"),
    ("return period 1.01 years is shorter than the mean time between storms (2 years)", "return_periods"),
    ("buoy.csv: 0.08 years observed; an extreme-value analysis needs at least 1 year", None),
])
def test_analysis_fault(message, fault):
    assert analysis_fault(message) == fault


def test_each_key_is_declared_once_as_a_field_of_its_table():
    """DESIGN_KEYS, the reading of a table and the example's tables all come from the fields of the
    tables' dataclasses: the keys in the order declared, a key's default its field's, its lines in
    the example its own (each naming its key), every required key shown in the example."""
    import dataclasses
    import re

    from regimemap.caisson.file_keys import DESIGN_KEYS, DESIGN_TABLES, design_reader, example_tables

    text = example_tables()
    assert text in example_design_text()
    for table, cls in DESIGN_TABLES.items():
        names = [f.name for f in dataclasses.fields(cls)]
        assert list(DESIGN_KEYS[table]) == names
        assert f"[{table}]\n" in text
        for f in dataclasses.fields(cls):
            spec = DESIGN_KEYS[table][f.name]
            assert spec.required == (f.default is dataclasses.MISSING), f.name
            if spec.example:
                first = next(line for line in spec.example.splitlines() if f"{f.name} = " in line)
                assert re.match(rf"(# )?{f.name} = ", first), f.name
                assert spec.example in text
            else:
                assert not spec.required, f"required [{table}] {f.name} has no example line"
    # the reader fills a table from its fields: given keys, defaults for the others, in order
    r = design_reader("x.toml", "")
    site = r.table("site", {"depth": 10.0, "armour_depth": 5.0, "seabed_slope": 0.01}, DESIGN_TABLES["site"])
    assert site == DESIGN_TABLES["site"](depth=10.0, armour_depth=5.0, seabed_slope=0.01)
    assert site.water_density == 1030.0
    with pytest.raises(DesignFileError, match=r"x.toml: \[site\] armour_depth is missing; accepted: a depth"):
        r.table("site", {"depth": 10.0}, DESIGN_TABLES["site"])
