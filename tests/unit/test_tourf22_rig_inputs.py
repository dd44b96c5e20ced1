"""Session-22 user tour A, the test-rig engineer with a 7210 BE angular-contact rig scene
written from the docs: bare numbers in a protocol, typos in the scene's names and files,
the time column mapped as a sensor, the loss range of a protocol ending with a stop, and
Ctrl-C before the first step."""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd
import pytest

from thermobearing.cli import main
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.measured import read_measured_file
from thermobearing.scene import load_scene, loads_scene, with_absolute_paths
from thermobearing.scene_schedule import Schedule
from thermobearing.simulation import Simulation, _loss_range_line

#: the catalogue 7210 BE of the tour (envelope and ball set; the rest estimated)
BEARING = """name = "7210BE"
kind = "angular_contact"
source = "catalogue envelope 50 x 90 x 20 mm, 40 deg; ball set 14 x 1/2 in typical"
estimate_missing = true
bore = "50 mm"
outer_diameter = "90 mm"
width = "20 mm"
ball_diameter = "12.7 mm"
n_balls = 14
contact_angle = "40 deg"
"""

SCENE = """title = "7210 BE rig"
[[bearings]]
name = "test"
path = "b7210.toml"
[lubricant]
preset = "ISO_VG32"
[supply]
method = "jet"
flow = {flow}
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "23 degC"
[schedule]
radial_load = "1 kN"
steps = [
  {{ duration = {duration}, speed = {speed}, axial_load = "2 kN" }},
  {{ duration = "10 min", speed = "6000 rpm", axial_load = "5 kN" }},
  {{ duration = "10 min", speed = "0 rpm", axial_load = "5 kN" }},
]
[network]
template = "four_node_paper002"
[network.parameters]
housing_outer_diameter = "160 mm"
{housing}
shaft_diameter = "50 mm"
shaft_length = "300 mm"
[outputs]
want = ["temperatures", "losses"]
{measured}"""

MEASURED = """[measured]
file = "rig_tc.csv"
time_column = "time [min]"
unit = "degC"
columns = {{ "TC1 housing [degC]" = "{node}" }}
"""


def _write(tmp_path: Path, *, flow: str = '"2 L/min"', duration: str = '"10 min"',
           speed: str = '"3000 rpm"', housing: str = 'housing_length = "60 mm"',
           measured: str = "") -> Path:
    (tmp_path / "b7210.toml").write_text(BEARING, encoding="utf-8")
    (tmp_path / "rig_tc.csv").write_text(
        "time [min],TC1 housing [degC],TC2 oil [degC]\n0,23.1,23.0\n10,30.2,41.0\n"
        "20,33.0,\n30,31.0,40.2\n", encoding="utf-8")
    path = tmp_path / "rig.toml"
    path.write_text(SCENE.format(flow=flow, duration=duration, speed=speed,
                                 housing=housing, measured=measured), encoding="utf-8")
    return path


def test_a_bare_speed_is_noted_with_its_reading_in_r_per_min(tmp_path):
    """``speed = 3000`` is 3000 rad/s (28648 r/min): before, check and run said nothing and
    the rig protocol ran 9.5 times too fast."""
    scene = load_scene(str(_write(tmp_path, speed="3000")))
    sim = Simulation(scene, progress=False)
    note = next(n for n in sim.notes if n.startswith("schedule.steps[0].speed = 3000"))
    assert "read as 3000 rad/s = 28647.9 r/min" in note
    assert '"3000 rpm"' in note
    assert f"note: {note}" in sim.describe_chain()
    assert scene.schedule.steps[0].speed == pytest.approx(3000.0)  # still SI, as documented


def test_a_bare_duration_is_noted_and_the_note_survives_absolute_paths(tmp_path):
    """``run`` makes the bearing path absolute (a TOML round trip, which writes every step
    with its unit): the note must still reach the run."""
    scene = with_absolute_paths(load_scene(str(_write(tmp_path, duration="10"))))
    notes = Simulation(scene, progress=False).notes
    assert any(n.startswith("schedule.steps[0].duration = 10 has no unit")
               and "read as 10 s = 0.166667 min" in n for n in notes)


