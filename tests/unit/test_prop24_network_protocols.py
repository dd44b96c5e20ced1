"""Property tests, round 6: the network steppers under heat protocols (session 24), beside
the constant-heat books of test_prop21_network.py, the orders of
test_prop23_network_steppers.py (sinusoidal heat) and network/test_network_property.py.

A random linear network (a tree of conductances, one edge to the ambient, an oil stream
through some nodes, every boundary at one temperature T_b) is driven by a protocol

    q(t) = P_k + r t + c sin(w t),   t in [t_k, t_k+1)  (P_k piecewise constant, breakpoints t_k)

(a machine switched between load steps, warming up, with a periodic duty). Invariants, for
every stepper of :data:`thermobearing.network.STEPPERS` (``backward_euler``,
``crank_nicolson``, ``explicit_euler``, ``exprb43``, ``tr_bdf2``):

- books: each run's audit closes, generated = stored + to_boundaries + to_streams, to
  round-off (the network is linear), for adaptive and fixed steps;
- the audit's heat is the protocol's: ``generated`` equals the exact integral of sum q(t)
  to round-off when q is piecewise constant between the breakpoints (every step ends at a
  breakpoint); with a ramp and a sine it converges at the stepper's order
  (test_prop24_network_orders.py);
- linearity (superposition): with fixed steps every stepper is a linear map of the start
  rise and the heat, so T[T0, q1 + q2] - T_b = (T[T0, q1] - T_b) + (T[T_b, q2] - T_b) and
  T[T_b, lambda q] - T_b = lambda (T[T_b, q] - T_b) to round-off;
- time invariance: the network does not know the clock, so a protocol shifted by s and run
  from s gives the unshifted run's temperatures, step for step (fixed steps) and within the
  tolerance (adaptive steps);
- positivity and comparison (M-matrix: exp(-C^-1 K t) >= 0, (C + h K)^-1 >= 0, and
  I - h C^-1 K >= 0 for h <= min C_i / K_ii): from T_b under a non-negative protocol no
  node falls below T_b for backward Euler (any step), exprb43 (exact on constant heat) and
  explicit Euler at h <= min C_i / K_ii; a protocol that is everywhere larger gives every
  node a temperature at least as large.

The runs span half the slowest time constant (enough to cross every breakpoint and several
periods of the sine, and cheap for explicit Euler's small stable step). The tolerances are
round-off (books 1e-10 of the flows, temperatures 1e-9 of the rise): measured over 60
networks, every stepper, fixed and adaptive steps, 6.7e-12 for the books and 2.0e-11 of the
rise for the superposition (with the ``jump`` row a run records when it re-initialises its
zero-capacity nodes at the start left out of the step-by-step comparisons).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.network import ThermalNetwork, assemble, integrate

T_B = 300.0
_ALL = ("backward_euler", "crank_nicolson", "explicit_euler", "exprb43", "tr_bdf2")


@st.composite
def networks(draw, massless: bool = True, min_capacity: float = 10.0):
    """A tree of 2..5 nodes (``min_capacity``..1000 J/K; some zero off the first node when
    ``massless``), 1..10 W/K edges, one edge to the ambient, an oil stream (0..10 W/K)
    through 1..n nodes; every boundary at T_B."""
    n = draw(st.integers(2, 5))
    net = ThermalNetwork("protocol")
    net.add_boundary("amb", T_B)
    net.add_boundary("oil_in", T_B)
    for i in range(n):
        zero = massless and i > 0 and draw(st.booleans())
        net.add_node(f"n{i}", 0.0 if zero else draw(st.floats(min_capacity, 1000.0)))
    for i in range(1, n):
        net.add_edge(f"n{i}", f"n{draw(st.integers(0, i - 1))}", draw(st.floats(1.0, 10.0)))
    net.add_edge(f"n{draw(st.integers(0, n - 1))}", "amb", draw(st.floats(1.0, 10.0)))
    order = draw(st.permutations(list(range(n))))
    path = [f"n{i}" for i in order[:draw(st.integers(1, n))]]
    net.add_stream(["oil_in", *path], draw(st.floats(0.0, 10.0)))
    return net


class Protocol:
    """q(t) = P_k + r t + c sin(w t) [W per state node]; P_k on [t_k, t_k+1), k = 0 before
    the first breakpoint. ``shift`` s: the protocol q(t - s)."""

    def __init__(self, cuts, levels, ramp, amp, w, shift: float = 0.0) -> None:
        self.cuts = np.asarray(cuts, dtype=float)
        self.levels = np.asarray(levels, dtype=float)
        self.ramp = np.asarray(ramp, dtype=float)
        self.amp = np.asarray(amp, dtype=float)
        self.w = float(w)
        self.shift = float(shift)
        # the jump times on the clock, the floats integrate() is given: the piece is chosen
        # on them, so that the left limit the stepper asks for (just below a breakpoint) is
        # the left piece (t - s below c need not hold in floating point when t < c + s)
        self.jumps = self.cuts + self.shift

    @property
    def breakpoints(self) -> list[float]:
        return [float(c) for c in self.jumps]

    def shifted(self, s: float) -> Protocol:
        return Protocol(self.cuts, self.levels, self.ramp, self.amp, self.w, self.shift + s)

    def scaled(self, lam: float) -> Protocol:
        return Protocol(self.cuts, lam * self.levels, lam * self.ramp, lam * self.amp, self.w,
                        self.shift)

    def __call__(self, t: float, T=None) -> np.ndarray:
        u = t - self.shift
        # a step that ends on a breakpoint evaluates its end just left of it (core.t_end_left)
        k = int(np.searchsorted(self.jumps, t, side="right"))
        return self.levels[k] + self.ramp * u + self.amp * math.sin(self.w * u)

    def integral(self, t0: float, t1: float) -> float:
        """Exact integral of sum_i q_i over [t0, t1] [J]."""
        u0, u1 = t0 - self.shift, t1 - self.shift
        edges = [u0, *[float(c) for c in self.cuts if u0 < c < u1], u1]
        total = 0.0
        for a, b in zip(edges[:-1], edges[1:], strict=True):
            k = int(np.searchsorted(self.cuts, 0.5 * (a + b), side="right"))
            total += float(np.sum(self.levels[k])) * (b - a)
        total += float(np.sum(self.ramp)) * 0.5 * (u1 * u1 - u0 * u0)
        if self.w > 0.0:
            total += float(np.sum(self.amp)) * (math.cos(self.w * u0) - math.cos(self.w * u1)) \
                / self.w
        return total


def _plus(p: Protocol, q: Protocol) -> Protocol:
    """The sum of two protocols with the same breakpoints and frequency."""
    return Protocol(p.cuts, p.levels + q.levels, p.ramp + q.ramp, p.amp + q.amp, p.w, p.shift)


@st.composite
def protocols(draw, n: int, t_end: float, smooth: bool = True, pieces: int | None = None):
    """1..4 pieces of 0..200 W per node (1 W more on one node), and when ``smooth`` a ramp
    of 0..200 W over the run (4 W more on one node) and a sine of 0..100 W (10 W more on one
    node) of 0.5..10 periods over the run; non-negative throughout."""
    k = pieces if pieces is not None else draw(st.integers(1, 4))
    fr = sorted(draw(st.lists(st.floats(0.05, 0.95), min_size=k - 1, max_size=k - 1,
                              unique=True)))
    cuts = [t_end * f for f in fr]
    levels = np.array(draw(st.lists(st.lists(st.floats(0.0, 200.0), min_size=n, max_size=n),
                                    min_size=k, max_size=k)))
    levels[0, draw(st.integers(0, n - 1))] += 1.0
    vec = st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n)
    if smooth:
        ramp = 0.2 * np.array(draw(vec)) * (200.0 / t_end)
        amp = 100.0 * np.array(draw(vec))
        ramp[draw(st.integers(0, n - 1))] += 0.02 * (200.0 / t_end)   # a smooth part somewhere
        amp[draw(st.integers(0, n - 1))] += 10.0
        w = 2.0 * math.pi * draw(st.floats(0.5, 10.0)) / t_end
    else:
        ramp = amp = np.zeros(n)
        w = 0.0
    return Protocol(cuts, levels, ramp, amp, w)


def _system(net: ThermalNetwork):
    sys_ = assemble(net)
    K = sys_.K.toarray() if hasattr(sys_.K, "toarray") else np.asarray(sys_.K)
    return np.asarray(sys_.C, dtype=float), K


def _time_scale(net: ThermalNetwork) -> float:
    """The slowest time constant of the network [s]: the largest eigenvalue of K^-1 C (the
    slowest mode's 1 / lambda of C dT/dt = -K T)."""
    C, K = _system(net)
    lam = np.linalg.eigvals(np.linalg.solve(K, np.diag(C)))
    return float(np.max(np.abs(lam)))


def _stable_explicit_step(net: ThermalNetwork) -> float:
    """min C_i / K_ii [s]: explicit Euler keeps I - h C^-1 K non-negative up to it."""
    C, K = _system(net)
    return float(np.min(C / np.diag(K)))


def _run(net, q, t_span, method, T0=T_B, **kw):
    return integrate(net, q, t_span, T0, method=method, breakpoints=q.breakpoints,
                     jacobian="none", **kw)


def _by_step(res) -> np.ndarray:
    """The temperatures at the step times: a run whose zero-capacity nodes are re-initialised
    at the start records the start twice (before and after); the state after counts."""
    keep = np.append(np.diff(res.times) > 0.0, True)
    return res.temperatures[keep]


def _fixed_steps(net: ThermalNetwork, t_end: float) -> dict[str, float]:
    """A fixed step per stepper: t_end / 200, explicit Euler at half its positivity step."""
    h = t_end / 200.0
    return {m: (min(h, 0.5 * _stable_explicit_step(net)) if m == "explicit_euler" else h)
            for m in _ALL}


def _methods(net: ThermalNetwork):
    """The steppers that take this network (explicit Euler: no zero-capacity node)."""
    C, _ = _system(net)
    return [m for m in _ALL if m != "explicit_euler" or np.all(C > 0.0)]


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.data())
def test_books_close_and_the_audit_takes_the_protocols_heat(net, data):
    """Every stepper's books close to round-off under a piecewise-constant protocol with a
    ramp and a sine, and its ``generated`` is the exact integral of the heat when the
    protocol is piecewise constant (fixed and adaptive steps)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    steps = _fixed_steps(net, t_end)
    for smooth in (True, False):
        q = data.draw(protocols(n, t_end, smooth=smooth), label=f"protocol smooth={smooth}")
        exact = q.integral(0.0, t_end)
        for method in _methods(net):
            runs = [{"dt": steps[method]}]
            if method in ("backward_euler", "exprb43", "tr_bdf2"):
                runs.append({"rtol": 1e-6, "atol": 1e-6})
            for kw in runs:
                res = _run(net, q, (0.0, t_end), method, **kw)
                assert np.all(np.isfinite(res.temperatures)), (method, kw)
                assert res.audit.relative_imbalance() < 1e-10, (method, kw)
                C, _ = _system(net)
                stored = float(np.dot(C, res.temperatures[-1] - res.temperatures[0]))
                tot = res.audit.totals()
                assert abs(tot["stored"] - stored) <= 1e-10 * max(1.0, abs(exact)), (method, kw)
                if not smooth:
                    assert tot["generated"] == pytest.approx(exact, rel=1e-10), (method, kw)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.data(), st.floats(-3.0, 3.0))
def test_every_fixed_step_stepper_is_linear(net, data, lam):
    """Superposition of the start rise and the heat, and homogeneity in the heat, to
    round-off (2e-11 of the rise measured; asserted 1e-9)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q1 = data.draw(protocols(n, t_end), label="q1")
    q2 = data.draw(protocols(n, t_end, pieces=len(q1.levels)), label="q2")
    q2 = Protocol(q1.cuts, q2.levels, q2.ramp, q2.amp, q1.w)
    rise0 = np.array(data.draw(st.lists(st.floats(-20.0, 50.0), min_size=n, max_size=n),
                               label="start rise"))
    steps = _fixed_steps(net, t_end)
    for method in _methods(net):
        dt = steps[method]
        both = _by_step(_run(net, _plus(q1, q2), (0.0, t_end), method, T0=T_B + rise0, dt=dt))
        one = _by_step(_run(net, q1, (0.0, t_end), method, T0=T_B + rise0, dt=dt))
        two = _by_step(_run(net, q2, (0.0, t_end), method, dt=dt))
        scaled = _by_step(_run(net, q2.scaled(lam), (0.0, t_end), method, dt=dt))
        assert both.shape == one.shape == two.shape == scaled.shape, method
        span = max(1.0, float(np.max(np.abs(both - T_B))), float(np.max(np.abs(scaled - T_B))))
        np.testing.assert_allclose(both - T_B, (one - T_B) + (two - T_B), rtol=0,
                                   atol=1e-9 * span, err_msg=method)
        np.testing.assert_allclose(scaled - T_B, lam * (two - T_B), rtol=0, atol=1e-9 * span,
                                   err_msg=method)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.data(), st.floats(1.0, 1e5))
