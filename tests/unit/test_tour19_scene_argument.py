"""Session-19 user tour: a SCENE argument naming a file that is not there is refused as a
missing file (it was refused as a misspelt preset: "known names are: ...")."""

from __future__ import annotations

import pytest

from thermobearing.cli import main


@pytest.mark.parametrize("command", ["run", "check", "sweep", "calibrate"])
def test_a_missing_scene_file_is_named_as_a_file(tmp_path, monkeypatch, capsys, command):
    monkeypatch.chdir(tmp_path)
    extra = {"sweep": ["--set", "supply.flow=20", "--out", "s"],
             "calibrate": ["--fit", "network.parameters.h_oil"]}.get(command, [])
    assert main([command, "rigs/my_rig.toml", *extra]) != 0
    err = capsys.readouterr().err
    missing = tmp_path / "rigs" / "my_rig.toml"
    assert f"a scene TOML file (no such file: {missing})" in err, err
    assert "qj1044_rig" in err  # the presets are still offered


def test_a_folder_is_not_a_scene_and_a_preset_name_still_loads(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "results").mkdir()
    assert main(["check", "results"]) != 0
    assert f"(a folder: {tmp_path / 'results'})" in capsys.readouterr().err
    assert main(["check", "qj1044_synthetic_measured"]) == 0

