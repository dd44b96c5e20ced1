"""User tour C (session 23): ``--set`` inputs of a speed x load sweep that surprised.

* ``--set schedule.speed=1500:3000:1000`` ran 1500 and 2500 r/min, never the 3000 written as
  the range's stop, without a word -> a note names the values run and the stop left out;
* ``--set schedule.step_duration=1,2`` on a scene whose ``[schedule]`` has ``step_duration``
  was refused as "an existing scene field, e.g. ...; did you mean schedule.duration?" -> the
  refusal says that a sweep sets ``schedule.duration``, every step's own duration.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from thermobearing.errors import InputError
from thermobearing.sweep_params import parse_set

SCENE = {"title": "t", "schedule": {"step_duration": "1 min", "speed": "1500 rpm",
                                    "steps": [{"duration": "1 min", "speed": "1500 rpm",
                                               "axial_load": "1 kN"}]},
         "supply": {"flow": "2 L/min"}}


def test_a_range_whose_stop_is_not_reached_says_so():
    p = parse_set("schedule.speed=1500:3000:1000", SCENE)
    assert p.values == ("1500 rpm", "2500 rpm")
    (note,) = p.notes
    assert note.startswith("sweep: schedule.speed = 1500:3000:1000 runs 1500, 2500 rpm")
    assert "the stop 3000 is not the start plus a whole number of steps of 1000" in note


@pytest.mark.parametrize("spec, values", [
    ("schedule.speed=1500:3000:750", ("1500 rpm", "2250 rpm", "3000 rpm")),
    ("schedule.speed=0.1:0.3:0.1 krpm", ("0.1 krpm", "0.2 krpm", "0.3 krpm")),
    ("supply.flow=1:3:0.5", ("1 L/min", "1.5 L/min", "2 L/min", "2.5 L/min", "3 L/min")),
    ("schedule.axial_load=0.5:2:0.5", ("0.5 kN", "1 kN", "1.5 kN", "2 kN")),
    ("schedule.speed=1500:1500:500", ("1500 rpm",)),
])
def test_a_range_that_ends_on_its_stop_gives_no_note(spec, values):
    p = parse_set(spec, SCENE)
    assert p.values == values and p.notes == ()


def test_the_note_is_printed_before_the_runs(tmp_path, capsys):
    from thermobearing.scene import loads_scene
    from thermobearing.sweep import run_sweep

    examples = Path(__file__).resolve().parents[2] / "examples"
    scene = loads_scene((examples / "loss_point_6206_oil_bath.toml").read_text("utf-8"),
                        base_dir=examples)
    param = parse_set("schedule.speed=1500:3500:1000", scene.to_dict())
    run_sweep(scene, [param], tmp_path / "out", workers=1, progress=False,
              runner=_fake_runner)
    err = capsys.readouterr().err
    assert "is not the start plus" not in err
    param = parse_set("schedule.speed=1500:3000:1000", scene.to_dict())
    run_sweep(scene, [param], tmp_path / "out2", workers=1, progress=False,
              runner=_fake_runner)
    assert "the stop 3000 is not the start plus a whole number of steps" in \
        capsys.readouterr().err


def _fake_runner(scene_toml: str) -> dict[str, float]:
    return {"mean total loss [W]": float(len(scene_toml))}


def test_the_scenes_step_duration_key_is_swept_as_schedule_duration():
    with pytest.raises(InputError) as exc:
        parse_set("schedule.step_duration=1,2", SCENE)
    text = str(exc.value)
    assert "schedule.duration, the duration of every step" in text
    assert "[schedule] step_duration is the steps' default" in text
    p = parse_set("schedule.duration=1,2", SCENE)
    assert p.values == ("1 min", "2 min")
