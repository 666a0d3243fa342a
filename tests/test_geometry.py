"""Region polygons contain exactly the points classify gives their mode."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import MAP_MODES, Mode, Parameters, classify
from regimemap.maps.geometry import final_intervals, raw_intervals, region_polygons
from regimemap.mechanics.regions import raw_region


def _inside(poly: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Even-odd point-in-polygon test (numpy only)."""
    x, y = pts[:, 0][:, None], pts[:, 1][:, None]
    x0, y0 = poly[:, 0][None, :], poly[:, 1][None, :]
    x1, y1 = np.roll(poly[:, 0], -1)[None, :], np.roll(poly[:, 1], -1)[None, :]
    cond = (y0 > y) != (y1 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xc = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
    return (cond & (x < xc)).sum(axis=1) % 2 == 1


@pytest.mark.parametrize("gamma,kprime", [(3.0, 0.2), (3.0, 0.4), (3.0, 0.9), (1.0, 0.0),
                                           (1.0, -0.3), (3.0, -0.8), (2.0, -1.0)])
def test_polygons_match_classify(gamma, kprime):
    p = Parameters(gamma, kprime)
    polys = region_polygons(p, 3.0, 3.0, samples=401)
    rng = np.random.default_rng(0)
    pts = rng.uniform(0, 3, (4000, 2))
    lab = classify(pts[:, 0], pts[:, 1], gamma, kprime)
    hits = np.zeros(len(pts), int)
    which = np.full(len(pts), -1)
    for mode, lst in polys.items():
        for poly in lst:
            c = _inside(poly, pts)
            hits += c
            which[c] = mode
    # away from boundaries every point is in exactly one polygon, of its mode
    eps = 1e-3
    stable = np.ones(len(pts), bool)
    for dk, dm in ((eps, 0), (-eps, 0), (0, eps), (0, -eps)):
        stable &= classify(np.abs(pts[:, 0] + dk), np.abs(pts[:, 1] + dm), gamma, kprime) == lab
    assert (hits[stable] == 1).all()
    assert (which[stable] == lab[stable]).all()


@pytest.mark.parametrize("gamma,kprime", [(3.0, 0.4), (3.0, 0.9), (1.0, -0.3), (3.0, -0.8)])
def test_raw_intervals_match_raw_predicates(gamma, kprime):
    p = Parameters(gamma, kprime)
    k = np.linspace(0, 4, 97)
    mu = np.linspace(0, 3, 89)
    for mode in MAP_MODES:
        lo, hi = raw_intervals(mode, p, k, 10.0)
        K, M = np.meshgrid(k, mu)
        inside = (M > lo + 1e-9) & (M < hi - 1e-9)
        outside = (M < lo - 1e-9) | (M > hi + 1e-9)
        pred = raw_region(mode, p, K, M)
        assert pred[inside].all(), mode
        assert not pred[outside].any(), mode


def test_final_intervals_tile_each_column():
    p = Parameters(1.0, -0.3)
    k = np.linspace(0, 5, 51)
    iv = final_intervals(p, k, 4.0)
    total = sum(hi - lo for lo, hi in iv.values())
    assert np.allclose(total, 4.0)


def test_polygons_of_absent_modes_are_empty():
    polys = region_polygons(Parameters(3.0, 0.2), 3.0, 3.0)
    assert polys[Mode.SRO_PLUS] == [] and polys[Mode.SRO_PRIME_MINUS] == []


def test_area_in_view_clips_to_the_rectangle():
    from regimemap.maps.geometry import area_in_view

    square = np.array([[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]])
    assert area_in_view(square, 2.0, 2.0) == pytest.approx(1.0)
    assert area_in_view(square, 1.0, 1.0) == pytest.approx(0.25)  # one quarter inside
    assert area_in_view(square, 1.0, 0.5) == 0.0  # touches the top edge only
    assert area_in_view(square + 5.0, 2.0, 2.0) == 0.0
    big = np.array([[-1.0, -1.0], [9.0, -1.0], [9.0, 9.0], [-1.0, 9.0]])  # no vertex inside
    assert area_in_view(big, 2.0, 3.0) == pytest.approx(6.0)
    tri = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])  # cut by k = 1: int_0^1 (2 - k) dk
    assert area_in_view(tri, 1.0, 2.0) == pytest.approx(1.5)
