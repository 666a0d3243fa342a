"""The design file's hard limits (errors, exit 2), the line of every refused key, and the values
echoed as the file writes them."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from regimemap.caisson.file import DesignFileError, example_design_text, parse_design
from regimemap.io.toml_lines import key_line

EXAMPLE = example_design_text()


def _replace(old: str, new: str) -> str:
    text = re.sub(rf"^{re.escape(old)}(?=[ \t]|$)", new, EXAMPLE, count=1, flags=re.MULTILINE)
    assert text != EXAMPLE
    return text


def _write(tmp_path, text, name="goda.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


LIMITS = [
    ("H0 = 6.3", "H0 = 1e300", "wave", "H0", "1e300", "above 30 m"),
    ("H0 = 6.3", "H0 = 630", "wave", "H0", "630", "centimetres for metres"),
    ("period = 11.4", "period = 0.5", "wave", "period", "0.5", "shorter than 1 s"),
    ("period = 11.4", "period = 40", "wave", "period", "40", "longer than 30 s"),
    ("depth = 10.1", "depth = 0", "site", "depth", "0", "shallower than 0.5 m"),
    ("depth = 10.1", "depth = 500", "site", "depth", "500", "deeper than 100 m"),
    ("width = 15.0", "width = 1e300", "caisson", "width", "1e300", "above 500 m"),
    ("crest = 3.4", "crest = 1e300", "caisson", "crest", "1e300", "above 100 m"),
    ("buoyant_weight = 2312", "buoyant_weight = 1e300", "caisson", "buoyant_weight", "1e300", "kN/m"),
    # a caisson that weighs nothing in water floats (buoyancy 1: no equivalent block)
    ("buoyant_weight = 2312", "buoyant_weight = 1e-300", "caisson", "buoyant_weight", "1e-300",
     "below 0.001 kN/m, a caisson that floats"),
    ("buoyant_weight = 2312", "buoyant_weight = 0", "caisson", "buoyant_weight", "0", "below 0.001 kN/m"),
    ("armour_depth = 5.6", "armour_depth = 1e-300", "site", "armour_depth", "1e-300", "below 0.01 m"),
]


@pytest.mark.parametrize(("old", "new", "table", "key", "written", "why"), LIMITS)
def test_hard_limits_exit_2_naming_line_key_value_limit_and_why(run_cli, tmp_path, old, new, table, key,
                                                                 written, why):
    text = _replace(old, new)
    path = _write(tmp_path, text)
    r = run_cli(["caisson", path, "-o", str(tmp_path / "sheet.png")])
    assert r.code == 2 and r.stdout == "" and "Traceback" not in r.stderr
    (line,) = r.stderr.strip().splitlines()
    n = key_line(text, table, key)
    assert f"{path}, line {n}: [{table}] {key} = {written}: out of range, " in line
    assert why in line and "; accepted: " in line
    assert not (tmp_path / "sheet.png").exists()


def test_the_limits_hold_for_simulate_design_too(run_cli, tmp_path):
    path = _write(tmp_path, _replace("period = 11.4", "period = 40"))
    r = run_cli(["simulate", "--design", path])
    assert r.code == 2 and "'--design'" in r.stderr and "[wave] period = 40: out of range" in r.stderr


def test_values_inside_the_limits_are_accepted():
    for old, new in (("period = 11.4", "period = 1"), ("period = 11.4", "period = 30"),
                     ("H0 = 6.3", "H0 = 30"), ("depth = 10.1", "depth = 100")):
        parse_design(_replace(old, new))


@pytest.mark.parametrize(("old", "new", "table", "key", "message"), [
    ("width = 15.0", "widht = 15.0", "caisson", "widht", "unknown key [caisson] widht (did you mean 'width'?)"),
    ("depth = 10.1", "depht = 10.1", "site", "depht", "unknown key [site] depht (did you mean 'depth'?)"),
    ("angle = 15", "angle = 95", "wave", "angle", "[wave] angle = 95: out of range"),
    ("friction = 0.6", "friction = true", "caisson", "friction", "[caisson] friction = true: expected a number"),
    # a friction below 0.01 is no caisson's (and the lifetime's sliding overflows)
    ("friction = 0.6", "friction = 1e-300", "caisson", "friction",
     "[caisson] friction = 1e-300: out of range; accepted: a friction coefficient 0.01 <= friction <= 2"),
    ("H0 = 6.3", "H0 = 6.3\nH13 = 5.0", "wave", "H0", "[wave] H0 = 6.3 together with"),
    ("depth = 10.1", "depth = 6.0", "caisson", "base_depth", "[caisson] base_depth = 7.1: the base"),
    ("armour_depth = 5.6", "armour_depth = 7.5", "site", "armour_depth", "[site] armour_depth = 7.5: the top"),
])
def test_every_error_names_its_line(old, new, table, key, message):
    text = _replace(old, new)
    with pytest.raises(DesignFileError) as info:
        parse_design(text, "goda.toml")
    n = key_line(text, table, key)
    lines = text.splitlines()
    assert n is not None and lines[n - 1].lstrip().startswith(key)
    assert str(info.value).startswith(f"goda.toml, line {n}: {message}")


def test_a_missing_key_names_its_table_line():
    text = _replace("period = 11.4", "")
    with pytest.raises(DesignFileError, match=r"^goda\.toml, line 13: \[wave\] period is missing"):
        parse_design(text, "goda.toml")
    assert text.splitlines()[12] == "[wave]"


def test_values_are_kept_as_written():
    d = parse_design(_replace("depth = 10.1", "depth = 10.10").replace("width = 15.0", "width = 1.5e1"))
    assert d.as_written("site", "depth") == "10.10" and d.site.depth == 10.1
    assert d.as_written("caisson", "width") == "1.5e1" and d.as_written("caisson", "impulsive") is None
    with pytest.raises(DesignFileError, match=r"\[wave\] period = 4\.0e1: out of range"):
        parse_design(_replace("period = 11.4", "period = 4.0e1"))


@pytest.mark.subprocess
@pytest.mark.parametrize("old,new", [("H0 = 6.3", "H0 = 30"), ("period = 11.4", "period = 1"),
                                     ("width = 15.0", "width = 0.05"), ("depth = 10.1", "depth = 100"),
                                     ("crest = 3.4", "crest = 100"), ("armour_depth = 5.6", "armour_depth = 0.01")])
def test_no_runtime_warning_reaches_the_user(tmp_path, old, new):
    """At the limits, the caisson command runs with RuntimeWarnings as errors: none is raised."""
    path = _write(tmp_path, _replace(old, new).split("[lifetime]")[0])
    run = subprocess.run([sys.executable, "-W", "error::RuntimeWarning", "-m", "regimemap", "caisson", path,
                          "--json"], capture_output=True, text=True, check=False)
    assert "RuntimeWarning" not in run.stderr and "internal error" not in run.stderr, run.stderr
    assert run.returncode in (0, 1, 2), run.stderr


@pytest.mark.render
@pytest.mark.subprocess
@pytest.mark.parametrize("old,new", [("buoyant_weight = 2312", "buoyant_weight = 1e7"),
                                     ("width = 15.0", "width = 500")])
@pytest.mark.deep
def test_the_sheet_draws_at_the_limits(tmp_path, old, new):
    """The heaviest and the widest section accepted still draw their sheet, warnings and all."""
    path = _write(tmp_path, _replace(old, new).split("[lifetime]")[0])
    sheet = tmp_path / "sheet.png"
    run = subprocess.run([sys.executable, "-W", "error::RuntimeWarning", "-m", "regimemap", "caisson", path,
                          "-o", str(sheet)], capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert sheet.is_file() and "internal error" not in run.stderr
