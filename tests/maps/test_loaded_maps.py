"""Maps of a loaded block through the public API: polygons, curves, view, queries, margins, ambiguity."""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap import LOADED_MAP_MODES, Mode, Parameters, classify, label_grid, margin, query_point
from regimemap.maps import ambiguous_regions, auto_extent, compute_map, region_polygons
from regimemap.mechanics.curves import map_curves, named_points

#: Loaded blocks that show lift-off, rock about O', rest failing about O', heavy buoyancy.
CASES = [
    Parameters(1.5, 0.0, uplift=0.4, uplift_ratio=0.5, uplift_arm=0.0),
    Parameters(3.0, 0.4, buoyancy=0.3, uplift=0.2, uplift_ratio=0.4, uplift_arm=-0.8),
    Parameters(0.8, -0.5, buoyancy=0.2, uplift=0.9, uplift_arm=-1.0, gyration=0.5),
    Parameters(3.0, -0.6, buoyancy=0.5, gyration=2.0),
    Parameters(6.0, 1.2, uplift=0.3, uplift_ratio=2.0, uplift_arm=0.5, crest=1.5),
]


def _inside(poly: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Even-odd point-in-polygon test."""
    px, py = poly[:, 0], poly[:, 1]
    inside = np.zeros(x.shape, bool)
    j = len(px) - 1
    for i in range(len(px)):
        with np.errstate(divide="ignore", invalid="ignore"):
            cross = ((py[i] > y) != (py[j] > y)) & (x < (px[j] - px[i]) * (y - py[i]) / (py[j] - py[i]) + px[i])
        inside ^= cross
        j = i
    return inside


def _near_edge(poly: np.ndarray, xs: np.ndarray, ys: np.ndarray, scale, tol: float) -> np.ndarray:
    """Whether each point of the grid ``meshgrid(xs, ys)`` (raveled) lies closer than ``tol`` to an
    edge of ``poly``, distances measured in units of ``scale`` (the view).

    A point can be that close to a segment only inside the segment's box grown by ``tol``: the
    distance is computed there only (a few cells of the grid per segment, not every point).
    """
    gx, gy = xs / scale[0], ys / scale[1]
    s = poly / np.asarray(scale)
    near = np.zeros((gy.size, gx.size), bool)
    for a, b in zip(s[:-1], s[1:], strict=True):
        lo, hi = np.minimum(a, b) - 2.0 * tol, np.maximum(a, b) + 2.0 * tol
        i0, i1 = np.searchsorted(gx, lo[0]), np.searchsorted(gx, hi[0], side="right")
        j0, j1 = np.searchsorted(gy, lo[1]), np.searchsorted(gy, hi[1], side="right")
        if i0 >= i1 or j0 >= j1:
            continue
        qx, qy = np.meshgrid(gx[i0:i1], gy[j0:j1])
        d = b - a
        L2 = max(float(d @ d), 1e-300)
        t = np.clip(((qx - a[0]) * d[0] + (qy - a[1]) * d[1]) / L2, 0, 1)
        near[j0:j1, i0:i1] |= np.hypot(a[0] + t * d[0] - qx, a[1] + t * d[1] - qy) < tol
    return near.ravel()


@pytest.mark.slow
@pytest.mark.parametrize("p", CASES, ids=repr)
def test_polygons_of_loaded_maps_match_label_grid(p):
    k_max, mu_max = auto_extent(p)
    polys = region_polygons(p, k_max, mu_max, samples=401)
    kk = np.linspace(0, k_max, 151)
    mu = np.linspace(0, mu_max, 131)
    grid = label_grid(kk, mu, p.gamma, p.kprime, **p.loads)
    K, M = np.meshgrid(kk, mu)
    x, y = K.ravel(), M.ravel()
    covered = np.zeros(x.shape, int)
    near = np.zeros(x.shape, bool)
    for mode, lst in polys.items():
        for poly in lst:
            ins = _inside(poly, x, y)
            edge = _near_edge(poly, kk, mu, (k_max, mu_max), 2e-3)
            near |= edge
            assert (grid.ravel()[ins & ~edge] == mode).all(), (mode.label,)
            covered += ins
    assert (covered[~near] == 1).all()  # the polygons tile the view away from their edges
    assert set(np.unique(grid)) <= {int(m) for m in LOADED_MAP_MODES}


def test_lift_off_polygons_are_whole_columns_from_L():
    p = CASES[0]
    polys = region_polygons(p, 4.0, 3.0)
    (lo,) = polys[Mode.LO]
    assert lo[:, 0].min() == pytest.approx(p.k_L, rel=1e-9)
    assert lo[:, 1].min() == 0.0 and lo[:, 1].max() >= 3.0


@pytest.mark.parametrize("p", CASES, ids=repr)
def test_curves_points_and_view_of_loaded_maps(p):
    cur = map_curves(p)
    pts = named_points(p)
    k_max, mu_max = auto_extent(p)
    for c in cur.values():
        if c.func is not None and math.isfinite(c.k_from):
            k = np.linspace(max(c.k_from, 0.0), min(c.k_to, 5.0), 5)
            spec = c.spec
            val = c.func(k)
            if spec["type"] == "line":
                expect = spec["c0"] + spec["c1"] * k
            else:
                num = spec["p"] * k + spec["q"]
                with np.errstate(divide="ignore", invalid="ignore"):
                    expect = (np.abs(num) if spec["abs"] else num) / (spec["r"] * k + spec["t"])
            ok = np.isfinite(val) & np.isfinite(expect)
            assert np.allclose(val[ok], expect[ok], rtol=1e-9, atol=1e-12), c.name
    if math.isfinite(p.k_L):
        assert pts["L"].k == p.k_L and cur["LO"].vertical_k == p.k_L
        assert p.k_L <= k_max  # the view shows where lift-off starts
        # classify: LO on the right of L, not on the left
        assert classify(p.k_L * 1.01 + 1e-9, 0.5, p.gamma, p.kprime, **p.loads) == Mode.LO
        assert classify(p.k_L * 0.99, 0.5, p.gamma, p.kprime, **p.loads) != Mode.LO
    if "A" in pts:
        assert pts["A"].k <= k_max
    m = compute_map(p, samples=201)
    assert m.modes == LOADED_MAP_MODES and m.k_max == k_max


@pytest.mark.slow
@pytest.mark.parametrize("p", CASES, ids=repr)
@pytest.mark.deep
def test_query_point_and_margins_with_loads_agree_with_classify(p):
    rng = np.random.default_rng(3)
    k_max, mu_max = auto_extent(p)
    for k, mu in zip(rng.uniform(0, k_max, 12), rng.uniform(0, mu_max, 12)):
        r = query_point(k, mu, p.gamma, p.kprime, **p.loads)
        mode = Mode(int(classify(k, mu, p.gamma, p.kprime, **p.loads)))
        assert r.mode is mode and r.loads == p.loads
        assert r.admissible and mode in r.admissible  # the admissible set, with the chosen mode
        assert r.as_dict()["loads"] == p.loads
        mk, mm = margin(k, mu, p.gamma, p.kprime, **p.loads)
        assert (mk, mm) == (r.margin_k, r.margin_mu)
        for mg in (mk, mm):
            for c in (mg.up, mg.down):
                if c is None:
                    continue
                # the crossing: the point's mode just before `at`, another mode at `at`
                before = np.nextafter(c.at, mg.value)
                args = (before, mu) if mg.variable == "k" else (k, before)
                at = (c.at, mu) if mg.variable == "k" else (k, c.at)
                assert classify(*args, p.gamma, p.kprime, **p.loads) == mode or c.on_boundary
                assert classify(*at, p.gamma, p.kprime, **p.loads) != mode


@pytest.mark.slow
def test_query_point_reports_least_constraint_choices():
    p = CASES[0]
    regions = ambiguous_regions(p, 4.0, 3.0)
    labels = {r.label for r in regions}
    assert "{LO, RO, SRO-} -> LO (least constraint)" in labels
    r0 = next(r for r in regions if r.chosen is Mode.LO)
    k, mu = r0.anchor()
    res = query_point(k, mu, p.gamma, p.kprime, **p.loads)
    assert res.mode is Mode.LO and set(res.admissible) == {Mode.LO, Mode.RO, Mode.SRO_MINUS}
    assert res.admissible[0] is Mode.LO and res.chosen_by == "least constraint"
    # the report's block keeps Section 4.7's labels
    assert [r.label for r in ambiguous_regions(Parameters(3.0, -0.6), 4.0, 3.0)] == [
        "{SL, RO, SRO-} -> SL (Section 4.7)"]


def test_parameters_with_loads():
    p = Parameters(3.0, 0.4, buoyancy=0.3, gyration=1.5)
    assert p.loaded and not Parameters(3.0, 0.4).loaded and not Parameters(3.0, 0.4, crest=1.2).loaded
    assert p == Parameters(3.0, 0.4, buoyancy=0.3, gyration=1.5) != Parameters(3.0, 0.4)
    assert hash(p) == hash(Parameters(3.0, 0.4, buoyancy=0.3, gyration=1.5))
    assert repr(p) == "Parameters(gamma=3.0, kprime=0.4, buoyancy=0.3, gyration=1.5, a=2.2, b=9.0, c=12.6, d=37.0)"
    assert repr(Parameters(3.0, 0.4)) == "Parameters(gamma=3.0, kprime=0.4, a=2.2, b=9.0, c=12.6, d=37.0)"
    assert p.as_dict()["buoyancy"] == 0.3 and "buoyancy" not in Parameters(3.0, 0.4).as_dict()
    with pytest.raises(TypeError):
        Parameters(3.0, 0.4, 0.3)  # the loads are keyword-only
