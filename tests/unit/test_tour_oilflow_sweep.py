"""An oil-flow what-if study from the command line (issue 6, a user tour of flow-rate,
inlet-temperature and oil-grade sweeps on the default rig and a catalogue bearing): each
test is a defect found by running ``thermobearing sweep`` / ``report``, written before its
fix.
"""

from __future__ import annotations

import textwrap

import pytest

from thermobearing.network import oil_capacity_rate
from thermobearing.scene import load_scene, loads_scene
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



def capacity_runner(scene_toml: str) -> dict[str, float]:
    """The oil flow [L/min] of a case: enough to see which case ran with which flow,
    without the physics."""
    return {"flow seen [L/min]": loads_scene(scene_toml).supply.flow * 60e3}


# --- flows in m3/s (and other data-sheet spellings) lost their numeric column ------------
@pytest.mark.parametrize("spec, column, numbers", [
    ("supply.flow=2.5e-4,5.5e-4 m3/s", "supply.flow [m3/s]", [2.5e-4, 5.5e-4]),
    ("supply.flow=900 L/h,5.5e-4 m3/s", "supply.flow [L/h]", [900.0, 1980.0]),
    ("schedule.speed=1500,1800 r/min", "schedule.speed [r/min]", [1500.0, 1800.0]),
])
def test_summary_numeric_column_reads_data_sheet_units(tmp_path, spec, column, numbers):
    # before: summary.csv had 'supply.flow' with "0.00025 m3/s" but no numeric
    # 'supply.flow [m3/s]' column (the scene reads m3/s, the summary asked pint directly),
    # so the table did not plot and the unit was nowhere in a column name
    from thermobearing.sweep import parse_set, run_sweep

    scene = load_scene()
    df = run_sweep(scene, [parse_set(spec, scene.to_dict())], tmp_path, workers=1,
                   runner=capacity_runner, progress=False, check=False)
    assert column in df.columns
    assert df[column].tolist() == pytest.approx(numbers, rel=1e-12)


def test_same_speed_in_rpm_and_r_per_min_is_one_case():
    # before: "1800 rpm" and "1800 r/min" were two values (two identical cases run)
    from thermobearing.sweep import parse_set

    p = parse_set("schedule.speed=1800 rpm,1800 r/min,1500 r/min", load_scene().to_dict())
    assert p.values == ("1800 rpm", "1500 r/min")
    assert len(p.dropped) == 1 and "1800 r/min" in p.dropped[0]
