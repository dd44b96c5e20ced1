"""Thermal network of a bearing assembly and its implicit transient solvers.

- :class:`ThermalNetwork` (:mod:`.graph`): nodes with capacities [J/K] (0 allowed) or fixed
  temperatures [K], edges with conductance models (:mod:`.conductances`, registry
  ``conductance``), directed oil enthalpy streams, roles and groups (one per bearing).
- :func:`assemble` (:mod:`.assemble`): C, K, s of ``C dT/dt = -K T + s + q(t, T)``.
- :func:`integrate`, :class:`TransientStepper`, :func:`solve_steady` (:mod:`.steppers`,
  registry ``stepper``): TR-BDF2 (default), backward Euler; exponential Rosenbrock
  ``exprb43`` (:mod:`.exponential`: exact on the stiff linear network); energy audit
  (:mod:`.audit`).
- templates (:mod:`.templates`, registry ``network_template``): the four-node network of
  paper 002 and a finer seven-node one, from a bearing and a lubricant.

Quick use::

    from thermobearing.network import ThermalNetwork, integrate, solve_steady
    net = ThermalNetwork()
    net.add_boundary("ambient", 308.15)
    net.add_node("housing", 6.0e4, role="outer_ring")
    net.add_edge("housing", "ambient", 5.0)
    res = integrate(net, lambda t, T: [200.0], (0.0, 3600.0), 308.15,
                    breakpoints=[600.0])
    res.temperature("housing"), res.audit.totals()

``heat(t, T)``: T over ``network.state_nodes`` [K]; returns W per state node (array, or
dict by node name; :meth:`ThermalNetwork.distribute` maps heat-source roles to nodes).
Pass ``heat_jacobian(t, T)`` (dq/dT, (n,) diagonal or (n, n)) when you have it (or
``heat_with_jacobian(t, T) -> (q, dq/dT)`` when one call gives both: ``exprb43`` then
needs one call per step start instead of two), and ``heat_time_dependent=False`` when q
changes with t only at the breakpoints.

Step-wise use (a coupled loop that re-solves kinematics between thermal steps)::

    stepper = TransientStepper(net, method="tr_bdf2", rtol=1e-5, atol=1e-3)
    out = stepper.advance(t, T, dt, heat)      # adaptive sub-steps inside [t, t + dt]
    t, T = out.time, out.temperatures          # out.audit: energy flows of the interval

Templates: ``four_node_paper002(bearing, lubricant, housing_outer_diameter=...,
housing_length=..., oil_flow=...)`` and ``seven_node(...)``; ``TEMPLATES`` registry.
Oil-flow what-if: ``net.set_stream_flow("oil", oil_capacity_rate(lub, Q, T_in))``.
Scene TOML: ``net.to_dict()`` / ``ThermalNetwork.from_dict(d)``.
"""

from .assemble import Assembler, System, assemble
from .audit import EnergyAudit, SteadyResult, TransientResult
from .conductances import CONDUCTANCE, ConductanceModel
from .exponential import ExpRosenbrock43, phi_functions
from .graph import ROLES, Stream, ThermalNetwork
from .steppers import STEPPERS, StepOutcome, TransientStepper, integrate, solve_steady
from .templates import TEMPLATES, four_node_paper002, oil_capacity_rate, seven_node

__all__ = [
    "CONDUCTANCE", "ROLES", "STEPPERS", "Assembler", "ConductanceModel", "EnergyAudit",
    "ExpRosenbrock43", "StepOutcome", "SteadyResult", "Stream", "System", "TEMPLATES",
    "ThermalNetwork",
    "TransientResult", "TransientStepper", "assemble", "four_node_paper002", "integrate",
    "oil_capacity_rate", "phi_functions", "seven_node", "solve_steady",
]
