"""Session-19 user tour, the terminal summary and the sweep summary: the over-skidding range
is that of every solved state, as the skid warnings are, not only the kinematics table's
first state of each step."""

from __future__ import annotations

import math
import re
import warnings

import pandas as pd
import pytest
from scene_parts import VG32_JET, scene_title

from thermobearing.operating_checks import CheckLog, StateCheck
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation, _first_csr_lines
from thermobearing.simulation_summary import summarize_scene
from thermobearing.simulation_tables import over_skidding_range

#: an NU 214 warming up at 8000 r/min under 500 N: its cage slows as the oil thins within
#: the step (the kinematics are re-solved as the viscosity moves), so the step's first
#: state is not its worst
NU214 = scene_title("NU214 warming at 8000 r/min") + """[[bearings]]
name = "nu"
preset = "NU214"
""" + VG32_JET + """[environment]
ambient_temperature = "25 degC"
[schedule]
radial_load = "500 N"
axial_load = "0 N"
step_duration = "5 min"
steps = [{ speed = "8000 rpm" }]
[network]
template = "four_node_paper002"
[network.parameters]
housing_outer_diameter = "180 mm"
housing_length = "40 mm"
shaft_diameter = "70 mm"
shaft_length = "200 mm"
[outputs]
want = ["temperatures", "losses", "kinematics"]
"""


def _state(csr: float, csr_th: float = 0.45) -> StateCheck:
    return StateCheck(slip=csr / csr_th - 1.0, csr=csr, csr_th=csr_th, max_pressure=1e9,
                      stress_limit=4e9, film_parameter=None)


def test_the_range_covers_the_states_re_solved_within_a_step():
    kin = pd.DataFrame({"step": [0, 1], "bearing": ["b", "b"],
                        "cage speed ratio [-]": [0.45, 0.40],
                        "theoretical cage speed ratio [-]": [0.45, 0.45],
                        "over-skidding [%]": [0.0, 100 * (0.40 / 0.45 - 1)]})
    log = CheckLog(bearing="b", roughness=None)
    for step, csr in ((0, 0.45), (1, 0.40), (1, 0.36), (1, 0.37)):
        log.record(step, _state(csr))
    hi, lo = over_skidding_range(kin, {"b": log})
    assert hi == 0.0 and lo == pytest.approx(100 * (0.36 / 0.45 - 1), rel=1e-12)
    # the table alone, and no over-skidding at all (kinematics "none", every step at rest)
    assert over_skidding_range(kin, {})[1] == pytest.approx(100 * (0.40 / 0.45 - 1))
    assert over_skidding_range(kin.assign(**{"over-skidding [%]": math.nan}),
                               {"b": log}) is None
    line = _first_csr_lines(kin, {"b": log})[1]
    assert line == ("over-skidding over every solved state: max +0.00 %, min -20.00 % "
                    "(kinematics.csv: each step's first state)")
    assert _first_csr_lines(kin, {"b": log}, race_control=True)[1].endswith(
        "(race control: the cage rolls by construction)")


def test_terminal_and_sweep_summaries_agree_with_the_skid_warning():
    """The terminal said "over-skidding: ... min -37.83 %" (the step's first state) under a
    warning of "-44.7 % at step 2" for the same run; a sweep's min over-skidding was the
    table's too."""
    sim = Simulation(loads_scene(NU214), progress=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = sim.run()
    first = float(res.tables["kinematics"]["over-skidding [%]"].min())
    text = sim.summary_text(res)
    got = float(re.search(r"min ([-+0-9.]+) % \(kinematics", text).group(1))
    warned = [w for w in res.warnings if "cage skidding" in w]
    assert len(warned) == 1
    largest = float(re.search(r"largest ([-+0-9.]+) %", warned[0]).group(1))
    assert got == pytest.approx(largest, abs=0.051)  # the warning rounds to 0.1 %
    assert got < first - 1.0  # the step's first state skids less than its worst
    summary = summarize_scene(NU214)
    assert summary["min over-skidding [%]"] == pytest.approx(got, abs=0.006)


def test_a_steady_run_checks_its_steady_states_and_prints_its_temperatures():
    """A steady run's skid warning took the fixed-point iterates' CSR (not states the
    bearing runs in), the terminal called its rows "each step's first state" and printed
    no temperature."""
    text = NU214.replace('want = ["temperatures", "losses", "kinematics"]',
                         'mode = "steady"\nwant = ["temperatures", "losses", "kinematics"]')
    text = text.replace('steps = [{ speed = "8000 rpm" }]',
                        'steps = [{ speed = "8000 rpm" }, { speed = "2000 rpm" }]')
    sim = Simulation(loads_scene(text), progress=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = sim.run()
    kin = res.tables["kinematics"]
    for i, states in sim.checks["nu"].steps.items():
        (state,) = states  # the steady state only
        assert state.csr == pytest.approx(float(kin["cage speed ratio [-]"].iloc[i]),
                                          rel=1e-12)
    out = sim.summary_text(res)
    lo = float(kin["over-skidding [%]"].min())
    assert "over-skidding at the steady states: max " in out and f"min {lo:+.2f} %" in out
    assert "each step's first state" not in out
    steady = res.tables["steady_temperatures"]
    hot = int(steady["nu.rollers [degC]"].to_numpy().argmax())
    assert f"hottest steady state (step {hot}): nu.rollers " in out
    assert "last steady state (step 1)" in out or hot == 1
