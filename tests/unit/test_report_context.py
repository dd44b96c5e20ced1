"""The report says which bearing ran where, at which oil temperature the losses were
evaluated, how the run's total compares with the catalogue models, and whether the loss
breakdown is the heat the network received."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scene_parts import PAPER002_AMBIENT, PAPER002_JET, QJ1044_DE, scene_title

from thermobearing.global_friction import global_friction
from thermobearing.report_context import (
    bearing_table,
    catalogue_crosscheck,
    load_scene_bearings,
    load_scene_lubricant,
    loss_temperature_note,
    oil_temperatures,
    operating_points,
)
from thermobearing.report_losses import network_heat_check
from thermobearing.scene import loads_scene

_SCENE = scene_title("t") + QJ1044_DE + """[[bearings]]
name = "crb"
preset = "CRB_50x75x16"
""" + PAPER002_JET + PAPER002_AMBIENT + """initial_temperature = "30 degC"
[schedule]
radial_load = "1 kN"
axial_load = "10 kN"
steps = [{ duration = "3 min", speed = "1800 rpm" }, { duration = "6 min", speed = "600 rpm" }]
[outputs]
mode = "steady"
want = ["losses"]
"""


def _losses() -> pd.DataFrame:
    rows = []
    for name in ("de", "crb"):
        for step, (t, rpm, w) in enumerate(((180.0, 1800.0, 2000.0), (540.0, 600.0, 200.0))):
            for src, share in (("raceway_traction", 0.25), ("churning_elements", 0.75)):
                rows.append({"step": step, "time [s]": t, "bearing": name,
                             "speed [rpm]": rpm, "radial load [kN]": 1.0,
                             "axial load [kN]": 10.0, "source": src,
                             "power [W]": share * w})
    return pd.DataFrame(rows)


def test_bearing_and_schedule_tables_name_the_bearing_its_size_and_the_steps():
    scene = loads_scene(_SCENE)
    bearings, notes = load_scene_bearings(scene)
    assert notes == []
    table = bearing_table(scene, bearings)
    de = table.set_index("bearing").loc["de"]
    assert de["designation"] == "QJ1044" and de["d x D x B [mm]"] == "220 x 340 x 56"
    assert de["type"] == "four point" and de["nominal contact angle [deg]"] == pytest.approx(40.0)
    steps = operating_points(scene)
    assert list(steps["speed [rpm]"]) == pytest.approx([1800.0, 600.0])
    assert list(steps["duration [min]"]) == pytest.approx([3.0, 6.0])
    assert list(steps["axial load [kN]"]) == pytest.approx([10.0, 10.0])


def test_losses_without_a_network_are_said_to_be_at_the_initial_temperature():
    scene = loads_scene(_SCENE)
    note = loss_temperature_note({}, scene)
    assert "initial temperature, 30 degC" in note
    assert "steady-state" in loss_temperature_note({"steady_temperatures": None}, scene)
    temps = oil_temperatures(_losses(), {}, scene)
    np.testing.assert_allclose(temps, 303.15)


def test_oil_temperature_of_a_loss_row_follows_its_bearing_and_time():
    scene = loads_scene(_SCENE)
    temps = pd.DataFrame({"time [s]": [0.0, 360.0, 720.0],
                          "de.oil [degC]": [30.0, 40.0, 50.0],
                          "crb.oil [degC]": [30.0, 60.0, 90.0]})
    losses = _losses()
    t = oil_temperatures(losses, {"temperatures": temps}, scene) - 273.15
    de0 = (losses["bearing"] == "de") & (losses["step"] == 0)
    crb1 = (losses["bearing"] == "crb") & (losses["step"] == 1)
    np.testing.assert_allclose(t[de0], 35.0)   # 180 s: halfway to 40 degC
    np.testing.assert_allclose(t[crb1], 75.0)  # 540 s: halfway from 60 to 90 degC
    steady = pd.DataFrame({"step": [0, 1], "de.oil [degC]": [41.0, 33.0],
                           "crb.oil [degC]": [80.0, 70.0]})
    t = oil_temperatures(losses, {"steady_temperatures": steady}, scene) - 273.15
    np.testing.assert_allclose(t[crb1], 70.0)


def test_crosscheck_sets_the_run_beside_the_catalogue_models_at_its_oil_temperature():
    scene = loads_scene(_SCENE)
    bearings, _ = load_scene_bearings(scene)
    lub = load_scene_lubricant(scene)
    table, notes = catalogue_crosscheck(_losses(), {}, scene, bearings, lub)
    row = table[(table["bearing"] == "de") & (table["step"] == 0)].iloc[0]
    skf = global_friction("skf_four_term", bearings["de"], lub, 303.15,
                          1800.0 * 2 * math.pi / 60, 1e3, 10e3, lubrication="jet")
    assert row["this run [W]"] == pytest.approx(2000.0)
    assert row["oil [degC]"] == pytest.approx(30.0)
    assert row["SKF four-term [W]"] == pytest.approx(skf.power)
    assert row["this run vs SKF four-term [%]"] == pytest.approx(
        100.0 * (2000.0 / skf.power - 1.0))
    assert "Palmgren M0 + M1 [W]" in table
    # the SKF series of a designation it cannot read is said once, not guessed
    crb = table[table["bearing"] == "crb"]
    assert crb["SKF four-term [W]"].isna().all()
    assert len([n for n in notes if n.startswith("skf_four_term for bearing crb")]) == 1


def test_breakdown_matches_the_heat_the_network_received():
    losses = _losses()
    # the network's heat: 4000 W up to 180 s (two bearings at 2000 W), 400 W after
    energy = pd.DataFrame({"time [s]": [90.0, 180.0, 360.0, 540.0]})
    energy["generated [J]"] = [4000.0 * 90, 4000.0 * 180, 4000.0 * 180 + 400.0 * 180,
                               4000.0 * 180 + 400.0 * 360]
    check = network_heat_check(losses, energy)
    assert list(check["step"]) == [0, 1]
    np.testing.assert_allclose(check["breakdown total [W]"], [4000.0, 400.0])
    np.testing.assert_allclose(check["network heat input [W]"], [4000.0, 400.0])
    np.testing.assert_allclose(check["difference [%]"], 0.0, atol=1e-12)
    # a breakdown that misses heat shows as a difference
    short = losses[losses["source"] != "raceway_traction"]
    assert network_heat_check(short, energy)["difference [%]"].iloc[0] == pytest.approx(
        100.0 / 3.0)
    assert network_heat_check(losses, pd.DataFrame()) is None


def test_crosscheck_takes_the_series_the_scene_names_without_running_the_source():
    """A designation without a readable SKF series (CRB_50x75x16) gets the SKF column when
    the scene names the series under [models] heat_source_options.global_friction, with
    global_friction not among the heat sources (it was refused there until the option
    became a cross-check input; then the report did not read it)."""
    only_crb = (_SCENE.replace('[[bearings]]\nname = "de"\npreset = "QJ1044"\n', "")
                .replace("[outputs]", "[models]\nheat_source_options = { global_friction = "
                         '{ series = "10" } }\n[outputs]'))
    scene = loads_scene(only_crb)
    bearings, _ = load_scene_bearings(scene)
    lub = load_scene_lubricant(scene)
    losses = _losses()
    losses = losses[losses["bearing"] == "crb"]
    table, notes = catalogue_crosscheck(losses, {}, scene, bearings, lub)
    row = table[table["step"] == 0].iloc[0]
    skf = global_friction("skf_four_term", bearings["crb"], lub, row["oil [degC]"] + 273.15,
                          1800.0 * 2 * math.pi / 60, 1e3, 10e3, lubrication="jet",
                          series="10")
    assert row["SKF four-term [W]"] == pytest.approx(skf.power)
    assert not [n for n in notes if n.startswith("skf_four_term for bearing crb")]
    # without the option the series is refused, as before
    table0, notes0 = catalogue_crosscheck(losses, {}, loads_scene(
        _SCENE.replace('[[bearings]]\nname = "de"\npreset = "QJ1044"\n', "")), bearings, lub)
    col = "SKF four-term [W]"
    assert col not in table0 or table0[col].isna().all()
    assert [n for n in notes0 if n.startswith("skf_four_term for bearing crb")]
