"""Bad-input audit through the command line (issue 6 and the brief's rule): a bad scene, a bad
``[measured]`` CSV, a bad sweep, an unreachable dask scheduler and Ctrl-C each end with a
non-zero exit code and one paragraph on stderr naming the field and value -- never a Python
traceback -- and an interrupted run or sweep keeps what it wrote and says where.

Everything goes through :func:`thermobearing.cli.main`, the console script's entry point.
"""

from __future__ import annotations

import json

import pytest

from tests.unit.test_bad_input_scene import BASE, edited
from thermobearing import cli
from thermobearing.scene import dumps_toml


@pytest.fixture(scope="module", autouse=True)
def _warm_imports():
    """Import CoolProp (air properties of the network, ~5 s once) and every sub-command
    module (~3 s) outside the timed tests."""
    from thermobearing.lubricant_properties import air_properties

    air_properties(300.0)
    cli.build_parser()


def write_scene(tmp_path, data, name="scene.toml"):
    path = tmp_path / name
    path.write_text(dumps_toml(data), encoding="utf-8")
    return path


def run_cli(capsys, *argv):
    """(exit code, stderr) of ``thermobearing ARGV``; fails on any escaping exception."""
    code = cli.main([str(a) for a in argv])
    captured = capsys.readouterr()
    return code, captured.err


def assert_one_paragraph(err: str, *words: str) -> None:
    assert "Traceback" not in err
    assert err.strip() and "\n\n" not in err.strip()
    for w in words:
        assert w in err, (w, err)


# --- bad scenes: exit 1, field + value in one line ---------------------------------------
@pytest.mark.parametrize(("path", "value", "words"), [
    ("schedule.steps", [{"duration": "5 min"}, {"duration": "-2 min"}],
     ["schedule.steps[1].duration", "'-2 min'", "> 0"]),
    ("supply.flow", "33 kg", ["supply.flow", "'33 kg'", "m**3/s"]),
    ("models.kinematics", "skiding", ["models.kinematics", "skiding", "race_control"]),
    ("solver.rtol", 0.0, ["solver.rtol", "0.0", "(0, 1)"]),
    ("solver.chunk", "0 s", ["solver.chunk", "'0 s'", "> 0"]),
    ("network.parameters", {}, ["network.parameters", "housing_outer_diameter"]),
])
def test_check_bad_scene_exits_1_with_the_field(tmp_path, capsys, path, value, words):
    scene = write_scene(tmp_path, edited(path, value))
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, "thermobearing check: error:", *words)


def test_run_missing_network_parameters_is_named_not_a_type_error(tmp_path, capsys):
    # before: TypeError "four_node_paper002() missing 2 required keyword-only arguments"
    # with a traceback, after the kinematics set-up
    scene = write_scene(tmp_path, edited("network.parameters", {}))
    code, err = run_cli(capsys, "run", scene, "--out", tmp_path / "out", "--quiet")
    assert code == 1
    assert_one_paragraph(err, "network.parameters", "housing_outer_diameter", "housing_length")


def test_unknown_scene_name_lists_presets(capsys):
    code, err = run_cli(capsys, "check", "qj1044_rgi")
    assert code == 1
    assert_one_paragraph(err, "'qj1044_rgi'", "qj1044_rig", "qj1044_synthetic_measured")


def test_unwritable_results_folder(tmp_path, capsys):
    # before: NotADirectoryError traceback
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    scene = write_scene(tmp_path, BASE)
    code, err = run_cli(capsys, "run", scene, "--out", blocker / "out", "--quiet")
    assert code == 1
    assert_one_paragraph(err, "thermobearing run: error:", str(blocker / "out"))


# --- issue 6: "a measured CSV whose columns do not map to nodes" (+ file neighbours) ------
def measured_scene(tmp_path, csv_text, **measured):
    (tmp_path / "rig.csv").write_text(csv_text, encoding="utf-8")
    data = edited("measured", {"file": "rig.csv", "time_column": "time [min]",
                               "columns": {"TC1": "de.housing"}, **measured})
    return write_scene(tmp_path, data)


