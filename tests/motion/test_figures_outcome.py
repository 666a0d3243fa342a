"""regimemap.motion.figures.outcome and .motion: what an outcome map and a motion figure draw (no simulation)."""

from __future__ import annotations

import io

import numpy as np
import pytest

from regimemap.drawing.style import MODE_STYLE, OUTCOME_STYLE, phase_style
from regimemap.dynamics import (
    CATEGORY_LABELS,
    OVERTURN,
    REST,
    ROCK,
    SLIDE,
    SLIDE_ROCK,
    STILL_MOVING,
    OutcomeMap,
)
from regimemap.mechanics.modes import Mode
from regimemap.motion.figures.outcome import (
    category_rectangles,
    cell_edges,
    draw_outcome_map,
    outcome_figure,
)


def synthetic_map(nx: int = 30, ny: int = 20, categories=(REST, SLIDE, ROCK, SLIDE_ROCK, OVERTURN)) -> OutcomeMap:
    x = np.linspace(0.1, 2.0, nx)
    y = np.linspace(0.2, 1.5, ny)
    X, Y = np.meshgrid(x, y)
    band = np.clip((X * 2.5).astype(int), 0, len(categories) - 1)
    cat = np.asarray(categories, dtype=np.int8)[band]
    slide = np.where((cat == SLIDE) | (cat == SLIDE_ROCK), X * Y * 0.3, 0.0)
    rot = np.where((cat == ROCK) | (cat == SLIDE_ROCK), 0.02 * X * Y, 0.0)
    rot = np.where(cat == OVERTURN, 0.4, rot)
    return OutcomeMap(first_name="k_peak", first_values=x, second_name="duration", second_values=y,
                      category=cat, overturned=cat == OVERTURN, max_rotation=rot, residual_slide=slide)


def test_style_registry_is_complete_and_colour_distinct():
    assert sorted(OUTCOME_STYLE) == [REST, SLIDE, ROCK, SLIDE_ROCK, OVERTURN, STILL_MOVING] == [0, 1, 2, 3, 4, 5]
    assert len(OUTCOME_STYLE) == len(CATEGORY_LABELS)
    assert len({s.color for s in OUTCOME_STYLE.values()}) == 6
    assert len({s.hatch for s in OUTCOME_STYLE.values()}) == 6
    assert OUTCOME_STYLE[ROCK] == MODE_STYLE[Mode.RO]  # the map's colours carry over
    assert OUTCOME_STYLE[SLIDE] == MODE_STYLE[Mode.SL] and OUTCOME_STYLE[REST] == MODE_STYLE[Mode.RE]
    assert phase_style(8).color == "#FFFFFF" and phase_style(2) == MODE_STYLE[Mode.RO]


def test_cell_edges_and_rectangles_cover_the_mask():
    np.testing.assert_allclose(cell_edges([1.0, 2.0, 4.0]), [0.5, 1.5, 3.0, 5.0])
    rng = np.random.default_rng(3)
    cat = rng.integers(0, 3, size=(9, 11))
    for code in range(3):
        cover = np.zeros(cat.shape, dtype=int)
        for j0, j1, i0, i1 in category_rectangles(cat, code):
            cover[i0:i1, j0:j1] += 1
        assert np.array_equal(cover, (cat == code).astype(int))


@pytest.mark.render
def test_outcome_map_has_a_patch_per_category_hatches_contours_and_key():
    m = synthetic_map()
    fig, ax, art = outcome_figure(m, xlabel="k", ylabel="T")
    present = sorted(int(c) for c in np.unique(m.category))
    assert sorted(art.regions) == present == [0, 1, 2, 3, 4]
    for code, patch in art.regions.items():
        assert patch.get_hatch() == OUTCOME_STYLE[code].hatch
        assert patch.get_facecolor()[:3] == pytest.approx(
            tuple(int(OUTCOME_STYLE[code].color[i:i + 2], 16) / 255 for i in (1, 3, 5)))
    assert set(art.contours) == {"residual_slide", "max_rotation"}
    assert art.boundaries is not None and len(art.boundaries.get_segments()) > 0
    texts = [t.get_text() for t in art.legend.get_texts()]
    assert texts[:5] == list(CATEGORY_LABELS[:5])
    assert "residual slide (m)" in texts and "maximum rotation (°)" in texts


