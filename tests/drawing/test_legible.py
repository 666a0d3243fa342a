"""Maps an engineer can read at any parameters: no text collides, nothing leaves the figure.

A sweep of maps (gamma from 0.3 to 10, k' from -1 to 1 with +-0.99, +-1 and 0;
with and without design points; raw single-mode maps; an atlas; animation
frames) is rendered at low dpi and checked from the artists' window extents:

* no two texts overlap (point names, region labels, line labels, tick labels,
  design points, titles, keys), nor a label a marker, nor leaves the figure;
* a line's label sits on or next to its line, or points at it with a leader;
* a region's label has its anchor inside its region;
* a dotted line that coincides with a boundary is not drawn nor in the key.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.path import Path  # noqa: E402

from regimemap import Mode, Parameters  # noqa: E402
from regimemap.drawing.text.tidy import MEASURE_DPI, text_boxes  # noqa: E402
from regimemap.maps import DesignPoint, classify  # noqa: E402
from regimemap.maps.figures.animation import draw_frame, frame_figure  # noqa: E402
from regimemap.maps.figures.atlas import atlas_figure  # noqa: E402
from regimemap.maps.figures.figure import map_figure  # noqa: E402
from regimemap.maps.figures.presets import FIGURE_IDS  # noqa: E402
from regimemap.maps.run import run_map  # noqa: E402
from regimemap.maps.run_atlas import run_atlas  # noqa: E402

pytestmark = pytest.mark.render

DPI = 50
GAMMAS = (0.3, 1.0, 3.0, 10.0)
KPRIMES = (-1.0, -0.99, -0.5, 0.0, 0.4, 0.99, 1.0)

CASES = [(g, kp, "all") for g in GAMMAS for kp in KPRIMES] + [
    (2.0, -0.3, "points"), (5.0, -0.99, "points"), (3.0, 0.4, "points"), (1.0, -0.5, "all"),
    (5.0, -1.0, "all"), (3.0, -0.3, "raw-RO"), (3.0, 0.85, "raw-SRO+"), (3.0, -0.6, "raw-all"),
    (0.7, -0.018, "goda"), (3.0, 0.4, "loaded"), (1.0, -0.6, "loaded"),
]

#: Loads of the loaded cases: Goda's caisson (lift-off in view) and two others.
LOADS = {(0.7, -0.018): {"buoyancy": 0.318, "uplift_ratio": 0.524},
         (3.0, 0.4): {"buoyancy": 0.4, "uplift": 0.1},
         (1.0, -0.6): {"buoyancy": 0.5, "uplift_ratio": 0.8}}


def _hit(a, b, tol=0.5):
    return a[0] + tol < b[2] and b[0] + tol < a[2] and a[1] + tol < b[3] and b[1] + tol < a[3]


def _check_boxes(fig, boxes):
    """``boxes`` from :func:`text_boxes` after the figure was drawn at its own resolution.

    Call as ``_check_boxes(fig, lambda: text_boxes(...))``: the figure is laid
    out first, as a file is (the axis labels take their places when drawn), at
    the resolution the tidy pass measures with (the layout is the same at every
    resolution; below ~100 dpi hinting may make neighbours touch).
    """
    fig.set_dpi(MEASURE_DPI)
    fig.draw_without_rendering()
    boxes = boxes()
    fb = fig.bbox
    frame = (fb.x0 - 0.5, fb.y0 - 0.5, fb.x1 + 0.5, fb.y1 + 0.5)
    texts = boxes["fixed"] + boxes["labels"]
    for name, b in texts:
        assert frame[0] <= b[0] and frame[1] <= b[1] and b[2] <= frame[2] and b[3] <= frame[3], \
            f"{name} leaves the figure: {b} not in {frame}"
    for i, (na, a) in enumerate(texts):
        for nb, b in texts[i + 1:]:
            assert not _hit(a, b), f"{na} overlaps {nb}"
    for na, a in boxes["labels"]:
        for nb, b in boxes["markers"]:
            assert not _hit(a, b), f"{na} overlaps the marker of {nb}"


def _dense(q, step=0.5):
    """A polyline (pixels) with vertices at most ``step`` pixels apart."""
    parts = [q[:1]]
    for a, b in zip(q[:-1], q[1:]):
        n = max(1, int(np.ceil(np.hypot(*(b - a)) / step)))
        parts.append(a + (np.arange(1, n + 1) / n)[:, None] * (b - a))
    return np.concatenate(parts)


def _near_line(ax, label, points, renderer):
    """Is the label's box within one text height of the polyline (display coordinates)?"""
    b = label.get_window_extent(renderer)
    dense = _dense(ax.transData.transform(points))
    dx = np.maximum(np.maximum(b.x0 - dense[:, 0], dense[:, 0] - b.x1), 0.0)
    dy = np.maximum(np.maximum(b.y0 - dense[:, 1], dense[:, 1] - b.y1), 0.0)
    return float(np.min(np.hypot(dx, dy))) <= b.height


