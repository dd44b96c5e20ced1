"""Session-23 user tour D, the test-rig engineer with a cylindrical roller bearing rig: an
NU 214 made NJ-type in the scene (``ribbed_ring = "both"`` and rib geometry overrides),
8-12 kN radial with 0.5-1 kN thrust on a 2 L/min jet, the rib source's heat sources copied
from ``configs/scenes/crb_rib_example.toml``, a logger file with an extra channel.

Found: a rib too low for the end face was refused under ``models.heat_sources =
'rib_friction'`` with ``rib.rib_height = 0.003`` (metres) inside, and without
``heat_sources`` the source was left out with a hint to add the keys the bearing already
had, said by ``run`` but not by ``check``; an overridden ``ribbed_ring`` stayed among the
estimated inputs with the preset's "NU type" reasoning; an unbalance mass above the roller
mass passed ``check`` and stopped the run at its first solve (``unbalance_mass = 0.005``);
the copied source list books no rolling resistance under race control (``raceway_traction``
0.0 W on every step), said nowhere; ``check`` did not say which columns of the file no
node reads.
"""

from __future__ import annotations

import pytest

from thermobearing import cli, load_scene
from thermobearing.errors import InputError
from thermobearing.simulation import Simulation

RIB = ('ribbed_ring = "both", end_face_crown_radius = "500 mm", rib_angle = "0.5 deg", '
       'rib_height = "{rib}", axial_clearance = "0.05 mm"')
SOURCES = ('heat_sources = ["raceway_traction", "churning_elements", "churning_cage", '
           '"churning_inner_ring", "cage_guide", "pocket_friction", "rib_friction"]')

SCENE = """title = "NJ 214 rig"
[[bearings]]
name = "test"
preset = "NU214"
overrides = {{ {overrides} }}
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
[schedule]
radial_load = "8 kN"
axial_load = "0.5 kN"
step_duration = "5 min"
steps = [{{ speed = "2000 rpm" }}, {{ speed = "4000 rpm", axial_load = "1 kN" }}]
[models]
kinematics = "race_control"
{models}
[network]
template = "four_node_paper002"
parameters = {{ housing_outer_diameter = "180 mm", housing_length = "50 mm" }}
{measured}
[outputs]
want = ["temperatures", "losses"]
"""


def _scene(tmp_path, *, rib="3 mm", models=SOURCES, measured="", overrides=None):
    path = tmp_path / "rig.toml"
    path.write_text(SCENE.format(overrides=overrides or RIB.format(rib=rib), models=models,
                                 measured=measured))
    return path


def test_a_rib_below_the_contact_point_is_named_in_the_scene_with_its_unit(tmp_path):
    """0.5 deg rib face and a 500 mm crown put the end face's contact 2.137 mm above the
    inner raceway: a 1.5 mm rib is not touched."""
    with pytest.raises(InputError) as info:
        Simulation(load_scene(_scene(tmp_path, rib="1.5 mm")), progress=False)
    err = info.value
    assert err.field == "bearings[0].overrides.rib_height" and err.value == "1.5 mm"
    assert "H_contact = 2.137 mm" in str(err) and "0.0015" not in str(err)
    assert "rib_friction" in str(err)


def test_a_default_rib_source_left_out_is_said_by_check_with_the_right_hint(tmp_path,
                                                                           capsys):
    path = _scene(tmp_path, rib="1.5 mm", models="")
    assert cli.main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "default heat source rib_friction left out (rib_height = 1.5 mm" in out
    assert "change the bearing's rib_height, rib_angle or end_face_crown_radius" in out
    assert "once the bearing has end_face_crown_radius and rib_height" not in out
    assert "the axial load of steps 0, 1 books no loss" in out


def test_overridden_values_are_no_longer_listed_as_estimated(tmp_path):
    overrides = RIB.format(rib="3 mm") + ', cage = { inner_diameter = "91.5 mm" }'
    sim = Simulation(load_scene(_scene(tmp_path, overrides=overrides)), progress=False)
    estimated = sim.estimated_inputs()["bearing test (NU214)"]
    assert "ribbed_ring" not in estimated and "cage.inner_diameter" not in estimated
    # what the scene leaves to the preset keeps its mark and reasoning
    assert "cage.outer_diameter" in estimated and "outer_diameter" in estimated


def test_an_unbalance_heavier_than_the_roller_is_refused_before_the_run(tmp_path):
    models = (SOURCES + '\nheat_source_options = { rib_friction = { unbalance_mass = '
              '"50 g" } }')
    with pytest.raises(InputError) as info:
        Simulation(load_scene(_scene(tmp_path, models=models)), progress=False)
    err = info.value
    assert err.field == "models.heat_source_options.rib_friction.unbalance_mass"
    assert err.value == "50 g" and "roller mass" in str(err) and " g of NU214" in str(err)


def test_a_source_list_without_rolling_resistance_under_race_control_is_noted(tmp_path):
    sim = Simulation(load_scene(_scene(tmp_path)), progress=False)
    notes = [n for n in sim.notes if "rolling resistance" in n]
    assert len(notes) == 1 and "ehl_rolling_resistance" in notes[0]
    assert "raceway_traction books 0 W" in notes[0]
    listed = SOURCES.replace('"raceway_traction",', '"raceway_traction", '
                             '"ehl_rolling_resistance",')
    sim = Simulation(load_scene(_scene(tmp_path, models=listed)), progress=False)
    assert not [n for n in sim.notes if "rolling resistance" in n]
    sim = Simulation(load_scene(_scene(tmp_path, models="")), progress=False)  # defaults
    assert not [n for n in sim.notes if "rolling resistance" in n]


def test_check_names_the_file_columns_no_node_reads(tmp_path, capsys):
    (tmp_path / "rig.csv").write_text(
        "Logger export\nZeit [min];TC outer ring [degC];TC oil out [degC];TC ambient [degC]\n"
        "0,0;25,0;40,0;25,0\n0,5;27,4;;25,0\n1,0;----;42,2;25,1\n")
    measured = ('[measured]\nfile = "rig.csv"\ntime_column = "Zeit [min]"\nunit = "degC"\n'
                'columns = { "TC outer ring [degC]" = "test.housing", '
                '"TC oil out [degC]" = "test.oil" }')
    path = _scene(tmp_path, measured=measured)
    assert cli.main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "measured: rig.csv: 2 sensors, 3 samples" in out
    assert "not compared (no node in [measured] columns): 'TC ambient [degC]'" in out


def test_a_rib_angle_putting_the_contact_off_the_roller_names_both_bearing_keys(tmp_path):
    """5 deg on a 500 mm crown: the contact point 43.6 mm from the roller axis. The two
    fields were 'bearings[0] (NU214) rib_angle / rib.crown_radius' (the model's name of
    the crown, and not the scene's overrides)."""
    overrides = RIB.format(rib="3 mm").replace('"0.5 deg"', '"5 deg"')
    with pytest.raises(InputError) as info:
        Simulation(load_scene(_scene(tmp_path, overrides=overrides)), progress=False)
    err = info.value
    assert err.field == "bearings[0].overrides.rib_angle / end_face_crown_radius"
    assert err.value == "5 deg / 500 mm" and "a rib angle < 1.49 deg" in str(err)
