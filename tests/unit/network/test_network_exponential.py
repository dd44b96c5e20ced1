"""Verification of the exponential Rosenbrock stepper ``exprb43`` (network.exponential).

Same checks as the implicit steppers (test_network_steppers.py): exact RC and two-node
solutions, observed order, energy audit, discrete maximum principle at dt = 600 s,
zero-capacity nodes, failures reported with time and step size, never NaN.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from scipy.integrate import solve_ivp
from scipy.linalg import expm
from test_network_property import networks  # same folder (pytest prepend import mode)
from test_network_steppers import T_AMB, _dmp_case, chain, rc

from thermobearing.errors import ConvergenceError
from thermobearing.network import (
    STEPPERS,
    ThermalNetwork,
    TransientStepper,
    integrate,
    phi_functions,
    solve_steady,
)
from thermobearing.network.problems import bearing_network, load_protocol, viscous_heat_for


def chain_exact(t, Q=(100.0, 0.0), T0=T_AMB) -> np.ndarray:
    """T = T_ss + expm(-C^-1 K t) (T0 - T_ss) of the chain (matrix exponential)."""
    C = np.array([500.0, 2000.0])
    K = np.array([[3.0, -3.0], [-3.0, 4.0]])
    Tss = np.linalg.solve(K, np.array([0.0, T_AMB]) + np.array(Q))
    return np.array([Tss + expm(-K / C[:, None] * ti) @ (np.full(2, T0) - Tss)
                     for ti in np.atleast_1d(t)])


def test_registered_with_citations():
    entry = STEPPERS.entry("exprb43")
    assert "hochbruck2009_exprb" in entry.references


def test_phi_functions_match_augmented_matrix_exponential():
    """phi_k(z) = [expm([[z, e_1^T], [0, N_k]])]_{0,k} (N_k the shift matrix): Saad 1992,
    Sidje 1998 (Expokit) augmented-matrix identity; real, complex, small, stiff z."""
    zs = np.array([1e-9, -0.3, 0.5, 0.99, 1.01, -0.7 + 0.4j, -3.0, 5.0, -40.0, 2.0 + 3.0j])
    ph = phi_functions(zs, 5)
    for k in range(1, 6):
        ref = []
        for z in zs:
            M = np.zeros((k + 1, k + 1), complex)
            M[0, 0] = z
            M[np.arange(k), np.arange(1, k + 1)] = 1.0
            ref.append(expm(M)[0, k])
        np.testing.assert_allclose(ph[k], ref, rtol=1e-13)
    assert phi_functions(np.array([-1e4]), 3)[3][0] == pytest.approx(1.0 / (2 * 1e4), rel=1e-3)


@pytest.mark.parametrize("dt", [None, 600.0])
def test_single_rc_node_exact_at_any_step(dt):
    # T(t) = T_amb + Q/G (1 - exp(-G t / C)), Q = 100 W, G = 2 W/K, C = 1000 J/K: the
    # network is linear, so the exponential step is the exact flow whatever its size
    res = integrate(rc(), [100.0], (0.0, 3000.0), T_AMB, method="exprb43", dt=dt)
    exact = T_AMB + 50.0 * (1.0 - np.exp(-2.0 * res.times / 1000.0))
    assert np.max(np.abs(res.temperature("a") - exact)) < 1e-10
    if dt is None:
        assert res.stats["steps"] == 1  # one step over the whole span


def test_two_node_chain_exact_with_dense_output():
    res = integrate(chain(), {"a": 100.0}, (0.0, 5000.0), T_AMB, method="exprb43",
                    max_step=700.0)
    assert np.max(np.abs(res.temperatures - chain_exact(res.times))) < 1e-9
    grid = np.linspace(0, 5000, 101)
    assert np.max(np.abs(res.sample(grid) - chain_exact(grid))) < 1e-9  # dense output


def _viscous_rc():
    net = rc(1000.0, 20.0)

    def heat(t, T):
        return np.array([2000.0 * math.exp(-0.03 * (T[0] - T_AMB))])

    return net, heat


def test_observed_order_four_on_the_nonlinear_source():
    """On the linear part the method is exact; its order shows on the nonlinear source
    q = 2000 W exp(-0.03 (T - 300 K)): fixed steps, error at t = 400 s against solve_ivp
    (Radau, rtol 1e-13). Fitted slope within 0.1 of 4."""
    net, heat = _viscous_rc()
    ref = solve_ivp(lambda t, T: (-20.0 * (T - T_AMB) + heat(t, T)) / 1000.0, (0.0, 400.0),
                    [T_AMB], method="Radau", rtol=1e-13, atol=1e-12).y[0, -1]
    dts = np.array([100.0, 50.0, 25.0, 12.5])
    errs = []
    for dt in dts:
        res = integrate(net, heat, (0.0, 400.0), T_AMB, method="exprb43", dt=dt,
                        heat_time_dependent=False, jacobian="fd_diagonal")
        errs.append(abs(res.temperatures[-1, 0] - ref))
    slope = np.polyfit(np.log(dts), np.log(errs), 1)[0]
    assert abs(slope - 4.0) < 0.1, (slope, errs)


def test_time_dependent_source_ramp():
    """q = 50 + 0.2 t W (a ramp, linear in T): represented exactly by the dq/dt term;
    exact solution of C T' = -G (T - T_amb) + a + b t, G = 2, C = 1000."""
    a, b, G, C = 50.0, 0.2, 2.0, 1000.0
    res = integrate(rc(C, G), lambda t, T: np.array([a + b * t]), (0.0, 3000.0), T_AMB,
                    method="exprb43", rtol=1e-8, atol=1e-8)
    t = res.times
    k = G / C
    # particular solution T_p(t) = T_amb + (a + b t)/G - b C/G^2; homogeneous part decays
    Tp = T_AMB + (a + b * t) / G - b * C / G**2
    exact = Tp + (T_AMB - (T_AMB + a / G - b * C / G**2)) * np.exp(-k * t)
    assert np.max(np.abs(res.temperature("a") - exact)) < 1e-5


