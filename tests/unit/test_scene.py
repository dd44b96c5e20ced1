import math

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import load_scene, loads_scene

MINIMAL = """
title = "t"
[[bearings]]
name = "b"
preset = "QJ1044"
[lubricant]
preset = "ISO_VG46"
[supply]
flow = "33 L/min"
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "2 kN"
duration = "10 min"
"""


def test_default_scene_protocol():
    scene = load_scene()
    steps = scene.schedule.steps
    assert len(steps) == 22  # 0..42 kN in 2 kN steps
    assert scene.schedule.duration == pytest.approx(66 * 60)
    assert steps[0].axial_load == 0.0 and steps[-1].axial_load == pytest.approx(42e3)
    assert steps[0].speed == pytest.approx(1800 * math.pi / 30)
    assert scene.supply.flow == pytest.approx(33e-3 / 60)
    assert scene.environment.ambient_temperature == pytest.approx(308.15)
    assert [b.name for b in scene.bearings] == ["drive_end", "non_drive_end"]
    assert scene.schedule.breakpoints[0] == pytest.approx(180.0)


def test_round_trip():
    scene = load_scene()
    again = loads_scene(scene.to_toml())
    assert again.schedule == scene.schedule
    assert again.supply == scene.supply
    assert again.environment == scene.environment
    assert again.bearings == scene.bearings
    assert again.solver == scene.solver and again.outputs == scene.outputs
    assert again.to_toml() == scene.to_toml()


@pytest.mark.parametrize(
    ("edit", "field"),
    [
        (("title = \"t\"", "title = \"t\"\ncolour = \"red\""), "scene.colour"),
        (("duration = \"10 min\"", "duration = \"-1 min\""), "schedule.duration"),
        (("duration = \"10 min\"", "duration = \"0 s\""), "schedule.duration"),
        (("flow = \"33 L/min\"", "flow = \"-3 L/min\""), "supply.flow"),
        (("flow = \"33 L/min\"", "flow = \"33 kg\""), "supply.flow"),
        (("speed = \"1800 rpm\"", "speed = \"1800 kg\""), "schedule.speed"),
        (("[supply]", "[supply]\nmethod = \"bucket\""), "supply.method"),
    ],
)
def test_bad_scene(edit, field):
    text = MINIMAL.replace(*edit)
    with pytest.raises(InputError) as info:
        loads_scene(text)
    assert field in str(info.value)


def test_unknown_preset_scene():
    with pytest.raises(InputError) as info:
        load_scene("no_such_scene")
    assert "qj1044_rig" in str(info.value)


def test_steps_and_file(tmp_path):
    csv_path = tmp_path / "protocol.csv"
    csv_path.write_text("duration [min],speed [rpm],radial_load [kN],axial_load [kN]\n"
                        "3,600,1,0\n3,600,1,2\n", encoding="utf-8")
    text = MINIMAL.replace('duration = "10 min"', 'file = "protocol.csv"')
    scene = loads_scene(text, base_dir=tmp_path)
    assert [s.axial_load for s in scene.schedule.steps] == [0.0, 2000.0]
    assert scene.schedule.steps[0].speed == pytest.approx(600 * math.pi / 30)
    steps = MINIMAL.replace('duration = "10 min"',
                            'steps = [{duration = "1 min"}, {duration = "2 min", '
                            'axial_load = "4 kN"}]')
    sc = loads_scene(steps)
    assert sc.schedule.steps[1].axial_load == 4000.0 and sc.schedule.steps[0].axial_load == 2000.0


@pytest.mark.parametrize("bad", ['"0 s"', '"-5 s"', '"5 kg"', '"soon"'])
def test_output_interval_must_be_a_positive_time(bad):
    import tomllib

    from thermobearing.errors import InputError
    from thermobearing.scene import Outputs

    with pytest.raises(InputError, match="outputs.interval"):
        Outputs.from_dict(tomllib.loads(f"interval = {bad}"))


def test_docstring_layout_models_names_are_real():
    """The ``[models]`` block of the scene module's layout names only accepted keys and
    registered models (it drifted once: 'raceway', 'traction' were never names)."""
    import re
    import tomllib

    from thermobearing import scene as scene_module
    from thermobearing.film import FILM
    from thermobearing.heat_sources import HEAT_SOURCES
    from thermobearing.kinematic_models import KINEMATICS
    from thermobearing.simulation import MODEL_KEYS
    from thermobearing.state import RACE_CONTROLS

    doc = scene_module.__doc__
    block = doc.split("[models]", 1)[1].split("\n    [", 1)[0]
    text = "\n".join(line for line in block.splitlines()[1:] if "..." not in line)
    models = tomllib.loads(re.sub(r"^    ", "", text, flags=re.M))
    assert set(models) <= MODEL_KEYS
    assert {"kinematics", "film", "heat_sources"} <= set(models)
    assert models["kinematics"] in KINEMATICS
    assert models["film"] in FILM
    assert all(name in HEAT_SOURCES for name in models["heat_sources"])
    assert models["control"] in RACE_CONTROLS
