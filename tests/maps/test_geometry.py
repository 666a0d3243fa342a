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


# -- the edges of the polygons, all at once ----------------------------------------------------------


def test_bisect_edges_finds_what_bisect_edge_finds_one_by_one():
    from regimemap.maps.geometry import bisect_edge, bisect_edges

    rng = np.random.default_rng(3)
    n = 40
    cut = rng.uniform(0.0, 5.0, n)  # edge e holds for k <= cut[e] (or >= when reversed)
    below = rng.random(n) < 0.5
    width = 10.0 ** rng.uniform(-12, 0, n)
    k_in = np.where(below, cut - width * rng.random(n), cut + width * rng.random(n))
    k_out = np.where(below, cut + width, cut - width)
    k_in[0], k_out[0] = 1.0, np.nextafter(1.0, 2.0)  # adjacent floats: nothing to bisect
    cut[0], below[0] = 1.0, True

    def holds(e: int, k: np.ndarray) -> np.ndarray:
        return np.asarray(k <= cut[e]) if below[e] else np.asarray(k >= cut[e])

    def present(which: np.ndarray, k: np.ndarray) -> np.ndarray:
        return np.array([holds(int(e), row) for e, row in zip(which, k)])

    for columns, iterations in ((512, 60), (1, 60), (100, 7), (4000, 60), (64, 0)):
        got = bisect_edges(present, k_in, k_out, iterations=iterations, columns=columns)
        want = [bisect_edge(lambda k, e=e: bool(holds(e, np.array(k))), float(k_in[e]),
                            float(k_out[e]), iterations=iterations) for e in range(n)]
        np.testing.assert_array_equal(got, want)
    assert bisect_edges(present, np.zeros(0), np.zeros(0)).size == 0


def _one_edge_at_a_time(p: Parameters, k_max: float, mu_max: float, samples: int, modes, raw):
    """The polygons of a loaded block from the pieces' lists and bisect_edge, edge by edge."""
    from regimemap.maps.geometry import bisect_edge, final_pieces, raw_pieces, sample_k

    mu_cap = 1.5 * mu_max
    k = sample_k(p, k_max, samples)

    def pieces(kk: np.ndarray):
        return raw_pieces(p, kk, mu_cap, modes) if raw else final_pieces(p, kk, mu_cap)

    def piece_at(kk: float, key):
        found = [(lo, hi) for m, lo, hi in pieces(np.array([kk]))[0] if m == key[0]]
        return found[key[1]] if len(found) > key[1] else None

    tracks: dict = {}
    for j, col in enumerate(pieces(k)):
        seen: dict = {}
        for m, lo, hi in col:
            t = seen[m] = seen.get(m, -1) + 1
            lo_t, hi_t = tracks.setdefault((m, t), (np.full(k.size, np.nan), np.full(k.size, np.nan)))
            lo_t[j], hi_t[j] = lo, hi
    out: dict = {m: [] for m in modes}
    for key, (lo, hi) in sorted(tracks.items(), key=lambda kv: (int(kv[0][0]), kv[0][1])):
        if key[0] not in out:
            continue
        idx = np.flatnonzero(np.isfinite(lo))
        for run in np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1):
            ks, los, his = list(k[run]), list(lo[run]), list(hi[run])
            for inner, outer, front in ((run[0], run[0] - 1, True), (run[-1], run[-1] + 1, False)):
                if not 0 <= outer < k.size:
                    continue
                ke = bisect_edge(lambda kk, key=key: piece_at(kk, key) is not None, k[inner], k[outer])
                pc = piece_at(ke, key)
                if pc is not None and ke != k[inner]:
                    at = 0 if front else len(ks)
                    ks.insert(at, ke)
                    los.insert(at, pc[0])
                    his.insert(at, pc[1])
            kk, ll, hh = np.asarray(ks), np.asarray(los), np.asarray(his)
            out[key[0]].append(np.concatenate([np.column_stack([kk, ll]),
                                               np.column_stack([kk[::-1], hh[::-1]])]))
    return out


@pytest.mark.parametrize("p", [
    Parameters(0.8, -0.018, buoyancy=0.318, uplift_ratio=0.524),  # Goda's caisson, lift-off in view
    Parameters(1.5, -0.018, buoyancy=0.318, uplift_ratio=0.524),  # one float of no mode at mu_B'
    Parameters(3.0, -0.6, buoyancy=0.5, gyration=2.0),
    Parameters(1.5, 0.0, uplift=0.4, uplift_ratio=0.5, uplift_arm=0.0),  # 2 raw pieces of a mode
], ids=repr)
@pytest.mark.deep
def test_loaded_polygons_are_the_pieces_followed_one_edge_at_a_time(p):
    """The vectorised tracks and edges give exactly the polygons of the plain lists and bisect_edge."""
    from regimemap.mechanics.modes import LOADED_MAP_MODES

    cases = [(tuple(LOADED_MAP_MODES), False)] + [((m,), True) for m in LOADED_MAP_MODES]
    cases.append((tuple(LOADED_MAP_MODES), True))  # raw regions may overlap
    for modes, raw in cases:
        want = _one_edge_at_a_time(p, 2.0, 1.2, 201, modes, raw)
        got = region_polygons(p, 2.0, 1.2, modes=modes, raw=raw, samples=201)
        assert list(got) == list(want)
        for mode in want:
            assert len(got[mode]) == len(want[mode]), (mode, raw)
            for a, b in zip(got[mode], want[mode]):
                np.testing.assert_array_equal(a, b)


def test_a_single_float_of_no_mode_is_left_out():
    """Where strict ends meet (mu = mu_B' at a corner) no hypothesis holds: no piece, no error."""
    from regimemap.maps import auto_extent
    from regimemap.maps.geometry import final_pieces, sample_k

    p = Parameters(1.5, -0.018, buoyancy=0.318, uplift_ratio=0.524)
    k_max, mu_max = auto_extent(p)
    k = sample_k(p, k_max, 801)
    cols = final_pieces(p, k, 1.5 * mu_max)
    gaps = [(j, a[2], b[1]) for j, col in enumerate(cols) for a, b in zip(col, col[1:]) if a[2] != b[1]]
    assert gaps  # this block has such a point in a column
    for j, top, bottom in gaps:
        assert bottom - top <= 4 * np.spacing(bottom)  # a float or two wide
        assert classify(k[j], 0.5 * (top + bottom), p.gamma, p.kprime, **p.loads) == 255
    polys = region_polygons(p, k_max, mu_max)
    rng = np.random.default_rng(1)
    pts = rng.uniform(0.0, 1.0, (3000, 2)) * (k_max, mu_max)
    lab = classify(pts[:, 0], pts[:, 1], p.gamma, p.kprime, **p.loads)
    eps = 1e-3
    stable = np.ones(len(pts), bool)
    for dk, dm in ((eps, 0), (-eps, 0), (0, eps), (0, -eps)):
        stable &= classify(np.abs(pts[:, 0] + dk), np.abs(pts[:, 1] + dm), p.gamma, p.kprime,
                           **p.loads) == lab
    hits = np.zeros(len(pts), int)
    for mode, lst in polys.items():
        for poly in lst:
            inside = _inside(poly, pts)
            hits += inside
            assert (lab[inside & stable] == mode).all(), mode
    assert (hits[stable] == 1).all()
