"""Tests of the Maxwell (viscoelastic) Hertz-zone film of the roller skidding solver.

Reference values are hand-derived from the Maxwell element (Johnson & Tevaarwerk 1977) in
steady flow through the contact, u_e d tau/ds = G (V/h - tau/eta): for a constant
viscosity tau(s) = tau_ss (1 - exp(-s/lambda)), lambda = eta u_e / G; its elastic limit
(eta -> inf) tau = G V s / (h u_e), whose Hertz-zone force is 2 G l b^2 V / (h u_e).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, default_traction_law, solve_roller
from thermobearing.skidding.roller_fluid import closed_form_contact_forces
from thermobearing.skidding.roller_maxwell import (
    maxwell_contact_forces,
    maxwell_hertz_traction,
)

T = 303.15
B = 1.5e-4  # Hertz half-width [m]
L = 0.0108  # contact length [m]
H = 5e-7  # film [m]
UE = 30.0  # entrainment speed [m/s]


@dataclass(frozen=True)
class ConstantViscosity:
    """Newtonian film of constant viscosity (pressure independent): tau = eta V / h."""

    eta: float
    requires_film = True

    def shear_stress(self, slide_speed, pressure, film_thickness=None, temperature=None):
        s = np.asarray(slide_speed, dtype=float)
        h = np.asarray(film_thickness, dtype=float)
        return self.eta * s / h, self.eta / h * np.ones_like(s)


def _force(v, law, g):
    return maxwell_hertz_traction(np.atleast_1d(v), np.atleast_1d(UE), np.atleast_1d(1e9),
                                  np.atleast_1d(B), np.atleast_1d(H), L, law, T, g)


def test_linear_maxwell_matches_the_exact_solution():
    # constant eta: the piecewise-exponential integration is exact. Mean stress over 2b:
    # tau_ss (1 - (lambda/2b)(1 - exp(-2b/lambda))), lambda = eta u_e / G
    eta, g, v = 50.0, 1e9, 0.02
    lam = eta * UE / g  # 1.5e-6 * ... = 1.5 um (De = lam/b = 0.01)
    for eta_k in (eta, 5e3, 5e5):
        lam = eta_k * UE / g
        tau_ss = eta_k * v / H
        expected = L * 2 * B * tau_ss * (1 - lam / (2 * B) * (1 - math.exp(-2 * B / lam)))
        f, _ = _force(v, ConstantViscosity(eta_k), g)
        assert f[0] == pytest.approx(expected, rel=1e-12)


def test_elastic_and_viscous_limits():
    v, g = 0.01, 1e9
    # eta -> inf: elastic solid, 2 G l b^2 V / (h u_e)
    f_el, df_el = _force(v, ConstantViscosity(1e15), g)
    assert f_el[0] == pytest.approx(2 * g * L * B**2 * v / (H * UE), rel=1e-6)
    assert df_el[0] == pytest.approx(f_el[0] / v, rel=1e-6)
    # G -> inf: the point-wise viscous film, eta V / h over 2 b l
    f_v, _ = _force(v, ConstantViscosity(10.0), 1e25)
    assert f_v[0] == pytest.approx(10.0 * v / H * 2 * B * L, rel=1e-9)
    # the sign follows V, zero load gives zero
    f_neg, _ = _force(-v, ConstantViscosity(10.0), g)
    assert f_neg[0] < 0
    f0, d0 = maxwell_hertz_traction([v], [UE], [0.0], [0.0], [np.inf], L,
                                    ConstantViscosity(10.0), T, g)
    assert f0[0] == 0.0 and d0[0] == 0.0


@pytest.mark.parametrize("v", [0.0, 1e-4, 0.01, 0.3])
def test_slope_matches_finite_difference_with_the_capped_law(v):
    # the solver's law: Newtonian at the Roelands viscosity of the Hertz pressure, capped by
    # Lambda p (both regimes cross inside the contact at these speeds)
    law = default_traction_law(load_lubricant("OIL_4109"))
    args = ([UE], [1.3e9], [B], [H], L, law, T, 1e9)
    f, df = maxwell_hertz_traction([v], *args)
    eps = 1e-7 * max(v, 1e-3)
    fp, _ = maxwell_hertz_traction([v + eps], *args)
    if v == 0.0:
        fd = fp[0] / eps
    else:
        fm, _ = maxwell_hertz_traction([v - eps], *args)
        fd = (fp[0] - fm[0]) / (2 * eps)
    assert df[0] == pytest.approx(fd, rel=2e-4, abs=1e-9 * max(abs(fd), 1.0))
    # bounded by the limiting shear force Lambda * (pi/4) p_H 2 b l
    assert abs(f[0]) <= 0.075 * math.pi / 4 * 1.3e9 * 2 * B * L * (1 + 1e-12)


def test_heavy_contact_traction_grows_slower_with_load_than_the_viscous_film():
    # The point of the model: at EHL pressures the viscous (Roelands) film makes the Hertz-
    # zone traction at a fixed sliding speed grow much faster than the load; the Maxwell film
    # is elastic where eta u_e / G exceeds the Hertz width (p > ~0.8 GPa here, OIL_4109 at
    # 30 degC) and approaches the elastic law (16/pi) G R Q V / (E' h u_e), ~ Q^1.1.
    # Measured (V = 0.01 m/s, u_e = 30 m/s, G = 1 GPa; 1/2/4/8 kN, p_H 0.80-2.26 GPa):
    # viscous 1.68 / 40.4 / 253 / 569 N (capped by Lambda p at 8 kN), Maxwell 1.57 / 14.7 /
    # 49.3 / 117 N.
    bearing = load_bearing("D1842926")
    oil = load_lubricant("OIL_4109")
    loads = np.array([2000.0, 4000.0, 8000.0])
    v = np.full(3, 0.01)
    ratios = {}
    for g in (None, 1e9):
        m = build_model(bearing, oil, T, fluid_shear_modulus=g)
        f = m.contact_forces(loads, m.length, m.radius_inner, m.effective_modulus,
                             UE + 0.5 * v, UE - 0.5 * v, eta0=m.eta0, alpha=m.alpha,
                             film=m.film_inner, traction_law=m.traction_law, temperature=T)
        ratios[g] = f.hertz_traction[1:] / f.hertz_traction[:-1]
    assert ratios[1e9][0] < 0.6 * ratios[None][0]
    # 4 -> 8 kN: elastic regime, 2 x (h ratio)^-1 ~ 2.1, within the Lambda p cap
    assert 1.9 < ratios[1e9][1] < 2.6


def test_maxwell_wrapper_keeps_the_other_forces():
    bearing = load_bearing("D1842926")
    oil = load_lubricant("OIL_4109")
    m = build_model(bearing, oil, T)
    law = m.traction_law
    q = np.array([0.0, 500.0, 3000.0])
    ur, uro = np.full(3, 30.0), np.array([29.9, 29.95, 29.99])
    kw = dict(eta0=m.eta0, alpha=m.alpha, film=m.film_inner, temperature=T)
    base = closed_form_contact_forces(q, m.length, m.radius_inner, m.effective_modulus, ur,
                                      uro, traction_law=law, **kw)
    mx = maxwell_contact_forces(closed_form_contact_forces, 1e9)(
        q, m.length, m.radius_inner, m.effective_modulus, ur, uro, traction_law=law, **kw)
    np.testing.assert_allclose(mx.rolling_force, base.rolling_force, rtol=1e-14)
    np.testing.assert_allclose(mx.poiseuille, base.poiseuille, rtol=1e-14)
    np.testing.assert_allclose(mx.film_thickness, base.film_thickness, rtol=1e-14)
    side_base = base.traction - base.hertz_traction
    np.testing.assert_allclose(mx.traction - mx.hertz_traction, side_base, rtol=1e-12,
                               atol=1e-15)
    assert mx.traction[0] == 0.0
    # the elastic film transmits less than the viscous one at the heavy contact
    assert 0 < mx.hertz_traction[2] < base.hertz_traction[2]


def test_bad_shear_modulus_is_an_error():
    with pytest.raises(InputError):
        build_model(load_bearing("D1842926"), load_lubricant("OIL_4109"), T,
                    fluid_shear_modulus=-1.0)


def test_paper001_load_and_speed_trends_and_energy_balance():
    # Paper 001 (seed 001_5ba4564faedebfb7.txt) Figs. 7 and 9: the cage sliding ratio falls
    # with the radial load (13218 r/min) and rises with the speed (18 kN)
    bearing = load_bearing("D1842926")
    oil = load_lubricant("OIL_4109")
    w = 13218 * math.pi / 30
    opts = dict(fluid_shear_modulus=1e9)
    s8 = solve_roller(bearing, oil, w, 8e3, 0.0, T, **opts)
    s24 = solve_roller(bearing, oil, w, 24e3, 0.0, T, **opts)
    s_slow = solve_roller(bearing, oil, 8000 * math.pi / 30, 18e3, 0.0, T, **opts)
    s_fast = solve_roller(bearing, oil, 16000 * math.pi / 30, 18e3, 0.0, T, **opts)
    assert s8.slip > s24.slip > 0
    assert s_fast.slip > s_slow.slip > 0
    for r in (s8, s24):
        assert r.shaft_torque * w == pytest.approx(r.power_loss["total"], rel=1e-7)


def test_light_load_paper000_is_viscous_regime():
    # paper 000 (NU214, 150 N, 5000 r/min): Deborah number eta u_e/(G b) << 1 at 0.1-0.25
    # GPa, so the Maxwell film changes the cage speed by well under 1 %
    nu214 = load_bearing("NU214")
    oil = load_lubricant("PAPER000_OIL")
    w = 5000 * math.pi / 30
    a = solve_roller(nu214, oil, w, 150.0, 0.0, 313.15, viscosity=0.08)
    b = solve_roller(nu214, oil, w, 150.0, 0.0, 313.15, viscosity=0.08,
                     fluid_shear_modulus=1e9)
    assert b.cage_speed == pytest.approx(a.cage_speed, rel=1e-2)


# --- Hertz-zone pressure by regime (skidding/roller_pressure.py) ---------------------------
def test_martin_pi_matches_the_closed_form_of_roller_fluid():
    from thermobearing.skidding.roller_fluid import _pi_function, martin_coefficients
    from thermobearing.skidding.roller_pressure import martin_pi

    xs = martin_coefficients()[3]
    hs = 1.0 + xs * xs
    x = np.array([-30.0, -2.0, -xs, -0.1, 0.0, 0.3, xs - 1e-9, xs + 0.1, 5.0])
    ref = [max(_pi_function(v, -math.inf, hs), 0.0) if v < xs else 0.0 for v in x]
    np.testing.assert_allclose(martin_pi(x), ref, rtol=1e-12, atol=1e-15)
    # peak upstream at X = -X* (dp/dX = 0 where H = H*)
    grid = np.linspace(-2, 1, 30001)
    assert grid[np.argmax(martin_pi(grid))] == pytest.approx(-xs, abs=2e-4)


def test_rigid_pressure_carries_the_load():
    from scipy.integrate import quad

    from thermobearing.skidding.roller_pressure import rigid_pressure

    w, u, r, eta = 4300.0, 30.0, 5.6e-3, 0.08  # paper 000 NU214, ~56 N on 13 mm
    total = (quad(lambda x: float(rigid_pressure(x, w, u, r, eta)), -np.inf, -1e-3)[0]
             + quad(lambda x: float(rigid_pressure(x, w, u, r, eta)), -1e-3, 1e-3,
                    limit=200)[0])
    assert total == pytest.approx(w, rel=1e-6)


def test_regime_min_pressure_limits():
    from thermobearing.skidding.roller_pressure import (
        hertz_zone_pressure,
        rigid_peak_pressure,
        rigid_pressure,
    )

    xb = np.linspace(-0.95, 0.95, 9)
    # the peak of the rigid profile
    grid = np.linspace(-3e-3, 1e-3, 40001)
    assert rigid_peak_pressure(4300.0, 30.0, 5.6e-3, 0.08) == pytest.approx(
        rigid_pressure(grid, 4300.0, 30.0, 5.6e-3, 0.08).max(), rel=1e-6)
    # EHL contact (D1842926 inner race, 4 kN, U = 60 m/s, eta0 0.033): M >> 1, Hertz
    b, p_h, w, r = 1.47e-4, 1.6e9, 4000 / 0.0108, 5.5e-3
    p = hertz_zone_pressure("regime_min", xb, [p_h], [b], [w], [60.0], r, 0.033)
    np.testing.assert_allclose(p[0], p_h * np.sqrt(1 - xb**2), rtol=1e-12)
    # rigid contact (paper 000 NU214, 56 N on 13 mm, U = 30 m/s, 0.08 Pa s; M ~ 0.1): the
    # peak is the rigid one, ~10 MPa, an order below p_H = 0.17 GPa
    w = 56.0 / 0.013
    b = math.sqrt(8 * w * 5.6e-3 / (math.pi * 2.28e11))
    p_h = 2 * w / (math.pi * b)
    p = hertz_zone_pressure("regime_min", xb, [p_h], [b], [w], [30.0], 5.6e-3, 0.08)
    peak = rigid_peak_pressure(w, 30.0, 5.6e-3, 0.08)
    assert peak < 0.15 * p_h
    np.testing.assert_allclose(p[0], peak * np.sqrt(1 - xb**2), rtol=1e-12)
    with pytest.raises(InputError):
        hertz_zone_pressure("elastic", xb, [p_h], [b], [w], [30.0], 5.6e-3, 0.08)


def test_regime_min_removes_the_hertz_zone_shear_of_rigid_contacts_and_keeps_energy():
    nu214 = load_bearing("NU214")
    oil = load_lubricant("PAPER000_OIL")
    w = 5000 * math.pi / 30
    a = solve_roller(nu214, oil, w, 150.0, 0.0, 313.15, viscosity=0.08, tol=1e-12)
    b = solve_roller(nu214, oil, w, 150.0, 0.0, 313.15, viscosity=0.08, tol=1e-12,
                     film_pressure="regime_min")
    # the roller under the load (M ~ 0.1): 8.2 N of Hertz-zone shear at eta(p_H) become
    # 0.64 N at the rigid peak pressure; no contact gains any
    assert abs(b.inner.hertz_traction[0]) < 0.1 * abs(a.inner.hertz_traction[0])
    loaded = a.inner_load > 0
    assert np.all(np.abs(b.inner.hertz_traction[loaded])
                  < np.abs(a.inner.hertz_traction[loaded]))
    assert b.shaft_torque * w == pytest.approx(b.power_loss["total"], rel=1e-8)
    with pytest.raises(InputError):
        build_model(nu214, oil, 313.15, film_pressure="elastic")


def test_regime_min_hertz_zone_shear_matches_the_numerical_ehl_of_paper000():
    # Paper 000 eq. 33 shears the oil at the pressure of its eqs. 7-11. For the NU214 roller
    # under the load (61 N on 13 mm, u_e = 8.1 m/s, 0.08 Pa s, Roelands z = 0.602; Moes
    # M = 0.115, L = 28: rigid regime) the numerical line-contact EHL (thermobearing.ehl)
    # gives p_max = 14.2 MPa against p_H = 174 MPa, and the Hertz-zone integral int eta/h dx
    # = 0.647 Pa s (measured 2026-11-22). regime_min reproduces both within ~11 %, the Hertz
    # pressure overestimates the integral 15-fold.
    from thermobearing.ehl.line import solve_line_contact
    from thermobearing.skidding.roller_pressure import rigid_peak_pressure
    from thermobearing.validation.runners_roller_skidding import paper000_eq9_lubricant

    nu214 = load_bearing("NU214")
    t = 313.15
    lub = paper000_eq9_lubricant(load_lubricant("PAPER000_OIL"), 0.08, t)
    q, ue, v = 61.0, 8.1, 1e-3
    m_h = build_model(nu214, lub, t, viscosity=0.08, limiting_shear_coefficient=1.0)
    r = m_h.radius_inner
    s = solve_line_contact(q / m_h.length, r, m_h.effective_modulus, ue, 0.08,
                           roelands_z=0.602, n=1024)
    inz = np.abs(s.x) < s.hertz_half_width
    numeric = np.trapezoid((s.viscosity / s.film)[inz], s.x[inz])
    assert float(rigid_peak_pressure(q / m_h.length, 2 * ue, r, 0.08)) == pytest.approx(
        s.max_pressure, rel=0.03)
    out = {}
    for fp in ("hertz", "regime_min"):
        m = build_model(nu214, lub, t, viscosity=0.08, limiting_shear_coefficient=1.0,
                        film_pressure=fp)
        f = m.contact_forces(np.array([q]), m.length, r, m.effective_modulus,
                             np.array([ue + v / 2]), np.array([ue - v / 2]), eta0=m.eta0,
                             alpha=m.alpha, film=m.film_inner, traction_law=m.traction_law,
                             temperature=t)
        out[fp] = f.hertz_traction[0] / v / m.length
    assert out["regime_min"] == pytest.approx(numeric, rel=0.15)
    assert out["hertz"] > 10 * numeric


def test_hertz_zone_options_refused_with_a_numerical_drag():
    """film_pressure / fluid_shear_modulus replace the drag model's Hertz-zone shear by a
    closed-form integral: with the numerical-EHL drag (its own pressure) they are refused."""
    import thermobearing.ehl.drag  # noqa: F401  registers numerical_ehl

    bearing, oil = load_bearing("NU214"), load_lubricant("PAPER000_OIL")
    for opts in ({"film_pressure": "regime_min"}, {"fluid_shear_modulus": 1e9}):
        with pytest.raises(InputError, match="closed-form drag only"):
            build_model(bearing, oil, 313.15, drag_model="numerical_ehl", **opts)
    build_model(bearing, oil, 313.15, drag_model="numerical_ehl")  # plain: accepted
