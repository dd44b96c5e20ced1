"""An oil-flow what-if study from the command line (issue 6, a user tour of flow-rate,
inlet-temperature and oil-grade sweeps on the default rig and a catalogue bearing): each
test is a defect found by running ``thermobearing sweep`` / ``report``, written before its
fix.
"""

from __future__ import annotations

import textwrap

import pytest
from scene_parts import PAPER002_AMBIENT, PAPER002_JET, scene_title

from thermobearing.network import oil_capacity_rate
from thermobearing.scene import load_scene, loads_scene
from thermobearing.simulation import Simulation, summarize_scene

#: one steady operating point of the default rig (one QJ1044, 1800 r/min, 20 kN axial)
STEADY_RIG = scene_title("QJ1044 rig, one steady point") + textwrap.dedent("""\
    [[bearings]]
    name = "drive_end"
    preset = "QJ1044"
    """) + PAPER002_JET + PAPER002_AMBIENT + textwrap.dedent("""\
    [schedule]
    speed = "1800 rpm"
    radial_load = "1 kN"
    axial_load = "20 kN"
    steps = [{ duration = "3 min" }]
    [network]
    template = "four_node_paper002"
    parameters.housing_outer_diameter = "510 mm"
    parameters.housing_length = "140 mm"
    parameters.shaft_diameter = "220 mm"
    parameters.shaft_length = "500 mm"
    [outputs]
    mode = "steady"
    want = ["temperatures", "losses", "kinematics"]
""")


# --- a steady what-if sweep gave no temperatures --------------------------------------
def test_steady_scene_summary_has_the_steady_temperatures():
    # before: summarize_scene read only the transient 'temperatures' table, so a sweep of a
    # steady scene (the quick what-if: one steady point per flow) had losses and skidding
    # but no oil outlet, ball or housing temperature at all
    out = summarize_scene(STEADY_RIG)
    steady = Simulation(loads_scene(STEADY_RIG), progress=False).run() \
        .tables["steady_temperatures"]
    for node in ("balls", "housing", "shaft", "oil"):
        col = f"drive_end.{node} [degC]"
        assert out[f"final {col}"] == pytest.approx(float(steady[col].iloc[-1]), abs=1e-9)
        assert out[f"rise over ambient drive_end.{node} [K]"] == pytest.approx(
            float(steady[col].iloc[-1]) - 35.0, abs=1e-9)
    # the oil stream carries part of the loss away (energy balance of the steady state):
    # m_dot c_p (T_out - T_in) is positive and not above the total loss
    scene = loads_scene(STEADY_RIG)
    lub = Simulation(scene, progress=False).lubricant
    carried = oil_capacity_rate(lub, scene.supply.flow, scene.supply.inlet_temperature) \
        * out["rise over ambient drive_end.oil [K]"]
    assert 0.0 < carried <= out["mean total loss [W]"]



def capacity_runner(scene_toml: str) -> dict[str, float]:
    """The oil flow [L/min] of a case: enough to see which case ran with which flow,
    without the physics."""
    return {"flow seen [L/min]": loads_scene(scene_toml).supply.flow * 60e3}


# --- flows in m3/s (and other data-sheet spellings) lost their numeric column ------------
@pytest.mark.parametrize("spec, column, numbers", [
    ("supply.flow=2.5e-4,5.5e-4 m3/s", "supply.flow [m3/s]", [2.5e-4, 5.5e-4]),
    ("supply.flow=900 L/h,5.5e-4 m3/s", "supply.flow [L/h]", [900.0, 1980.0]),
    ("schedule.speed=1500,1800 r/min", "schedule.speed [r/min]", [1500.0, 1800.0]),
])
def test_summary_numeric_column_reads_data_sheet_units(tmp_path, spec, column, numbers):
    # before: summary.csv had 'supply.flow' with "0.00025 m3/s" but no numeric
    # 'supply.flow [m3/s]' column (the scene reads m3/s, the summary asked pint directly),
    # so the table did not plot and the unit was nowhere in a column name
    from thermobearing.sweep import parse_set, run_sweep

    scene = load_scene()
    df = run_sweep(scene, [parse_set(spec, scene.to_dict())], tmp_path, workers=1,
                   runner=capacity_runner, progress=False, check=False)
    assert column in df.columns
    assert df[column].tolist() == pytest.approx(numbers, rel=1e-12)


def test_same_speed_in_rpm_and_r_per_min_is_one_case():
    # before: "1800 rpm" and "1800 r/min" were two values (two identical cases run)
    from thermobearing.sweep import parse_set

    p = parse_set("schedule.speed=1800 rpm,1800 r/min,1500 r/min", load_scene().to_dict())
    assert p.values == ("1800 rpm", "1500 r/min")
    assert len(p.dropped) == 1 and "1800 r/min" in p.dropped[0]


