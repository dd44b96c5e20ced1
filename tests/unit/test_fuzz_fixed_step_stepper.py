"""A scene naming a stepper without error control (found by the scene fuzzer): the transient
stopped at its first chunk with 'dt is missing: a fixed step size', naming no scene field
(a scene has no step-size key). It is now refused before the run, naming solver.stepper and
the usable steppers."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import load_scene
from thermobearing.scene_checks import check_model_names


@pytest.mark.parametrize("stepper", ["crank_nicolson", "explicit_euler"])
def test_fixed_step_stepper_is_refused_naming_the_field(stepper):
    scene = load_scene("qj1044_rig")
    scene = scene.with_changes(solver=scene.solver.__class__(stepper=stepper))
    with pytest.raises(InputError, match=r"solver\.stepper = '" + stepper
                       + r"'.*error control \(.*exprb43.*tr_bdf2"):
        check_model_names(scene)


def test_adaptive_steppers_pass():
    scene = load_scene("qj1044_rig")
    for stepper in ("exprb43", "tr_bdf2", "backward_euler"):
        check_model_names(scene.with_changes(solver=scene.solver.__class__(stepper=stepper)))
