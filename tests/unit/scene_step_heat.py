"""A scene's first step at fixed temperatures, for tests that check the kinematics a scene
solves against the heat its sources book: the kinematic result and the booked power by source.
"""

from __future__ import annotations

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation


def first_step_heat(text: str, temperatures: dict[str, float]):
    """(kinematics, step, power [W] by source) of the first bearing at the first step of the
    scene ``text`` (TOML) with the node ``temperatures`` [K] held."""
    sim = Simulation(loads_scene(text), progress=False)
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    kin = sim.solve_kinematics(b, 0, step, temperatures)
    ev = sim.evaluate_heat(b, step, kin, temperatures, with_rows=True)
    by_source: dict[str, float] = {}
    for row in ev.rows:
        by_source[row["source"]] = by_source.get(row["source"], 0.0) + row["power [W]"]
    return kin, step, by_source
