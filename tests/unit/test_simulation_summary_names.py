"""The sweep summary's names say what they are (simulation_summary), and sweep folders
written with the earlier names resume and report under the current ones (sweep_store)."""

from __future__ import annotations

import json

import pytest

from thermobearing.scene import load_scene
from thermobearing.simulation_summary import current_result_name, current_result_names
from thermobearing.sweep_store import base_scene_mode, finished_cases, summary_frame


@pytest.mark.parametrize(("old", "steady", "new"), [
    ("total loss [W]", False, "mean total loss [W]"),
    ("total loss drive_end [W]", True, "mean total loss drive_end [W]"),
    ("rise drive_end.housing [K]", False, "rise over initial drive_end.housing [K]"),
    ("rise drive_end.housing [K]", True, "rise over ambient drive_end.housing [K]"),
    # current names, and names that were never renamed, stay
    ("mean total loss [W]", False, "mean total loss [W]"),
    ("rise over ambient drive_end.oil [K]", False, "rise over ambient drive_end.oil [K]"),
    ("max total loss [W]", False, "max total loss [W]"),
    ("churning_elements [W]", False, "churning_elements [W]"),
    ("final drive_end.oil [degC]", True, "final drive_end.oil [degC]"),
])
def test_earlier_names_map_to_the_current_ones(old, steady, new):
    assert current_result_name(old, steady) == new


def test_a_current_name_wins_over_an_earlier_one():
    got = current_result_names({"total loss [W]": 1.0, "mean total loss [W]": 2.0})
    assert got == {"mean total loss [W]": 2.0}


def _old_folder(tmp_path, mode: str) -> None:
    """A sweep folder as the earlier version left it: one finished case with the old
    names in cases.jsonl, the base scene in scene.toml."""
    scene = load_scene()
    text = scene.to_toml().replace('mode = "transient"', f'mode = "{mode}"')
    (tmp_path / "scene.toml").write_text(text, encoding="utf-8")
    rec = {"case": "c1", "params": {"supply.flow": "15 L/min"},
           "result": {"total loss [W]": 1500.0, "rise drive_end.housing [K]": 12.5,
                      "final drive_end.housing [degC]": 47.5}}
    (tmp_path / "cases.jsonl").write_text(json.dumps(rec) + "\n", encoding="utf-8")


@pytest.mark.parametrize(("mode", "rise"), [("transient", "rise over initial"),
                                            ("steady", "rise over ambient")])
def test_a_resumed_old_folder_reads_under_the_current_names(tmp_path, mode, rise):
    _old_folder(tmp_path, mode)
    assert base_scene_mode(tmp_path) == mode
    done = finished_cases(tmp_path)
    assert done["c1"]["result"] == {"mean total loss [W]": 1500.0,
                                    f"{rise} drive_end.housing [K]": 12.5,
                                    "final drive_end.housing [degC]": 47.5}
    # an old and a new case in one summary: one column per quantity, no empty halves
    new = {"case": "c2", "params": {"supply.flow": "33 L/min"},
           "result": {"mean total loss [W]": 1900.0, f"{rise} drive_end.housing [K]": 9.0,
                      "final drive_end.housing [degC]": 44.0}}
    df = summary_frame([done["c1"], new])
    assert df["mean total loss [W]"].tolist() == [1500.0, 1900.0]
    assert f"{rise} drive_end.housing [K]" in df and "total loss [W]" not in df
    assert not df.isna().any().any()


def test_a_case_swept_to_steady_reads_its_rise_over_the_ambient(tmp_path):
    _old_folder(tmp_path, "transient")
    rec = {"case": "c3", "params": {"outputs.mode": "steady"},
           "result": {"rise drive_end.oil [K]": 3.0}}
    with (tmp_path / "cases.jsonl").open("a", encoding="utf-8") as fh:
        fh.write(json.dumps(rec) + "\n")
    assert finished_cases(tmp_path)["c3"]["result"] == {
        "rise over ambient drive_end.oil [K]": 3.0}


def test_a_folder_without_a_base_scene_is_read_as_transient(tmp_path):
    assert base_scene_mode(tmp_path) == "transient"
    (tmp_path / "scene.toml").write_text("not = [toml", encoding="utf-8")
    assert base_scene_mode(tmp_path) == "transient"


def _old_runner(scene_toml: str) -> dict[str, float]:
    """Results under the earlier names (made-up numbers, monotonic in the flow)."""
    from thermobearing.scene import loads_scene

    q = loads_scene(scene_toml).supply.flow * 60e3
    return {"total loss [W]": 100.0 * q, "churning_elements [W]": 60.0 * q,
            "drag_elements [W]": 40.0 * q, "final drive_end.housing [degC]": 50.0 - 0.1 * q,
            "rise drive_end.housing [K]": 15.0 - 0.1 * q}


def test_the_report_of_an_old_folder_uses_the_current_names(tmp_path, monkeypatch):
    """A sweep folder written before the rename (summary.csv and cases.jsonl with
    ``total loss [W]``): the report plots the mean total loss as such, not as a heat
    source in the stacked bars."""
    import thermobearing.report as report
    import thermobearing.report_losses as report_losses
    from thermobearing.commands.report import sweep_report
    from thermobearing.sweep import parse_set, run_sweep

    scene = load_scene()
    run_sweep(scene, [parse_set("supply.flow=10,20,33", scene.to_dict())], tmp_path,
              runner=_old_runner, workers=1, progress=False, check=False)
    # summary.csv as an earlier version left it (whatever names this sweep wrote)
    summary = (tmp_path / "summary.csv").read_text(encoding="utf-8")
    (tmp_path / "summary.csv").write_text(
        summary.replace("mean total loss [W]", "total loss [W]").replace(
            "rise over initial drive_end.housing [K]", "rise drive_end.housing [K]"),
        encoding="utf-8")
    drawn, bars = {}, {}
    real_whatif, real_bars = report.fig_whatif, report_losses.fig_sweep_breakdown

    def whatif(summary, x, ys, group=None):
        drawn[x] = list(ys)
        return real_whatif(summary, x, ys, group=group)

    def breakdown(summary, params):
        bars["columns"] = list(summary.columns)
        return real_bars(summary, params)

    monkeypatch.setattr(report, "fig_whatif", whatif)
    monkeypatch.setattr(report_losses, "fig_sweep_breakdown", breakdown)
    sweep_report(tmp_path)
    assert drawn["supply.flow [L/min]"][:1] == ["mean total loss [W]"]
    assert "rise over initial drive_end.housing [K]" in drawn["supply.flow [L/min]"]
    assert not any("total loss" in c for c in bars["columns"])
    assert "churning_elements [W]" in bars["columns"]
