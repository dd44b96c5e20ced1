"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1): the L0 rung (kinematics = "none",
SKF four-term) on a deep-groove bearing under axial load stopped with
"static_load_rating is missing", a field no scene or bearing file can set. The scene now
gives the catalogue C0 as a global_friction option, and the refusal names that option."""

from __future__ import annotations

import pytest
from scene_parts import FUZZ17_OIL, GLOBAL_FRICTION_ONLY, SKF6304_A, scene_title

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.global_friction import skf_four_term
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

# the fuzz reproducer, cut to one step
SCENE = (scene_title("fuzz case: L0 rung, deep-groove bearing with axial load") + "\n"
         + SKF6304_A + "\n" + FUZZ17_OIL + """
[schedule]
speed = "844.329 rpm"
radial_load = "0.00252284 N"
axial_load = "343.78 N"
step_duration = "17.8765 s"

""" + GLOBAL_FRICTION_ONLY + """{options}

[outputs]
mode = "steady"
want = ["losses"]
""")


def _run(options: str):
    scene = loads_scene(SCENE.replace("{options}", options))
    return Simulation(scene, progress=False).run()


def test_missing_c0_names_the_scene_option():
    with pytest.raises(InputError) as err:
        _run("")
    assert err.value.field == "models.heat_source_options.global_friction.static_load_rating"
    assert "SKF6304" in str(err.value) and "palmgren" in str(err.value)


def test_c0_option_gives_the_skf_loss():
    res = _run('heat_source_options = { global_friction = { static_load_rating = "7.8 kN" } }')
    total = res.tables["losses"]["power [W]"].sum()
    bearing = load_bearing("SKF6304")
    from thermobearing import load_lubricant

    oil = load_lubricant("ISO_VG68")
    speed = 844.329 * 2 * 3.141592653589793 / 60
    direct = skf_four_term(bearing, float(oil.kinematic_viscosity(385.75)), speed,
                           0.00252284, 343.78, lubrication="circulation",
                           static_load_rating=7800.0, lubricant_kind=oil.kind)
    assert total > 0
    assert total == pytest.approx(direct.power, rel=1e-9)


def test_c0_option_refused_with_palmgren():
    with pytest.raises(InputError, match="static_load_rating"):
        _run('heat_source_options = { global_friction = { model = "palmgren", '
             'static_load_rating = "7.8 kN" } }')
