"""The designer's default view, the points off it, numbers for people, and Fig. 2.1."""

from __future__ import annotations

import json

import pytest

from regimemap import Parameters
from regimemap.maps.designer_view import DESIGN_MU, designer_extent, points_off_view, view_extent
from regimemap.maps.view import auto_extent


@pytest.mark.parametrize("gamma,kprime", [(1.0, -0.99), (5.0, -0.99), (3.0, 0.4), (3.0, -0.3),
                                          (0.3, 0.0), (10.0, 1.0), (1.0, -1.0)])
def test_designer_view_shows_real_friction(gamma, kprime):
    p = Parameters(gamma, kprime)
    k_max, mu_max = designer_extent(p)
    assert mu_max == DESIGN_MU and 0.0 < k_max <= 14.0
    # every characteristic point is either in view or reported off it
    off = {pt.name for pt in points_off_view(p, k_max, mu_max)}
    assert all(pt.name in off or (pt.k <= k_max and pt.mu <= mu_max)
               for pt in [q for q in points_off_view(p, 1e9, 1e9)])


def test_k_prime_near_minus_one_no_longer_shrinks_the_band():
    p = Parameters(1.0, -0.99)
    assert auto_extent(p)[0] >= 100.0          # the report's view: A at (100, 100)
    k_max, mu_max = view_extent(p)             # the designer's: the band mu <= 1.2
    assert k_max <= 4.0 and mu_max == 1.2
    assert {"A", "E"} <= {pt.name for pt in points_off_view(p, k_max, mu_max)}


def test_explicit_limits_win_and_design_points_grow_the_view():
    p = Parameters(3.0, 0.4)
    assert view_extent(p, "designer", k_max=7.0, mu_max=0.5) == (7.0, 0.5)
    assert view_extent(p, "report", k_max=7.0, mu_max=0.5) == (7.0, 0.5)
    k_max, mu_max = designer_extent(p, include=[(3.0, 2.0)])
    assert k_max >= 3.0 and mu_max >= 2.0
    with pytest.raises(ValueError, match="view must be one of designer, report"):
        view_extent(p, "poster")


def test_parameters_repr_has_no_float_noise():
    assert repr(Parameters(3.0, 0.4)) == "Parameters(gamma=3.0, kprime=0.4, a=2.2, b=9.0, c=12.6, d=37.0)"


def test_exports_round_for_people(tmp_path):
    from regimemap.maps.record_export import export_map

    p = Parameters(3.0, -0.6)
    export_map(tmp_path / "m.json", p)
    text = (tmp_path / "m.json").read_text()
    numbers = [float(x) for x in json.loads(text)["constants"].values() if isinstance(x, float)]
    assert all(repr(v) == repr(float(f"{v:.12g}")) for v in numbers)
    assert "9999999" not in text and "0000000000" not in text


@pytest.mark.render
def test_model_figure_draws_the_block():
    pytest.importorskip("matplotlib")
    from regimemap.maps.figures.model import model_figure

    fig = model_figure(dpi=40)
    texts = " ".join(t.get_text() for ax in fig.axes for t in ax.texts) + " ".join(
        t.get_text() for t in fig.texts)
    for symbol in ("$B$", "$H$", "$C$", "$O$", "$O'$", "$F = mgk$", "$h = k'H$", "$f_x$", "$f_y$",
                   r"$\xi$", r"$\theta$"):
        assert symbol in texts, symbol
    assert "half width" in texts and r"$\gamma = H/B$" in texts
