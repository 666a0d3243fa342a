"""Exports round-trip: .npz and .csv equal classify, .json polylines satisfy their equations."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify
from regimemap.maps.designer_view import view_extent as auto_extent  # the default view of export and atlas
from regimemap.maps.record_export import (
    DEFAULT_RESOLUTION,
    boundary_curves,
    export_map,
    format_of,
    grid_axes,
    map_geometry,
    map_grid,
)
from regimemap.mechanics.curves import named_points
from regimemap.mechanics.validation import MAX_RESOLUTION

CASES = [(3.0, 0.4), (3.0, 0.9), (1.0, 0.0), (3.0, -0.2), (3.0, -0.6), (2.0, -1.0), (0.5, 1.0)]


@pytest.mark.parametrize("gamma,kprime", CASES)
def test_npz_round_trip(tmp_path, gamma, kprime):
    p = Parameters(gamma, kprime)
    path = tmp_path / "map.npz"
    assert export_map(path, p, resolution=(57, 43)) == "npz"
    with np.load(path, allow_pickle=False) as z:
        k, mu, mode, labels = z["k"], z["mu"], z["mode"], z["labels"]
        assert k.shape == (57,) and mu.shape == (43,) and mode.shape == (43, 57)
        assert mode.dtype == np.uint8
        K, M = np.meshgrid(k, mu)
        assert np.array_equal(mode, classify(K, M, gamma, kprime))
        assert [str(s) for s in labels] == [m.label for m in Mode]
        assert float(z["gamma"]) == gamma and float(z["kprime"]) == kprime
        assert str(z["case"]) == p.case.value
        assert (float(z["k_max"]), float(z["mu_max"])) == auto_extent(p)
        assert float(z["a"]) == p.a and float(z["k_A"]) == p.k_A
        assert k[-1] == float(z["k_max"]) and mu[-1] == float(z["mu_max"])
        # labels indexed by code name every cell
        assert set(labels[mode].ravel()) <= {m.label for m in Mode}


@pytest.mark.parametrize("gamma,kprime", CASES[:5])
def test_csv_rows_equal_classify(tmp_path, gamma, kprime):
    p = Parameters(gamma, kprime)
    path = tmp_path / "map.csv"
    export_map(path, p, k_max=2.0, mu_max=1.5, resolution=31)
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 31 * 31
    assert list(rows[0]) == ["k", "mu", "mode"]
    k = np.array([float(r["k"]) for r in rows])
    mu = np.array([float(r["mu"]) for r in rows])
    want = [Mode(int(c)).label for c in classify(k, mu, gamma, kprime)]
    assert [r["mode"] for r in rows] == want
    # mu outer, k inner
    assert k[0] == 0.0 and k[30] == 2.0 and mu[30] == 0.0 and mu[31] > 0.0
    assert mu[-1] == 1.5


def _on_spec(spec: dict, k: float, mu: float) -> float:
    """Residual of a point against the machine-readable equation of a curve."""
    if spec["type"] == "line":
        return mu - (spec["c0"] + spec["c1"] * k)
    if spec["type"] == "vertical":
        return k - spec["k"]
    num = spec["p"] * k + spec["q"]
    if spec["abs"]:
        num = abs(num)
    return mu - num / (spec["r"] * k + spec["t"])


@pytest.mark.parametrize("gamma,kprime", CASES)
@pytest.mark.slow
def test_json_polylines_satisfy_their_equations(tmp_path, gamma, kprime):
    p = Parameters(gamma, kprime)
    path = tmp_path / "map.json"
    export_map(path, p)
    text = path.read_text()
    assert "NaN" not in text and "Infinity" not in text
    d = json.loads(text)
    k_max, mu_max = d["extent"]["k_max"], d["extent"]["mu_max"]
    assert (k_max, mu_max) == auto_extent(p)
    assert d["parameters"] == {"gamma": gamma, "kprime": kprime}
    assert d["case"]["value"] == p.case.value
    n_pts = 0
    for name, c in d["curves"].items():
        for pl in c["polylines"]:
            pts = np.asarray(pl)
            assert pts.shape[1] == 2 and len(pts) >= 2
            assert (pts[:, 0] >= -1e-12).all() and (pts[:, 0] <= k_max * (1 + 1e-12)).all()
            assert (pts[:, 1] >= -1e-12).all() and (pts[:, 1] <= mu_max * (1 + 1e-12)).all()
            for kk, mm in pts:
                assert abs(_on_spec(c["spec"], kk, mm)) <= 1e-9 * max(1.0, mm), (name, kk, mm)
                n_pts += 1
    assert n_pts > 0
    # the same curves, checked against the library's own functions
    from regimemap.mechanics.curves import lower_line, mu_star, mu_star_star, upper_line

    funcs = {"OA": lambda k: k, "mu_star": lambda k: mu_star(p, k),
             "mu_star_star": lambda k: mu_star_star(p, k)}
    funcs["CD" if p.above else "AB"] = lambda k: upper_line(p, k)
    if not p.above:
        funcs["DC"] = lambda k: lower_line(p, k)
    for name, f in funcs.items():
        if name not in d["curves"]:
            continue
        for pl in d["curves"][name]["polylines"]:
            pts = np.asarray(pl)
            np.testing.assert_allclose(pts[:, 1], f(pts[:, 0]), rtol=1e-9, atol=1e-12)


def test_json_content_below_c(tmp_path):
    p = Parameters(3.0, -0.6)
    d = map_geometry(p, view="report")  # mu up to 2.5: the non-unique part (mu > 1.44) in view
    assert set(d["curves"]) == {"OA", "AE", "AB", "DC", "dotted", "mu_star", "mu_star_star"}
    assert d["curves"]["AE"]["spec"] == {"type": "vertical", "k": pytest.approx(p.k_A, rel=1e-11)}
    assert set(d["named_points"]) == set(named_points(p))
    for name, pt in named_points(p).items():
        assert d["named_points"][name]["k"] == pytest.approx(pt.k)
        assert d["named_points"][name]["mu"] == pytest.approx(pt.mu)
    assert set(d["regions"]) == {"RE", "SL", "RO", "SRO-", "SRO+", "SRO'-"}
    assert d["regions"]["SRO+"] == []
    assert [a["chosen"] for a in d["ambiguity"]] == ["SL"]
    # mu** ends before its pole and starts at F on the k axis
    mss = np.asarray(d["curves"]["mu_star_star"]["polylines"][0])
    assert mss[0, 0] == pytest.approx(p.k_F) and mss[0, 1] == pytest.approx(0.0, abs=1e-12)
    assert mss[:, 0].max() < p.k_pole


def test_json_regions_are_the_map(tmp_path):
    """A point inside an exported region polygon has that region's mode."""
    p = Parameters(3.0, 0.9)
    d = map_geometry(p)
    rng = np.random.default_rng(2)
    k_max = d["extent"]["k_max"]
    for label, polys in d["regions"].items():
        for poly in polys:
            poly = np.asarray(poly)
            ks = np.unique(poly[:, 0])
            for kk in rng.choice(ks[(ks > 0) & (ks < k_max)], size=min(20, ks.size - 2),
                                 replace=False):
                col = poly[np.isclose(poly[:, 0], kk)][:, 1]
                lo, hi = col.min(), col.max()
                if hi - lo < 1e-6:
                    continue
                mid = 0.5 * (lo + hi)
                assert Mode(int(classify(kk, mid, p.gamma, p.kprime))).label == label


