"""``run`` refuses what the ``global_friction`` source would refuse at a later step before it
solves the first one (preflight), with the source's own error text."""

from __future__ import annotations

import pytest
from probe_scene import probe_scene

from thermobearing.commands._preflight import preflight
from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = probe_scene(
    title="preflight probe",
    axial='axial_load_steps = { start = "0 N", stop = "200 N", step = "100 N" }',
    models='kinematics = "none"\nheat_sources = ["global_friction"]')


def test_preflight_refuses_c0_missing_at_a_later_step_with_the_runs_text() -> None:
    sim = Simulation(loads_scene(SCENE), progress=False)
    with pytest.raises(InputError, match=r"\(100 N here") as pre:
        preflight(sim, build=False)
    with pytest.raises(InputError) as ran:
        Simulation(loads_scene(SCENE), progress=False).run()
    assert str(pre.value) == str(ran.value)
    assert pre.value.field == "models.heat_source_options.global_friction.static_load_rating"


def test_preflight_passes_the_scene_once_c0_is_given() -> None:
    text = SCENE.replace(
        'heat_sources = ["global_friction"]',
        'heat_sources = ["global_friction"]\n'
        'heat_source_options = { global_friction = { static_load_rating = "7.8 kN" } }')
    preflight(Simulation(loads_scene(text), progress=False), build=False)
