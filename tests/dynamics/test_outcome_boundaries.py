"""Refined boundaries of outcome maps: bisection between neighbouring cells, polygons, polylines.

The algorithm (regimemap.dynamics.boundaries, .regions) on categories known in closed form, then
the Makris-Roussos block (half-sine, mu high) against the event-driven reference on a coarse
25-point k grid, so that the refinement and not the grid does the work.
"""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.dynamics import Block, Pulse, simulate
from regimemap.dynamics.boundaries import (
    Crossings,
    crossing_points,
    plan_refinement,
    refinable,
    refine_crossings,
    saddle_cells,
)
from regimemap.dynamics.outcome import outcome_map
from regimemap.dynamics.regions import assemble

from . import _dyn_reference as ref


def _area(p: np.ndarray) -> float:
    return 0.5 * float(np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]))


class Counter:
    """An evaluate() that counts its batches and runs."""

    def __init__(self, f):
        self.f, self.batches, self.runs = f, 0, 0

    def __call__(self, x, y):
        self.batches += 1
        self.runs += np.size(x)
        return self.f(np.asarray(x), np.asarray(y))


def disc(x, y):
    return ((x - 1.0) ** 2 + (y - 1.0) ** 2 < 0.5).astype(np.int8)


def _grid(f, x, y):
    X, Y = np.meshgrid(x, y)
    return f(X, Y)


def _staircase_corners(p: np.ndarray, pitch: tuple[float, float]) -> int:
    """Pairs of consecutive segments, one horizontal and one vertical, each at least half a grid
    pitch long: the corners of a staircase."""
    d = np.diff(p, axis=0)
    horizontal = (np.abs(d[:, 1]) < 1e-12) & (np.abs(d[:, 0]) >= 0.5 * pitch[0])
    vertical = (np.abs(d[:, 0]) < 1e-12) & (np.abs(d[:, 1]) >= 0.5 * pitch[1])
    return int(np.count_nonzero((horizontal[:-1] & vertical[1:]) | (vertical[:-1] & horizontal[1:])))


def test_crossings_of_a_disc_within_the_tolerance_in_few_batches():
    x, y = np.linspace(0, 3, 25), np.linspace(0, 2.5, 21)
    cat = _grid(disc, x, y)
    ev = Counter(disc)
    plan = plan_refinement(x, y, cat)
    c = refine_crossings(x, y, cat, ev)
    assert ev.batches == plan.batches == c.batches <= 3 and ev.runs == plan.runs == c.runs
    pts = crossing_points(c, x, y)
    r = np.hypot(pts[:, 0] - 1.0, pts[:, 1] - 1.0)
    # a crossing is the middle of a bracket at most 1e-3 of the axis wide
    along = np.where(c.axis == 0, 3.0, 2.5) * 1e-3 / 2
    on_x = c.axis == 0
    exact = np.where(on_x, 1.0 + np.sign(pts[:, 0] - 1.0) * np.sqrt(np.maximum(0.5 - (pts[:, 1] - 1) ** 2, 0)),
                     1.0 + np.sign(pts[:, 1] - 1.0) * np.sqrt(np.maximum(0.5 - (pts[:, 0] - 1) ** 2, 0)))
    err = np.abs(np.where(on_x, pts[:, 0], pts[:, 1]) - exact)
    assert np.all(err <= along * (1 + 1e-9)), err.max()
    assert np.all(np.abs(r - np.sqrt(0.5)) < 0.01)
    # every boundary edge of the grid has its crossing
    assert len(c) == int(np.count_nonzero(cat[:, 1:] != cat[:, :-1]) + np.count_nonzero(cat[1:] != cat[:-1]))


def test_polygons_tile_the_map_and_the_disc_is_round():
    x, y = np.linspace(0, 3, 25), np.linspace(0, 2.5, 21)
    cat = _grid(disc, x, y)
    geo = assemble(cat, refine_crossings(x, y, cat, disc)).scaled(x, y)
    areas = {c: sum(_area(p) for p in loops) for c, loops in geo.regions.items()}
    assert sum(areas.values()) == pytest.approx(3.0 * 2.5, rel=1e-12)
    # chords inside the circle: 0.6 % less than its area
    assert areas[1] == pytest.approx(np.pi * 0.5, rel=1e-2)
    (a, b, line), = geo.boundaries
    assert (a, b) == (0, 1) and np.array_equal(line[0], line[-1])  # one closed curve
    assert _staircase_corners(line, (x[1] - x[0], y[1] - y[0])) == 0


