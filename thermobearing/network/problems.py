"""Benchmark and verification problems of the network solvers (BM-1, BM-2, BM-3, tests).

- :func:`bearing_network` -- networks of 4, 20 or 100 state nodes: the four-node assembly of
  paper 002 (balls, housing/outer ring, shaft/inner ring, oil+cage) with an oil stream and
  ambient, and refinements in which each body is split into a chain of sub-nodes (stiff: a
  0.1-1 J/K oil-film node beside a 6e4 J/K housing).
- :class:`ViscousHeat` -- heat sources that fall with temperature as a viscous loss does:
  q_i(t, T) = P_i(t) exp(-beta (T_i - T_ref)) (the viscosity of a mineral oil falls by about
  3 %/K near 40-80 degC: beta = 0.03 1/K), with P_i(t) piecewise constant over a load
  protocol, and its analytic (diagonal) Jacobian.
- :func:`load_protocol` -- the 66-min protocol with 22 load steps of BM-1 (3 min each), or
  any number of steps (BM-2: 120).

These are solver test problems with realistic magnitudes, not a validated bearing model.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .graph import ThermalNetwork

T_AMBIENT = 308.15  # 35 degC, paper 002 sec. 4.3
T_OIL_IN = 308.15


def bearing_network(n_nodes: int = 4, oil_capacity_rate: float = 946.0,
                    film_capacity: float = 0.1) -> ThermalNetwork:
    """A stiff bearing-like network with ``n_nodes`` state nodes (4, or a multiple of 4 >= 8).

    Four bodies (capacities [J/K]: balls 1.0e3, housing 6.0e4, shaft 2.0e4, oil+cage 5.0e2)
    connected as in paper 002 eqs. 22-25; with ``n_nodes > 4`` each body becomes a chain of
    ``n_nodes/4`` sub-nodes, and the first oil sub-node is a thin oil film of capacity
    ``film_capacity``. The oil stream (m_dot c_p = 946 W/K: 33 L/min of oil at 860 kg/m^3,
    2000 J/(kg K)) enters the first oil node from the inlet boundary.
    """
    if n_nodes < 4 or n_nodes % 4:
        raise ValueError("n_nodes must be 4 or a multiple of 4")
    m = n_nodes // 4
    net = ThermalNetwork(f"bearing_{n_nodes}")
    net.add_boundary("ambient", T_AMBIENT)
    net.add_boundary("oil_inlet", T_OIL_IN)
    bodies = {
        "balls": (1.0e3, "elements"),
        "housing": (6.0e4, "outer_ring"),
        "shaft": (2.0e4, "inner_ring"),
        "oil": (5.0e2, ("oil", "cage")),
    }
    chains: dict[str, list[str]] = {}
    for body, (cap, role) in bodies.items():
        names = [body] if m == 1 else [f"{body}_{k}" for k in range(m)]
        caps = [cap] if m == 1 else [cap / m] * m
        if body == "oil" and m > 1:
            caps[0] = film_capacity
        for name, c in zip(names, caps, strict=True):
            net.add_node(name, c, group="bearing", role=role)
        # internal conduction along the chain (a body split into slices)
        g_int = {"balls": 400.0, "housing": 150.0, "shaft": 300.0, "oil": 200.0}[body] * m
        for a, b in zip(names[:-1], names[1:], strict=True):
            net.add_edge(a, b, g_int)
        chains[body] = names
    first = {k: v[0] for k, v in chains.items()}
    last = {k: v[-1] for k, v in chains.items()}
    # paper 002 eqs. 22-25 paths (magnitudes: Hertz contacts ~1-5 W/K, oil convection
    # 50-1500 W/(m^2 K) over ~0.1-0.5 m^2, housing to air ~10 W/(m^2 K) over ~1.5 m^2)
    net.add_edge(first["balls"], first["housing"], 3.0)
    net.add_edge(first["balls"], first["shaft"], 2.5)
    net.add_edge(first["balls"], first["oil"], 60.0)
    net.add_edge(first["housing"], first["oil"], 80.0)
    net.add_edge(first["shaft"], first["oil"], 50.0)
    net.add_edge(last["housing"], "ambient", 15.0)
    net.add_edge(last["shaft"], "ambient", 4.0)
    net.add_edge(last["oil"], "ambient", 2.0)
    net.add_stream(["oil_inlet", *chains["oil"]], oil_capacity_rate, name="oil")
    return net


def load_protocol(n_steps: int = 22, step_duration: float = 180.0,
                  peak_power: float = 2500.0) -> tuple[np.ndarray, np.ndarray]:
    """Step times [s] (n_steps + 1 edges) and the total power [W] of each step.

    Load rises over the first two thirds of the protocol and falls back, with a drop to
    zero load (0 W) in the middle and at the last step (hard case: load dropping to zero).
    """
    edges = np.arange(n_steps + 1) * step_duration
    k = np.arange(n_steps)
    shape = np.sin(np.pi * (k + 0.5) / n_steps) ** 0.7
    power = peak_power * (0.25 + 0.75 * shape)
    power[n_steps // 2] = 0.0
    power[-1] = 0.0
    return edges, power


@dataclass
class ViscousHeat:
    """q_i(t, T) = share_i P(t) exp(-beta (T_i - T_ref)) [W]; P(t) piecewise constant.

    Attributes
    ----------
    edges : step times [s]; powers : P of each step [W]; shares : fraction per state node;
    beta : viscosity-temperature coefficient [1/K]; T_ref : reference temperature [K].
    """

    edges: np.ndarray
    powers: np.ndarray
    shares: np.ndarray
    beta: float = 0.03
    T_ref: float = T_OIL_IN

    def __post_init__(self) -> None:
        self._k = 0  # cached step index: the lookup is O(1) while t stays in one step
        self._edges = [float(x) for x in self.edges]

    def power(self, t: float) -> float:
        k, e = self._k, self._edges
        if not (e[k] <= t < e[k + 1]):
            k = int(np.searchsorted(self.edges, t, side="right")) - 1
            k = min(max(k, 0), len(self.powers) - 1)
            self._k = k
        return float(self.powers[k])

    def __call__(self, t: float, T: np.ndarray) -> np.ndarray:
        return self.power(t) * self.shares * np.exp(-self.beta * (T - self.T_ref))

    def jacobian(self, t: float, T: np.ndarray) -> np.ndarray:
        """Diagonal dq_i/dT_i [W/K]."""
        return -self.beta * self(t, T)

    def with_jacobian(self, t: float, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(q [W], diagonal dq/dT [W/K]) from one evaluation: dq_i/dT_i = -beta q_i."""
        q = self(t, T)
        return q, -self.beta * q

    def at_segment(self, k: int):
        """(heat, jacobian) with P frozen at step k (for solvers restarted per step)."""
        p = float(self.powers[k])
        shares, beta, tref = self.shares, self.beta, self.T_ref

        def heat(t, T):
            return p * shares * np.exp(-beta * (T - tref))

        def jac(t, T):
            return -beta * p * shares * np.exp(-beta * (T - tref))

        return heat, jac


def viscous_heat_for(network: ThermalNetwork, edges: np.ndarray, powers: np.ndarray,
                     beta: float = 0.03) -> ViscousHeat:
    """Split the protocol power over the roles: 40 % elements, 20 % each ring, 20 % oil+cage.

    Within a role the power is split equally over its nodes (first node of each chain gets
    all of it, the contact/oil side).
    """
    names = network.state_nodes
    shares = np.zeros(len(names))
    split = {"elements": 0.4, "outer_ring": 0.2, "inner_ring": 0.2, "oil": 0.2}
    for role, frac in split.items():
        nodes = network.nodes_for_role(role)
        shares[names.index(nodes[0])] += frac
    return ViscousHeat(np.asarray(edges, float), np.asarray(powers, float), shares, beta)
