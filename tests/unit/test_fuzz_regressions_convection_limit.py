"""A convection coefficient far beyond any convection, found while fuzzing ``thermobearing
calibrate`` (session 18): ``--x0 network.parameters.h_oil=1e300`` stopped on a singular
stepper matrix reported as "did not converge (residual inf)". The coefficient is refused,
naming the scene parameter, above 1e6 W/(m^2 K) (ten times the top of Incropera et al.
2007 Table 1.1, boiling and condensation)."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG32_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.network.conductances import H_CONVECTION_MAX, Convection
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = 'title = "h"\n' + SKF6304_A + VG32_JET_1LPM + """inlet_temperature = "35 degC"
[schedule]
speed = "1500 rpm"
radial_load = "1 kN"
axial_load = "0 N"
step_duration = "10 s"
[network]
template = "seven_node"
parameters = {{ housing_outer_diameter = "100 mm", housing_length = "30 mm", h_oil = "{h}" }}
[outputs]
mode = "transient"
want = ["temperatures"]
"""


def test_convection_above_the_limit_is_refused():
    assert Convection(H_CONVECTION_MAX, 1.0).conductance(300.0, 300.0) == H_CONVECTION_MAX
    with pytest.raises(InputError, match=r"convection.h = 1e\+300 .*<= 1e\+06"):
        Convection(1e300, 1.0)


def test_scene_names_its_parameter():
    sim = Simulation(loads_scene(SCENE.format(h="1e300 W/(m**2*K)")), progress=False)
    with pytest.raises(InputError, match=r"convection.h = 1e\+300.*set by \[network\] "
                                         r"parameters.*h_oil"):
        sim.run()
