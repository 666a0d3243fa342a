"""The study file: its sections (overrides read by the design reader), scenarios, hash and refusals."""

from __future__ import annotations

import re

import pytest

from regimemap.caisson.file import example_design_text
from regimemap.study.file import StudyFileError, parse_study, read_study
from regimemap.study.file_example import example_study_text

from .conftest import SITE, scenario_table, section_table, study_head

SECTIONS = (section_table("a", 0.0, *SITE, "width = 14.0")
            + section_table("b", 100.0, "widths = [12.0, 15.0]"))

SCENARIOS = (scenario_table("today")
             + scenario_table("rise", "sea_level_rise = { 10 = 0.2, 30 = 1.0 }",
                              "wave_height_factor = { 50 = 1.1 }", "storm_rate_factor = { 25 = 2.0 }"))


def _study(write_study, sections=SECTIONS, scenarios=SCENARIOS):
    return write_study(study_head(5, 50) + sections + scenarios)


def test_the_example_parses_into_three_sections_and_two_scenarios(tmp_path):
    path = tmp_path / "ex.toml"
    path.write_text(example_study_text())
    s = read_study(path)
    assert [sec.name for sec in s.sections] == ["trunk 8 m", "trunk 12 m", "head 18 m"]
    assert [sec.design.site.depth for sec in s.sections] == [8.0, 12.0, 18.0]
    assert [sec.chainage for sec in s.sections] == [0.0, 250.0, 500.0]
    assert s.sections[2].target == 0.1 and s.sections[2].widths == (20.0, 45.0)
    assert (s.seed, s.trials, s.years) == (2026, 2000, 50)
    today, rise = s.scenarios
    assert today.today and today.stationary and not rise.stationary and not rise.today
    assert rise.sea_level[0] == pytest.approx(0.02) and rise.sea_level[24] == pytest.approx(0.5)
    assert rise.sea_level[-1] == 1.0
    assert s.model(s.sections[0], today).trend is None
    assert s.model(s.sections[0], rise).trend.sea_level == rise.sea_level


def test_a_section_changes_the_base_design_and_keeps_the_rest(write_study):
    s = read_study(_study(write_study))
    a, b = s.sections
    assert (a.design.site.depth, a.design.site.armour_depth, a.design.caisson.base_depth) == (8.0, 4.5, 5.5)
    assert a.design.caisson.crest == b.design.caisson.crest == 3.4
    assert b.design.site.depth == 10.1
    assert a.widths == (14.0,) and b.widths == (12.0, 15.0)
    assert a.design.caisson.width == 15.0  # the widths are simulated from the design's section


def test_the_scenario_tables_are_linear_between_years_and_constant_after_the_last(write_study):
    rise = read_study(_study(write_study)).scenarios[1]
    assert len(rise.sea_level) == 50
    assert rise.sea_level[4] == pytest.approx(0.1)      # year 5: halfway from 0 m today to 0.2 m
    assert rise.sea_level[19] == pytest.approx(0.6)     # year 20: halfway from 0.2 to 1.0
    assert rise.sea_level[29:] == (1.0,) * 21
    assert rise.wave_height[49] == pytest.approx(1.1) and rise.wave_height[24] == pytest.approx(1.05)
    assert rise.storm_rate[24:] == (2.0,) * 26


def test_rate_and_acceleration_give_the_quadratic_rise(write_study):
    sc = '[[scenario]]\nname = "q"\nrate = 0.004\nacceleration = 0.0002\n'
    rise = read_study(_study(write_study, scenarios=sc)).scenarios[0]
    assert rise.sea_level[49] == pytest.approx(0.004 * 50 + 0.5 * 0.0002 * 50**2)
    assert rise.sea_level[0] == pytest.approx(0.004 + 0.0001)


def test_a_key_two_tables_share_is_written_with_its_table(write_study):
    sec = '[[section]]\nname = "a"\nchainage = 0\ncaisson.impulsive = false\nlifetime.impulsive = true\n'
    s = read_study(_study(write_study, sections=sec))
    assert s.sections[0].design.caisson.impulsive is False
    assert s.sections[0].design.lifetime_spec().impulsive is True


def test_the_hash_follows_the_content_not_the_comments(tmp_path, write_study):
    path = _study(write_study)
    h = read_study(path).study_hash
    path.write_text(path.read_text().replace("seed = 5", "seed = 5   # a comment"))
    assert read_study(path).study_hash == h
    path.write_text(path.read_text().replace("depth = 8.0", "depth = 8.5"))
    assert read_study(path).study_hash != h
    (tmp_path / "goda.toml").write_text(example_design_text().replace("crest = 3.4", "crest = 3.5"))
    path.write_text(path.read_text().replace("depth = 8.5", "depth = 8.0"))
    assert read_study(path).study_hash != h  # the base file's change counts


