"""Goda's pressures split into a sea state and the heights: the same numbers, to the last bit.

:func:`regimemap.waves.goda_pressures` is :func:`goda_sea_state` (everything
that does not depend on the wave height) followed by :func:`goda_pressures_for`
(the rest).  Here both are compared with the formulas written out in one
piece, as ``goda_pressures`` computed them before the split (regimemap
2ad9f7f), over arrays of sea states and heights, and with scalar calls one
condition at a time.
"""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.waves import caisson_loads, goda_pressures, impulsive_coefficient, wavelength
from regimemap.waves.pressure import goda_pressures_for, goda_sea_state

FIELDS = ("L", "beta", "eta_star", "alpha1", "alpha2", "alpha3", "alpha_I", "alpha_I0", "alpha_I1",
          "alpha_star", "p1", "p2", "p3", "p4", "pu", "hc_star")


def _in_one_piece(H, t, h, hb, d, hp, hc, bm, ang, rot, impulsive, lambdas=(1.0, 1.0, 1.0)):
    """Goda-Takahashi pressures, every formula in one function (the code before the split)."""
    rho_w, g = 1030.0, 9.81
    H, t, h, hb, d, hp, hc, bm, ang, rot = np.broadcast_arrays(
        *(np.asarray(a, dtype=np.float64) for a in (H, t, h, hb, d, hp, hc, bm, ang, rot)))
    lam1, lam2, lam3 = lambdas
    beta = np.maximum(np.abs(ang) - rot, 0.0)
    cb = np.cos(np.radians(beta))
    w0 = rho_w * g
    L = wavelength(t, h, g)
    x4 = 4.0 * np.pi * h / L
    with np.errstate(over="ignore"):
        alpha1 = 0.6 + 0.5 * np.where(x4 < 700.0, x4 / np.sinh(np.minimum(x4, 700.0)), 0.0) ** 2
        cosh2 = np.cosh(np.minimum(2.0 * np.pi * h / L, 700.0))
    alpha2 = np.minimum((hb - d) / (3.0 * hb) * (H / d) ** 2, 2.0 * d / H)
    alpha3 = 1.0 - hp / h * (1.0 - 1.0 / cosh2)
    a_i0 = np.where(H <= 2.0 * d, H / d, 2.0)
    x = bm / L - 0.12
    z = (h - d) / h - 0.6
    d11 = 0.93 * x + 0.36 * z
    d22 = -0.36 * x + 0.93 * z
    d1 = np.where(d11 <= 0.0, 20.0 * d11, 15.0 * d11)
    d2 = np.where(d22 <= 0.0, 4.9 * d22, 3.0 * d22)
    with np.errstate(over="ignore"):
        a_i1 = np.where(d22 <= 0.0, np.cos(d2) / np.cosh(d1), 1.0 / (np.cosh(d1) * np.sqrt(np.cosh(d2))))
    a_i = a_i0 * a_i1
    alpha_star = np.maximum(alpha2, a_i) if impulsive else alpha2
    eta = 0.75 * (1.0 + cb) * lam1 * H
    p1 = 0.5 * (1.0 + cb) * (lam1 * alpha1 + lam2 * alpha_star * cb**2) * w0 * H
    p4 = np.where(eta > hc, p1 * (1.0 - hc / eta), 0.0)
    pu = 0.5 * (1.0 + cb) * lam3 * alpha1 * alpha3 * w0 * H
    return dict(L=L, beta=beta, eta_star=eta, alpha1=alpha1, alpha2=alpha2, alpha3=alpha3, alpha_I=a_i,
                alpha_I0=a_i0, alpha_I1=a_i1, alpha_star=alpha_star, p1=p1, p2=p1 / cosh2, p3=alpha3 * p1,
                p4=p4, pu=pu, hc_star=np.minimum(eta, hc))


