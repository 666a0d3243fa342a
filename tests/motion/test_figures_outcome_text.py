"""The text of outcome maps fits: no two texts overlap, none leaves the figure, titles wrap.

Every committed outcome figure (D.1-D.3, as ``make figures`` draws them) is checked on its PNG and
its PDF with the renderer's text boxes (the helpers of tests/drawing/test_legible.py), and so are maps made
to crowd: many contour levels in a thin band, a long title.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from regimemap.drawing.save import save_figure  # noqa: E402
from regimemap.dynamics import OutcomeMap  # noqa: E402
from regimemap.dynamics.boundaries import refine_crossings  # noqa: E402
from regimemap.dynamics.presets import DYNAMICS_FIGURE_IDS, DYNAMICS_FIGURES  # noqa: E402
from regimemap.motion.figures.outcome import outcome_figure, outcome_title  # noqa: E402
from regimemap.motion.figures.outcome_text import outcome_text_boxes  # noqa: E402
from regimemap.motion.figures.presets import dynamics_figure  # noqa: E402
from regimemap.motion.record_outcome import cached_outcome  # noqa: E402

from ..drawing.test_legible import _check_boxes  # noqa: E402


def _check_labels(fig, art) -> None:
    """Region names inside their region; contour labels inside a region where they mean something."""
    lookup = art.category_at
    for t in art.labels:
        code = int(t.get_gid().split("-")[1])
        assert lookup(np.asarray([t.get_position()]))[0] == code, t.get_text()
    for t in art.contour_labels:
        codes = (1, 3) if t.get_gid().endswith("residual_slide") else (2, 3)
        assert lookup(np.asarray([t.get_position()]))[0] in codes, t.get_text()


#: The cache ``make figures`` fills (``regimemap dynamics-figures --cache``), under the repository's root.
MAKE_FIGURES_CACHE = ".cache/dynamics-figures"


@pytest.fixture(scope="module")
def cache_dir(pytestconfig, tmp_path_factory):
    """Where the maps of D.1-D.3 are kept between runs: pytest's cache (a folder of this module's
    own with ``-p no:cacheprovider``), holding copies of the maps ``make figures`` computed.

    Computing the three maps takes about a minute of one core; ``make figures`` (``make``)
    computes the same ones (the same names and keys: :func:`regimemap.motion.record_outcome.cached_outcome`
    keys a map by the figure's definition, the versions, numpy's CPU dispatch and the source of
    :mod:`regimemap.dynamics`, and reads back the very arrays a fresh computation gives).  Its
    files are copied, never changed: :func:`cached_outcome` skips those of other keys and
    computes the maps still missing.
    """
    import os
    import shutil

    cache = getattr(pytestconfig, "cache", None)  # None with -p no:cacheprovider
    folder = cache.mkdir("dynamics-figures") if cache is not None else tmp_path_factory.mktemp("dyn")
    made = pytestconfig.rootpath / MAKE_FIGURES_CACHE
    for fid in DYNAMICS_FIGURE_IDS:
        for npz in sorted(made.glob(f"{fid}-*.npz")):
            if not (folder / npz.name).is_file():  # whole or not at all (xdist workers share it)
                part = folder / f".{npz.name}.{os.getpid()}"
                shutil.copyfile(npz, part)
                os.replace(part, folder / npz.name)
    return folder


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.parametrize("fid", DYNAMICS_FIGURE_IDS)
@pytest.mark.deep
def test_committed_outcome_figures_never_collide(fid, cache_dir, tmp_path):
    f = DYNAMICS_FIGURES[fid]
    m, x, y, _ = cached_outcome(cache_dir, fid, repr(f), f.compute)
    assert m.refined
    boxes = {}
    for fmt in ("png", "pdf"):
        fig = dynamics_figure(f, (m, x, y))
        art = fig._regimemap_outcome
        save_figure(fig, tmp_path / f.filename(fmt), fmt)
        _check_boxes(fig, lambda fig=fig, art=art: outcome_text_boxes(fig, art))
        _check_labels(fig, art)
        assert art.contour_labels or not art.contours, "contours without a label"
        boxes[fmt] = outcome_text_boxes(fig, art)
        # every contour line drawn has its label
        for key, cs in art.contours.items():
            drawn = sum(1 for p in cs.get_paths() if len(p.vertices))
            labelled = sum(1 for t in art.contour_labels if t.get_gid() == f"contour-{key}")
            assert drawn == labelled, (key, drawn, labelled)
    assert boxes["png"] == boxes["pdf"]  # the same layout in every format


def crowded_map(title_arm: float = 1 / 3) -> OutcomeMap:
    """Rotation contours crowded into a thin band above rest (as in D.2), slides beside them."""
    x = np.linspace(0.5, 10.0, 48)
    y = np.linspace(0.25, 12.0, 40)
    X, Y = np.meshgrid(x, y)

    def f(a, b):
        cat = np.where(b < 1.0, 0, 2)
        cat = np.where((b > 1.0) & (a > 7.0), 3, cat)
        cat = np.where(b > 1.3 + 0.9 * a, 4, cat)
        return cat.astype(np.int8)

    cat = f(X, Y)
    # from nothing on the rest boundary (k = 1) to 15 degrees, the lines converging to the left
    rot = np.where(np.isin(cat, (2, 3)), np.radians(15.0) * (np.clip(Y - 1.0, 0, None) / 11.0) ** 0.3 * X / 10, 0.0)
    slide = np.where(cat == 3, 0.001 * (X - 7.0) * Y, 0.0)
    m = OutcomeMap(first_name="omega_p", first_values=x, second_name="k_peak", second_values=y, category=cat,
                   overturned=cat == 4, max_rotation=rot, residual_slide=slide)
    import dataclasses

    return dataclasses.replace(m, crossings=refine_crossings(x, y, cat, f))


@pytest.mark.render
@pytest.mark.parametrize("refined", [True, False])
def test_crowded_contours_and_a_long_title_fit(refined):
    m = crowded_map()
    title = outcome_title("half-sine", {"gamma": 3.0, "half_width": 0.2, "mu": 0.5, "kprime": 0.0, "buoyancy": 0.3,
                                        "uplift": 0.1, "uplift_ratio": 0.52, "uplift_arm": 1 / 3},
                          restitution=0.85, min_rotation=1e-3)
    assert title.endswith("rocking from 0.0573°") and "e_u = 0.3333" in title
    fig, ax, art = outcome_figure(m, title=title, refined=refined, dpi=60)
    _check_boxes(fig, lambda: outcome_text_boxes(fig, art))
    _check_labels(fig, art)
    assert "\n" in art.title.get_text()  # wrapped, not clipped
    assert "e_u = 0.3333" in art.title.get_text().replace("\n", " ")
    levels = art.contours["max_rotation"].levels
    assert len(levels) >= 5 and 1 <= len([t for t in art.contour_labels if "°" in t.get_text()]) <= len(levels)
    assert art.report is not None and any("contour" in s for s in art.report.placed)


@pytest.mark.render
def test_refined_map_is_drawn_as_polygons_without_staircase():
    m = crowded_map()
    fig, ax, art = outcome_figure(m, dpi=60)
    assert ax.get_xlim() == (0.5, 10.0)  # the polygons span the nodes
    over = art.regions[4].get_path().vertices
    d = np.diff(over, axis=0)
    slanted = (np.abs(d[:, 0]) > 1e-9) & (np.abs(d[:, 1]) > 1e-9)
    assert slanted.sum() > 10  # the slanted boundary of the overturned region, not steps
    assert art.boundaries is not None and len(art.boundary_lines) >= 3
    cells = outcome_figure(m, dpi=60, refined=False)[2]
    assert len(cells.boundary_lines) > len(art.boundary_lines)  # the staircase: one segment per run of cells
