"""Tour E (session 24): the report of a stopped sweep names the planned cases without a
result, not only the gaps between the values some finished case had.

A flow x inlet sweep (4 x 8 cases) stopped after 11 said "3 of 14 combinations of the
swept values have no result": 55 degC and 40, 60 L/min, which no finished case had, were
not counted, while the line above said "11 of 32 planned cases finished".
"""

from __future__ import annotations

import pandas as pd

from thermobearing.commands.report import missing_cases, sweep_report
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep


class Stop(Exception):
    pass


def test_stopped_sweep_names_every_planned_case_without_result(tmp_path):
    scene = load_scene()
    d = scene.to_dict()
    params = [parse_set("supply.flow=5,20,40", d), parse_set("supply.inlet_temperature=25,40",
                                                            d)]
    done: list[str] = []

    def runner(text: str) -> dict[str, float]:
        if len(done) == 3:
            raise Stop   # Ctrl-C after three cases
        done.append(text)
        sc = loads_scene(text)
        return {"mean total loss [W]": sc.supply.flow * 6e6,
                "churning_elements [W]": sc.supply.flow * 3e6}

    try:
        run_sweep(scene, params, tmp_path, runner=runner, workers=1, progress=False)
    except Stop:
        pass
    html = sweep_report(tmp_path).read_text(encoding="utf-8")
    df = pd.read_csv(tmp_path / "summary.csv")
    (note,) = missing_cases(tmp_path, df, ["supply.flow", "supply.inlet_temperature"])
    assert note.startswith("3 of 6 planned cases have no result")
    assert "supply.flow = 20 L/min, supply.inlet_temperature = 40 degC" in note
    assert "supply.flow = 40 L/min, supply.inlet_temperature = 25 degC" in note
    assert "3 of 6 planned cases have no result" in html


def test_finished_sweep_has_no_missing_note(tmp_path):
    scene = load_scene()
    params = [parse_set("supply.flow=5,20", scene.to_dict())]
    run_sweep(scene, params, tmp_path, runner=lambda t: {"x [W]": 1.0}, workers=1,
              progress=False)
    assert missing_cases(tmp_path, pd.read_csv(tmp_path / "summary.csv"),
                         ["supply.flow"]) == []
