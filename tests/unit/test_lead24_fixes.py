"""Lead fixes of session 24 reported by the user tours: a run or check names an inlet or
initial temperature outside the oil's property data (a sweep did; a single run was silent)."""

from __future__ import annotations

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "NU 214, hot inlet"
[[bearings]]
name = "nu"
preset = "NU214"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "{inlet}"
[environment]
ambient_temperature = "35 degC"
{initial}
[schedule]
speed = "2000 rpm"
radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{{}}]
[outputs]
want = ["losses"]
"""


def _notes(inlet: str, initial: str = "") -> list[str]:
    scene = loads_scene(SCENE.format(inlet=inlet, initial=initial))
    return [n for n in Simulation(scene, progress=False).notes if "property data" in n]


def test_an_inlet_outside_the_oils_data_is_named():
    (note,) = _notes("200 degC")
    assert note.startswith("supply.inlet_temperature = 200 degC is outside the temperatures "
                           "ISO_VG46's property data cover, 0 to 146 degC")
    assert _notes("60 degC") == []


def test_an_initial_temperature_outside_the_oils_data_is_named():
    (note,) = _notes("60 degC", 'initial_temperature = "-10 degC"')
    assert note.startswith("environment.initial_temperature = -10 degC is outside")
