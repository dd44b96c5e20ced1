"""Scene fuzzing (scripts/fuzz_scenes.py, ``[schedule]`` defaults): a negative default speed
or load is refused, and it was shown at the first step that took it in SI
(``schedule.axial_load_steps[0].speed = -314.159``, the scene wrote ``-3 krpm``); the
error now names the key the scene wrote and shows the value as written."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene_schedule import Schedule


@pytest.mark.parametrize(("key", "raw", "allowed"), [
    ("speed", "-3 krpm", "a speed >= 0"),
    ("radial_load", "-0.5 kN", "a load >= 0"),
    ("axial_load", "-10 lbf", "a load >= 0"),
    ("step_duration", "0 min", "a duration > 0"),
    ("duration", "-1 s", "a duration > 0"),
])
@pytest.mark.parametrize("form", ["axial_load_steps", "steps", "defaults"])
def test_bad_default_is_shown_as_written(key, raw, allowed, form):
    data = {"speed": "1000 rpm", "radial_load": "1 kN", "axial_load": "0 N",
            "step_duration": "1 min"}
    if form == "axial_load_steps":
        if key == "axial_load":
            return  # the sweep sets every step's axial load
        data[form] = {"start": "0 N", "stop": "100 N", "step": "50 N"}
    elif form == "steps":
        data[form] = [{}]
    if key == "duration":
        del data["step_duration"]
    data[key] = raw
    with pytest.raises(InputError) as err:
        Schedule.from_dict(data)
    # refused under the key the scene wrote (not the first step that took the default)
    assert err.value.field == f"schedule.{key}"
    assert f"'{raw}'" in str(err.value) and allowed in str(err.value)


def test_good_defaults_still_fill_the_steps():
    steps = Schedule.from_dict({"speed": "1000 rpm", "radial_load": "1 kN",
                                "step_duration": "1 min",
                                "steps": [{"axial_load": "0 N"}, {"axial_load": "5 N"}]}).steps
    assert [s.axial_load for s in steps] == [0.0, 5.0]
    assert all(s.radial_load == 1000.0 and s.duration == 60.0 for s in steps)
