"""Tour E (session 24): the sweep's terminal table shows the cage slip that matters.

An oil-flow sweep of a skidding NU 214 (5000 r/min, 0.5-8 kN, 0.5-8 L/min) printed only
``max over-skidding [%]``, -0.005 to -0.02 % in every case, while its cage skidded by 20 to
41 % (``min over-skidding [%]``, in summary.csv only). Numbers below are that sweep's.
"""

from __future__ import annotations

import pandas as pd
import pytest

import thermobearing.report as report
from thermobearing.commands.report import sweep_report
from thermobearing.commands.sweep import terminal_columns
from thermobearing.errors import InputError
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep


def _table(max_os: list[float], min_os: list[float]) -> pd.DataFrame:
    return pd.DataFrame({
        "case": ["a", "b", "c"], "supply.flow": ["0.5 L/min", "2 L/min", "8 L/min"],
        "supply.flow [L/min]": [0.5, 2.0, 8.0],
        "mean total loss [W]": [604.6, 841.0, 1154.4],
        "churning_elements [W]": [181.6, 301.9, 491.1],
        "max over-skidding [%]": max_os, "min over-skidding [%]": min_os,
        "final n.housing [degC]": [78.8, 68.2, 63.3],
        "rise over initial n.housing [K]": [38.8, 28.2, 23.3]})


def test_a_skidding_roller_bearing_shows_its_skid_not_the_noise_of_max():
    df = _table([-0.0059, -0.0052, -0.0060], [-23.0, -26.3, -33.0])
    shown, hidden = terminal_columns(df, ["supply.flow"])
    assert "min over-skidding [%]" in shown and "max over-skidding [%]" not in shown
    assert shown[-4:] == ["mean total loss [W]", "min over-skidding [%]",
                          "final n.housing [degC]", "rise over initial n.housing [K]"]
    assert hidden == 2


def test_a_bearing_that_skids_and_over_skids_shows_both():
    # the QJ1044 rig: skids at 0 kN axial, over-skids at 2-8 kN (tour sweep 5-60 L/min)
    df = _table([10.8, 8.6, 5.3], [-34.5, -54.2, -68.0])
    shown, hidden = terminal_columns(df, ["supply.flow"])
    assert shown[-4:] == ["mean total loss [W]", "max over-skidding [%]",
                          "min over-skidding [%]", "final n.housing [degC]"]
    assert hidden == 2   # the rise (final minus initial) and the churning, in summary.csv


def test_an_over_skidding_bearing_keeps_max():
    df = _table([10.8, 8.6, 5.3], [0.0, 0.0, 0.0])
    shown, _ = terminal_columns(df, ["supply.flow"])
    assert "max over-skidding [%]" in shown and "min over-skidding [%]" not in shown


def test_race_control_zeros_leave_room_for_other_results():
    # the CRB rib example (race control) swept over 1, 2, 4 L/min: two columns of 0 %
    df = _table([0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    shown, hidden = terminal_columns(df, ["supply.flow"])
    assert "max over-skidding [%]" not in shown and "min over-skidding [%]" not in shown
    assert shown[-4:] == ["mean total loss [W]", "churning_elements [W]",
                          "final n.housing [degC]", "rise over initial n.housing [K]"]
    assert hidden == 2


def test_a_range_with_a_unit_on_each_number_says_where_the_unit_goes():
    d = load_scene().to_dict()
    for raw in ("5 L/min:60 L/min:5 L/min", "5:60"):
        with pytest.raises(InputError, match="one unit after it, e.g. 10:30:10 L/min"):
            parse_set(f"supply.flow={raw}", d)
    with pytest.raises(InputError, match=r"e.g. 10:30:10 rpm"):
        parse_set("schedule.speed=600 rpm:1800 rpm:300 rpm", d)
    assert parse_set("supply.flow=5:15:5 L/min", d).values == ("5 L/min", "10 L/min",
                                                               "15 L/min")


def test_sweep_report_leaves_out_the_noise_extreme_of_a_skidding_bearing(tmp_path,
                                                                         monkeypatch):
    # the what-if panels follow the terminal's rule: the NU 214 sweep drew a max
    # over-skidding panel of -0.005 to -0.02 % beside its -20 to -41 % skid
    def runner(text: str) -> dict[str, float]:
        flow = loads_scene(text).supply.flow * 6e4
        return {"mean total loss [W]": 500.0 + 80.0 * flow,
                "churning_elements [W]": 80.0 * flow,
                "max over-skidding [%]": -0.005 - 0.002 * flow,
                "min over-skidding [%]": -20.0 - 2.5 * flow}

    scene = load_scene()
    run_sweep(scene, [parse_set("supply.flow=0.5,2,8", scene.to_dict())], tmp_path,
              runner=runner, workers=1, progress=False)
    drawn: list[list[str]] = []
    real = report.fig_whatif

    def spy(summary, x, ys, group=None):
        drawn.append(list(ys))
        return real(summary, x, ys, group=group)

    monkeypatch.setattr(report, "fig_whatif", spy)
    sweep_report(tmp_path)
    assert drawn == [["mean total loss [W]", "min over-skidding [%]"]]
