"""A negative ``load_share.axial`` (a reversed thrust, README) on several bearings of one
scene (found by the scene fuzzer): the run stopped at the first solve with
``operating.axial_load = -2302.95 is not allowed``, naming no scene field. Deep-groove and
four-point bearings now take the thrust's magnitude (their models are symmetric) and the
tables keep its sign; an angular-contact bearing refuses it before the run, naming the share."""

from __future__ import annotations

import pytest
from scene_parts import VG46_JET_2LPM

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "reversed thrust"
[[bearings]]
name = "a"
preset = "{a}"
[[bearings]]
name = "b"
preset = "{b}"
load_share = {{ radial = 1.0, axial = -1.0 }}
""" + VG46_JET_2LPM + """[environment]
ambient_temperature = "40 degC"
[schedule]
steps = [{{ speed = "3000 rpm", radial_load = "1 kN", axial_load = "1.5 kN", duration = "1 min" }}]
[models]
kinematics = "race_control"
[outputs]
mode = "steady"
want = ["kinematics"]
"""


def test_reversed_thrust_on_a_deep_groove_bearing_runs_as_its_mirror_image():
    scene = loads_scene(SCENE.format(a="SKF6304", b="SKF6304"))
    kin = Simulation(scene, progress=False).run().tables["kinematics"].set_index("bearing")
    assert kin.loc["a", "axial load [kN]"] == pytest.approx(1.5)
    assert kin.loc["b", "axial load [kN]"] == pytest.approx(-1.5)
    for col in ("max contact pressure [MPa]", "cage speed ratio [-]"):
        assert kin.loc["b", col] == pytest.approx(kin.loc["a", col], rel=1e-9)


def test_reversed_thrust_on_an_angular_contact_bearing_is_refused_naming_the_share():
    text = SCENE.format(a="SKF6304", b="SKF6304").replace(
        'preset = "SKF6304"\nload_share', 'path = "examples/spindle_7014C_catalogue.toml"'
        '\nload_share')
    from pathlib import Path

    scene = loads_scene(text, base_dir=Path(__file__).resolve().parents[2])
    with pytest.raises(InputError, match=r"bearings\[1\]\.load_share\.axial = -1\.0 .*"
                                         r"angular-contact"):
        Simulation(scene, progress=False)
