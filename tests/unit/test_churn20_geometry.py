"""Churning geometry of paper 002 eqs. 15 and 17 (seed 002_0add79adaca5495c.txt) by hand.

The cage gap is the mean radial gap between the cage body and its radial neighbours (the
guide land of the guiding ring, the land or raceway of the other); the skidding solvers'
drags take the same geometry functions as the heat sources, so the booked heat is the drag
the solver balanced. Hand values from the bearing files (configs/bearings/*.toml, mm).
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import pytest

from thermobearing import skidding
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.heat_sources import HeatContext, evaluate
from thermobearing.heat_sources import churning as ch
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball_models import default_ball_models
from thermobearing.state import KinematicState, OilSupply, OperatingPoint

RPM = math.pi / 30.0
T_30C = 303.15


# (neighbours D_in, D_out; cage gap) in mm, by hand from the files:
# D1842926: outer-ring guided on the 162.23 mm bore of its outer ribs (d_o 167.03 -
#   2 x 2.4 mm rib), inner raceway 155 - 12 - 0.03 = 142.97 (no inner rib); cage 150 /
#   161.83: gaps (162.23 - 161.83)/2 = 0.2 and (150 - 142.97)/2 = 3.515, mean 1.8575
#   (session 21: the land was estimated at 170 mm, beyond the raceway, with a 169.6 mm cage;
#   the gap was the same 1.8575 mm, the cage mean diameter 159.8 mm)
# CRB_50x75x16: inner-ring guided on its 59.485 land, outer raceway 68.515 (no outer rib);
#   cage 59.685 / 66: radial gaps 0.1 and 1.2575, ((68.515 - 59.485) - 6.315)/4 = 0.67875
#   (unchanged)
# NU214: element guided, lands 84.4875 / 105.3125 (rib 2.6 mm on d_o 110.5125); cage 91 /
#   104: (3.25625 + 0.65625)/2 = 1.95625 (unchanged)
# QJ1044: outer-ring guided on 301 = outer shoulder, inner shoulder 259; cage 264 / 300.4:
#   (2.5 + 0.3)/2 = 1.4 (unchanged)
# SKF6304: element guided, shoulders 30.285 / 41.715; cage 32 / 40: (0.8575 + 0.8575)/2
CASES = {
    "D1842926": (142.97, 162.23, 1.8575),
    "CRB_50x75x16": (59.485, 68.515, 0.67875),
    "NU214": (84.4875, 105.3125, 1.95625),
    "QJ1044": (259.0, 301.0, 1.4),
    "SKF6304": (30.285, 41.715, 0.8575),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_cage_gap_is_the_clearance_to_its_neighbours_by_hand(name):
    b = load_bearing(name)
    d_in, d_out, gap = CASES[name]
    n_in, n_out = ch.cage_neighbour_diameters(b)
    assert n_in * 1e3 == pytest.approx(d_in, abs=1e-9)
    assert n_out * 1e3 == pytest.approx(d_out, abs=1e-9)
    assert n_in <= b.cage.inner_diameter and n_out >= b.cage.outer_diameter
    d_c, c = ch.cage_churning_geometry(b)
    assert d_c == pytest.approx(0.5 * (b.cage.inner_diameter + b.cage.outer_diameter))
    assert c * 1e3 == pytest.approx(gap, abs=1e-9)


def test_unguided_cage_past_the_rib_faces_the_raceway():
    # NU214 with the cage drawn out to 107 mm, past the 105.3125 mm rib: its outside faces
    # the 110.5125 mm outer raceway between the ribs: (1.75625 + 3.25625)/2 = 2.50625 mm
    b = load_bearing("NU214")
    wide = dataclasses.replace(b, cage=dataclasses.replace(b.cage, outer_diameter=0.107))
    assert ch.cage_neighbour_diameters(wide)[1] == pytest.approx(0.1105125, abs=1e-12)
    assert ch.cage_churning_geometry(wide)[1] == pytest.approx(2.50625e-3, abs=1e-12)


def _d1842926_context():
    b = load_bearing("D1842926")
    oil = load_lubricant("OIL_4109")
    op = OperatingPoint(inner_speed=13218.0 * RPM, radial_load=8000.0, axial_load=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(b, op, lubricant=oil, temperature=T_30C)
    supply = OilSupply("jet", 2e-3 / 60.0, T_30C, None)
    return HeatContext.isothermal(T_30C, bearing=b, lubricant=oil, supply=supply,
                                  operating=op, kinematics=ks, options={})


def test_d1842926_cage_churning_eq15_by_hand():
    """Paper 001's bearing at 13218 r/min, 8 kN, OIL_4109 at 30 degC (970 kg/m^3,
    nu = 3.40206e-5 m^2/s), jet 2 L/min, race control."""
    ctx = _d1842926_context()
    # omega_c = (1384.2 / 2)(1 - 12/155) = 638.51 rad/s
    assert ctx.kinematics.cage_speed == pytest.approx(638.51, rel=1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = evaluate(["churning_cage"], ctx)[0]
    # X = 1.46e7 * 2000^0.37 / (13218 * 155^1.7) % = 2.4309e8 / 6.9904e7 = 3.4775 %
    assert r.details["oil_fraction"] == pytest.approx(0.034775, rel=1e-3)
    # cage mean diameter D_c = (150 + 161.83)/2 = 155.915 mm
    # Re = 0.0779575 * 638.51 * 1.8575e-3 / 3.40206e-5 = 2717.8 (> 2500: eq. 14)
    assert r.details["reynolds"] == pytest.approx(2717.8, rel=1e-4)
    assert r.details["regime"] == 2
    # mu_v = 3 * 16/2717.8 * (2717.8/2500)^0.85596 = 0.017662 * 1.07411 = 0.018970
    assert r.details["mu_v"] == pytest.approx(0.018970, rel=2e-4)
    # Q = pi * (0.034754 * 970) * 0.018970 * 638.51^3 * 0.018 * 0.155915^4 / 64 = 86.93 W
    # (95.58 W with the former 159.8 mm cage, whose 170 mm land lay beyond the raceway;
    # the 0.1 mm floor of an earlier gap rule gave laminar mu_v = 16/150 and 539.5 W)
    assert r.components["cage churning"] == pytest.approx(86.93, rel=1e-3)


def test_d1842926_skidding_drag_is_the_booked_cage_churning():
    ctx = _d1842926_context()
    b, oil, sup = ctx.bearing, ctx.lubricant, ctx.supply
    w = ctx.operating.inner_speed
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        res = skidding.solve(b, oil, w, 8000.0, 0.0, T_30C, supply=sup)
    assert res.converged
    # the solver's cage churning moment is eq. 15 with the same gap at its own cage speed
    wc = res.cage_speed
    d_c, gap = ch.cage_churning_geometry(b)
    reg = ch.viscous_friction_coefficient(0.5 * d_c, wc, gap, oil.kinematic_viscosity(T_30C))
    rho_e = res.drag["cage_oil_fraction"] * float(oil.density(T_30C))
    q = float(ch.cage_churning_power(rho_e, reg.mu_v, wc, b.cage.width, d_c))
    assert abs(res.drag["cage_churning_moment"] * wc) == pytest.approx(q, rel=1e-9)
    booked = res.booked_power()
    assert booked["churning_cage"] == pytest.approx(q, rel=1e-9)
    assert booked["total"] == pytest.approx(res.shaft_torque * w, rel=1e-8)


def _inner_guided_qj1044():
    """QJ1044 with its cage centred on the inner ring instead: 259 mm inner shoulder as the
    guide land, 0.6 mm diametral clearance (cage bore 259.6 mm), 10 mm of land."""
    b = load_bearing("QJ1044")
    cage = dataclasses.replace(b.cage, guidance="inner_ring", guide_land_diameter=0.259,
                               inner_diameter=0.2596)
    return dataclasses.replace(b, cage=cage)


def test_inner_guided_ball_cage_geometry_by_hand():
    b = _inner_guided_qj1044()
    # inner ring: the land film (0.3 mm) is cage_guide's; eq. 17 takes the cavity height
    # (301 - 259)/2 = 21 mm over the shoulders less half the land, (56 - 34.925)/2 - 5
    d_li, arc, shoulder, gap = ch.inner_ring_churning_geometry(b)
    assert d_li == pytest.approx(0.259)
    assert arc == pytest.approx(0.034925)
    assert shoulder == pytest.approx(5.5375e-3, abs=1e-12)
    assert gap == pytest.approx(21e-3, abs=1e-12)
    # cage: neighbours 259 (guide land) and 301: ((301 - 259) - (300.4 - 259.6))/4 = 0.3 mm
    assert ch.cage_churning_geometry(b)[1] == pytest.approx(0.3e-3, abs=1e-12)


@pytest.mark.parametrize("guided", ["outer", "inner"])
def test_ball_solver_drags_are_the_heat_sources_churning(guided):
    """The ball solver's cage and inner-ring churning torques times the speeds are the
    heat the churning sources book at the same point (one geometry code path)."""
    b = load_bearing("QJ1044") if guided == "outer" else _inner_guided_qj1044()
    oil = load_lubricant("ISO_VG46")  # the qj1044_rig scene's oil
    t = 333.15
    w = 6000.0 * RPM
    sup = OilSupply("jet", 2e-3 / 60.0, t, None)
    op = OperatingPoint(inner_speed=w, radial_load=0.0, axial_load=10000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(b, op, lubricant=oil, temperature=t)
        ctx = HeatContext.isothermal(t, bearing=b, lubricant=oil, supply=sup, operating=op,
                                     kinematics=ks, options={})
        heat = {r.source: r.total for r in evaluate(["churning_cage", "churning_inner_ring"],
                                                    ctx)}
    models = default_ball_models(b, oil, temperature=t, speed=w, supply=sup)
    wc = ks.cage_speed
    assert abs(models.cage_torque(wc) * wc) == pytest.approx(heat["churning_cage"], rel=1e-9)
    ring = abs(models.inner_ring_torque(w) * w)
    assert ring == pytest.approx(heat["churning_inner_ring"], rel=1e-9)
    if guided == "inner":
        # the land film the ring churning used to take (0.3 mm gap over the full shoulders)
        # is left to cage_guide: the solver's ring drag is the smaller, 21 mm cavity one
        reg = ch.viscous_friction_coefficient(0.1295, w, 0.3e-3,
                                              oil.kinematic_viscosity(t))
        rho_e = models.parameters["oil_fraction"] * float(oil.density(t))
        old = float(ch.inner_ring_churning_power(rho_e, reg.mu_v, w, 0.034925, 10.5375e-3,
                                                 0.259))
        assert ring < 0.5 * old
