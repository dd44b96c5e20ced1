"""Implicit time steppers and the steady Newton solve of the thermal network.

Problem: ``C dT/dt = f(t, T) = -K T + s + q(t, T)`` (see :mod:`.assemble`), ``C_i = 0``
allowed (algebraic nodes: a semi-explicit index-1 DAE).

Steppers (registry ``stepper``)
-------------------------------
- ``tr_bdf2`` (default): TR-BDF2 of Bank et al. (1985) with gamma = 2 - sqrt(2), in the
  form and with the embedded third-order error estimate of Hosea & Shampine (1996). One
  iteration matrix ``C - d h J`` (d = gamma/2) serves both stages; L-stable, second order,
  stiffly accurate. Adaptive step size (or fixed ``dt``).
- ``backward_euler``: first order, L-stable; adaptive (error ~ h/2 (f1 - f0)) or fixed.
- ``exprb43`` (module :mod:`.exponential`): exponential Rosenbrock method of order 4
  (Hochbruck, Ostermann & Schweitzer 2009): the linearised network is integrated exactly
  (eigendecomposition of the small dense Jacobian), so steps are limited only by the
  nonlinearity of q; exact dense output; O(n^3) per step (dense networks only).
- ``crank_nicolson`` (this and ``explicit_euler`` in :mod:`.steppers_comparison`;
  :func:`solve_steady` in :mod:`.steady`): trapezoidal rule, A- but not L-stable: it
  rings on stiff modes and on zero-capacity nodes. Fixed step only; kept to show (BM-3)
  what the L-stable methods avoid.
- ``explicit_euler``: forward Euler, unstable above h = 2 C/K on the smallest node.
  Fixed step only; same purpose.

Heat sources are treated implicitly: each stage is a Newton solve with the Jacobian
``J = -K + dq/dT`` (``heat_jacobian(t, T)`` analytic if given -- an (n, n) array or the
(n,) diagonal --, else finite differences: ``jacobian="fd"`` full (n extra heat
evaluations) or ``"fd_diagonal"`` (1 extra; valid when q_i depends only on T_i), or
``"none"`` (q independent of T)). The Jacobian and the LU factors are reused across
steps while Newton converges; the LU is refactored when h changes. Temperature-dependent
conductances are assembled at the start of every step for the iteration matrix, and their
drift within the step is part of the stage heat (``_Core.q_stage``, ``Assembler.drift``),
so the stage equations hold with K(T) at the stage values, not lagged by a step. The
evaluations, the Jacobian, the LU cache and the Newton solve are in :mod:`.stepper_core`.

Error control: local error estimate ``e`` (filtered by the iteration matrix, Shampine)
measured as max_i |e_i| / (atol + rtol |T_i|) <= 1, the same scaled max norm as
scipy's solve_ivp tolerances (atol in K).

Restarts: :func:`integrate` stops exactly at every breakpoint (load or speed steps),
re-evaluates q, refreshes the Jacobian and re-initialises the zero-capacity nodes
consistently, so a discontinuity in q never falls inside a step. Within a segment that
ends at a breakpoint t_b, ``heat`` is called with times < t_b (a stage at t_b is passed
``nextafter(t_b, -inf)``), so a right-continuous schedule is seen from the left there.

Step-wise API (for a loop that re-solves kinematics between thermal steps)::

    stepper = TransientStepper(network, method="tr_bdf2", rtol=1e-5, atol=1e-3)
    T = initial_state_vector
    for k in range(n):
        out = stepper.advance(t, T, dt, heat, heat_jacobian=None)  # adaptive inside [t, t+dt]
        T, t = out.temperatures, out.time
        # ... re-solve kinematics with the new temperatures, build a new `heat` ...

``heat(t, T)`` gets the state temperatures [K] (order ``network.state_nodes``, boundary
nodes excluded) and returns watts per state node: an array of that length (or over all
nodes, with zeros on boundary nodes) or a ``{node name: W}`` dict.

A step whose Newton iteration fails is retried with h/4 and a fresh Jacobian; below
``min_step`` a :class:`~thermobearing.errors.ConvergenceError` reports the time, the step
size and the residual. Non-finite values are never returned.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..errors import ConvergenceError, InputError
from ..registry import Registry
from .assemble import assembler_for
from .audit import EnergyAudit, TransientResult, roundoff_floor
from .graph import ThermalNetwork
from .stepper_core import (  # noqa: F401  (the core's names stay importable from here)
    HeatFn,
    _audit,
    _Core,
    _Method,
    _NewtonFailure,
    _Trial,
)

STEPPERS: Registry[type] = Registry("stepper", "time integration of the thermal network")

_GAMMA = 2.0 - math.sqrt(2.0)
_D = _GAMMA / 2.0
_W = math.sqrt(2.0) / 4.0
# b - b_hat of Hosea & Shampine (1996): (4w-1)/3, -1/3, 2d/3 (they sum to zero)
_E0 = (4.0 * _W - 1.0) / 3.0
_E1 = -1.0 / 3.0
_E2 = 2.0 * _D / 3.0


@STEPPERS.register("tr_bdf2", references=["bank1985_trbdf2", "hosea_shampine1996"],
                   parameters={"rtol": "-", "atol": "K"},
                   validity="any stiffness; L-stable, 2nd order; DAE index 1 (C = 0 nodes)")
class TRBDF2(_Method):
    """TR-BDF2 (gamma = 2 - sqrt 2), L-stable 2nd order, embedded 3rd-order error estimate.

    Bank et al. (1985) eq. (2.5)-(2.6); Hosea & Shampine (1996) sec. 2 for the one-matrix
    form, the weights (w, w, d), w = sqrt(2)/4, d = gamma/2, and the error estimate
    h [(4w-1)/3 f_n - 1/3 f_gamma + 2d/3 f_{n+1}] filtered by (C - d h J)^-1.
    """

    order = 2
    name = "tr_bdf2"

    def step(self, core, t, h, y0, f0, q0):
        coef = _D * h
        core.factor(coef)
        # stage 1: trapezoidal rule to t + gamma h, Newton started from y0 (q0 known; for
        # a heat source that depends on t only through step changes, q(t + gamma h, y0) =
        # q0 inside a segment; otherwise the first residual is off by the time change of
        # q, which Newton removes)
        start_q = None if core.time_dependent else q0
        z, fg, qg, _ = core.newton(t + _GAMMA * h, y0, y0, coef, coef * f0, q_start=start_q)
        _, dbg = core.stage_drift
        # stage 2: BDF2 through y0, z to t + h, started from z (q known the same way)
        start_q = None if core.time_dependent else qg
        y1, f1, q1, _ = core.newton(t + h, y0, z, coef, (h * _W) * (f0 + fg), q_start=start_q)
        d1, db1 = core.stage_drift
        est = core.solve(h * (_E0 * f0 + _E1 * fg + _E2 * f1))
        sc = core.atol + core.rtol * np.abs(y1)
        err = float((np.abs(est) / sc).max())
        if err > 1.0:
            # second filtering (C - d h J)^-1 C est (Hairer & Wanner 1996, IV.8, eq. 8.20):
            # a stiff node off its slow manifold after a restart is damped by the L-stable
            # step (error ~ delta/|z|), which the once-filtered estimate does not see.
            err = float((np.abs(core.solve(core.C * est)) / sc).max())
        ybar = _W * (y0 + z) + _D * y1
        # the stage heats qg, q1 carry the conductances' drift (zero at y0, where the step's
        # system was assembled); its sum over the nodes is minus the change of the heat to
        # the boundaries, so with the same weights it moves from generated to boundaries
        moved = h * (_W * dbg + _D * db1)
        gen = h * (_W * (q0.sum() + qg.sum()) + _D * q1.sum()) + moved
        sys_ = core.sys
        to_b = h * sys_.to_boundaries(ybar) + moved
        to_s = h * sys_.to_streams(ybar) if len(sys_.str_W) else 0.0
        return _Trial(y1, f1, q1 - d1, err, gen, to_b, to_s)


@STEPPERS.register("backward_euler", references=["hairer_wanner1996"],
                   parameters={"rtol": "-", "atol": "K"},
                   validity="any stiffness; L-stable, 1st order")
class BackwardEuler(_Method):
    """Backward (implicit) Euler, C (y1 - y0) = h f(t1, y1); L-stable, first order.

    Hairer & Wanner (1996) sec. IV.3. Error estimate for step control: (h/2)(f1 - f0)
    filtered by (C - h J)^-1 (the leading local-error term of the method).
    """

    order = 1
    name = "backward_euler"

    def step(self, core, t, h, y0, f0, q0):
        core.factor(h)
        ydot0 = f0 * core.invC
        y1, f1, q1, _ = core.newton(t + h, y0, y0 + h * ydot0, h, np.zeros_like(y0))
        d1, db1 = core.stage_drift   # the conductances' drift at y1 (see TRBDF2.step)
        est = core.solve(0.5 * h * (f1 - f0))
        sc = core.atol + core.rtol * np.abs(y1)
        err = float((np.abs(est) / sc).max())
        if err > 1.0:  # second filtering, as in TRBDF2.step
            err = float((np.abs(core.solve(core.C * est)) / sc).max())
        q1 = q1 - d1
        gen, to_b, to_s = _audit(core, h, (1.0,), (y1,), (q1,))
        return _Trial(y1, f1, q1, err, gen, to_b + h * db1, to_s)


# ==================================================================== driver
class _Driver:
    """Runs a stepper over [t0, t1] (one smooth segment) and records the steps."""

    def __init__(self, network: ThermalNetwork, method: str, rtol: float, atol: float,
                 dt: float | None, max_step: float, first_step: float | None,
                 min_step: float, jacobian: str) -> None:
        self.network = network
        self.method: _Method = STEPPERS.get(method)()
        self.method_name = method
        if rtol < 0 or atol <= 0 or not math.isfinite(rtol) or not math.isfinite(atol):
            raise InputError("rtol/atol", (rtol, atol), "rtol >= 0 and atol > 0 [K]")
        if dt is not None and (not math.isfinite(dt) or dt <= 0):
            raise InputError("dt", dt, "a step size > 0 s (or None for adaptive steps)")
        if dt is None and not self.method.adaptive:
            raise InputError("dt", dt, f"a fixed step size: {method!r} has no error control")
        if max_step <= 0:
            raise InputError("max_step", max_step, "a value > 0 s")
        self.rtol, self.atol = float(rtol), float(atol)
        self.dt = dt
        self.max_step = float(max_step)
        self.first_step = first_step
        self.min_step = float(min_step)
        self.jacobian = jacobian
        self._build()
        self.fast_info: tuple | None = None  # exp_fast: (K symmetric?, C^-1/2) of the build
        self.h_last: float | None = None
        self.h_first: float | None = None  # first accepted step of the last segment
        self.h0_factor = 2.0  # first step 2 / max|dT/dt / (atol + rtol |T|)| [s]
        self.facmax = 5.0

    def _fast_applies(self) -> bool:
        """Whether the compiled exprb43 path (exp_fast) runs this network (cached per
        build)."""
        ok = self._fast_ok
        if ok is None:
            from . import exp_fast

            self._exp_fast = exp_fast
            ok = self._fast_ok = exp_fast.applies(self)
        return ok

    def _build(self) -> None:
        self.asm = assembler_for(self.network)  # validates the network
        self.core = _Core(self.network, self.asm, self.rtol, self.atol, self.jacobian)
        self.core.adaptive = self.dt is None
        self.fast_info = None
        self._fast_ok: bool | None = None

    def _initial_step(self, t0: float, t1: float, y0: np.ndarray, f0: np.ndarray) -> float:
        core = self.core
        if self.first_step is not None:
            return min(self.first_step, t1 - t0)
        if self.method.trial_first_step:
            # exact on the stiff linear part: the error estimate of a trial step sizes it
            h = min(t1 - t0, self.max_step)
            if self.h_first is not None:
                h = min(h, 4.0 * self.h_first)
            return h
        # rates filtered by the node's own conductance at a trial step h_b (the backward-
        # Euler increment per unit time): a stiff node (C/K << h_b) whose raw rate f/C is
        # huge is damped by the L-stable steppers and must not dictate the first step.
        h_b = 1e-3 * min(t1 - t0, self.max_step)
        KmJ = core.KmJ
        diag = KmJ.diagonal() if sp.issparse(KmJ) else np.diagonal(KmJ)
        ydot = np.where(core.diff, f0 / (core.C + h_b * np.maximum(diag, 0.0)), 0.0)
        d1 = float(np.max(np.abs(ydot) / core.scale(y0)))
        h = self.h0_factor / d1 if d1 > 0 else (t1 - t0)
        if self.h_last is not None:
            h = min(h, 4.0 * self.h_last)
        return max(min(h, t1 - t0, self.max_step), min(self.min_step * 10, t1 - t0))

    def segment(self, t0: float, t1: float, y0: np.ndarray, heat: HeatFn | None,
                heat_jacobian: Callable | None, rec: _Recorder,
                time_dependent: bool = True,
                heat_with_jacobian: Callable | None = None) -> np.ndarray:
        """Integrate one smooth segment; returns the state at t1 (exactly at t1)."""
        if self.network._revision != self.asm.revision:
            self._build()
        core = self.core
        core.time_dependent = time_dependent
        core.set_heat(heat, heat_jacobian)
        core.t_end = t1
        core.t_end_left = math.nextafter(t1, -math.inf)
        if self.method.name == "exprb43" and self._fast_applies():
            return self._exp_fast.run_segment(self, t0, t1, y0, heat, heat_jacobian,
                                              heat_with_jacobian, rec, time_dependent)
        try:
            core.update_system(y0)
            if core.has_alg:
                y_cons = core.consistent_algebraic(t0, y0)
                if rec.active and np.any(y_cons != y0):
                    rec.jump(t0, y_cons, core)
                y0 = y_cons
            f0, q0 = core.f(t0, y0)
            core.refresh_jacobian(t0, y0, q0)
        except _NewtonFailure as exc:
            raise stepper_failure(self.method_name, exc.residual, exc.reason, t0, 0.0,
                                  y0) from None
        if not rec.started:
            rec.start(t0, y0, f0, core)
        t = t0
        y = y0
        if self.dt is not None:
            h = min(self.dt, t1 - t0)
        else:
            h = self._initial_step(t0, t1, y0, f0)
        method = self.method
        p1 = (method.error_order or method.order) + 1.0
        fresh_jac = True
        first_in_segment = True
        rejected_in_row = False
        tiny = 1e-12 * max(1.0, abs(t1))
        while t < t1 - tiny:
            h, last = clip_step(t, h, t1)
            if core.asm.temperature_dependent:
                core.update_system(y, keep_heat_jacobian=True)
                # f at the step start with the conductances the step uses (q unchanged),
                # so that the stage equations and the audit see one K
                f0 = core.sys.s - core.sys.K @ y + q0
            try:
                trial = method.step(core, t, h, y, f0, q0)
            except _NewtonFailure as exc:
                core.stats["newton_failures"] += 1
                if not fresh_jac:
                    core.refresh_jacobian(t, y, q0)
                    fresh_jac = True
                    continue
                h_new = h / 4.0
                if h_new < self.min_step or self.dt is not None and h_new < self.dt * 1e-6:
                    raise stepper_failure(self.method_name, exc.residual, exc.reason, t, h,
                                          y) from None
                h = h_new
                continue
            err = trial.err
            if self.dt is None and err is not None and err > 1.0:
                core.stats["rejected"] += 1
                fac = max(0.1, 0.9 * err ** (-1.0 / p1))
                if method.trial_first_step and rejected_in_row:
                    # a trial step far outside the asymptotic range (the estimate does
                    # not yet scale like h^p1): halve at least
                    fac = min(fac, 0.5)
                rejected_in_row = True
                h = h * fac
                if h < self.min_step:
                    raise stepper_failure(self.method_name, err, STEP_UNDERFLOW, t, h, y)
                continue
            # accept
            rejected_in_row = False
            if first_in_segment:
                self.h_first = h
                first_in_segment = False
            core.stats["steps"] += 1
            stored = float(np.dot(core.C, trial.y1 - y))
            t = t1 if last else t + h
            y, f0, q0 = trial.y1, trial.f1, trial.q1
            rec.add(t, y, f0, core, trial.gen, stored, trial.to_b, trial.to_s, trial.dense)
            fresh_jac = False
            if self.dt is not None:
                h = self.dt
            else:
                self.h_last = h
                fac = (self.facmax if err == 0.0
                       else min(self.facmax, max(0.2, 0.9 * err ** (-1.0 / p1))))
                if not 1.0 <= fac <= 1.2:
                    h = h * fac
                h = min(h, self.max_step)
        return y


def stepper_failure(method_name: str, residual: float, reason: str, t: float, h: float,
                    y: np.ndarray) -> ConvergenceError:
    """The error of an adaptive network stepper that cannot go on (a Newton failure at the
    smallest step, or :data:`STEP_UNDERFLOW`): names the stepper, the residual or error
    estimate [-] and the reason, with the time t [s], the step size h [s] and the
    temperatures y [K] at the failure. Shared by this module's loop and :mod:`.exp_fast`."""
    return ConvergenceError(f"network stepper {method_name}", residual, reason,
                            {"time": t, "step_size": h, "temperatures": y})


