"""Session-19 user tour: a run into a log file (stderr no terminal, so no progress bar)
says where it writes and prints one line per finished step; --quiet prints none."""

from __future__ import annotations

import re

from thermobearing.cli import main

#: two short steps of a losses-only 6206 (no network: operating points without time) and
#: the same with a network (a transient: the simulated time in each line)
SCENE = """
title = "6206 two steps"
[[bearings]]
name = "test"
path = "{bearing}"
[lubricant]
preset = "ISO_VG68"
[supply]
method = "oil_bath"
level = "5 mm"
[environment]
ambient_temperature = "40 degC"
[schedule]
radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "2 min"
steps = [{{ speed = "1500 rpm" }}, {{ speed = "3000 rpm" }}]
[models]
kinematics = "race_control"
{network}
[outputs]
want = {want}
"""

NETWORK = """[network]
template = "four_node_paper002"
[network.parameters]
housing_outer_diameter = "90 mm"
housing_length = "30 mm"
shaft_diameter = "30 mm"
shaft_length = "100 mm"
"""


def _scene(tmp_path, network: bool):
    from pathlib import Path

    import thermobearing

    bearing = (Path(thermobearing.__file__).parents[1] / "examples"
               / "catalogue_bearing_6206.toml")
    text = SCENE.format(bearing=bearing.as_posix(), network=NETWORK if network else "",
                        want='["temperatures", "losses"]' if network else '["losses"]')
    path = tmp_path / ("transient.toml" if network else "points.toml")
    path.write_text(text, encoding="utf-8")
    return path


def test_a_run_into_a_file_prints_a_line_per_step(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", str(_scene(tmp_path, network=True)), "--out", str(out)]) == 0
    captured = capsys.readouterr()
    assert f"writing results to {out}/ as they are computed" in captured.out
    lines = [x for x in captured.err.splitlines() if x.startswith("step ")]
    assert len(lines) == 2, captured.err
    assert re.fullmatch(r"step 1/2 done \(t = 120 of 240 s simulated\), [0-9.]+ s wall",
                        lines[0])
    assert lines[1].startswith("step 2/2 done (t = 240 of 240 s simulated)")


def test_operating_points_have_no_time_and_quiet_prints_no_step(tmp_path, capsys):
    scene = _scene(tmp_path, network=False)
    assert main(["run", str(scene), "--out", str(tmp_path / "a")]) == 0
    err = capsys.readouterr().err
    assert re.search(r"^step 2/2 done, [0-9.]+ s wall$", err, re.M), err
    assert main(["run", str(scene), "--out", str(tmp_path / "b"), "--quiet"]) == 0
    assert "step " not in capsys.readouterr().err


def test_a_sweep_into_a_file_prints_a_line_per_case(tmp_path, capsys):
    scene = _scene(tmp_path, network=False)
    out = tmp_path / "sweep"
    assert main(["sweep", str(scene), "--set", "schedule.radial_load=1,2", "-j", "1",
                 "--out", str(out)]) == 0
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if x.startswith("sweep: ")]
    assert [x.split(",")[0] for x in lines] == ["sweep: 1/2 cases done",
                                                "sweep: 2/2 cases done"], err
    assert main(["sweep", str(scene), "--set", "schedule.radial_load=1,2,3", "-j", "1",
                 "--out", str(out), "--quiet"]) == 0  # resumes: one case to run, quiet
    assert "cases done" not in capsys.readouterr().err


def test_a_rerun_into_a_folder_leaves_no_figure_or_report_of_the_earlier_run(tmp_path):
    """A steady scene run into the folder of a transient one kept the transient's
    temperatures.png and loss maps beside its own; a run stopped by an error kept the
    earlier run's report.html, which read as this one's."""
    out = tmp_path / "out"
    out.mkdir()
    stale = ["temperatures.png", "loss_maps_nu.png", "report.html", "cage_speed_ratio.png"]
    for name in stale:
        (out / name).write_text("earlier run", encoding="utf-8")
    (out / "my_notes.txt").write_text("mine", encoding="utf-8")
    (out / "loss_maps_nu.txt").write_text("mine too", encoding="utf-8")
    assert main(["run", str(_scene(tmp_path, network=False)), "--out", str(out),
                 "--quiet"]) == 0
    for name in stale:
        path = out / name
        assert not path.exists() or path.read_bytes() != b"earlier run", name
    assert not (out / "temperatures.png").exists()  # a run without a network draws none
    assert not (out / "loss_maps_nu.png").exists()
    assert (out / "report.html").read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    assert (out / "my_notes.txt").read_text(encoding="utf-8") == "mine"
    assert (out / "loss_maps_nu.txt").is_file()


def test_an_out_that_is_a_file_is_refused_without_saying_it_writes_there(tmp_path, capsys):
    target = tmp_path / "afile"
    target.write_text("x", encoding="utf-8")
    assert main(["run", str(_scene(tmp_path, network=False)), "--out", str(target)]) == 1
    captured = capsys.readouterr()
    assert "writing results to" not in captured.out
    assert "this is a file" in captured.err
