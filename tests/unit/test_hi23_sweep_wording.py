"""Session 23 (HI): the sweep's messages count their cases in words ("1 case", "6 cases"),
not "1 case(s)"; one swept quantity reads in one unit throughout a sweep folder; a report
table groups the thousands of every number by one rule."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from thermobearing.commands.sweep import interrupt_message
from thermobearing.sweep_store import counted, kept_text


def test_counted_agrees_with_the_number():
    assert counted(1, "case") == "1 case"
    assert counted(0, "case") == "0 cases"
    assert counted(6, "planned case") == "6 planned cases"


def test_kept_text_agrees_verb_and_noun():
    # before: "1 finished case(s) of 6 planned are kept"
    assert kept_text(1, 6) == "1 finished case of 6 planned is kept"
    assert kept_text(2) == "2 finished cases are kept"


def test_interrupt_message_reads_singular_and_plural(tmp_path: Path):
    assert interrupt_message(tmp_path, 1, 6).startswith(
        "interrupted: 1 finished case of 6 planned is kept in")
    assert interrupt_message(tmp_path, 3, 6).startswith(
        "interrupted: 3 finished cases of 6 planned are kept in")
    one = interrupt_message(tmp_path, 0, 1)
    assert "0 of 1 planned case finished" in one and "case(s)" not in one


# --- B. one swept quantity in one unit throughout a sweep folder -------------------------
def _load_runner(scene_toml: str) -> dict[str, float]:
    """The radial load [N] and the flow [L/min] the case's scene holds (no physics)."""
    from thermobearing.scene import loads_scene

    sc = loads_scene(scene_toml)
    return {"load seen [N]": sc.schedule.steps[0].radial_load,
            "flow seen [L/min]": sc.supply.flow * 60e3}


def test_a_resume_in_other_units_keeps_the_first_runs_unit(tmp_path: Path, capsys):
    # before: 0.5 kN then "500 N,700 N" gave summary.csv's text column "0.5 kN", "700 N"
    # (and the 700 N case recorded as "700 N" in cases.jsonl): two spellings of one field
    from thermobearing.scene import load_scene
    from thermobearing.sweep import finished_cases, parse_set, run_sweep

    scene = load_scene()
    d = scene.to_dict()
    run_sweep(scene, [parse_set("schedule.radial_load=0.5 kN", d)], tmp_path,
              runner=_load_runner, workers=1, progress=False, check=False)
    df = run_sweep(scene, [parse_set("schedule.radial_load=500 N,700 N,1.5 kN", d)],
                   tmp_path, runner=_load_runner, workers=1, progress=False, check=False)
    assert df["schedule.radial_load"].tolist() == ["0.5 kN", "0.7 kN", "1.5 kN"]
    assert df["schedule.radial_load [kN]"].tolist() == [0.5, 0.7, 1.5]
    # the scene of each case holds the load itself (the unit is only its spelling)
    assert df["load seen [N]"].tolist() == [500.0, 700.0, 1500.0]
    recorded = {r["params"]["schedule.radial_load"] for r in finished_cases(tmp_path).values()}
    assert recorded == {"0.5 kN", "0.7 kN", "1.5 kN"}
    # the same values in the store's unit are the same cases: nothing runs again
    again = run_sweep(scene, [parse_set("schedule.radial_load=0.5,0.7 kN", d)], tmp_path,
                      runner=_load_runner, workers=1, progress=None, check=False)
    assert again["schedule.radial_load"].tolist() == ["0.5 kN", "0.7 kN"]
    assert "resuming: 2 of 2 cases already in" in capsys.readouterr().err


def test_one_sweep_writes_its_values_in_its_first_values_unit(tmp_path: Path):
    from thermobearing.scene import load_scene
    from thermobearing.sweep import parse_set, run_sweep

    scene = load_scene()
    p = parse_set("supply.flow=15 L/min,1200 L/h,0.55 L/s", scene.to_dict())
    df = run_sweep(scene, [p], tmp_path, runner=_load_runner, workers=1, progress=False,
                   check=False)
    assert df["supply.flow"].tolist() == ["15 L/min", "20 L/min", "33 L/min"]
    assert df["flow seen [L/min]"].tolist() == pytest.approx([15.0, 20.0, 33.0], rel=1e-12)