# --- -j / --jobs, as `thermobearing validate` spells it ---------------------------------
def test_sweep_takes_jobs_like_validate(tmp_path, monkeypatch):
    # before: `thermobearing sweep -j 2 ...` was "unrecognized arguments: -j" while
    # `validate` takes -j N; --workers stays
    import pandas as pd

    from thermobearing import cli

    seen = []

    def fake_run_sweep(scene, params, out, *, workers=None, **kwargs):
        seen.append(workers)
        return pd.DataFrame({"case": ["a"], "supply.flow": ["15 L/min"],
                             "flow seen [L/min]": [15.0]})

    monkeypatch.setattr("thermobearing.commands.sweep.run_sweep", fake_run_sweep)
    for flag in ("-j", "--jobs", "--workers"):
        assert cli.main(["sweep", "--set", "supply.flow=15,33", "--out",
                         str(tmp_path / flag.strip("-")), flag, "2", "--quiet"]) == 0
    assert seen == [2, 2, 2]


# --- a failing case in a process pool: the queued cases ran and their results were lost --
def _marking_runner(scene_toml: str) -> dict[str, float]:
    """The 10 L/min case fails at once; every other case takes 0.3 s and leaves a marker
    file (in $TOUR_MARKS) when it finished, whether or not the sweep records it."""
    import os
    import time
    from pathlib import Path

    from thermobearing.errors import ConvergenceError

    flow = round(loads_scene(scene_toml).supply.flow * 60e3, 6)
    if flow == 10.0:
        raise ConvergenceError("kinematics (skidding)", 6.7e-4, "no convergence", {})
    time.sleep(0.3)
    Path(os.environ["TOUR_MARKS"], f"{flow:g}").touch()
    return {"flow seen [L/min]": flow}


def test_failing_case_in_a_pool_keeps_the_running_ones_and_starts_no_other(tmp_path,
                                                                           monkeypatch):
    # before: the error left the pool's with-block, which ran every queued case to the
    # end (6 here) and recorded none of those finished after the failure
    from thermobearing.errors import ConvergenceError
    from thermobearing.sweep import finished_cases, parse_set, run_sweep

    marks = tmp_path / "marks"
    marks.mkdir()
    monkeypatch.setenv("TOUR_MARKS", str(marks))
    scene = load_scene()
    p = parse_set("supply.flow=10,15,20,25,30,35,40", scene.to_dict())
    with pytest.raises(ConvergenceError, match=r"supply.flow=10 L/min.*finished case"):
        run_sweep(scene, [p], tmp_path / "sw", runner=_marking_runner, workers=2,
                  progress=False, check=False)
    ran = {f.name for f in marks.iterdir()}
    kept = {f"{r['result']['flow seen [L/min]']:g}"
            for r in finished_cases(tmp_path / "sw").values()}
    assert ran == kept  # every case that finished is in the store
    assert len(ran) < 6  # the queued cases were not started after the failure


_INTERRUPTING_SWEEP = """
import os, signal, sys, time
from pathlib import Path

from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep


def runner(scene_toml):
    # the 15 L/min case presses Ctrl-C (SIGINT to the sweep's process); every case writes
    # its process id to $TOUR_MARKS/pid-<flow> and then takes 20 s
    flow = round(loads_scene(scene_toml).supply.flow * 60e3, 6)
    Path(os.environ["TOUR_MARKS"], f"pid-{flow:g}").write_text(str(os.getpid()))
    if flow == 15.0:
        time.sleep(0.2)
        os.kill(int(os.environ["TOUR_MAIN_PID"]), signal.SIGINT)
    time.sleep(20.0)
    return {"flow seen [L/min]": flow}


if __name__ == "__main__":
    # Ctrl-C at a terminal: a process started in the background of a non-interactive shell
    # (a CI runner's `cmd &`) inherits SIGINT ignored, and the press would never arrive
    signal.signal(signal.SIGINT, signal.default_int_handler)
    os.environ["TOUR_MAIN_PID"] = str(os.getpid())
    scene = load_scene()
    p = parse_set("supply.flow=15,20,25", scene.to_dict())
    t0 = time.monotonic()
    try:
        run_sweep(scene, [p], Path(sys.argv[1]), runner=runner, workers=2, progress=False,
                  check=False)
    except KeyboardInterrupt:
        print(f"interrupted after {time.monotonic() - t0:.1f} s")
        sys.exit(3)
    print("finished")
"""