GOOD_CSV = "time [min],TC1\n0,35.0\n5,36.1\n10,37.0\n"


def test_measured_column_mapped_to_unknown_node(tmp_path, capsys):
    # before: `check` accepted it; only `run` found it (after loading every model)
    scene = measured_scene(tmp_path, GOOD_CSV, columns={"TC1": "de.hosuing"})
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, "measured.columns['TC1']", "'de.hosuing'", "de.housing",
                         "de.oil")


def test_measured_column_missing_from_file(tmp_path, capsys):
    scene = measured_scene(tmp_path, GOOD_CSV, columns={"TC9": "de.housing"})
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, "measured.columns['TC9']", "time [min], TC1")


def test_measured_time_going_backwards(tmp_path, capsys):
    # before: accepted; the overlay and RMSE were computed on a scrambled time axis
    scene = measured_scene(tmp_path, "time [min],TC1\n0,35\n10,36\n5,37\n")
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, "measured column 'time [min]'", "row 3: 5 after 10",
                         "strictly increasing")


def test_measured_text_cell(tmp_path, capsys):
    # before: ValueError "could not convert string to float: 'abc'" from pandas, raised
    # at the END of `run` (when the report overlay read the file), after the whole run
    scene = measured_scene(tmp_path, "time [min],TC1\n0,35\n5,abc\n10,37\n")
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, "measured column 'TC1'", "row 2: 'abc'", "numbers")


def test_measured_file_missing(tmp_path, capsys):
    data = edited("measured", {"file": "nope.csv", "columns": {"TC1": "de.housing"}})
    code, err = run_cli(capsys, "check", write_scene(tmp_path, data))
    assert code == 1
    assert_one_paragraph(err, "measured.file", "'nope.csv'", "an existing data file")


def test_measured_good_file_passes_check(tmp_path, capsys):
    code, err = run_cli(capsys, "check", measured_scene(tmp_path, GOOD_CSV))
    assert code == 0 and "error" not in err


# --- issue 6: "Ctrl-C during a run keeps everything written so far and says where" --------
def test_ctrl_c_during_run_keeps_rows_and_says_where(tmp_path, capsys, monkeypatch):
    import thermobearing.network as network

    advance = network.TransientStepper.advance
    def interrupted_advance(self, t, *args, **kwargs):
        # the user presses Ctrl-C during the second 300-s chunk (the chunk starting at
        # 300 s: the first may be integrated twice, coupled.chord_first_chunk)
        if t >= 300.0 - 1e-6:
            raise KeyboardInterrupt
        return advance(self, t, *args, **kwargs)

    monkeypatch.setattr(network.TransientStepper, "advance", interrupted_advance)
    out = tmp_path / "results"
    code, err = run_cli(capsys, "run", write_scene(tmp_path, BASE), "--out", out, "--quiet")
    assert code == 130
    assert_one_paragraph(err, "interrupted", str(out))
    rows = (out / "temperatures.csv").read_text().strip().splitlines()
    assert rows[0].startswith("time [s]")
    assert [r.split(",")[0] for r in rows[1:]] == ["0.0", "300.0"]  # t = 0 and chunk 1 kept
    assert (out / "scene.toml").is_file() and (out / "kinematics.csv").is_file()


# --- sweeps: "a sweep parameter that does not exist", values, Ctrl-C, dask ----------------
def test_sweep_parameter_that_does_not_exist(tmp_path, capsys):
    scene = write_scene(tmp_path, BASE)
    code, err = run_cli(capsys, "sweep", scene, "--set", "supply.flwo=5,10",
                        "--out", tmp_path / "sw")
    assert code == 1
    assert_one_paragraph(err, "'supply.flwo'", "an existing scene field", "supply.flow")


