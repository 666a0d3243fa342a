"""Panel (d) of the caisson design sheet: the loaded map's exact polygons, not contours of a grid."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.caisson.file import example_design_text, parse_design
from regimemap.caisson.report import CaissonReport

pytestmark = pytest.mark.render

LIGHT = example_design_text().replace("buoyant_weight = 2312", "buoyant_weight = 1300")


def _report(text: str) -> CaissonReport:
    from regimemap.caisson.report import caisson_report

    return caisson_report(parse_design(text).analysis_inputs())


def _open(poly: np.ndarray) -> np.ndarray:
    """Vertices without the closing one (a Polygon patch repeats the first at the end)."""
    poly = np.asarray(poly, dtype=float)
    return poly[:-1] if len(poly) > 1 and np.array_equal(poly[0], poly[-1]) else poly


@pytest.mark.parametrize("text", [example_design_text(), LIGHT], ids=["goda", "light"])
@pytest.mark.deep
def test_panel_d_fills_are_the_maps_exact_polygons(text: str) -> None:
    """Each region of (d) is a Polygon patch whose vertices are compute_map's, mode by mode."""
    from matplotlib.patches import Polygon

    from regimemap.caisson.report import map_view
    from regimemap.drawing.style import MODE_STYLE
    from regimemap.maps.mapdata import compute_map
    from tests.conftest import draw_sheet

    report = _report(text)
    view = map_view(report)
    fig = draw_sheet(report)
    (ax,) = [a for a in fig.axes if a.get_label() == "map"]
    data = compute_map(report.map.parameters(), k_max=view.k_max, mu_max=view.mu_max)
    assert (ax.get_xlim(), ax.get_ylim()) == ((0.0, view.k_max), (0.0, view.mu_max))
    n = 0
    for mode in data.modes:
        polys = [p for p in data.polygons.get(mode, []) if len(p) >= 3]
        drawn = [p for p in ax.patches if isinstance(p, Polygon) and p.get_label() == f"_{mode.label}"]
        assert len(drawn) == len(polys), mode
        for patch, poly in zip(drawn, polys):
            np.testing.assert_array_equal(_open(patch.get_xy()), _open(poly))
            assert patch.get_facecolor()[:3] == pytest.approx(
                tuple(int(MODE_STYLE[mode].color[i:i + 2], 16) / 255 for i in (1, 3, 5)))
        n += len(drawn)
    assert n >= 4  # RE, SL, RO, SRO- at least
    # the boundaries are the map's curves, drawn as `regimemap plot` draws them
    drawn_lines = {ln.get_label() for ln in ax.lines}
    assert {"_OA", "_mu_star"} <= drawn_lines


def test_panel_d_draws_no_contours() -> None:
    """A fallback to contours of a sampled grid (label_grid) would draw ContourSets: none here."""
    from matplotlib.collections import PathCollection
    from matplotlib.contour import ContourSet

    from tests.conftest import draw_sheet

    fig = draw_sheet(_report(example_design_text()))
    (ax,) = [a for a in fig.axes if a.get_label() == "map"]
    assert not [c for c in ax.collections if isinstance(c, (ContourSet, PathCollection))]
    assert ax.patches  # the regions are patches


def test_panel_d_keys_the_modes_in_view_and_the_lines() -> None:
    from tests.conftest import draw_sheet

    fig = draw_sheet(_report(example_design_text()))
    (ax,) = [a for a in fig.axes if a.get_label() == "map"]
    legend = ax.get_legend()
    assert legend is not None
    texts = [t.get_text() for t in legend.get_texts()]
    assert texts[:4] == ["rest", "slide", "rock about O", "slide-rock about O, O slipping left"]
    assert "boundary of a region" in texts and texts[-1].startswith("path: H")
    # the key names the dotted line when it is drawn (not when it lies under a boundary)
    dotted_drawn = any(ln.get_label() == "_dotted" for ln in ax.lines)
    assert dotted_drawn == any(t.startswith("dotted line") for t in texts)


def test_sheet_map_is_compute_map_in_the_view() -> None:
    from regimemap.caisson.report import map_view, sheet_map

    report = _report(example_design_text())
    view = map_view(report)
    same, data = sheet_map(report, view)
    assert same is view
    assert (sheet_map(report)[0].k_max, sheet_map(report)[0].mu_max) == (view.k_max, view.mu_max)
    assert (data.k_max, data.mu_max) == (view.k_max, view.mu_max)
    assert data.params == report.map.parameters()
    assert {"A", "E"} <= set(data.points)


def _overlaps(fig) -> list[tuple[str, str]]:
    """Pairs of texts of the sheet that overlap: every text, the keys' and tick labels too."""
    from regimemap.drawing.text.labelplacer import figure_texts

    fig.draw_without_rendering()  # laid out as drawn, without the pixels
    renderer = fig.canvas.get_renderer()
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in figure_texts(fig)]
    assert len(boxes) > 150
    return [(a, b) for i, (a, ba) in enumerate(boxes) for b, bb in boxes[i + 1:] if ba.overlaps(bb)]


@pytest.mark.deep
def test_the_lifetime_sheet_draws_the_required_factors_and_no_text_overlaps() -> None:
    """With panel (g), (e) is drawn shorter: it still draws the file's required safety factors;
    no text of the sheet (the key of (d) included) meets another, with or without (g)."""
    from regimemap.lifetime import lifetime_sliding
    from tests.conftest import draw_sheet

    d = parse_design(example_design_text())
    life = lifetime_sliding(d.lifetime_caisson(), d.lifetime_model(), trials=50, seed=1)
    report = _report(example_design_text())
    fig = draw_sheet(report, title="goda.toml", lifetime=life, required=(1.3, 1.5))
    (ax,) = [a for a in fig.axes if a.get_label() == "path"]
    texts = [t.get_text().strip() for t in ax.texts]
    assert "required 1.3" in texts and "required 1.5" in texts
    assert not _overlaps(fig)
    assert not _overlaps(draw_sheet(report, title="goda.toml"))
