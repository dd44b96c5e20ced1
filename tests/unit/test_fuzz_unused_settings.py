"""Scene fuzzing (session 17): settings of the thermal run that a scene's outputs leave
unused ran without a word: ``[network]``, ``[solver]``, ``[measured]``, ``outputs.interval``
and ``models.churning_heat_to`` of a scene without 'temperatures' / 'energy' (no network
runs), ``outputs.interval`` of a steady run, and 'energy' wanted from a steady run (no
table). The run now says so in one note, and a
sweep of such a setting names it before its cases run."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.sweep import check_cases, expand, parse_set

BASE = (scene_title("unused settings") + "\n" + SKF6304_A + "\n" + VG68_JET_1LPM + """
[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "1 kN", axial_load = "0 N" }]

[models]
kinematics = "race_control"
""")
NETWORK = """
[network]
template = "seven_node"
parameters = { housing_outer_diameter = "120 mm", housing_length = "40 mm" }
"""


def _notes(text: str) -> list[str]:
    sim = Simulation(loads_scene(text), progress=False)
    return [n for n in sim.notes if "not used" in n and "supply." not in n]


def test_thermal_settings_without_a_network_are_noted():
    text = (BASE.replace('kinematics = "race_control"',
                         'kinematics = "race_control"\nchurning_heat_to = "paper002"')
            + NETWORK + '\n[solver]\nchunk = "10 s"\n'
            + '\n[outputs]\nmode = "transient"\nwant = ["losses"]\ninterval = "5 s"\n')
    (note,) = _notes(text)
    for name in ("[network]", "[solver]", "outputs.interval", "models.churning_heat_to"):
        assert name in note
    assert "are not used" in note and "(losses)" in note


def test_no_note_when_the_network_runs_or_nothing_is_set():
    thermal = BASE + NETWORK + '\n[outputs]\nmode = "transient"\nwant = ["temperatures"]\n'
    assert _notes(thermal) == []
    assert _notes(BASE + '\n[outputs]\nmode = "steady"\nwant = ["losses"]\n') == []


def test_interval_of_a_steady_run_is_noted():
    text = BASE + NETWORK + ('\n[outputs]\nmode = "steady"\nwant = ["temperatures", "losses"]'
                             '\ninterval = "10 s"\n')
    (note,) = _notes(text)
    assert note.startswith("outputs.interval (10 s) is not used: a steady run")


@pytest.mark.parametrize(("setting", "unused"), [
    ("network.parameters.h_oil=100,1000", True), ("schedule.speed=1000,2000", False)])
def test_sweep_of_an_unused_network_parameter_is_named(setting, unused):
    scene = loads_scene(BASE + NETWORK + '\n[outputs]\nmode = "steady"\nwant = ["losses"]\n')
    lines = check_cases(expand(scene, [parse_set(setting, scene.to_dict())]))
    path = setting.split("=")[0]
    assert bool(lines) is unused
    if unused:
        assert lines[0].startswith(f"sweep: {path} is swept but not used")


def test_energy_wanted_in_a_steady_run_is_noted():
    text = BASE + NETWORK + ('\n[outputs]\nmode = "steady"\nwant = ["energy", "losses"]\n')
    sim = Simulation(loads_scene(text), progress=False)
    notes = [n for n in sim.notes if n.startswith("outputs.want 'energy'")]
    assert len(notes) == 1 and "steady run" in notes[0]
    res = sim.run()
    assert "energy" not in res.tables and notes[0] in res.warnings