def _line_of(text: str, needle: str, nth: int = 1) -> int:
    lines = [n for n, line in enumerate(text.splitlines(), start=1) if needle in line]
    return lines[nth - 1]


BAD_SECTIONS = [
    # (sections, the line holding this text, (nth), what the message says)
    (SECTIONS.replace('name = "b"', 'name = "a"'), 'name = "a"', 2, "a duplicate of the section at line"),
    (SECTIONS.replace("chainage = 100.0", "chainage = -5.0"), "chainage = -5.0", 1, "goes back"),
    (SECTIONS.replace("depth = 8.0", "dpeth = 8.0"), "dpeth", 1, "[[section]] dpeth: unknown key (did you mean"),
    (SECTIONS.replace("width = 14.0", "impulsive = true"), "impulsive", 1, "a key of both [caisson] and"),
    (SECTIONS.replace("width = 14.0", "trials = 7"), "trials = 7", 1, "the same for every section"),
    (SECTIONS.replace("base_depth = 5.5", "base_depth = 9.5"), "base_depth = 9.5", 1,
     "section 'a': [caisson] base_depth = 9.5: the base of the caisson would be deeper than the water"),
    (SECTIONS.replace("depth = 8.0", "depth = 800.0"), "depth = 800.0", 1, "section 'a': [site] depth"),
    (SECTIONS.replace("width = 14.0", "width = -1"), "width = -1", 1, "[[section]] width = -1"),
    (SECTIONS.replace("width = 14.0", "target = 0.1"), "target = 0.1", 1, "target needs widths"),
    (SECTIONS.replace("widths = [12.0, 15.0]", "widths = [15.0, 12.0]"), "widths = [15.0", 1, "not increasing"),
    (SECTIONS.replace("width = 14.0", "caisson.colour = 1"), "caisson.colour", 1, "unknown key"),
]


@pytest.mark.parametrize(("sections", "needle", "nth", "says"), BAD_SECTIONS)
def test_a_bad_section_is_refused_with_its_file_line_and_key(write_study, sections, needle, nth, says):
    path = _study(write_study, sections=sections)
    with pytest.raises(StudyFileError) as info:
        read_study(path)
    msg = str(info.value)
    assert msg.startswith(f"{path}, line {_line_of(path.read_text(), needle, nth)}: "), msg
    assert says in msg
    assert "\n" not in msg


BAD_SCENARIOS = [
    (SCENARIOS.replace('name = "rise"', 'name = "today"'), 'name = "today"', 2, "a duplicate of the scenario"),
    (SCENARIOS.replace("30 = 1.0", "51 = 1.0"), "sea_level_rise", 1,
     "the year 51 is outside the design life; accepted: service years 1 to 50"),
    (SCENARIOS.replace("10 = 0.2", "0 = 0.2"), "sea_level_rise", 1, "the year 0 is outside the design life"),
    (SCENARIOS.replace("50 = 1.1", "50 = 0.0"), "wave_height_factor", 1, "year 50 = 0.0; accepted: a factor > 0"),
    (SCENARIOS.replace("25 = 2.0", "25 = -1"), "storm_rate_factor", 1, "accepted: a factor > 0"),
    (SCENARIOS.replace("storm_rate_factor", "storm_rate_facter"), "storm_rate_facter", 1, "did you mean"),
    (SCENARIOS.replace("storm_rate_factor = { 25 = 2.0 }", "rate = 0.01"), "rate = 0.01", 1,
     "together with sea_level_rise"),
]


@pytest.mark.parametrize(("scenarios", "needle", "nth", "says"), BAD_SCENARIOS)
def test_a_bad_scenario_is_refused_with_its_file_line_and_key(write_study, scenarios, needle, nth, says):
    path = _study(write_study, scenarios=scenarios)
    with pytest.raises(StudyFileError) as info:
        read_study(path)
    msg = str(info.value)
    assert msg.startswith(f"{path}, line {_line_of(path.read_text(), needle, nth)}: "), msg
    assert says in msg


def test_a_key_of_the_base_is_refused_at_its_line_in_the_base(tmp_path, write_study):
    path = _study(write_study)
    (tmp_path / "goda.toml").write_text(example_design_text().replace("shape = 2.0 ", "shape = -2.0"))
    with pytest.raises(StudyFileError, match=re.escape(f"{tmp_path / 'goda.toml'}, line ")) as info:
        read_study(path)
    assert "[lifetime] shape" in str(info.value)


