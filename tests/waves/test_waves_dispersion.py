"""Linear dispersion: machine-precision residual, limits, tables, broadcasting."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap.waves import deep_water_wavelength, wavelength, wavenumber


def test_residual_is_machine_precision() -> None:
    rng = np.random.default_rng(20261123)
    T = 10 ** rng.uniform(-1.0, 2.5, 50_000)
    h = 10 ** rng.uniform(-4.0, 5.0, 50_000)
    k = wavenumber(T, h)
    omega2 = (2 * np.pi / T) ** 2
    residual = np.abs(9.81 * k * np.tanh(k * h) - omega2) / omega2
    assert residual.max() <= 4e-15


def test_deep_water_limit() -> None:
    T = np.array([2.0, 8.0, 11.4])
    L0 = deep_water_wavelength(T)
    np.testing.assert_allclose(wavelength(T, 1e5), L0, rtol=1e-15)
    np.testing.assert_allclose(wavelength(T, np.inf), L0, rtol=1e-15)
    # h / L0 = 0.5: x = L/L0 solves x = tanh(pi / x); within 0.4 % of deep water
    x = float(wavelength(10.0, 0.5 * deep_water_wavelength(10.0)) / deep_water_wavelength(10.0))
    assert x == pytest.approx(np.tanh(np.pi / x), rel=1e-15)
    assert 0.996 < x < 0.997


def test_shallow_water_limit() -> None:
    # L -> T sqrt(g h); relative error (kh)^2 / 6 to leading order
    T, h = 20.0, np.array([1e-4, 1e-2])
    L = wavelength(T, h)
    L_shallow = T * np.sqrt(9.81 * h)
    kh = 2 * np.pi * h / L
    np.testing.assert_allclose(L / L_shallow - 1, -(kh**2) / 6, rtol=1e-3, atol=1e-15)


@pytest.mark.parametrize(("T", "h", "L_table"), [
    # Goda (2000) tables, g = 9.8, as used in the Deltares coastal-structures-toolbox tests
    (2.0, 0.2, 2.71), (2.0, 1.0, 5.21), (2.0, 2.0, 6.05), (2.0, 11.0, 6.24), (5.0, 6.0, 32.17),
])
def test_goda_tables(T: float, h: float, L_table: float) -> None:
    assert float(wavelength(T, h, g=9.8)) == pytest.approx(L_table, abs=1e-2)


def test_broadcasting_equals_loop() -> None:
    T = np.array([[4.0], [8.0], [11.4]])
    h = np.array([0.5, 5.0, 10.1, 50.0])
    L = wavelength(T, h)
    assert L.shape == (3, 4)
    loop = np.array([[float(wavelength(t, d)) for d in h] for t in T[:, 0]])
    np.testing.assert_allclose(L, loop, rtol=1e-15)


def test_scalar_gives_0d_array() -> None:
    L = wavelength(11.4, 10.1)
    assert isinstance(L, np.ndarray) and L.shape == ()
    assert float(L) == pytest.approx(107.54, abs=0.01)