def clip_step(t: float, h: float, t1: float) -> tuple[float, bool]:
    """The step h [s] to take from t [s] towards the segment end t1 [s] and whether it is the
    segment's last: a step that would end within 1e-3 h of t1 (or beyond) is stretched or cut
    to t1 - t, so that no sliver step is left. Shared by this module's loop and
    :mod:`.exp_fast`."""
    if t + h >= t1 - 1e-3 * h:
        return t1 - t, True
    return h, False


#: reason of the error when error control shrinks the step below the stepper's minimum
STEP_UNDERFLOW = "step size underflow in error control"


class _Recorder:
    """Collects (t, T, dT/dt) and audit rows."""

    def __init__(self, active: bool = True, floor: float = 0.0) -> None:
        self.active = active
        self.floor = floor  # EnergyAudit.floor [J] (audit.roundoff_floor)
        self.started = False
        self.t: list[float] = []
        self.y: list[np.ndarray] = []
        self.r: list[np.ndarray] = []
        self.rows: list[tuple[float, float, float, float, float]] = []
        self.pieces: list = []  # dense output pieces of methods that have their own
        self.fast_store = None  # exp_fast.DenseStore of the compiled exprb43 path

    @staticmethod
    def _rate(f: np.ndarray, core: _Core) -> np.ndarray:
        return f * core.invC  # dT/dt; 0 on zero-capacity nodes

    def start(self, t, y, f, core) -> None:
        self.started = True
        if self.active:
            self.t.append(t)
            self.y.append(y.copy())
            self.r.append(self._rate(f, core))

    def jump(self, t, y, core) -> None:
        if self.started:
            f, _ = core.f(t, y)
            self.t.append(t)
            self.y.append(y.copy())
            self.r.append(self._rate(f, core))

    def add(self, t, y, f, core, gen, stored, to_b, to_s, dense=None) -> None:
        self.rows.append((t, gen, stored, to_b, to_s))
        if self.active:
            if dense is not None:
                self.pieces.append(dense)
            self.t.append(t)
            self.y.append(y)
            self.r.append(self._rate(f, core))

    def audit(self) -> EnergyAudit:
        a = np.array(self.rows, dtype=float).reshape(-1, 5)
        return EnergyAudit(a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4], floor=self.floor)


