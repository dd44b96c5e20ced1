"""Scene fuzzing (scripts/fuzz_scenes.py, seed 3 case 22): a run stopped with
"skidding.ball did not converge (residual 6.766e-09): continuation in speed failed too ..."
naming neither the bearing nor the step (it was the second step, 366 r/min under 24.1 kN
radial, not the first at 0.89 r/min). A kinematics solver's ConvergenceError now reaches the
caller with the bearing, the step and its operating point in front, residual kept."""

from __future__ import annotations

import dataclasses

import pytest
from scene_parts import VG32_JET, scene_title

from thermobearing.errors import ConvergenceError
from thermobearing.kinematic_models import KINEMATICS
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = scene_title("fuzz case") + """
[[bearings]]
name = "front"
preset = "SKF6304"

""" + VG32_JET + """
[environment]
ambient_temperature = "40 degC"

[schedule]
radial_load = "2 kN"
axial_load = "100 N"
step_duration = "10 s"
steps = [{ speed = "600 rpm" }, { speed = "366.256 rpm" }]

[models]
kinematics = "race_control"

[outputs]
mode = "steady"
want = ["kinematics"]
"""


def test_solver_failure_names_bearing_and_step(monkeypatch):
    """The solver is the registered race control, failing (as the fuzz case's ball solver
    did) at the second step only."""
    entry = KINEMATICS.entry("race_control")
    real = entry.obj

    def second_step_fails(bearing, lubricant, operating, **kw):
        if operating.inner_speed < 50.0:   # 366 r/min = 38.4 rad/s
            raise ConvergenceError("skidding.ball", 6.766e-9, "stalled")
        return real(bearing, lubricant, operating, **kw)

    monkeypatch.setitem(KINEMATICS._entries, "race_control",
                        dataclasses.replace(entry, obj=second_step_fails))
    with pytest.raises(ConvergenceError) as err:
        Simulation(loads_scene(SCENE), progress=False).run()
    text = str(err.value)
    assert err.value.residual == 6.766e-9
    assert text.startswith("kinematics (race_control) of front did not converge (residual "
                           "6.766e-09): at step 1 (366.256 r/min, radial 2000 N, axial 100 N")
    assert "skidding.ball did not converge (residual 6.766e-09): stalled" in text
    assert err.value.state == {"step": 1}
