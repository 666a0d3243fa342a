"""On a loaded map the lines are curves (rational in k when the uplift grows with the push):
each segment of a curve is a boundary exactly when the regions on its two sides differ,
judged on the curve itself, not on the chord of the segment."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import Parameters, classify
from regimemap.maps.mapdata import compute_map
from regimemap.mechanics.curves import map_curves

GODA_1300 = Parameters(0.7, -0.0180155, buoyancy=0.452887, uplift_ratio=0.524144,
                       uplift_arm=0.333333, gyration=0.704746)  # Goda's example, W' = 1300 kN/m
LOADED = [
    GODA_1300,
    Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524),  # Goda's example, W' = 2312 kN/m
    Parameters(1.5, -0.018, buoyancy=0.318, uplift_ratio=0.524),
    Parameters(3.0, -0.6, buoyancy=0.318, uplift_ratio=0.524),
    Parameters(3.0, 0.4, buoyancy=0.3, uplift=0.2, uplift_ratio=0.4, uplift_arm=-0.8),
    Parameters(1.2, 0.5, uplift=0.1, uplift_ratio=0.4, uplift_arm=0.25),
    Parameters(3.0, 0.4, uplift_ratio=1.0),
]
IDS = ["goda-1300", "goda", "goda-g1.5", "g3-kp-0.6", "g3-kp0.4-arm-0.8", "g1.2-kp0.5", "slender"]


def _sides(p: Parameters, k: float, mu: float, d: float) -> tuple[int, int]:
    up = int(classify(k, mu + d, p.gamma, p.kprime, **p.loads))
    down = int(classify(k, mu - d, p.gamma, p.kprime, **p.loads))
    return up, down


@pytest.mark.parametrize("p", LOADED, ids=IDS)
def test_curved_segments_of_loaded_maps_are_judged_on_the_curve(p):
    """A segment of a (curved) graph is a boundary exactly when classify differs on its two
    sides at the curve's own point over the middle of the segment, 1e-4 of the view away."""
    d = compute_map(p, samples=401)
    funcs = {name: c.func for name, c in map_curves(p).items()}
    scale = np.array([d.k_max, d.mu_max])
    checked = 0
    for name, c in d.curves.items():
        f = funcs[name]
        if f is None:
            continue  # a vertical
        pts = c.points
        for i in range(len(pts) - 1):
            a, b = pts[i], pts[i + 1]
            if np.hypot(*((b - a) / scale)) < 0.02:
                continue  # too short to probe away from its ends (and from other curves)
            k = 0.5 * (a[0] + b[0])
            mu = float(f(np.array([k]))[0])
            eps = 1e-4 * d.mu_max
            if not (2 * eps < mu < d.mu_max):
                continue
            up, down = _sides(p, k, mu, eps)
            if (up, down) != _sides(p, k, mu, 0.1 * eps):
                continue  # another curve within 1e-4 of the view
            assert bool(c.boundary[i]) == (up != down), (name, i, k, mu, up, down)
            checked += 1
    assert checked >= 5


def test_goda_1300_slide_sro_minus_boundary_is_drawn_solid():
    """Goda's caisson with W' = 1300 kN/m (`regimemap caisson` of the example file with
    ``buoyant_weight = 1300``): AB (the upper line, curved) bounds SL from SRO- all the way
    from A down to B on the k axis; left of A (rest on both sides) it is a construction line."""
    d = compute_map(GODA_1300)
    runs = d.curves["AB"].runs()
    assert [is_b for _, is_b in runs] == [False, True]
    solid = runs[1][0]
    a, b = d.points["A"], d.line_ends["B"]
    assert np.allclose(solid[0], (a.k, a.mu), atol=1e-3 * d.mu_max)
    assert np.allclose(solid[-1], b) and b[1] == 0.0