def _roundoff_floor(network: ThermalNetwork, atol: float) -> float:
    """The audit's round-off floor of a run on ``network`` (:func:`.audit.roundoff_floor`):
    a run with no heat from equilibrium has round-off flows only."""
    caps = np.array([network.capacity(name) for name in network.state_nodes], dtype=float)
    return roundoff_floor(caps, atol)


# ================================================================== public API
def _escaped(method: str, exc: _NewtonFailure) -> ConvergenceError:
    """The public error of a stepper failure that left the step loop's own handling (a heat
    source that turns non-finite in a finite-difference Jacobian after a failed step
    escaped integrate as the private _NewtonFailure)."""
    return ConvergenceError(f"network stepper {method}", exc.residual, exc.reason)


def _as_heat_fn(network: ThermalNetwork, heat) -> tuple[HeatFn | None, bool]:
    """(callable or None, constant?) from a callable, a {node: W} dict or a vector."""
    if heat is None:
        return None, True
    if callable(heat):
        return heat, False
    q = network.heat_vector(heat).copy()
    bad = np.flatnonzero(~np.isfinite(q))
    if bad.size:  # was 'did not converge (residual inf)' at t = 0 (a _NewtonFailure, steady)
        node = network.state_nodes[int(bad[0])]
        raise InputError(f"heat[{node!r}]", float(q[bad[0]]), "a finite heat rate [W]")
    return (lambda t, T: q), True


