"""The TOML design file: the example reproduces Goda's caisson; each kind of error says what and where."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from regimemap.caisson.file import DesignFileError, example_design_text, parse_design, read_design

EXAMPLE = example_design_text()


def edit(text: str, old: str, new: str) -> str:
    """Replace one whole line ``old`` (up to its comment) by ``new``."""
    pattern = re.compile(rf"^{re.escape(old)}[ \t]*(#.*)?$", re.MULTILINE)
    out, n = pattern.subn(new, text)
    assert n == 1, old
    return out


def error_of(text: str, tmp_path: Path) -> str:
    path = tmp_path / "breakwater.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(DesignFileError) as info:
        read_design(path)
    msg = str(info.value)
    assert str(path) in msg
    return msg


def test_example_reproduces_the_worked_example(tmp_path: Path) -> None:
    path = tmp_path / "goda.toml"
    path.write_text(EXAMPLE, encoding="utf-8")
    d = read_design(path)
    assert d.site.depth == 10.1 and d.wave.H0 == 6.3 and d.caisson.buoyant_weight == 2312
    a = d.analyse()
    assert f"{float(a.heights.H13):.3g}" == "5.8"
    assert f"{float(a.heights.Hmax):.3g}" == "8.05"
    assert f"{float(a.pressures.p1) / 1e3:.3g}" == "97.6"
    assert f"{float(a.loads.P) / 1e3:.3g}" == "941"
    assert f"{float(a.loads.U) / 1e3:.3g}" == "493"
    assert f"{float(a.stability.sliding):.3g}" == "1.16"
    assert f"{float(a.stability.overturning):.3g}" == "2.56"


def test_densities_instead_of_weight() -> None:
    text = edit(EXAMPLE, "buoyant_weight = 2312", "concrete_fraction = 0.25\nconcrete_density = 2400\n"
                "fill_density = 2000")
    d = parse_design(text)
    assert d.caisson.buoyant_weight is None and d.caisson.fill_density == 2000
    a = d.analyse()
    assert float(a.section.buoyant_weight) > 0


def test_heights_given_directly() -> None:
    text = edit(EXAMPLE, "H0 = 6.3", "H13 = 5.8\nHmax = 8.05")
    a = parse_design(text).analyse()
    assert float(a.heights.Hmax) == 8.05


def test_missing_key(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "period = 11.4", ""), tmp_path)
    assert "line 13: [wave] period is missing" in msg and "1 <= T1/3 <= 30 in seconds" in msg


def test_missing_wave_height(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "H0 = 6.3", ""), tmp_path)
    assert "[wave] H0 is missing" in msg and "both H13 and Hmax" in msg
    msg = error_of(edit(EXAMPLE, "H0 = 6.3", "H13 = 5.8"), tmp_path)
    assert "[wave] Hmax is missing" in msg


def test_wrong_type(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "width = 15.0", 'width = "15 m"'), tmp_path)
    assert '[caisson] width = "15 m"' in msg and "expected a number, found a string" in msg  # as written
    assert "full width 0.05 <= width <= 500 in metres" in msg
    msg = error_of(edit(EXAMPLE, "friction = 0.6", "friction = true"), tmp_path)
    assert "[caisson] friction = true" in msg and "expected a number" in msg


def test_negative_depth(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "depth = 10.1", "depth = -10.1"), tmp_path)
    assert "[site] depth = -10.1" in msg and "out of range" in msg and "0.5 <= h <= 100" in msg


def test_crest_below_water(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "crest = 3.4", "crest = -0.5"), tmp_path)
    assert "[caisson] crest = -0.5" in msg and "0 <= hc <= 100" in msg and "not below the water" in msg


def test_base_deeper_than_water(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "base_depth = 7.1", "base_depth = 12.0"), tmp_path)
    assert "[caisson] base_depth = 12.0" in msg
    assert "deeper than the water" in msg and "accepted: 0 < base_depth <= [site] depth = 10.1" in msg


def test_armour_depth_below_base(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "armour_depth = 5.6", "armour_depth = 8.0"), tmp_path)
    assert "[site] armour_depth = 8.0" in msg
    assert "accepted: 0 < armour_depth <= [caisson] base_depth = 7.1" in msg


def test_typo_suggests_the_key(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "base_depth = 7.1", "base_dept = 7.1"), tmp_path)
    assert "unknown key [caisson] base_dept" in msg and "did you mean 'base_depth'?" in msg
    msg = error_of(edit(EXAMPLE, "seabed_slope = 0.01", "sea_bed_slope = 0.01"), tmp_path)
    assert "unknown key [site] sea_bed_slope" in msg and "did you mean 'seabed_slope'?" in msg
    msg = error_of(edit(EXAMPLE, "[caisson]", "[caison]"), tmp_path)
    assert "unknown table [caison]" in msg and "did you mean 'caisson'?" in msg
    # a key above every table (a study file given as a design file) is a key, not a table
    msg = error_of("seed = 2026\n" + EXAMPLE, tmp_path)
    assert ", line 1: unknown key seed above the tables; a design file has only the tables [site]," in msg


def test_unknown_key_without_suggestion(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "angle = 15", "angle = 15\ncolour = 3"), tmp_path)
    assert "unknown key [wave] colour" in msg and "did you mean" not in msg
    assert "accepted keys in [wave]: H0, H13, Hmax, period, angle, rotation" in msg


def test_toml_syntax_error_has_line_number(tmp_path: Path) -> None:
    text = edit(EXAMPLE, "period = 11.4", "period = = 11.4")
    line = 1 + text.splitlines().index("period = = 11.4")
    msg = error_of(text, tmp_path)
    assert f"TOML syntax error at line {line}" in msg


def test_both_height_kinds(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "H0 = 6.3", "H0 = 6.3\nH13 = 5.8\nHmax = 8.0"), tmp_path)
    assert "[wave] H0 = 6.3 together with [wave] H13/Hmax" in msg


def test_weight_and_densities(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "buoyant_weight = 2312", "buoyant_weight = 2312\nfill_density = 2000"),
                   tmp_path)
    assert "[caisson] buoyant_weight = 2312 together with densities (fill_density)" in msg
    msg = error_of(edit(EXAMPLE, "buoyant_weight = 2312", "fill_density = 2000"), tmp_path)
    assert "[caisson] concrete_fraction and concrete_density missing" in msg


def test_rotation_range(tmp_path: Path) -> None:
    msg = error_of(edit(EXAMPLE, "rotation = 0", "rotation = 20"), tmp_path)
    assert "[wave] rotation = 20" in msg and "0 <= rotation <= 15 degrees" in msg


def test_unreadable_file(tmp_path: Path) -> None:
    with pytest.raises(DesignFileError, match="cannot read the design file"):
        read_design(tmp_path / "nowhere.toml")


def test_error_class_is_a_value_error() -> None:
    assert issubclass(DesignFileError, ValueError)
    with pytest.raises(ValueError, match="<design>"):
        parse_design("[site]\n")
