"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1 cases 24, 50; seed 2 cases 33, 121): a
turning step with neither radial nor axial load on a ball bearing under the ball skidding
solver stopped the run at that step with "skidding.ball did not converge (residual inf):
no external load ...", naming neither the step nor the bearing. It is now refused before
anything is solved, like the roller solver's step without radial load."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

# seed 2, case 121 (the spindle bearing of examples/, here by its path from the repository)
SCENE = """
title = "fuzz case"

[[bearings]]
name = "a"
path = "../../examples/spindle_7014C_catalogue.toml"

[lubricant]
preset = "ISO_VG100"

[supply]
method = "jet"
flow = "0.898098 L/min"
inlet_temperature = "28.11 degC"

[environment]
ambient_temperature = "37 degC"

[schedule]
steps = [
  { speed = "@SPEED@", radial_load = "0 N", axial_load = "0 N" },
  { speed = "31.3381 rpm", radial_load = "3.63743 N", axial_load = "0.228456 N" },
]
step_duration = "2.25006 s"

[models]
kinematics = "@KIN@"

[outputs]
mode = "steady"
want = ["kinematics"]
"""


def _scene(speed: str, kin: str):
    from pathlib import Path

    here = Path(__file__).resolve().parent
    return loads_scene(SCENE.replace("@SPEED@", speed).replace("@KIN@", kin), base_dir=here)


def test_unloaded_turning_step_refused_before_solving():
    with pytest.raises(InputError) as err:
        Simulation(_scene("34.9982 rpm", "skidding"), progress=False)
    assert err.value.field == ("schedule step 0 radial_load and axial_load (bearing 'a', "
                               "7014C)")
    assert "race_control" in str(err.value)


def test_unloaded_step_at_rest_and_race_control_run():
    at_rest = Simulation(_scene("0 rpm", "skidding"), progress=False).run()
    assert len(at_rest.tables["kinematics"]) == 2
    kin = Simulation(_scene("34.9982 rpm", "race_control"), progress=False).run()
    rows = kin.tables["kinematics"]
    assert rows["converged"].all() and len(rows) == 2
