"""Parts of the map with several admissible modes, against the solver."""

from __future__ import annotations

import math

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify
from regimemap.maps.ambiguity import (
    AmbiguousRegion,
    admissible_set,
    ambiguous_in_view,
    ambiguous_regions,
    column_pieces,
    set_label,
)
from regimemap.maps.run import run_map
from regimemap.mechanics.solver import admissible

from .._sweep import sweep, tiered

H = 1e-6


def _inside(poly: np.ndarray, k: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """Even-odd point-in-polygon test (pure numpy)."""
    x, y = poly[:, 0], poly[:, 1]
    x2, y2 = np.roll(x, -1), np.roll(y, -1)
    inside = np.zeros(k.shape, bool)
    for xa, ya, xb, yb in zip(x, y, x2, y2):
        cond = (ya > mu) != (yb > mu)
        with np.errstate(divide="ignore", invalid="ignore"):
            xc = xa + (mu - ya) * (xb - xa) / (yb - ya)
        inside ^= cond & (k < xc)
    return inside


def _solver_bits(k, mu, g, kp):
    """The solver's admissible set of every point, as bits (bit i: the i-th mode of Mode)."""
    adm = admissible(k, mu, g, kp)
    bits = np.zeros(k.size, np.int64)
    for i, m in enumerate(Mode):
        bits |= adm[m].astype(np.int64) << i
    return bits


def _stable_mask(k, mu, g, kp):
    """Points whose solver set is the same at four neighbours (off the boundaries), and the set
    of every point."""
    base = _solver_bits(k, mu, g, kp)
    ok = np.ones(k.size, bool)
    for dk, dm in ((H, 0), (-H, 0), (0, H), (0, -H)):
        ok &= _solver_bits(np.maximum(k + dk, 0), np.maximum(mu + dm, 0), g, kp) == base
    sets = {b: frozenset(m for i, m in enumerate(Mode) if b >> i & 1) for b in np.unique(base).tolist()}
    return [sets[b] for b in base.tolist()], ok


def _view(p: Parameters) -> tuple[float, float]:
    marks = [x for x in (p.k_A, p.k_Bprime, p.k_D, 1.0) if math.isfinite(x)]
    return min(3.0 * max(marks), 60.0), 2.5 * p.mu_Bprime


@pytest.mark.parametrize("gamma,kprime", tiered([pair for pair in sweep(9) if pair[1] < 0], every=8, deep=8))
def test_polygons_equal_solver_non_uniqueness(gamma, kprime):
    p = Parameters(gamma, kprime)
    k_max, mu_max = _view(p)
    regions = ambiguous_regions(p, k_max, mu_max)
    rng = np.random.default_rng(int(gamma * 1000 - kprime * 100) % 1009)
    n = 1500
    k = rng.uniform(0, k_max, n)
    mu = rng.uniform(0, mu_max, n)
    # and points inside each region, where they exist
    for r in regions:
        j = rng.integers(0, r.k.size, 200)
        t = rng.uniform(0.05, 0.95, 200)
        k = np.concatenate([k, r.k[j]])
        mu = np.concatenate([mu, r.lo[j] + t * (r.hi[j] - r.lo[j])])
    sets, stable = _stable_mask(k, mu, gamma, kprime)
    which = np.full(k.size, -1)
    for i, r in enumerate(regions):
        hit = _inside(r.polygon, k, mu)
        assert not (hit & (which >= 0)).any(), "regions overlap"
        which[hit] = i
    codes = classify(k, mu, gamma, kprime)
    # polygon sides are chords of the curved edges: allow a thin band near them
    near = np.zeros(k.size, bool)
    for r in regions:
        near |= _near_edge(r.polygon, k, mu, 1e-4 * max(k_max, mu_max))
    checked = 0
    for i in np.flatnonzero(stable & ~near):
        s = sets[i]
        if which[i] >= 0:
            r = regions[which[i]]
            assert s == frozenset(r.modes), (k[i], mu[i], s, r.label)
            assert Mode(int(codes[i])) is r.chosen
            checked += 1
        else:
            assert len(s) == 1, (k[i], mu[i], s)
    if regions:
        assert checked > 100


def _near_edge(poly, k, mu, tol):
    """Whether each point (k, mu) lies closer than ``tol`` to a side of the closed ``poly``.

    A point can be that close to a side only inside the side's box grown by ``tol``: the points
    sorted by k once, each side measures the few points of its box only.
    """
    a = poly
    b = np.roll(poly, -1, axis=0)
    d = b - a
    L2 = np.maximum((d ** 2).sum(1), 1e-300)
    order = np.argsort(k, kind="stable")
    ks = k[order]
    lo_box, hi_box = np.minimum(a, b) - 2.0 * tol, np.maximum(a, b) + 2.0 * tol
    out = np.zeros(k.size, bool)
    for ai, di, li, lo, hi in zip(a, d, L2, lo_box, hi_box):
        idx = order[np.searchsorted(ks, lo[0]):np.searchsorted(ks, hi[0], side="right")]
        idx = idx[(mu[idx] >= lo[1]) & (mu[idx] <= hi[1])]
        if idx.size == 0:
            continue
        pts = np.stack([k[idx], mu[idx]], 1)
        t = np.clip(((pts - ai) @ di) / li, 0, 1)
        proj = ai + t[:, None] * di
        out[idx] |= np.hypot(*(pts - proj).T) < tol
    return out


@pytest.mark.slow
@pytest.mark.deep
def test_admissible_set_equals_solver_off_boundaries():
    rng = np.random.default_rng(5)
    n_checked = 0
    for g, kp in [(3.0, -0.2), (3.0, -0.6), (1.0, -0.5), (0.5, -0.3), (3.0, 0.4), (3.0, 0.9)]:
        p = Parameters(g, kp)
        k_max, mu_max = _view(p)
        k = rng.uniform(0, k_max, 400)
        mu = rng.uniform(0, mu_max, 400)
        sets, stable = _stable_mask(k, mu, g, kp)
        for i in np.flatnonzero(stable):
            assert frozenset(admissible_set(p, k[i], mu[i])) == sets[i]
            n_checked += 1
    assert n_checked > 2000


def test_known_sets_and_choices():
    labels = {r.label for r in ambiguous_regions(Parameters(3.0, -0.2), 16.0, 3.0)}
    assert labels == {"{SL, RO, SRO-} -> SL (Section 4.7)",
                      "{RO, SRO-, SRO'-} -> SRO'- (Section 4.7)"}
    regs = ambiguous_regions(Parameters(3.0, -0.6), 4.0, 3.0)
    assert [(r.modes, r.chosen) for r in regs] == [
        ((Mode.SL, Mode.RO, Mode.SRO_MINUS), Mode.SL)]


def test_ambiguity_lies_above_mu_bprime():
    """Non-uniqueness needs mu > mu_B' = (4+g^2)/(3g), (4.49)."""
    for g, kp in [(3.0, -0.2), (3.0, -0.6), (1.0, -0.5), (0.5, -0.3)]:
        p = Parameters(g, kp)
        for r in ambiguous_regions(p, *_view(p)):
            assert r.polygon[:, 1].min() >= p.mu_Bprime - 1e-9
            assert r.area() > 0


@pytest.mark.parametrize("gamma,kprime", [(3.0, 0.0), (3.0, 0.4), (3.0, 0.9), (1.0, 1.0),
                                          (0.5, 0.2), (2.0, -1.0)])
def test_none_above_c_or_at_kprime_minus_one(gamma, kprime):
    p = Parameters(gamma, kprime)
    assert ambiguous_regions(p, 50.0, 20.0) == []


def test_none_when_view_below_mu_bprime():
    p = Parameters(3.0, -0.6)
    assert ambiguous_regions(p, 4.0, 0.9 * p.mu_Bprime) == []


def test_polygon_edges_on_the_boundary_curves():
    """Vertices lie exactly on the raw regions' edges: the set changes just across them."""
    p = Parameters(3.0, -0.2)
    for r in ambiguous_regions(p, 16.0, 3.0):
        inner = (r.hi - r.lo) > 1e-6
        for kk, lo, hi in zip(r.k[inner][::25], r.lo[inner][::25], r.hi[inner][::25]):
            eps = 1e-9 * max(1.0, hi)
            assert set(admissible_set(p, kk, lo + eps)) == set(r.modes)
            assert set(admissible_set(p, kk, hi - eps)) == set(r.modes)
            if hi < 3.0 - 1e-6:
                assert set(admissible_set(p, kk, hi + 1e-7)) != set(r.modes)
            assert set(admissible_set(p, kk, lo - 1e-7)) != set(r.modes)


def test_column_pieces_merge_and_order():
    p = Parameters(3.0, -0.2)
    pieces = column_pieces(p, np.array([12.0]), 3.0)[0]
    assert len(pieces) == 2
    (m1, lo1, hi1), (m2, lo2, hi2) = pieces
    assert lo1 < hi1 <= lo2 < hi2
    modes = lambda m: {Mode(i) for i in range(8) if m >> i & 1}  # noqa: E731
    assert modes(m1) == {Mode.RO, Mode.SRO_MINUS, Mode.SRO_PRIME_MINUS}
    assert modes(m2) == {Mode.SL, Mode.RO, Mode.SRO_MINUS}


def test_labels_and_anchor():
    r = ambiguous_regions(Parameters(3.0, -0.6), 4.0, 3.0)[0]
    assert isinstance(r, AmbiguousRegion)
    assert r.tex.startswith(r"$\{SL, RO, SRO_{-}\}$") and "§4.7" in r.tex
    a = r.anchor(4.0, 3.0)
    assert a is not None
    assert _inside(r.polygon, np.array([a[0]]), np.array([a[1]]))[0]
    assert r.anchor(0.1, 3.0) is None  # the part starts far right of k = 0.1
    d = r.as_dict()
    assert d["chosen"] == "SL" and d["modes"] == ["SL", "RO", "SRO-"]
    assert set_label((Mode.RO, Mode.SRO_MINUS), Mode.RO) == "{RO, SRO-} -> RO (Section 4.7)"


def test_bad_view_rejected():
    with pytest.raises(ValueError, match="k_max and mu_max"):
        ambiguous_regions(Parameters(3.0, -0.6), 0.0, 3.0)


# -- drawing (matplotlib) -------------------------------------------------------------------


def _map_axes(gamma, kprime, **kw):
    from regimemap.maps.figures.figure import map_figure

    fig, ax, art = map_figure(run_map(Parameters(gamma, kprime), samples=201, **kw))
    return fig, ax, art


@pytest.mark.render
def test_draw_ambiguity_outlines_and_annotates():
    from matplotlib.patches import Polygon as MplPolygon

    from regimemap.maps.figures.ambiguity import GID, LEGEND_LABEL, draw_ambiguity

    fig, ax, art = _map_axes(3.0, -0.6, k_max=4.0, mu_max=3.0)
    n_before = len(ax.patches)
    artists = draw_ambiguity(ax, ambiguous_in_view(Parameters(3.0, -0.6), 4.0, 3.0), 4.0, 3.0)
    assert artists
    polys = [a for a in artists if isinstance(a, MplPolygon)]
    assert len(polys) == 2  # stipple + outline of the one part
    assert all(not p.get_fill() for p in polys)  # the map stays visible underneath
    assert any(p.get_hatch() for p in polys)
    assert len(ax.patches) == n_before + 2
    texts = [a.get_text() for a in artists if hasattr(a, "get_text") and a.get_gid() == GID]
    assert texts == [r"$\{SL, RO, SRO_{-}\}$" + "\n" + r"$\rightarrow SL$ (§4.7)"]
    legend = ax.get_legend()
    labels = [t.get_text() for t in legend.get_texts()]
    assert labels[-1] == LEGEND_LABEL
    assert labels[:-1] == [t.get_text() for t in art.legend.get_texts()]
    fig.canvas.draw()  # renders without error


@pytest.mark.render
def test_draw_ambiguity_nothing_above_c_or_out_of_view():
    from regimemap.maps.figures.ambiguity import draw_ambiguity

    fig, ax, art = _map_axes(3.0, 0.4)
    n = len(ax.get_children())
    assert draw_ambiguity(ax, ambiguous_in_view(Parameters(3.0, 0.4), *art.extent), *art.extent) == []
    assert len(ax.get_children()) == n
    # below C but the view ends under mu_B'
    fig, ax, art = _map_axes(3.0, -0.6, k_max=4.0, mu_max=1.2)
    assert draw_ambiguity(ax, ambiguous_in_view(Parameters(3.0, -0.6), 4.0, 1.2), 4.0, 1.2) == []


@pytest.mark.render
def test_draw_ambiguity_without_legend():
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from regimemap.maps.figures.ambiguity import LEGEND_LABEL, draw_ambiguity

    fig = Figure()
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.set_xlim(0, 16)
    ax.set_ylim(0, 3)
    artists = draw_ambiguity(ax, ambiguous_in_view(Parameters(3.0, -0.2), 16.0, 3.0), 16.0, 3.0)
    assert len([a for a in artists if a.get_label() == LEGEND_LABEL]) == 1
    assert ax.get_legend() is None
    leg = ax.legend()
    assert [t.get_text() for t in leg.get_texts()] == [LEGEND_LABEL]
    # two parts: two labels, which do not overlap
    renderer = fig.canvas.get_renderer()
    for a in artists:
        if hasattr(a, "get_text"):
            a.draw(renderer)  # lays out the text box
    boxes = [a.get_bbox_patch().get_window_extent(renderer) for a in artists
             if hasattr(a, "get_text") and a.get_text()]
    assert len(boxes) == 2 and not boxes[0].overlaps(boxes[1])
