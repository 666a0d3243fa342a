"""What the workflows compute and hand to the drawing functions, checked against the library's
own functions called independently."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Parameters
from regimemap.maps.ambiguity import ambiguous_in_view, ambiguous_regions
from regimemap.maps.designer_view import points_off_view
from regimemap.maps.mapdata import compute_map, map_for_view
from regimemap.maps.points import DesignPoint
from regimemap.maps.query import classify_point, query_point
from regimemap.maps.sweeps import sweep_extent, sweep_frames, sweep_params


@pytest.mark.parametrize("params", [Parameters(3.0, 0.4), Parameters(0.7, -0.018, buoyancy=0.318,
                                                                    uplift_ratio=0.524)])
@pytest.mark.slow
def test_classify_point_is_query_point_of_the_block(params: Parameters) -> None:
    for k, mu in [(0.45, 0.6), (0.05, 1.0), (2.0, 0.1)]:
        got = classify_point(DesignPoint(k, mu), params)
        want = query_point(k, mu, params.gamma, params.kprime, **params.loads)
        assert got.mode == want.mode and (got.k, got.mu) == (k, mu)


def test_map_for_view_is_compute_map_of_the_view() -> None:
    p = Parameters(3.0, 0.4)
    a = map_for_view(p, k_max=2.0, mu_max=1.5, samples=101)
    b = compute_map(p, k_max=2.0, mu_max=1.5, samples=101)
    assert (a.k_max, a.mu_max) == (2.0, 1.5) and a.points.keys() == b.points.keys()
    assert all(np.array_equal(x, y) for m in b.polygons for x, y in zip(a.polygons[m], b.polygons[m]))


@pytest.mark.parametrize(("k_max", "mu_max"), [(0.5, 0.5), (2.0, 1.2), (50.0, 50.0)])
def test_off_view_points_are_the_named_points_outside(k_max: float, mu_max: float) -> None:
    p = Parameters(3.0, -0.3)
    data = compute_map(p, k_max=k_max, mu_max=mu_max, samples=101)
    want = points_off_view(p, k_max, mu_max)
    assert [q.name for q in data.off_view] == [q.name for q in want]
    assert all(q.k > k_max or q.mu > mu_max for q in data.off_view)
    assert bool(data.off_view) == (k_max < 50.0)  # B' and C' lie beyond 2 x 1.2, nothing beyond 50
    assert compute_map(p, k_max=k_max, mu_max=mu_max, samples=101, curves=False).off_view == ()


def test_ambiguous_in_view_keeps_the_parts_with_an_anchor_in_the_view() -> None:
    p = Parameters(3.0, -0.6)
    got = ambiguous_in_view(p, 4.0, 3.0)
    every = ambiguous_regions(p, 4.0 * 1.02, 3.0 * 1.02)
    assert got and len(got) == sum(r.anchor(4.0, 3.0) is not None for r in every)
    assert ambiguous_in_view(p, 4.0, 1.2) == []  # below the sliver: nothing in view


def test_sweep_frames_share_one_view_and_compute_each_map_when_drawn() -> None:
    values = [-0.6, 0.0, 0.5]
    frames = sweep_frames(3.0, values, samples=101)
    assert (frames.k_max, frames.mu_max) == sweep_extent(3.0, values)
    assert frames.blocks == tuple(Parameters(3.0, v) for v in values) and not frames.loaded
    assert not isinstance(frames.maps, list)  # computed one at a time, as the frames are drawn
    maps = list(frames.maps)
    for p, m in zip(frames.blocks, maps):
        want = compute_map(p, k_max=frames.k_max, mu_max=frames.mu_max, samples=101)
        assert m.params == p and m.points.keys() == want.points.keys()
    loaded = sweep_frames(0.7, [0.0, 0.5], sweep="uplift_ratio", fixed={"kprime": -0.02}, samples=51,
                          k_max=3.0, mu_max=2.0)
    assert loaded.loaded and isinstance(loaded.maps, list) and len(loaded.maps) == 2
    assert loaded.blocks[1] == sweep_params(0.7, "uplift_ratio", 0.5, {"kprime": -0.02})
    assert (loaded.maps[0].k_max, loaded.maps[0].mu_max) == (3.0, 2.0)
    with pytest.raises(ValueError, match="kprime"):
        sweep_frames(3.0, [1.5])
