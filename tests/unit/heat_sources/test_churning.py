"""Churning sources: paper 002 eqs. 12-17 by hand, the SI form of eq. 16, oil fraction."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.heat_sources import churning as ch
from thermobearing.units import unit_registry

from .conftest import make_context, uniform_state


def test_regimes_by_hand():
    # R = 0.1 m, c = 1 mm, nu = 1e-4 m^2/s
    # omega = 1 rad/s: Re = 0.1*1*1e-3/1e-4 = 1, Ta = 1*sqrt(0.01) = 0.1 -> laminar 16/Re = 16
    r = ch.viscous_friction_coefficient(0.1, 1.0, 1e-3, 1e-4)
    assert float(r.mu_v) == pytest.approx(16.0) and int(r.regime) == 0
    # omega = 2000: Re = 2000, Ta = 200 -> vortex: 1.3 * 16/2000 * (200/41)^0.539474 (eq. 13)
    r = ch.viscous_friction_coefficient(0.1, 2000.0, 1e-3, 1e-4)
    assert float(r.mu_v) == pytest.approx(1.3 * 0.008 * (200 / 41) ** 0.539474, rel=1e-12)
    assert int(r.regime) == 1
    # omega = 5000: Re = 5000 > 2500 -> Couette turbulent: 3 * 16/5000 * 2^0.85596 (eq. 14)
    r = ch.viscous_friction_coefficient(0.1, 5000.0, 1e-3, 1e-4)
    assert float(r.mu_v) == pytest.approx(3.0 * 16 / 5000 * 2 ** 0.85596, rel=1e-12)
    assert int(r.regime) == 2


def test_scalar_and_array_inputs_agree_across_the_regimes():
    # omega 0 (no rotation), laminar, both sides of N_Ta = 41 and of N_Re = 2500
    omegas = [0.0, 1.0, 409.0, 411.0, 2499.0, 2501.0, 5000.0, -5000.0]
    arr = ch.viscous_friction_coefficient(0.1, np.array(omegas), 1e-3, 1e-4)
    for i, w in enumerate(omegas):
        one = ch.viscous_friction_coefficient(0.1, w, 1e-3, 1e-4)
        assert float(one.mu_v) == float(arr.mu_v[i]) and int(one.regime) == int(arr.regime[i])
    assert list(arr.regime) == [0, 0, 0, 1, 1, 2, 2, 2]
    assert float(arr.mu_v[0]) == 0.0 and arr.mu_v.dtype == float


def test_cage_and_ring_power_by_hand():
    # eq. 15: pi*800*0.01*100^3*0.04*0.28^4/64 = 96.55 W
    q = ch.cage_churning_power(800.0, 0.01, 100.0, 0.04, 0.28)
    assert float(q) == pytest.approx(math.pi * 800 * 0.01 * 1e6 * 0.04 * 0.28 ** 4 / 64)
    assert float(q) == pytest.approx(96.55, rel=1e-3)
    # eq. 17 with B_arc = 35 mm, B_Li = 10 mm, D_Li = 0.245 m, omega 188.5 rad/s
    q = ch.inner_ring_churning_power(860.0, 0.03, 188.5, 0.035, 0.010, 0.245)
    assert float(q) == pytest.approx(
        math.pi * 860 * 0.03 * 188.5 ** 3 * 0.055 * 0.245 ** 4 / 64, rel=1e-12)


def test_eq16_si_form_is_a_power_and_the_printed_form_is_not():
    ureg = unit_registry()
    rho = ureg.Quantity(860.0, "kg/m**3")
    omega = ureg.Quantity(85.0, "1/s")
    dm = ureg.Quantity(0.28, "m")
    db = ureg.Quantity(0.035, "m")
    g = ureg.Quantity(9.81, "m/s**2")
    si = ch.ball_churning_power_paper002(0.45, rho, 0.02, omega, dm, db, 20)
    assert si.check("[power]")
    printed = 0.45 * math.pi * rho * 0.02 * omega ** 3 * dm ** 3 * db * 20 / (256 * g)
    assert not printed.check("[power]")
    # even with a weight density (N/m^3) the printed D_b^1 form is one length short
    rho_w = rho * g
    printed_w = 0.45 * math.pi * rho_w * 0.02 * omega ** 3 * dm ** 3 * db * 20 / (256 * g)
    assert (printed_w * ureg.Quantity(1.0, "m")).check("[power]")
    # SI form = Harris drag power x mu_v/4:  Z * 1/2 c_d rho (pi D^2/4) u^3, u = omega dm/2
    u = omega * dm / 2
    harris = 20 * 0.5 * 0.45 * rho * (math.pi * db ** 2 / 4) * u ** 3
    assert si.to("W").magnitude == pytest.approx((harris * 0.02 / 4).to("W").magnitude)


def test_parker_fraction():
    # QJ1044 (d_m = 280 mm), 1800 r/min, 33 L/min = 33000 cm^3/min:
    # X = 1.46e7 * 33000^0.37 / (1800 * 280^1.7) % = 26.3 %
    x33 = ch.parker_oil_fraction(33e-3 / 60, 1800 * math.pi / 30, 0.28)
    assert x33 == pytest.approx(1.46e7 * 33000 ** 0.37 / (1800 * 280 ** 1.7) / 100, rel=1e-9)
    assert x33 == pytest.approx(0.263, abs=0.002)
    x15 = ch.parker_oil_fraction(15e-3 / 60, 1800 * math.pi / 30, 0.28)
    assert x15 / x33 == pytest.approx((15 / 33) ** 0.37, rel=1e-12)
    assert ch.parker_oil_fraction(1.0, 1.0, 0.01) == 1.0  # capped


def test_oil_bath_fraction():
    ro, r = 0.17, 0.14
    assert float(ch.oil_bath_fraction(ro - r, ro, r)) == pytest.approx(0.0)
    assert float(ch.oil_bath_fraction(ro, ro, r)) == pytest.approx(0.5)
    assert float(ch.oil_bath_fraction(ro + r, ro, r)) == pytest.approx(1.0)


def test_sources_scale_with_flow(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    totals = {}
    for flow in (33.0, 15.0):
        ctx = make_context(qj1044, vg46, op, ks, flow=flow)
        totals[flow] = sum(getattr(ch, n)(ctx).total for n in
                           ("churning_cage", "churning_elements", "churning_inner_ring"))
    assert totals[15.0] / totals[33.0] == pytest.approx((15 / 33) ** 0.37, rel=1e-9)


def test_element_drag_harris_form_by_hand(qj1044, vg46, race_control_state):
    op, _ = race_control_state
    z = qj1044.n_elements
    ks = uniform_state(z, cage_speed=85.0)
    ctx = make_context(qj1044, vg46, op, ks,
                       options={"churning_elements": {"form": "harris", "oil_fraction": 0.1}})
    r = ch.churning_elements(ctx)
    rho = float(vg46.density(318.15)) * 0.1
    u = 85.0 * qj1044.pitch_diameter / 2
    f = 0.5 * 0.45 * rho * u ** 2 * math.pi * qj1044.ball_diameter ** 2 / 4
    np.testing.assert_allclose(-r.forces["element_drag_force"], f, rtol=1e-12)
    assert r.total == pytest.approx(z * f * u, rel=1e-12)


def test_oil_bath_and_grease(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    ctx = make_context(qj1044, vg46, op, ks, flow=0.0, method="oil_bath", level=0.0)
    assert ch.churning_cage(ctx).total == 0.0
    ctx = make_context(qj1044, vg46, op, ks, flow=0.0, method="oil_bath", level=0.4)
    assert ch.churning_cage(ctx).details["oil_fraction"] == pytest.approx(1.0)
    ctx = make_context(qj1044, vg46, op, ks, flow=0.0, method="grease")
    with pytest.warns(ch.ValidityWarning):
        assert ch.churning_inner_ring(ctx).total == 0.0


def test_roller_bearing_uses_eq10_drag(vg46):
    from thermobearing.errors import InputError
    from thermobearing.geometry import load_bearing
    from thermobearing.state import OperatingPoint

    nu214 = load_bearing("NU214")
    op = OperatingPoint(inner_speed=523.6, radial_load=150.0)
    ks = uniform_state(nu214.n_elements, cage_speed=220.0)
    with pytest.raises(InputError, match="harris"):
        ch.churning_elements(make_context(nu214, vg46, op, ks, options={
            "churning_elements": {"form": "paper002"}}))
    r = ch.churning_elements(make_context(nu214, vg46, op, ks))  # default: eq. 10 drag
    area = nu214.roller_diameter * nu214.roller_length
    u = 220.0 * nu214.pitch_diameter / 2
    rho = r.details["oil_fraction"] * float(vg46.density(318.15))
    assert r.total == pytest.approx(nu214.n_elements * 0.5 * 1.0 * rho * area * u ** 3)
