"""Maps of the loaded block drawn: lift-off's fill and key entry, the title states the loads,
the overlay names least constraint; the report's block keeps its key and title."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import LOADED_MAP_MODES, MAP_MODES, Mode, Parameters, classify
from regimemap.drawing.style import MODE_STYLE
from regimemap.maps.describe import format_value, loads_text
from regimemap.maps.figures.figure import map_figure
from regimemap.maps.figures.mapplot import default_title
from regimemap.maps.run import run_map

GODA = Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524)
SLENDER = Parameters(3.0, 0.4, uplift_ratio=1.0)


def _key_labels(art):
    return [t.get_text() for t in art.legend.get_texts()]


def test_every_loaded_mode_has_its_own_colour_and_hatch():
    styles = [MODE_STYLE[m] for m in LOADED_MAP_MODES]
    assert len({s.color.lower() for s in styles}) == len(styles)
    assert len({s.hatch for s in styles}) == len(styles)
    assert MODE_STYLE[Mode.LO].color.lower() == "#99ddff"  # Paul Tol's light cyan


@pytest.mark.render
@pytest.mark.parametrize("p", [GODA, SLENDER], ids=["goda", "slender"])
def test_loaded_map_fills_lift_off_and_keys_it(p):
    fig, ax, art = map_figure(run_map(p, samples=301))
    assert art.fills[Mode.LO], "a patch for lift-off"
    # the LO patch covers points the classifier calls LO, and only those
    poly = art.polygons[Mode.LO][0]
    k_mid = float(np.mean(poly[:, 0]))
    mu_mid = float(np.mean(poly[:, 1]))
    assert Mode(int(classify(k_mid, mu_mid, p.gamma, p.kprime, **p.loads))) is Mode.LO
    labels = _key_labels(art)
    assert Mode.LO.description in labels
    # the key lists the modes present, nothing more
    present = [m for m in LOADED_MAP_MODES if any(len(q) >= 3 for q in art.polygons.get(m, []))]
    assert labels[:len(present)] == [m.description for m in present]
    assert "L" in art.point_markers and "LO" in art.curves


@pytest.mark.render
def test_loaded_fills_are_vector_polygons_not_a_staircase():
    _, _, art = map_figure(run_map(GODA, samples=301))
    poly = art.polygons[Mode.LO][0]
    # lift-off starts at k_L: its left edge is the vertical through L, exactly
    assert np.isclose(poly[:, 0].min(), GODA.k_L, rtol=0, atol=1e-12)
    assert len(poly) < 40  # a few vertices, not one per grid column


@pytest.mark.render
def test_title_states_the_loads():
    _, _, art = map_figure(run_map(GODA, samples=201))
    title = art.title.get_text()
    assert r"$\beta = 0.318$" in title and r"$\nu = 0.524$" in title and "$e_u = 1/3$" in title
    assert "case" not in title
    assert default_title(GODA).startswith("All modes, block with loads")


@pytest.mark.render
def test_report_block_keeps_its_title_and_key():
    p = Parameters(3.0, -0.3)
    fig, ax, art = map_figure(run_map(p, samples=201))
    assert "$\\beta" not in art.title.get_text() and p.case.tex in art.title.get_text()
    labels = _key_labels(art)
    assert Mode.LO.description not in labels
    assert art.data.modes == MAP_MODES


@pytest.mark.render
def test_overlay_names_least_constraint():
    from regimemap.maps.ambiguity import ambiguous_in_view
    from regimemap.maps.figures.ambiguity import draw_ambiguity

    # {LO, RO, SRO-} lies above mu = 1.2: in the report's view, not the designer's
    fig, ax, art = map_figure(run_map(GODA, samples=201, view="report"))
    drawn = draw_ambiguity(ax, ambiguous_in_view(GODA, art.data.k_max, art.data.mu_max),
                           art.data.k_max, art.data.mu_max)
    texts = [a.get_text() for a in drawn if hasattr(a, "get_text")]
    assert any("least constraint" in t and "LO" in t for t in texts)


def test_loads_text():
    assert loads_text(GODA) == "beta = 0.318, nu = 0.524, e_u = 1/3"
    assert loads_text(Parameters(3.0, 0.4)) == ""
    assert loads_text(Parameters(2.0, 0.2, uplift=0.1, uplift_arm=0.0, gyration=0.9, crest=1.5)) == (
        "u = 0.1, e_u = 0, i = 0.9, crest = 1.5")
    assert format_value(-2.0 / 3.0) == "-2/3" and format_value(0.25) == "0.25"


@pytest.mark.render
@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_worked_figures_ids_and_files(run_cli, tmp_path):
    from regimemap.maps.figures.presets import FIGURE_IDS
    from regimemap.maps.figures.worked import WORKED, WORKED_IDS

    assert WORKED_IDS == ("W.1", "W.2", "W.3", "W.4")
    assert not set(WORKED_IDS) & set(FIGURE_IDS)
    sea, air = WORKED["W.1"].params, WORKED["W.2"].params
    assert (sea.gamma, sea.kprime) == (air.gamma, air.kprime) and sea.loaded and not air.loaded
    assert sea.lift_off is not None and WORKED["W.3"].params.lift_off is not None
    r = run_cli(["figures", "--out", str(tmp_path), "--format", "svg", "--set", "worked"])
    assert r.code == 0, r.output
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"fig-{w}.svg" for w in WORKED_IDS]
    r = run_cli(["figure", "w.1", "-o", str(tmp_path / "one.png"), "--dpi", "40"])
    assert r.code == 0, r.output
    r = run_cli(["figures", "--list", "--set", "all"])
    assert r.stdout.splitlines()[-1].startswith("W.4") and len(r.stdout.splitlines()) == 29  # 2.1, 24, W.1-4
