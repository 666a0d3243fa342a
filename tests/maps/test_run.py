"""run_map: the map of one block, its points and warnings as data; map_figure draws the record."""

from __future__ import annotations

import pytest

from regimemap.maps.mapdata import map_for_view
from regimemap.maps.points import DesignPoint
from regimemap.maps.run import points_of_map
from regimemap.mechanics.block import Parameters
from regimemap.workflows import MapRecord, run_map


def test_the_record_holds_the_map_plot_computes():
    p = Parameters(3.0, 0.4)
    rec = run_map(p, samples=51)
    assert isinstance(rec, MapRecord) and rec.params is p and rec.view == "designer"
    same = map_for_view(p, samples=51)
    assert (rec.data.k_max, rec.data.mu_max) == (same.k_max, same.mu_max)
    assert rec.data.polygons.keys() == same.polygons.keys()
    assert rec.notices == () and rec.points == () and rec.ambiguity is None


def test_points_of_another_block_are_a_notice_not_drawn():
    p = Parameters(3.0, 0.4, buoyancy=0.2)
    pts = [DesignPoint(0.5, 0.8, "mine"), DesignPoint(0.5, 0.8, "g2", gamma=2.0),
           DesignPoint(0.5, 0.8, "kp", kprime=-0.3), DesignPoint(0.5, 0.8, "b", buoyancy=0.3),
           DesignPoint(0.4, 0.7, "same-b", buoyancy=0.2, gamma=3.0)]
    kept, notices = points_of_map(pts, p)
    assert [q.name for q in kept] == ["mine", "same-b"]
    (n,) = notices
    assert n.code == "other-block" and n.value == 3
    assert n.message.endswith("are not drawn on this map: g2, kp, b")


def test_points_extend_the_view_and_beyond_a_fixed_view_are_named():
    far = DesignPoint(3.0, 2.0, "far")
    rec = run_map(Parameters(3.0, 0.4), samples=51, points=[far])
    assert rec.data.k_max > 3.0 and rec.data.mu_max > 2.0 and rec.notices == ()
    rec = run_map(Parameters(3.0, 0.4), samples=51, points=[far, DesignPoint(0.1, 0.1)],
                  k_max=1.0, mu_max=1.0)
    (n,) = rec.notices
    assert (n.code, n.value) == ("outside-view", 1)
    assert n.message == "1 point(s) outside the view k <= 1, mu <= 1: far"


def test_ambiguity_only_when_asked():
    p = Parameters(3.0, -0.2)
    assert run_map(p, samples=51, k_max=16.0, mu_max=3.0).ambiguity is None
    rec = run_map(p, samples=51, k_max=16.0, mu_max=3.0, ambiguity=True)
    assert rec.ambiguity and all(r.anchor(16.0, 3.0) is not None for r in rec.ambiguity)


def test_the_field_table_reads_the_record():
    rec = run_map(Parameters(3.0, 0.4), samples=51)
    rows = {label: value for label, value, *_ in rec.field_rows()}
    assert rows["gamma"] == 3.0 and rows["k'"] == 0.4 and rows["view"] == "designer"
    assert rows["k_max"] == rec.data.k_max
    assert "<table" in rec._repr_html_()


@pytest.mark.render
def test_map_figure_draws_the_record_points_and_overlay():
    from regimemap.maps.figures.figure import map_figure

    rec = run_map(Parameters(3.0, -0.2), samples=51, k_max=16.0, mu_max=3.0,
                  points=[DesignPoint(2.0, 1.0, "here")], ambiguity=True)
    fig, ax, art = map_figure(rec, dpi=40)
    assert art.data is rec.data
    texts = [t.get_text() for t in ax.texts] + [t.get_text() for t in art.legend.get_texts()]
    assert "here" in texts and "several modes admissible" in texts
    _, _, plain = map_figure(rec.data, dpi=40)  # the data alone: no points, no overlay
    assert "here" not in [t.get_text() for t in plain.extra if hasattr(t, "get_text")]
