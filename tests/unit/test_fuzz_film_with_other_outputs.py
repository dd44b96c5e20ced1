"""Scene fuzzing (scripts/fuzz_scenes.py, ``[outputs] want`` mixes): a scene that asked for
``film`` beside ``kinematics`` or ``losses`` got no film table and no word about it; one
with temperatures neither. The operating-point run now writes the film table at the same
(initial) temperatures as the kinematics, and a run with temperatures says why it has none.
"""

from __future__ import annotations

import math

from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = (scene_title("film beside other outputs") + "\n" + SKF6304_A + "\n" + VG68_JET_1LPM + """
[environment]
ambient_temperature = "40 degC"

[schedule]
steps = [
  { duration = "1 min", speed = "1500 rpm", radial_load = "500 N", axial_load = "0 N" },
  { duration = "1 min", speed = "3000 rpm", radial_load = "1 kN", axial_load = "100 N" },
]

[models]
kinematics = "race_control"

[outputs]
mode = "steady"
want = WANT

[network]
template = "seven_node"
parameters = { housing_outer_diameter = "120 mm", housing_length = "40 mm" }
""")


def _run(want: str):
    sim = Simulation(loads_scene(SCENE.replace("WANT", want)), progress=False)
    return sim.run()


def test_film_table_beside_losses():
    res = _run('["film", "losses"]')
    assert {"film", "kinematics", "losses"} <= set(res.tables)
    film = res.tables["film"]
    assert sorted(set(film["step"])) == [0, 1]
    assert set(film["race"]) == {"inner", "outer"}
    films = film["central film [um]"].to_numpy()
    assert all(math.isfinite(h) and h > 0 for h in films)
    # the faster, more loaded step has the thicker film at the same temperature
    by_step = film.groupby("step")["central film [um]"].min()
    assert by_step[1] > by_step[0]


def test_film_only_scene_unchanged():
    res = _run('["film"]')
    assert set(res.tables) == {"film"}


def test_run_with_temperatures_says_it_has_no_film_table():
    res = _run('["film", "temperatures"]')
    assert "film" not in res.tables
    assert any(w.startswith("outputs.want: no film table in a run with temperatures")
               for w in res.warnings)