def test_units_written_and_a_bare_zero_give_no_note():
    schedule = Schedule.from_dict({"radial_load": "1 kN", "axial_load": 0, "steps": [
        {"duration": "1 min", "speed": "1500 rpm"}, {"duration": "1 min", "speed": 0}]})
    assert schedule.unitless == ()
    many = Schedule.from_dict({"radial_load": "1 kN", "axial_load": "0 kN",
                               "speed": 100, "step_duration": 60,
                               "steps": [{"speed": 200}, {"speed": 300}]})
    speed = next(n for n in many.unitless if "speed" in n)
    assert speed.startswith("schedule.speed = 100 (and 2 more speed values without a unit)")
    assert f"{100 * 30 / math.pi:.6g} r/min" in speed
    assert any(n.startswith("schedule.step_duration = 60 has no unit") for n in many.unitless)


def test_a_bare_flow_beyond_the_range_says_it_was_read_in_cubic_metres_per_second(tmp_path):
    with pytest.raises(InputError) as err:
        load_scene(str(_write(tmp_path, flow="2")))
    text = str(err.value)
    assert text.startswith("supply.flow = 2 is not allowed")
    assert "a bare number in a scene is in m^3/s (2 m^3/s = 120000 L/min)" in text
    assert '"2 L/min"' in text
    with pytest.raises(InputError) as err:  # written with its unit: the range only
        load_scene(str(_write(tmp_path, flow='"2e5 L/min"')))
    assert "bare number" not in str(err.value)


def test_the_time_column_mapped_as_a_sensor_is_refused(tmp_path):
    """It was read as a sensor and compared with the node: 0-30 "degC" of a time in
    minutes against the shaft."""
    _write(tmp_path)
    with pytest.raises(InputError) as err:
        read_measured_file(tmp_path / "rig_tc.csv", "time [min]",
                           {"TC1 housing [degC]": "test.housing", "time [min]": "test.shaft"})
    assert err.value.field == "measured.columns['time [min]']"
    assert "this is the time column (measured.time_column)" in str(err.value)
    assert "TC1 housing [degC], TC2 oil [degC]" in str(err.value)


def test_a_misspelt_node_of_the_column_map_gets_the_nearest_node(tmp_path, capsys):
    path = _write(tmp_path, measured=MEASURED.format(node="test.housin"))
    assert main(["check", str(path)]) == 1
    err = capsys.readouterr().err
    assert "measured.columns['TC1 housing [degC]'] = 'test.housin'" in err
    assert "(did you mean 'test.housing'?)" in err


def test_a_misspelt_network_parameter_gets_the_nearest_name(tmp_path, capsys):
    path = _write(tmp_path, housing='housing_lenght = "60 mm"')
    assert main(["check", str(path)]) == 1
    err = capsys.readouterr().err
    assert "network.parameters.housing_lenght = '60 mm' is not allowed" in err
    assert "(did you mean 'housing_length'?)" in err


def test_a_missing_bearing_file_and_an_unknown_preset_name_their_scene_field(tmp_path):
    """They were ``bearing path = ... an existing TOML file`` (no field of the scene, no
    place looked at) and ``bearing preset = ...``."""
    path = _write(tmp_path)
    text = path.read_text(encoding="utf-8")
    scene = loads_scene(text.replace("b7210.toml", "b7211.toml"), base_dir=tmp_path)
    with pytest.raises(InputError) as err:
        Simulation(scene, progress=False)
    assert err.value.field == "bearings[0].path"
    assert f"looked at {tmp_path / 'b7211.toml'}" in str(err.value)
    scene = loads_scene(text.replace('path = "b7210.toml"', 'preset = "QJ1044x"'),
                        base_dir=tmp_path)
    with pytest.raises(UnknownNameError) as err:
        Simulation(scene, progress=False)
    assert err.value.field == "bearings[0].preset"
    assert "(did you mean 'QJ1044'?)" in str(err.value)


def test_an_out_that_is_a_file_is_refused_before_the_chain_is_printed(tmp_path, capsys):
    path = _write(tmp_path)
    assert main(["run", str(path), "--out", str(path)]) == 1
    captured = capsys.readouterr()
    assert "model chain" not in captured.out
    assert f"--out = '{path}' is not allowed" in captured.err


