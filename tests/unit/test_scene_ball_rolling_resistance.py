"""`[models] ball_rolling_resistance`: the ball solver's opt-in EHL rolling force from a scene.

The option puts the point-contact rolling force (thermobearing.rolling_resistance) into the
ball skidding balance and adds the ``ehl_rolling_resistance`` source that books its heat,
so the scene's heat sources still add up to the solver's shaft power (issue 5's energy
identity). Bad values are refused naming the field.
"""

from __future__ import annotations

import pytest
from scene_parts import PAPER002_OIL, QJ1044_DE, scene_title

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = scene_title("QJ1044 with EHL rolling resistance") + QJ1044_DE + PAPER002_OIL + """\
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "4 kN"
[models]
kinematics = "skidding"
{extra}
[outputs]
mode = "steady"
want = ["losses"]
"""

TEMPS = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 320.0)


def _sim(extra: str) -> Simulation:
    return Simulation(loads_scene(SCENE.format(extra=extra)), progress=False)


def _state(sim: Simulation):
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    kin = sim.solve_kinematics(b, 0, step, TEMPS)
    return b, step, kin


@pytest.mark.parametrize("extra", [
    'ball_rolling_resistance = "harris"',
    'ball_rolling_resistance = { model = "harris", reduction = "thermal_starvation" }',
])
def test_scene_option_books_the_rolling_force_and_closes_the_energy_identity(extra):
    sim = _sim(extra)
    b, step, kin = _state(sim)
    assert "ehl_rolling_resistance" in b.sources
    params = b.kin_options["params"]
    assert params.rolling_resistance == "harris"
    ev = sim.evaluate_heat(b, step, kin, TEMPS, with_rows=True)
    shaft_power = kin.raw.shaft_torque * step.speed
    assert sum(ev.by_role.values()) == pytest.approx(shaft_power, rel=1e-8)
    rolling = sum(r["power [W]"] for r in ev.rows if r["source"] == "ehl_rolling_resistance")
    assert rolling > 0.0
    # the reduced force is smaller than the isothermal, fully flooded one
    if "thermal_starvation" in extra:
        full = _sim('ball_rolling_resistance = "harris"')
        fb, fstep, fkin = _state(full)
        fev = full.evaluate_heat(fb, fstep, fkin, TEMPS, with_rows=True)
        full_rolling = sum(r["power [W]"] for r in fev.rows
                           if r["source"] == "ehl_rolling_resistance")
        assert rolling < full_rolling


def test_default_scene_has_no_ball_rolling_resistance():
    b, _, _ = _state(_sim(""))
    assert "ehl_rolling_resistance" not in b.sources
    assert b.kin_options["params"].rolling_resistance == "none"


@pytest.mark.parametrize("extra, field", [
    ('ball_rolling_resistance = "houpert"', "models.ball_rolling_resistance"),
    ('ball_rolling_resistance = { model = "harris", reduction = "cold" }',
     "models.ball_rolling_resistance.reduction"),
    ('ball_rolling_resistance = { model = "harris", factor = 2 }',
     "models.ball_rolling_resistance.factor"),
    ('ball_rolling_resistance = 3', "models.ball_rolling_resistance"),
    ('ball_rolling_resistance = "harris"\nheat_sources = ["raceway_traction", '
     '"churning_elements", "cage_guide", "pocket_friction"]', "models.heat_sources"),
])
def test_bad_ball_rolling_resistance_is_refused_naming_the_field(extra, field):
    with pytest.raises(InputError) as err:
        _sim(extra)
    assert field in str(err.value)


def test_scene_with_the_option_round_trips_through_toml():
    sc = loads_scene(SCENE.format(
        extra='ball_rolling_resistance = { model = "harris", reduction = "thermal" }'))
    again = loads_scene(sc.to_toml())
    assert again.models["ball_rolling_resistance"] == {"model": "harris",
                                                       "reduction": "thermal"}