def test_a_shifted_protocol_gives_the_same_temperatures(net, data, shift):
    """q(t - s) from t = s: the same temperatures at the same step (fixed steps, to 1e-9 of
    the rise; the step times differ by the round-off of s + t) and at the end (adaptive,
    within 20 x the tolerance: 1e-7, backward Euler 1e-5)."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(protocols(n, t_end))
    moved = q.shifted(shift)
    steps = _fixed_steps(net, t_end)
    for method in _methods(net):
        kws = [{"dt": steps[method]}]
        if method in ("backward_euler", "exprb43", "tr_bdf2"):
            tol = 1e-5 if method == "backward_euler" else 1e-7   # first order: many steps
            kws.append({"rtol": tol, "atol": tol})
        for kw in kws:
            ref = _run(net, q, (0.0, t_end), method, **kw)
            got = _run(net, moved, (shift, shift + t_end), method, **kw)
            span = max(1.0, float(np.max(np.abs(ref.temperatures - T_B))))
            if "dt" in kw:
                assert len(got.times) == len(ref.times), method
                np.testing.assert_allclose(got.times - shift, ref.times, rtol=0,
                                           atol=1e-12 * (shift + t_end))
                np.testing.assert_allclose(got.temperatures, ref.temperatures, rtol=0,
                                           atol=1e-9 * span, err_msg=method)
            else:
                np.testing.assert_allclose(got.temperatures[-1], ref.temperatures[-1], rtol=0,
                                           atol=20 * kw["rtol"] * max(span, T_B),
                                           err_msg=method)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.data())
def test_positive_heat_raises_and_more_heat_raises_more(net, data):
    """From T_b under a non-negative piecewise-constant protocol no node falls below T_b, and
    an everywhere larger protocol gives no node a lower temperature: backward Euler (fixed
    and adaptive), exprb43 (fixed) and explicit Euler at h <= min C_i / K_ii."""
    t_end = 0.5 * _time_scale(net)
    n = len(net.state_nodes)
    q = data.draw(protocols(n, t_end, smooth=False), label="q")
    extra = data.draw(protocols(n, t_end, smooth=False, pieces=len(q.levels)), label="extra")
    more = Protocol(q.cuts, q.levels + extra.levels, q.ramp, q.amp, q.w)
    steps = _fixed_steps(net, t_end)
    runs = [("backward_euler", {"dt": steps["backward_euler"]}),
            ("backward_euler", {"rtol": 1e-5, "atol": 1e-5}),
            ("exprb43", {"dt": steps["exprb43"]})]
    if "explicit_euler" in _methods(net):
        runs.append(("explicit_euler", {"dt": steps["explicit_euler"]}))
    for method, kw in runs:
        low = _by_step(_run(net, q, (0.0, t_end), method, **kw))
        span = max(1.0, float(np.max(low - T_B)))
        assert float(np.min(low)) >= T_B - 1e-9 * span, (method, kw)
        if "dt" in kw:   # the same steps: compare sample by sample
            high = _by_step(_run(net, more, (0.0, t_end), method, **kw))
            assert float(np.min(high - low)) >= -1e-9 * span, (method, kw)