def _check_map(fig, art):
    ax = art.title.axes if art.title is not None else None
    renderer = fig.canvas.get_renderer()
    if ax is None:
        return
    for name, t in art.curve_labels.items():
        if not t.get_visible():
            continue
        pts = art.data.curves[name].points
        if getattr(t, "arrow_patch", None) is not None:  # a leader: its tip is on the line
            tip = ax.transData.transform([t.xy])[0]
            dense = _dense(ax.transData.transform(pts))
            assert np.min(np.hypot(*(dense - tip).T)) <= 2.0, f"leader of {name} misses its line"
        else:
            assert _near_line(ax, t, pts, renderer), f"label of {name} is far from its line"
    for mode, texts in art.region_labels.items():
        polys = [Path(p) for p in art.data.polygons.get(mode, []) if len(p) >= 3]
        for t in texts:
            if not t.get_visible():
                continue
            xy = t.xy if getattr(t, "arrow_patch", None) is not None else t.get_position()
            assert any(p.contains_point(xy, radius=1e-9 * art.data.k_max) or
                       p.contains_point(xy, radius=-1e-9 * art.data.k_max) for p in polys), \
                f"label of {Mode(mode).label} at {xy} is not inside its region"
    if art.data.params.kprime == -1.0:
        assert "dotted" not in art.data.curves, "mu = k|k'| coincides with OA at k' = -1"
        if art.legend is not None:
            assert not any("dotted" in t.get_text() for t in art.legend.get_texts())


@pytest.mark.parametrize("gamma,kprime,what", CASES)
def test_map_text_never_collides(gamma, kprime, what):
    kw = {}
    points = ()
    if what == "points":
        p = Parameters(gamma, kprime)
        k_a = min(p.k_A, 1.0) if np.isfinite(p.k_A) else 0.5
        points = [DesignPoint(0.45, 0.6, "caisson-A"), DesignPoint(0.3, 0.1, "caisson-B"),
                  DesignPoint(k_a, k_a, "at A"), DesignPoint(0.9 * k_a, 0.5, "")]
    elif what.startswith("raw-"):
        label = what[4:]
        kw = {"raw": True} if label == "all" else {"raw": True, "modes": [Mode.from_label(label)]}
    loads = LOADS.get((gamma, kprime), {}) if what in ("goda", "loaded") else {}
    fig, ax, art = map_figure(run_map(Parameters(gamma, kprime, **loads), points=points, samples=201,
                                      **kw), dpi=DPI)
    _check_boxes(fig, lambda: text_boxes(fig, [art]))
    _check_map(fig, art)
    if what.startswith("raw-") and what != "raw-all":
        assert "Raw region of" in art.title.get_text()
    if what == "raw-all":
        assert "Raw regions of all modes" in art.title.get_text()
    if what == "goda":  # the designer's view keeps lift-off (k_L = 3.45) in sight
        assert art.data.k_max >= Parameters(gamma, kprime, **loads).k_L
        assert any(t.get_text() == "lift-off (no contact)" for t in art.legend.get_texts())
    # every mode seen in the view has its entry in the key
    if art.legend is not None and not kw:
        k_max, mu_max = art.data.k_max, art.data.mu_max
        kk, mm = np.meshgrid(np.linspace(0, k_max, 300)[1:-1], np.linspace(0, mu_max, 300)[1:-1])
        seen = {Mode(int(c)).description for c in np.unique(classify(kk, mm, gamma, kprime, **loads))}
        assert seen <= {t.get_text() for t in art.legend.get_texts()}


