"""A network template length far beyond any machine, found by mutating fuzzed scenes
(session 18): ``housing_outer_diameter = "1e308 m"`` stopped with ``OverflowError:
Numerical result out of range`` in the housing volume. A length whose cube is no finite
number is refused naming the scene parameter."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.network.templates import _check_dims
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """title = "size"
[[bearings]]
name = "a"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG32"
[supply]
method = "jet"
flow = "1 L/min"
[schedule]
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