def _conditions(n: int, seed: int = 2) -> dict[str, np.ndarray]:
    """Sea states from shallow to deep water, berms short and long, heights up to breaking."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(4.0, 40.0, n)
    d = h * rng.uniform(0.3, 0.95, n)
    return dict(t=rng.uniform(5.0, 18.0, n), h=h, hb=h * rng.uniform(1.0, 1.3, n), d=d,
                hp=np.minimum(d + rng.uniform(0.5, 3.0, n), h), hc=rng.uniform(0.5, 8.0, n),
                bm=rng.uniform(0.0, 40.0, n), ang=rng.uniform(-40.0, 40.0, n), rot=rng.uniform(0.0, 15.0, n),
                H=rng.uniform(0.3, 2.5, n) * d)


def _call(c: dict[str, np.ndarray], impulsive: bool, lambdas=(1.0, 1.0, 1.0)):
    return goda_pressures(Hmax=c["H"], period=c["t"], depth=c["h"], hb=c["hb"], armour_depth=c["d"],
                          base_depth=c["hp"], crest=c["hc"], berm_width=c["bm"], angle_deg=c["ang"],
                          rotation_deg=c["rot"], impulsive=impulsive, lambdas=lambdas)


@pytest.mark.parametrize("impulsive", [True, False])
@pytest.mark.parametrize("lambdas", [(1.0, 1.0, 1.0), (0.8, 0.4, 0.7)])
def test_goda_pressures_are_the_formulas_in_one_piece_to_the_last_bit(impulsive, lambdas):
    c = _conditions(3000)
    p = _call(c, impulsive, lambdas)
    ref = _in_one_piece(c["H"], c["t"], c["h"], c["hb"], c["d"], c["hp"], c["hc"], c["bm"], c["ang"],
                        c["rot"], impulsive, lambdas)
    assert np.any(ref["alpha_I"] > ref["alpha2"]) and np.any(ref["p4"] > 0) and np.any(ref["p4"] == 0)
    for name in FIELDS:
        assert np.array_equal(getattr(p, name), ref[name]), name


def test_array_calls_equal_scalar_calls():
    c = _conditions(200, seed=4)
    p = _call(c, True)
    for i in range(200):
        one = _call({k: float(v[i]) for k, v in c.items()}, True)
        for name in FIELDS:
            assert getattr(one, name).shape == ()
            assert float(getattr(one, name)) == float(getattr(p, name)[i]), (name, i)


@pytest.mark.parametrize("impulsive", [True, False])
def test_one_sea_state_many_heights(impulsive):
    c = _conditions(300, seed=6)
    sea = goda_sea_state(period=c["t"][:, None], depth=c["h"][:, None], hb=c["hb"][:, None],
                         armour_depth=c["d"][:, None], base_depth=c["hp"][:, None], crest=c["hc"][:, None],
                         berm_width=c["bm"][:, None], angle_deg=c["ang"][:, None],
                         rotation_deg=c["rot"][:, None])
    H = c["d"][:, None] * np.linspace(0.2, 2.4, 9)[None, :]
    p = goda_pressures_for(sea, H, impulsive=impulsive)
    ref = _in_one_piece(H, *(c[k][:, None] for k in ("t", "h", "hb", "d", "hp", "hc", "bm", "ang", "rot")),
                        impulsive)
    for name in FIELDS:
        assert getattr(p, name).shape == (300, 9), name
        assert np.array_equal(getattr(p, name), ref[name]), name
    # the loads of the caisson too
    loads = caisson_loads(p, c["hp"][:, None], 1.0)
    ref_P = 0.5 * (ref["p1"] + ref["p3"]) * c["hp"][:, None] + 0.5 * (ref["p1"] + ref["p4"]) * ref["hc_star"]
    assert np.array_equal(loads.P, ref_P) and np.array_equal(loads.U, 0.5 * ref["pu"])


def test_a_given_wavelength_is_used_and_the_results_stay_writable():
    c = _conditions(50, seed=8)
    L = wavelength(c["t"], c["h"])
    a = goda_pressures(Hmax=c["H"], period=c["t"], depth=c["h"], hb=c["hb"], armour_depth=c["d"],
                       base_depth=c["hp"], crest=c["hc"], L=L)
    b = goda_pressures(Hmax=c["H"], period=c["t"], depth=c["h"], hb=c["hb"], armour_depth=c["d"],
                       base_depth=c["hp"], crest=c["hc"])
    assert all(np.array_equal(getattr(a, n), getattr(b, n)) for n in FIELDS)
    assert b.p1.flags.writeable and b.alpha1.flags.writeable


def test_impulsive_coefficient_unchanged():
    c = _conditions(500, seed=10)
    a_i, a_i0, a_i1 = impulsive_coefficient(c["H"], c["h"], c["d"], c["bm"], wavelength(c["t"], c["h"]))
    ref = _in_one_piece(c["H"], c["t"], c["h"], c["hb"], c["d"], c["hp"], c["hc"], c["bm"], c["ang"], c["rot"],
                        True)
    assert np.array_equal(a_i, ref["alpha_I"]) and np.array_equal(a_i0, ref["alpha_I0"])
    assert np.array_equal(a_i1, ref["alpha_I1"])
