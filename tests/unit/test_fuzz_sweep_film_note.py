"""Scene fuzzing (scripts/fuzz_scenes.py, sweeps of film-only scenes): ``thermobearing
sweep`` said "the cases will give no results to tabulate" for a scene whose outputs are
``["film"]``, then tabulated their smallest films (summarize_scene). The note is now kept
for outputs that give nothing to tabulate."""

from __future__ import annotations

import pandas as pd
from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.cli import main

SCENE = (scene_title("film-only sweep") + "\n" + SKF6304_A + "\n" + VG68_JET_1LPM + """
[environment]
ambient_temperature = "40 degC"

[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "500 N", axial_load = "0 N" }]

[outputs]
mode = "steady"
want = ["film"]
""")


def test_film_only_sweep_tabulates_without_the_empty_note(tmp_path, capsys):
    scene = tmp_path / "scene.toml"
    scene.write_text(SCENE, encoding="utf-8")
    code = main(["sweep", str(scene), "--set", "environment.ambient_temperature=20,60",
                 "-j", "1", "--quiet", "--out", str(tmp_path / "sw")])
    err = capsys.readouterr().err
    assert code == 0
    assert "no results to tabulate" not in err
    films = pd.read_csv(tmp_path / "sw" / "summary.csv")["min central film [um]"]
    # warmer oil, thinner film: the column holds the cases' results
    assert films.iloc[0] > films.iloc[1] > 0
