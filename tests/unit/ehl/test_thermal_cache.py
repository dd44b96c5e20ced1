"""Thermal EHL, the cache table and the registry."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.ehl import EHL_SOLVERS, FilmTable, SolidThermal, solve_thermal_line_contact
from thermobearing.ehl.thermal import _film_fields
from thermobearing.lubricant import load_lubricant
from thermobearing.materials import get_material

LUB = load_lubricant("OIL_4109")
STEEL = SolidThermal.of(get_material("PAPER001_STEEL"))


def test_effective_integrals_reduce_to_isothermal_reynolds():
    # uniform temperature across the film: (rho/eta)_e = rho/eta and the Couette flux density
    # rho_e u_a + eta_e rho_e' (u_b - u_a) = rho (u_a + u_b)/2 (Yang & Wen 1990 limit)
    n, nz = 5, 11
    T = np.full((n, nz), 320.0)
    p = np.linspace(0.0, 1e9, n)
    h = np.full(n, 1e-6)
    zeta = np.linspace(0, 1, nz)
    dpdx = np.linspace(-1e12, 1e12, n)
    eta, rho, u, tau, roe, couette = _film_fields(LUB, T, p, h, zeta, dpdx, 3.0, 1.0)
    assert np.allclose(roe, rho[:, 0] / eta[:, 0], rtol=1e-10)
    assert np.allclose(couette, rho[:, 0] * 2.0, rtol=1e-10)
    # velocity profile: surface speeds and Poiseuille parabola
    assert np.allclose(u[:, 0], 3.0) and np.allclose(u[:, -1], 1.0)
    z = h[:, None] * zeta
    exact = 3.0 + (1.0 - 3.0) * z / h[:, None] + dpdx[:, None] / (2 * eta) * (z**2 - z * h[:, None])
    assert np.allclose(u, exact, rtol=1e-9, atol=1e-9)


def test_slow_rolling_is_nearly_isothermal():
    # 1e5 N/m on R = 10 mm at 0.5 m/s: thermal loading eta0 beta u^2/k = 0.09 << 1, so the
    # thermal film must stay within 3 % of the isothermal one (Wilson-Sheu: phi_T = 0.97)
    sol = solve_thermal_line_contact(1e5, 0.01, 2.2e11, 0.5, 0.0, LUB, 303.15, solid1=STEEL,
                                     n=256)
    assert 0.95 < sol.thermal_reduction <= 1.001
    assert sol.max_temperature - 303.15 < 2.0


@pytest.mark.slow
def test_fast_rolling_heats_and_thins_the_film():
    # paper 001 conditions (53 m/s, oil 4109): strong inlet heating, film several times thinner
    sol = solve_thermal_line_contact(1.8e5, 5.535e-3, 2.3956e11, 53.3, 0.0, LUB, 303.15,
                                     solid1=STEEL, n=256)
    assert sol.thermal_reduction < 0.5
    assert sol.max_temperature > 303.15 + 30.0
    assert sol.minimum_film < sol.isothermal.minimum_film


@pytest.mark.slow
def test_table_reuses_solves_and_interpolates():
    table = FilmTable("numerical_ehl", 0.01, 2.2e11, lubricant=LUB, n=256)
    # grid: load and speed at powers of 1.25, SRR multiples of 0.02 (0 is a grid value, so
    # only 8 corners), temperature multiples of 5 K
    w_a, w_b = 1.25**51.3, 1.25**51.6  # about 9.4e4 and 1.0e5 N/m, same cell
    u_a, u_b = 1.25**7.2, 1.25**7.5
    a = table(w_a, u_a, 0.0, 313.15)
    first = table.solves
    assert first == 8
    b = table(w_a, u_a, 0.0, 313.15)
    assert table.solves == first and a == b  # memo hit
    c = table(w_b, u_b, 0.0, 313.15)  # same cell: no new corner solves
    assert table.solves == first
    direct = EHL_SOLVERS.get("numerical_ehl")(w_b, 0.01, 2.2e11, u_b, 0.0, 313.15,
                                              lubricant=LUB, n=256)
    assert c.central_film == pytest.approx(direct.central_film, rel=0.01)
    assert math.isfinite(c.traction)
