"""A ``[models] heat_source_options`` parameter that a ball bearing's kinematics sets to
match its own force models (e.g. ``churning_inner_ring.oil_fraction``, which the ball
kinematics derive from the supply) is refused when the scene is built, so ``thermobearing
check`` says so; before, ``check`` passed and the run stopped at its first heat evaluation
(scene fuzzing, session 17, seed 37 case 5)."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.cli import main
from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = (scene_title("option clash") + "\n" + SKF6304_A + "\n" + VG68_JET_1LPM + """\
inlet_temperature = "40 degC"

[schedule]
steps = [{{ duration = "1 min", speed = "{speed}", radial_load = "500 N", axial_load = "0 N" }}]

[models]
kinematics = "{kinematics}"
heat_source_options = {{ churning_inner_ring = {{ oil_fraction = 0.5 }} }}

[outputs]
mode = "steady"
want = ["losses"]
""")


@pytest.mark.parametrize("kinematics", ["race_control", "skidding"])
def test_a_clash_is_refused_when_the_scene_is_built(kinematics):
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(SCENE.format(kinematics=kinematics, speed="3000 rpm")),
                   progress=False)
    msg = str(info.value)
    assert "models.heat_source_options.churning_inner_ring.oil_fraction" in msg
    assert kinematics in msg and "'a'" in msg


def test_check_reports_the_clash(tmp_path, capsys):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE.format(kinematics="race_control", speed="3000 rpm"), encoding="utf-8")
    assert main(["check", str(path)]) != 0
    assert "churning_inner_ring.oil_fraction" in capsys.readouterr().err


def test_global_friction_scene_keeps_its_options():
    # kinematics "none" sets no source options: the option is the scene's to give
    text = SCENE.format(kinematics="none", speed="3000 rpm").replace(
        "heat_source_options = { churning_inner_ring = { oil_fraction = 0.5 } }",
        'heat_sources = ["global_friction"]\n'
        'heat_source_options = { global_friction = { model = "palmgren" } }')
    Simulation(loads_scene(text), progress=False)
