"""Tests of thermobearing.rib (paper 003 eqs. 1-17, 21-24)."""

import math

import numpy as np
import pytest

from thermobearing.errors import InputError, ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.hertz import point_contact
from thermobearing.rib import (
    lubricant_drag,
    rib_forces,
    rib_geometry,
    rib_sliding_speed,
    unbalance_check,
)


@pytest.fixture(scope="module")
def geom():
    return rib_geometry(load_bearing("CRB_50x75x16"))


def test_contact_height_eq11(geom):
    # hand value: H = D/2 - R_s sin(theta_f) = 3 mm - 300 mm * sin(0.3 deg) = 1.42921 mm
    assert geom.contact_height() == pytest.approx(3e-3 - 0.3 * math.sin(math.radians(0.3)))
    assert geom.contact_height() == pytest.approx(1.42921e-3, rel=1e-5)


def _cone_offset(geom, a):
    """(phi, rise) of the sphere end face at skew a on the conical rib (rib.py module notes,
    "Contact normal"): its centre sits z_c = 0.297 sin(a) off the roller's radial plane, at
    the meridional angle phi = atan(z_c / rc0) about the bearing axis (rc0 = d_i/2 + D_w/2);
    the rib cone lies rise = sin(theta_f)(sqrt(rc0^2 + z_c^2) - rc0) further off there."""
    rc0 = 0.5 * geom.inner_raceway_diameter + 0.5 * geom.roller_diameter
    z_c = 0.297 * math.sin(a)
    return (math.atan2(z_c, rc0),
            math.sin(geom.rib_angle) * (math.hypot(rc0, z_c) - rc0))


def test_approach_eq1_hand_value(geom):
    # eq. 1 with R_p - L_p/2 = R_s - L_r/2 = 297 mm, C_a/2 = 15 um, C_af = 0, X = 0:
    # alpha = 0.012 rad -> (1 - cos 0.012) * 0.297 - 15e-6 = 6.3838e-6 m, times cos(0.3 deg),
    # less the rib cone's rise at the offset sphere centre, 1.061 um (z_c = 3.56 mm)
    dl, dr = geom.approach(0.012, 0.0)
    eq1 = ((1 - math.cos(0.012)) * 0.297 - 15e-6) * math.cos(math.radians(0.3))
    expect = eq1 - _cone_offset(geom, 0.012)[1]
    assert _cone_offset(geom, 0.012)[1] == pytest.approx(1.061e-6, rel=1e-3)
    assert dl == pytest.approx(expect) and dr == pytest.approx(expect)
    # an axial shift opens the left side and closes the right (eq. 5)
    dl, dr = geom.approach(0.0, 5e-6)
    assert dr - dl == pytest.approx(2 * 5e-6 * math.cos(math.radians(0.3)))
    assert dl < 0


def test_curvature_eq10(geom):
    rx, ry = geom.curvature()
    r_c = 0.5 * geom.inner_raceway_diameter + geom.contact_height()
    assert ry == pytest.approx(0.3)
    assert 1 / rx == pytest.approx(1 / 0.3 + math.tan(math.radians(0.3)) / r_c)
    assert ry / rx >= 1.0


def test_force_is_hertz_point_contact(geom):
    # Q = K delta^1.5 must invert hertz.point_contact's approach
    q = 200.0
    rx, ry = geom.curvature()
    # eqs. 6-9 are the Brewe-Hamrock fits: invert hertz's approach with the same method
    delta = point_contact(q, rx, ry, geom.effective_modulus,
                          method="brewe_hamrock_1977").approach
    from thermobearing.rib import rib_normal_force
    assert rib_normal_force(geom, delta) == pytest.approx(q, rel=1e-6)
    assert rib_normal_force(geom, -1e-6) == 0.0