def test_sweep_value_that_is_refused_names_the_field(tmp_path, capsys):
    scene = write_scene(tmp_path, BASE)
    code, err = run_cli(capsys, "sweep", scene, "--set", "supply.flow=-5,10",
                        "--out", tmp_path / "sw")
    assert code == 1
    assert_one_paragraph(err, "supply.flow", "'-5 L/min'", "a flow > 0")


def test_sweep_values_with_a_unit_after_the_list():
    # the documented form "supply.flow=15,33 L/min" gave ONE value '15 33 L/min' before
    from thermobearing.scene import loads_scene
    from thermobearing.sweep import parse_set

    d = loads_scene(dumps_toml(BASE)).to_dict()
    assert parse_set("supply.flow=15,33 L/min", d).values == ("15 L/min", "33 L/min")
    assert parse_set("supply.flow=1e1,2e1 L/min", d).values == ("10 L/min", "20 L/min")
    assert parse_set("lubricant.preset=ISO_VG32,ISO_VG68", d).values == ("ISO_VG32",
                                                                         "ISO_VG68")


def test_sweep_wrong_unit_after_the_list(tmp_path, capsys):
    scene = write_scene(tmp_path, BASE)
    code, err = run_cli(capsys, "sweep", scene, "--set", "supply.flow=5,10 kg",
                        "--out", tmp_path / "sw")
    assert code == 1
    assert_one_paragraph(err, "supply.flow", "'5 kg'", "m**3/s")


def test_sweep_zero_workers(tmp_path, capsys):
    # before: ValueError "max_workers must be greater than 0" from concurrent.futures
    scene = write_scene(tmp_path, BASE)
    code, err = run_cli(capsys, "sweep", scene, "--set", "supply.flow=5,10",
                        "--out", tmp_path / "sw", "--workers", "0")
    assert code == 1
    assert_one_paragraph(err, "workers", "0", ">= 1")


def test_ctrl_c_during_sweep_keeps_cases_and_says_how_to_resume(tmp_path, capsys,
                                                                 monkeypatch):
    import thermobearing.simulation as simulation

    calls = []

    def runner(scene_toml):
        calls.append(scene_toml)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return {"max temperature [degC]": 40.0 + len(calls)}

    monkeypatch.setattr(simulation, "summarize_scene", runner)
    out = tmp_path / "sw"
    scene = write_scene(tmp_path, BASE)
    argv = ("sweep", scene, "--set", "supply.flow=5,10,15", "--out", out, "--workers", "1",
            "--quiet")
    code, err = run_cli(capsys, *argv)
    # before: "thermobearing sweep: interrupted" and nothing on where or how to go on
    assert code == 130
    assert_one_paragraph(err, "interrupted", "1 finished case", str(out / "cases.jsonl"),
                         "rerun the same command")
    kept = [json.loads(line) for line in (out / "cases.jsonl").read_text().splitlines()]
    assert [r["params"]["supply.flow"] for r in kept] == ["5 L/min"]
    # resuming runs only the two cases not yet in the store
    calls.clear()
    calls.append("already counted")  # so the runner's interrupt (at call 2) is not hit
    monkeypatch.setattr(simulation, "summarize_scene",
                        lambda text: {"max temperature [degC]": 50.0})
    code, err = run_cli(capsys, *argv)
    assert code == 0
    flows = [json.loads(line)["params"]["supply.flow"]
             for line in (out / "cases.jsonl").read_text().splitlines()]
    assert flows == ["5 L/min", "10 L/min", "15 L/min"]