def test_json_non_finite_as_null():
    d = map_geometry(Parameters(2.0, -1.0))  # k' = -1: k_A and the pole are infinite
    assert d["constants"]["k_A"] is None and d["constants"]["k_pole"] is None
    assert "A" not in d["named_points"]
    d = map_geometry(Parameters(3.0, 0.4))  # above C: no B'
    assert d["constants"]["k_Bprime"] is None


def test_above_c_json_curves():
    p = Parameters(3.0, 0.9)
    d = map_geometry(p)
    assert set(d["curves"]) == {"OA", "AB", "CD", "dotted", "mu_star"}
    assert d["ambiguity"] == []


def test_resolution_limits_refused_before_allocating(tmp_path, monkeypatch):
    import regimemap.maps.record_export as ex

    def boom(*a, **k):  # pragma: no cover - must not be reached
        raise AssertionError("allocated a grid")

    monkeypatch.setattr(ex, "label_grid", boom)
    p = Parameters(3.0, 0.4)
    for bad in (MAX_RESOLUTION + 1, 1, 0, (10, MAX_RESOLUTION + 1)):
        with pytest.raises(ValueError, match="resolution"):
            export_map(tmp_path / "x.npz", p, resolution=bad)
    assert not (tmp_path / "x.npz").exists()
    # the total number of points is checked too (with a smaller limit to reach it)
    monkeypatch.setattr(ex, "MAX_GRID_POINTS", 100)
    with pytest.raises(ValueError, match="exceeds the limit of 100 points"):
        export_map(tmp_path / "x.csv", p, resolution=11)
    with pytest.raises(ValueError, match="exceeds the limit"):
        grid_axes(1.0, 1.0, (20, 6))
    assert not (tmp_path / "x.csv").exists()


