"""The roller skidding solver balances the oil drags a scene's heat sources book (issue 5).

With an oil supply (every scene: ``skidding.solve(..., supply=...)``) the paper 000 Z + 1
equations (seed 000_3b5ca6eed61dd596.txt) contain the drags of paper 002 (seed
002_0add79adaca5495c.txt): the roller drag of eq. 10 in each roller's orbital balance, the
cage churning of eq. 15 and the guide land of eq. 5 in the cage equation, the inner-ring
churning of eq. 17 in the shaft torque (``skidding.roller_drag``). The ``churning_*`` and
``cage_guide`` sources book the forces the state carries, so the shaft power equals the
booked heat of all sources. Paper 000's direct ``solve_roller`` has no drag and does not move.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.scene_step_heat import first_step_heat
from thermobearing import skidding
from thermobearing.errors import InputError, ValidityWarning
from thermobearing.heat_sources import HeatContext, evaluate
from thermobearing.skidding.roller import default_traction_law, solve_roller
from thermobearing.state import OilSupply, OperatingPoint

T_OIL = 313.15
TEMPS = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), T_OIL)
OMEGA = 5000.0 * math.pi / 30.0
SOURCES = ["raceway_traction", "ehl_rolling_resistance", "churning_elements",
           "churning_cage", "churning_inner_ring", "cage_guide", "pocket_friction"]

SCENE = """
title = "NU 214 drag balance"
[[bearings]]
name = "nu214"
preset = "{preset}"
[lubricant]
preset = "PAPER000_OIL"
[supply]
{supply}
inlet_temperature = "40 degC"
[schedule]
speed = "{speed}"
radial_load = "{load}"
axial_load = "0 kN"
[models]
kinematics = "skidding"
heat_sources = {sources}
[outputs]
mode = "steady"
want = ["losses"]
"""
JET = 'method = "jet"\nflow = "1 L/min"'
BATH = 'method = "oil_bath"\nflow = "0 L/min"\nlevel = "15 mm"'


def _scene_heat(supply: str, load: str, preset: str = "NU214", speed: str = "5000 rpm"):
    text = SCENE.format(preset=preset, supply=supply, speed=speed, load=load,
                        sources="[" + ", ".join(f'"{s}"' for s in SOURCES) + "]")
    kin, step, by_source = first_step_heat(text, TEMPS)
    return kin.raw, step.speed, by_source


@pytest.mark.parametrize("supply", [JET, BATH], ids=["jet", "oil_bath"])
@pytest.mark.parametrize("load", ["150 N", "1 kN"])
def test_scene_heat_equals_the_shaft_power(supply, load):
    res, speed, by_source = _scene_heat(supply, load)
    assert res.converged and res.drag is not None
    shaft = res.shaft_torque * speed
    total = sum(by_source.values())
    assert total == pytest.approx(shaft, rel=1e-8)
    booked = res.booked_power()
    for name in SOURCES:
        assert by_source[name] == pytest.approx(booked[name], rel=1e-12, abs=1e-12)
    # the drags are there and are not small against the film losses
    assert by_source["churning_elements"] > 0.01 * total
    assert by_source["churning_inner_ring"] > 0.01 * total
    assert by_source["cage_guide"] == 0.0  # NU 214 preset: rolling-element-guided cage


def test_oil_bath_fractions_follow_the_radius(nu214, oil):
    """The bath level model immerses each body over its own radius (the sources' rule)."""
    from thermobearing.heat_sources.churning import oil_bath_fraction

    sup = OilSupply("oil_bath", 0.0, T_OIL, level=0.015)
    res = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup)
    drag = res.drag
    r_o = 0.5 * nu214.outer_raceway_diameter
    assert drag["element_oil_fraction"] == pytest.approx(
        float(oil_bath_fraction(0.015, r_o, 0.5 * nu214.pitch_diameter)), rel=1e-15)
    assert drag["inner_ring_oil_fraction"] < drag["element_oil_fraction"]


def test_ring_guided_cages_book_the_land_moment():
    """CRB 50x75x16 (inner-ring guided: the land drives the cage and the shaft pays for it)
    and D1842926 (outer-ring guided: the land holds the cage back)."""
    for preset, speed, load in (("CRB_50x75x16", "10000 rpm", "1 kN"),
                                ("D1842926", "5000 rpm", "2 kN")):
        res, w, by_source = _scene_heat(JET, load, preset=preset, speed=speed)
        assert res.converged
        moment = res.drag["cage_guide_moment"]
        assert (moment > 0.0) is (preset == "CRB_50x75x16")
        assert by_source["cage_guide"] > 0.0
        assert sum(by_source.values()) == pytest.approx(res.shaft_torque * w, rel=1e-8)


