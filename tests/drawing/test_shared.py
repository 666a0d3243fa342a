"""What every figure draws the same way: regimemap.drawing.style's and labelplacer's shared helpers."""

from __future__ import annotations

import pytest

from regimemap.drawing.style import agg_figure, key_below, label_axes
from regimemap.drawing.text.labelplacer import (
    LabelPlacer,
    hline_candidates,
    hline_label,
    vline_candidates,
    vline_label,
)
from regimemap.drawing.text.textboxes import major_tick_labels

pytestmark = pytest.mark.render


def test_agg_figure_has_an_agg_canvas_and_no_pyplot_manager():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = agg_figure((3.0, 2.0), dpi=50, facecolor="none")
    assert isinstance(fig.canvas, FigureCanvasAgg)
    assert fig.canvas.manager is None
    assert tuple(fig.get_size_inches()) == (3.0, 2.0)
    assert fig.dpi == 50
    assert fig.get_facecolor()[3] == 0.0


def test_label_axes_sets_labels_ticks_and_the_left_title():
    fig = agg_figure((3.0, 2.0))
    ax = fig.add_axes((0.2, 0.2, 0.7, 0.6))
    label_axes(ax, "x (m)", "y (m)", 8.0, "(a) panel", title_larger=0.5)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x (m)", "y (m)")
    assert ax.xaxis.label.get_fontsize() == ax.yaxis.label.get_fontsize() == 8.0
    assert ax.get_title(loc="left") == "(a) panel" and ax.get_title() == ""
    assert ax._left_title.get_fontsize() == 8.5
    fig.draw_without_rendering()
    assert {t.get_fontsize() for t in major_tick_labels(ax)} == {7.5}
    other = fig.add_axes((0.2, 0.2, 0.7, 0.6), label="other")
    label_axes(other, None, "only y", 10.0)
    assert other.get_xlabel() == "" and other.get_title(loc="left") == ""


def test_key_below_is_a_frameless_figure_legend_at_the_bottom():
    from matplotlib.lines import Line2D

    fig = agg_figure((4.0, 3.0))
    key = [(Line2D([], [], color="k"), "one"), (Line2D([], [], color="r"), "two"),
           (Line2D([], [], color="b"), "three")]
    leg = key_below(fig, key, 0.02, 7.0, ncols=3, handlelength=2.8)
    assert fig.legends == [leg]
    assert [t.get_text() for t in leg.get_texts()] == ["one", "two", "three"]
    assert not leg.get_frame_on() and leg._ncols == 3 and leg.handlelength == 2.8
    assert leg.get_texts()[0].get_fontsize() == 7.0


def test_line_labels_come_with_their_candidates():
    fig = agg_figure((3.0, 2.0))
    ax = fig.add_axes((0.2, 0.2, 0.7, 0.6))
    t, cands, texts = vline_label(ax, 0.4, "b = 1 m", fontsize=7.0, color="red", side_first=-1,
                                  texts=("b =\n1 m",))
    assert t.get_rotation() == 90.0 and t.get_color() == "red" and t.get_fontsize() == 7.0
    assert cands == vline_candidates(0.4, side_first=-1) and texts == ["b =\n1 m"]
    h, hcands, htexts = hline_label(ax, 0.3, "0.3 m", fontsize=7.5)
    assert h.get_rotation() == 0.0 and hcands == hline_candidates(0.3) and htexts == []


def test_label_placer_as_a_context_manager_restores_the_resolution():
    fig = agg_figure((3.0, 2.0), dpi=40)
    ax = fig.add_axes((0.2, 0.2, 0.7, 0.6))
    ax.plot([0.0, 1.0], [0.0, 1.0])
    labels = [vline_label(ax, 0.5, "middle", fontsize=7.0)]
    with LabelPlacer(fig) as placer:
        assert fig.dpi != 40
        placer.avoid_lines_of(ax)
        placer.place_all(ax, labels)
    assert fig.dpi == 40
    assert labels[0][0].xy[0] == 0.5