def test_unreachable_dask_scheduler_says_so_and_falls_back_only_if_asked(tmp_path, capsys,
                                                                         monkeypatch):
    import distributed

    def refuse(address, **kwargs):  # what Client raises when nobody listens (after 5 s)
        raise OSError(f"Timed out trying to connect to {address} after 5 s")

    monkeypatch.setattr(distributed, "Client", refuse)
    import thermobearing.simulation as simulation

    monkeypatch.setattr(simulation, "summarize_scene", lambda text: {"x": 1.0})
    scene = write_scene(tmp_path, BASE)
    base = ("sweep", scene, "--set", "supply.flow=5,10", "--scheduler", "tcp://10.9.9.9:8786")
    code, err = run_cli(capsys, *base, "--out", tmp_path / "a")
    assert code == 1
    assert_one_paragraph(err, "cannot reach the dask scheduler", "'tcp://10.9.9.9:8786'",
                         "--fallback-local")
    assert not (tmp_path / "a" / "cases.jsonl").exists()  # nothing ran locally unasked
    code, err = run_cli(capsys, *base, "--out", tmp_path / "b", "--fallback-local",
                        "--workers", "1")
    assert code == 0
    assert "unreachable, running locally" in err
    assert len((tmp_path / "b" / "cases.jsonl").read_text().splitlines()) == 2


# --- calibrate: a long run of many scene runs; Ctrl-C keeps each finished run -------------
def test_ctrl_c_during_calibrate_keeps_runs_and_says_where(tmp_path, capsys, monkeypatch):
    import thermobearing.calibrate as calibrate

    def fake_calibrate(scene, fit, *, callback=None, **kwargs):
        # two model runs finish, then the user presses Ctrl-C during the third
        callback(1, {"network.parameters.h_oil": 270.0}, 0.80)
        callback(2, {"network.parameters.h_oil": 350.0}, 0.35)
        raise KeyboardInterrupt

    monkeypatch.setattr(calibrate, "calibrate", fake_calibrate)
    scene = measured_scene(tmp_path, GOOD_CSV)
    out = tmp_path / "cal"
    code, err = run_cli(capsys, "calibrate", scene, "--fit", "network.parameters.h_oil",
                        "--out", out, "--quiet")
    # before: "thermobearing calibrate: interrupted" and every finished run was lost
    assert code == 130
    assert_one_paragraph(err, "interrupted", str(out / "calibration_runs.csv"),
                         "best so far: run 2", "network.parameters.h_oil=350", "RMSE 0.35 K")
    rows = (out / "calibration_runs.csv").read_text().strip().splitlines()
    assert rows == ["run,network.parameters.h_oil,rmse [K]", "1,270.0,0.8", "2,350.0,0.35"]


def test_calibrate_max_runs_below_one(tmp_path, capsys):
    scene = measured_scene(tmp_path, GOOD_CSV)
    code, err = run_cli(capsys, "calibrate", scene, "--fit", "network.parameters.h_oil",
                        "--out", tmp_path / "cal", "--max-runs", "0")
    assert code == 1
    assert_one_paragraph(err, "--max-runs", "0", ">= 1")


def test_sweep_case_failing_at_run_time_names_the_case(tmp_path, capsys, monkeypatch):
    # a value that only the models refuse (here: a ConvergenceError of one case)
    import thermobearing.simulation as simulation
    from thermobearing.errors import ConvergenceError

    def runner(scene_toml):
        if "10 L/min" in scene_toml:
            raise ConvergenceError("coupled transient", 3.2, "thermal runaway", {"time": 60.0})
        return {"x": 1.0}

    monkeypatch.setattr(simulation, "summarize_scene", runner)
    out = tmp_path / "sw"
    code, err = run_cli(capsys, "sweep", write_scene(tmp_path, BASE), "--set",
                        "supply.flow=5,10,15", "--out", out, "--workers", "1")
    # before: only the model's message, without which case or what was kept
    assert code == 1
    assert_one_paragraph(err, "sweep case", "supply.flow=10 L/min", "residual 3.200e+00",
                         "thermal runaway", str(out / "cases.jsonl"), "resume")
    assert len((out / "cases.jsonl").read_text().splitlines()) == 1  # the 5 L/min case