def _initial_vector(network: ThermalNetwork, T0) -> np.ndarray:
    names = network.state_nodes
    if type(T0) is np.ndarray and T0.shape == (len(names),):  # the common case
        y = T0.astype(float)  # (a copy: the caller's array is never aliased)
    elif isinstance(T0, Mapping):
        missing = [n for n in names if n not in T0]
        if missing:
            raise InputError("T0", sorted(T0), f"a temperature for every state node; missing "
                                               f"{missing}")
        y = np.array([float(T0[n]) for n in names])
    elif np.ndim(T0) == 0:
        y = np.full(len(names), float(T0))
    else:
        y = np.array(T0, dtype=float)
        if y.shape != (len(names),):
            raise InputError("T0", y.shape, f"shape ({len(names)},) in the order "
                                            f"network.state_nodes")
    lo = float(y.min()) if y.size else 1.0
    if not (lo > 0.0 and math.isfinite(float(y.sum()))):  # (NaN fails both)
        raise InputError("T0", y, "finite temperatures > 0 K")
    return y


def _jacobian_of(heat_jacobian: Callable | None,
                 heat_with_jacobian: Callable | None) -> Callable | None:
    """heat_jacobian, or the Jacobian part of heat_with_jacobian when only that is given."""
    if heat_jacobian is not None or heat_with_jacobian is None:
        return heat_jacobian
    return lambda t, T: heat_with_jacobian(t, T)[1]


