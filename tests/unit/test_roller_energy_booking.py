"""Energy bookkeeping of cylindrical roller bearings: the heat sources book the forces the
roller skidding solver balanced (paper 000, seed 000_3b5ca6eed61dd596.txt).

The roller solver's shaft power omega T = omega (d_m - D)/2 sum_j (C_ij + Q_xij/2) equals
its film dissipation sum C V (eq. 5 Couette term, eqs. 33-34) + sum Q_x |u_e| (eq. 5
Poiseuille term, Q_x of eq. 35) + sum f_d omega_r D/2 (pocket film, eqs. 37-38): the roller
moment balances (eqs. 28/31) and the cage equation (eq. 32) make the sum telescope. The heat
sources ``raceway_traction``, ``ehl_rolling_resistance`` and ``pocket_friction`` must book
exactly these products. Before: ``raceway_traction`` re-integrated the traction law over the
Hertz zone and left the solver's Newtonian inlet/outlet shear out, and ``pocket_friction``
booked a boundary mu = 0.1 times F_d instead of the pocket film's f_d (NU 214, ISO VG 46 at
320 K, jet: 5000 r/min, 200 N booked 221.2 of 272.0 W; 3000 r/min, 8 kN 482.7 of 513.6 W).
A scene's solve (with the oil supply) also balances the oil drags of paper 002 and the
``churning_*`` and ``cage_guide`` sources book them (tests/unit/test_roller_drag_balance.py).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scene_parts import VG46_2LPM, scene_title

from tests.unit.scene_step_heat import first_step_heat
from thermobearing.heat_sources import HeatContext, evaluate
from thermobearing.skidding.roller import default_traction_law, solve_roller
from thermobearing.state import OilSupply, OperatingPoint

BALANCED = ("raceway_traction", "ehl_rolling_resistance", "pocket_friction")
#: the oil drags the solver balances when a scene gives it the supply (skidding.roller_drag)
DRAGS = ("churning_elements", "churning_cage", "churning_inner_ring", "cage_guide")
TEMPS = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 320.0)

SCENE = scene_title("NU 214 energy booking") + """[[bearings]]
name = "de"
preset = "NU214"
""" + VG46_2LPM + """[schedule]
speed = "{speed}"
radial_load = "{load}"
axial_load = "0 kN"
[models]
kinematics = "skidding"
[outputs]
mode = "steady"
want = ["losses"]
"""


def _scene_state(speed: str, load: str):
    return first_step_heat(SCENE.format(speed=speed, load=load), TEMPS)


@pytest.mark.parametrize("speed, load, skids", [
    ("5000 rpm", "200 N", True),     # light load: cage slip 0.39
    ("3000 rpm", "8 kN", False),     # heavy load: rolling (slip < 1e-4)
])
def test_scene_sources_book_the_roller_solver_shaft_power(speed, load, skids):
    kin, step, by_source = _scene_state(speed, load)
    res = kin.raw
    assert res.converged
    assert (res.slip > 0.1) is skids
    shaft = res.shaft_torque * step.speed
    booked = sum(by_source[s] for s in BALANCED + DRAGS)
    assert booked == pytest.approx(shaft, abs=_residual_power(res, step.speed))
    # source by source the solver's own products (RollerSkiddingResult.booked_power),
    # the oil drags included: the scene's solver balances them
    expected = res.booked_power()
    for name in BALANCED + DRAGS:
        assert by_source[name] == pytest.approx(expected[name], rel=1e-12, abs=1e-12)
    assert expected["total"] == pytest.approx(shaft, abs=_residual_power(res, step.speed))
    assert by_source["churning_elements"] > 0.0 and by_source["churning_inner_ring"] > 0.0
    # only rib friction (none on the NU 214 preset's state) comes on top of the shaft power
    assert sum(by_source.values()) == pytest.approx(
        booked + by_source.get("rib_friction", 0.0), rel=1e-12)


def _residual_power(res, speed: float) -> float:
    """Bound on |dissipation - shaft power| [W] of a state solved to a finite residual: the
    power of the residual forces (roller equations [N] at the roller surface speed, the cage
    equation at the pitch speed), doubled, plus round-off. The scene solves to tol 1e-9
    (NU 214 at 3000 r/min, 8 kN: 1.9e-5 W of 514 W, 3.7e-8 relative)."""
    z = res.roller_speed.size
    d = res.extras["roller_diameter"]
    d_m = d + 2.0 * res.extras["raceway_radius_inner"]
    bound = (float(np.sum(np.abs(res.residual[:z] * 0.5 * d * res.roller_speed)))
             + abs(float(res.residual[z])) * 0.5 * d_m * abs(res.cage_speed))
    return 2.0 * bound + 1e-12 * abs(res.shaft_torque * speed)


def _context(bearing, oil, state, speed, load, options=None):
    return HeatContext.isothermal(
        313.15, bearing=bearing, lubricant=oil, supply=OilSupply("jet", 1e-5, 313.15),
        operating=OperatingPoint(inner_speed=speed, radial_load=load), kinematics=state,
        traction=default_traction_law(oil), options=options or {})


def _check_identity(bearing, oil, res, speed, load):
    results = evaluate(BALANCED, _context(bearing, oil, res.kinematic_state, speed, load))
    heat = sum(r.total for r in results)
    # every watt is a force times a relative sliding speed
    assert sum(p.power for r in results for p in r.force_pairs) == pytest.approx(heat,
                                                                                 rel=1e-12)
    assert heat == pytest.approx(res.shaft_torque * speed, rel=1e-9)
    return {r.source: r.total for r in results}


OMEGA = 5000.0 * math.pi / 30.0
PAPER000 = dict(ring_support="films", film_pressure="regime_min", pocket_film="two_faces",
                limiting_shear_coefficient=1.0)


@pytest.mark.parametrize("options", [
    {},
    {"clearance_film": True},  # unloaded rollers driven across the gap (inner load 0)
    PAPER000,                  # the validation case's model (film-supported ring)
], ids=["default", "clearance_film", "paper000_case"])
def test_api_states_book_the_shaft_power(nu214, oil, options):
    res = solve_roller(nu214, oil, OMEGA, 150.0, 0.0, 313.15, tol=1e-12, **options)
    assert res.converged
    booked = _check_identity(nu214, oil, res, OMEGA, 150.0)
    assert booked["raceway_traction"] > 0 and booked["pocket_friction"] > 0
    if options.get("clearance_film"):
        free = res.inner_load == 0.0
        assert np.any(free) and np.all(res.inner.traction[free] > 0.0)


def test_whirl_samples_book_their_shaft_power(nu214, oil):
    """Paper 000 Tables 2-3 conditions (e = 6e-5 m, synchronous whirl, 200 N): the whirl
    inertia of evenly spaced rollers does no net work (sum_j a_t,j = 0), so every quasi-static
    sample books its own shaft power."""
    from thermobearing.skidding.whirl import Whirl

    w = solve_roller(nu214, oil, OMEGA, 200.0, 0.0, 313.15, tol=1e-12,
                     whirl=Whirl(6.0e-5, n_samples=4), **PAPER000)
    assert w.converged
    for state in w.states:
        _check_identity(nu214, oil, state, OMEGA, 200.0)


def test_raceway_traction_books_the_inlet_outlet_shear(nu214, oil):
    """The solver's Couette force has a Hertz-zone part (the traction law) and a Newtonian
    inlet/outlet part (paper 000 eq. 5 outside the Hertz zone); the law's integral over the
    Hertz zone alone (the state without the solver's forces) misses the second."""
    res = solve_roller(nu214, oil, OMEGA, 150.0, 0.0, 313.15, tol=1e-12)
    state = res.kinematic_state
    new = evaluate(["raceway_traction"], _context(nu214, oil, state, OMEGA, 150.0))[0]
    stripped = dataclasses.replace(state, contacts=tuple(cs.with_() for cs in state.contacts))
    law_only = evaluate(["raceway_traction"],
                        _context(nu214, oil, stripped, OMEGA, 150.0))[0]
    for race, f, v in (("inner", res.inner, res.inner_sliding_speed),
                       ("outer", res.outer, res.outer_sliding_speed)):
        total = float(np.sum(f.traction * v))
        hertz = float(np.sum(f.hertz_traction * v))
        assert new.components[f"{race} contact"] == pytest.approx(total, rel=1e-12)
        # the same Hertz-zone shear by the law's own quadrature (16 x 8 nodes, against the
        # solver's 24 Gauss nodes: 0.85 % apart at the inner race here)
        assert law_only.components[f"{race} contact"] == pytest.approx(hertz, rel=2e-2)
        assert total - hertz > 0.1 * total  # the inlet/outlet shear is not small here


def test_pocket_books_the_film_friction_unless_a_coefficient_is_asked_for(nu214, oil):
    res = solve_roller(nu214, oil, OMEGA, 150.0, 0.0, 313.15, tol=1e-12)
    state = res.kinematic_state
    d = nu214.roller_diameter
    film = evaluate(["pocket_friction"], _context(nu214, oil, state, OMEGA, 150.0))[0]
    assert film.total == pytest.approx(
        float(np.sum(np.abs(res.pocket_friction) * np.abs(res.roller_speed) * 0.5 * d)),
        rel=1e-12)
    assert film.details["regime"].startswith("solver pocket film")
    # paper 002 eq. 19 with a friction coefficient, on request (no longer the solver's force)
    mu = evaluate(["pocket_friction"], _context(
        nu214, oil, state, OMEGA, 150.0,
        options={"pocket_friction": {"friction_coefficient": 0.05}}))[0]
    assert mu.total == pytest.approx(float(np.sum(
        0.05 * np.abs(res.pocket_normal_force) * np.abs(res.roller_speed) * 0.5 * d)),
        rel=1e-12)


def test_rolling_resistance_books_the_solver_force_unless_a_model_is_asked_for(nu214,
                                                                                oil):
    """The carried Q_x is the solver's (starved by the inlet oil layer here: smaller than
    the flooded formula); naming a model recomputes the flooded force on purpose."""
    res = solve_roller(nu214, oil, OMEGA, 2000.0, 0.0, 313.15, tol=1e-12,
                       oil_layer=2.0e-6)
    state = res.kinematic_state
    carried = evaluate(["ehl_rolling_resistance"],
                       _context(nu214, oil, state, OMEGA, 2000.0))[0]
    expected = sum(float(np.sum(f.rolling_force * np.abs(ue))) for f, ue in (
        (res.inner, res.inner_entrainment_speed), (res.outer, res.outer_entrainment_speed)))
    assert carried.total == pytest.approx(expected, rel=1e-12)
    flooded = evaluate(["ehl_rolling_resistance"], _context(
        nu214, oil, state, OMEGA, 2000.0,
        options={"ehl_rolling_resistance": {"rolling_force": "regime_min"}}))[0]
    assert flooded.total > carried.total
    _check_identity(nu214, oil, res, OMEGA, 2000.0)
