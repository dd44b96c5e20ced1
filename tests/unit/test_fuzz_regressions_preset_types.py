"""Preset names of other types, found by mutating fuzzed scenes (session 18):
``[lubricant] preset = 0`` stopped in the simulation with ``KeyError: 'path'`` and
``preset = -1`` with a TypeError from pathlib; a bearing's preset or path of another type
or empty is refused the same way, naming the field."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene

SCENE = """title = "t"
[[bearings]]
name = "a"
{bearing}
[lubricant]
{lubricant}
[supply]
method = "jet"
flow = "1 L/min"
[schedule]
speed = "1500 rpm"
radial_load = "1 kN"
axial_load = "0 N"
[outputs]
mode = "steady"
want = ["film"]
"""


@pytest.mark.parametrize("value", ["0", "-1", "true", '""', "[1]", '"  "'])
@pytest.mark.parametrize("key", ["preset", "path"])
def test_lubricant_preset_or_path_of_another_type(key, value):
    with pytest.raises(InputError, match=rf"lubricant.{key} = "):
        loads_scene(SCENE.format(bearing='preset = "SKF6304"', lubricant=f"{key} = {value}"))


@pytest.mark.parametrize("value", ["0", "1.5", '""', "{ a = 1 }"])
@pytest.mark.parametrize("key", ["preset", "path"])
def test_bearing_preset_or_path_of_another_type(key, value):
    with pytest.raises(InputError, match=rf"bearings\[0\].{key} = "):
        loads_scene(SCENE.format(bearing=f"{key} = {value}", lubricant='preset = "ISO_VG32"'))


@pytest.mark.parametrize("value", ["{ a = 1 }", "5", '""', "[]"])
def test_schedule_file_of_another_type(value):
    text = SCENE.format(bearing='preset = "SKF6304"', lubricant='preset = "ISO_VG32"')
    text = text.replace('speed = "1500 rpm"\nradial_load = "1 kN"\naxial_load = "0 N"',
                        f"file = {value}")
    with pytest.raises(InputError, match=r"schedule.file = .*a CSV file path"):
        loads_scene(text)


@pytest.mark.parametrize("value", [{"a": 1}, 5, "", None])
def test_measured_file_of_another_type(value):
    from thermobearing.scene_sections import Measured

    data = {"columns": {"TC1": "a.housing"}}
    if value is not None:
        data["file"] = value
    with pytest.raises(InputError, match=r"measured.file"):
        Measured.from_dict(data)