def test_energy_audit_closes_on_linear_network():
    net = bearing_network(20)
    q = np.zeros(len(net.state_nodes))
    q[:4] = [300.0, 100.0, 50.0, 20.0]
    res = integrate(net, q, (0.0, 4000.0), 308.15, method="exprb43", breakpoints=[1000.0])
    assert res.audit.relative_imbalance() < 1e-10
    tot = res.audit.totals()
    assert tot["generated"] == pytest.approx(470.0 * 4000.0, rel=1e-12)
    assert tot["to_streams"] > 0 and tot["to_boundaries"] > 0 and tot["stored"] > 0


def test_energy_audit_nonlinear_and_accuracy_on_the_protocol():
    """The books close on the nonlinear protocol too (the method's own quadrature of q),
    and the result agrees with a tight TR-BDF2 run to the tolerance."""
    net = bearing_network(4)
    edges, P = load_protocol(6, 120.0)
    heat = viscous_heat_for(net, edges, P)
    res = integrate(net, heat, (0.0, edges[-1]), 308.15, method="exprb43",
                    breakpoints=edges, rtol=1e-5, atol=1e-4, heat_jacobian=heat.jacobian,
                    heat_time_dependent=False)
    assert res.audit.relative_imbalance() < 1e-10
    ref = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-10,
                    atol=1e-9, heat_jacobian=heat.jacobian)
    grid = np.linspace(0.0, edges[-1], 73)
    assert np.max(np.abs(res.sample(grid) - ref.sample(grid))) < 1e-3
    # the generated heat is a quadrature of q: bounded by the schedule
    steps = res.audit
    assert np.all(steps.generated <= P.max() * np.diff(np.r_[0.0, steps.step_end_times]) + 1e-6)
    # time-dependent path (dq/dt by a difference quotient) gives the same answer
    td = integrate(net, heat, (0.0, edges[-1]), 308.15, method="exprb43",
                   breakpoints=edges, rtol=1e-5, atol=1e-4, heat_jacobian=heat.jacobian)
    assert np.max(np.abs(td.sample(grid) - ref.sample(grid))) < 1e-3
    assert td.audit.relative_imbalance() < 1e-10


