"""A network node cut off from every fixed temperature by the scene's parameters is refused
naming the template, the [network] parameters it was built from and those set to 0 (it
named only the node, no scene field; scene fuzzing)."""

from __future__ import annotations

import pytest
from scene_parts import GLOBAL_FRICTION_ONLY, QJ1044_A, VG46_JET_5LPM, scene_title

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = scene_title("isolated") + QJ1044_A + VG46_JET_5LPM + GLOBAL_FRICTION_ONLY + """\
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