def test_ctrl_c_before_the_first_step_says_nothing_was_computed(tmp_path, capsys,
                                                                monkeypatch):
    """It said "everything computed so far is in DIR/" of an empty folder (or one with the
    scene and metadata only) and named a report that had no step to show."""
    def interrupted(self, out_dir=None):
        self.steps_done = 0
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        (Path(out_dir) / "metadata.json").write_text("{}", encoding="utf-8")
        raise KeyboardInterrupt

    monkeypatch.setattr(Simulation, "run", interrupted)
    out = tmp_path / "res"
    assert main(["run", str(_write(tmp_path)), "--out", str(out), "--quiet"]) == 130
    err = capsys.readouterr().err
    assert "interrupted before the first of 3 steps finished: no step was computed" in err
    assert "everything computed so far" not in err
    assert "thermobearing report" not in err


def test_ctrl_c_after_some_steps_says_how_many(tmp_path, capsys, monkeypatch):
    def interrupted(self, out_dir=None):
        self.steps_done = 0
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        (Path(out_dir) / "metadata.json").write_text("{}", encoding="utf-8")
        self.log_step(0, 600.0)
        raise KeyboardInterrupt

    monkeypatch.setattr(Simulation, "run", interrupted)
    out = tmp_path / "res"
    assert main(["run", str(_write(tmp_path)), "--out", str(out), "--quiet"]) == 130
    err = capsys.readouterr().err
    assert (f"interrupted: everything computed so far is in {out}/ (1 of 3 steps; "
            f"`thermobearing report {out}` writes their report)") in err


def _losses(speeds_and_watts):
    rows = []
    for step, (rpm, watts) in enumerate(speeds_and_watts):
        rows += [{"step": step, "bearing": "test", "speed [rpm]": rpm, "source": s,
                  "power [W]": watts / 2} for s in ("a", "b")]
    return pd.DataFrame(rows)


def test_the_terminal_loss_range_leaves_out_the_steps_at_rest():
    """A protocol ending with a stop printed "total loss per bearing: 0 - 400 W"."""
    line = _loss_range_line(_losses([(3000.0, 49.62), (9000.0, 400.3), (0.0, 0.0)]))
    assert line == "total loss per bearing: 49.6 - 400 W (turning steps; 0 W at rest: step 2)"
    assert _loss_range_line(_losses([(3000.0, 49.62)])) == "total loss per bearing: 49.6 W"
    assert _loss_range_line(_losses([(0.0, 0.0), (0.0, 0.0)])) == \
        "total loss per bearing: 0 W"


def test_schedule_file_columns_without_a_unit_are_noted(tmp_path):
    """A protocol file ``duration,speed,...`` of 10,3000,1,2 ran 10-s steps under 1-2 N
    without a word (the defaults s, rpm, N, N are in the scene docstring only)."""
    (tmp_path / "proto.csv").write_text(
        "duration,speed [rpm],radial_load,axial_load [kN]\n10,3000,1,2\n10 min,6000,1,2\n",
        encoding="utf-8")
    schedule = Schedule.from_dict({"file": "proto.csv"}, tmp_path)
    notes = "\n".join(schedule.unitless)
    assert ("schedule.file proto.csv: column 'duration' has no [unit]: its numbers are "
            "read in s (10 = 10 s); write the unit in the header, e.g. 'duration [min]'"
            ) in notes
    assert "column 'radial_load' has no [unit]: its numbers are read in N" in notes
    assert "'speed [rpm]'" not in notes and "axial_load [kN]'" not in notes
    assert [s.duration for s in schedule.steps] == [10.0, 600.0]


def test_an_empty_scene_file_says_so(tmp_path, capsys):
    """It said "scene.title is missing", as if the rest were there."""
    empty = tmp_path / "new.toml"
    empty.write_text("# my rig\n", encoding="utf-8")
    assert main(["check", str(empty)]) == 1
    err = capsys.readouterr().err
    assert "this TOML has no key at all (an empty or unsaved file?)" in err
    assert "scene.title" not in err