def test_sliding_speed_pure_rolling(geom):
    # at pure rolling omega_r = (w_i - w_c) d_i / D the rib slides at
    # (w_i - w_c) H (1 + d_i/D) (derived in rib.py)
    wi, wc = 3000.0, 1300.0
    wr = (wi - wc) * geom.inner_raceway_diameter / geom.roller_diameter
    v = rib_sliding_speed(geom, wi, wc, wr)
    h = geom.contact_height()
    assert v == pytest.approx((wi - wc) * h * (1 + geom.inner_raceway_diameter
                                              / geom.roller_diameter))
    # a skew rate adds -/+ alpha_dot L/2 on the two faces
    vl = rib_sliding_speed(geom, wi, wc, wr, 10.0, side=-1)
    vr = rib_sliding_speed(geom, wi, wc, wr, 10.0, side=+1)
    assert vr - vl == pytest.approx(10.0 * geom.roller_length)


def test_forces_balance_and_signs(geom):
    f = rib_forces(geom, 0.012, 2e-6, inner_speed=3141.6, cage_speed=1400.0,
                   roller_spin=16000.0, skew_rate=0.0, friction_coefficient=0.05)
    assert f.normal_right > f.normal_left > 0          # shifted right: right rib harder
    assert f.axial_force < 0                           # pushed back to the left
    assert f.skew_moment < 0                           # restores a positive skew (M_er)
    # Coulomb friction mu Q along the sliding direction: its circumferential part is
    # mu Q v_z / |v| (v_z > 0: C = +1 of eq. 13), the heat mu Q |v|
    assert f.sliding_left > 0
    assert f.friction_left == pytest.approx(
        0.05 * f.normal_left * f.sliding_left / f.slide_speed_left)
    assert f.heat_right == pytest.approx(0.05 * f.normal_right * f.slide_speed_right)
    assert f.pv_right == pytest.approx(f.pressure_right * f.slide_speed_right)
    # eq. 10's cone radius d_i/2 + H at the contact point's own distance from the bearing
    # axis (it lies z_K off the radial plane)
    r_p = math.hypot(0.5 * geom.inner_raceway_diameter + f.contact_height_right,
                     f.contact_offset_right)
    pc = point_contact(f.normal_right,
                       *geom.curvature(r_p - 0.5 * geom.inner_raceway_diameter),
                       geom.effective_modulus, method="brewe_hamrock_1977")
    assert f.pressure_right == pytest.approx(3 * f.normal_right / (2 * math.pi * pc.a * pc.b))
    # the radial sliding of the offset contact point brakes the spin (rolling sense < 0)
    assert f.spin_moment < 0
    # no contact at zero skew and centred roller
    f0 = rib_forces(geom, 0.0, 0.0, inner_speed=3141.6, cage_speed=1400.0, roller_spin=1e4)
    assert f0.normal_left == 0 and f0.pv_left == 0 and f0.heat_left == 0


def test_contact_point_moves_with_skew(geom):
    # sphere end face: the contact point moves circumferentially with the sphere centre,
    # (R_s - L_r/2) sin(alpha) (hand value 297 mm x sin 0.0101), and lies R_s along the rib
    # cone's normal there, turned by phi about the bearing axis: z_K = z_c - R_s
    # sin(theta_f) sin(phi), H = D_w/2 - R_s sin(theta_f) cos(phi) (eq. 11 at phi = 0)
    h, z, blend = geom.contact_point(0.0101, side=1)
    phi = _cone_offset(geom, 0.0101)[0]
    rho = 0.3 * math.sin(geom.rib_angle) * math.cos(phi)
    assert h == pytest.approx(0.5 * geom.roller_diameter - rho, rel=1e-9)
    assert h - geom.contact_height() == pytest.approx(7.19e-6, rel=1e-3)
    assert z == pytest.approx(0.297 * math.sin(0.0101)
                              - 0.3 * math.sin(geom.rib_angle) * math.sin(phi), rel=1e-9)
    assert not blend
    _, z_left, _ = geom.contact_point(0.0101, side=-1)
    assert z_left == pytest.approx(-z)
    # sliding speed at skew (rigid-body velocities, hand formulas): circumferential part
    # (w_i - w_c)(d_i/2 + H) - w_r rho cos(alpha); radial part (w_i - w_c) z + w_r p_z, with
    # p_z = R_s (cos(theta_f) sin(alpha) - sin(theta_f) sin(phi) cos(alpha)) the point's
    # offset from the (skewed) spin axis
    wi, wc, wr = 3141.6, 1400.0, 16000.0
    f = rib_forces(geom, 0.0101, 1e-5, inner_speed=wi, cage_speed=wc, roller_spin=wr)
    vz = (wi - wc) * (0.5 * geom.inner_raceway_diameter + h) - wr * rho * math.cos(0.0101)
    p_z = 0.3 * (math.cos(geom.rib_angle) * math.sin(0.0101)
                 - math.sin(geom.rib_angle) * math.sin(phi) * math.cos(0.0101))
    vy = (wi - wc) * z + wr * p_z
    # (the kernel removes the slide's component along the rib normal, ~ v_y sin theta_f:
    # 1e-5 relative here)
    assert f.sliding_right == pytest.approx(vz, rel=1e-4)
    assert f.slide_speed_right == pytest.approx(math.hypot(vz, vy), rel=1e-4)
    assert f.contact_offset_right == pytest.approx(z)


