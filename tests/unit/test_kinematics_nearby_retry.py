"""A kinematics solve that stalls at the current temperatures is retried a fraction of a
kelvin away (Simulation._solve_nearby), inside the viscosity tolerance the coupled run
already accepts; the shift is reported, and the exact-temperature error is raised when the
nearby solves fail too."""

from __future__ import annotations

import pytest

from thermobearing.errors import ConvergenceError
from thermobearing.kinematic_models import KINEMATICS
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "stall retry"
[[bearings]]
name = "de"
preset = "QJ1044"
[lubricant]
preset = "ISO_VG46"
[supply]
flow = "40 L/min"
inlet_temperature = "40 degC"
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "4 kN"
[models]
kinematics = "skidding"
[outputs]
mode = "steady"
want = ["kinematics"]
"""

TEMPS = {"elements": 323.70, "outer_ring": 309.80, "inner_ring": 309.73, "cage": 313.90,
         "oil": 313.90}


def _stalling(monkeypatch, stall_everywhere: bool):
    real = KINEMATICS.get("skidding")
    calls = []

    def fn(*args, **kw):
        calls.append((kw["contact_temperature"], kw["oil_temperature"]))
        if stall_everywhere or kw["oil_temperature"] == TEMPS["oil"]:
            raise ConvergenceError("skidding.ball", 6.66e-4, "stalled (test)")
        return real(*args, **kw)

    original_get = KINEMATICS.get
    monkeypatch.setattr(KINEMATICS, "get",
                        lambda name: fn if name == "skidding" else original_get(name))
    return calls


def test_stalled_solve_is_retried_nearby_and_reported(monkeypatch):
    sim = Simulation(loads_scene(SCENE), progress=False)
    calls = _stalling(monkeypatch, stall_everywhere=False)
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    kin = sim.solve_kinematics(b, 0, step, TEMPS)
    assert kin.raw.converged
    shifted = calls[-1]
    d_oil = shifted[1] - TEMPS["oil"]
    assert 0.0 < abs(d_oil) < 0.5  # a fraction of a kelvin
    t_contact = (TEMPS["inner_ring"] + TEMPS["outer_ring"] + 2 * TEMPS["elements"]) / 4
    assert shifted[0] - t_contact == pytest.approx(d_oil)
    # the shift stays well inside the kinematics tolerance of the viscosity
    tol = sim.scene.solver.kinematics_tolerance
    ratio = (sim.lubricant.dynamic_viscosity(shifted[0])
             / sim.lubricant.dynamic_viscosity(t_contact))
    assert abs(float(ratio) - 1.0) <= tol / 4
    assert any("stalled at residual 0.000666" in w for w in sim.warnings)


def test_stall_everywhere_raises_the_exact_temperature_error(monkeypatch):
    sim = Simulation(loads_scene(SCENE), progress=False)
    _stalling(monkeypatch, stall_everywhere=True)
    b = sim.bearings[0]
    with pytest.raises(ConvergenceError) as err:
        sim.solve_kinematics(b, 0, sim.scene.schedule.steps[0], TEMPS)
    assert "step 0" in str(err.value) and "6.66" in str(err.value)
