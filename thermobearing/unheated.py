"""The temperature of a run without a thermal network (outputs kinematics, losses, film).

Without ``temperatures`` or ``energy`` in ``[outputs] want`` (and not ``mode = "steady"``) no
network computes the part temperatures: every operating point is taken with the rings, the
elements, the cage and the oil at one temperature, chosen here once for the run, its report
and its sweep summaries:

1. ``environment.initial_temperature`` when the scene gives it (the user states the
   temperature of the operating point);
2. otherwise, for a supply that feeds a stream of oil into the bearing (jet, circulation,
   oil-air, or an oil bath with a flow) whose ``supply.inlet_temperature`` the scene gives:
   that inlet temperature. A fed bearing's oil, and the parts it washes, start from the
   stream's temperature; the heat the bearing adds to it needs the network. This is the
   convention of this tool (the lowest temperature the fed contacts can see, so the
   viscous losses are an upper bound of the steady ones), not a published rule;
3. otherwise the initial temperature's default, the ambient one.

A jet at 80 degC on a rig at 20 degC thus gives the losses of 80 degC oil, not of 20 degC oil
(QJ1044, 1800 r/min, 5 L/min: the total loss differs by a factor of about 2), and a sweep of
the inlet temperature of a losses-only scene changes its losses.
"""

from __future__ import annotations

from typing import Any

#: supply methods whose oil enters the bearing as a stream at the inlet temperature
_FED = ("jet", "circulation", "oil_air")


def fed_stream(supply: Any) -> bool:
    """True when the supply feeds a stream of oil at its inlet temperature (a jet,
    circulation or oil-air supply, or an oil bath with a flow through it)."""
    return supply.method in _FED or (supply.method == "oil_bath" and supply.flow > 0.0)


def unheated_temperature(scene: Any) -> tuple[float, str]:
    """The temperature [K] of every part and of the oil in a run without a thermal network,
    and the scene field it comes from (``"environment.initial_temperature"`` or
    ``"supply.inlet_temperature"``); rules in the module docstring."""
    env, sup = scene.environment, scene.supply
    if getattr(env, "initial_given", True):
        return float(env.initial_temperature), "environment.initial_temperature"
    if fed_stream(sup) and getattr(sup, "inlet_given", False):
        return float(sup.inlet_temperature), "supply.inlet_temperature"
    return float(env.initial_temperature), "environment.initial_temperature"
