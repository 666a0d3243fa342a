"""The test cases of Sander-w/breakwater (test/test_goda.py), reproduced with this library.

Their cases are Goda (2000)'s examples (p. 78: nonlinear shoaling; p. 140: the upright breakwater),
with ``Hmax = 8.050 m`` and ``H1/3 = 5.796 m`` given directly, ``rho = 1030``, ``g = 9.81``, the
impulsive coefficient on and no rotation of the wave direction. Reference numbers only; no code of
theirs is used.
"""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.waves import (
    GodaPressures,
    caisson_loads,
    design_heights,
    goda_pressures,
    heel_pressure,
    section_from_densities,
    shoaling_coefficient,
)


@pytest.fixture(scope="module")
def pressures() -> GodaPressures:
    return goda_pressures(Hmax=8.050, period=11.4, depth=10.1, hb=10.1 + 5 * 5.796 * 0.01, armour_depth=5.6,
                          base_depth=7.1, crest=3.4, berm_width=8.0, angle_deg=15.0)


def test_shoaling_goda_page_78() -> None:
    assert float(shoaling_coefficient(4.5, 12.0, 8.0)) == pytest.approx(1.24, abs=0.005)


def test_heights_goda_page_140() -> None:
    dh = design_heights(6.3, 11.4, 10.1, 0.01)
    assert float(dh.H13) == pytest.approx(5.796, abs=5e-4)
    assert float(dh.Hmax) == pytest.approx(8.050, abs=5e-4)


def test_pressures_goda_page_140(pressures: GodaPressures) -> None:
    assert float(pressures.alpha_I) == pytest.approx(0.3223, abs=5e-5)
    assert float(pressures.p1) == pytest.approx(97644.84, abs=0.01)
    assert float(pressures.p3) == pytest.approx(87211.93, abs=0.01)
    assert float(pressures.p4) == pytest.approx(69674.10, abs=0.01)
    assert float(pressures.pu) == pytest.approx(65739.31, abs=0.01)


def test_centroid_and_required_mass(pressures: GodaPressures) -> None:
    ld = caisson_loads(pressures, 7.1, 15.0)
    # height of the resultant of P above the base
    assert float(ld.Mp / ld.P) == pytest.approx(5.155, abs=5e-4)
    # dry mass per metre giving SF_s = 1.16 and SF_o = 2.56 (the larger of the two)
    w_prime = max(float(ld.P) * 1.16 / 0.6 + float(ld.U), (float(ld.Mp) * 2.56 + float(ld.Mu)) / 7.5)
    mass = (w_prime + 1030 * 9.81 * 15.0 * 7.1) / 9.81
    assert mass / 1e3 == pytest.approx(345.4477, abs=5e-5)


def test_mass_and_bearing_pressure(pressures: GodaPressures) -> None:
    # their caisson: concrete fraction Pc of the whole section, one fill density above and below water
    sec = section_from_densities(15.0, 7.1, 3.4, concrete_fraction=0.8, concrete_density=2400.0,
                                 fill_density=1600.0)
    assert float(sec.mass) / 1e3 == pytest.approx(352.8, abs=1e-9)
    sec = section_from_densities(15.0, 7.1, 3.4, concrete_fraction=0.72142857, concrete_density=2400.0,
                                 fill_density=1600.0)
    ld = caisson_loads(pressures, 7.1, 15.0)
    pe, te = heel_pressure(sec.buoyant_weight, ld, sec.t, sec.width)
    assert float(pe) / 1e3 == pytest.approx(291.040, abs=5e-4)
    assert float(te) < 5.0 and np.isfinite(pe)
