"""Report and sweep-report wording left by the session-22 user tours: each test pins a
defect seen in a report or on the terminal, written before its fix (the "before" in the
comments is what the report said).

The sweeps run with a small deterministic runner (the physics runner is tested
elsewhere): what is under test is what the folder records and what the report says.
"""

from __future__ import annotations

import json

import matplotlib.figure
import numpy as np
import pandas as pd
import pytest

from thermobearing import cli
from thermobearing.commands.report import (
    case_count_text,
    film_curves,
    flagged_cases,
    per_bearing_totals,
    sweep_report,
)
from thermobearing.commands.sweep import interrupt_message
from thermobearing.errors import InputError
from thermobearing.report import fig_csr
from thermobearing.report_losses import summary_lines
from thermobearing.report_measured import (
    ALL_GAPS,
    NO_SAMPLE,
    comparison_notes,
    fig_temperatures,
    temperature_errors,
    terminal_lines,
)
from thermobearing.scene import Scene, load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep
from thermobearing.sweep_store import PLANNED_FILE, planned_cases


def loss_runner(scene_toml: str) -> dict[str, float]:
    """A mean total loss that grows with the flow [W], and the oil's film parameter
    falling with the inlet temperature (a stand-in: what matters is the column)."""
    sc = loads_scene(scene_toml)
    return {"mean total loss [W]": 1e6 * sc.supply.flow,
            "min film parameter [-]": 400.0 / sc.supply.inlet_temperature}


@pytest.fixture(scope="module")
def scene():
    return load_scene()  # the default scene: one bearing (QJ1044 rig of paper 002)


def _legend_texts(monkeypatch) -> list[list[str]]:
    """Collects the legend entries of every axes of each figure saved."""
    seen: list[list[str]] = []
    real_save = matplotlib.figure.Figure.savefig

    def save(self, *args, **kwargs):
        for ax in self.axes:
            legend = ax.get_legend()
            seen.append([t.get_text() for t in legend.get_texts()] if legend else [])
        return real_save(self, *args, **kwargs)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", save)
    return seen


# --- 1. one case, one bearing, one step ------------------------------------------------
def test_a_one_case_one_bearing_sweep_report_speaks_in_the_singular(scene, tmp_path):
    out = tmp_path / "sw"
    run_sweep(scene, [parse_set("supply.flow=15", scene.to_dict())], out,
              runner=loss_runner, workers=1, progress=False)
    html = sweep_report(out).read_text(encoding="utf-8")
    # before: "1 cases; swept: supply.flow ... <code>mean total loss <bearing> [W]</code>
    # per bearing." on a summary without such a column
    # run_sweep records its plan too: one planned case, every one finished
    assert "<p>1 case (every planned case finished); swept: supply.flow." in html
    assert "1 cases" not in html and "per bearing" not in html
    assert per_bearing_totals(["mean total loss [W]", "case"]) == []
    assert per_bearing_totals(["mean total loss [W]", "mean total loss de [W]"]) == [
        "mean total loss de [W]"]


def test_every_case_with_one_flagged_step_says_step():
    df = pd.DataFrame({"flow": [15.0, 33.0], "steps over skid limit [-]": [1, 1]})
    (note,) = flagged_cases(df, ["flow"])
    # before: "every case, 1 steps each"
    assert note.endswith(": every case, 1 step each")
    (one,) = flagged_cases(df.iloc[:1], ["flow"])
    # before: "1 of 1 cases have steps"
    assert one.startswith("1 of 1 case has steps with cage skidding")


# --- 2. an interrupted sweep says how many of its planned cases finished ---------------
def test_an_interrupted_sweep_reports_the_cases_it_did_not_run(scene, tmp_path,
                                                                 monkeypatch, capsys):
    import thermobearing.simulation as simulation

    calls = []

    def stop_after_one(text):
        if calls:
            raise KeyboardInterrupt
        calls.append(text)
        return loss_runner(text)

    monkeypatch.setattr(simulation, "summarize_scene", stop_after_one)
    out = tmp_path / "sw"
    code = cli.main(["sweep", "--set", "supply.flow=15,20,25", "--set",
                     "supply.inlet_temperature=30,40,50 degC", "--out", str(out),
                     "--workers", "1", "--quiet"])
    err = capsys.readouterr().err
    assert code == 130
    # before: "1 finished case(s) are kept" and nothing of the 8 not run
    assert "interrupted: 1 finished case of 9 planned is kept in" in err
    ids = planned_cases(out)
    assert ids is not None and len(ids) == 9
    record = json.loads((out / PLANNED_FILE).read_text(encoding="utf-8"))
    assert record["planned"] == 9 and len(record["cases"]) == 9
    assert record["cases"][0]["params"] == {"supply.flow": "15 L/min",
                                            "supply.inlet_temperature": "30 degC"}
    html = sweep_report(out).read_text(encoding="utf-8")
    # before: "1 cases; swept: ..." and nothing of the 8 cases not run
    assert "<p>1 of 9 planned cases finished (the sweep was stopped before the others " \
        "ran" in html


