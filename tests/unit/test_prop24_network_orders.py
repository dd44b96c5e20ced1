"""Property tests, round 6: orders and nonlinear books of the network steppers under heat
protocols (session 24); the networks, protocols and helpers of
test_prop24_network_protocols.py (its docstring: the linear books, superposition, time
invariance and positivity).

- the audit's quadrature: with a ramp and a sine in the heat, |generated - int sum q dt|
  falls as h^p when the fixed step is halved, p the stepper's order (backward Euler and
  explicit Euler 1, Crank-Nicolson and TR-BDF2 2 (Bank et al. 1985), exprb43 4 (Hochbruck &
  Ostermann 2010): the audit integrates the heat with the weights of the stepper's own
  stages, audit.py), measured between the two finest steps above round-off within
  p - 0.3 .. p + 0.6, on heat protocols whose leading error term cannot vanish
  (:func:`order_protocols`; a sine ending where its endpoint differences cancel the ramp's
  gave errors 1.28e-3, 1.43e-3, 9.1e-4 J for backward Euler at 256, 512, 1024 steps);
- explicit Euler (Hairer & Wanner 1996, sec. IV.2; first order) converges at order 1
  (0.7 .. 1.3) on a capacitive network in its asymptotic range (h |lambda| <= 0.25), its
  error the largest over the run; test_prop23_network_steppers.py has the other four
  steppers' orders;
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
    Protocol,
    _run,
    _stable_explicit_step,
    _time_scale,
    networks,
)
from thermobearing.network import integrate, solve_steady

_ORDER = {"backward_euler": 1, "explicit_euler": 1, "crank_nicolson": 2, "tr_bdf2": 2,
          "exprb43": 4}


@st.composite
def order_protocols(draw, n: int, t_end: float):
    """q = P + r t + c sin(w t), one piece, whose quadrature error has a leading term away
    from zero. A composite rule of order p with a fixed step errs by
    c_p h^p (q^(p-1)(T) - q^(p-1)(0)) + O(h^(p+1)) (Euler-Maclaurin), so the endpoint
    differences must not vanish: sum q(T) - q(0) = R T + sum c sin(w T) >= sum c + 4 W
    (p = 1: a ramp R T >= 2 sum c + 4 W), and |cos(w T) - 1| >= 1.3 (p = 2 and 4: 0.3..0.7
    of a period beyond 0..2 whole ones). A sine of 0.3..2.7 periods at 64 or more steps
    is in the asymptotic range (h w <= 0.27)."""
    amp = 100.0 * np.array(draw(st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n)))
    amp[draw(st.integers(0, n - 1))] += 10.0
    weights = np.array(draw(st.lists(st.floats(0.1, 1.0), min_size=n, max_size=n)))
    ramp = weights / weights.sum() * (2.0 * amp.sum() + 4.0) / t_end
    periods = draw(st.integers(0, 2)) + draw(st.floats(0.3, 0.7))
    levels = np.array([draw(st.lists(st.floats(0.0, 200.0), min_size=n, max_size=n))])
    return Protocol([], levels, ramp, amp, 2.0 * math.pi * periods / t_end)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(massless=False), st.data())
def test_the_audits_heat_converges_at_the_steppers_order(net, data):
    """With a ramp and a sine, |generated - int q dt| falls by 2^p when the fixed step is
    halved (p - 0.3 .. p + 0.6 between the two finest steps above round-off; p = 4 for
    exprb43, whose stages sample the heat at its order-4 nodes; :func:`order_protocols`)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(order_protocols(n, t_end))
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


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(massless=False, min_capacity=100.0), st.data())
def test_explicit_euler_converges_at_first_order(net, data):
    """Explicit Euler's global error, the largest over the coarsest run's step times, against
    exprb43 on those steps (fourth order; its error there is below 1e-4 of explicit Euler's)
    falls as h^1 from a quarter of the positivity step h0 = min C_i / K_ii to h0 / 16
    (h |lambda| <= 0.25: the asymptotic range; at h0 the ratio was 2.2, pre-asymptotic),
    0.7 .. 1.3. The largest error over the run (test_prop23_network_steppers.py): the error
    at one time alone can vanish by chance."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(order_protocols(n, t_end))
    k0 = 4 * math.ceil(t_end / _stable_explicit_step(net))
    ref = _run(net, q, (0.0, t_end), "exprb43", dt=t_end / k0).temperatures[-k0:]
    err = []
    for m in (1, 2, 4):
        got = _run(net, q, (0.0, t_end), "explicit_euler", dt=t_end / (m * k0)).temperatures
        err.append(float(np.max(np.abs(got[-m * k0:][m - 1::m] - ref))))
    span = max(1.0, float(np.max(np.abs(ref - T_B))))
    assert err[2] > 1e-9 * span, err   # resolvable above round-off
    ratio = math.log2(err[1] / err[2])
    assert 0.7 < ratio < 1.3, (err, ratio)


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
