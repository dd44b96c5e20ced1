"""Fixes of defects the user tours reported: a run or check names an inlet or initial
temperature outside the oil's property data (a sweep did; a single run was silent); the
chunk model's linearisation across a heat source's regime jump."""

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


def _linear(fn):
    """Coupler.linearize on one bearing whose heat on node 0 is fn(T0) [W]."""
    from types import SimpleNamespace

    import numpy as np

    from thermobearing.coupled import Coupler

    class OneNode(Coupler):
        def __init__(self):  # no simulation: the heat is fn
            self.sim = SimpleNamespace(bearings=[SimpleNamespace(name="b")])
            self.role_nodes = {"b": {"oil": [0]}}

        def _bearing_heat(self, b, step, T, kin=None):
            return np.array([fn(float(T[0])), 0.0]), frozenset({"oil"})

    return OneNode().linearize(None, np.array([300.0, 300.0]))


def test_the_chunk_model_keeps_the_curvature_of_a_smooth_heat():
    import pytest

    lin = _linear(lambda t: 100.0 - 2.0 * (t - 300.0) + 0.1 * (t - 300.0) ** 2)
    assert lin.J[0, 0] == pytest.approx(-2.0, rel=1e-9)
    assert lin.H[0, 0] == pytest.approx(0.2, rel=1e-6)


def test_the_chunk_model_does_not_extrapolate_a_jump_as_curvature():
    """A source switching regime within +-dT (paper 002's inner-ring churning, +26 W within
    0.4 K): the central differences read the jump as a slope of 26 W/K and a curvature of
    104 W/K^2, which the chunk model extrapolated to kilowatts a few kelvin away. The
    column takes the one-sided slope of the smaller magnitude and no curvature."""
    import numpy as np
    import pytest

    lin = _linear(lambda t: 100.0 - 2.0 * (t - 300.0) + (26.0 if t > 300.2 else 0.0))
    assert lin.J[0, 0] == pytest.approx(-2.0, rel=1e-9)
    assert not lin.H.any()
    far = lin.heat(0.0, np.array([313.0, 300.0]))[0]
    assert far == pytest.approx(100.0 - 26.0, rel=1e-9)   # true value 100 - 26 + 26 = 100