def test_in_store_units_keeps_what_is_not_a_quantity_of_that_unit():
    from thermobearing.sweep_params import SweepParameter, in_store_units

    records = [{"params": {"supply.flow": "15 L/min", "lubricant.preset": "ISO_VG32"}}]
    flow, preset, other = in_store_units(
        [SweepParameter("supply.flow", ("15 L/min", "900 L/h", "2 kN")),
         SweepParameter("lubricant.preset", ("ISO_VG46",)),
         SweepParameter("supply.inlet_temperature", ("313.15 K", "45 degC"))], records)
    # a value of another dimension stays as written (the scene check names it)
    assert flow.values == ("15 L/min", "15 L/min", "2 kN")
    assert preset.values == ("ISO_VG46",)
    # no record of the field: the unit of its first value, offset units converted exactly
    assert other.values == ("313.15 K", "318.15 K")


# --- C. one grouping rule for every number of a report table ----------------------------
def test_a_report_table_groups_thousands_in_every_column():
    # before: "1,031" W (fmt_power groups from 10 W) next to "1169" N mm (other columns
    # were grouped only when they reached 1e4) and "1500" r/min (an integer column)
    import numpy as np
    import pandas as pd

    from thermobearing.report_sections import html_table

    df = pd.DataFrame({"speed [rpm]": [1500, 800], "total [W]": [1031.4, 12.6],
                       "friction torque [N mm]": [1169.3, np.nan],
                       "share [%]": [55.5, 44.5], "film [um]": [0.4567, 2.0]})
    rows = [re.findall(r"<td>(.*?)</td>", row)
            for row in re.findall(r"<tr>(.*?)</tr>", html_table(df), re.S)]
    rows = [r for r in rows if r]
    assert rows == [["1,500", "1,031", "1,169", "55.5", "0.4567"],
                    ["800", "13", "\u2014", "44.5", "2"]]


# --- D. the sweep's catalogue cross-check speaks of cases --------------------------------
def test_the_sweep_crosscheck_names_its_columns_this_case():
    # before: a sweep report's cross-check headed its columns "this run [W]", "this run
    # M = P / omega [N mm]", "this run vs SKF four-term [%]" over rows of cases
    from thermobearing.report_context import CASE_TORQUE, sweep_catalogue_crosscheck
    from thermobearing.scene import loads_scene

    examples = Path(__file__).resolve().parents[2] / "examples"
    point = loads_scene((examples / "loss_point_6206_oil_bath.toml").read_text("utf-8"),
                        base_dir=examples)
    records = [{"case": "c1500", "params": {"schedule.speed": "1500 rpm"},
                "result": {"mean total loss [W]": 10.0}}]
    table, _ = sweep_catalogue_crosscheck(point, records)
    cols = list(table.columns)
    assert not [c for c in cols if c.startswith("this run")]
    assert cols[cols.index("this case [W]") + 1] == CASE_TORQUE
    assert "this case vs SKF four-term [%]" in cols
    # the moment is the case's total over its one omega: 10 W at 1500 r/min
    assert table[CASE_TORQUE].item() == pytest.approx(1e4 / (1500 * 3.141592653589793 / 30))


def test_the_zero_loss_notes_of_a_sweep_speak_of_cases():
    # before: a sweep report said "cage guide land (film shear): 0 W at every step" over a
    # table of cases (each a one-step scene); a run's breakdown keeps "at every step"
    from types import SimpleNamespace

    import pandas as pd

    from thermobearing.report_sections import source_notes

    ball = SimpleNamespace(kind="ball", cage=SimpleNamespace(guidance="rolling_element"))
    scene = SimpleNamespace(models={"kinematics": "skidding"},
                            schedule=SimpleNamespace(steps=()))
    sweep = pd.DataFrame({"case": ["a", "b"], "cage_guide [W]": [0.0, 0.0]})
    run = pd.DataFrame({"step": [0, 1], "cage_guide [W]": [0.0, 0.0]})
    (in_sweep,) = source_notes(sweep, scene, {"test": ball})
    (in_run,) = source_notes(run, scene, {"test": ball})
    assert in_sweep.startswith("cage guide land (film shear): 0 W in every case: the cage")
    assert in_run.startswith("cage guide land (film shear): 0 W at every step: the cage")