def test_ctrl_c_in_a_pool_stops_the_running_cases(tmp_path):
    # before: after Ctrl-C the workers ran on (the command said "interrupted", then
    # waited at its exit for the running and queued cases to end, about two minutes on
    # the default rig with cold workers, and recorded none of them). The sweep runs in a
    # fresh interpreter, as the command does, with Python's own SIGINT handler (a test
    # session started in the background of a non-interactive shell inherits SIGINT
    # ignored: the in-process version of this test then saw no KeyboardInterrupt).
    import os
    import subprocess
    import sys
    from pathlib import Path

    marks = tmp_path / "marks"
    marks.mkdir()
    script = tmp_path / "sweep_ctrl_c.py"
    script.write_text(_INTERRUPTING_SWEEP, encoding="utf-8")
    root = Path(__file__).resolve().parents[2]
    env = {**os.environ, "TOUR_MARKS": str(marks),
           "PYTHONPATH": os.pathsep.join(filter(None, [str(root),
                                                       os.environ.get("PYTHONPATH")]))}
    proc = subprocess.run([sys.executable, str(script), str(tmp_path / "sw")], env=env,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 3, proc.stdout + proc.stderr
    assert "interrupted after" in proc.stdout
    # stopped at once, not after the running 20-s cases (or the queued one) ended
    assert float(proc.stdout.split("interrupted after")[1].split()[0]) < 15.0
    pids = [int(f.read_text()) for f in marks.iterdir()]
    assert pids  # the cases had started
    for pid in pids:  # their workers are gone when the sweep returns
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            continue
        # a zombie not yet reaped by init counts as gone
        status = Path(f"/proc/{pid}/status")
        assert status.exists() and "zombie" in status.read_text().lower(), pid


# --- a case that does not converge: "rerun the same command to resume" -------------------
def test_failed_case_message_says_a_rerun_fails_the_same_way(tmp_path, capsys, monkeypatch):
    # before: "... are kept in DIR/cases.jsonl (rerun the same command to resume)": the
    # rerun starts with the failed case and stops there again (40 L/min at 40 degC inlet
    # on the default rig: the ball skidding solver stops at residual 6.7e-4 at 4 kN), so
    # a serial sweep never reaches the cases after it
    import thermobearing.simulation as simulation
    from thermobearing import cli
    from thermobearing.errors import ConvergenceError

    def runner(text):
        if loads_scene(text).supply.flow > 30e-3 / 60:
            raise ConvergenceError("kinematics (skidding)", 6.7e-4, "no convergence", {})
        return capacity_runner(text)

    monkeypatch.setattr(simulation, "summarize_scene", runner)
    args = ["sweep", "--set", "supply.flow=15,40", "--out", str(tmp_path / "sw"), "-j", "1",
            "--quiet"]
    assert cli.main(args) != 0
    err = capsys.readouterr().err
    assert "supply.flow=40 L/min" in err and "1 finished case is kept" in err
    assert "fails again" in err and "--keep-going" in err


# --- an oil grade from the user's own lubricant file ----------------------------------
def test_lubricant_file_sweep_replaces_the_preset_and_reads_from_here(tmp_path, monkeypatch):
    # before: `--set lubricant.path=my_vg150.toml` failed with "lubricant = {'preset':
    # 'ISO_VG46', 'path': '.../configs/scenes/my_vg150.toml'} is not allowed: exactly one of
    # 'preset' or 'path'": the preset stayed, and the file typed on the command line was
    # looked for in the scene's folder
    from thermobearing.scene import configs_dir
    from thermobearing.sweep import expand, parse_set

    text = (configs_dir() / "lubricants" / "ISO_VG68.toml").read_text(encoding="utf-8")
    (tmp_path / "my_vg68.toml").write_text(text.replace('"ISO_VG68"', '"MY_VG68"'),
                                           encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    scene = load_scene()
    p = parse_set("lubricant.path=my_vg68.toml", scene.to_dict())
    assert p.values == (str(tmp_path / "my_vg68.toml"),)
    (case,) = expand(scene, [p])
    lub = loads_scene(case.scene_toml).lubricant
    assert lub.get("path") == str(tmp_path / "my_vg68.toml") and "preset" not in lub
    # and back: a preset swept on a scene that names a file drops the file
    q = parse_set("lubricant.preset=ISO_VG32", loads_scene(case.scene_toml).to_dict())
    (back,) = expand(loads_scene(case.scene_toml), [q])
    assert loads_scene(back.scene_toml).lubricant == {"preset": "ISO_VG32"}


# --- a bearing from the user's own file on a preset scene ------------------------------
def test_bearing_file_sweep_replaces_the_preset(tmp_path, monkeypatch):
    # before: `--set bearings.0.path=my_qj1044.toml` on the default scene was refused with
    # "'bearings.0.path' is not allowed: an existing scene field" (the bearing names a preset)
    from thermobearing.scene import configs_dir
    from thermobearing.sweep import expand, parse_set

    text = (configs_dir() / "bearings" / "QJ1044.toml").read_text(encoding="utf-8")
    (tmp_path / "my_qj1044.toml").write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    scene = load_scene()
    p = parse_set("bearings.0.path=my_qj1044.toml", scene.to_dict())
    assert p.values == (str(tmp_path / "my_qj1044.toml"),)
    (case,) = expand(scene, [p])
    swept = loads_scene(case.scene_toml)
    assert swept.bearings[0].path == str(tmp_path / "my_qj1044.toml")
    assert swept.bearings[0].preset is None
    assert swept.bearings[1].preset == "QJ1044"  # the other bearing untouched
    # and back: a preset on a bearing that names a file drops the file
    q = parse_set("bearings.0.preset=QJ1044", swept.to_dict())
    (back,) = expand(swept, [q])
    returned = loads_scene(back.scene_toml).bearings[0]
    assert returned.preset == "QJ1044" and returned.path is None
    # an index the scene does not have is still named
    from thermobearing.errors import InputError

    with pytest.raises(InputError, match="0 = drive_end, 1 = non_drive_end"):
        parse_set("bearings.2.path=my_qj1044.toml", scene.to_dict())


# --- a flow swept on an oil-bath scene changed the results without a word ----------------
def test_oil_bath_with_a_flow_says_what_the_flow_does():
    # before: `thermobearing sweep examples/catalogue_bearing_rig.toml --set
    # supply.flow=1,5` ran (the 6206's housing 24.07 / 23.59 degC) and neither `check` nor
    # the run said that the flow circulates the bath through the network's oil stream while
    # the churning keeps following the level; nor was the inlet temperature checked
    from pathlib import Path

    from thermobearing.errors import InputError

    example = Path(__file__).resolve().parents[2] / "examples" / "catalogue_bearing_rig.toml"
    scene = load_scene(example)
    assert scene.supply.method == "oil_bath" and scene.supply.flow == 0.0
    assert not any("circulated bath" in n for n in Simulation(scene, progress=False).notes)
    d = scene.to_dict()
    d["supply"]["flow"] = "2 L/min"
    flowing = loads_scene(_toml(d), base_dir=example.parent)
    notes = Simulation(flowing, progress=False).notes
    (note,) = [n for n in notes if "circulated bath" in n]
    assert "2 L/min" in note and "22 degC" in note and "supply.level" in note
    # a circulated bath's inlet is checked like a jet's (a bare 40 is kelvin: not liquid)
    d["supply"]["inlet_temperature"] = 40
    with pytest.raises(InputError, match="supply.inlet_temperature"):
        Simulation(loads_scene(_toml(d), base_dir=example.parent), progress=False)


def _toml(d):
    from thermobearing.scene import Scene

    return Scene.from_dict(d).to_toml()


# --- the report's what-if curves left out the oil outlet temperature ---------------------
def _temperature_runner(scene_toml: str) -> dict[str, float]:
    """Made-up but monotonic results of the flow (what the report draws, not physics)."""
    q = loads_scene(scene_toml).supply.flow * 60e3
    return {"mean total loss [W]": 100.0 * q, "final drive_end.housing [degC]": 50.0 - 0.1 * q,
            "rise over initial drive_end.housing [K]": 15.0 - 0.1 * q,
            "final drive_end.oil [degC]": 40.0 - 0.1 * q,
            "rise over initial drive_end.oil [K]": 5.0 - 0.1 * q}


def test_whatif_curves_show_the_oil_outlet_temperature(tmp_path, monkeypatch):
    # before: the what-if figure drew the total loss, the over-skidding and the housing's
    # final temperature and rise; the oil outlet temperature, the first thing an oil-flow
    # what-if asks (and m_dot c_p dT against the loss), was only in the table
    import thermobearing.report as report
    from thermobearing.commands.report import sweep_report
    from thermobearing.sweep import parse_set, run_sweep

    drawn = {}
    real = report.fig_whatif

    def spy(summary, x, ys, group=None):
        drawn[x] = list(ys)
        return real(summary, x, ys, group=group)

    monkeypatch.setattr(report, "fig_whatif", spy)
    scene = load_scene()
    run_sweep(scene, [parse_set("supply.flow=10,20,33", scene.to_dict())], tmp_path,
              runner=_temperature_runner, workers=1, progress=False, check=False)
    sweep_report(tmp_path)
    assert drawn["supply.flow [L/min]"] == [
        "mean total loss [W]", "final drive_end.housing [degC]",
        "rise over initial drive_end.housing [K]", "final drive_end.oil [degC]"]


# --- one case of a grid that does not converge blocked the rest of the grid ---------------
def _failing_at_40(scene_toml: str) -> dict[str, float]:
    """Stops like the ball solver at 40 L/min and 40 degC inlet on the default rig
    (residual 6.7e-4 at 4 kN; 38 and 42 L/min converge); the flow otherwise."""
    from thermobearing.errors import ConvergenceError

    sc = loads_scene(scene_toml)
    if round(sc.supply.flow * 60e3) == 40 and round(sc.supply.inlet_temperature) == 313:
        raise ConvergenceError("kinematics (skidding)", 6.7e-4, "no convergence", {})
    return capacity_runner(scene_toml)


@pytest.mark.parametrize("workers", [1, 2])
def test_keep_going_runs_the_rest_of_the_grid(tmp_path, workers):
    # before: the 40 L/min x 40 degC case stopped the sweep, a rerun stopped there again,
    # and leaving 40 L/min out of --set dropped the 30 degC case with it: the rest of the
    # grid could not be run at all
    from thermobearing.sweep import finished_cases, parse_set, run_sweep

    scene = load_scene()
    d = scene.to_dict()
    params = [parse_set("supply.flow=30,40", d), parse_set("supply.inlet_temperature=30,40", d)]
    df = run_sweep(scene, params, tmp_path, runner=_failing_at_40, workers=workers,
                   progress=False, check=False, keep_going=True)
    assert len(df) == 3 and len(finished_cases(tmp_path)) == 3
    (line,) = df.attrs["failed"]
    assert "supply.flow=40 L/min, supply.inlet_temperature=40 degC" in line
    assert "6.7" in line and "finished case" not in line
    # without keep_going the first failure still stops the sweep
    from thermobearing.errors import ConvergenceError

    with pytest.raises(ConvergenceError):
        run_sweep(scene, params, tmp_path / "stop", runner=_failing_at_40, workers=1,
                  progress=False, check=False)


def test_keep_going_on_the_command_line(tmp_path, capsys, monkeypatch):
    import thermobearing.simulation as simulation
    from thermobearing import cli

    monkeypatch.setattr(simulation, "summarize_scene", _failing_at_40)
    out = tmp_path / "sw"
    args = ["sweep", "--set", "supply.flow=30,40", "--set", "supply.inlet_temperature=30,40",
            "--out", str(out), "-j", "1", "--quiet", "--keep-going"]
    assert cli.main(args) == 1  # not every case ran
    captured = capsys.readouterr()
    assert "1 case failed" in captured.err and "a rerun tries it again" in captured.err
    assert "supply.flow=40 L/min, supply.inlet_temperature=40 degC" in captured.err
    assert captured.out.count(" L/min ") == 3  # the three other cases in the table


# --- the same flows in another unit ran again -------------------------------------------
def test_rerun_in_another_unit_does_not_recompute(tmp_path):
    # before: `--set supply.flow=900,1980 L/h` after `supply.flow=15,33` on the same folder
    # ran both cases again (the case id hashed the values' text) and the summary listed
    # each flow twice
    from thermobearing.sweep import expand, parse_set, run_sweep

    scene = load_scene()
    ran = []

    def counting(text):
        ran.append(round(loads_scene(text).supply.flow * 60e3, 9))
        return capacity_runner(text)

    first = parse_set("supply.flow=15,33", scene.to_dict())
    # ids of existing stores (the hash covers the base scene: it changes with the default scene)
    assert expand(scene, [first])[0].case_id == "4c7ca637f230"
    run_sweep(scene, [first], tmp_path, runner=counting, workers=1, progress=False,
              check=False)
    again = parse_set("supply.flow=900 L/h,1980 L/h,1200 L/h", scene.to_dict())
    df = run_sweep(scene, [again], tmp_path, runner=counting, workers=1, progress=False,
                   check=False)
    assert ran == [15.0, 33.0, 20.0]  # only 1200 L/h was new
    assert len(df) == 3 and df["supply.flow [L/min]"].tolist() == [15.0, 33.0, 20.0]
    # a record of another base scene in the folder does not count for this one
    other = scene.with_changes(title="another rig")
    run_sweep(other, [first], tmp_path, runner=counting, workers=1, progress=False,
              check=False)
    assert ran[3:] == [15.0, 33.0]
