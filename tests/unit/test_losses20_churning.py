"""Churning of the high-speed CRB 50x75x16 (seed paper 003) by hand, term by term.

The point of configs/scenes/crb_rib_example.toml: 30000 r/min, 3 kN radial, race
control, oil jet 2 L/min of MIL-PRF-23699, everything at 80 degC. The hand values are
written out below from the bearing file (d_m 62.5 mm, D = l = 6 mm, 24 rollers, inner
land 59.485 mm, outer raceway 68.515 mm, width 16 mm, inner-ring-guided cage with 4 mm
of land) and the oil's density and viscosity at 80 degC.
"""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.heat_sources import HeatContext, evaluate
from thermobearing.heat_sources import churning as ch
from thermobearing.lubricant import load_lubricant
from thermobearing.state import KinematicState, OilSupply, OperatingPoint

T_OIL = 353.15
RPM = math.pi / 30.0


def _context(bearing_name: str = "CRB_50x75x16", speed_rpm: float = 30000.0):
    bearing = load_bearing(bearing_name)
    oil = load_lubricant("MIL_PRF_23699")
    op = OperatingPoint(inner_speed=speed_rpm * RPM, radial_load=3000.0, axial_load=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(bearing, op, lubricant=oil, temperature=T_OIL)
    supply = OilSupply("jet", 2e-3 / 60.0, T_OIL, None)
    return HeatContext.isothermal(T_OIL, bearing=bearing, lubricant=oil, supply=supply,
                                  operating=op, kinematics=ks, options={})


@pytest.fixture(scope="module")
def crb30k():
    return _context()


def _by_source(ctx, names):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return {r.source: r for r in evaluate(list(names), ctx)}


def test_oil_fraction_and_orbit_by_hand(crb30k):
    # Parker: X = 1.46e7 * 2000^0.37 / (30000 * 62.5^1.7) % ; 2000^0.37 = 16.650,
    # 62.5^1.7 = 1130.3 -> 2.4309e8 / 3.3909e7 = 7.169 %
    x = ch.parker_oil_fraction(2e-3 / 60.0, 30000 * RPM, 0.0625)
    assert x == pytest.approx(0.07169, rel=1e-3)
    # race control: omega_m = (omega_i / 2)(1 - D/d_m) = 1570.8 * (1 - 0.096) = 1420.0 rad/s
    assert float(crb30k.kinematics.orbital_speed[0]) == pytest.approx(1420.0, rel=1e-4)


def test_element_churning_is_eq10_per_roller_by_hand(crb30k):
    rho = float(crb30k.lubricant.density(T_OIL))
    assert rho == pytest.approx(957.4, rel=1e-3)  # the oil file's density at 80 degC
    # rho_e = 0.07169 * 957.4 = 68.63 kg/m^3; u = 1420.0 * 0.03125 = 44.375 m/s;
    # A = 6 mm * 6 mm = 3.6e-5 m^2 (roller broadside); c_d = 1.0 (roller default)
    # F = 0.5 * 1.0 * 68.63 * 44.375^2 * 3.6e-5 = 2.433 N; P = 24 * F * u = 2591 W
    assert ch.element_frontal_area(crb30k.bearing) == pytest.approx(3.6e-5, rel=1e-12)
    r = _by_source(crb30k, ["churning_elements"])["churning_elements"]
    assert r.details["form"] == "harris"
    # the roller's own Reynolds number u D / nu = 44.375 * 0.006 / 7.896e-6 = 3.37e4: inside
    # the cylinder drag plateau that c_d = 1.0 stands for
    assert r.details["element_reynolds"] == pytest.approx(3.372e4, rel=2e-3)
    assert r.components["element churning"] == pytest.approx(2591.0, rel=2e-3)
    force = r.forces["element_drag_force"]
    assert float(force[0]) == pytest.approx(-2.433, rel=2e-3)  # against the orbit


def test_inner_ring_churning_leaves_the_guide_film_to_cage_guide(crb30k):
    b = crb30k.bearing
    assert b.cage.guidance == "inner_ring"
    d_li, arc, shoulder, gap = ch.inner_ring_churning_geometry(b)
    # the cage runs on the inner land: that film (land 4 mm wide, gap 0.1 mm) is cage_guide's
    assert d_li == pytest.approx(0.059485)
    assert arc + 2 * shoulder + b.cage.land_width == pytest.approx(b.width)  # 6 + 2*3 + 4
    # gap: cavity height between the lands (68.515 - 59.485)/2 = 4.515 mm, not 0.1 mm
    assert gap == pytest.approx(4.515e-3, rel=1e-9)
    # eq. 17: Re = 0.0297425 * 3141.59 * 4.515e-3 / 7.896e-6 = 5.343e4 (turbulent):
    # mu_v = 3 * 16/53430 * (53430/2500)^0.85596 = 0.012354;
    # Q = pi * 68.63 * 0.012354 * 3141.59^3 * 0.012 * 0.059485^4 / 64 = 193.9 W
    srcs = _by_source(crb30k, ["churning_inner_ring", "cage_guide"])
    ring = srcs["churning_inner_ring"]
    assert ring.details["regime"] == 2
    assert ring.details["mu_v"] == pytest.approx(0.012354, rel=1e-3)
    assert ring.components["inner ring churning"] == pytest.approx(193.9, rel=3e-3)
    # the land film itself stays booked once, by cage_guide (Petroff on 4 mm of land)
    assert srcs["cage_guide"].components["cage guide"] > 0.0


def test_outer_guided_and_element_guided_cages_keep_paper002_geometry():
    # paper 002's own (outer-ring guided) layout: gap land -> cage bore over the full width
    for name in ("QJ1044", "NU214", "D1842926"):
        b = load_bearing(name)
        d_li, arc, shoulder, gap = ch.inner_ring_churning_geometry(b)
        assert shoulder == pytest.approx(max(0.5 * (b.width - b.element_diameter), 0.0))
        assert gap == pytest.approx(max(0.5 * (b.cage.inner_diameter - d_li), 1e-4))


def test_element_drag_speed_law_against_skf_drag_term():
    """Parker's X ~ 1/n makes the element drag power ~ n^2 at a given flow, SKF's drag term
    (moment ~ n^2) ~ n^3: the ratio falls 3x from 10000 to 30000 r/min (module docstring:
    3.2 and 1.08 at 80 degC). A change of either law shows here."""
    from thermobearing.global_friction import skf_four_term

    ratios = []
    powers = []
    for rpm in (10000.0, 30000.0):
        ctx = _context(speed_rpm=rpm)
        p = _by_source(ctx, ["churning_elements"])["churning_elements"].components[
            "element churning"]
        nu = float(ctx.lubricant.kinematic_viscosity(T_OIL))
        skf = skf_four_term(ctx.bearing, nu, rpm * RPM, 3000.0, series="10",
                            lubrication="oil_jet")
        powers.append(p)
        ratios.append(p / (skf.components["drag"] * rpm * RPM))
    assert powers[1] / powers[0] == pytest.approx(9.0, rel=1e-3)  # n^2 (race control)
    assert ratios[0] == pytest.approx(3.2, rel=0.05)
    assert ratios[1] == pytest.approx(1.08, rel=0.05)
