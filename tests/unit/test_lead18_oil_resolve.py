"""The skidding kinematics are re-solved when the oil node's viscosity moves beyond
``solver.kinematics_tolerance`` as well as the contacts': the solvers balance the oil drag
at the oil temperature (the roller solver's churning and guide moments are what the sources
book). Regression scene qj1044_short: max temperature difference from a run at tolerance
0.001 was 0.102 K with the contact viscosity alone (6 solves), 0.0075 K now (7 solves)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np

from thermobearing.scene import Scene
from thermobearing.simulation import Simulation

SCENE = Path(__file__).resolve().parents[1] / "regression" / "scenes" / "qj1044_short.toml"


def _run(tolerance: float | None = None):
    data = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    if tolerance is not None:
        data["solver"]["kinematics_tolerance"] = tolerance
    res = Simulation(Scene.from_dict(data), progress=False).run()
    return res.tables["temperatures"], res.stats["kinematics_solves"]


def test_oil_viscosity_re_solves_and_tracks_a_tight_run():
    temps, solves = _run()
    tight, tight_solves = _run(0.001)
    assert tight_solves >= solves
    merged = temps.merge(tight, on="time [s]", suffixes=("", "_tight"))
    cols = [c for c in temps.columns if c.endswith("[degC]")]
    worst = max(float(np.max(np.abs(merged[c] - merged[c + "_tight"]))) for c in cols)
    assert worst < 0.03  # K (0.102 K when only the contact viscosity was watched)


def test_oil_viscosity_is_recorded_for_skidding_bearings_only():
    data = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    sim = Simulation(Scene.from_dict(data), progress=False)
    b = sim.bearings[0]
    temps = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 313.15)
    step = sim.scene.schedule.steps[1]
    first = sim.solve_kinematics(b, 1, step, temps)
    assert np.isfinite(b.last_oil_viscosity)
    # the contacts unchanged, the oil 10 K warmer: re-solved (a new state)
    warmer = {**temps, "oil": 323.15}
    second = sim.solve_kinematics(b, 1, step, warmer)
    assert second is not first
    # within the tolerance: the same state
    assert sim.solve_kinematics(b, 1, step, {**warmer, "oil": 323.2}) is second
