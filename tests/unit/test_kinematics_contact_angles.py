"""Contact-angle columns of the kinematics table (simulation_tables.contact_angle_columns)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from scene_parts import RACE_CONTROL, ROOM_22C, VG32_OIL_AIR, VG46_2LPM

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

SPINDLE = f"""
title = "7014 C at speed, kinematics only"
[[bearings]]
name = "front"
path = "{(EXAMPLES / 'spindle_7014C_catalogue.toml').as_posix()}"
{VG32_OIL_AIR}{ROOM_22C}[schedule]
radial_load = "200 N"
axial_load = "500 N"
steps = [{{ duration = "1 min", speed = "0 r/min" }},
         {{ duration = "1 min", speed = "4000 r/min" }},
         {{ duration = "1 min", speed = "16000 r/min" }}]
[models]
kinematics = "@KIN@"
[outputs]
want = ["kinematics"]
"""


def _table(kinematics: str):
    sim = Simulation(loads_scene(SPINDLE.replace("@KIN@", kinematics)), progress=False)
    return sim.run().tables["kinematics"], sim.bearings[0].bearing


@pytest.mark.parametrize("kinematics", ["skidding", "race_control"])
def test_angles_are_load_weighted_and_turn_apart_with_speed(kinematics):
    """7014 C (15 deg nominal), 500 N axial + 200 N radial: at 4000 r/min both angles sit
    near the mounted angle; at 16000 r/min the balls' centrifugal force turns the outer
    angle down and the inner one up (measured with the skidding solver: 17.5 / 15.8 deg at
    4000, 25.4 / 6.0 deg at 16000 r/min)."""
    kin, bearing = _table(kinematics)
    nominal = math.degrees(bearing.contact_angle)
    at = kin.set_index("speed [rpm]")
    i4, o4 = at.loc[4000.0, ["inner contact angle [deg]", "outer contact angle [deg]"]]
    i16, o16 = at.loc[16000.0, ["inner contact angle [deg]", "outer contact angle [deg]"]]
    assert abs(i4 - nominal) < 5 and abs(o4 - nominal) < 5
    assert o16 < o4 < i4 < i16
    assert i16 - o16 > 10.0


def test_angles_at_rest_and_for_rollers():
    """At rest the static contacts still give the angles; a roller bearing gets no
    contact-angle columns."""
    kin, _ = _table("skidding")
    rest = kin[kin["speed [rpm]"] == 0.0].iloc[0]
    assert 10.0 < rest["inner contact angle [deg]"] < 30.0
    from thermobearing.simulation_tables import contact_angle_columns

    roller = Simulation(loads_scene("""
title = "NU 214"
[[bearings]]
name = "r"
preset = "NU214"
""" + VG46_2LPM + """[schedule]
speed = "3000 rpm"
radial_load = "8 kN"
axial_load = "0 kN"
""" + RACE_CONTROL + """[outputs]
want = ["kinematics"]
"""), progress=False)
    res = roller.run()
    assert not any("contact angle" in c for c in res.tables["kinematics"].columns)
    assert contact_angle_columns(roller.bearings[0].last, roller.bearings[0].bearing) == {}


def test_global_friction_rows_have_no_contact_pressure():
    """kinematics = "none" (SKF / Palmgren global model) solves no contacts at a turning
    step: the pressure, film-parameter and angle columns are NaN there, not 0."""
    text = SPINDLE.replace("@KIN@", "none").replace(
        'want = ["kinematics"]', 'want = ["kinematics", "losses"]').replace(
        'kinematics = "none"', 'kinematics = "none"\nheat_sources = ["global_friction"]\n'
        'heat_source_options = { global_friction = { model = "palmgren" } }')
    res = Simulation(loads_scene(text), progress=False).run()
    kin = res.tables["kinematics"]
    kin = kin[kin["speed [rpm]"] > 0]  # (at rest the static contacts are solved)
    assert len(kin) == 2
    for col in ("max contact pressure [MPa]", "min film parameter [-]",
                "inner contact angle [deg]", "outer contact angle [deg]"):
        assert kin[col].isna().all(), col


def test_skidding_solver_states_report_the_film_formula_outside_its_range_once_per_shape():
    """The ball solver's film (Hamrock-Dowson 1977, compiled without checks) is checked on
    the converged state like race control's: the 7014 C at 4000-16000 r/min is beyond the
    fitted U, W and k ranges, and the run lists it in merged lines (inner and outer
    contacts: two shapes), not once per step and contact."""
    sim = Simulation(loads_scene(SPINDLE.replace("@KIN@", "skidding")), progress=False)
    res = sim.run()
    film = [w for w in res.warnings if "hamrock_dowson_1977_central" in w]
    assert 1 <= len(film) <= 2
    assert all(w.startswith("front, steps 1-2: ") for w in film)
    assert any("U in [" in w and "outside [1e-12, 1e-10]" in w for w in film)


def test_round_off_contacts_of_an_unloaded_state_give_no_angle():
    """Race control without any load leaves contacts with round-off loads (~3e-10 N): no
    angle is reported from them (was an inner angle of 23.8 deg for the 7014 C)."""
    text = SPINDLE.replace("@KIN@", "race_control").replace(
        'radial_load = "200 N"', 'radial_load = "0 N"').replace(
        'axial_load = "500 N"', 'axial_load = "0 N"')
    kin = Simulation(loads_scene(text), progress=False).run().tables["kinematics"]
    turning = kin[kin["speed [rpm]"] > 0]
    assert turning["inner contact angle [deg]"].isna().all()