def test_discrete_maximum_principle_600s():
    """Fixed 600 s steps on the stiff network with a 1e-6 J/K node: the step is the exact
    flow, so nothing below ambient, nothing above the steady state, monotone approach."""
    net, q, steady = _dmp_case()
    res = integrate(net, q, (0.0, 36000.0), 308.15, method="exprb43", dt=600.0)
    assert res.temperatures.min() >= 308.15 - 1e-9
    assert res.temperatures.max() <= steady.max() + 1e-9
    assert np.all(np.diff(res.temperatures, axis=0) >= -1e-9)
    np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-8)


def test_maximum_principle_600s_nonlinear_source():
    """Viscous (temperature-dependent) heat, fixed 600 s steps: the interpolated
    remainder could in principle overshoot; measured, it stays within the bounds
    (ambient .. steady state at the largest load) and settles on the steady state."""
    net = bearing_network(20, film_capacity=1e-6)
    edges, P = np.array([0.0, 1e9]), np.array([2500.0])
    heat = viscous_heat_for(net, edges, P)
    steady = solve_steady(net, heat, T_guess=308.15).temperatures_vector
    res = integrate(net, heat, (0.0, 36000.0), 308.15, method="exprb43", dt=600.0,
                    heat_jacobian=heat.jacobian, heat_time_dependent=False)
    assert res.temperatures.min() >= 308.15 - 1e-9
    assert res.temperatures.max() <= steady.max() + 1e-6
    np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-6)


def test_zero_capacity_nodes():
    """An algebraic node sits at the conductance-weighted mean of its neighbours + q/G."""
    net = ThermalNetwork()
    net.add_boundary("amb", T_AMB)
    net.add_node("body", 1000.0)
    net.add_node("film", 0.0)
    net.add_edge("body", "film", 10.0)
    net.add_edge("film", "amb", 5.0)
    res = integrate(net, {"film": 30.0}, (0.0, 2000.0), 350.0, method="exprb43")
    Tb, Tf = res.temperature("body"), res.temperature("film")
    np.testing.assert_allclose(Tf, (10 * Tb + 5 * T_AMB + 30.0) / 15.0, rtol=0, atol=1e-9)
    g, q = 10 * 5 / 15, 30 * 10 / 15
    exact = T_AMB + q / g + (350.0 - T_AMB - q / g) * np.exp(-g * res.times / 1000.0)
    assert np.max(np.abs(Tb - exact)) < 1e-9
    assert res.audit.relative_imbalance() < 1e-10
    grid = np.linspace(0.0, 2000.0, 41)
    Ys = res.sample(grid)
    np.testing.assert_allclose(Ys[:, 1], (10 * Ys[:, 0] + 5 * T_AMB + 30.0) / 15.0, atol=1e-9)


def test_zero_capacity_nodes_nonlinear_match_tr_bdf2():
    """Zero-capacity film nodes with a temperature-dependent source on them."""
    net = bearing_network(8)
    net.set_capacity("oil_0", 0.0)
    edges, P = load_protocol(4, 120.0)
    heat = viscous_heat_for(net, edges, P)
    a = integrate(net, heat, (0.0, edges[-1]), 308.15, method="exprb43", breakpoints=edges,
                  rtol=1e-6, atol=1e-5, heat_jacobian=heat.jacobian)
    b = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-10,
                  atol=1e-9, heat_jacobian=heat.jacobian)
    np.testing.assert_allclose(a.temperatures[-1], b.temperatures[-1], atol=1e-4)
    assert a.audit.relative_imbalance() < 1e-10


def test_stepwise_api_matches_integrate():
    net = bearing_network(4)
    edges, P = load_protocol(4, 120.0)
    heat = viscous_heat_for(net, edges, P)
    ref = integrate(net, heat, (0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-9,
                    atol=1e-8)
    stepper = TransientStepper(net, method="exprb43", rtol=1e-6, atol=1e-5)
    T, t = np.full(4, 308.15), 0.0
    for _ in range(8):
        out = stepper.advance(t, T, 60.0, heat)
        T, t = out.temperatures, out.time
    np.testing.assert_allclose(T, ref.temperatures[-1], atol=1e-4)
    assert out.audit.relative_imbalance() < 1e-10


def test_failed_step_reports_time_step_and_residual():
    def runaway(t, T):  # heat that explodes with temperature: no solution past a point
        return np.array([1e3 * math.exp(min((T[0] - 300.0) / 2.0, 700.0))])

    with pytest.raises(ConvergenceError) as info:
        integrate(rc(), runaway, (0.0, 1e5), T_AMB, method="exprb43", jacobian="fd",
                  min_step=1e-3)
    err = info.value
    assert "time" in err.state and "step_size" in err.state
    assert math.isfinite(err.state["time"])
    assert "residual" in str(err)


def test_nan_heat_never_returns_nan():
    with pytest.raises(ConvergenceError):
        integrate(rc(), lambda t, T: np.array([np.nan]), (0.0, 10.0), T_AMB,
                  method="exprb43", min_step=1e-3)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks())
