"""The kinematics' contact temperature follows the rolling elements: the solvers, their
re-solve test and the film table take the contacts' inlet oil temperature
(T_inner_ring + T_outer_ring + 2 T_elements) / 4, the heat sources' convention
(kinematic_models.contact_temperature)."""

from __future__ import annotations

import numpy as np
import pytest
from scene_parts import (
    PAPER002_OIL,
    QJ1044_DE,
    RACE_CONTROL,
    ROOM_22C,
    VG46_JET_2LPM,
    scene_title,
)

from thermobearing import simulation_tables
from thermobearing.coupled import RUNAWAY_TEMPERATURE
from thermobearing.errors import InputError
from thermobearing.kinematic_models import KINEMATICS, contact_temperature
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

BALL_SCENE = scene_title("t") + QJ1044_DE + PAPER002_OIL + """[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "4 kN"
duration = "3 min"
""" + RACE_CONTROL + """[outputs]
want = ["kinematics"]
"""

#: node temperatures [K] by role: hot elements, cooler rings (a run-up)
HOT_ELEMENTS = {"inner_ring": 330.0, "outer_ring": 320.0, "elements": 360.0,
                "cage": 340.0, "oil": 315.0}


def test_contact_temperature_is_the_mean_of_the_two_contact_inlets():
    t = contact_temperature(HOT_ELEMENTS)
    inner_inlet = 0.5 * (HOT_ELEMENTS["elements"] + HOT_ELEMENTS["inner_ring"])
    outer_inlet = 0.5 * (HOT_ELEMENTS["elements"] + HOT_ELEMENTS["outer_ring"])
    assert t == pytest.approx(0.5 * (inner_inlet + outer_inlet), rel=1e-15)
    assert t == pytest.approx((330.0 + 320.0 + 2 * 360.0) / 4, rel=1e-15)
    # cage and oil nodes do not enter
    assert contact_temperature({**HOT_ELEMENTS, "cage": 500.0, "oil": 290.0}) == t


def test_contact_temperature_names_a_missing_role():
    with pytest.raises(InputError, match="elements"):
        contact_temperature({"inner_ring": 330.0, "outer_ring": 320.0})


@pytest.fixture()
def recorded(monkeypatch):
    """The ball scene's Simulation with its kinematics function wrapped: every call's
    contact_temperature is recorded, the real model answers."""
    sim = Simulation(loads_scene(BALL_SCENE), progress=False)
    calls: list[float] = []
    real = KINEMATICS.get("race_control")

    def spy(*args, contact_temperature, **kw):
        calls.append(contact_temperature)
        return real(*args, contact_temperature=contact_temperature, **kw)

    monkeypatch.setattr(KINEMATICS, "get", lambda name: spy)
    return sim, calls


def test_kinematics_receive_the_element_weighted_temperature(recorded):
    sim, calls = recorded
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    sim.solve_kinematics(b, 0, step, HOT_ELEMENTS)
    assert calls == [pytest.approx(342.5, rel=1e-15)]  # not the rings' mean 325 K
    assert b.last_viscosity == pytest.approx(float(sim.lubricant.dynamic_viscosity(342.5)),
                                             rel=1e-15)


def test_resolve_test_reads_the_viscosity_at_the_same_temperature(recorded):
    sim, calls = recorded
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    tol = sim.scene.solver.kinematics_tolerance
    sim.solve_kinematics(b, 0, step, HOT_ELEMENTS)
    # rings exchanged, elements unchanged: the same contact temperature, no re-solve
    swapped = {**HOT_ELEMENTS, "inner_ring": 320.0, "outer_ring": 330.0}
    sim.solve_kinematics(b, 0, step, swapped)
    assert len(calls) == 1
    # only the elements warm: the contact oil thins; the rise that moves the viscosity by
    # twice the tolerance re-solves, at the new contact temperature
    eta0 = float(sim.lubricant.dynamic_viscosity(342.5))
    rises = np.linspace(0.0, 20.0, 2001)
    etas = np.array([float(sim.lubricant.dynamic_viscosity(342.5 + 0.5 * d)) for d in rises])
    small = rises[np.argmax(np.abs(etas / eta0 - 1.0) > 0.5 * tol)]
    large = rises[np.argmax(np.abs(etas / eta0 - 1.0) > 2.0 * tol)]
    sim.solve_kinematics(b, 0, step, {**HOT_ELEMENTS, "elements": 360.0 + small})
    assert len(calls) == 1  # viscosity moved by about half the tolerance: reused
    sim.solve_kinematics(b, 0, step, {**HOT_ELEMENTS, "elements": 360.0 + large})
    assert len(calls) == 2
    assert calls[-1] == pytest.approx(342.5 + 0.5 * large, rel=1e-15)


