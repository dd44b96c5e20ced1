"""Per-bearing load shares ([[bearings]] load_share): a shaft's bearings carry their own
fractions of the schedule's loads."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

PAIR = """
title = "locating deep-groove ball bearing and floating NU on one shaft"
[[bearings]]
name = "locating"
preset = "SKF6304"
{locating}
[[bearings]]
name = "floating"
preset = "NU214"
{floating}
[lubricant]
preset = "ISO_VG46"
[supply]
flow = "1 L/min"
inlet_temperature = "40 degC"
[schedule]
speed = "3000 rpm"
radial_load = "2 kN"
axial_load = "0.5 kN"
[models]
kinematics = "race_control"
[outputs]
want = ["kinematics", "losses"]
"""


def test_floating_nu_takes_no_axial_load_and_the_radial_load_splits():
    """An NU bearing refuses an axial load; with load_share axial = 0 it floats, and the
    tables carry each bearing's own loads (2 kN radial split 0.4 / 0.6, the axial load on
    the locating ball bearing)."""
    with pytest.raises(InputError, match="ribbed_ring = 'outer' is an NU-type"):
        Simulation(loads_scene(PAIR.format(locating="", floating="")), progress=False)
    text = PAIR.format(locating="load_share = { radial = 0.4 }",
                       floating="load_share = { radial = 0.6, axial = 0 }")
    sim = Simulation(loads_scene(text), progress=False)
    res = sim.run()
    kin = res.tables["kinematics"].set_index("bearing")
    assert kin.loc["locating", "radial load [kN]"] == pytest.approx(0.8)
    assert kin.loc["locating", "axial load [kN]"] == pytest.approx(0.5)
    assert kin.loc["floating", "radial load [kN]"] == pytest.approx(1.2)
    assert kin.loc["floating", "axial load [kN]"] == 0.0
    # the solved states carry the shares: the inner-ring reaction balances the share
    for b, (fr, fa) in zip(sim.bearings, ((800.0, 500.0), (1200.0, 0.0)), strict=True):
        assert b.loads(sim.scene.schedule.steps[0]) == pytest.approx((fr, fa))
    losses = res.tables["losses"]
    assert set(losses["bearing"]) == {"locating", "floating"}
    assert losses.loc[losses["bearing"] == "floating", "axial load [kN]"].eq(0.0).all()


def test_identical_bearings_with_different_shares_do_not_share_states():
    text = """
title = "two 6304 with different radial shares"
[[bearings]]
name = "a"
preset = "SKF6304"
load_share = { radial = 0.25 }
[[bearings]]
name = "b"
preset = "SKF6304"
load_share = { radial = 0.75 }
[lubricant]
preset = "ISO_VG46"
[supply]
flow = "1 L/min"
inlet_temperature = "40 degC"
[schedule]
speed = "3000 rpm"
radial_load = "4 kN"
axial_load = "0 kN"
[models]
kinematics = "race_control"
[outputs]
want = ["kinematics"]
"""
    kin = Simulation(loads_scene(text), progress=False).run().tables["kinematics"]
    p = kin.set_index("bearing")["max contact pressure [MPa]"]
    assert p["b"] > p["a"] * 1.2


@pytest.mark.parametrize("share, text", [
    ("{ radial = -0.5 }", "a fraction >= 0"),
    ("{ radial = \"half\" }", "a number"),
    ("{ tangential = 1 }", "tangential"),
])
def test_bad_shares_name_the_field(share, text):
    with pytest.raises(InputError, match=r"bearings\[0\]\.load_share") as err:
        loads_scene(PAIR.format(locating=f"load_share = {share}", floating=""))
    assert text in str(err.value)


def test_load_share_round_trips_through_to_toml():
    sc = loads_scene(PAIR.format(locating="load_share = { radial = 0.4 }",
                                 floating="load_share = { radial = 0.6, axial = 0 }"))
    again = loads_scene(sc.to_toml())
    assert [b.load_share for b in again.bearings] == [{"radial": 0.4},
                                                       {"radial": 0.6, "axial": 0.0}]


def test_check_and_the_report_say_each_share():
    sim = Simulation(loads_scene(PAIR.format(
        locating="load_share = { radial = 0.4 }",
        floating="load_share = { radial = 0.6, axial = 0 }")), progress=False)
    assert ("floating carries 0.6 of the schedule's radial load and 0 of its axial load "
            "([[bearings]] load_share)") in sim.describe_chain()
    assert any(w.startswith("locating carries 0.4") for w in sim.warnings)