def test_random_networks_conserve_energy_and_reach_steady(case):
    """The hypothesis property of test_network_property.py, with exprb43."""
    net, heat, t_end = case
    T_amb = net.boundary_temperature("amb")
    res = integrate(net, heat, (0.0, t_end), T_amb, method="exprb43")
    assert res.audit.relative_imbalance() < 1e-9
    assert np.all(np.isfinite(res.temperatures))
    steady = solve_steady(net, heat).temperatures_vector
    scale = max(1.0, float(np.max(steady - T_amb)))
    np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-8 * scale, rtol=0)


def test_defective_stream_chain_is_refused_with_advice():
    """Three equal nodes on an oil stream with no conduction: A is a Jordan block (one
    eigenvalue, one eigenvector); the eigenbasis is refused, the error says what to use."""
    net = ThermalNetwork()
    net.add_boundary("inlet", T_AMB)
    for k in range(3):
        net.add_node(f"o{k}", 100.0)
    net.add_stream(["inlet", "o0", "o1", "o2"], 50.0)
    with pytest.raises(ConvergenceError, match="tr_bdf2"):
        integrate(net, {"o0": 100.0}, (0.0, 60.0), T_AMB, method="exprb43")
    ok = integrate(net, {"o0": 100.0}, (0.0, 60.0), T_AMB, method="tr_bdf2")
    assert np.all(np.isfinite(ok.temperatures))


def test_temperature_dependent_conductances_are_not_lagged_silently():
    """Seven-node template (oil and air convection with temperature-dependent properties):
    the conductances' drift over a step is added to the heat at the stage values, so long
    steps stay accurate; the books still close to round-off."""
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.network import seven_node

    net = seven_node(load_bearing("QJ1044"), load_lubricant("ISO_VG68"),
                     housing_outer_diameter=0.5, housing_length=0.2)
    q = np.full(len(net.state_nodes), 100.0)
    ref = integrate(net, q, (0.0, 1800.0), 308.15, rtol=1e-9, atol=1e-9)
    res = integrate(net, q, (0.0, 1800.0), 308.15, method="exprb43", rtol=1e-6, atol=1e-5)
    assert np.max(np.abs(res.temperatures[-1] - ref.temperatures[-1])) < 2e-3  # 2.8e-4 K
    assert res.audit.relative_imbalance() < 1e-10


def test_wild_trial_stage_of_a_temperature_dependent_network_is_a_rejected_step():
    """A long first trial step puts exprb43's stage values far outside the physical range
    (here > 2000 K, where the air properties of free convection stop): that trial is
    rejected and retried shorter (``stepper_core.stage_drift``), not an InputError of the
    input as it was; the run reaches the hot steady state and its books close."""
    from thermobearing.network import solve_steady
    from thermobearing.network.conductances import NaturalConvectionCylinder

    net = ThermalNetwork("hot")
    net.add_boundary("amb", 300.0)
    net.add_node("n0", 1.0)
    net.add_node("n1", 5000.0)
    net.add_edge("n0", "n1", 0.2)
    net.add_edge("n0", "amb", NaturalConvectionCylinder(0.05, 0.05))
    heat = np.array([400.0, 1.0])
    res = integrate(net, heat, (0.0, 1e6), 300.0, method="exprb43", rtol=1e-9, atol=1e-9)
    assert res.stats["rejected"] + res.stats["newton_failures"] > 0
    assert res.audit.relative_imbalance() < 1e-12
    steady = solve_steady(net, heat).temperatures_vector
    np.testing.assert_allclose(res.temperatures[-1], steady, atol=1e-6)
