"""Bad-input audit, issue 3 (thermal network): each clause of "What bad input gets" through
the public :mod:`thermobearing.network` API, asserting the error type and that the message
names the node / edge and the value; a failing step reports time, step size and residual
and the solver never returns NaN.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import ConvergenceError, InputError, UnknownNameError
from thermobearing.network import ThermalNetwork, integrate, solve_steady


def small() -> ThermalNetwork:
    net = ThermalNetwork()
    net.add_boundary("ambient", 300.0)
    net.add_node("housing", 100.0, role="outer_ring")
    net.add_edge("housing", "ambient", 1.0)
    return net


def test_disconnected_node_named():
    net = small()
    net.add_node("cage", 10.0)  # no edge, no stream
    with pytest.raises(InputError) as info:
        solve_steady(net, lambda t, T: np.zeros(2))
    assert "cage" in info.value.field
    assert "path" in info.value.allowed and "fixed-temperature" in info.value.allowed


@pytest.mark.parametrize("value", [-1.0, math.nan, math.inf])
def test_negative_or_non_finite_conductance(value):
    with pytest.raises(InputError) as info:
        small().add_edge("housing", "ambient", value)
    assert "'housing'-'ambient'" in info.value.field
    assert info.value.value == value or math.isnan(value)
    assert ">= 0" in info.value.allowed


@pytest.mark.parametrize("value", [-1.0, math.nan])
def test_negative_or_nan_capacity(value):
    with pytest.raises(InputError) as info:
        small().add_node("shaft", value)
    assert "shaft" in info.value.field and ">= 0" in info.value.allowed


def test_edge_to_unknown_node_lists_known_ones():
    with pytest.raises(UnknownNameError) as info:
        small().add_edge("housing", "shafft", 1.0)
    assert info.value.value == "shafft" and "'housing'-'shafft'" in info.value.field
    assert set(info.value.known) == {"ambient", "housing"}


def test_heat_on_fixed_temperature_node():
    with pytest.raises(InputError) as info:
        solve_steady(small(), lambda t, T: {"ambient": 10.0})
    assert "ambient" in info.value.field and info.value.value == 10.0
    assert "fixed-temperature" in info.value.allowed


def test_heat_on_unknown_node_lists_known_ones():
    with pytest.raises(UnknownNameError) as info:
        integrate(small(), lambda t, T: {"housng": 1.0}, (0.0, 100.0), 300.0)
    assert info.value.value == "housng" and info.value.known == ["housing"]


def test_heat_on_unknown_role_names_roles_present():
    # issue 4's "a heat source naming a node the network lacks": roles -> nodes
    with pytest.raises(InputError) as info:
        small().distribute({"cage": 5.0})
    assert "cage" in info.value.field and "outer_ring" in info.value.allowed


@pytest.mark.parametrize("flow", [-5.0, math.nan])
def test_negative_oil_flow(flow):
    net = small()
    net.add_boundary("oil_in", 300.0)
    net.add_node("oil", 10.0)
    net.add_edge("oil", "housing", 2.0)
    with pytest.raises(InputError) as info:
        net.add_stream(["oil_in", "oil"], flow)
    assert "mass_flow_heat_capacity" in info.value.field and ">= 0" in info.value.allowed


def test_time_span_backwards():
    with pytest.raises(InputError) as info:
        integrate(small(), lambda t, T: [1.0], (100.0, 0.0), 300.0)
    assert info.value.field == "t_span" and "t1 > t0" in info.value.allowed


def test_heat_returning_nan_is_a_convergence_error_with_time():
    with pytest.raises(ConvergenceError) as info:
        integrate(small(), lambda t, T: [math.nan], (0.0, 100.0), 300.0)
    assert "non-finite" in str(info.value)
    assert {"time", "step_size"} <= set(info.value.state)


def test_runaway_reports_time_step_and_residual_never_nan():
    # heat grows as exp(T - 300 K): no bounded solution, the step size collapses
    def runaway(t, T):
        return [1e3 * math.exp(min(T[0] - 300.0, 700.0))]

    with pytest.raises(ConvergenceError) as info:
        integrate(small(), runaway, (0.0, 1000.0), 300.0)
    err = info.value
    assert math.isfinite(err.residual) and err.residual > 0
    assert err.state["time"] < 1000.0 and err.state["step_size"] < 1e-6
    assert np.all(np.isfinite(err.state["temperatures"]))
