"""The thrust share's contact on the outer-ring rib of a both-ribbed (NJ / NUP) bearing
(thermobearing.rib_outer, heat source rib_friction): hand-checked geometry and speed, the
mirror symmetry with the inner rib, and the loss component in the heat result."""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest

from thermobearing.bearing_config import load_bearing
from thermobearing.errors import InputError, ValidityWarning
from thermobearing.rib import rib_geometry, rib_sliding_speed, with_changes
from thermobearing.rib_outer import (
    outer_contact_radius,
    outer_curvature,
    outer_rib_sliding_speed,
    outer_thrust_contact,
)


@pytest.fixture(scope="module")
def geom():
    return rib_geometry(load_bearing("CRB_50x75x16"))


def test_contact_radius_and_curvature_by_hand(geom):
    rho = geom.crown_radius * math.sin(geom.rib_angle)          # 300 mm x sin 0.3 deg
    assert rho == pytest.approx(1.5708e-3, rel=1e-4)
    r_o = outer_contact_radius(geom)
    assert r_o == pytest.approx(0.5 * geom.inner_raceway_diameter
                                + 0.5 * geom.roller_diameter + rho, rel=1e-15)
    rx, ry = outer_curvature(geom)
    assert ry == geom.crown_radius
    assert 1.0 / rx == pytest.approx(1.0 / geom.crown_radius - math.tan(geom.rib_angle) / r_o,
                                     rel=1e-14)
    # the concave outer cone flattens the contact, the convex inner one sharpens it
    rx_in, _ = geom.curvature()
    assert rx_in < geom.crown_radius < rx
    # the cone's curvature is the rib's: a larger crown radius, the same contact height
    # (R_s sin theta_f fixed), gives the same 1/R_x - 1/R_s
    other = with_changes(geom, crown_radius=2 * geom.crown_radius,
                         rib_angle=math.asin(0.5 * math.sin(geom.rib_angle)))
    assert 1.0 / outer_curvature(other)[0] - 1.0 / other.crown_radius == pytest.approx(
        -math.tan(other.rib_angle) / outer_contact_radius(other), rel=1e-12)


def test_sliding_speed_pure_rolling_and_mirror(geom):
    """In pure rolling on the outer race (omega_o = 0) the face slides over the outer rib at
    the height D_w/2 - rho below the raceway: v_o = -(omega_r - omega_c)(D_w/2 - rho); the
    inner rib's v_i = (omega_i - omega_c + omega_r)(D_w/2 - rho) in pure rolling on the inner
    race: the same lever D_w/2 - rho."""
    wi, wc = 3141.6, 1400.0
    d_i, d_w = geom.inner_raceway_diameter, geom.roller_diameter
    d_o = d_i + 2.0 * d_w
    # spin of pure rolling on the outer race: -(0 - omega_c) d_o/2 = omega_r D_w/2
    spin_o = wc * d_o / d_w
    rho = geom.contact_arm
    v_o = outer_rib_sliding_speed(geom, 0.0, wc, spin_o)
    assert v_o == pytest.approx(-(spin_o - wc) * (0.5 * d_w - rho), rel=1e-12)
    # pure rolling on the inner race: v_i = (omega_i - omega_c)(d_i/2 + h) - omega_r rho
    spin_i = (wi - wc) * d_i / d_w
    v_i = rib_sliding_speed(geom, wi, wc, spin_i)
    assert v_i == pytest.approx((wi - wc + spin_i) * (0.5 * d_w - rho), rel=1e-12)
    # vectorised per roller
    v = outer_rib_sliding_speed(geom, 0.0, wc, np.array([spin_o, 2 * spin_o]))
    assert v.shape == (2,) and v[0] < 0
    assert v[1] - v[0] == pytest.approx(spin_o * rho, rel=1e-12)


def test_thrust_contact_hertz(geom):
    p, area, hw = outer_thrust_contact(geom, 20.0)
    # Q = (2/3) p_max pi a b (Hertz ellipse)
    assert 20.0 == pytest.approx(2.0 / 3.0 * p * area, rel=1e-9)
    assert hw == pytest.approx(math.sqrt(area / math.pi), rel=1e-12)
    assert outer_thrust_contact(geom, 0.0) == (0.0, 0.0, 0.0)
    with pytest.raises(InputError, match="normal_force"):
        outer_thrust_contact(geom, -1.0)


