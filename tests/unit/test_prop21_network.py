"""Property tests of the thermal network's transient steppers with an oil stream and
zero-capacity nodes (session 21), beside the steady books of test_prop19_network.py and the
stream-free transients of network/test_network_property.py.

Random connected networks: a spanning tree of conductances, a conductance to the ambient,
an enthalpy stream from an inlet boundary through a random subset of the nodes, some nodes
without capacity (algebraic nodes: the seal air, the oil film), constant non-negative heat.

- books: each stepper's audit closes, generated = stored + to_boundaries + to_streams, to
  round-off (the network is linear, so each stage's Newton solve is exact), and the run's
  stored energy is sum C_i (T_i(t1) - T_i(t0)) recomputed from the returned temperatures;
- the steady state does not depend on the stepper: every L-stable stepper (TR-BDF2,
  backward Euler, exprb43) ends, after many slowest time constants, at
  :func:`solve_steady`'s temperatures. Crank-Nicolson (fixed step, A- but not L-stable)
  closes its books too but is not asked to settle: its stiff modes ring with an
  amplification near -1 (measured at 400 steps over the run: up to 58 % of the steady rise
  left on a 1 J/K node beside a 7470 J/K one), the behaviour BM-3 shows it for;
- positivity: from the coldest boundary temperature with non-negative heat no node of a
  backward-Euler run ever drops below that temperature (backward Euler's (C + h K)^-1 is
  the inverse of an M-matrix, so it is non-negative);
- step-wise = whole run: chained :meth:`TransientStepper.advance` calls over the same
  interval end where :func:`integrate` ends (within the tolerances asked for), and their
  audits add up to the whole run's books;
- temperature-dependent conductances (free convection) at zero-capacity nodes: exprb43 and
  TR-BDF2 run, close their books and end at the nonlinear steady state. The zero-capacity
  nodes were initialised (``_Core.consistent_algebraic``) with the conductances of the
  incoming temperatures, not of the solved ones; exprb43 then stopped at t = 0 with 'step
  size underflow' (10 of 30 seeded networks);
- the oil stream of the four- and seven-node templates: its capacity rate is
  rho c_p Q at the inlet, the steady books close through the ambient and the stream, and
  more oil from an inlet no warmer than the ambient lowers every temperature;
- bad heat: a non-finite constant heat is an InputError naming the node, a heat source
  turning non-finite a ConvergenceError from every entry point (the private
  _NewtonFailure escaped solve_steady, integrate and TransientStepper.advance).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.network import ThermalNetwork, TransientStepper, integrate, solve_steady


@st.composite
def stream_networks(draw, zero_capacity: bool = True):
    n = draw(st.integers(2, 6))
    net = ThermalNetwork("random stream")
    t_amb = draw(st.floats(250.0, 350.0))
    t_in = draw(st.floats(250.0, 350.0))
    net.add_boundary("amb", t_amb)
    net.add_boundary("oil_in", t_in)
    caps = []
    for i in range(n):
        massless = zero_capacity and i > 0 and draw(st.booleans())
        c = 0.0 if massless else draw(st.floats(1.0, 1e4))
        caps.append(c)
        net.add_node(f"n{i}", c)
    g = st.floats(0.1, 100.0)
    resist = 0.0
    for i in range(1, n):
        j = draw(st.integers(0, i - 1))
        w = draw(g)
        resist += 1.0 / w
        net.add_edge(f"n{i}", f"n{j}", w)
    w = draw(g)
    resist += 1.0 / w
    net.add_edge(f"n{draw(st.integers(0, n - 1))}", "amb", w)
    order = draw(st.permutations(list(range(n))))
    k = draw(st.integers(1, n))
    path = [f"n{i}" for i in order[:k]]
    flow = draw(st.floats(0.0, 100.0))
    net.add_stream(["oil_in", *path], flow)
    # at least 1 W somewhere: with no heat and the nodes at the boundary temperature every
    # flow is round-off and relative_imbalance() is round-off over round-off (measured 1.0
    # for Crank-Nicolson and TR-BDF2 on two nodes at 250 K: stored 2.8e-14 J, nothing else)
    heat = np.array(draw(st.lists(st.floats(0.0, 500.0), min_size=n, max_size=n)))
    heat[draw(st.integers(0, n - 1))] += 1.0
    t_end = 40.0 * sum(caps) * resist  # >> the slowest time constant (no flow, one path)
    return net, heat, t_end


def _stored(net: ThermalNetwork, t0: np.ndarray, t1: np.ndarray) -> float:
    caps = np.array([net.capacity(name) for name in net.state_nodes])
    return float(np.dot(caps, t1 - t0))


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(stream_networks())
def test_every_stepper_closes_its_books_and_ends_at_the_steady_state(case):
    net, heat, t_end = case
    steady = solve_steady(net, heat).temperatures_vector
    t0 = min(net.boundary_temperature("amb"), net.boundary_temperature("oil_in"))
    scale = max(1.0, float(np.max(np.abs(steady - t0))))
    # backward Euler (first order) at 1e-9 took up to 15 s a network: 1e-8 K on its steps
    runs = {"tr_bdf2": {"rtol": 1e-9, "atol": 1e-9}, "exprb43": {"rtol": 1e-9, "atol": 1e-9},
            "backward_euler": {"rtol": 1e-7, "atol": 1e-7},
            # a fixed step: the run is 400 steps long whatever the time constants
            "crank_nicolson": {"dt": t_end / 400.0}}
    for method, kwargs in runs.items():
        res = integrate(net, heat, (0.0, t_end), t0, method=method, **kwargs)
        assert np.all(np.isfinite(res.temperatures)), method
        assert res.audit.relative_imbalance() < 1e-9, method
        tot = res.audit.totals()
        stored = _stored(net, res.temperatures[0], res.temperatures[-1])
        assert abs(tot["stored"] - stored) <= 1e-9 * max(1.0, abs(stored), tot["generated"]), \
            method
        if method != "crank_nicolson":
            np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-5 * scale, rtol=0,
                                       err_msg=method)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(stream_networks(), st.floats(0.01, 1.0))
def test_backward_euler_stays_above_the_coldest_boundary(case, fraction):
    net, heat, t_end = case
    floor = min(net.boundary_temperature("amb"), net.boundary_temperature("oil_in"))
    res = integrate(net, heat, (0.0, fraction * t_end), floor, method="backward_euler",
                    rtol=1e-6, atol=1e-6)
    span = max(1.0, float(np.max(res.temperatures - floor)))
    assert float(np.min(res.temperatures)) >= floor - 1e-9 * span


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(stream_networks(), st.integers(2, 6), st.sampled_from(["tr_bdf2", "exprb43"]))
def test_chained_advances_equal_one_run(case, pieces, method):
    net, heat, t_end = case
    t_end = 0.2 * t_end
    t0 = net.boundary_temperature("amb")
    whole = integrate(net, heat, (0.0, t_end), t0, method=method, rtol=1e-10, atol=1e-10)
    stepper = TransientStepper(net, method=method, rtol=1e-10, atol=1e-10)
    t, temps = 0.0, whole.temperatures[0]
    generated = stored = out = 0.0
    for _ in range(pieces):
        step = stepper.advance(t, temps, t_end / pieces, heat)
        t, temps = step.time, step.temperatures
        generated += float(np.sum(step.audit.generated))
        stored += float(np.sum(step.audit.stored))
        out += float(np.sum(step.audit.to_boundaries) + np.sum(step.audit.to_streams))
    scale = max(1.0, float(np.max(np.abs(whole.temperatures[-1] - t0))))
    np.testing.assert_allclose(temps, whole.temperatures[-1], atol=1e-6 * scale, rtol=0)
    tot = whole.audit.totals()
    flows = max(1.0, abs(tot["generated"]), abs(tot["stored"]))
    assert abs(generated - tot["generated"]) <= 1e-9 * flows
    assert abs(generated - stored - out) <= 1e-9 * flows
    assert abs(stored - _stored(net, whole.temperatures[0], temps)) <= 1e-9 * flows


@st.composite
def convecting_stream_networks(draw):
    """:func:`stream_networks` plus free convection to the ambient from one node and,
    sometimes, between two nodes; zero-capacity nodes included (the convection may touch
    them). The heat is scaled so that the steady rise stays below 300 K (the air model's
    range)."""
    from thermobearing.network.conductances import NaturalConvectionCylinder

    net, heat, t_end = draw(stream_networks())
    n = len(net.state_nodes)
    rise = float(np.max(solve_steady(net, heat).temperatures_vector
                        - net.boundary_temperature("amb")))
    if rise > 300.0:
        heat = heat * (300.0 / rise)
    i = draw(st.integers(0, n - 1))
    net.add_edge(f"n{i}", "amb", NaturalConvectionCylinder(draw(st.floats(0.05, 0.5)),
                                                           draw(st.floats(0.05, 2.0))))
    if draw(st.booleans()):
        a, b = draw(st.permutations(range(n)))[:2]
        net.add_edge(f"n{a}", f"n{b}", NaturalConvectionCylinder(0.1, draw(st.floats(0.05, 1.0))))
    return net, heat, t_end


def _convecting_case(case, tol: float) -> None:
    """exprb43 and TR-BDF2 with free convection, zero-capacity nodes and an oil stream:
    both run (exprb43 stopped at t = 0 with 'step size underflow' on 10 of 30 seeded
    networks: the zero-capacity nodes were initialised with the conductances of the start
    temperatures), close their books (exprb43 to round-off, TR-BDF2 to its Newton
    tolerance) and end at the nonlinear steady state. 2-6 s a network (the air
    properties at every conductance evaluation)."""
    net, heat, t_end = case
    t0 = net.boundary_temperature("amb")
    steady = solve_steady(net, heat).temperatures_vector
    scale = max(1.0, float(np.max(np.abs(steady - t0))))
    for method, books in (("exprb43", 1e-9), ("tr_bdf2", 1e-6)):
        res = integrate(net, heat, (0.0, t_end), t0, method=method, rtol=tol, atol=tol)
        assert np.all(np.isfinite(res.temperatures)), method
        assert res.audit.relative_imbalance() < books, method
        np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-5 * scale, rtol=0,
                                   err_msg=method)


@settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(convecting_stream_networks())
def test_temperature_dependent_edges_at_zero_capacity_nodes(case):
    _convecting_case(case, 1e-7)


@pytest.mark.slow
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(convecting_stream_networks())
def test_temperature_dependent_edges_at_zero_capacity_nodes_many(case):
    _convecting_case(case, 1e-9)


def test_zero_capacity_node_under_free_convection_starts_consistently():
    """The measured case: n0 (1.30 J/K) and the zero-capacity n1 with free convection to
    the ambient and to n0, an oil stream through both; exprb43 at rtol 1e-7 stopped at
    t = 0 (residual 1.3e3 W). It now runs and ends where TR-BDF2 ends."""
    from thermobearing.network.conductances import NaturalConvectionCylinder

    net = ThermalNetwork("two nodes")
    net.add_boundary("amb", 299.9277862440115)
    net.add_boundary("oil_in", 310.1498357623357)
    net.add_node("n0", 1.3024349253322585)
    net.add_node("n1", 0.0)
    net.add_edge("n0", "amb", 0.16265286913013008)
    net.add_edge("n1", "amb", NaturalConvectionCylinder(0.4767478039812988, 1.2626730059529465))
    net.add_edge("n1", "n0", 60.90221230296086)
    net.add_edge("n1", "n0", NaturalConvectionCylinder(0.1, 0.5358205207130995))
    net.add_stream(["oil_in", "n0", "n1"], 13.765440788056466)
    heat = np.array([42.25245379, 236.62383876])
    ends = {}
    for method in ("exprb43", "tr_bdf2"):
        res = integrate(net, heat, (0.0, 321.15), 299.9277862440115, method=method,
                        rtol=1e-7, atol=1e-7)
        ends[method] = res.temperatures[-1]
    np.testing.assert_allclose(ends["exprb43"], ends["tr_bdf2"], atol=1e-4, rtol=0)
    np.testing.assert_allclose(ends["exprb43"], [320.489, 322.154], atol=2e-3, rtol=0)


TEMPLATE_BEARINGS = ("SKF6304", "QJ1044", "NU214")


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(TEMPLATE_BEARINGS), seven=st.booleans(),
       log_flow=st.floats(-8.0, -4.0), more=st.floats(1.2, 10.0), cooler=st.floats(0.0, 30.0),
       power=st.floats(10.0, 2000.0))
def test_oil_stream_books_and_cools_the_template_networks(name, seven, log_flow, more, cooler,
                                                          power):
    """The paper 002 four-node and the seven-node templates with an oil stream: the stream's
    capacity rate is rho(T_in) c_p(T_in) Q (oil_capacity_rate); at steady state the heat
    leaves through the ambient conductances and the stream, W (T_oil - T_in); with the inlet
    no warmer than the ambient, more oil lowers every temperature (adding a conductance to
    the coldest boundary: the M-matrix's monotonicity)."""
    import warnings

    from thermobearing import load_bearing, load_lubricant
    from thermobearing.errors import ValidityWarning
    from thermobearing.network import four_node_paper002, oil_capacity_rate, seven_node

    b = load_bearing(name)
    oil = load_lubricant("ISO_VG46")
    t_amb = 308.15
    t_in = t_amb - cooler
    flow = 10.0**log_flow
    build = seven_node if seven else four_node_paper002
    net = build(b, oil, housing_outer_diameter=1.6 * b.outer_diameter,
                housing_length=2.0 * b.width, oil_flow=flow, oil_inlet_temperature=t_in,
                ambient_temperature=t_amb)
    w = oil_capacity_rate(oil, flow, t_in)
    assert net.streams["oil"].capacity_rate == pytest.approx(w, rel=1e-12)
    heat = net.distribute({"elements": 0.5 * power, "inner_ring": 0.3 * power,
                           "outer_ring": 0.2 * power})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        res = solve_steady(net, heat)
        t_oil = res.temperatures["oil"]
        assert res.to_streams == pytest.approx(w * (t_oil - t_in), rel=1e-9, abs=1e-9)
        assert res.generated == pytest.approx(power, rel=1e-12)
        assert res.to_boundaries + res.to_streams == pytest.approx(power, rel=1e-8)
        net.set_stream_flow("oil", oil_capacity_rate(oil, more * flow, t_in))
        colder = solve_steady(net, heat).temperatures_vector
    assert np.all(colder <= res.temperatures_vector + 1e-9 * power)


def _one_node() -> ThermalNetwork:
    net = ThermalNetwork("one node")
    net.add_boundary("amb", 300.0)
    net.add_node("a", 10.0, role="elements")
    net.add_edge("a", "amb", 1.0)
    return net


@pytest.mark.parametrize("heat", [np.array([np.nan]), np.array([np.inf]), {"a": -np.inf}])
def test_a_non_finite_constant_heat_names_its_node(heat):
    """Was 'did not converge (residual inf)' from integrate and the private _NewtonFailure
    from solve_steady."""
    from thermobearing.errors import InputError

    net = _one_node()
    with pytest.raises(InputError, match="heat\\['a'\\]"):
        solve_steady(net, heat)
    with pytest.raises(InputError, match="heat\\['a'\\]"):
        integrate(net, heat, (0.0, 10.0), 300.0)


@pytest.mark.parametrize("method", ["tr_bdf2", "exprb43", "backward_euler"])
def test_a_heat_source_turning_non_finite_is_a_convergence_error(method):
    """A callable heat that is NaN above 300.5 K: every entry point raises the public
    ConvergenceError with an infinite residual (integrate and TransientStepper.advance let
    the private _NewtonFailure out of a finite-difference Jacobian after a failed step,
    solve_steady from its first residual)."""
    from thermobearing.errors import ConvergenceError

    def heat(t, T):
        return np.array([1e3 if T[0] < 300.5 else np.nan])

    net = _one_node()
    with pytest.raises(ConvergenceError, match="non-finite"):
        integrate(net, heat, (0.0, 10.0), 300.0, method=method)
    with pytest.raises(ConvergenceError, match="non-finite"):
        TransientStepper(net, method=method).advance(0.0, 300.0, 10.0, heat)
    with pytest.raises(ConvergenceError, match="non-finite"):
        solve_steady(net, lambda t, T: np.array([np.nan]))