# --- the other commands a user types by hand ------------------------------------------------
def test_scene_file_with_broken_toml_is_named(tmp_path, capsys):
    path = tmp_path / "my_rig.toml"
    path.write_text("title = \n", encoding="utf-8")
    code, err = run_cli(capsys, "check", path)
    # before: "scene = '<toml>' is not allowed: valid TOML (...)" without the file
    assert code == 1
    assert_one_paragraph(err, str(path), "valid TOML", "line 1")


@pytest.mark.parametrize(("temperatures", "words"), [
    ("40 kg", ["--temperatures", "'40 kg'", "K"]),          # before: ValueError traceback
    ("-300 degC", ["--temperatures", "'-300 degC'", "absolute zero"]),
    ("40,-280", ["--temperatures", "'-280'", "absolute zero"]),
])
def test_lubricant_table_bad_temperatures(capsys, temperatures, words):
    code, err = run_cli(capsys, "lubricant", "ISO_VG46", "--temperatures", temperatures)
    assert code == 1
    assert_one_paragraph(err, *words)


def test_lubricant_table_temperatures_in_kelvin_accepted(capsys):
    code = cli.main(["lubricant", "ISO_VG46", "--temperatures", "40,373.15 K"])
    out = capsys.readouterr().out
    assert code == 0 and "\n     40.0 " in out and "\n    100.0 " in out


def test_report_of_a_folder_with_a_broken_table(tmp_path, capsys):
    # before: KeyError 'time [s]' traceback from pandas
    folder = tmp_path / "results"
    folder.mkdir()
    (folder / "scene.toml").write_text(dumps_toml(BASE), encoding="utf-8")
    (folder / "temperatures.csv").write_text("garbage\n1\n", encoding="utf-8")
    code, err = run_cli(capsys, "report", folder)
    assert code == 1
    assert_one_paragraph(err, "temperatures.csv", "'time [s]'")


def test_report_of_a_sweep_folder_with_an_empty_store(tmp_path, capsys):
    # before: IndexError (list index out of range) traceback
    folder = tmp_path / "sw"
    folder.mkdir()
    (folder / "summary.csv").write_text("case\n", encoding="utf-8")
    (folder / "cases.jsonl").write_text("", encoding="utf-8")
    code, err = run_cli(capsys, "report", folder)
    assert code == 1
    assert_one_paragraph(err, "cases.jsonl", "one JSON record")


def slow_case(scene_toml: str) -> dict[str, float]:
    """A picklable sweep runner: notes that it started (file named by an environment
    variable, inherited by the pool's processes) and takes 0.25 s."""
    import os
    import time

    with open(os.environ["TB_AUDIT_CASE_LOG"], "a", encoding="utf-8") as fh:
        fh.write("started\n")
    time.sleep(0.25)
    return {"x": 1.0}


def test_ctrl_c_in_a_local_process_pool_does_not_run_the_queued_cases(tmp_path, monkeypatch):
    # before: leaving the `with ProcessPoolExecutor` block on Ctrl-C waited for every queued
    # case (all 16 ran, ~2 s on 2 workers) and threw their results away
    from thermobearing import sweep
    from thermobearing.scene import loads_scene

    write_summary = sweep._write_summary

    def interrupted_after_first(out, cases, *done):
        write_summary(out, cases, *done)
        raise KeyboardInterrupt

    log = tmp_path / "started.log"
    monkeypatch.setenv("TB_AUDIT_CASE_LOG", str(log))
    monkeypatch.setattr(sweep, "_write_summary", interrupted_after_first)
    scene = loads_scene(dumps_toml(BASE))
    flows = ",".join(str(f) for f in range(5, 21))
    params = [sweep.parse_set(f"supply.flow={flows}", scene.to_dict())]
    out = tmp_path / "sw"
    with pytest.raises(KeyboardInterrupt):
        sweep.run_sweep(scene, params, out, runner=slow_case, workers=2, progress=False)
    started = len(log.read_text().splitlines())
    assert started < 8  # the running ones and the few already handed to a worker
    assert len(sweep.finished_cases(out)) == 1