def test_key_leaves_out_modes_beyond_the_view():
    """At gamma = 0.3, k' = 0.99 rocking starts above A (1.68, 1.68): not in the designer's view."""
    p = Parameters(0.3, 0.99)
    fig, ax, art = map_figure(run_map(p, samples=201), dpi=DPI)
    assert art.data.mu_max == 1.2 and p.mu_A > 1.2
    keyed = {t.get_text() for t in art.legend.get_texts()}
    assert Mode.RO.description not in keyed and Mode.SL.description in keyed
    # the report's view shows A and rocking above it, and keys it
    fig, ax, art = map_figure(run_map(p, samples=201, view="report"), dpi=DPI)
    assert Mode.RO.description in {t.get_text() for t in art.legend.get_texts()}

@pytest.mark.deep
def test_atlas_panels_never_collide():
    fig = atlas_figure(run_atlas([1.0, 3.0], [-0.6, 0.0, 0.9], samples=151), dpi=DPI)
    arts = fig._regimemap_maps  # the panels' MapArtists
    _check_boxes(fig, lambda: text_boxes(fig, arts))
    for art in arts:
        _check_map(fig, art)


@pytest.mark.slow
def test_one_row_atlas_leaves_room_for_mu():
    fig = atlas_figure(run_atlas([3.0], [-1.0, -0.5, 0.0, 0.5, 1.0], share="none", samples=151), dpi=DPI)
    _check_boxes(fig, lambda: text_boxes(fig, fig._regimemap_maps))


@pytest.mark.parametrize("kprime", [-1.0, -0.5, 0.0, 0.99])
def test_animation_frames_never_collide(kprime):
    fig, ax = frame_figure(dpi=60)
    from regimemap.maps.mapdata import compute_map

    art = draw_frame(fig, ax, 3.0, kprime, compute_map(Parameters(3.0, kprime), k_max=2.0, mu_max=1.2,
                                                       samples=151))
    box = next(t for t in fig.texts if t.get_gid() == "frame-kprime")
    _check_boxes(fig, lambda: text_boxes(fig, [art], [box]))
    _check_map(fig, art)
    # the k' box is outside the map, the key below it
    renderer = fig.canvas.get_renderer()
    assert box.get_window_extent(renderer).y0 >= ax.bbox.y1
    leg = fig.legends[0].get_window_extent(renderer)
    assert leg.y1 <= ax.bbox.y0 and leg.height < 0.2 * fig.bbox.height


@pytest.mark.parametrize("fid", FIGURE_IDS)
def test_report_figures_never_collide(fid):
    """The report's 24 figures keep their views and get the same tidy pass (Figs 3.8, 3.9a, 4.7b)."""
    from regimemap.maps.figures.figure import preset_figure
    from regimemap.maps.figures.presets import get_preset

    preset = get_preset(fid)
    fig, ax, art = preset_figure(preset, run_map(**preset.map_keywords, samples=201), dpi=DPI)
    if preset.k_max is not None:  # the preset's axes win
        assert art.data.k_max == preset.k_max
    if preset.mu_max is not None:
        assert art.data.mu_max == preset.mu_max
    _check_boxes(fig, lambda: text_boxes(fig, [art]))
    _check_map(fig, art)


@pytest.mark.slow
@pytest.mark.parametrize("wid", ["W.1", "W.2", "W.3", "W.4"])
def test_worked_figures_never_collide(wid):
    from regimemap.maps.figures.worked import WORKED, render_worked

    w = WORKED[wid]
    if w.sweep is not None:  # an atlas: the artists of its panels
        fig = render_worked(w, run_atlas(**w.atlas_keywords, samples=151), dpi=DPI)
        arts = fig._regimemap_maps
    else:
        fig, ax, art = map_figure(run_map(**w.map_keywords, samples=151), dpi=DPI, title=w.title)
        arts = [art]
    _check_boxes(fig, lambda: text_boxes(fig, arts))
    for art in arts:
        _check_map(fig, art)


def test_the_layout_does_not_depend_on_the_resolution(tmp_path):
    """An SVG is the same whatever --dpi was asked for (the texts are placed at MEASURE_DPI)."""
    from regimemap.drawing.save import save_figure

    out = []
    for dpi in (30, 150, 300):
        fig, _, _ = map_figure(run_map(Parameters(3.0, -0.3), samples=201), dpi=dpi)
        save_figure(fig, tmp_path / f"m{dpi}.svg", "svg")
        out.append((tmp_path / f"m{dpi}.svg").read_bytes())
    assert out[0] == out[1] == out[2]
