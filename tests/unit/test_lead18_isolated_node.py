"""A network node cut off from every fixed temperature by the scene's parameters is refused
naming the template, the [network] parameters it was built from and those set to 0 (it
named only the node, no scene field; scene fuzzing)."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "isolated"
[[bearings]]
name = "a"
preset = "QJ1044"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "5 L/min"
inlet_temperature = "35 degC"
[models]
kinematics = "none"
heat_sources = ["global_friction"]
[schedule]
steps = [{ duration = "1 min", speed = "1800 rpm", radial_load = "1 kN", axial_load = "10 kN" }]
[outputs]
want = ["temperatures"]
[network]
template = "four_node_paper002"
[network.parameters]
housing_outer_diameter = "510 mm"
housing_length = "140 mm"
shaft_diameter = "220 mm"
shaft_length = "500 mm"
h_air = "0 W/(m**2*K)"
h_oil = "0 W/(m**2*K)"
"""


def test_isolated_node_names_the_settings_that_built_it():
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(SCENE), progress=False).run()
    text = str(info.value)
    assert "template 'four_node_paper002'" in text and "a.balls" in text
    assert "set to 0: h_air, h_oil" in text