def test_film_table_takes_the_same_contact_temperature(monkeypatch):
    import thermobearing.state as state

    sim = Simulation(loads_scene(BALL_SCENE.replace('want = ["kinematics"]',
                                                    'want = ["film"]')), progress=False)
    seen: list[float] = []
    real = state.race_control_state

    def spy(*args, temperature, **kw):
        seen.append(temperature)
        return real(*args, temperature=temperature, **kw)

    monkeypatch.setattr(state, "race_control_state", spy)
    rows, _ = simulation_tables.film_table(sim.bearings[0], sim.lubricant,
                                           sim.scene.schedule.steps[0], HOT_ELEMENTS)
    assert seen == [pytest.approx(342.5, rel=1e-15)]
    assert rows and all(r["central film [um]"] > 0 for r in rows)


NU214_RUN_UP = """
title = "NU 214 fast run-up"
[[bearings]]
name = "de"
preset = "NU214"
""" + VG46_JET_2LPM + ROOM_22C + """[schedule]
radial_load = "8 kN"
axial_load = "0 kN"
steps = [{steps}]
[models]
kinematics = "skidding"
[network]
template = "four_node_paper002"
parameters = {{ housing_outer_diameter = "200 mm", housing_length = "50 mm" }}
[solver]
chunk = "{chunk}"
[outputs]
want = ["temperatures"]
"""

RAMP = ", ".join(f'{{ duration = "5 s", speed = "{n} rpm" }}' for n in (2000, 4000, 6000, 8000))


@pytest.mark.slow
@pytest.mark.parametrize("steps, chunk", [
    # 0 -> 10000 r/min at once, 2-s coupling chunks: the ring-mean contact temperature ran
    # the rollers past 300 degC at 14 s (7.5 kW of heat)
    ('{ duration = "1 min", speed = "10000 rpm" }', "2 s"),
    # 5-s steps to 10000 r/min, default 90-s chunks: the ring-mean contact temperature ran
    # the rollers to 502 degC at 110 s
    (RAMP + ', { duration = "3 min", speed = "10000 rpm" }', "90 s"),
], ids=["start_at_10000rpm", "ramp_5s_steps"])
def test_nu214_fast_run_up_does_not_run_away(steps, chunk):
    """A fast run-up heats the rollers within seconds while the rings lag: solved at the
    rings' mean the contact oil stayed thick, the contact losses high, and the coupled
    transient stopped as a thermal runaway. At the contacts' inlet temperature the run
    completes with every node below the runaway limit."""
    res = Simulation(loads_scene(NU214_RUN_UP.format(steps=steps, chunk=chunk)),
                     progress=False).run()
    temps = res.tables["temperatures"]
    rollers = temps["de.rollers [degC]"].to_numpy()
    assert temps["time [s]"].iloc[-1] == pytest.approx(sum(
        s.duration for s in loads_scene(NU214_RUN_UP.format(steps=steps, chunk=chunk))
        .schedule.steps))
    nodes = temps[[c for c in temps.columns if c.endswith("[degC]")]].to_numpy()
    assert np.all(np.isfinite(nodes))
    assert nodes.max() + 273.15 < RUNAWAY_TEMPERATURE
    # the rollers are the hottest node: their heat is what the contact temperature follows
    assert rollers.max() == nodes.max()