def test_a_folder_without_the_planned_record_says_nothing_of_planned_cases():
    df = pd.DataFrame({"case": ["a", "b"]})
    assert case_count_text(df, None) == "2 cases"
    assert case_count_text(df.iloc[:1], None) == "1 case"
    assert case_count_text(df, ["a", "b", "c"]).startswith("2 of 3 planned cases finished")
    # a folder whose summary is of an earlier plan: counted apart
    assert case_count_text(df, ["a"]) == ("1 case (every planned case finished); the "
                                          "summary also has 1 case of an earlier sweep in "
                                          "this folder")


# --- 3. interrupted before the first case: a sweep folder, not a run --------------------
def test_a_sweep_stopped_before_its_first_case_is_not_reported_as_a_run(tmp_path,
                                                                      monkeypatch, capsys):
    import thermobearing.simulation as simulation

    def interrupted(text):
        raise KeyboardInterrupt

    monkeypatch.setattr(simulation, "summarize_scene", interrupted)
    out = tmp_path / "sw"
    assert cli.main(["sweep", "--set", "supply.flow=15,33", "--out", str(out), "--workers",
                     "1", "--quiet"]) == 130
    err = capsys.readouterr().err
    # before: "nothing was kept" while scene.toml was written
    assert "nothing was kept" not in err
    assert "0 of 2 planned cases finished" in err and "scene.toml" in err
    assert (out / "scene.toml").is_file() and (out / PLANNED_FILE).is_file()
    assert not (out / "cases.jsonl").exists()
    # before: the report read scene.toml as a run's and wrote a run report of nothing
    assert cli.main(["report", str(out)]) == 1
    err = capsys.readouterr().err
    assert "is a sweep folder whose sweep stopped before its first case finished" in err
    assert "0 of 2 planned cases finished" in err
    assert not (out / "report.html").exists()


def test_a_sweep_refused_before_it_starts_leaves_no_record(scene, tmp_path, capsys):
    out = tmp_path / "sw"
    assert cli.main(["sweep", "--set", "lubricant.preset=ISO_VG99", "--out", str(out),
                     "--workers", "1", "--quiet"]) != 0
    assert "no case was run" in capsys.readouterr().err
    assert not (out / PLANNED_FILE).exists()


def test_the_interrupt_message_of_a_folder_without_a_started_sweep(tmp_path):
    assert "nothing was kept" in interrupt_message(tmp_path, 0, None)
    assert interrupt_message(tmp_path, 2, None).startswith(
        "interrupted: 2 finished cases are kept in")


# --- 4. a sensor whose every reading is a gap ---------------------------------------------
def _temps() -> pd.DataFrame:
    t = np.arange(0.0, 601.0, 60.0)
    return pd.DataFrame({"time [s]": t, "de.housing [degC]": 35.0 + t / 60.0,
                         "de.oil [degC]": 35.0 + t / 120.0})


def test_a_sensor_of_gaps_only_is_said_so_and_kept_out_of_the_legend(monkeypatch):
    t = np.arange(0.0, 601.0, 120.0)
    measured = pd.DataFrame({"time [s]": t, "TC1": 35.5 + t / 60.0, "TC2": np.nan,
                             "TC3": 36.0})
    measured.loc[:, "TC3"] = np.where(t > 0, np.nan, 36.0)
    columns = {"TC1": "de.housing", "TC2": "de.oil", "TC3": "de.oil"}
    err = temperature_errors(_temps(), measured, columns).set_index("sensor")
    # before: "no sample inside the run" for a sensor without a single reading
    assert err.loc["TC2", "note"] == ALL_GAPS and err.loc["TC2", "points"] == 0
    assert err.loc["TC1", "note"] == "" and err.loc["TC3", "points"] == 1
    notes = comparison_notes(measured, _temps(), columns)
    assert f"TC2: {ALL_GAPS} (left out of the errors)" in notes
    assert not any(n.startswith(f"TC2: {NO_SAMPLE}") for n in notes)
    assert f"TC2 {ALL_GAPS}" in terminal_lines(measured, _temps(), columns)[0]
    seen = _legend_texts(monkeypatch)
    fig_temperatures(_temps(), measured, columns)
    (legend,) = seen
    # before: an entry "TC2 (measured, de.oil)" with no point
    assert "TC1 (measured, de.housing)" in legend and "TC3 (measured, de.oil)" in legend
    assert not any(x.startswith("TC2") for x in legend)