def integrate(network: ThermalNetwork, heat: HeatFn | None, t_span: tuple[float, float], T0,
              method: str = "tr_bdf2", rtol: float = 1e-5, atol: float = 1e-3,
              breakpoints: Sequence[float] = (), heat_jacobian: Callable | None = None,
              dt: float | None = None, max_step: float = math.inf,
              first_step: float | None = None, min_step: float = 1e-14,
              jacobian: str = "fd", heat_time_dependent: bool = True,
              heat_with_jacobian: Callable | None = None) -> TransientResult:
    """Integrate the network from ``t_span[0]`` to ``t_span[1]`` [s].

    Parameters
    ----------
    network : the :class:`ThermalNetwork`.
    heat : ``heat(t, T) -> W`` per state node (see the module docstring); or a constant
        vector / ``{node: W}`` dict; or None.
    t_span : (t0, t1) [s].
    T0 : initial temperatures [K]: scalar, array over ``network.state_nodes`` or dict.
        Zero-capacity nodes are re-initialised consistently.
    method : a :data:`STEPPERS` name (``tr_bdf2``, ``backward_euler``, ``crank_nicolson``,
        ``explicit_euler``).
    rtol, atol : error tolerances (scaled max norm; atol in K).
    breakpoints : times [s] where ``heat`` (or anything) jumps; steps end exactly there and
        the solver restarts.
    heat_jacobian : ``(t, T) -> dq/dT`` [W/K], (n, n) or (n,) diagonal; default finite
        differences (``jacobian``).
    dt : fixed step size [s] (no error control), else adaptive.
    max_step, first_step, min_step : step bounds [s].
    jacobian : ``"fd"``, ``"fd_diagonal"`` or ``"none"`` when ``heat_jacobian`` is None.
    heat_time_dependent : False promises that ``heat`` depends on t only through jumps at
        the breakpoints (piecewise constant in t): TR-BDF2 then starts each stage's Newton
        iteration from the previous stage value with its known q, saving two of the four
        heat evaluations per step. Leave True (default) for ramps or any continuous
        time dependence.
    heat_with_jacobian : optional ``(t, T) -> (q [W], dq/dT [W/K])`` from one call, for a
        source that computes both at once (the same values as ``heat`` and
        ``heat_jacobian``). ``exprb43`` calls it at every step start instead of the two
        separate calls; the other steppers use ``heat`` and ``heat_jacobian`` (derived
        from this one when not given).

    Returns
    -------
    TransientResult with times, temperatures, rates, the energy audit and solver stats.
    """
    t0, t1 = (float(x) for x in t_span)
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 <= t0:
        raise InputError("t_span", t_span, "finite (t0, t1) with t1 > t0")
    y = _initial_vector(network, T0)
    heat, constant = _as_heat_fn(network, heat)
    if constant:
        jacobian = "none"
        heat_with_jacobian = None
    heat_jacobian = _jacobian_of(heat_jacobian, heat_with_jacobian)
    driver = _Driver(network, method, rtol, atol, dt, max_step, first_step, min_step, jacobian)
    rec = _Recorder(floor=_roundoff_floor(network, atol))
    cuts = sorted({float(b) for b in breakpoints if t0 < float(b) < t1})
    edges = [t0, *cuts, t1]
    td = bool(heat_time_dependent) and not constant
    try:
        if method == "exprb43" and driver._fast_applies():  # compiled path, all segments
            y = driver._exp_fast.run_segments(driver, edges, y, heat, heat_jacobian,
                                              heat_with_jacobian, rec, td)
        else:
            for a, b in zip(edges[:-1], edges[1:], strict=True):
                y = driver.segment(a, b, y, heat, heat_jacobian, rec, td, heat_with_jacobian)
    except _NewtonFailure as exc:
        raise _escaped(method, exc) from None
    return TransientResult(
        names=network.state_nodes,
        boundary={n: network.boundary_temperature(n) for n in network.boundary_nodes},
        times=np.array(rec.t), temperatures=np.array(rec.y), rates=np.array(rec.r),
        audit=rec.audit(), stats=dict(driver.core.stats), method=method,
        dense=tuple(rec.pieces) if len(rec.pieces) == len(rec.rows) else (),
    )