def test_the_drag_slows_the_cage_at_light_load(nu214, oil):
    sup = OilSupply("jet", 1e-3 / 60.0, T_OIL)
    dry = skidding.solve(nu214, oil, OMEGA, 150.0, 0.0, T_OIL)
    wet = skidding.solve(nu214, oil, OMEGA, 150.0, 0.0, T_OIL, supply=sup)
    assert dry.drag is None and wet.drag is not None
    # measured: CSR 0.1972 -> 0.1674 (cage slip 0.545 -> 0.614)
    assert wet.cage_speed_ratio < dry.cage_speed_ratio - 0.01
    # the cage holds against the oil: its pocket terms balance the churning moment
    d_m = nu214.pitch_diameter
    cage_terms = wet.pocket_normal_force - (nu214.roller_diameter / d_m) * wet.pocket_friction
    m_cage = wet.drag["cage_churning_moment"] + wet.drag["cage_guide_moment"]
    assert m_cage < 0.0
    assert float(np.sum(cage_terms)) == pytest.approx(-m_cage / (0.5 * d_m), rel=1e-6)


def test_paper000_direct_solve_is_unchanged(nu214, oil):
    """Validation runners call ``solve_roller`` directly: no supply, no drag, the state of
    before (the nu214_skidding regression reference at 150 N, 5000 r/min, 40 degC:
    CSR 0.19720411455336789)."""
    res = solve_roller(nu214, oil, OMEGA, 150.0, 0.0, T_OIL)
    assert res.drag is None and "solver_drag" not in res.kinematic_state.extras
    assert res.cage_speed_ratio == pytest.approx(0.19720411455336789, rel=1e-9)
    assert set(res.booked_power()) == {"raceway_traction", "ehl_rolling_resistance",
                                       "pocket_friction", "total"}
    same = skidding.solve(nu214, oil, OMEGA, 150.0, 0.0, T_OIL)
    assert same.cage_speed_ratio == res.cage_speed_ratio


def test_roller_drag_by_hand(nu214, oil):
    """Paper 002 eq. 10 on one roller: F = c_d rho_e u^2 A / 2, c_d = 1, A = D l,
    u = omega_c d_m / 2, rho_e = X rho with Parker's X[%] = 1.46e7 Q^0.37 / (n d_m^1.7)
    (Q = 1000 cm^3/min, n = 5000 r/min, d_m = 97.5 mm)."""
    sup = OilSupply("jet", 1e-3 / 60.0, T_OIL)
    res = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup)
    x = 1.46e7 * 1000.0 ** 0.37 / (5000.0 * 97.5 ** 1.7) / 100.0
    assert res.drag["element_oil_fraction"] == pytest.approx(x, rel=1e-12)
    rho = float(oil.density(T_OIL))
    u = res.cage_speed * 0.0975 / 2.0
    force = 0.5 * 1.0 * x * rho * u ** 2 * (0.013 * 0.013)
    assert -res.drag["element_force"] == pytest.approx(force, rel=1e-12)
    # 18 rollers at the pitch speed: the churning_elements heat of the state
    ctx = HeatContext.isothermal(
        T_OIL, bearing=nu214, lubricant=oil, supply=sup,
        operating=OperatingPoint(inner_speed=OMEGA, radial_load=1000.0),
        kinematics=res.kinematic_state, traction=default_traction_law(oil))
    heat = evaluate(["churning_elements"], ctx)[0]
    assert heat.total == pytest.approx(18 * force * u, rel=1e-12)
    # options beyond where the heat goes ask for the source's own model on purpose, said
    with pytest.warns(ValidityWarning, match="not the drag the roller skidding solver"):
        own = evaluate(["churning_elements"], HeatContext.isothermal(
            T_OIL, bearing=nu214, lubricant=oil, supply=sup,
            operating=OperatingPoint(inner_speed=OMEGA, radial_load=1000.0),
            kinematics=res.kinematic_state, traction=default_traction_law(oil),
            options={"churning_elements": {"drag_coefficient": 0.5}}))[0]
    assert own.total == pytest.approx(0.5 * heat.total, rel=1e-12)


def test_roller_drag_parameters_and_bad_input(nu214, oil):
    sup = OilSupply("jet", 1e-3 / 60.0, T_OIL)
    base = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup)
    half = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup,
                          params={"drag_coefficient": 0.5})
    assert half.drag["drag_coefficient"] == 0.5
    assert half.cage_speed_ratio > base.cage_speed_ratio  # less drag, faster cage
    with pytest.raises(InputError, match="params"):
        skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup,
                       params={"oil_fraction": 0.1})
    with pytest.raises(InputError, match="drag_coefficient"):
        skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup,
                       params={"drag_coefficient": -1.0})
    with pytest.raises(InputError, match="drag"):
        solve_roller(nu214, oil, OMEGA, 1000.0, drag="churning")


def test_grease_fill_has_no_churning_drag(nu214, oil):
    sup = OilSupply("grease", 0.0, T_OIL)
    res = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL, supply=sup)
    dry = skidding.solve(nu214, oil, OMEGA, 1000.0, 0.0, T_OIL)
    assert res.drag["element_force"] == 0.0 and res.drag["inner_ring_moment"] == 0.0
    assert res.cage_speed_ratio == pytest.approx(dry.cage_speed_ratio, rel=1e-9)