def test_format_of():
    assert format_of("a.NPZ") == "npz" and format_of("a.csv") == "csv"
    assert format_of("a.txt", "json") == "json"
    with pytest.raises(ValueError, match=r"unknown file suffix \.png in 'a\.png'; use \.npz, \.csv or \.json"):
        format_of("a.png")
    with pytest.raises(ValueError, match="no file suffix in 'map'"):
        format_of("map")
    with pytest.raises(ValueError, match="unknown export format 'xml'"):
        format_of("a.csv", "xml")


def test_atomic_write_leaves_no_partial_file(tmp_path, monkeypatch):
    import contextlib

    import regimemap.io.json as json_file

    path = tmp_path / "map.json"
    path.write_text("old")
    real = json_file.atomic_open

    @contextlib.contextmanager
    def fail_half_way(target, *a, **k):
        with real(target, *a, **k) as fh:
            fh.write('{"format": "regimemap-map", ')
            raise OSError("disk full")
        yield fh  # pragma: no cover

    monkeypatch.setattr(json_file, "atomic_open", fail_half_way)
    with pytest.raises(OSError):
        export_map(path, Parameters(3.0, 0.4))
    assert path.read_text() == "old"
    assert [f.name for f in tmp_path.iterdir()] == ["map.json"]


def test_npz_is_byte_stable(tmp_path):
    p = Parameters(3.0, -0.6)
    a, b = tmp_path / "a.npz", tmp_path / "b.npz"
    export_map(a, p, resolution=50)
    export_map(b, p, resolution=50)
    assert a.read_bytes() == b.read_bytes()


def test_map_grid_default():
    p = Parameters(3.0, 0.4)
    k, mu, mode = map_grid(p)
    assert k.size == mu.size == DEFAULT_RESOLUTION
    assert (k[-1], mu[-1]) == auto_extent(p)


def test_boundary_curves_clip_to_view():
    p = Parameters(3.0, -0.2)
    curves = boundary_curves(p, 1.0, 0.3)
    for c in curves.values():
        for pl in c["polylines"]:
            pts = np.asarray(pl)
            assert pts[:, 0].max() <= 1.0 + 1e-12 and pts[:, 1].max() <= 0.3 + 1e-12
    # the upper line AB (mu = 1/3 + 0.2 k > 0.3 everywhere) is out of view
    assert curves["AB"]["polylines"] == []