def test_cap_end_face_blend(geom):
    from thermobearing.rib import with_changes

    cap = with_changes(geom, end_face="cap")
    # at zero skew the sphere point (1.57 mm off the axis) is inside the 2.5 mm flat face:
    # same approach as the sphere
    assert cap.approach(0.0, 0.0)[1] == pytest.approx(geom.approach(0.0, 0.0)[1])
    # at 0.0101 rad the sphere point would be 3.4 mm off the axis: the chamfer blend
    # touches instead, higher up and with a smaller approach than the whole sphere
    h, z, blend = cap.contact_point(0.0101)
    assert blend and h > geom.contact_height()
    assert cap.approach(0.0101, 0.0)[1] < geom.approach(0.0101, 0.0)[1]
    with pytest.raises(InputError, match="end_face"):
        with_changes(geom, end_face="flat")


def test_lubricant_drag_units(geom):
    # eq. 14-15 (repaired): F = dw eta (4/3)(R0/Ca) h sqrt(r^2 - (r-h)^2)
    f, m = lubricant_drag(geom, 3000.0, 1000.0, 1e-3)
    r, h = 3e-3, 1.5e-3
    r0 = 0.5 * geom.inner_raceway_diameter + geom.contact_height()
    expect = 2000.0 * 1e-3 * 4 / 3 * r0 / 3e-5 * h * math.sqrt(r * r - (r - h) ** 2)
    assert f == pytest.approx(expect)
    assert m == pytest.approx(expect * (r - h / 2))


def test_bad_input_names_field():
    b = load_bearing("CRB_50x75x16")
    with pytest.raises(InputError, match="rib_height"):
        rib_geometry(b, rib_height=1.0e-3)          # contact point 1.43 mm above a 1 mm rib
    with pytest.raises(InputError, match="axial_clearance"):
        rib_geometry(b, axial_clearance=-1e-6)
    with pytest.raises(InputError, match="unbalance_mass"):
        unbalance_check(2e-3, b.roller_mass)
    with pytest.raises(InputError, match="crown_radius"):
        rib_geometry(b, crown_radius=2e-3)


def test_vectorised(geom):
    a = np.linspace(0, 0.015, 5)
    f = rib_forces(geom, a, 0.0, inner_speed=3000.0, cage_speed=1300.0, roller_spin=1.6e4)
    assert f.normal_left.shape == (5,)
    assert np.all(np.diff(f.normal_left) >= 0)


_SKID = {}