@pytest.mark.render
def test_only_the_categories_present_and_no_contour_without_motion():
    m = synthetic_map(categories=(REST, OVERTURN))
    _, _, art = outcome_figure(m)
    assert sorted(art.regions) == [REST, OVERTURN]
    assert art.contours == {}  # nothing slid or rocked and stood


@pytest.mark.render
def test_decreasing_axis_is_drawn_increasing():
    m = synthetic_map()
    from matplotlib.figure import Figure

    ax = Figure().subplots()
    draw_outcome_map(ax, m, x=m.first_values[::-1].copy(), legend=False)
    lo, hi = ax.get_xlim()
    assert lo < hi


def svg_bytes(m: OutcomeMap) -> bytes:
    from regimemap.drawing.save import print_figure

    fig, _, _ = outcome_figure(m, title="test")
    buf = io.BytesIO()
    print_figure(fig, buf, "svg")
    return buf.getvalue()


@pytest.mark.render
def test_svg_is_byte_stable():
    m = synthetic_map()
    a, b = svg_bytes(m), svg_bytes(m)
    assert a == b and b"<svg" in a


@pytest.mark.render
@pytest.mark.deep
def test_motion_figure_shades_the_phases():
    from regimemap.dynamics import Block, Pulse, simulate
    from regimemap.motion.figures.history import motion_figure, phase_runs

    sim = simulate(Block(B=0.2, gamma=3.0, mu=0.35), Pulse.half_sine(0.6, 0.5), history=0)
    h = sim.history
    runs = phase_runs(h)
    assert [r[0] for r in runs[:3]] == [0, 2, 3]  # RE, RO, SRO-
    assert runs[0][1] == 0.0 and runs[-1][2] == h.t[-1]
    labels = [lab for lab, _ in sim.phases[0]]
    assert len(runs) == len(labels)
    fig = motion_figure(h, H=0.6, alpha=float(np.arctan(1 / 3)), duration=0.5, title="x")
    assert len(fig.axes) == 3
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "RE  rest" in legend and "SRO-  slide-rock about O, O slipping left" in legend


@pytest.mark.slow
def test_the_figure_of_an_outcome_record_labels_its_axes_and_titles_its_inputs() -> None:
    """outcome_record_figure reads the record: dimensionless axes where it has them, the fixed inputs."""
    from types import SimpleNamespace

    from regimemap.motion.figures.outcome_record import outcome_record_figure

    m = synthetic_map(8, 6)
    options = SimpleNamespace(swept=("k_peak", "duration"), shape="half-sine", fixed={"mu": 0.5})
    plain = SimpleNamespace(options=options, dimensionless_axes={}, restitution=None, outcome=m)
    ax = outcome_record_figure(plain, dpi=40).axes[0]
    assert "k_p" in ax.get_xlabel() and "duration" in ax.get_ylabel()
    assert 2.0 <= ax.get_xlim()[1] < 2.5  # the cells' edges, in k_peak
    dim = SimpleNamespace(options=options, restitution=0.8, outcome=m,
                          dimensionless_axes={"k_peak": np.linspace(1.0, 20.0, 8)})
    fig = outcome_record_figure(dim, dpi=40)
    ax = fig.axes[0]
    assert ax.get_xlabel() == r"$k_p\,/\tan\alpha$" and 20.0 <= ax.get_xlim()[1] < 25.0
    title = fig._suptitle.get_text() if fig._suptitle else ax.get_title()
    assert "μ = 0.5" in title and "0.8" in title


def test_the_title_of_a_run_names_the_pulse_and_the_block_or_the_design_file() -> None:
    from types import SimpleNamespace

    from regimemap.motion.figures.history import simulation_title

    inputs = {"design": None, "pulse_file": None, "k_peak": 0.6, "mu": 0.35, "kprime": 0.0,
              "pulse": "half-sine", "gamma": 3.0, "half_width": 0.2}
    run = SimpleNamespace(inputs=inputs, duration=0.5)
    assert simulation_title(run) == "half-sine pulse, k_peak = 0.6, T = 0.5 s; γ = 3, B = 0.2 m, μ = 0.35, k' = 0"
    run = SimpleNamespace(inputs={**inputs, "design": "/x/goda.toml", "k_peak": 0.2776}, duration=4.564)
    assert simulation_title(run) == "goda.toml: design wave, k = 0.2776, τ0 = 4.564 s; μ = 0.35"
