"""Property tests, round 6: orders and nonlinear books of the network steppers under heat
protocols (session 24); the networks, protocols and helpers of
test_prop24_network_protocols.py (its docstring: the linear books, superposition, time
invariance and positivity).

- the audit's quadrature: with a ramp and a sine in the heat, |generated - int sum q dt|
  falls as h^p when the fixed step is halved, p the stepper's order (backward Euler and
  explicit Euler 1, Crank-Nicolson and TR-BDF2 2 (Bank et al. 1985), exprb43 4 (Hochbruck &
  Ostermann 2010): the audit integrates the heat with the weights of the stepper's own
  stages, audit.py), measured between the two finest steps above round-off within
  p - 0.3 .. p + 0.6;
- explicit Euler (Hairer & Wanner 1996, sec. IV.2; first order) converges at order 1
  (within 0.7 .. 1.6) on a capacitive network from its positivity step min C_i / K_ii down;
  test_prop23_network_steppers.py has the other four steppers' orders;
- a heat falling with temperature, q = q0 exp(-beta (T - T_b)) (a viscous loss as the oil
  thins): TR-BDF2, backward Euler and exprb43 close their books to the Newton tolerance
  (1e-6 relative) and settle at :func:`solve_steady`'s state of the same heat.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.unit.test_prop24_network_protocols import (
    _ALL,
    T_B,
    _run,
    _stable_explicit_step,
    _time_scale,
    networks,
    protocols,
)
from thermobearing.network import integrate, solve_steady

_ORDER = {"backward_euler": 1, "explicit_euler": 1, "crank_nicolson": 2, "tr_bdf2": 2,
          "exprb43": 4}


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(massless=False), st.data())
def test_the_audits_heat_converges_at_the_steppers_order(net, data):
    """With a ramp and a sine, |generated - int q dt| falls by 2^p when the fixed step is
    halved (p - 0.3 .. p + 0.6 between the two finest steps above round-off; p = 4 for
    exprb43, whose stages sample the heat at its order-4 nodes)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(protocols(n, t_end, pieces=1))
    exact = q.integral(0.0, t_end)
    h_ee = 0.5 * _stable_explicit_step(net)
    for method in _ALL:
        # 25 steps a period of the sine at least: the asymptotic range (at 6 steps a period
        # the right-point rule's error rose from h to h/2: 0.023 J, 0.169 J, 0.123 J)
        # (exprb43, fourth order, from 64 steps: at 256 it is at round-off)
        k0 = {"exprb43": 64, "explicit_euler": max(256, math.ceil(t_end / h_ee))}.get(method, 256)
        err = []
        for k in (k0, 2 * k0, 4 * k0):
            res = _run(net, q, (0.0, t_end), method, dt=t_end / k)
            err.append(abs(res.audit.totals()["generated"] - exact))
        p = _ORDER[method]
        usable = [i for i in range(2) if err[i + 1] > 1e-12 * exact]   # above round-off
        if not usable:   # round-off at every step: nothing left to converge
            assert max(err) <= 1e-10 * exact, (method, err)
            continue
        i = usable[-1]
        ratio = math.log2(err[i] / err[i + 1])
        assert p - 0.3 < ratio < p + 0.6, (method, err, ratio)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(massless=False), st.data())
def test_explicit_euler_converges_at_first_order(net, data):
    """Explicit Euler's error at t_end against exprb43 at a fine step (exact to round-off on
    the linear part; its quadrature of the sine is of order 4) falls as h^1 from the
    positivity step h0 = min C_i / K_ii down to h0 / 4 (ratio 0.7 .. 1.6)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(protocols(n, t_end, pieces=1))
    ref = _run(net, q, (0.0, t_end), "exprb43", dt=t_end / 1024).temperatures[-1]
    h0 = _stable_explicit_step(net)
    k0 = math.ceil(t_end / h0)
    err = [float(np.max(np.abs(_run(net, q, (0.0, t_end), "explicit_euler",
                                    dt=t_end / k).temperatures[-1] - ref)))
           for k in (k0, 2 * k0, 4 * k0)]
    span = max(1.0, float(np.max(np.abs(ref - T_B))))
    if err[2] < 1e-9 * span:
        return   # already at round-off (a tiny rise)
    ratio = math.log2(err[1] / err[2])
    assert 0.7 < ratio < 1.6, (err, ratio)


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.data(), st.floats(0.001, 0.05))
def test_heat_falling_with_temperature_closes_the_books_and_settles(net, data, beta):
    """q = q0 exp(-beta (T - T_b)): TR-BDF2, backward Euler and exprb43 close their books to
    the Newton tolerance (1e-6 relative) and end, after 30 time constants, at the steady
    state of the same heat (1e-5 of the rise)."""
    n = len(net.state_nodes)
    q0 = np.array(data.draw(st.lists(st.floats(0.0, 500.0), min_size=n, max_size=n)))
    q0[data.draw(st.integers(0, n - 1))] += 10.0

    def heat(t, T):
        return q0 * np.exp(-beta * (np.asarray(T) - T_B))

    def dheat(t, T):
        return -beta * heat(t, T)

    t_end = 30.0 * _time_scale(net)
    steady = solve_steady(net, heat, heat_jacobian=dheat).temperatures_vector
    span = max(1.0, float(np.max(steady - T_B)))
    assert np.all(steady >= T_B - 1e-9 * span)
    for method in ("tr_bdf2", "backward_euler", "exprb43"):
        res = integrate(net, heat, (0.0, t_end), T_B, method=method, rtol=1e-8, atol=1e-8,
                        heat_jacobian=dheat, heat_time_dependent=False)
        assert res.audit.relative_imbalance() < 1e-6, method
        np.testing.assert_allclose(res.temperatures[-1], steady, rtol=0, atol=1e-5 * span,
                                   err_msg=method)
