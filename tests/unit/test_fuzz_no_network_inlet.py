"""Scenes without a thermal network and the oil inlet temperature (thermobearing.unheated).

A run whose outputs start no network takes every part and the oil at one temperature: the
scene's environment.initial_temperature when it gives one, else the inlet temperature of a
fed supply (jet, circulation, oil-air, circulated bath), else the ambient. A sweep of the
inlet of a scene with an explicit initial temperature gave identical rows and said nothing
(scene fuzzing); such a run notes that the inlet is not used and the sweep says so before
its cases run. Without an explicit initial temperature the inlet is used and changes the
results."""

from __future__ import annotations

import tomllib

import pandas as pd
import pytest
from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.cli import main
from thermobearing.scene import Scene
from thermobearing.simulation import Simulation
from thermobearing.sweep import check_cases, expand, parse_set
from thermobearing.unheated import unheated_temperature

SCENE = (scene_title("jet at 80 degC, no network") + "\n" + SKF6304_A + "\n" + VG68_JET_1LPM + """\
inlet_temperature = "80 degC"

[environment]
ambient_temperature = "20 degC"
initial_temperature = "20 degC"

[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "500 N", axial_load = "0 N" }]

[outputs]
mode = "steady"
want = ["film"]
""")
#: the same scene without an initial temperature: the runs take the inlet's
NO_INITIAL = SCENE.replace('initial_temperature = "20 degC"\n', "")


def _scene(text: str = SCENE) -> Scene:
    return Scene.from_dict(tomllib.loads(text))


def _inlet_notes(scene: Scene) -> list[str]:
    return [n for n in Simulation(scene, progress=False).notes
            if n.startswith("supply.inlet_temperature (")]


def test_run_without_network_says_the_inlet_is_not_used():
    (note,) = _inlet_notes(_scene())
    assert "80 degC" in note and "environment.initial_temperature (20 degC)" in note
    assert "'temperatures'" in note


def test_no_note_where_the_inlet_is_used_or_matches():
    with_network = SCENE.replace('want = ["film"]', 'want = ["temperatures", "losses"]')
    assert _inlet_notes(_scene(with_network)) == []
    same = SCENE.replace('inlet_temperature = "80 degC"', 'inlet_temperature = "20 degC"')
    assert _inlet_notes(_scene(same)) == []
    not_given = SCENE.replace('inlet_temperature = "80 degC"\n', "")
    assert _inlet_notes(_scene(not_given)) == []
    assert _inlet_notes(_scene(NO_INITIAL)) == []  # the inlet is used


@pytest.mark.parametrize(("text", "celsius", "source"), [
    (SCENE, 20.0, "environment.initial_temperature"),
    (NO_INITIAL, 80.0, "supply.inlet_temperature"),
    (NO_INITIAL.replace('method = "jet"', 'method = "oil_bath"').replace(
        'flow = "1 L/min"', 'flow = "0 L/min"\nlevel = "10 mm"'),
     20.0, "environment.initial_temperature"),  # a still bath has no inlet: the ambient
])
def test_which_temperature_a_run_without_network_takes(text, celsius, source):
    t, where = unheated_temperature(_scene(text))
    assert t == pytest.approx(273.15 + celsius) and where == source


def test_film_without_initial_temperature_is_taken_at_the_inlet():
    """Hot inlet oil is thinner: the films of the 80 degC run are thinner than those of the
    scene that states 20 degC, and equal to those of a scene that states 80 degC."""
    def films(text):
        res = Simulation(_scene(text), progress=False).run()
        return res.tables["film"].filter(like="central film").to_numpy(float)

    at_inlet = films(NO_INITIAL)
    cold = films(SCENE)
    stated = films(SCENE.replace('initial_temperature = "20 degC"',
                                 'initial_temperature = "80 degC"'))
    finite = at_inlet == at_inlet
    assert finite.any()
    assert (at_inlet[finite] < 0.5 * cold[finite]).all()
    assert at_inlet[finite] == pytest.approx(stated[finite], rel=1e-12)


def test_sweep_names_the_unused_swept_path(tmp_path, capsys):
    scene = _scene()
    cases = expand(scene, [parse_set("supply.inlet_temperature=40,80", scene.to_dict())])
    (line,) = check_cases(cases)
    assert line.startswith("sweep: supply.inlet_temperature is swept but not used")
    # a swept path the runs use: no line
    cases = expand(scene, [parse_set("schedule.speed=1000,2000", scene.to_dict())])
    assert check_cases(cases) == []

    path = tmp_path / "scene.toml"
    path.write_text(SCENE, encoding="utf-8")
    out = tmp_path / "sweep"
    rc = main(["sweep", str(path), "--set", "supply.inlet_temperature=40,80", "--out",
               str(out), "--workers", "1", "--quiet"])
    assert rc == 0
    err = capsys.readouterr().err
    assert "supply.inlet_temperature is swept but not used" in err
    assert len(pd.read_csv(out / "summary.csv")) == 2
