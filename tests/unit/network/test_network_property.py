"""Property test: random connected networks conserve energy and reach their steady state."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.network import ThermalNetwork, integrate, solve_steady


@st.composite
def networks(draw):
    n = draw(st.integers(2, 7))
    caps = draw(st.lists(st.floats(1.0, 1e4), min_size=n, max_size=n))
    net = ThermalNetwork("random")
    net.add_boundary("amb", draw(st.floats(250.0, 350.0)))
    for i, c in enumerate(caps):
        net.add_node(f"n{i}", c)
    g = st.floats(0.1, 100.0)
    resist = 0.0
    # a random spanning tree keeps it connected ...
    for i in range(1, n):
        j = draw(st.integers(0, i - 1))
        w = draw(g)
        resist += 1.0 / w
        net.add_edge(f"n{i}", f"n{j}", w)
    # ... plus random extra edges and at least one path to ambient
    for _ in range(draw(st.integers(0, n))):
        a, b = draw(st.integers(0, n - 1)), draw(st.integers(0, n - 1))
        if a != b:
            net.add_edge(f"n{a}", f"n{b}", draw(g))
    w = draw(g)
    resist += 1.0 / w
    net.add_edge(f"n{draw(st.integers(0, n - 1))}", "amb", w)
    heat = np.array(draw(st.lists(st.floats(1.0, 500.0), min_size=n, max_size=n)))
    t_end = 40.0 * sum(caps) * resist  # >> slowest time constant
    return net, heat, t_end


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks())
def test_random_networks_conserve_energy_and_reach_steady(case):
    net, heat, t_end = case
    T_amb = net.boundary_temperature("amb")
    res = integrate(net, heat, (0.0, t_end), T_amb, rtol=1e-9, atol=1e-9)
    assert res.audit.relative_imbalance() < 1e-9
    assert np.all(np.isfinite(res.temperatures))
    steady = solve_steady(net, heat).temperatures_vector
    scale = max(1.0, float(np.max(steady - T_amb)))
    np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-5 * scale, rtol=0)
    # energy: generated = stored + to ambient (no streams here)
    tot = res.audit.totals()
    stored = float(np.dot([net.capacity(n) for n in net.state_nodes],
                          res.temperatures[-1] - T_amb))
    assert abs(tot["stored"] - stored) <= 1e-9 * max(1.0, abs(stored))


@st.composite
def networks_with_free_convection(draw):
    """A random network of :func:`networks` plus temperature-dependent edges: free convection
    of a horizontal cylinder to the ambient from one node and, sometimes, between two nodes
    (an edge between two state nodes gives the conductances' Jacobian off-diagonal terms)."""
    from thermobearing.network.conductances import NaturalConvectionCylinder

    net, heat, t_end = draw(networks())
    # keep the steady rise inside the air model's range (100-2000 K): scale the heat so the
    # network without the added cooling edges stays below 1000 K above the ambient
    rise = float(np.max(solve_steady(net, heat).temperatures_vector
                        - net.boundary_temperature("amb")))
    heat = heat * min(1.0, 1000.0 / rise)
    n = len(net.state_nodes)
    i = draw(st.integers(0, n - 1))
    net.add_edge(f"n{i}", "amb", NaturalConvectionCylinder(draw(st.floats(0.05, 0.5)),
                                                           draw(st.floats(0.05, 2.0))))
    if n > 1 and draw(st.booleans()):
        a, b = draw(st.permutations(range(n)))[:2]
        net.add_edge(f"n{a}", f"n{b}", NaturalConvectionCylinder(0.1, draw(st.floats(0.05, 1.0))))
    return net, heat, t_end


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks_with_free_convection())
def test_temperature_dependent_networks_close_their_books_and_reach_steady(case):
    """exprb43 and TR-BDF2 with temperature-dependent conductances (their drift in the
    stages, their derivatives in the linearisation / Newton matrix): exprb43's books close
    to round-off, TR-BDF2's to its Newton tolerance (nonlinear stages), and both runs end on
    the steady state of the nonlinear network (damped steady Newton)."""
    net, heat, t_end = case
    T_amb = net.boundary_temperature("amb")
    steady = solve_steady(net, heat).temperatures_vector
    scale = max(1.0, float(np.max(steady - T_amb)))
    for method, books in (("exprb43", 1e-10), ("tr_bdf2", 1e-6)):
        res = integrate(net, heat, (0.0, t_end), T_amb, method=method, rtol=1e-9, atol=1e-9)
        assert res.audit.relative_imbalance() < books, method
        assert np.all(np.isfinite(res.temperatures))
        np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-5 * scale, rtol=0)


def test_steady_newton_accepts_round_off_residual_of_hot_weakly_cooled_chains():
    """A chain of stiff edges (50-100 W/K) cooled through 0.1-0.2 W/K reaches ~3000-10000 K
    rises: one ulp of its flows is ~1e-10 W, so the last Newton step (5e-10 K) exceeds the
    step tolerance while no step can lower the residual. That is convergence (16 of these
    50 x 4 networks raised 'line search failed' before): every node balances to round-off
    of its flows."""
    rng = np.random.default_rng(1)
    for _ in range(50):
        net = ThermalNetwork("chain")
        net.add_boundary("amb", 300.0)
        for i in range(5):
            net.add_node(f"n{i}", 1.0)
        for i in range(1, 5):
            net.add_edge(f"n{i}", f"n{i - 1}", float(rng.uniform(50.0, 100.0)))
        g_amb = float(rng.uniform(0.1, 0.2))
        net.add_edge("n0", "amb", g_amb)
        heat = rng.uniform(100.0, 500.0, 5)
        res = solve_steady(net, heat)
        rise = res.temperatures_vector[0] - 300.0
        assert rise == pytest.approx(heat.sum() / g_amb, rel=1e-12)
        assert res.residual <= 1e3 * np.finfo(float).eps * 100.0 * res.temperatures_vector.max()


def test_drift_jacobian_at_the_edge_of_a_conductance_range_is_one_sided():
    """Free convection is defined up to 2000 K (air): at 2000 K - 1e-4 the central
    difference would step outside; the derivative is then the one-sided one, equal to
    the central one a little further inside to its first-order error (0.2 % here)."""
    from thermobearing.network.assemble import Assembler
    from thermobearing.network.conductances import NaturalConvectionCylinder

    net = ThermalNetwork("edge")
    net.add_boundary("amb", 300.0)
    net.add_node("n0", 1.0)
    net.add_edge("n0", "amb", NaturalConvectionCylinder(0.2, 0.5))
    asm = Assembler(net)
    at_edge = asm.drift_jacobian(np.array([2000.0 - 1e-4]))
    inside = asm.drift_jacobian(np.array([1999.9]))
    assert np.all(np.isfinite(at_edge))
    np.testing.assert_allclose(at_edge, inside, rtol=5e-3)
