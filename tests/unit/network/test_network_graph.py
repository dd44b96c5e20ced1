"""ThermalNetwork data object: editing, roles/groups, serialization, bad input, assembly."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.network import ThermalNetwork, assemble, solve_steady
from thermobearing.network.conductances import CylindricalShell, PlaneWall


def two_bearing_rig() -> ThermalNetwork:
    """Drive-end and non-drive-end bearings on one shaft: one network, two groups."""
    net = ThermalNetwork("rig")
    net.add_boundary("ambient", 300.0)
    net.add_boundary("oil_inlet", 310.0)
    for g in ("de", "nde"):
        net.add_node(f"{g}_balls", 1000.0, group=g, role="elements")
        net.add_node(f"{g}_housing", 5e4, group=g, role="outer_ring")
        net.add_node(f"{g}_oil", 300.0, group=g, role=("oil", "cage"))
        net.add_edge(f"{g}_balls", f"{g}_housing", 3.0)
        net.add_edge(f"{g}_balls", f"{g}_oil", 40.0)
        net.add_edge(f"{g}_housing", "ambient", 12.0)
        net.add_stream(["oil_inlet", f"{g}_oil"], 500.0, name=f"oil_{g}")
    net.add_node("shaft", 2e4, role="inner_ring")
    net.add_edge("shaft", "de_balls", 2.0)
    net.add_edge("shaft", "nde_balls", 2.0)
    return net


def test_roles_and_groups_map_heat_to_nodes():
    net = two_bearing_rig()
    assert net.groups() == ["de", "nde"]
    assert net.nodes_for_role("cage", group="de") == ["de_oil"]
    assert net.nodes_for_role("elements") == ["de_balls", "nde_balls"]
    q = net.distribute({"elements": 100.0, "cage": 20.0, "oil": 5.0}, group="nde")
    names = net.state_nodes
    assert q[names.index("nde_balls")] == 100.0
    assert q[names.index("nde_oil")] == 25.0
    assert q.sum() == 125.0
    with pytest.raises(InputError, match="inner_ring"):
        net.distribute({"inner_ring": 1.0}, group="de")  # the shaft has no group


def test_parallel_edges_add():
    net = ThermalNetwork()
    net.add_boundary("amb", 300.0)
    net.add_node("a", 10.0)
    net.add_edge("a", "amb", 2.0)
    net.add_edge("a", "amb", 3.0)
    sys_ = assemble(net)
    assert sys_.K[0, 0] == pytest.approx(5.0)
    assert sys_.s[0] == pytest.approx(5.0 * 300.0)


def test_laplacian_matches_networkx():
    """K restricted to state nodes = networkx Laplacian (constant conductances, no streams)."""
    rng = np.random.default_rng(3)
    net = ThermalNetwork()
    net.add_boundary("amb", 300.0)
    g = nx.Graph()
    n = 12
    for i in range(n):
        net.add_node(f"n{i}", 10.0)
    for i in range(n):
        for j in range(i + 1, n):
            if rng.random() < 0.3 or j == i + 1:
                w = float(rng.uniform(0.5, 5.0))
                net.add_edge(f"n{i}", f"n{j}", w)
                g.add_edge(f"n{i}", f"n{j}", weight=w)
    net.add_edge("n0", "amb", 7.0)
    L = nx.laplacian_matrix(g, nodelist=[f"n{i}" for i in range(n)], weight="weight").toarray()
    K = assemble(net).K
    L[0, 0] += 7.0
    np.testing.assert_allclose(K, L, rtol=1e-14, atol=1e-14)


def test_stream_terms_are_upwind_and_energy_identity():
    net = ThermalNetwork()
    net.add_boundary("inlet", 310.0)
    net.add_boundary("amb", 300.0)
    for n in ("o1", "o2", "o3"):
        net.add_node(n, 5.0)
    net.add_edge("o2", "amb", 1.0)
    net.add_stream(["inlet", "o1", "o2", "o3"], 20.0)
    sys_ = assemble(net)
    np.testing.assert_allclose(sys_.K, [[20, 0, 0], [-20, 21, 0], [0, -20, 20]])
    np.testing.assert_allclose(sys_.s, [20 * 310.0, 300.0, 0.0])
    T = np.array([320.0, 330.0, 345.0])
    # sum of the network part of f = -(heat to boundaries + heat carried by the stream)
    assert sys_.flux(T).sum() == pytest.approx(
        -(sys_.to_boundaries(T) + sys_.to_streams(T)), rel=1e-14)
    assert sys_.to_streams(T) == pytest.approx(20.0 * (345.0 - 310.0))


def test_oil_flow_what_if_is_a_parameter_change():
    net = two_bearing_rig()
    heat = net.distribute({"elements": 200.0, "oil": 100.0}, group="de")
    hot = solve_steady(net, heat).temperatures["de_oil"]
    net.set_stream_flow("oil_de", 100.0)  # less oil -> hotter oil
    less = solve_steady(net, heat).temperatures["de_oil"]
    assert less > hot + 0.1
    with pytest.raises(InputError, match="oil_de"):
        net.set_stream_flow("oil_de", -1.0)


def test_roundtrip_to_dict_from_dict():
    net = two_bearing_rig()
    net.add_node("ring", 10.0, group="de", role="outer_ring")
    net.add_edge("ring", "de_housing", CylindricalShell(40.0, 0.1, 0.12, 0.05))
    net.add_edge("ring", "ambient", PlaneWall(1.0, 0.01, 0.02))
    d = net.to_dict()
    back = ThermalNetwork.from_dict(d)
    assert back.to_dict() == d
    s1, s2 = assemble(net), assemble(back)
    np.testing.assert_array_equal(s1.K, s2.K)
    np.testing.assert_array_equal(s1.s, s2.s)
    with pytest.raises(InputError, match="bogus"):
        ThermalNetwork.from_dict({**d, "bogus": 1})


def test_editing_after_construction():
    net = two_bearing_rig()
    net.remove_node("nde_oil")  # also removes the stream through it
    assert "oil_nde" not in net.streams
    net.set_capacity("de_balls", 123.0)
    assert net.capacity("de_balls") == 123.0
    net.remove_edge("shaft", "nde_balls")
    net.set_edge_conductance("de_balls", "de_housing", 9.0)
    assert assemble(net).n == len(net.state_nodes)


# ------------------------------------------------------------------- bad input
def test_disconnected_node_is_named():
    net = ThermalNetwork()
    net.add_boundary("amb", 300.0)
    net.add_node("a", 1.0)
    net.add_node("island", 1.0)
    net.add_edge("a", "amb", 1.0)
    with pytest.raises(InputError, match="island"):
        net.validate()
    with pytest.raises(InputError, match="island"):
        solve_steady(net)


def test_negative_values_and_unknown_nodes():
    net = ThermalNetwork()
    net.add_boundary("amb", 300.0)
    net.add_node("a", 1.0)
    with pytest.raises(InputError, match="'a'-'amb'"):
        net.add_edge("a", "amb", -1.0)
    with pytest.raises(InputError, match="'b'"):
        net.add_node("b", -5.0)
    with pytest.raises(UnknownNameError, match="ghost"):
        net.add_edge("a", "ghost", 1.0)
    with pytest.raises(InputError, match="oil"):
        net.add_stream(["amb", "a"], -3.0, name="oil")
    with pytest.raises(InputError):
        net.add_stream(["a", "amb"], 3.0)  # must start at a boundary
    with pytest.raises(InputError):
        PlaneWall(-1.0, 1.0, 1.0)


def test_heat_on_fixed_temperature_node_is_an_error():
    net = ThermalNetwork()
    net.add_boundary("amb", 300.0)
    net.add_node("a", 1.0)
    net.add_edge("a", "amb", 1.0)
    with pytest.raises(InputError, match="amb"):
        net.heat_vector({"amb": 5.0})
    with pytest.raises(InputError, match="amb"):
        net.heat_vector(np.array([5.0, 1.0]))  # all-node order: amb first
    with pytest.raises(InputError, match="amb"):
        solve_steady(net, lambda t, T: {"amb": 1.0})
