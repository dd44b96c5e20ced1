"""Scene fuzzing (session 17): two settings that changed nothing or the wrong thing without
a word. A grease supply with a flow (``flow = "5 L/min"``) gave the network an oil stream
through the bearing: an SKF 6304 at 3000 r/min settled at 21 degC instead of 42 degC with
no flow. ``ball_rolling_resistance`` on a scene without ball bearings changed nothing.
Both are refused naming the field. A grease supply's inlet temperature (no stream enters)
is noted as unused."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.state import OilSupply

SCENE = """
title = "settings without effect"

[[bearings]]
name = "a"
preset = "{preset}"

[lubricant]
preset = "ISO_VG68"

[supply]
{supply}

[schedule]
steps = [{{ duration = "1 min", speed = "3000 rpm", radial_load = "1 kN", axial_load = "0 N" }}]

[models]
kinematics = "race_control"
{models}

[outputs]
mode = "steady"
want = ["film"]
"""


def _text(preset="SKF6304", supply='method = "grease"', models=""):
    return SCENE.format(preset=preset, supply=supply, models=models)


def test_grease_with_a_flow_is_refused():
    with pytest.raises(InputError, match=r"supply.flow = '5 L/min'.*grease fill"):
        loads_scene(_text(supply='method = "grease"\nflow = "5 L/min"'))
    assert loads_scene(_text(supply='method = "grease"\nflow = "0 L/min"')).supply.flow == 0.0
    assert loads_scene(_text()).supply.flow == 0.0
    with pytest.raises(InputError, match="supply.flow_rate"):
        OilSupply("grease", 1e-5, 308.15)
    assert OilSupply("grease", 0.0, 308.15).flow_rate == 0.0


def test_ball_rolling_resistance_needs_a_ball_bearing():
    scene = loads_scene(_text(preset="NU214", supply='method = "jet"\nflow = "1 L/min"',
                              models='ball_rolling_resistance = "harris"'))
    with pytest.raises(InputError, match="models.ball_rolling_resistance = 'harris'.*without "
                                         "ball bearings"):
        Simulation(scene, progress=False)
    ball = loads_scene(_text(supply='method = "jet"\nflow = "1 L/min"',
                             models='ball_rolling_resistance = "harris"'))
    Simulation(ball, progress=False)  # a ball bearing: accepted


def test_grease_inlet_temperature_is_noted_as_unused():
    scene = loads_scene(_text(supply='method = "grease"\ninlet_temperature = "80 degC"'))
    notes = [n for n in Simulation(scene, progress=False).notes
             if n.startswith("supply.inlet_temperature (80 degC) is not used")]
    assert len(notes) == 1 and "grease fill has no inlet" in notes[0]
    plain = Simulation(loads_scene(_text()), progress=False)
    assert not any(n.startswith("supply.inlet_temperature") for n in plain.notes)