_RECORD = '\n[lifetime.record]\npath = "buoy.txt"\nthreshold = "95%"\ngap_hours = -3\n\n'
_CLIMATE = ("H0_10 = 5.0 ", "H0_50 = 6.3 ", 'distribution = "weibull"', "shape = 2.0 ")


def _with_record(design: str) -> str:
    """The example design with a ``[lifetime.record]`` table (its gap_hours out of range) in place
    of its climate."""
    kept = "\n".join(line for line in design.splitlines() if not line.startswith(_CLIMATE))
    return kept.replace("\n[lifetime.errors]", _RECORD + "[lifetime.errors]")


@pytest.mark.parametrize("where", ["base", "inline"])
def test_a_key_of_a_record_table_is_refused_at_its_own_line(tmp_path, write_study, where):
    """A key of ``[lifetime.record]`` is named at its own line (in the base file or in the study),
    not at the line of its table or of ``[lifetime]``."""
    path = _study(write_study)
    if where == "base":
        (tmp_path / "goda.toml").write_text(_with_record(example_design_text()))
        file, text = tmp_path / "goda.toml", (tmp_path / "goda.toml").read_text()
    else:
        path.write_text(path.read_text().replace('base = "goda.toml"\n', _with_record(example_design_text())))
        file, text = path, path.read_text()
    line = text.splitlines().index("gap_hours = -3") + 1
    with pytest.raises(StudyFileError) as info:
        read_study(path)
    assert str(info.value).startswith(f"{file}, line {line}: "), str(info.value)
    assert "[lifetime.record] gap_hours = -3" in str(info.value)


@pytest.mark.parametrize(("text", "says"), [
    ('seed = 1\nsection = 3\n', "no [lifetime] table"),
    ('seed = 1\nbase = "missing.toml"\n', "cannot read the design file"),
    ('seed = 1\ncolour = 3\n', "unknown key colour"),
    ('seed = 1\nbase = "goda.toml"\n' + SECTIONS, "no [[scenario]]"),
    ('seed = 1\nbase = "goda.toml"\n' + SCENARIOS, "no [[section]]"),
    ('seed = -1\nbase = "goda.toml"\n' + SECTIONS + SCENARIOS, "seed = -1"),
    ('trials = 0\nbase = "goda.toml"\n' + SECTIONS + SCENARIOS, "trials = 0"),
    ('seed = 1\nbase = "goda.toml"\n[[section]]\nname = "x"\n' + SCENARIOS, "chainage = None"),
    ('seed = [1\n', "TOML syntax error"),
    # a tolerance as wide as the bracket: the search would stop at once, its width outside its band
    ('seed = 1\nbase = "goda.toml"\n' + section_table("c", 0.0, "target = 0.1", "widths = [16.0, 40.0]",
                                                      "tolerance = 24") + SCENARIOS,
     "[[section]] tolerance = 24: not below the bracket of widths (16 to 40 m, 24 m wide)"),
])
def test_a_bad_study_is_refused_in_one_line(write_study, text, says):
    path = write_study(text, "s.toml")
    with pytest.raises(StudyFileError) as info:
        read_study(path)
    assert says in str(info.value) and str(info.value).startswith(str(path))


def test_a_study_file_that_cannot_be_read_says_so_once(tmp_path):
    # not 'cannot read the study file: ...: cannot read the design file: ...'
    with pytest.raises(StudyFileError) as info:
        read_study(tmp_path / "none.toml")
    assert str(info.value) == f"{tmp_path / 'none.toml'}: cannot read the study file: No such file or directory"
    binary = tmp_path / "b.toml"
    binary.write_bytes(b"seed = 1\n\xff\xfe\n")
    with pytest.raises(StudyFileError) as info:
        read_study(binary)
    assert str(info.value) == (f"{binary}: cannot read the study file: not a UTF-8 text file: byte 0xff at "
                               "offset 9, line 2")
    path = tmp_path / "s.toml"
    path.write_text('seed = 1\nbase = "missing.toml"\n', encoding="utf-8")
    with pytest.raises(StudyFileError) as info:
        read_study(path)
    assert str(info.value) == (f"{path}, line 2: base = 'missing.toml': cannot read the design file "
                               f"'{tmp_path / 'missing.toml'}': No such file or directory")


def test_the_text_parses_without_a_file():
    s = parse_study(example_study_text(), "example.toml")
    assert s.source == "example.toml" and len(s.sections) == 3