def test_a_thin_band_between_two_nodes_gives_two_crossings_on_one_edge():
    def f(x, y):
        return np.where(x >= 1.0, 2, np.where(x >= 0.97, 1, 0)).astype(np.int8)

    x, y = np.linspace(0, 2, 6), np.linspace(0, 1, 3)  # pitch 0.4: the band (0.03 wide) falls between
    cat = _grid(f, x, y)
    assert set(np.unique(cat)) == {0, 2}
    c = refine_crossings(x, y, cat, f)
    assert len(c) == 2 * 3  # 0|1 and 1|2 on each row
    pts = crossing_points(c, x, y)
    np.testing.assert_allclose(np.sort(np.unique(np.round(pts[:, 0], 2))), [0.97, 1.0], atol=2e-3)
    geo = assemble(cat, c).scaled(x, y)
    assert 1 in geo.regions and sum(_area(p) for p in geo.regions[1]) == pytest.approx(0.03, rel=0.1)
    assert {(a, b) for a, b, _ in geo.boundaries} == {(0, 1), (1, 2)}


def test_a_saddle_is_resolved_at_the_cell_centre():
    def f(x, y):  # two quadrants of 1 that meet at a corner, joined by a bridge through the middle
        q = ((x > 0.5) == (y > 0.5)) | ((np.abs(x - 0.5) < 0.1) & (np.abs(y - 0.5) < 0.1))
        return q.astype(np.int8)

    x = y = np.array([0.0, 1.0])
    cat = _grid(f, x, y)
    assert saddle_cells(cat)[0].tolist() == [0]
    c = refine_crossings(x, y, cat, f)
    assert c.centre.tolist() == [1]
    geo = assemble(cat, c).scaled(x, y)
    assert len(geo.regions[1]) == 1 and len(geo.regions[0]) == 2  # 1 joined through the middle
    assert sum(_area(p) for loops in geo.regions.values() for p in loops) == pytest.approx(1.0)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_fields_close_every_loop_and_tile_the_map(seed):
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0, 1, size=(6, 2))
    codes = rng.integers(0, 4, size=6)

    def f(x, y):  # Voronoi cells of a few random points, a few of them sharing a category
        d = (x[..., None] - centres[:, 0]) ** 2 + (y[..., None] - centres[:, 1]) ** 2
        return codes[np.argmin(d, axis=-1)].astype(np.int8)

    x, y = np.linspace(0, 1, 13), np.linspace(0, 1, 11)[::-1]  # a decreasing axis too
    cat = _grid(f, x, y)
    c = refine_crossings(x, y, cat, f)
    g = assemble(cat, c)
    total = sum(_area(p) for loops in g.regions.values() for p in loops)
    assert total == pytest.approx(12 * 10, rel=1e-12)
    geo = g.scaled(x, y)
    X, Y = np.meshgrid(np.linspace(0.001, 0.999, 300), np.linspace(0.001, 0.999, 300))
    truth = f(X, Y)
    from matplotlib.path import Path

    got = np.full(truth.shape, -1)
    for code, loops in geo.regions.items():
        verts = np.concatenate([np.vstack([p, p[:1]]) for p in loops])
        kinds = np.concatenate([[Path.MOVETO] + [Path.LINETO] * (len(p) - 1) + [Path.CLOSEPOLY] for p in loops])
        inside = Path(verts, kinds).contains_points(np.column_stack([X.ravel(), Y.ravel()])).reshape(X.shape)
        got[inside] = code
    assert np.mean(got == truth) > 0.985  # a straight chord across each cell: the corners of cells differ


def test_nothing_to_refine_and_axes_that_cannot_be():
    x, y = np.linspace(0, 1, 4), np.linspace(0, 1, 3)
    c = refine_crossings(x, y, np.zeros((3, 4), dtype=np.int8), disc)
    assert len(c) == 0 and c.batches == 0
    assert not refinable([1.0], y) and not refinable([0.0, 1.0, 0.5], y)
    with pytest.raises(ValueError, match="strictly monotonic"):
        refine_crossings([0.0, 1.0, 0.5], y, np.zeros((3, 3)), disc)
    with pytest.raises(ValueError, match="shape"):
        refine_crossings(x, y, np.zeros((4, 3)), disc)
    arrays = c.arrays()
    assert Crossings.from_arrays(arrays).arrays().keys() == arrays.keys()


