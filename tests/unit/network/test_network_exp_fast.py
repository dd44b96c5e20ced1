"""The compiled exprb43 path (network.exp_fast) against the general exprb43 path.

The general path (exponential.ExpRosenbrock43.step in the generic driver loop) is the
verified reference (test_network_exponential.py: exact RC/chain, observed order 4, audit);
here the compiled path must reproduce it, its cyclic Jacobi eigensolver must match LAPACK,
and its own features (heat_with_jacobian, rates at breakpoints from the step's own
solution, dense-output store growth, the non-symmetric fallback) are checked.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_network_steppers import T_AMB, chain, chain_exact  # same folder (prepend import)

from thermobearing.errors import ConvergenceError
from thermobearing.network import TransientStepper, assemble, integrate
from thermobearing.network.exp_fast import _jacobi_eigh
from thermobearing.network.problems import bearing_network, load_protocol, viscous_heat_for
from thermobearing.network.steppers import _Driver


@pytest.fixture
def general_path(monkeypatch):
    """Switch the compiled path off: integrate() then runs ExpRosenbrock43.step."""
    monkeypatch.setattr(_Driver, "_fast_applies", lambda self: False)


def _protocol(n_nodes=4, n_steps=6, duration=120.0):
    net = bearing_network(n_nodes)
    edges, P = load_protocol(n_steps, duration)
    return net, edges, viscous_heat_for(net, edges, P)


def _run(net, edges, heat, rtol, **kw):
    return integrate(net, heat, (0.0, edges[-1]), 308.15, method="exprb43", rtol=rtol,
                     atol=100 * rtol, breakpoints=edges, heat_jacobian=heat.jacobian,
                     heat_time_dependent=False, **kw)


@pytest.mark.parametrize("n", [1, 2, 4, 7, 12])
def test_jacobi_matches_lapack_eigh(n):
    """Random symmetric matrices, half of them graded (scaled by 1e-6..1e2 as the capacity
    scaling C^-1/2 does): S = Q diag(w) Q^T, Q orthogonal, eigenvalues equal to LAPACK's
    (numpy.linalg.eigvalsh) to ~1e-14 of the norm."""
    rng = np.random.default_rng(n)
    for k in range(40):
        B = rng.normal(size=(n, n))
        S = B + B.T
        if k % 2:
            d = np.sqrt(10.0 ** rng.uniform(-6, 2, n))
            S = S * d[:, None] * d[None, :]
        w, Q = _jacobi_eigh(S)
        scale = np.max(np.abs(S))
        assert np.max(np.abs(Q @ np.diag(w) @ Q.T - S)) < 1e-13 * scale
        assert np.max(np.abs(Q.T @ Q - np.eye(n))) < 1e-13
        np.testing.assert_allclose(np.sort(w), np.linalg.eigvalsh(S), rtol=0,
                                   atol=1e-13 * scale)


def test_jacobi_small_eigenvalue_of_the_stiff_network_to_high_relative_accuracy():
    """The slow thermal mode of the 4-node bearing network (eigenvalue ~1e-4 1/s beside a
    ~2 1/s oil mode): the Demmel-Veselic stopping rule gives it to ~1e-12 relative."""
    sys_ = assemble(bearing_network(4))
    rs = 1.0 / np.sqrt(sys_.C)
    S = -sys_.K * rs[:, None] * rs[None, :]
    w, _ = _jacobi_eigh(S)
    ref = np.linalg.eigvalsh(S)
    np.testing.assert_allclose(np.sort(w), ref, rtol=1e-12)
    assert abs(ref).min() < 1e-3 * abs(ref).max()  # really stiff


def test_compiled_path_matches_general_path_on_the_protocol(monkeypatch):
    """Nonlinear viscous heat, 6 load steps: both paths within the tolerance of a tight
    TR-BDF2 reference and of each other; the books close on both."""
    net, edges, heat = _protocol()
    ref = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-10,
                    atol=1e-9, heat_jacobian=heat.jacobian)
    grid = np.linspace(0.0, edges[-1], 73)
    fast = _run(net, edges, heat, 1e-5)
    assert fast.stats["steps"] >= len(edges) - 1
    monkeypatch.setattr(_Driver, "_fast_applies", lambda self: False)
    slow = _run(net, edges, heat, 1e-5)
    for res in (fast, slow):
        assert res.audit.relative_imbalance() < 1e-10
        assert np.max(np.abs(res.sample(grid) - ref.sample(grid))) < 1e-3
    assert np.max(np.abs(fast.sample(grid) - slow.sample(grid))) < 1e-3
    # same step sequence up to the rejection rule: the same accepted-step count here
    assert abs(fast.stats["steps"] - slow.stats["steps"]) <= 2


def test_linear_chain_exact_and_store_growth():
    """A linear network is integrated exactly; 100 steps (> the store's initial 64 rows)
    exercise the dense-store growth; dense output exact between the steps."""
    res = integrate(chain(), {"a": 100.0}, (0.0, 5000.0), T_AMB, method="exprb43",
                    max_step=50.0)
    assert res.stats["steps"] == 100
    assert np.max(np.abs(res.temperatures - chain_exact(res.times))) < 1e-9
    grid = np.linspace(0.0, 5000.0, 457)
    assert np.max(np.abs(res.sample(grid) - chain_exact(grid))) < 1e-9
    piece = res.dense[37]
    np.testing.assert_allclose(piece(np.array([piece.t0 + 0.3 * piece.h])),
                               chain_exact([piece.t0 + 0.3 * piece.h]), rtol=0, atol=1e-9)
    assert res.audit.relative_imbalance() < 1e-10


def test_rates_at_breakpoints_are_the_left_derivative():
    """At a breakpoint the recorded rate is dT/dt of the step's own solution (no extra heat
    call); on the linear chain that solution is exact, so it equals C^-1 (s - K T + q_left)
    with the heat of the segment that ends there."""
    def heat(t, T):
        return np.array([100.0 if t < 1000.0 else 20.0, 0.0])

    res = integrate(chain(), heat, (0.0, 2000.0), T_AMB, method="exprb43",
                    breakpoints=[1000.0], jacobian="none", heat_time_dependent=False)
    sys_ = assemble(chain())
    k = int(np.flatnonzero(res.times == 1000.0)[0])
    T = res.temperatures[k]
    left = (sys_.s - sys_.K @ T + np.array([100.0, 0.0])) / sys_.C
    np.testing.assert_allclose(res.rates[k], left, rtol=1e-9, atol=1e-12)
    k0 = 0  # the run's first point: f(T0)/C exactly
    np.testing.assert_allclose(res.rates[k0], (sys_.s - sys_.K @ res.temperatures[0]
                                               + np.array([100.0, 0.0])) / sys_.C)


def test_heat_with_jacobian_same_result_fewer_calls():
    """(q, dq/dT) from one call at the step starts: identical temperatures, one call per
    step start instead of two (counted on the callables themselves)."""
    net, edges, heat = _protocol()
    calls = {"q": 0, "j": 0, "qj": 0}

    def q(t, T):
        calls["q"] += 1
        return heat(t, T)

    def j(t, T):
        calls["j"] += 1
        return heat.jacobian(t, T)

    def qj(t, T):
        calls["qj"] += 1
        return heat.with_jacobian(t, T)

    a = integrate(net, q, (0.0, edges[-1]), 308.15, method="exprb43", rtol=1e-4,
                  atol=1e-2, breakpoints=edges, heat_jacobian=j, heat_time_dependent=False)
    n_separate = calls["q"] + calls["j"]
    calls.update(q=0, j=0, qj=0)
    b = integrate(net, q, (0.0, edges[-1]), 308.15, method="exprb43", rtol=1e-4,
                  atol=1e-2, breakpoints=edges, heat_with_jacobian=qj,
                  heat_time_dependent=False)
    np.testing.assert_allclose(a.temperatures, b.temperatures, rtol=0, atol=1e-12)
    assert calls["j"] == 0 and calls["qj"] == b.stats["jacobians"]
    assert calls["q"] + calls["qj"] == n_separate - b.stats["jacobians"]
    assert calls["q"] + calls["qj"] == b.stats["heat_evaluations"]


def test_heat_with_jacobian_alone_serves_the_other_steppers():
    """Only heat_with_jacobian given: TR-BDF2 takes its Jacobian part."""
    net, edges, heat = _protocol(n_steps=3)
    a = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-6,
                  heat_with_jacobian=heat.with_jacobian)
    b = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-6,
                  heat_jacobian=heat.jacobian)
    np.testing.assert_allclose(a.temperatures, b.temperatures, rtol=0, atol=1e-12)


def test_non_symmetric_network_general_eigenbasis(monkeypatch):
    """20 nodes with the oil stream through a chain of oil nodes (upwind: K not symmetric):
    the compiled path uses the general eigendecomposition; it matches the general path."""
    net, edges, heat = _protocol(n_nodes=20, n_steps=3)
    K = assemble(net).K
    assert not np.array_equal(K, K.T)
    grid = np.linspace(0.0, edges[-1], 37)
    fast = _run(net, edges, heat, 1e-6, heat_with_jacobian=heat.with_jacobian)
    monkeypatch.setattr(_Driver, "_fast_applies", lambda self: False)
    slow = _run(net, edges, heat, 1e-6)
    assert np.max(np.abs(fast.sample(grid) - slow.sample(grid))) < 1e-4
    assert fast.audit.relative_imbalance() < 1e-10


def test_stepwise_api_with_heat_with_jacobian():
    net, edges, heat = _protocol(n_steps=4)
    ref = integrate(net, heat, (0.0, edges[-1]), 308.15, breakpoints=edges, rtol=1e-9,
                    atol=1e-8, heat_jacobian=heat.jacobian)
    stepper = TransientStepper(net, method="exprb43", rtol=1e-6, atol=1e-5)
    T, t = np.full(4, 308.15), 0.0
    for _ in range(len(edges) - 1):
        out = stepper.advance(t, T, edges[1] - edges[0], heat,
                              heat_with_jacobian=heat.with_jacobian,
                              heat_time_dependent=False)
        T, t = out.temperatures, out.time
        assert out.audit.relative_imbalance() < 1e-10
    np.testing.assert_allclose(T, ref.temperatures[-1], atol=1e-4)


def test_non_finite_heat_or_jacobian_is_reported(general_path):
    """(general path here; the compiled path below) a NaN heat raises ConvergenceError."""
    with pytest.raises(ConvergenceError):
        integrate(chain(), lambda t, T: np.array([np.nan, 0.0]), (0.0, 10.0), T_AMB,
                  method="exprb43", min_step=1e-3)


@pytest.mark.parametrize("bad", ["heat", "jacobian"])
def test_non_finite_values_on_the_compiled_path(bad):
    def qj(t, T):
        q = np.array([50.0, 0.0])
        jq = np.array([-0.1, 0.0])
        if t > 100.0:
            (q if bad == "heat" else jq)[0] = math.nan
        return q, jq

    with pytest.raises(ConvergenceError, match="non-finite") as info:
        integrate(chain(), lambda t, T: qj(t, T)[0], (0.0, 1000.0), T_AMB, method="exprb43",
                  heat_with_jacobian=qj, breakpoints=[200.0], heat_time_dependent=False)
    # the failing step starts where the source turns NaN (t = 100 s), or just before it
    # when a stage of a shrinking step crosses it
    assert 99.0 <= info.value.state["time"] <= 200.0


def test_complex_spectrum_on_a_symmetric_network_switches_the_store():
    """Symmetric K (chain) but a full, skew heat Jacobian dq/dT = [[0, 20], [-20, 0]] W/K
    (a linear source q = B (T - T_amb) + b): A = C^-1 (-K + B) has complex eigenvalues, so
    the compiled path leaves the Jacobi branch, and the run's real dense store turns complex.
    The source is linear, so the method is exact: compare with expm of the linear system."""
    from scipy.linalg import expm

    B = np.array([[0.0, 20.0], [-20.0, 0.0]])
    b = np.array([50.0, 0.0])

    def heat(t, T):
        return B @ (T - T_AMB) + b

    res = integrate(chain(), heat, (0.0, 3000.0), T_AMB, method="exprb43",
                    heat_jacobian=lambda t, T: B, max_step=400.0)
    sys_ = assemble(chain())
    J = -sys_.K + B
    assert np.iscomplexobj(np.linalg.eigvals(J / sys_.C[:, None]))
    assert np.iscomplexobj(res.dense[0].store.lam)
    rhs = sys_.s + b - B @ np.full(2, T_AMB)
    Tss = np.linalg.solve(-J, rhs)
    A = J / sys_.C[:, None]

    def exact(t):
        return np.array([Tss + expm(A * ti) @ (np.full(2, T_AMB) - Tss) for ti in t])

    assert np.max(np.abs(res.temperatures - exact(res.times))) < 1e-9
    grid = np.linspace(0.0, 3000.0, 61)
    assert np.max(np.abs(res.sample(grid) - exact(grid))) < 1e-9
    assert res.audit.relative_imbalance() < 1e-10


def test_network_edited_during_the_run_hands_over_to_the_driver(monkeypatch):
    """A heat function that changes the oil flow when first called at t >= 300 s (a
    what-if inside the run; that call is the restart at the 300-s breakpoint, so the edit
    takes effect from the next breakpoint, 450 s, as in the generic driver, which checks
    the network at each restart): the compiled multi-segment loop hands the remaining
    segments to the generic driver; the result equals the general path and two runs."""
    edges, P = load_protocol(4, 150.0)

    def run(general: bool):
        net = bearing_network(4)
        heat = viscous_heat_for(net, edges, P)

        def editing(t, T):
            if t >= 300.0 and net.streams["oil"].capacity_rate != 400.0:
                net.set_stream_flow("oil", 400.0)
            return heat(t, T)

        with monkeypatch.context() as m:
            if general:
                m.setattr(_Driver, "_fast_applies", lambda self: False)
            return integrate(net, editing, (0.0, edges[-1]), 308.15, method="exprb43",
                             breakpoints=edges, rtol=1e-6, atol=1e-5,
                             heat_jacobian=heat.jacobian, heat_time_dependent=False)

    a, g = run(False), run(True)
    net_b = bearing_network(4)
    heat = viscous_heat_for(net_b, edges, P)
    kw = dict(method="exprb43", breakpoints=edges, rtol=1e-6, atol=1e-5,
              heat_jacobian=heat.jacobian, heat_time_dependent=False)
    b1 = integrate(net_b, heat, (0.0, 450.0), 308.15, **kw)
    net_b.set_stream_flow("oil", 400.0)
    b2 = integrate(net_b, heat, (450.0, edges[-1]), b1.temperatures[-1], **kw)
    np.testing.assert_allclose(a.temperatures[-1], g.temperatures[-1], atol=1e-4)
    np.testing.assert_allclose(a.temperatures[-1], b2.temperatures[-1], atol=1e-4)


def test_temperature_dependent_network_runs_compiled_and_matches_general_path(monkeypatch):
    """Seven-node template (oil and air convection with temperature-dependent properties):
    the compiled path runs it (K(T) assembled at each step start, the conductances'
    derivatives added to dq/dT and their drift to the heat at the stage values, as the
    general path does); both paths agree
    with a tight reference within their tolerance, with each other, at sampled
    (dense-output) times too, and the books close."""
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.network import exp_fast, seven_node

    net = seven_node(load_bearing("QJ1044"), load_lubricant("ISO_VG68"),
                     housing_outer_diameter=0.5, housing_length=0.2)
    n = len(net.state_nodes)
    edges = [0.0, 600.0, 1200.0, 1800.0]
    level = [60.0, 250.0, 120.0]

    def heat(t, T):
        k = min(int(np.searchsorted(edges, t, side="right")) - 1, 2)
        return np.full(n, level[k]) * (1.0 + 2e-3 * (T - 308.15))

    def jac(t, T):
        k = min(int(np.searchsorted(edges, t, side="right")) - 1, 2)
        return np.full(n, level[k] * 2e-3)

    kw = dict(breakpoints=edges, heat_jacobian=jac, heat_time_dependent=False)
    ref = integrate(net, heat, (0.0, 1800.0), 308.15, rtol=1e-10, atol=1e-9, **kw)
    seen = []
    orig = exp_fast.run_segments
    monkeypatch.setattr(exp_fast, "run_segments",
                        lambda *a, **k: seen.append(1) or orig(*a, **k))
    fast = integrate(net, heat, (0.0, 1800.0), 308.15, method="exprb43", rtol=1e-6,
                     atol=1e-5, **kw)
    assert seen, "the compiled path did not run the temperature-dependent network"
    monkeypatch.setattr(_Driver, "_fast_applies", lambda self: False)
    slow = integrate(net, heat, (0.0, 1800.0), 308.15, method="exprb43", rtol=1e-6,
                     atol=1e-5, **kw)
    grid = np.linspace(0.0, 1800.0, 61)
    for res in (fast, slow):
        assert res.audit.relative_imbalance() < 1e-10
        assert np.max(np.abs(res.sample(grid) - ref.sample(grid))) < 2e-3
    assert np.max(np.abs(fast.sample(grid) - slow.sample(grid))) < 2e-3
    # without the drift the compiled path's long steps were 200x less accurate (8e-4 K
    # instead of 4e-6 K on the default scene): the error is bounded like the general path's
    e_fast = np.max(np.abs(fast.temperatures[-1] - ref.temperatures[-1]))
    e_slow = np.max(np.abs(slow.temperatures[-1] - ref.temperatures[-1]))
    print(f"compiled {e_fast:.2e} K, general {e_slow:.2e} K, steps "
          f"{fast.stats['steps']} / {slow.stats['steps']}")
    assert e_fast < 3.0 * e_slow + 1e-5