def _ctx(axial_load=0.0, options=None):
    from thermobearing.heat_sources import HeatContext
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.roller import solve_roller
    from thermobearing.state import OilSupply, OperatingPoint

    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    w = 30000 * math.pi / 30
    if "res" not in _SKID:
        _SKID["res"] = solve_roller(b, lub, w, 3000.0, 0.0, 353.15)
    res = _SKID["res"]
    return HeatContext.isothermal(
        353.15, bearing=b, lubricant=lub,
        supply=OilSupply(method="jet", flow_rate=1e-5, inlet_temperature=353.15, level=None),
        operating=OperatingPoint(inner_speed=w, radial_load=3000.0, axial_load=axial_load),
        kinematics=res.kinematic_state, options=options or {})


def test_rib_heat_source_thrust_and_network_roles():
    from thermobearing.heat_sources import HEAT_SOURCES, evaluate

    assert "rib_friction" in HEAT_SOURCES
    reduced = {"rib_friction": {"model": "reduced"}}
    drag_only = HEAT_SOURCES.get("rib_friction")(_ctx(0.0, reduced))
    with pytest.warns(ValidityWarning, match="no path"):
        thrust = HEAT_SOURCES.get("rib_friction")(_ctx(480.0, reduced))
    # thrust: Q = F_a / (Z cos theta) per roller; heat = sum mu Q |v| + drag (hand check)
    kin = _ctx(480.0).kinematics
    g = rib_geometry(load_bearing("CRB_50x75x16"))
    v = rib_sliding_speed(g, kin.inner_speed, kin.cage_speed, np.abs(kin.element_spin))
    q = 480.0 / (24 * math.cos(g.rib_angle))
    f = 0.05 * q + drag_only.details["drag_force"] * 2
    assert thrust.total == pytest.approx(float(np.sum(np.abs(f * v))), rel=1e-9)
    assert thrust.total > drag_only.total > 0
    # heat == sum of force x relative speed
    assert sum(p.power for p in thrust.force_pairs) == pytest.approx(thrust.total, rel=1e-9)
    # own loss component, split elements / inner ring (Blok partition, 0 < share < 1)
    assert set(thrust.power_by_role) == {"elements", "inner_ring"}
    assert 0 < thrust.details["element_share"] < 1
    assert list(thrust.components) == ["roller end face / rib"]
    # a network without an inner-ring node is refused
    with pytest.raises(InputError, match="rib_friction"):
        evaluate(["rib_friction"], _ctx(0.0, reduced), node_roles=["elements", "oil"])


def test_rib_heat_source_unbalance_option():
    from thermobearing.heat_sources import HEAT_SOURCES

    plain = HEAT_SOURCES.get("rib_friction")(_ctx(0.0, {"rib_friction": {"model": "reduced"}}))
    dyn = HEAT_SOURCES.get("rib_friction")(
        _ctx(0.0, {"rib_friction": {"unbalance_mass": 1e-4, "model": "reduced"}}))
    assert dyn.total > plain.total
    # without thrust the reduced dynamics' heat (skew contacts + drag of both faces) is the
    # whole heat: the drag at the kinematic spins is not added a second time
    assert dyn.details["dynamic_heat"] == pytest.approx(dyn.total, rel=1e-12)
    assert sum(p.power for p in dyn.force_pairs) == pytest.approx(dyn.total, rel=1e-9)
    with pytest.raises(InputError, match="unbalance_mass"):
        HEAT_SOURCES.get("rib_friction")(_ctx(0.0, {"rib_friction": {"unbalance_mass": -1.0}}))
    with pytest.raises(InputError, match="model"):
        HEAT_SOURCES.get("rib_friction")(_ctx(0.0, {"rib_friction": {"model": "full"}}))
    # an outer-ribbed (NU-type) bearing: the inner-rib model does not apply
    import dataclasses

    ctx = _ctx(0.0)
    # (with a roller-guided cage that clears the outer ribs: the inner-rib land it was guided
    # on is gone from a plain inner ring, as the geometry check says)
    outer = dataclasses.replace(ctx.bearing, ribbed_ring="outer",
                                cage=dataclasses.replace(ctx.bearing.cage,
                                                         guidance="rolling_element",
                                                         outer_diameter=0.065))
    nu = dataclasses.replace(ctx, bearing=outer)
    with pytest.raises(InputError, match="ribbed_ring"):
        HEAT_SOURCES.get("rib_friction")(nu)


