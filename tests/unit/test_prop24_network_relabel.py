"""Property tests, round 6: a thermal network is a graph, not a listing (session 24).

The temperatures of :mod:`thermobearing.network` depend on the nodes, edges, streams and
heat only, not on how the network was written down:

- the order the nodes are added in (the order of the state vector), the order of the
  edges, the direction each edge is written in (a to b or b to a), and a constant
  conductance written as two parallel edges G1 + G2 = G (parallel edges add, graph.py)
  change no node's temperature: the steady state (:func:`solve_steady`) and the transients
  of TR-BDF2, backward Euler and exprb43 at fixed steps, compared node by node by name,
  and the energy books of the runs;
- the dense and the sparse assembly (``assemble.DENSE_LIMIT``: dense K up to 120 state
  nodes) give the same temperatures.

Random networks: a spanning tree of constant conductances plus extra edges, one edge to the
ambient, sometimes free convection to the ambient (temperature-dependent), an oil stream
from an inlet through some nodes, some zero-capacity nodes. Tolerances: 1e-9 of the rise
(the permuted system is the same linear algebra in another order, round-off apart; the
temperature-dependent edges are solved by Newton to far below it); 200 draws of each
property passed (scratch).
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.network import ThermalNetwork, integrate, solve_steady
from thermobearing.network.conductances import NaturalConvectionCylinder

T_AMB, T_IN = 300.0, 310.0


@st.composite
def specs(draw):
    """A network as data: capacities, edges (a, b, G or a convection model spec), the
    stream path and flow, heat per node."""
    n = draw(st.integers(2, 7))
    caps = [draw(st.floats(10.0, 1000.0)) if i == 0 or not draw(st.booleans()) else 0.0
            for i in range(n)]
    edges = [(i, draw(st.integers(0, i - 1)), draw(st.floats(0.5, 20.0))) for i in range(1, n)]
    for _ in range(draw(st.integers(0, n))):
        a, b = draw(st.integers(0, n - 1)), draw(st.integers(0, n - 1))
        if a != b:
            edges.append((a, b, draw(st.floats(0.5, 20.0))))
    edges.append((draw(st.integers(0, n - 1)), "amb", draw(st.floats(0.5, 20.0))))
    if draw(st.booleans()):   # free convection (temperature dependent) to the ambient
        edges.append((draw(st.integers(0, n - 1)), "amb",
                      ("convection", draw(st.floats(0.05, 0.3)), draw(st.floats(0.05, 1.0)))))
    order = draw(st.permutations(list(range(n))))
    path = order[:draw(st.integers(1, n))]
    flow = draw(st.floats(0.0, 20.0))
    heat = draw(st.lists(st.floats(0.0, 300.0), min_size=n, max_size=n))
    return caps, edges, path, flow, heat


def _build(spec, node_order, edge_order, flip, split) -> ThermalNetwork:
    caps, edges, path, flow, _ = spec
    net = ThermalNetwork("relabel")
    net.add_boundary("amb", T_AMB)
    net.add_boundary("oil_in", T_IN)
    for i in node_order:
        net.add_node(f"n{i}", caps[i])
    for k in edge_order:
        a, b, g = edges[k]
        a, b = f"n{a}", (b if b == "amb" else f"n{b}")
        if flip[k] and b != "amb":
            a, b = b, a
        if isinstance(g, tuple):
            net.add_edge(a, b, NaturalConvectionCylinder(g[1], g[2]))
        elif split[k] > 0.0:
            net.add_edge(a, b, split[k] * g)
            net.add_edge(a, b, (1.0 - split[k]) * g)
        else:
            net.add_edge(a, b, g)
    net.add_stream(["oil_in", *[f"n{i}" for i in path]], flow)
    return net


def _by_name(net: ThermalNetwork, vector) -> dict[str, float]:
    return dict(zip(net.state_nodes, np.asarray(vector, float), strict=True))


def _runs(net: ThermalNetwork, heat: dict[str, float]) -> dict[str, object]:
    out = {"steady": solve_steady(net, heat).temperatures_vector}
    for method in ("tr_bdf2", "backward_euler", "exprb43"):
        res = integrate(net, heat, (0.0, 2000.0), T_AMB, method=method, dt=50.0, rtol=1e-10,
                        atol=1e-10)
        out[method] = (res.temperatures[-1], res.audit.totals())
    return out


def _same(net_a, runs_a, net_b, runs_b) -> None:
    span = max(1.0, float(np.max(np.abs(runs_a["steady"] - T_AMB))))
    for key in runs_a:
        va, vb = (runs_a[key], runs_b[key]) if key == "steady" else (runs_a[key][0],
                                                                     runs_b[key][0])
        a, b = _by_name(net_a, va), _by_name(net_b, vb)
        for name in a:
            assert abs(a[name] - b[name]) <= 1e-9 * span, (key, name, a[name], b[name])
        if key != "steady":
            ta, tb = runs_a[key][1], runs_b[key][1]
            scale = max(1.0, abs(ta["generated"]), abs(ta["stored"]))
            for flow in ("generated", "stored", "to_boundaries", "to_streams"):
                assert abs(ta[flow] - tb[flow]) <= 1e-9 * scale, (key, flow)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(specs(), st.data())
def test_the_order_direction_and_splitting_of_the_listing_do_not_matter(spec, data):
    caps, edges, _, _, heat = spec
    n, m = len(caps), len(edges)
    plain = _build(spec, range(n), range(m), [False] * m, [0.0] * m)
    node_order = data.draw(st.permutations(list(range(n))), label="node order")
    edge_order = data.draw(st.permutations(list(range(m))), label="edge order")
    flip = data.draw(st.lists(st.booleans(), min_size=m, max_size=m), label="flip")
    split = data.draw(st.lists(st.one_of(st.just(0.0), st.floats(0.1, 0.9)), min_size=m,
                               max_size=m), label="split")
    other = _build(spec, node_order, edge_order, flip, split)
    assert other.state_nodes == tuple(f"n{i}" for i in node_order)   # the vector's order
    q = {f"n{i}": heat[i] for i in range(n)}
    _same(plain, _runs(plain, q), other, _runs(other, q))


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(specs())
def test_dense_and_sparse_assembly_agree(spec):
    caps, edges, _, _, heat = spec
    n, m = len(caps), len(edges)
    q = {f"n{i}": heat[i] for i in range(n)}
    dense_net = _build(spec, range(n), range(m), [False] * m, [0.0] * m)
    dense = _runs(dense_net, q)
    asm_mod = importlib.import_module("thermobearing.network.assemble")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(asm_mod, "DENSE_LIMIT", 0)
        sparse_net = _build(spec, range(n), range(m), [False] * m, [0.0] * m)
        assert not asm_mod.assemble(sparse_net).dense
        sparse = _runs(sparse_net, q)
    _same(dense_net, dense, sparse_net, sparse)
