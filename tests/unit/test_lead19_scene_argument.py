"""load_scene with a path that is not there, and the preset suggestion (session 19 tour)."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG46_JET_1LPM, scene_title

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.scene import load_scene


def test_missing_toml_file_is_named(tmp_path):
    missing = tmp_path / "nosuch.toml"
    with pytest.raises(InputError) as info:
        load_scene(str(missing))
    msg = str(info.value)
    assert not isinstance(info.value, UnknownNameError)
    assert "no such file" in msg and str(missing) in msg
    assert "qj1044_rig" in msg  # the presets are still listed


def test_folder_is_named(tmp_path):
    with pytest.raises(InputError, match="a folder"):
        load_scene(str(tmp_path))


def test_preset_prefix_is_suggested():
    pattern = r"did you mean 'qj1044_rig' or 'qj1044_synthetic_measured'"
    with pytest.raises(UnknownNameError, match=pattern):
        load_scene("qj1044")


def test_misspelt_preset_still_unknown_name():
    with pytest.raises(UnknownNameError, match="known names are"):
        load_scene("qj1044_rgi_x")


def test_misspelt_network_material_names_the_scene_parameter():
    """A template's UnknownNameError (a misspelt ``housing_material``) is reported under the
    scene's [network] parameters with the presets listed, as other template errors are."""
    from thermobearing import Simulation
    from thermobearing.coupled import build_network
    from thermobearing.scene import loads_scene

    text = scene_title("probe") + SKF6304_A + VG46_JET_1LPM + """[schedule]
speed = "3000 rpm"
radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{}]
[models]
kinematics = "race_control"
heat_sources = ["raceway_traction"]
[network]
template = "four_node_paper002"
[network.parameters]
housing_outer_diameter = "100 mm"
housing_length = "30 mm"
housing_material = "steel"
"""
    sim = Simulation(loads_scene(text))
    with pytest.raises(UnknownNameError) as info:
        build_network(sim)
    assert info.value.field == "network.parameters.housing_material"
    assert info.value.value == "steel"
    assert "STEEL_52100" in info.value.known


def test_a_sensor_column_of_only_gaps_says_it_is_not_compared(tmp_path):
    from thermobearing.measured import measured_notes, read_measured_file

    path = tmp_path / "log.csv"
    path.write_text("time [s],TC1,TC2\n0,20.0,OVL\n60,21.0,OVL\n120,22.0,\n")
    got = read_measured_file(path, "time [s]", ["TC1", "TC2"])
    notes = measured_notes(got)
    assert notes == ["TC2: every reading (3) is a gap (1 empty cell, 2 dropout flags); "
                     "this sensor is not compared with the model"]