@dataclass(frozen=True)
class StepOutcome:
    """Result of :meth:`TransientStepper.advance`: the state at ``time`` and the audit."""

    time: float
    temperatures: np.ndarray
    audit: EnergyAudit
    steps: int
    #: temperatures [K] at the requested sample times, shape (len(times), n), from the
    #: stepper's own dense output (or its Hermite interpolation); None if none were asked
    samples: np.ndarray | None = None


class TransientStepper:
    """Step-wise integration for coupled loops (see the module docstring).

    Each :meth:`advance` call is a restart (the heat function may have changed); the step
    size, Jacobian policy and counters persist between calls. Changes to the network
    (``set_stream_flow``, capacities, edges) are picked up at the next call.
    """

    def __init__(self, network: ThermalNetwork, method: str = "tr_bdf2", rtol: float = 1e-5,
                 atol: float = 1e-3, dt: float | None = None, max_step: float = math.inf,
                 min_step: float = 1e-14, jacobian: str = "fd") -> None:
        self.network = network
        self._driver = _Driver(network, method, rtol, atol, dt, max_step, None, min_step,
                               jacobian)

    @property
    def stats(self) -> dict[str, int]:
        return dict(self._driver.core.stats)

    def advance(self, t: float, T, dt: float, heat: HeatFn | None,
                heat_jacobian: Callable | None = None,
                heat_time_dependent: bool = True,
                heat_with_jacobian: Callable | None = None,
                sample_times: Sequence[float] | None = None) -> StepOutcome:
        """Advance from ``t`` to ``t + dt`` [s] from state ``T`` [K] with ``heat``
        (``heat_time_dependent`` and ``heat_with_jacobian`` as in :func:`integrate`);
        ``sample_times`` within [t, t + dt] [s]: the temperatures there are returned in
        ``samples`` (the steps are recorded for it, at a small extra cost)."""
        if not math.isfinite(dt) or dt <= 0:
            raise InputError("dt", dt, "a step > 0 s")
        ts = None if sample_times is None else np.asarray(sample_times, dtype=float)
        if ts is not None and ts.size and not (
                np.all(np.isfinite(ts)) and ts.min() >= t - 1e-9 * max(1.0, abs(t))
                and ts.max() <= t + dt + 1e-9 * max(1.0, abs(t + dt))):
            raise InputError("sample_times", (float(ts.min()), float(ts.max())),
                             f"times within [{t}, {t + dt}] s")
        y = _initial_vector(self.network, T)
        heat, constant = _as_heat_fn(self.network, heat)
        if constant:
            heat_with_jacobian = None
        heat_jacobian = _jacobian_of(heat_jacobian, heat_with_jacobian)
        sampled = ts is not None and ts.size > 0
        rec = _Recorder(active=sampled, floor=_roundoff_floor(self.network, self._driver.atol))
        steps0 = self._driver.core.stats["steps"]
        try:
            y1 = self._driver.segment(float(t), float(t) + float(dt), y, heat, heat_jacobian,
                                      rec, bool(heat_time_dependent) and not constant,
                                      heat_with_jacobian)
        except _NewtonFailure as exc:
            raise _escaped(self._driver.method_name, exc) from None
        samples = None
        if sampled:
            part = TransientResult(
                names=self.network.state_nodes, boundary={}, times=np.array(rec.t),
                temperatures=np.array(rec.y), rates=np.array(rec.r), audit=rec.audit(),
                dense=tuple(rec.pieces) if len(rec.pieces) == len(rec.rows) else ())
            samples = part.sample(np.clip(ts, float(t), float(t) + float(dt)))
        return StepOutcome(float(t) + float(dt), y1, rec.audit(),
                           self._driver.core.stats["steps"] - steps0, samples)


# the fixed-step comparison steppers (registered on import) and the steady solve live in
# their own modules; imported here so that ``steppers`` keeps every public name
from . import steppers_comparison  # noqa: E402, F401
from .steady import solve_steady  # noqa: E402, F401
