"""Session-20 user tour: the default rig's two identical bearings printed every film-range
and skid warning twice (8 lines, 5 different); the reader gets each once."""

from __future__ import annotations

import pandas as pd

from thermobearing.warning_groups import merge_twin_bearings

FILM = ("hamrock_dowson_1977_central: U in [9.79e-11, 1.82e-10] outside [1e-12, 1e-10] "
        "[raised 68 times at 22 steps; intervals are the envelope of all]")
SKID = ("cage skidding (cage slower than epicyclic) by more than 5% at 2 of 22 steps "
        "(steps 0-1); largest -51.9 % at step 0")


def test_lines_that_differ_only_in_their_bearing_are_one_line_at_the_first_place():
    lines = ["calibrated ball force-model parameters from QJ1044.calibration.toml",
             "shaft link drive_end.shaft -- non_drive_end.shaft: G = 3.573 W/K",
             f"drive_end, steps 0-21: {FILM}", f"non_drive_end, steps 0-21: {FILM}",
             f"drive_end: {SKID}", f"non_drive_end: {SKID.replace('-51.9', '-40.2')}"]
    merged = merge_twin_bearings(lines, ["drive_end", "non_drive_end"])
    assert merged == [lines[0], lines[1],
                      f"drive_end and non_drive_end (each), steps 0-21: {FILM}",
                      lines[4], lines[5]]  # the skid lines differ: both kept
    # three bearings, a name that is the start of another, no bearing at all
    three = [f"a: {SKID}", f"a_2: {SKID}", f"b: {SKID}", "a_2, step 3: other"]
    assert merge_twin_bearings(three, ["a", "a_2", "b"]) == [
        f"a, a_2 and b (each): {SKID}", "a_2, step 3: other"]
    assert merge_twin_bearings(lines[:2], []) == lines[:2]


def test_the_run_summary_and_the_report_list_a_twin_line_once(tmp_path):
    from thermobearing.report import html_report
    from thermobearing.results import Results

    warnings = [f"drive_end, steps 0-21: {FILM}", f"non_drive_end, steps 0-21: {FILM}"]
    kin = pd.DataFrame({"step": [0, 0], "bearing": ["drive_end", "non_drive_end"],
                        "cage speed ratio [-]": [0.45, 0.45]})
    res = Results(tables={"kinematics": kin}, warnings=warnings)
    text = html_report(res, "twins")
    assert text.count("hamrock_dowson_1977_central") == 1
    assert "drive_end and non_drive_end (each), steps 0-21" in text
    # the run's own list keeps one line per bearing
    assert res.warnings == warnings


def test_the_default_rig_summary_prints_its_film_range_warning_once():
    from thermobearing.scene import load_scene, loads_scene
    from thermobearing.simulation import Simulation
    from thermobearing.toml_writer import dumps_toml

    d = load_scene().to_dict()
    d["schedule"] = {"steps": [{"duration": "1 min", "speed": "1800 rpm",
                                "radial_load": "1 kN", "axial_load": "4 kN"}]}
    sim = Simulation(loads_scene(dumps_toml(d)), progress=False)
    res = sim.run()
    film = [w for w in res.warnings if "hamrock_dowson_1977_central:" in w]
    assert [w.split(",")[0] for w in film] == ["drive_end", "non_drive_end"]
    text = sim.summary_text(res)
    assert text.count("hamrock_dowson_1977_central:") == 1
    assert "  - drive_end and non_drive_end (each), step 0: hamrock_dowson" in text


def test_the_run_summary_gives_a_small_bearing_s_loss_with_its_digits():
    """The 6206 loss map printed "total loss per bearing: 1 - 23 W" for 0.962 - 22.9 W,
    and a one-point run "1486 - 1486 W"."""
    from thermobearing.results import Results
    from thermobearing.scene import load_scene
    from thermobearing.simulation import Simulation

    sim = Simulation(load_scene("qj1044_rig"), progress=False)

    def losses(powers):
        return pd.DataFrame({"step": list(range(len(powers))), "bearing": "test",
                             "power [W]": powers})

    text = sim.summary_text(Results(tables={"losses": losses([0.96215, 22.946])}))
    assert "total loss per bearing: 0.962 - 22.9 W" in text
    text = sim.summary_text(Results(tables={"losses": losses([1318.12, 1517.9])}))
    assert "total loss per bearing: 1318 - 1518 W" in text
    text = sim.summary_text(Results(tables={"losses": losses([1486.2])}))
    assert "total loss per bearing: 1486 W" in text


def test_ctrl_c_in_a_run_names_the_command_that_reports_the_finished_steps(
        tmp_path, capsys, monkeypatch):
    """An error said "`thermobearing report DIR` writes their report"; Ctrl-C said only
    where the tables are."""
    from thermobearing import cli
    from thermobearing.simulation import Simulation

    def interrupted(self, out_dir=None):
        (out_dir / "metadata.json").parent.mkdir(parents=True, exist_ok=True)
        (out_dir / "metadata.json").write_text("{}", encoding="utf-8")
        raise KeyboardInterrupt

    monkeypatch.setattr(Simulation, "run", interrupted)
    out = tmp_path / "rig"
    assert cli.main(["run", "--out", str(out), "--quiet"]) == 130
    err = capsys.readouterr().err
    assert f"interrupted: everything computed so far is in {out}/" in err
    assert f"`thermobearing report {out}` writes their report" in err


def test_a_source_that_hardly_moved_with_the_load_reads_its_small_change():
    """The rig's 'what the sources are' table read "-0 % from 0 to 42 kN axial" for the
    element churning (720.8 -> 720.0 W)."""
    from thermobearing.report_losses import _response_text

    def text(change):
        return _response_text({"change": change, "load": "axial load [kN]", "low": 0.0,
                               "high": 42.0, "speed": 1800.0})

    assert text(720.0 / 720.756 - 1.0) == "-0.1 % from 0 to 42 kN axial at 1800 r/min"
    assert text(0.0).startswith("+0 % from 0 to 42 kN")
    assert text(1.35).startswith("+135 % from")
    assert text(-0.02).startswith("-2 % from")


def test_the_report_gives_a_roller_s_length_beside_its_diameter():
    """The NU 214 loss map's bearing table read "18 x 13 mm rollers"."""
    from thermobearing.geometry import load_bearing
    from thermobearing.report_context import bearing_table
    from thermobearing.scene import load_scene

    scene = load_scene("crb_rib_example")
    table = bearing_table(scene, {"crb": load_bearing("CRB_50x75x16")})
    crb = load_bearing("CRB_50x75x16")
    expected = (f"{crb.n_elements} x {1e3 * crb.roller_diameter:.4g} x "
                f"{1e3 * crb.roller_length:.4g} mm rollers (diameter x length)")
    assert table["rolling elements"].tolist() == [expected]
    rig = load_scene("qj1044_rig")
    balls = bearing_table(rig, {"drive_end": load_bearing("QJ1044")})
    assert balls["rolling elements"].iloc[0] == "20 x 34.92 mm balls"