@pytest.mark.slow
def test_a_map_with_one_value_on_an_axis_is_not_refined():
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    m = outcome_map(blk, "half-sine", ("k_peak", [0.2, 0.5, 0.8]), ("duration", [0.5]))
    assert not m.refined and m.geometry() is None and m.boundaries() == []


# -- the Makris-Roussos block against the event-driven reference ------------------------------------------

MR = Block(B=0.2, gamma=3.0, mu=5.0)
DURATIONS = np.array([0.25, 0.5, 1.0, 2.0])
K = np.linspace(0.3, 1.5, 25)  # pitch 0.05: 9 % of the threshold at 0.5 s


@pytest.fixture(scope="module")
def mr_map():
    return outcome_map(MR, "half-sine", ("k_peak", K), ("duration", DURATIONS))


def _reference_threshold(T: float) -> float:
    p, alpha = float(MR.p), float(MR.alpha)

    def over(kp: float) -> bool:
        return ref.rocking(p, alpha, ref.half_sine(kp, T), T, eta=float(MR.housner_ratio),
                           t_end=T + 40 / p).overturned

    return ref.threshold(over, np.tan(alpha) * 1.0001, 1.5, tol=1e-5)


@pytest.mark.slow
@pytest.mark.deep
def test_refined_overturning_boundary_matches_the_reference(mr_map):
    m = mr_map
    assert m.refined and m.crossings is not None and m.crossings.batches <= 3
    (line,) = [p for a, b, p in m.boundaries() if {a, b} == {"rock only", "overturned"}]
    for T in DURATIONS:
        on_row = line[np.abs(line[:, 1] - T) < 1e-12]
        assert len(on_row) == 1, (T, on_row)
        k_st = float(on_row[0, 0])
        k_ref = _reference_threshold(float(T))
        assert k_st == pytest.approx(k_ref, rel=5e-3), (T, k_st, k_ref)
        assert (K[1] - K[0]) / k_ref > 0.05  # the grid's pitch alone: over 5 %
    # rest | rock only on tan(alpha) = 1/3, a vertical line
    (rest,) = [p for a, b, p in m.boundaries() if {a, b} == {"rest", "rock only"}]
    np.testing.assert_allclose(rest[:, 0], 1 / 3, rtol=2e-3)


@pytest.mark.slow
@pytest.mark.deep
def test_refined_boundaries_have_no_staircase(mr_map):
    pitch = (K[1] - K[0], float(np.min(np.diff(DURATIONS))))
    for a, b, p in mr_map.boundaries():
        assert _staircase_corners(p, pitch) == 0, (a, b, p)
    # the grid's staircase, for contrast: the cells of the map do have its corners
    cat = mr_map.category
    steps = np.count_nonzero(np.diff(np.argmax(cat == 4, axis=1)))
    assert steps > 0


@pytest.mark.slow
@pytest.mark.deep
def test_probes_of_the_refinement_are_runs_of_the_map(mr_map):
    """A probe at a node gives the node's category (the batch does not change a run)."""
    m = mr_map
    sim = simulate(MR, Pulse.half_sine(K, DURATIONS[1]), record_phases=False)
    assert np.array_equal(sim.categories(0.0), m.category[1])


def test_a_chaotic_map_does_not_swell_the_batches():
    def f(x, y):  # outcomes that flip from probe to probe
        return (np.floor(np.sin(x * 9173.1 + y * 7919.3) * 1e4) % 2).astype(np.int8)

    x, y = np.linspace(0, 1, 12), np.linspace(0, 1, 10)
    cat = _grid(f, x, y)
    ev = Counter(f)
    plan = plan_refinement(x, y, cat)
    c = refine_crossings(x, y, cat, ev)
    assert ev.runs < 40 * plan.runs and ev.batches <= 12
    g = assemble(cat, c)
    assert sum(_area(p) for loops in g.regions.values() for p in loops) == pytest.approx(11 * 9, rel=1e-12)
