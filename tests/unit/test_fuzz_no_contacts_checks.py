"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1, case 17): the L0 rung (kinematics =
"none", global_friction) computes no contacts, yet its states were checked as 0 Pa
contact pressure: the stress check passed silently and a sweep's summary gave
``max contact pressure [MPa] = 0`` under 344 N axial. The checks now say the stress and
Lambda were not checked, and the summary leaves the pressure out."""

from __future__ import annotations

import math

from scene_parts import FUZZ17_OIL, GLOBAL_FRICTION_ONLY, SKF6304_A, scene_title

from thermobearing.simulation import Simulation, summarize_scene

SCENE = (scene_title("fuzz case 17: L0 rung, two ball bearings") + "\n" + SKF6304_A + "\n"
         + FUZZ17_OIL + """
[schedule]
steps = [
  { speed = "844.329 rpm", radial_load = "0.00252284 N", axial_load = "343.78 N" },
  { speed = "0 rpm", radial_load = "1.80132 N", axial_load = "98.9185 N" },
]
step_duration = "10 s"

""" + GLOBAL_FRICTION_ONLY + """heat_source_options = { global_friction = { model = "palmgren" } }

[outputs]
mode = "steady"
want = ["losses"]
""")


def test_no_contacts_state_is_not_checked_as_zero_pressure():
    from thermobearing.scene import loads_scene

    sim = Simulation(loads_scene(SCENE.replace('{ speed = "0 rpm"', '{ speed = "237 rpm"')),
                     progress=False)
    res = sim.run()
    states = [c for cs in sim.checks["a"].steps.values() for c in cs]
    assert len(states) == 2 and all(math.isnan(c.max_pressure) for c in states)
    assert ('a: contact stress and film parameter Lambda not checked: the kinematics model '
            'computes no contacts (kinematics = "none")') in res.warnings
    out = summarize_scene(SCENE.replace('{ speed = "0 rpm"', '{ speed = "237 rpm"'))
    assert "max contact pressure [MPa]" not in out
    assert out["steps over stress limit [-]"] == 0.0


def test_summary_keeps_the_static_pressure_of_a_step_at_rest():
    """A step at rest has the static load distribution's contacts (standstill): its
    pressure is the summary's, whatever the order of the NaN states beside it."""
    sim_out = summarize_scene(SCENE)
    p = sim_out["max contact pressure [MPa]"]
    assert math.isfinite(p) and p > 0
