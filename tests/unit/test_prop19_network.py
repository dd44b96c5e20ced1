"""Property tests of steady thermal networks with an oil stream (session 19).

Random connected networks with conductances to ambient and an oil stream through a random
subset of the nodes (:func:`thermobearing.network.solve_steady`):

- energy balance: the sum of the sources equals the heat conducted to the boundaries plus
  the enthalpy the stream carries out, m_dot c_p (T_last - T_in), each recomputed here from
  the solved temperatures (not only the solver's own audit);
- positivity (discrete maximum principle, -K is an M-matrix): with non-negative sources
  every node sits at or above the coldest boundary (ambient or oil inlet), and a source
  raised at one node raises no temperature less than zero anywhere (the inverse of an
  M-matrix is non-negative).
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.network import ThermalNetwork, solve_steady


@st.composite
def stream_networks(draw):
    n = draw(st.integers(2, 7))
    net = ThermalNetwork("random stream")
    t_amb = draw(st.floats(250.0, 350.0))
    t_in = draw(st.floats(250.0, 350.0))
    net.add_boundary("amb", t_amb)
    net.add_boundary("oil_in", t_in)
    for i in range(n):
        net.add_node(f"n{i}", draw(st.floats(1.0, 1e4)))
    g = st.floats(0.01, 100.0)
    edges = []
    for i in range(1, n):
        j = draw(st.integers(0, i - 1))
        w = draw(g)
        net.add_edge(f"n{i}", f"n{j}", w)
        edges.append((f"n{i}", f"n{j}", w))
    to_amb = {}
    for i in sorted(set(draw(st.lists(st.integers(0, n - 1), min_size=0, max_size=n)))):
        w = draw(g)
        net.add_edge(f"n{i}", "amb", w)
        to_amb[f"n{i}"] = w
    order = draw(st.permutations(list(range(n))))
    k = draw(st.integers(1, n))
    path = [f"n{i}" for i in order[:k]]
    flow = draw(st.floats(0.0, 200.0) if to_amb else st.floats(0.5, 200.0))
    net.add_stream(["oil_in", *path], flow)
    if not to_amb and flow == 0.0:
        to_amb["n0"] = 1.0
        net.add_edge("n0", "amb", 1.0)
    heat = np.array(draw(st.lists(st.floats(0.0, 500.0), min_size=n, max_size=n)))
    return net, heat, t_amb, t_in, to_amb, path, flow


@settings(max_examples=40, deadline=None)
@given(stream_networks())
def test_steady_energy_balance_with_an_oil_stream(case):
    net, heat, t_amb, t_in, to_amb, path, flow = case
    res = solve_steady(net, heat)
    temps = res.temperatures
    generated = float(np.sum(heat))
    conducted = sum(w * (temps[node] - t_amb) for node, w in to_amb.items())
    enthalpy = flow * (temps[path[-1]] - t_in)
    scale = max(1.0, generated, abs(conducted), abs(enthalpy))
    assert abs(generated - conducted - enthalpy) <= 1e-8 * scale
    assert abs(res.to_boundaries - conducted) <= 1e-8 * scale
    assert abs(res.to_streams - enthalpy) <= 1e-8 * scale
    assert abs(res.generated - generated) <= 1e-9 * scale


@settings(max_examples=40, deadline=None)
@given(stream_networks(), st.data())
def test_steady_temperatures_obey_the_maximum_principle(case, data):
    net, heat, t_amb, t_in, _, _, _ = case
    t = solve_steady(net, heat).temperatures_vector
    floor = min(t_amb, t_in)
    span = max(1.0, float(np.max(np.abs(t - floor))))
    assert np.all(t >= floor - 1e-9 * span)
    i = data.draw(st.integers(0, heat.size - 1))
    more = heat.copy()
    more[i] += data.draw(st.floats(1.0, 500.0))
    t2 = solve_steady(net, more).temperatures_vector
    assert np.all(t2 - t >= -1e-9 * span)
    assert t2[i] > t[i]
