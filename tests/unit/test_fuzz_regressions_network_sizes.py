"""Network template parameters found by fuzzing (session 18): a length far beyond any
machine (``housing_outer_diameter = "1e308 m"``, from mutated scenes) stopped with
``OverflowError: Numerical result out of range`` in the housing volume; a length whose
cube is no finite number is refused naming the scene parameter. ``h_oil = 0`` in the
seven-node template is refused naming h_oil (the network check named node 'a.cage')."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG32_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.network.templates import _check_dims
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = 'title = "size"\n' + SKF6304_A + VG32_JET_1LPM + """[schedule]
speed = "1500 rpm"
radial_load = "1 kN"
axial_load = "0 N"
step_duration = "1 min"
[network]
template = "{template}"
parameters = {{ housing_outer_diameter = "1e308 m", housing_length = "30 mm" }}
[outputs]
mode = "transient"
want = ["temperatures"]
"""


@pytest.mark.parametrize("template", ["seven_node", "four_node_paper002"])
def test_huge_housing_is_refused_naming_the_parameter(template):
    sim = Simulation(loads_scene(SCENE.format(template=template)), progress=False)
    with pytest.raises(InputError, match=r"network.parameters.housing_outer_diameter = "
                                         r"'1e308 m'.*cube"):
        sim.run()


def test_ordinary_sizes_pass():
    _check_dims(housing_outer_diameter=0.3, housing_length=1e3, shaft_length=None)


def test_seven_node_without_oil_convection_names_h_oil():
    """h_oil = 0 in the seven-node template left the cage node without an edge and the
    network check named node 'a.cage' (no scene field); the four-node template has no cage
    node and runs."""
    text = SCENE.format(template="seven_node").replace(
        'housing_outer_diameter = "1e308 m"',
        'housing_outer_diameter = "100 mm", h_oil = "0 W/(m**2*K)"')
    sim = Simulation(loads_scene(text), progress=False)
    with pytest.raises(InputError, match=r"network.parameters.h_oil = '0 W/\(m\*\*2\*K\)'.*"
                                         r"cage exchanges heat only with the oil"):
        sim.run()
    four = text.replace('template = "seven_node"', 'template = "four_node_paper002"')
    assert "temperatures" in Simulation(loads_scene(four), progress=False).run().tables
