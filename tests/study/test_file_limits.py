"""A study's scenarios against a design file's limits, before any task: every scenario, year, section."""

from __future__ import annotations

import pytest

from regimemap.caisson.file_keys import WIDTH_RANGE
from regimemap.study.file import StudyFileError, read_study

from .conftest import SITE, scenario_table, section_table, study_head

HEAD = study_head(5, 20)
SECTIONS = (section_table("trunk", 0.0, *SITE, "width = 14.0")
            + section_table("head", 100.0, "caisson.crest = {crest}", "widths = [12.0, 15.0]"))


def _study(write_study, scenario: str, crest: float = 3.4, sections: str | None = None):
    body = SECTIONS.replace("{crest}", repr(crest)) if sections is None else sections
    return write_study(HEAD + body + scenario_table("today") + scenario_table("bad", scenario))


def _line(path, key: str) -> int:
    lines = path.read_text().splitlines()
    return next(n for n, line in enumerate(lines, start=1) if line.startswith(key))


def test_millimetres_typed_for_metres_are_refused_at_year_1_with_a_hint(write_study):
    path = _study(write_study, "sea_level_rise = { 50 = 1000 }")
    with pytest.raises(StudyFileError) as err:
        read_study(path)
    msg = str(err.value)
    assert msg.startswith(f"{path}, line {_line(path, 'sea_level_rise')}: [[scenario]] 'bad' sea_level_rise: "
                          "service year 1 = 20 m puts the crest of section 'trunk' under water")
    assert "hc = 3.4 - 20 = -16.6 m" in msg and msg.endswith("millimetres for metres?")
    assert "\n" not in msg


def test_a_rise_of_5_m_puts_the_crest_under_water_from_year_34_without_a_unit_hint(write_study):
    path = _study(write_study, "sea_level_rise = { 50 = 5.0 }")
    with pytest.raises(StudyFileError, match=r"service year 34 = 3\.4 m puts the crest of section 'trunk'") as err:
        read_study(path)
    assert "metres?" not in str(err.value)
    # one centimetre less by year 50 and year 34 stays under the crest (3.332 m), but not year 35
    path = _study(write_study, "sea_level_rise = { 50 = 4.9 }")
    with pytest.raises(StudyFileError, match="service year 35 = 3.43 m"):
        read_study(path)


def test_a_head_section_under_water_in_year_1_is_named_though_the_trunk_is_fine(write_study):
    path = _study(write_study, "sea_level_rise = { 1 = 0.5 }", crest=0.4)
    with pytest.raises(StudyFileError, match=r"service year 1 = 0\.5 m puts the crest of section 'head' under "
                                             r"water \(hc = 0\.4 - 0\.5 = -0\.1 m"):
        read_study(path)


def test_a_rate_that_falls_below_the_mound_leaves_it_dry(write_study):
    path = _study(write_study, "rate = -0.15")
    with pytest.raises(StudyFileError) as err:
        read_study(path)
    assert f"line {_line(path, 'rate')}: [[scenario]] 'bad' rate: service year 30 = -4.5 m leaves the mound " \
           "of section 'trunk' dry (d = 4.5 - 4.5 = 0 m" in str(err.value)
    assert "metres?" not in str(err.value)


def test_the_rise_that_keeps_every_crest_dry_is_accepted_and_checked_year_by_year(write_study):
    study = read_study(_study(write_study, "sea_level_rise = { 50 = 3.3 }"))
    assert study.scenarios[1].sea_level[-1] == 3.3 and study.notices == ()


@pytest.mark.parametrize("widths", ["widths = [12.0, 1200.0]", "width = 1200.0", "width = 0.01"])
def test_a_width_outside_the_design_files_range_is_refused(write_study, widths):
    sections = SECTIONS.replace("{crest}", "3.4").replace("widths = [12.0, 15.0]", widths)
    path = _study(write_study, "rate = 0.01", sections=sections)
    with pytest.raises(StudyFileError) as err:
        read_study(path)
    msg = str(err.value)
    assert f"line {_line(path, widths)}: [[section]] width" in msg
    assert "out of range" in msg and f"{WIDTH_RANGE[0]:g} <= width <= {WIDTH_RANGE[1]:g}" in msg


def test_a_falling_sea_level_table_is_a_notice(write_study):
    path = _study(write_study, "sea_level_rise = { 20 = 0.5, 50 = 0.2 }")
    study = read_study(path)
    (n,) = study.notices
    assert n.code == "falling-sea-level" and n.quantity == "sea_level_rise" and n.value == pytest.approx(0.2)
    assert n.message.startswith(f"{path}, line {_line(path, 'sea_level_rise')}: [[scenario]] 'bad' "
                                "sea_level_rise: the sea level falls, from 0.5 m (service year 20) to 0.2 m "
                                "in service year 50")


def test_a_negative_rate_falls_from_today(write_study):
    (n,) = read_study(_study(write_study, "rate = -0.01")).notices
    assert "from 0 m (today) to -0.5 m in service year 50" in n.message


def test_a_wave_height_factor_typed_as_a_per_cent_is_refused(write_study):
    path = _study(write_study, "wave_height_factor = { 50 = 10 }")
    with pytest.raises(StudyFileError) as err:
        read_study(path)
    assert str(err.value).startswith(
        f"{path}, line {_line(path, 'wave_height_factor')}: [[scenario]] 'bad' wave_height_factor: service year "
        "21 = 4.78 makes the 50-year H0' of section 'trunk' 30.11 m (6.3 m x 4.78; accepted in every service "
        "year: the 50-year return value of H0', H0_10 < H0_50 <= 30 m)")
    assert str(err.value).endswith("a per cent for a factor (1.1 for 10 % higher)?")
    assert read_study(_study(write_study, "wave_height_factor = { 50 = 1.2 }")).scenarios[1].wave_height[-1] == 1.2