def test_contact_skew_and_sliding_grow_with_axial_clearance(geom):
    # paper 003 sec. 10.1: with a larger axial clearance the roller skews further before
    # its end face reaches the rib; the contact point is then further off the roller's
    # radial plane (z_K = (R_s - L_r/2) sin alpha) and slides faster over the rib.
    from scipy.optimize import brentq

    from thermobearing.rib import with_changes

    skews, slides = [], []
    for ca in (0.01e-3, 0.05e-3, 0.09e-3):
        g = with_changes(geom, axial_clearance=ca)
        a = brentq(lambda s, g=g: float(g.approach(s, 0.0)[1]), 0.0, 0.1)
        # eq. 1 at X = 0: (R_s - L_r/2)(1 - cos a) = C_a/2 (hand inversion), less the rib
        # cone's rise at the offset sphere centre (_cone_offset): 2.6 % more skew at 0.03 mm
        a_eq1 = math.acos(1.0 - 0.5 * ca / 0.297)
        a_cone = brentq(lambda s, g=g, ca=ca: (0.297 * (1 - math.cos(s)) - 0.5 * ca)
                        * math.cos(g.rib_angle) - _cone_offset(g, s)[1], 0.0, 0.1)
        assert a == pytest.approx(a_cone, rel=1e-6)
        assert 1.0 < a / a_eq1 < 1.05
        f = rib_forces(g, a, 0.0, inner_speed=3141.6, cage_speed=730.0, roller_spin=16700.0)
        skews.append(a)
        slides.append(float(f.slide_speed_right))
    assert skews[0] < skews[1] < skews[2]
    assert slides[0] < slides[1] < slides[2]


def test_radial_plane_slide_option(geom):
    # slide="radial_plane" (paper 003 eqs. 11-13, 16, 24 read literally): the sliding speed
    # is the circumferential one at the eq. 11 height in the radial plane,
    # (w_i - w_c)(d_i/2 + H) - w_r rho cos(alpha) + alpha' x_K (hand formula; a skew rate moves
    # the end at x by -alpha' x along z, module notes), the friction
    # is circumferential only; the normal force (and its skew moment) is unchanged
    from dataclasses import replace

    gp = replace(geom, slide="radial_plane")
    wi, wc, wr, a, ad = 3141.6, 1400.0, 16000.0, 0.0101, 30.0
    kw = dict(inner_speed=wi, cage_speed=wc, roller_spin=wr, skew_rate=ad)
    f = rib_forces(gp, a, 1e-5, **kw)
    g = rib_forces(geom, a, 1e-5, **kw)
    h = geom.contact_point(a)[0]        # eq. 11 with the cone's normal (module notes)
    rho = 0.5 * geom.roller_diameter - h
    x_k = 0.5 * geom.roller_length - 0.297 * (1 - math.cos(geom.rib_angle))  # R_s cos - ...
    vz = (wi - wc) * (0.5 * geom.inner_raceway_diameter + h) - wr * rho * math.cos(a)
    assert f.slide_speed_right == pytest.approx(abs(vz + ad * x_k), rel=1e-4)
    assert f.slide_speed_right == pytest.approx(abs(f.sliding_right), rel=1e-12)
    assert f.normal_right == g.normal_right > 0
    # friction along z only: the radial force is the normal force's alone, Q sin(theta_f)
    # cos(phi) along the rib cone's normal
    q = f.normal_right
    phi = _cone_offset(geom, a)[0]
    assert f.radial_force == pytest.approx(q * math.sin(geom.rib_angle) * math.cos(phi),
                                           rel=1e-9)
    # rib faster than the end face point -> the friction drives the spin (eq. 13, C = +1)
    assert vz > 0 and f.spin_moment > 0
    with pytest.raises(InputError, match="slide"):
        replace(geom, slide="bogus")
