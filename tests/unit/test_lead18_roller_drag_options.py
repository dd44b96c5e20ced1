"""A roller scene's churning / cage-guide options and the roller skidding solver's drag.

The solver balances the oil drag those sources book (``skidding.roller_drag``), so
``[models] heat_source_options`` that set the drag model are handed to the solver
(``churning_elements.drag_coefficient``, the churning sources' ``parker_constant``): the
shaft power still equals the booked heat. Options of a source's own model that the solver
does not take (a ``form``, an ``oil_fraction``, the guide's ``friction_coefficient``) are
refused when the scene is built, as the ball bearings' clashing options are; they were
evaluated with a ValidityWarning and a heat the shaft torque did not hold."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SOURCES = ["raceway_traction", "ehl_rolling_resistance", "churning_elements",
           "churning_cage", "churning_inner_ring", "cage_guide", "pocket_friction"]
T = 313.15
TEMPS = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), T)

SCENE = """
title = "NU 214 drag options"
[[bearings]]
name = "nu214"
preset = "NU214"
[lubricant]
preset = "PAPER000_OIL"
[supply]
method = "jet"
flow = "1 L/min"
inlet_temperature = "40 degC"
[schedule]
speed = "5000 rpm"
radial_load = "150 N"
axial_load = "0 kN"
[models]
kinematics = "skidding"
heat_sources = [{sources}]
{options}
[outputs]
mode = "steady"
want = ["losses"]
"""


def _sim(options: str = "") -> Simulation:
    text = SCENE.format(sources=", ".join(f'"{s}"' for s in SOURCES), options=options)
    return Simulation(loads_scene(text), progress=False)


def _solve(sim: Simulation):
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    kin = sim.solve_kinematics(b, 0, step, TEMPS)
    ev = sim.evaluate_heat(b, step, kin, TEMPS, with_rows=True)
    heat = sum(r["power [W]"] for r in ev.rows)
    return kin.raw, step.speed, heat


def test_drag_options_reach_the_solver_and_the_balance_holds():
    base_raw, _, _ = _solve(_sim())
    opts = ('heat_source_options = { churning_elements = { drag_coefficient = 2.0, '
            'parker_constant = 2.0e7 }, churning_cage = { parker_constant = 2.0e7 } }')
    sim = _sim(opts)
    assert sim.bearings[0].kin_options["params"] == {"drag_coefficient": 2.0,
                                                     "parker_constant": 2.0e7}
    raw, speed, heat = _solve(sim)
    power = raw.shaft_torque * speed
    assert heat == pytest.approx(power, rel=1e-8)
    # twice the roller drag and more oil: the cage lags further at 150 N
    assert raw.cage_speed_ratio < base_raw.cage_speed_ratio
    drag = raw.kinematic_state.extras["solver_drag"]
    assert drag["drag_coefficient"] == 2.0 and drag["parker_constant"] == 2.0e7
    assert math.isfinite(power) and power > 0.0


@pytest.mark.parametrize(("options", "field"), [
    ('heat_source_options = { churning_elements = { oil_fraction = 0.1 } }',
     "models.heat_source_options.churning_elements.oil_fraction"),
    ('heat_source_options = { churning_cage = { gap = "1 mm" } }',
     "models.heat_source_options.churning_cage.gap"),
    ('heat_source_options = { cage_guide = { boundary_friction = 0.2 } }',
     "models.heat_source_options.cage_guide.boundary_friction"),
    ('heat_source_options = { churning_cage = { parker_constant = 2e7 }, '
     'churning_inner_ring = { parker_constant = 3e7 } }',
     "models.heat_source_options.churning_inner_ring.parker_constant"),
])
def test_own_model_options_are_refused_at_build(options, field):
    with pytest.raises(InputError) as info:
        _sim(options)
    assert info.value.field == field
    assert "roller skidding solver" in str(info.value)


def test_booking_options_are_kept():
    sim = _sim('heat_source_options = { cage_guide = { cage_share = 0.5 } }')
    raw, speed, heat = _solve(sim)
    assert heat == pytest.approx(raw.shaft_torque * speed, rel=1e-8)


BALL = SCENE.replace('preset = "NU214"', 'preset = "SKF6304"').replace(
    'preset = "PAPER000_OIL"', 'preset = "ISO_VG68"')


def test_a_parker_constant_the_ball_kinematics_would_not_use_is_refused():
    """The ball kinematics set the churning sources' oil fraction themselves (from the
    bearing's calibration): a Parker constant in heat_source_options went unused."""
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(BALL.format(
            sources='"churning_cage"',
            options='heat_source_options = { churning_cage = { parker_constant = 2e7 } }')),
            progress=False)
    assert info.value.field == "models.heat_source_options.churning_cage.parker_constant"


def test_cage_guide_friction_coefficient_is_refused_at_build_for_any_bearing():
    """Scene fuzzing (seeds 50/51): a race-control CRB scene with cage_guide
    friction_coefficient stopped mid-run naming options[cage_guide], no scene key."""
    text = SCENE.format(sources=", ".join(f'"{s}"' for s in SOURCES),
                        options='heat_source_options = { cage_guide = '
                                '{ friction_coefficient = 0.1603 } }').replace(
        'kinematics = "skidding"', 'kinematics = "race_control"')
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(text), progress=False)
    assert info.value.field == "models.heat_source_options.cage_guide.friction_coefficient"


def test_drag_sources_left_out_are_noted():
    """The skidding solver balances the oil drag whatever the scene books: a scene that
    lists only some of its sources is told that the booked heat falls short of the shaft
    power by the rest."""
    text = SCENE.format(sources='"raceway_traction", "ehl_rolling_resistance", '
                                '"churning_elements", "pocket_friction"', options="")
    sim = Simulation(loads_scene(text), progress=False)
    (note,) = [w for w in sim.warnings if "balances the oil drag" in w]
    assert "churning_cage, churning_inner_ring" in note
    assert _sim().warnings == [w for w in _sim().warnings if "balances the oil drag" not in w]
