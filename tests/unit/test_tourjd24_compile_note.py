"""Session-24 user tour F: the first ``thermobearing run`` of a fresh clone printed nothing
for 96 s of wall time (numba compiling its kernels) between "writing results" and its first
step line. A run with no numba cache says why it waits; a cached install says nothing."""

from __future__ import annotations

from thermobearing.commands._preflight import COMPILE_NOTE, compile_note


def test_no_cache_index_gives_the_note(tmp_path):
    (tmp_path / "__pycache__").mkdir()
    (tmp_path / "__pycache__" / "kernels.cpython-311.pyc").write_bytes(b"")
    assert compile_note(tmp_path) == COMPILE_NOTE
    assert compile_note(tmp_path / "absent") == COMPILE_NOTE


def test_a_cache_index_gives_none(tmp_path):
    sub = tmp_path / "skidding" / "__pycache__"
    sub.mkdir(parents=True)
    (sub / "ball_residual_kernels._residual-120.py311.nbi").write_bytes(b"")
    assert compile_note(tmp_path) is None


def test_run_prints_the_note_after_naming_its_folder(tmp_path, monkeypatch, capsys):
    import thermobearing.commands.run as run_cmd
    from thermobearing import cli

    monkeypatch.setattr(run_cmd, "compile_note", lambda root=None: COMPILE_NOTE)
    scene = tmp_path / "film.toml"
    scene.write_text(FILM_SCENE, encoding="utf-8")
    code = cli.main(["run", str(scene), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().out.splitlines()
    assert code == 0
    at = lines.index(COMPILE_NOTE)
    assert lines[at - 1].startswith("writing results to ")


def test_the_cache_is_looked_for_before_the_model_is_built(tmp_path, monkeypatch, capsys):
    # building the scene's Simulation writes numba cache files (51 of a fresh clone's):
    # looked for after it, the note never showed on the fresh clone it was written for
    import thermobearing.commands.calibrate as cal_cmd
    import thermobearing.commands.run as run_cmd
    from thermobearing import cli
    from thermobearing.simulation import Simulation

    events: list[str] = []

    def note(root=None):
        events.append("note")
        return COMPILE_NOTE

    built = Simulation.__init__

    def init(self, *args, **kwargs):
        events.append("model")
        built(self, *args, **kwargs)

    monkeypatch.setattr(run_cmd, "compile_note", note)
    monkeypatch.setattr(cal_cmd, "compile_note", note)
    monkeypatch.setattr(Simulation, "__init__", init)
    scene = tmp_path / "film.toml"
    scene.write_text(FILM_SCENE, encoding="utf-8")
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    assert events[0] == "note" and "model" in events
    events.clear()
    cli.main(["calibrate", "qj1044_synthetic_measured", "--fit", "network.parameters.h_oil",
              "--max-runs", "1", "--out", str(tmp_path / "cal")])
    assert events[0] == "note"
    out = capsys.readouterr().out
    assert COMPILE_NOTE in out
    # the fit writes tables; the line after names the run that draws it against the data
    calibrated = tmp_path / "cal" / "qj1044_synthetic_measured_calibrated.toml"
    assert (f"its temperatures against the measured ones (figures, report): thermobearing "
            f"run {calibrated} --out {tmp_path / 'cal' / 'run'}") in out
    assert calibrated.is_file()


def test_a_quiet_run_prints_no_note(tmp_path, monkeypatch, capsys):
    import thermobearing.commands.run as run_cmd
    from thermobearing import cli

    monkeypatch.setattr(run_cmd, "compile_note", lambda root=None: COMPILE_NOTE)
    scene = tmp_path / "film.toml"
    scene.write_text(FILM_SCENE, encoding="utf-8")
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    assert COMPILE_NOTE not in capsys.readouterr().out


FILM_SCENE = """
title = "film only"
[[bearings]]
name = "b"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "1 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "40 degC"
[schedule]
speed = "3000 rpm"
radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "1 min"
[models]
kinematics = "race_control"
[outputs]
mode = "transient"
want = ["film"]
"""


def test_one_step_is_counted_in_the_singular(tmp_path):
    # "interrupted before the first of 1 steps finished", "schedule: 1 steps, ..."
    from thermobearing.commands.run import stopped_text

    assert "before the first step finished" in stopped_text(tmp_path, 0, 1, True)
    assert "before the first of 3 steps finished" in stopped_text(tmp_path, 0, 3, True)
    (tmp_path / "metadata.json").write_text("{}", encoding="utf-8")
    assert "(its one step; stopped while the figures" in stopped_text(tmp_path, 1, 1, True)
    assert "(all 3 steps; stopped while the figures" in stopped_text(tmp_path, 3, 3, True)
    assert "(1 of 3 steps;" in stopped_text(tmp_path, 1, 3, False)


def test_check_says_one_step(tmp_path, capsys):
    from thermobearing import cli

    scene = tmp_path / "film.toml"
    scene.write_text(FILM_SCENE, encoding="utf-8")
    assert cli.main(["check", str(scene)]) == 0
    assert "schedule: 1 step, 1 min" in capsys.readouterr().out
