"""User tour 21, oil-flow what-if sweep of the default rig (two identical QJ1044 bearings) on
a 3-step protocol: summary.csv's ``steps over skid limit [-]`` was summed over the bearings
(6 for three steps flagged at both), and the sweep report said "every case, 4 to 6 steps
each", as if the protocol had more steps than it has. The summary now counts a step once
however many bearings it flags, and the report's note says so.
"""

from __future__ import annotations

import pandas as pd

from thermobearing.commands.report import flagged_cases, sweep_report
from thermobearing.scene import load_scene
from thermobearing.sweep import parse_set, run_sweep

ONCE = "(a step flagged at several of the 2 bearings counts once)"


def _flagged_runner(scene_toml: str) -> dict[str, float]:
    """A case flags 2 of its 3 steps at 15 L/min and all 3 at 33 L/min, with a loss that
    grows with the flow."""
    from thermobearing.scene import loads_scene

    flow = loads_scene(scene_toml).supply.flow
    return {"mean total loss [W]": 1e6 * flow,
            "steps over skid limit [-]": 2.0 if flow < 4e-4 else 3.0}


def test_note_says_a_step_counts_once_over_the_bearings():
    df = pd.DataFrame({"supply.flow [L/min]": [15.0, 33.0],
                       "steps over skid limit [-]": [2.0, 3.0]})
    (two,) = flagged_cases(df, ["supply.flow [L/min]"], bearings=2)
    assert two.endswith(f"every case, 2 to 3 steps each {ONCE}")
    (one,) = flagged_cases(df, ["supply.flow [L/min]"])
    assert one.endswith("every case, 2 to 3 steps each")


def test_sweep_report_of_the_two_bearing_rig_says_so(tmp_path):
    scene = load_scene()  # the default rig: drive_end and non_drive_end
    assert len(scene.bearings) == 2
    p = parse_set("supply.flow=15,33", scene.to_dict())
    run_sweep(scene, [p], tmp_path, runner=_flagged_runner, workers=1, progress=False)
    html = sweep_report(tmp_path).read_text(encoding="utf-8")
    assert f"every case, 2 to 3 steps each {ONCE}" in html