# --- 5. the loss range leaves the steps at rest out ---------------------------------------
def test_the_loss_range_is_that_of_the_turning_steps():
    breakdown = pd.DataFrame({"bearing": "test", "step": [1, 2, 3, 4],
                              "speed [rpm]": [600.0, 1200.0, 1800.0, 0.0],
                              "friction [W]": [100.0, 250.0, 400.0, 0.0],
                              "total [W]": [100.0, 250.0, 400.0, 0.0]})
    (line,) = summary_lines(breakdown)
    # before: "total loss 0 W (step 4, 0 r/min) to 400 W (step 3, 1800 r/min)"
    assert line.startswith("bearing test: total loss 100 W (step 1, 600 r/min) to 400 W "
                           "(step 3, 1800 r/min) over the turning steps (at rest, 0 r/min "
                           "and no loss, left out: step 4)")
    (moving,) = summary_lines(breakdown.iloc[:3])
    assert "turning" not in moving and "at rest" not in moving
    (still,) = summary_lines(breakdown.iloc[3:])  # nothing turns: the one step stays
    assert still.startswith("bearing test: total loss 0 W (step 4, 0 r/min)")


# --- 6. no empty legend entry for a step at rest in the cage-speed-ratio figure ---------
def test_the_cage_speed_figure_names_no_step_at_rest(monkeypatch):
    kin = pd.DataFrame({"bearing": "test", "step": [1, 2, 3, 4, 5],
                        "speed [rpm]": [600.0, 600.0, 1800.0, 1800.0, 0.0],
                        "axial load [kN]": [2.0, 5.0, 2.0, 5.0, 5.0],
                        "cage speed ratio [-]": [0.99, 0.995, 0.97, 0.98, np.nan],
                        "theoretical cage speed ratio [-]": [1.0, 1.0, 1.0, 1.0, 1.0]})
    seen = _legend_texts(monkeypatch)
    fig_csr(kin)
    (legend,) = seen
    # before: "test, 0 r/min" listed beside the two speeds, with no point
    assert legend == ["test, 600 r/min", "test, 1800 r/min", "theoretical (epicyclic) CSR"]


# --- 7. a scene temperature at the runaway limit -------------------------------------------
@pytest.mark.parametrize(("section", "key", "value", "kelvin_note"), [
    ("supply", "inlet_temperature", "300 degC", None),
    ("supply", "inlet_temperature", 600, "600 K = 326.85 degC"),
    ("environment", "ambient_temperature", "320 degC", None),
    ("environment", "initial_temperature", 573.15, "573.15 K = 300 degC"),
])
def test_a_scene_temperature_at_the_runaway_limit_is_refused(scene, section, key, value,
                                                            kelvin_note):
    d = scene.to_dict()
    d.setdefault(section, {})[key] = value
    # before: accepted; the run stopped as a thermal runaway
    with pytest.raises(InputError, match="runaway limit") as exc:
        Scene.from_dict(d)
    assert exc.value.field == f"{section}.{key}" and exc.value.value == value
    if kelvin_note:
        assert f"a bare number is read in kelvin ({kelvin_note})" in str(exc.value)
    else:
        assert "kelvin" not in str(exc.value)
    d[section][key] = "299 degC"  # below the limit: read as before
    assert Scene.from_dict(d) is not None


# --- 8. the film in the what-if figures ------------------------------------------------
def test_the_whatif_figures_show_the_film_parameter(scene, tmp_path, monkeypatch):
    import thermobearing.report as report

    drawn: dict[str, list[str]] = {}
    real = report.fig_whatif

    def whatif(df, x, ys, group=None):
        drawn[x] = list(ys)
        return real(df, x, ys, group=group)

    monkeypatch.setattr(report, "fig_whatif", whatif)
    out = tmp_path / "sw"
    run_sweep(scene, [parse_set("supply.inlet_temperature=30,50 degC", scene.to_dict())],
              out, runner=loss_runner, workers=1, progress=False)
    sweep_report(out)
    # before: the mean total loss alone (the runner gives no temperature)
    ys = drawn["supply.inlet_temperature [degC]"]
    assert ys == ["mean total loss [W]", "min film parameter [-]"]
    summary = pd.read_csv(out / "summary.csv")
    lam = summary.sort_values("supply.inlet_temperature [degC]")["min film parameter [-]"]
    assert lam.iloc[1] < lam.iloc[0]  # the stand-in runner's thinner film when hotter
    no_film = summary.drop(columns=["min film parameter [-]"])
    assert film_curves(no_film, list(no_film.columns)) == []
    elements = summary.assign(**{"final de.balls [degC]": [50.0, 60.0]})
    assert film_curves(elements, list(elements.columns)) == [
        "final de.balls [degC]", "min film parameter [-]"]


def test_run_sweep_records_its_plan_before_the_first_case(scene, tmp_path):
    """run_sweep (Python, no command line) writes planned_cases.json before any case runs,
    so a sweep killed in its first case still leaves its plan (was: only the sweep command
    wrote it, at the sweep's end)."""
    out = tmp_path / "plan"
    seen: list[bool] = []

    def first_case_looks(text):
        seen.append((out / PLANNED_FILE).exists())
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(scene, [parse_set("supply.flow=15,20", scene)], out_dir=out,
                  runner=first_case_looks, workers=1, progress=False)
    assert seen == [True]
    assert planned_cases(out) is not None and len(planned_cases(out)) == 2