def test_cone_sharper_than_face_refused(geom):
    # tan(theta_f) >= r_o / R_s: the concave cone is more curved than the crowned face (a
    # valid RibGeometry keeps R_s sin(theta_f) < D_w < r_o, so only a hand-made geometry
    # gets here)
    from types import SimpleNamespace

    steep = SimpleNamespace(crown_radius=4.0, rib_angle=math.radians(44.0),
                            inner_raceway_diameter=geom.inner_raceway_diameter,
                            roller_diameter=geom.roller_diameter,
                            contact_arm=4.0 * math.sin(math.radians(44.0)))
    with pytest.raises(InputError, match="rib_angle"):
        outer_curvature(steep)


def _both_ctx(axial_load, ribbed="both"):
    from thermobearing.heat_sources import HeatContext
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.roller import solve_roller
    from thermobearing.state import OilSupply, OperatingPoint

    b = load_bearing("CRB_50x75x16")
    cage = dataclasses.replace(b.cage, outer_diameter=0.065)
    b = dataclasses.replace(b, ribbed_ring=ribbed, cage=cage)
    lub = load_lubricant("MIL_PRF_23699")
    w = 20000 * math.pi / 30
    res = solve_roller(b, lub, w, 3000.0, 0.0, 353.15)
    return HeatContext.isothermal(
        353.15, bearing=b, lubricant=lub,
        supply=OilSupply(method="jet", flow_rate=3e-5, inlet_temperature=353.15, level=None),
        operating=OperatingPoint(inner_speed=w, radial_load=3000.0, axial_load=axial_load),
        kinematics=res.kinematic_state, options={"rib_friction": {"model": "reduced"}})


def test_heat_source_books_the_outer_rib():
    from thermobearing.heat_sources import HEAT_SOURCES

    src = HEAT_SOURCES.get("rib_friction")
    ctx = _both_ctx(400.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        res = src(ctx)
        inner_only = src(_both_ctx(400.0, ribbed="inner"))
    g = rib_geometry(ctx.bearing)
    kin = ctx.kinematics
    q = 400.0 / (g_n := ctx.bearing.n_rollers) / math.cos(g.rib_angle)
    spin = np.abs(np.asarray(kin.element_spin, float)) * np.ones(g_n)
    v_o = outer_rib_sliding_speed(g, kin.outer_speed, kin.cage_speed, spin)
    outer = 0.05 * q * float(np.sum(np.abs(v_o)))
    assert res.details["outer_thrust_heat"] == pytest.approx(outer, rel=1e-12)
    assert res.components["roller end face / outer rib"] == pytest.approx(outer, rel=1e-12)
    # the inner rib's component is the inner-ribbed bearing's whole heat (same kinematics)
    assert res.components["roller end face / rib"] == pytest.approx(inner_only.total,
                                                                     rel=1e-9)
    assert res.total == pytest.approx(inner_only.total + outer, rel=1e-12)
    assert res.details["total_heat"] == pytest.approx(res.total, rel=1e-12)
    # the two thrust contacts slide at speeds of the same order (levers D_w/2 - rho)
    assert 0.3 < outer / res.details["thrust_heat"] < 3.0
    # roles: the outer rib heats the rollers and the outer ring, by Blok's partition
    split = res.component_roles["roller end face / outer rib"]
    assert set(split) == {"elements", "outer_ring"}
    assert 0.0 < res.details["outer_element_share"] < 1.0
    assert res.power_by_role["outer_ring"] == pytest.approx(split["outer_ring"], rel=1e-12)
    # every watt is a force times the speed it acts across
    assert sum(p.power for p in res.force_pairs) == pytest.approx(res.total, rel=1e-9)


def test_no_thrust_no_outer_component():
    from thermobearing.heat_sources import HEAT_SOURCES

    res = HEAT_SOURCES.get("rib_friction")(_both_ctx(0.0))
    assert list(res.components) == ["roller end face / rib"]
    assert "outer_thrust_heat" not in res.details
