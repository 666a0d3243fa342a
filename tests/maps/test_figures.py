"""regimemap.maps.figures.presets: the 24 presets of the report's figures."""

from __future__ import annotations

import math

import pytest

from regimemap import MAP_MODES, Mode, Parameters
from regimemap.maps.figures.presets import FIGURE_IDS, PRESETS, get_preset, suggest_ids
from regimemap.maps.view import auto_extent
from regimemap.mechanics.block import Case

EXPECTED_IDS = ("3.1", "3.2", "3.3a", "3.3b", "3.4", "3.5", "3.6a", "3.6b", "3.7", "3.8",
                "3.9a", "3.9b", "3.10", "3.11", "4.2", "4.3", "4.4a", "4.4b", "4.5a", "4.5b",
                "4.6a", "4.6b", "4.7a", "4.7b")
ALL_MODE_IDS = ("3.9a", "3.9b", "3.10", "3.11", "4.7a", "4.7b")


def test_the_24_ids_in_report_order():
    assert FIGURE_IDS == EXPECTED_IDS
    assert len(PRESETS) == 24


@pytest.mark.parametrize("fid", EXPECTED_IDS)
def test_preset_satisfies_its_case(fid):
    pr = PRESETS[fid]
    p = Parameters(pr.gamma, pr.kprime)
    assert p.case in pr.cases
    assert pr.condition(p)


@pytest.mark.parametrize("fid", EXPECTED_IDS)
def test_preset_is_strictly_inside_its_case(fid):
    """Nudging k' (and gamma) a little keeps the case: the preset is away from thresholds."""
    pr = PRESETS[fid]
    for dg, dk in ((0, 0.02), (0, -0.02), (0.1, 0), (-0.1, 0)):
        kp = pr.kprime + dk
        if not -1.0 <= kp <= 1.0:
            continue
        p = Parameters(pr.gamma + dg, kp)
        assert pr.condition(p), (fid, dg, dk)
        assert p.case in pr.cases


@pytest.mark.parametrize("fid,case", [
    ("3.3a", Case.ABOVE_1A), ("3.6a", Case.ABOVE_1A), ("3.9a", Case.ABOVE_1A),
    ("3.3b", Case.ABOVE_1B), ("3.6b", Case.ABOVE_1B), ("3.9b", Case.ABOVE_1B),
    ("3.4", Case.ABOVE_2_3), ("3.5", Case.ABOVE_2_3), ("3.7", Case.ABOVE_2_3),
    ("3.8", Case.ABOVE_2_3), ("3.10", Case.ABOVE_2_3), ("3.11", Case.ABOVE_2_3),
    ("4.4a", Case.BELOW_DELTA_POS), ("4.5a", Case.BELOW_DELTA_POS),
    ("4.6a", Case.BELOW_DELTA_POS), ("4.7a", Case.BELOW_DELTA_POS),
    ("4.4b", Case.BELOW_DELTA_NEG), ("4.5b", Case.BELOW_DELTA_NEG),
    ("4.6b", Case.BELOW_DELTA_NEG), ("4.7b", Case.BELOW_DELTA_NEG),
])
def test_case_of_each_captioned_figure(fid, case):
    assert PRESETS[fid].params.case is case


def test_case_2_3_needs_a_slender_block():
    for fid in ("3.4", "3.5", "3.7", "3.8", "3.10", "3.11"):
        p = PRESETS[fid].params
        assert p.gamma > math.sqrt(2) and p.a < 0 and p.kprime >= p.kprime_2


def test_raw_and_final_figures():
    for fid, pr in PRESETS.items():
        if fid in ALL_MODE_IDS:
            assert not pr.raw
            assert len(pr.modes) >= 4
        else:
            assert pr.raw and len(pr.modes) == 1
        assert set(pr.modes) <= set(MAP_MODES)
    assert PRESETS["3.8"].modes == (Mode.SRO_PLUS,)
    assert PRESETS["4.6a"].modes == (Mode.SRO_PRIME_MINUS,)
    assert PRESETS["3.1"].modes == PRESETS["4.2"].modes == (Mode.RE,)


def _extent(pr):
    raw_mode = pr.modes[0] if pr.raw else None
    return auto_extent(pr.params, raw_mode, k_max=pr.k_max, mu_max=pr.mu_max)


@pytest.mark.parametrize("fid", ["4.4a", "4.5a", "4.6a", "4.7a"])
def test_b_prime_in_view_for_delta_positive(fid):
    pr = PRESETS[fid]
    p = pr.params
    k_max, mu_max = _extent(pr)
    assert p.k_A < p.k_Bprime < k_max and p.mu_Bprime < mu_max


@pytest.mark.parametrize("fid", ["4.4a", "4.5a", "4.7a"])
def test_b_prime_drawn(fid, preset_maps):
    assert "B'" in preset_maps[fid].points


def test_case_2_figures_end_a_little_beyond_g_and_case_3_well_beyond():
    for fid in ("3.4", "3.7", "3.10"):
        pr = PRESETS[fid]
        G = pr.params.b_over_abs_a
        k_max, _ = _extent(pr)
        assert G < k_max <= 1.3 * G, fid
        assert "G" in pr.title
    for fid in ("3.5", "3.8", "3.11"):
        pr = PRESETS[fid]
        G = pr.params.b_over_abs_a
        k_max, _ = _extent(pr)
        assert k_max >= 3 * G, fid
        assert "G" in pr.title


def test_sro_plus_region_in_view_for_case_3(preset_maps):
    pr = PRESETS["3.11"]
    assert not pr.raw  # the final map the figure draws
    d = preset_maps["3.11"]
    assert d.polygons[Mode.SRO_PLUS]
    assert "G" in d.points


def test_every_region_of_the_final_maps_is_drawn(preset_maps):
    for fid in ALL_MODE_IDS:
        pr = PRESETS[fid]
        assert not pr.raw
        d = preset_maps[fid]
        present = {m for m, polys in d.polygons.items() if polys}
        expected = {Mode.RE, Mode.SL, Mode.RO}
        if pr.params.above:
            expected.add(Mode.SRO_MINUS)
            if pr.params.a < 0:
                expected.add(Mode.SRO_PLUS)
        else:
            expected.add(Mode.SRO_PRIME_MINUS)
            if pr.params.delta > 0:
                expected.add(Mode.SRO_MINUS)
        assert expected <= present, (fid, expected - present)


def test_captions():
    for pr in PRESETS.values():
        assert pr.caption_source in ("report", "reconstructed")
        assert pr.caption.count("$") % 2 == 0  # balanced mathtext
        assert pr.title.startswith(f"Fig. {pr.id}  ")
        assert f"k' = {pr.kprime:g}" in pr.title
    assert PRESETS["3.9a"].caption.startswith("All modes, case 1")
    assert PRESETS["3.2"].caption == "Slide region"


def test_filenames():
    assert PRESETS["3.9a"].filename("png") == "fig-3.9a.png"
    assert PRESETS["4.7b"].filename(".svg") == "fig-4.7b.svg"


def test_get_preset_accepts_spellings_and_suggests():
    assert get_preset("3.9a").id == "3.9a"
    assert get_preset("Fig. 3.9A").id == "3.9a"
    assert get_preset("fig-4.7b").id == "4.7b"
    assert set(suggest_ids("3.9")) >= {"3.9a", "3.9b"}
    with pytest.raises(KeyError, match="did you mean"):
        get_preset("3.9")
    with pytest.raises(KeyError):
        get_preset("9.9")