@pytest.mark.parametrize(("key", "value", "words"), [
    ("housing_length", "-140 mm", ["housing_length", "-0.14", "> 0"]),
    ("oil_fill", 2.0, ["oil_fill", "2.0", "[0, 1]"]),
])
def test_check_builds_the_network_so_template_values_are_checked(tmp_path, capsys, key, value,
                                                                 words):
    # before: `check` passed; `run` failed only after loading every model
    scene = write_scene(tmp_path, edited(f"network.parameters.{key}", value))
    code, err = run_cli(capsys, "check", scene)
    assert code == 1
    assert_one_paragraph(err, *words)


def test_sweep_of_a_scene_with_relative_file_paths(tmp_path, monkeypatch):
    # before: each case's TOML kept 'oil.toml' / 'brg.toml' relative but lost the scene's
    # folder, so every case failed in the runner ("lubricant preset = 'oil.toml' is not
    # allowed: known names are ...") unless the sweep ran from the scene's folder
    import shutil

    from thermobearing.scene import configs_dir, load_scene, loads_scene
    from thermobearing.sweep import expand, parse_set

    folder = tmp_path / "rig"
    folder.mkdir()
    shutil.copy(configs_dir() / "lubricants" / "ISO_VG46.toml", folder / "oil.toml")
    shutil.copy(configs_dir() / "bearings" / "QJ1044.toml", folder / "brg.toml")
    data = edited("lubricant", {"path": "oil.toml"})
    data["bearings"] = [{"name": "de", "path": "brg.toml"}]
    write_scene(folder, data)
    monkeypatch.chdir(tmp_path)  # somewhere else
    scene = load_scene(folder / "scene.toml")
    cases = expand(scene, [parse_set("supply.flow=5,10", scene.to_dict())])
    for case in cases:
        again = loads_scene(case.scene_toml)  # what the runner does, without the folder
        assert again.lubricant["path"] == str(folder / "oil.toml")
        assert again.bearings[0].path == str(folder / "brg.toml")


def test_run_folder_scene_keeps_files_findable(tmp_path, capsys, monkeypatch):
    # before: scene.toml in the results folder kept "file = 'rig.csv'" relative to the
    # ORIGINAL scene's folder, so `thermobearing report DIR` failed with
    # "measured.file = 'rig.csv' is not allowed: an existing CSV file"
    import thermobearing.coupled as coupled
    from thermobearing.scene import check_measured_file, load_scene

    def stop(sim, writer):  # stop right after the run wrote scene.toml
        raise KeyboardInterrupt

    monkeypatch.setattr(coupled, "run_coupled", stop)
    scene_path = measured_scene(tmp_path, GOOD_CSV)
    out = tmp_path / "elsewhere" / "results"
    code, _ = run_cli(capsys, "run", scene_path, "--out", out, "--quiet")
    assert code == 130
    kept = load_scene(out / "scene.toml")
    assert kept.measured.file == str((tmp_path / "rig.csv").resolve())
    check_measured_file(kept)  # found from the results folder


def test_sweep_checks_the_base_scene_before_any_case(tmp_path, capsys, monkeypatch):
    # before: every case died in the runner with a TypeError traceback
    # ("four_node_paper002() missing 2 required keyword-only arguments")
    import thermobearing.simulation as simulation

    def must_not_run(scene_toml):
        raise AssertionError("a case ran")

    monkeypatch.setattr(simulation, "summarize_scene", must_not_run)
    scene = write_scene(tmp_path, edited("network.parameters", {}))
    code, err = run_cli(capsys, "sweep", scene, "--set", "supply.flow=5,10", "--out",
                        tmp_path / "sw", "--workers", "1")
    assert code == 1
    assert_one_paragraph(err, "network.parameters", "housing_outer_diameter")
