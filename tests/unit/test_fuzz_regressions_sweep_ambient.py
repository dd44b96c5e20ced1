"""A sweep of the ambient temperature of a scene without a thermal network, found by the
scene fuzzer (scripts/fuzz_scenes.py seed 51, case 17: QJ1044 + CRB_50x75x16, jet, outputs
kinematics and losses): the cases gave identical rows in all 19 result columns and the
sweep said nothing. The operating points of such a run are taken at the initial temperature
the scene gives, or at a fed supply's inlet; the sweep now says the ambient is not used,
and still sweeps it silently where it is used (the initial temperature left to its
default, the ambient)."""

from __future__ import annotations

from thermobearing.scene import loads_scene
from thermobearing.sweep import check_cases
from thermobearing.sweep_cases import expand
from thermobearing.sweep_params import parse_set

SCENE = """title = "ambient"
[[bearings]]
name = "a"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG32"
[supply]
method = "jet"
flow = "0.36 L/min"
{inlet}
[environment]
ambient_temperature = "38.37 degC"
{initial}
[schedule]
speed = "6000 rpm"
radial_load = "3.9 kN"
axial_load = "0.6 kN"
[outputs]
mode = "steady"
want = {want}
"""


def _notes(inlet: str = "", initial: str = "", want: str = '["kinematics", "losses"]'):
    scene = loads_scene(SCENE.format(inlet=inlet, initial=initial, want=want))
    d = scene.to_dict()
    cases = expand(scene, [parse_set("environment.ambient_temperature=38.37,53.37", d)])
    return check_cases(cases)


def test_ambient_of_a_jet_scene_taken_at_its_inlet_is_unused():
    (note,) = _notes(inlet='inlet_temperature = "0.47 degC"')
    assert note.startswith("sweep: environment.ambient_temperature is swept but not used")
    assert "taken at supply.inlet_temperature (0.47 degC)" in note


def test_ambient_of_a_scene_with_an_initial_temperature_is_unused():
    (note,) = _notes(initial='initial_temperature = "60 degC"')
    assert "taken at environment.initial_temperature (60 degC)" in note


def test_ambient_is_used_as_the_default_initial_or_by_the_network():
    assert _notes() == []  # no inlet, no initial: the operating point is at the ambient
    net = ('["temperatures"]\n[network]\ntemplate = "seven_node"\nparameters = { '
           'housing_outer_diameter = "100 mm", housing_length = "30 mm" }')
    assert _notes(inlet='inlet_temperature = "0.47 degC"', want=net) == []
