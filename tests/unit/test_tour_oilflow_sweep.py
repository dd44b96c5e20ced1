"""An oil-flow what-if study from the command line (issue 6, a user tour of flow-rate,
inlet-temperature and oil-grade sweeps on the default rig and a catalogue bearing): each
test is a defect found by running ``thermobearing sweep`` / ``report``, written before its
fix.
"""

from __future__ import annotations

import textwrap

import pytest

from thermobearing.network import oil_capacity_rate
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation, summarize_scene

#: one steady operating point of the default rig (one QJ1044, 1800 r/min, 20 kN axial)
STEADY_RIG = textwrap.dedent("""
    title = "QJ1044 rig, one steady point"
    [[bearings]]
    name = "drive_end"
    preset = "QJ1044"
    [lubricant]
    preset = "ISO_VG46"
    [supply]
    method = "jet"
    flow = "33 L/min"
    inlet_temperature = "35 degC"
    [environment]
    ambient_temperature = "35 degC"
    [schedule]
    speed = "1800 rpm"
    radial_load = "1 kN"
    axial_load = "20 kN"
    steps = [{ duration = "3 min" }]
    [network]
    template = "four_node_paper002"
    parameters.housing_outer_diameter = "510 mm"
    parameters.housing_length = "140 mm"
    parameters.shaft_diameter = "220 mm"
    parameters.shaft_length = "500 mm"
    [outputs]
    mode = "steady"
    want = ["temperatures", "losses", "kinematics"]
""")


# --- a steady what-if sweep gave no temperatures --------------------------------------
def test_steady_scene_summary_has_the_steady_temperatures():
    # before: summarize_scene read only the transient 'temperatures' table, so a sweep of a
    # steady scene (the quick what-if: one steady point per flow) had losses and skidding
    # but no oil outlet, ball or housing temperature at all
    out = summarize_scene(STEADY_RIG)
    steady = Simulation(loads_scene(STEADY_RIG), progress=False).run() \
        .tables["steady_temperatures"]
    for node in ("balls", "housing", "shaft", "oil"):
        col = f"drive_end.{node} [degC]"
        assert out[f"final {col}"] == pytest.approx(float(steady[col].iloc[-1]), abs=1e-9)
        assert out[f"rise drive_end.{node} [K]"] == pytest.approx(
            float(steady[col].iloc[-1]) - 35.0, abs=1e-9)
    # the oil stream carries part of the loss away (energy balance of the steady state):
    # m_dot c_p (T_out - T_in) is positive and not above the total loss
    scene = loads_scene(STEADY_RIG)
    lub = Simulation(scene, progress=False).lubricant
    carried = oil_capacity_rate(lub, scene.supply.flow, scene.supply.inlet_temperature) \
        * out["rise drive_end.oil [K]"]
    assert 0.0 < carried <= out["total loss [W]"]