def test_a_run_without_a_compared_reading_does_not_announce_the_readings_file(tmp_path,
                                                                              capsys):
    """A file whose times all lie after the run: the terminal named
    measured_vs_predicted.csv as "every compared reading" although it has no row."""
    scene = _write(tmp_path, measured=MEASURED.format(node="test.housing"))
    (tmp_path / "rig_tc.csv").write_text(
        "time [min],TC1 housing [degC]\n100,30.0\n110,31.0\n", encoding="utf-8")
    out = tmp_path / "res"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "no measured time inside the run" in text
    assert "every compared reading" not in text
    assert (out / "measured_vs_predicted.csv").read_text(encoding="utf-8").count("\n") == 1


def test_a_runaway_names_its_step_as_the_tables_number_it():
    """After the progress line "step 3/5 done" the error said "[..., step=3]": the 4th
    step (the tables count from 0), read as the step that had just finished."""
    import numpy as np

    from thermobearing.coupled import _check_runaway, _Linear
    from thermobearing.errors import ConvergenceError

    lin = _Linear(np.array([1771.0, 0.0]), np.zeros((2, 2)), np.full(2, 300.0))
    with pytest.raises(ConvergenceError) as err:
        _check_runaway(["test.balls", "test.oil"], np.array([580.15, 330.0]), 1830.0, 3, lin)
    assert ("reached 307 degC at t = 1830 s (limit 300 degC), in step 3 (numbered from 0, "
            "as in the tables), with 1771 W of heat") in str(err.value)


def test_report_of_a_run_whose_measured_file_moved_is_written_without_the_overlay(
        tmp_path, capsys):
    """`thermobearing report DIR` stopped with "an existing data file" after the rig's CSV
    was moved: no report at all, though the folder keeps the compared readings."""
    scene = _write(tmp_path, measured=MEASURED.format(node="test.housing"))
    out = tmp_path / "res"
    assert main(["run", str(scene), "--out", str(out), "--quiet"]) == 0
    (tmp_path / "rig_tc.csv").rename(tmp_path / "moved.csv")
    (out / "report.html").unlink()
    capsys.readouterr()
    assert main(["report", str(out)]) == 0
    err = capsys.readouterr().err
    assert "rig_tc.csv is no longer there: this report has no measured-vs-predicted section" \
        in err
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "is no longer there" in html
    assert "measured_vs_predicted.csv of this folder" in html


def test_a_run_into_the_scene_s_own_folder_does_not_replace_its_inputs(tmp_path, capsys):
    """``thermobearing run scene.toml --out .`` replaced the user's scene file (comments
    lost) with the run's copy; a rig file named temperatures.csv would have been replaced
    by the prediction."""
    scene = _write(tmp_path)
    mine = tmp_path / "scene.toml"
    mine.write_text("# my notes\n" + scene.read_text(encoding="utf-8"), encoding="utf-8")
    assert main(["run", str(mine), "--out", str(tmp_path), "--quiet"]) == 1
    assert "the scene (" in capsys.readouterr().err
    assert mine.read_text(encoding="utf-8").startswith("# my notes")
    (tmp_path / "rig_tc.csv").rename(tmp_path / "temperatures.csv")
    measured = MEASURED.format(node="test.housing").replace("rig_tc.csv", "temperatures.csv")
    scene = _write(tmp_path, measured=measured)
    (tmp_path / "rig_tc.csv").unlink()  # (_write wrote it again)
    before = (tmp_path / "temperatures.csv").read_text(encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path), "--quiet"]) == 1
    assert "measured.file" in capsys.readouterr().err
    assert (tmp_path / "temperatures.csv").read_text(encoding="utf-8") == before
    assert main(["sweep", str(mine), "--set", "supply.flow=2", "--out", str(tmp_path),
                 "-j", "1"]) == 1
    assert "the scene (" in capsys.readouterr().err


def test_a_rerun_from_a_results_folder_s_own_scene_copy_is_allowed(tmp_path, capsys):
    scene = _write(tmp_path)
    out = tmp_path / "res"
    assert main(["run", str(scene), "--out", str(out), "--quiet"]) == 0
    assert main(["run", str(out / "scene.toml"), "--out", str(out), "--quiet"]) == 0
