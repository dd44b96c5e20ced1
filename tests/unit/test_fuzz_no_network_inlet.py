"""Scene fuzzing (sweeps of scenes without a thermal network): ``--set
supply.inlet_temperature=...`` on a scene whose outputs run no network gave identical rows
and said nothing; the runs take every part and the oil at environment.initial_temperature.
The run now notes that the inlet is not used and the sweep says so before its cases run."""

from __future__ import annotations

import tomllib

import pandas as pd

from thermobearing.cli import main
from thermobearing.scene import Scene
from thermobearing.simulation import Simulation
from thermobearing.sweep import check_cases, expand, parse_set

SCENE = """
title = "jet at 80 degC, no network"

[[bearings]]
name = "a"
preset = "SKF6304"

[lubricant]
preset = "ISO_VG68"

[supply]
method = "jet"
flow = "1 L/min"
inlet_temperature = "80 degC"

[environment]
ambient_temperature = "20 degC"

[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "500 N", axial_load = "0 N" }]

[outputs]
mode = "steady"
want = ["film"]
"""


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
