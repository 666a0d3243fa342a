"""regimemap.maps.view: extent, curves (boundary vs construction), named points, label anchors."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from regimemap import Mode, Parameters, classify
from regimemap.drawing.text.placement import (
    box_hits,
    curve_label_anchor,
    interior_point,
    label_anchor,
    view_points,
)
from regimemap.maps.mapdata import compute_map
from regimemap.maps.view import auto_extent, nice_ceil, simplify
from regimemap.mechanics.curves import map_curves, named_points

# -- helpers ---------------------------------------------------------------------------------


def _run_near(curve, k, mu, scale):
    """The boundary flag of the segment of ``curve`` nearest to (k, mu)."""
    pts = curve.points / np.asarray(scale)
    q = np.array([k, mu]) / np.asarray(scale)
    a, b = pts[:-1], pts[1:]
    d = b - a
    L2 = np.maximum(np.einsum("ij,ij->i", d, d), 1e-300)
    t = np.clip(np.einsum("ij,ij->i", q - a, d) / L2, 0.0, 1.0)
    dist = np.hypot(*(a + t[:, None] * d - q).T)
    i = int(np.argmin(dist))
    assert dist[i] < 0.02, "no segment of the curve near the point"
    return bool(curve.boundary[i])


# -- nice_ceil / simplify --------------------------------------------------------------------


@pytest.mark.parametrize("x", [1e-6, 0.013, 0.53, 1.0, 2.13, 6.4, 99.0, 12345.0])
def test_nice_ceil_rounds_up_a_little(x):
    y = nice_ceil(x)
    assert y >= x
    assert y <= 1.5 * x + 1e-12


def test_nice_ceil_rejects_nonpositive():
    with pytest.raises(ValueError):
        nice_ceil(0.0)
    with pytest.raises(ValueError):
        nice_ceil(float("nan"))


def test_simplify_drops_collinear_points_and_keeps_ends():
    k = np.linspace(0, 1, 500)
    pts = np.column_stack([k, 2 * k])
    out = simplify(pts, 1e-6)
    assert len(out) == 2
    assert np.array_equal(out[0], pts[0]) and np.array_equal(out[-1], pts[-1])


@given(st.floats(0.05, 20.0), st.floats(1e-5, 1e-2))
@settings(max_examples=40, deadline=None)
@pytest.mark.slow
def test_simplify_stays_within_tolerance(curvature, tol):
    k = np.linspace(0, 1, 400)
    pts = np.column_stack([k, np.sin(curvature * k) / curvature])
    out = simplify(pts, tol)
    # every dropped vertex lies within tol of the simplified polyline
    y = np.interp(k, out[:, 0], out[:, 1])
    # vertical distance bounds the perpendicular one from above only for slopes ~ 1;
    # use the perpendicular distance to the chord instead
    for i in range(len(out) - 1):
        a, b = out[i], out[i + 1]
        sel = (k >= a[0]) & (k <= b[0])
        d = b - a
        dist = np.abs(d[0] * (pts[sel, 1] - a[1]) - d[1] * (pts[sel, 0] - a[0])) / np.hypot(*d)
        assert dist.max() <= tol + 1e-12
    assert np.all(np.isfinite(y))


# -- auto_extent -----------------------------------------------------------------------------

EXTREMES = [(g, kp) for g in (0.05, 0.3, 1.0, 1.5, 3.0, 10.0, 50.0)
            for kp in (-1.0, -0.999, -0.5, -0.001, 0.0, 0.001, 0.2, 0.5, 0.9, 1.0)]


@pytest.mark.parametrize("gamma,kprime", EXTREMES)
def test_auto_extent_is_finite_and_shows_A(gamma, kprime):
    p = Parameters(gamma, kprime)
    k_max, mu_max = auto_extent(p)
    assert math.isfinite(k_max) and math.isfinite(mu_max)
    assert k_max > 0 and mu_max > 0
    if math.isfinite(p.k_A):
        # A (and so the rest and rock regions around it) inside, with a margin
        assert p.k_A < k_max and p.mu_A < mu_max
        # A does not shrink into a corner: at least 5 % of the width
        assert p.k_A / k_max > 0.05


@pytest.mark.parametrize("gamma,kprime", EXTREMES)
def test_auto_extent_shows_the_characteristic_points(gamma, kprime):
    p = Parameters(gamma, kprime)
    k_max, mu_max = auto_extent(p)
    ref = p.k_A if math.isfinite(p.k_A) else p.k_D
    near = lambda k: k <= 12 * ref  # noqa: E731 - the documented cap
    if p.above and p.kprime > 0 and near(p.k_D):
        assert p.k_D < k_max  # D: SL region OAD closed
    if p.a < 0 and near(p.b_over_abs_a):
        assert p.b_over_abs_a < k_max  # G, and some SRO+ beyond it
    if not p.above and math.isfinite(p.k_A) and p.k_Bprime >= p.k_A and near(p.k_Bprime):
        assert p.k_Bprime < k_max and p.mu_Bprime < mu_max  # B', SRO- region
    if not p.above and math.isfinite(p.k_D) and near(p.k_D):
        assert p.k_D < k_max  # the SRO'- region below DC starts in view


def test_auto_extent_for_raw_regions():
    p = Parameters(3.0, -0.3)
    cp = named_points(p)["C'"]
    k_max, mu_max = auto_extent(p, Mode.RO)
    assert cp.k < k_max and cp.mu < mu_max  # sector CC'C'' of the Discussion
    k_re, _ = auto_extent(p, Mode.RE)
    assert p.k_A < k_re < auto_extent(p)[0]  # the rest strip is shown closer


def test_auto_extent_keeps_included_points_and_overrides():
    p = Parameters(3.0, 0.4)
    k_max, mu_max = auto_extent(p, include=[(5.0, 3.0)])
    assert k_max > 5.0 and mu_max > 3.0
    assert auto_extent(p, k_max=7.0)[0] == 7.0
    assert auto_extent(p, mu_max=0.9)[1] == 0.9


# -- curves and points -------------------------------------------------------------------------


def test_curves_above_c_case_1a():
    p = Parameters(3.0, 0.2)
    d = compute_map(p)
    s = (d.k_max, d.mu_max)
    assert {"OA", "AB", "CD", "mu_star"} <= set(d.curves)
    kA = p.k_A
    assert _run_near(d.curves["OA"], 0.5 * kA, 0.5 * kA, s)  # RE | SL
    assert _run_near(d.curves["AB"], kA, 1.3 * kA, s)  # RE | RO
    cd = lambda k: 1 / p.gamma - k * p.kprime  # noqa: E731
    assert not _run_near(d.curves["CD"], 0.5 * kA, cd(0.5 * kA), s)  # C to A: inside RE
    km = 0.5 * (kA + p.k_D)
    assert _run_near(d.curves["CD"], km, cd(km), s)  # A to D: SL | SRO-
    assert d.curves["mu_star"].boundary.all()  # RO | SRO- all along
    assert set(d.points) >= {"O", "A", "C", "D"}
    assert d.line_ends.get("B") is not None


def test_curves_below_c_delta_pos():
    p = Parameters(3.0, -0.3)
    d = compute_map(p)
    ms = d.curves["mu_star"]
    # mu* bounds SRO- (below) and RO (above) only between A and B'
    runs = [(pts[0, 0], pts[-1, 0], b) for pts, b in ms.runs()]
    bound = [(a, b) for a, b, flag in runs if flag]
    assert len(bound) == 1
    assert bound[0][0] == pytest.approx(p.k_A, rel=1e-6)
    assert bound[0][1] == pytest.approx(p.k_Bprime, rel=1e-3)
    # mu** and the dotted line (4.22) bound nothing on the final map
    assert not d.curves["mu_star_star"].is_boundary
    assert not d.curves["dotted"].is_boundary
    assert d.curves["DC"].is_boundary
    assert "B'" in d.points and "F" in d.points and "E" in d.points


def test_b_prime_hidden_when_delta_negative():
    d = compute_map(Parameters(3.0, -0.85))
    assert "B'" not in d.points  # k_B' < k_A: mu* from A never meets AB


@pytest.mark.parametrize("gamma,kprime", [(3.0, 0.2), (3.0, 0.85), (3.0, -0.3), (3.0, -0.85),
                                          (1.0, 0.5), (8.0, -0.2)])
def test_boundary_flags_agree_with_classify(gamma, kprime):
    """A segment is a boundary exactly when classify differs on its two sides."""
    p = Parameters(gamma, kprime)
    d = compute_map(p)
    funcs = {name: c.func for name, c in map_curves(p).items()}
    rng = np.random.default_rng(0)
    checked = 0
    for name, c in d.curves.items():
        if name in ("AB", "AE") and c.points[0, 0] == c.points[-1, 0]:
            continue  # verticals: checked left/right below
        pts = c.points
        for _ in range(20):
            i = rng.integers(0, len(pts) - 1)
            a, b = pts[i], pts[i + 1]
            if np.hypot(*((b - a) / (d.k_max, d.mu_max))) < 0.02:
                continue  # too short to probe away from its ends
            m = 0.5 * (a + b)
            if name in ("mu_star", "mu_star_star"):
                # curved: probed on the curve over the middle k (the chord's middle is off it)
                m = np.array([m[0], float(funcs[name](np.array([m[0]]))[0])])
                if not m[1] < d.mu_max:
                    continue
            eps = 1e-6 * d.mu_max
            if m[1] <= 2 * eps:
                continue
            up = classify(m[0], m[1] + eps, gamma, kprime)
            down = classify(m[0], m[1] - eps, gamma, kprime)
            assert bool(c.boundary[i]) == bool(up != down), (name, m)
            checked += 1
    assert checked >= 10


def test_raw_figures_draw_their_bounding_lines():
    p = Parameters(3.0, -0.3)
    d = compute_map(p, modes=[Mode.RO], raw=True)
    assert {"mu_star", "AE", "AB", "DC"} <= set(d.curves)  # Figs 4.4: mu* with AB and DC
    assert {"B'", "C'"} <= set(d.points)
    d = compute_map(p, modes=[Mode.SL], raw=True)
    assert "B'" not in d.points  # B' is mu* x AB; mu* is not drawn in Fig 4.3
    d = compute_map(p, modes=[Mode.SRO_PRIME_MINUS], raw=True)
    assert "OA" not in d.curves and "A" not in d.points
    assert "mu_star_star" in d.curves and "F" in d.points


def test_polygons_are_small():
    d = compute_map(Parameters(3.0, 0.4))
    for polys in d.polygons.values():
        for poly in polys:
            assert len(poly) < 400


# -- label anchors --------------------------------------------------------------------------


@pytest.mark.parametrize("gamma,kprime", [(3.0, 0.2), (3.0, 0.425), (3.0, 0.85), (3.0, -0.3),
                                          (3.0, -0.85)])
def test_label_anchor_is_inside_its_region(gamma, kprime):
    d = compute_map(Parameters(gamma, kprime))
    box = (0.08, 0.06)
    for mode, polys in d.polygons.items():
        for poly in polys:
            at = label_anchor(poly, d.k_max, d.mu_max, box)
            if at is None:
                continue
            k, mu = at
            assert 0 < k < d.k_max and 0 < mu < d.mu_max
            # the whole label box is in the region
            for dx in (-0.5, 0.0, 0.5):
                for dy in (-0.5, 0.0, 0.5):
                    kk = k + dx * box[0] * d.k_max
                    mm = mu + dy * box[1] * d.mu_max
                    assert classify(kk, mm, gamma, kprime) == mode


@given(st.floats(0.3, 20.0), st.floats(-0.99, 0.99))
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@pytest.mark.slow
def test_label_anchor_property(gamma, kprime):
    d = compute_map(Parameters(gamma, kprime), samples=201)
    for mode, polys in d.polygons.items():
        for poly in polys:
            at = label_anchor(poly, d.k_max, d.mu_max, (0.06, 0.05))
            if at is not None:
                assert classify(at[0], at[1], gamma, kprime) == mode
            ip = interior_point(poly, d.k_max, d.mu_max)
            if ip is not None:
                assert classify(ip[0], ip[1], gamma, kprime) == mode


def test_label_anchor_avoids_obstacles_and_gives_up_when_too_small():
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    at = label_anchor(square, 1.0, 1.0, (0.2, 0.1), obstacles=[(0.3, 0.3, 0.7, 0.7)])
    assert at is not None
    x, y = at
    assert not (0.2 < x < 0.8 and 0.25 < y < 0.75)
    sliver = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.01], [0.0, 0.01]])
    assert label_anchor(sliver, 1.0, 1.0, (0.2, 0.1)) is None
    assert interior_point(sliver, 1.0, 1.0) is not None


def test_curve_label_anchor_keeps_clear_of_lines():
    line = np.array([[0.0, 0.0], [1.0, 1.0]])
    other = np.array([[0.0, 0.1], [1.0, 1.1]])
    box = (0.15, 0.06)
    dense = [view_points(line, 1.0, 1.0), view_points(other, 1.0, 1.0)]
    at = curve_label_anchor(line, 1.0, 1.0, box, dense)
    assert at is not None
    b = (at[0] - box[0] / 2, at[1] - box[1] / 2, at[0] + box[0] / 2, at[1] + box[1] / 2)
    assert not box_hits(b, dense[0]) and not box_hits(b, dense[1])


@pytest.mark.subprocess
def test_view_does_not_import_matplotlib():
    code = ("import sys, regimemap.maps.view, regimemap.maps.figures.presets; "
            "print(any(m.startswith('matplotlib') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
