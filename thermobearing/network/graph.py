"""The thermal network: nodes with heat capacities or fixed temperatures, conductive edges,
and directed enthalpy streams (the oil flow).

A :class:`ThermalNetwork` wraps a :class:`networkx.MultiGraph` (parallel edges between two nodes
add). It holds *data only*; :mod:`.assemble` turns it into matrices and :mod:`.steppers`
integrates them.

Node kinds
----------
- **state node**: a lumped body with a heat capacity C [J/K] (``C = 0`` is allowed: an
  algebraic node whose temperature follows its neighbours instantly).
- **boundary node**: a fixed temperature [K] (ambient air, oil inlet). Boundary nodes take no
  heat source.

Every node may carry ``roles`` (the words the heat sources use for where their heat goes:
``"inner_ring"``, ``"outer_ring"``, ``"elements"``, ``"cage"``, ``"oil"``) and a ``group``
(one per bearing, so that the drive-end and non-drive-end bearings of one rig live in one
network). :meth:`ThermalNetwork.nodes_for_role` maps a role to its node(s) and
:meth:`ThermalNetwork.distribute` turns a ``{role: W}`` mapping into a heat vector.

Streams
-------
A stream is a directed enthalpy flow with capacity rate ``W = m_dot c_p`` [W/K] along a path
``[inlet_boundary, n1, n2, ...]``. Node ``n_k`` receives ``W (T_{k-1} - T_k)``: an upwind
(well-mixed, outlet-temperature) model of each oil volume. The heat carried away by the stream
is ``W (T_last - T_inlet)``. Changing the oil flow is :meth:`ThermalNetwork.set_stream_flow`,
not a new network.

Sign convention: heat flow on an edge is positive from the first node to the second.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import networkx as nx
import numpy as np

from ..errors import InputError, UnknownNameError, check_temperature
from .conductances import CONDUCTANCE, ConductanceModel, Fixed

#: Role words used by the heat sources (contract, heat sources section).
ROLES = ("inner_ring", "outer_ring", "elements", "cage", "oil")


@dataclass
class Stream:
    """A directed enthalpy stream.

    Attributes
    ----------
    name : stream name (``"oil"``).
    path : node names, first a boundary (the inlet), then state nodes in flow order.
    capacity_rate : m_dot * c_p [W/K] (>= 0).
    """

    name: str
    path: tuple[str, ...]
    capacity_rate: float


def _check_nonneg(field: str, value: float) -> float:
    v = float(value)
    if not math.isfinite(v) or v < 0.0:
        raise InputError(field, value, "a finite value >= 0")
    return v


class ThermalNetwork:
    """A lumped-capacity thermal network (see the module docstring).

    Parameters
    ----------
    name : a label for reports.

    Examples
    --------
    >>> net = ThermalNetwork("rc")
    >>> net.add_boundary("ambient", 300.0)
    >>> net.add_node("body", capacity=1000.0, role="outer_ring")
    >>> _ = net.add_edge("body", "ambient", 2.0)
    >>> net.state_nodes
    ('body',)
    """

    def __init__(self, name: str = "network") -> None:
        self.name = name
        self.graph = nx.MultiGraph()
        self.streams: dict[str, Stream] = {}
        self._revision = 0  # bumped on every change; the assembler caches on it
        self._validated = -1  # revision at the last successful validate()
        self._assembler_cache = None  # assemble.assembler_for: Assembler at a revision

    # ------------------------------------------------------------------ nodes
    def _touch(self) -> None:
        self._revision += 1

    def _check_new_name(self, name: str) -> None:
        if not isinstance(name, str) or not name:
            raise InputError("node name", name, "a non-empty string")
        if name in self.graph:
            raise InputError("node name", name, "a name not already used in the network")

    @staticmethod
    def _roles(role: str | Iterable[str] | None) -> tuple[str, ...]:
        if role is None:
            return ()
        roles = (role,) if isinstance(role, str) else tuple(role)
        for r in roles:
            if not isinstance(r, str) or not r:
                raise InputError("node role", role, "a non-empty string or a list of them")
        return roles

    def add_node(
        self,
        name: str,
        capacity: float,
        group: str | None = None,
        role: str | Iterable[str] | None = None,
    ) -> None:
        """Add a state node with heat capacity ``capacity`` [J/K] (0 = algebraic node)."""
        self._check_new_name(name)
        c = _check_nonneg(f"node {name!r}: capacity", capacity)
        self.graph.add_node(
            name, kind="state", capacity=c, group=group, roles=self._roles(role)
        )
        self._touch()

    def add_boundary(
        self,
        name: str,
        temperature: float,
        group: str | None = None,
        role: str | Iterable[str] | None = None,
    ) -> None:
        """Add a fixed-temperature node (ambient, oil inlet) at ``temperature`` [K]."""
        self._check_new_name(name)
        check_temperature(f"boundary {name!r}: temperature", temperature)
        self.graph.add_node(
            name, kind="boundary", temperature=float(temperature), group=group,
            roles=self._roles(role),
        )
        self._touch()

    def remove_node(self, name: str) -> None:
        """Remove a node, its edges and every stream passing through it."""
        self._require(name)
        self.graph.remove_node(name)
        for sname in [s for s, st in self.streams.items() if name in st.path]:
            del self.streams[sname]
        self._touch()

    def set_capacity(self, name: str, capacity: float) -> None:
        """Change the heat capacity [J/K] of a state node."""
        self._require(name, kind="state")
        self.graph.nodes[name]["capacity"] = _check_nonneg(f"node {name!r}: capacity", capacity)
        self._touch()

    def set_boundary_temperature(self, name: str, temperature: float) -> None:
        """Change the fixed temperature [K] of a boundary node."""
        self._require(name, kind="boundary")
        check_temperature(f"boundary {name!r}: temperature", temperature)
        self.graph.nodes[name]["temperature"] = float(temperature)
        self._touch()

    def _require(self, name: str, kind: str | None = None) -> None:
        if name not in self.graph:
            raise UnknownNameError("network node", name, list(self.graph.nodes))
        if kind is not None and self.graph.nodes[name]["kind"] != kind:
            raise InputError(
                f"node {name!r}", self.graph.nodes[name]["kind"], f"a {kind} node here"
            )

    # ------------------------------------------------------------------ edges
    def add_edge(
        self, a: str, b: str, conductance: float | ConductanceModel, name: str | None = None
    ) -> int:
        """Add a conductive edge between ``a`` and ``b``; returns its key.

        ``conductance`` is a number [W/K] or a model from :mod:`.conductances`.
        Parallel edges between the same two nodes add up.
        """
        for n in (a, b):
            if n not in self.graph:
                raise UnknownNameError(f"edge {a!r}-{b!r}: node", n, list(self.graph.nodes))
        if a == b:
            raise InputError(f"edge {a!r}-{b!r}", (a, b), "two different nodes")
        if isinstance(conductance, ConductanceModel):
            model = conductance
        else:
            g = float(conductance)
            if not math.isfinite(g) or g < 0.0:
                raise InputError(f"edge {a!r}-{b!r}: conductance", conductance,
                                 "a finite value >= 0 W/K (or a conductance model)")
            model = Fixed(g)
        key = self.graph.add_edge(a, b, model=model, name=name or f"{a}--{b}", a=a, b=b)
        # evaluate once so that a model with bad parameters fails here, naming the edge
        self.edge_conductance(a, b, key, 300.0, 300.0)
        self._touch()
        return key

    def remove_edge(self, a: str, b: str, key: int | None = None) -> None:
        """Remove the edge(s) between ``a`` and ``b`` (all parallel ones if ``key`` is None)."""
        if not self.graph.has_edge(a, b):
            raise InputError(f"edge {a!r}-{b!r}", (a, b), "an existing edge")
        if key is None:
            for k in list(self.graph[a][b]):
                self.graph.remove_edge(a, b, k)
        else:
            self.graph.remove_edge(a, b, key)
        self._touch()

    def set_edge_conductance(
        self, a: str, b: str, conductance: float | ConductanceModel, key: int | None = None
    ) -> None:
        """Replace the conductance of edge ``a``-``b`` (the only one, or ``key``)."""
        if not self.graph.has_edge(a, b):
            raise InputError(f"edge {a!r}-{b!r}", (a, b), "an existing edge")
        keys = list(self.graph[a][b]) if key is None else [key]
        if len(keys) != 1:
            raise InputError(f"edge {a!r}-{b!r}: key", key, f"one of {keys} (parallel edges)")
        data = self.graph[a][b][keys[0]]
        if isinstance(conductance, ConductanceModel):
            new_model = conductance
        else:
            new_model = Fixed(_check_nonneg(f"edge {a!r}-{b!r}: conductance", conductance))
        old_model, data["model"] = data["model"], new_model
        try:
            self.edge_conductance(a, b, keys[0], 300.0, 300.0)
        except Exception:
            data["model"] = old_model
            raise
        self._touch()

    def edge_conductance(self, a: str, b: str, key: int, Ta: float, Tb: float) -> float:
        """Conductance [W/K] of one edge at node temperatures ``Ta``, ``Tb`` [K]."""
        data = self.graph[a][b][key]
        model: ConductanceModel = data["model"]
        # the model sees the temperatures in its own (a, b) order as stored
        g = float(model.conductance(Ta, Tb))
        if not math.isfinite(g) or g < 0.0:
            raise InputError(f"edge {a!r}-{b!r}: conductance", g,
                             "a finite value >= 0 W/K from the conductance model")
        return g

    def edges(self) -> list[tuple[str, str, int, ConductanceModel]]:
        """All edges as (a, b, key, model), in insertion order."""
        return [(d["a"], d["b"], k, d["model"])
                for _, _, k, d in self.graph.edges(keys=True, data=True)]

    @property
    def temperature_dependent(self) -> bool:
        """True if any edge conductance depends on temperature."""
        return any(m.temperature_dependent for *_, m in self.edges())

    # ---------------------------------------------------------------- streams
    def add_stream(self, path: Sequence[str], mass_flow_heat_capacity: float,
                   name: str = "oil") -> None:
        """Add a directed enthalpy stream along ``path`` with m_dot*c_p [W/K].

        ``path[0]`` must be a boundary node (the inlet, e.g. oil at its supply temperature);
        the others are state nodes in flow order, each visited once.
        """
        if name in self.streams:
            raise InputError("stream name", name, "a name not already used")
        path = tuple(path)
        if len(path) < 2:
            raise InputError(f"stream {name!r}: path", path, "an inlet boundary and >= 1 node")
        for n in path:
            if n not in self.graph:
                raise UnknownNameError(f"stream {name!r}: node", n, list(self.graph.nodes))
        if self.graph.nodes[path[0]]["kind"] != "boundary":
            raise InputError(f"stream {name!r}: path[0]", path[0], "a boundary node (the inlet)")
        for n in path[1:]:
            if self.graph.nodes[n]["kind"] != "state":
                raise InputError(f"stream {name!r}: node", n, "a state node after the inlet")
        if len(set(path)) != len(path):
            raise InputError(f"stream {name!r}: path", path, "each node visited once")
        w = _check_nonneg(f"stream {name!r}: mass_flow_heat_capacity", mass_flow_heat_capacity)
        self.streams[name] = Stream(name, path, w)
        self._touch()

    def set_stream_flow(self, name: str, mass_flow_heat_capacity: float) -> None:
        """Change a stream's m_dot*c_p [W/K] (an oil-flow what-if is this call)."""
        if name not in self.streams:
            raise UnknownNameError("stream", name, self.streams)
        self.streams[name].capacity_rate = _check_nonneg(
            f"stream {name!r}: mass_flow_heat_capacity", mass_flow_heat_capacity
        )
        self._touch()

    def remove_stream(self, name: str) -> None:
        """Remove a stream."""
        if name not in self.streams:
            raise UnknownNameError("stream", name, self.streams)
        del self.streams[name]
        self._touch()

    # ------------------------------------------------------------- queries
    @property
    def node_names(self) -> tuple[str, ...]:
        """All node names in insertion order."""
        return tuple(self.graph.nodes)

    @property
    def state_nodes(self) -> tuple[str, ...]:
        """State (non-boundary) node names in insertion order: the order of heat vectors."""
        return tuple(n for n, d in self.graph.nodes(data=True) if d["kind"] == "state")

    @property
    def boundary_nodes(self) -> tuple[str, ...]:
        """Boundary node names in insertion order."""
        return tuple(n for n, d in self.graph.nodes(data=True) if d["kind"] == "boundary")

    def capacity(self, name: str) -> float:
        """Heat capacity [J/K] of a state node."""
        self._require(name, kind="state")
        return self.graph.nodes[name]["capacity"]

    def boundary_temperature(self, name: str) -> float:
        """Fixed temperature [K] of a boundary node."""
        self._require(name, kind="boundary")
        return self.graph.nodes[name]["temperature"]

    def groups(self) -> list[str]:
        """Distinct node groups (bearings), in first-seen order."""
        seen: list[str] = []
        for _, g in self.graph.nodes(data="group"):
            if g is not None and g not in seen:
                seen.append(g)
        return seen

    def nodes_for_role(self, role: str, group: str | None = None) -> list[str]:
        """State nodes that carry ``role`` (in ``group`` if given)."""
        out = [
            n for n, d in self.graph.nodes(data=True)
            if d["kind"] == "state" and role in d["roles"]
            and (group is None or d["group"] == group)
        ]
        return out

    def roles(self, group: str | None = None) -> dict[str, list[str]]:
        """Role -> state node names (in ``group`` if given)."""
        out: dict[str, list[str]] = {}
        for n, d in self.graph.nodes(data=True):
            if d["kind"] != "state" or (group is not None and d["group"] != group):
                continue
            for r in d["roles"]:
                out.setdefault(r, []).append(n)
        return out

    def distribute(self, power_by_role: Mapping[str, float], group: str | None = None,
                   out: np.ndarray | None = None) -> np.ndarray:
        """Heat vector [W] over :attr:`state_nodes` from ``{role: W}``.

        A role carried by several nodes of the group is split equally between them.
        A role with no node in the group is an :class:`InputError` (heat must not vanish).
        Adds into ``out`` if given.
        """
        index = {n: i for i, n in enumerate(self.state_nodes)}
        q = np.zeros(len(index)) if out is None else out
        for role, watts in power_by_role.items():
            nodes = self.nodes_for_role(role, group)
            if not nodes:
                raise InputError(f"heat role {role!r} (group {group!r})", watts,
                                 f"a role carried by a node; roles here: "
                                 f"{sorted(self.roles(group))}")
            share = float(watts) / len(nodes)
            for n in nodes:
                q[index[n]] += share
        return q

    def heat_vector(self, heat: Mapping[str, float] | np.ndarray) -> np.ndarray:
        """A heat vector over :attr:`state_nodes` from a ``{node: W}`` dict or an array.

        Arrays may be over the state nodes or over all nodes (then boundary entries must be
        zero). A heat source on a boundary node is an :class:`InputError` naming the node.
        """
        states = self.state_nodes
        if isinstance(heat, Mapping):
            index = {n: i for i, n in enumerate(states)}
            q = np.zeros(len(states))
            for n, w in heat.items():
                if n not in index:
                    if n in self.graph:
                        raise InputError(f"heat on node {n!r}", w,
                                         "no heat source on a fixed-temperature node")
                    raise UnknownNameError("heat node", n, states)
                q[index[n]] += float(w)
            return q
        q = np.asarray(heat, dtype=float)
        if q.shape == (len(states),):
            return q
        if q.shape == (self.graph.number_of_nodes(),):
            for i, n in enumerate(self.node_names):
                if self.graph.nodes[n]["kind"] == "boundary" and q[i] != 0.0:
                    raise InputError(f"heat on node {n!r}", q[i],
                                     "no heat source on a fixed-temperature node")
            mask = [self.graph.nodes[n]["kind"] == "state" for n in self.node_names]
            return q[np.array(mask)]
        raise InputError("heat vector", q.shape,
                         f"length {len(states)} (state nodes) or "
                         f"{self.graph.number_of_nodes()} (all nodes)")

    # ------------------------------------------------------------ validation
    def validate(self) -> None:
        """Check the network can be solved; raise :class:`InputError` naming the culprit.

        Every state node needs a path (through edges with conductance > 0 or streams) to a
        boundary node, else its temperature is undetermined at steady state. The result is
        remembered until the next change of the network (its revision).
        """
        if self._validated == self._revision:
            return
        if not self.boundary_nodes:
            raise InputError("network", self.name, "at least one fixed-temperature node")
        g = nx.Graph()
        g.add_nodes_from(self.graph.nodes)
        for a, b, _k, model in self.edges():
            if not model.temperature_dependent and model.conductance(300.0, 300.0) == 0.0:
                continue
            g.add_edge(a, b)
        for st in self.streams.values():
            if st.capacity_rate > 0:
                nx.add_path(g, st.path)
        reach: set[str] = set()
        for b in self.boundary_nodes:
            reach |= nx.node_connected_component(g, b)
        lost = [n for n in self.state_nodes if n not in reach]
        if lost:
            raise InputError(f"node {lost[0]!r}", lost,
                             "a path of conductances or streams to a fixed-temperature node")
        self._validated = self._revision

    # --------------------------------------------------------- serialization
    def to_dict(self) -> dict[str, Any]:
        """A plain dict (TOML-writable: only str, float, int, lists, tables)."""
        nodes = []
        for n, d in self.graph.nodes(data=True):
            item: dict[str, Any] = {"name": n, "kind": d["kind"]}
            if d["kind"] == "state":
                item["capacity"] = d["capacity"]
            else:
                item["temperature"] = d["temperature"]
            if d["group"] is not None:
                item["group"] = d["group"]
            if d["roles"]:
                item["roles"] = list(d["roles"])
            nodes.append(item)
        edges = []
        for _, _, _k, data in self.graph.edges(keys=True, data=True):
            edges.append({"a": data["a"], "b": data["b"], "name": data["name"],
                          "conductance": data["model"].to_dict()})
        streams = [{"name": s.name, "path": list(s.path),
                    "mass_flow_heat_capacity": s.capacity_rate} for s in self.streams.values()]
        return {"name": self.name, "nodes": nodes, "edges": edges, "streams": streams}

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> ThermalNetwork:
        """Rebuild a network written by :meth:`to_dict`; unknown keys are errors."""
        _keys("network", d, {"name", "nodes", "edges", "streams"})
        net = cls(d.get("name", "network"))
        for item in d.get("nodes", []):
            _keys("network.nodes", item, {"name", "kind", "capacity", "temperature",
                                          "group", "roles"})
            kind = item.get("kind", "state")
            if kind == "state":
                net.add_node(item["name"], item["capacity"], item.get("group"),
                             item.get("roles"))
            elif kind == "boundary":
                net.add_boundary(item["name"], item["temperature"], item.get("group"),
                                 item.get("roles"))
            else:
                raise InputError("network.nodes.kind", kind, "'state' or 'boundary'")
        for item in d.get("edges", []):
            _keys("network.edges", item, {"a", "b", "name", "conductance"})
            g = item["conductance"]
            model = CONDUCTANCE_from_dict(g) if isinstance(g, Mapping) else float(g)
            net.add_edge(item["a"], item["b"], model, name=item.get("name"))
        for item in d.get("streams", []):
            _keys("network.streams", item, {"name", "path", "mass_flow_heat_capacity"})
            net.add_stream(item["path"], item["mass_flow_heat_capacity"],
                           name=item.get("name", "oil"))
        return net

    def copy(self) -> ThermalNetwork:
        """An independent copy (through :meth:`to_dict`)."""
        return ThermalNetwork.from_dict(self.to_dict())

    def __repr__(self) -> str:
        return (f"ThermalNetwork({self.name!r}, {len(self.state_nodes)} state nodes, "
                f"{len(self.boundary_nodes)} boundaries, {self.graph.number_of_edges()} edges, "
                f"{len(self.streams)} streams)")


def CONDUCTANCE_from_dict(d: Mapping[str, Any]) -> ConductanceModel:  # noqa: N802
    """Build a conductance model from ``{"model": name, **parameters}``."""
    if "model" not in d:
        raise InputError("conductance", dict(d), "a table with a 'model' key")
    params = {k: v for k, v in d.items() if k != "model"}
    cls = CONDUCTANCE.get(d["model"])
    try:
        return cls(**params)
    except TypeError as exc:
        raise InputError(f"conductance {d['model']!r}", params, str(exc)) from None


def _keys(field: str, d: Mapping[str, Any], allowed: set[str]) -> None:
    extra = set(d) - allowed
    if extra:
        raise InputError(field, sorted(extra), f"only the keys {sorted(allowed)}")
