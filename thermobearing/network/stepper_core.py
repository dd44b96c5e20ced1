"""The shared core of the implicit network steppers (:mod:`.steppers`, :mod:`.exponential`,
:mod:`.steppers_comparison`, :mod:`.steady`): evaluations of the heat and of the right-hand
side ``f = s - K T + q`` on the assembled system, the heat Jacobian (analytic or finite
differences), the LU cache of the iteration matrix ``C + coef (K - dq/dT)``, the simplified
Newton solve of a stage equation (with the drift of temperature-dependent conductances in
the stage heat, :meth:`_Core.q_stage`), consistent initialisation of zero-capacity nodes, and
the interface a stepping method implements (:class:`_Method`, :class:`_Trial`).

Units: times [s], temperatures [K], heat [W], conductances [W/K], capacities [J/K].
"""

from __future__ import annotations

import abc
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.linalg import lapack

from ..errors import ConvergenceError, InputError
from .assemble import Assembler, System
from .graph import ThermalNetwork

#: heat(t [s], T [K] of the state nodes) -> W per state node (array) or {node name: W}
HeatFn = Callable[[float, np.ndarray], "np.ndarray | Mapping[str, float]"]


class _NewtonFailure(Exception):
    def __init__(self, residual: float, reason: str) -> None:
        super().__init__(reason)
        self.residual = residual
        self.reason = reason


def stage_drift(asm: Assembler, reference: System, T: np.ndarray) -> tuple[np.ndarray, float]:
    """``asm.drift(reference, T)`` at a trial stage value T [K]. A too-long trial step can put
    a stage far outside the physical range (e.g. below 0 K), where a conductance model
    refuses the temperature: that is a failed trial (the step is retried with h/4, and
    below the minimum step the ConvergenceError carries the model's message), not an
    error of the input."""
    try:
        d, db = asm.drift(reference, T)
    except (InputError, ValueError, FloatingPointError) as exc:
        raise _NewtonFailure(math.inf, f"conductance at a trial stage value: {exc}") from None
    if not (math.isfinite(db) and math.isfinite(float(d.sum()))):
        raise _NewtonFailure(math.inf, "non-finite conductance at a trial stage value")
    return d, db


# ===================================================================== the core
class _Core:
    """Evaluations, Jacobian and LU cache for one assembled system and heat function."""

    def __init__(self, network: ThermalNetwork, asm: Assembler, rtol: float, atol: float,
                 jacobian: str) -> None:
        self.network = network
        self.asm = asm
        self.sys: System = asm.system()
        self.sys_T: np.ndarray | None = None  # the state the conductances of sys are at
        self.C = self.sys.C
        self.n = len(self.C)
        self.alg = self.C == 0.0
        self.has_alg = bool(self.alg.any())
        self.diff = ~self.alg
        self.invC = np.where(self.diff, 1.0 / np.where(self.diff, self.C, 1.0), 0.0)
        self.rtol = rtol
        self.atol = atol
        self.jacobian_mode = jacobian
        self.heat: HeatFn | None = None
        self.time_dependent = True  # may q depend on t inside a segment?
        self.t_end = math.inf
        self.t_end_left = math.inf
        self.heat_jacobian: Callable | None = None
        self.Jq: np.ndarray | sp.spmatrix | None = None  # dq/dT
        self.KmJ: np.ndarray | sp.spmatrix | None = None  # K - dq/dT
        self.lu = None
        self.lu_coef = -1.0
        self.W0 = None
        self.eta = 1.0  # Newton convergence-rate estimate theta/(1 - theta)
        self.theta = 0.0
        self.jac_y: np.ndarray | None = None  # the state of the last Jacobian (identity)
        self.jac_t = math.nan
        self.adaptive = True  # error-controlled steps (a rejected trial may stop early)
        self.stats = {"steps": 0, "rejected": 0, "newton_failures": 0, "heat_evaluations": 0,
                      "jacobians": 0, "factorizations": 0, "solves": 0}
        self._no_drift = (np.zeros(self.n), 0.0)
        #: (d [W], db [W]) of the last stage value Newton returned: the conductances' drift
        #: from the step's system (Assembler.drift); zero without temperature-dependent edges
        self.stage_drift = self._no_drift

    # ------------------------------------------------------------ evaluations
    def set_heat(self, heat: HeatFn | None, heat_jacobian: Callable | None) -> None:
        self.heat = heat
        self.heat_jacobian = heat_jacobian
        self.Jq = None
        self.KmJ = None
        self.lu_coef = -1.0

    def q(self, t: float, T: np.ndarray) -> np.ndarray:
        self.stats["heat_evaluations"] += 1
        if self.heat is None:
            return np.zeros(self.n)
        if t >= self.t_end:  # a segment sees its end breakpoint from the left
            t = self.t_end_left
        r = self.heat(t, T)
        if type(r) is not np.ndarray or r.shape != (self.n,):
            r = self.network.heat_vector(r)
        if not math.isfinite(r.sum()):
            raise _NewtonFailure(math.inf, f"heat source returned a non-finite value at t={t}")
        return r

    def q_stage(self, t: float, T: np.ndarray) -> np.ndarray:
        """The heat at a stage value T plus the drift of the temperature-dependent
        conductances from the step's system ``sys`` (assembled at the step start):
        q(t, T) + d(T), so that s - K T + q_stage = s(T) - K(T) T + q(T) exactly and the
        implicit stages solve the true equation rather than one with lagged conductances.
        Records (d, db) in :attr:`stage_drift` for the step's books."""
        q = self.q(t, T)
        if not self.asm.temperature_dependent:
            self.stage_drift = self._no_drift
            return q
        self.stage_drift = stage_drift(self.asm, self.sys, T)
        return q + self.stage_drift[0]

    def f(self, t: float, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(f, q): f = -K T + s + q [W]."""
        q = self.q(t, T)
        return self.sys.s - self.sys.K @ T + q, q

    def update_system(self, T: np.ndarray, keep_heat_jacobian: bool = False) -> None:
        """Re-assemble temperature-dependent conductances at T (the step's K_n; the drift
        within the step is added to the stage heat, :meth:`q_stage`).

        With ``keep_heat_jacobian`` the last dq/dT is reused (K - dq/dT rebuilt without new
        heat evaluations), else the Jacobian must be refreshed before the next factor.
        """
        if self.asm.temperature_dependent:
            if self.sys_T is None or not np.array_equal(T, self.sys_T):
                # K(T) is a function of T only: the same state needs no re-assembly (the
                # first step of a segment starts where the segment's set-up assembled it)
                self.sys = self.asm.system(T)
                self.sys_T = np.array(T, dtype=float)
            self.lu_coef = -1.0
            if not keep_heat_jacobian:
                self.KmJ = None
                return
            self.KmJ = self._k_minus_j(self.Jq, T)

    def _k_minus_j(self, Jq: np.ndarray | None, T: np.ndarray) -> np.ndarray | sp.spmatrix:
        """-(df/dT) = K - dq/dT - D [W/K] at T [K] on the current system, D the
        conductances' own temperature derivatives (``Assembler.drift_jacobian``; zero
        without temperature-dependent edges): the exact Jacobian for the Newton matrices,
        the exponential's linearisation and the steady solve."""
        K = self.sys.K
        if self.sys.dense:
            KmJ = K if Jq is None else K - (np.diag(Jq) if Jq.ndim == 1 else Jq)
            if self.asm.temperature_dependent:
                KmJ = KmJ - self.asm.drift_jacobian(T)
            return KmJ
        KmJ = K if Jq is None else K - (sp.diags(Jq) if Jq.ndim == 1 else sp.csc_matrix(Jq))
        if self.asm.temperature_dependent:
            KmJ = KmJ - self.asm.drift_jacobian(T)
        return sp.csc_matrix(KmJ)

    def refresh_jacobian(self, t: float, T: np.ndarray, q0: np.ndarray | None = None) -> None:
        self.stats["jacobians"] += 1
        mode = self.jacobian_mode
        n = self.n
        if self.heat is None or mode == "none":
            Jq = None
        elif self.heat_jacobian is not None:
            Jq = np.asarray(self.heat_jacobian(t, T), dtype=float)
            if Jq.shape not in ((n,), (n, n)) or not np.all(np.isfinite(Jq)):
                raise InputError("heat_jacobian", Jq.shape,
                                 f"a finite ({n},) diagonal or ({n}, {n}) matrix")
        else:
            if q0 is None:
                q0 = self.q(t, T)
            delta = 1.49e-8 * np.maximum(np.abs(T), 1.0)
            if mode == "fd_diagonal":
                Jq = (self.q(t, T + delta) - q0) / delta
            elif mode == "fd":
                Jq = np.empty((n, n))
                for j in range(n):
                    Tp = T.copy()
                    Tp[j] += delta[j]
                    Jq[:, j] = (self.q(t, Tp) - q0) / delta[j]
            else:
                raise InputError("jacobian", mode, "'fd', 'fd_diagonal' or 'none'")
        self.Jq = Jq
        self.KmJ = self._k_minus_j(Jq, T)
        self.jac_y, self.jac_t = T, t
        self.lu_coef = -1.0
        self.eta = 1.0

    def factor(self, coef: float) -> None:
        """LU of W = diag(C) + coef (K - dq/dT), and W0 = diag(C) + coef K for residuals."""
        if coef == self.lu_coef:
            return
        self.stats["factorizations"] += 1
        if self.sys.dense:
            W = coef * self.KmJ
            W[np.diag_indices(self.n)] += self.C
            lu, piv, info = lapack.dgetrf(W)  # direct LAPACK: ~2 us at n = 4
            if info != 0:
                raise _NewtonFailure(math.inf, f"singular iteration matrix (dgetrf info {info})")
            self.lu = (lu, piv)
            W0 = coef * self.sys.K
            W0[np.diag_indices(self.n)] += self.C
        else:
            W = (sp.diags(self.C) + coef * self.KmJ).tocsc()
            self.lu = spla.splu(W)
            W0 = (sp.diags(self.C) + coef * self.sys.K).tocsr()
        self.W0 = W0
        self.lu_coef = coef

    def solve(self, r: np.ndarray) -> np.ndarray:
        self.stats["solves"] += 1
        if self.sys.dense:
            return lapack.dgetrs(self.lu[0], self.lu[1], r)[0]
        return self.lu.solve(r)

    def scale(self, y: np.ndarray) -> np.ndarray:
        return self.atol + self.rtol * np.abs(y)

    # ------------------------------------------------------------------ Newton
    def newton(self, t: float, y0: np.ndarray, y: np.ndarray, coef: float,
               rhs: np.ndarray, kappa: float = 0.01, max_iter: int = 7,
               q_start: np.ndarray | None = None,
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
        """Solve C (y - y0) - coef f(t, y) - rhs = 0; returns (y, f(y), q(y), iterations).
        With temperature-dependent conductances q is :meth:`q_stage` (the heat plus the
        conductances' drift from the step's system, recorded in :attr:`stage_drift`), so f
        is the exact right-hand side; ``q_start`` must be of that kind too.

        Written as W0 y - coef q(t, y) = C y0 + coef s + rhs with W0 = C + coef K, solved by
        simplified Newton with the factorised W = C + coef (K - dq/dT). An update dy is
        accepted when eta |dy| <= kappa * min(atol + rtol |y0|), eta = theta / (1 - theta)
        with theta the contraction rate (measured when two or more updates are made,
        otherwise carried over from the last stage and relaxed towards 1 as in Hairer &
        Wanner 1996, sec. IV.8). On a linear problem with an exact Jacobian theta is at
        round-off, one update is taken, and the stage equation holds to round-off (the
        energy audit closes to ~1e-13). f and q are always those of the returned y.
        ``q_start``: q(t, y) at the starting iterate if already known (saves an evaluation:
        the steppers start each stage from the previous stage value, whose q they have).
        """
        W0 = self.W0
        c_stage = self.C * y0 + coef * self.sys.s + rhs
        tol = kappa * (self.atol + self.rtol * float(np.abs(y0).min()))
        q = self.q_stage(t, y) if q_start is None else q_start
        R = W0 @ y - coef * q - c_stage
        prev = 0.0
        eta = self.eta
        for it in range(max_iter):
            dy = self.solve(R)
            norm = float(np.abs(dy).max())
            if not math.isfinite(norm):
                raise _NewtonFailure(float(np.abs(R).max()), "non-finite Newton update")
            y = y - dy
            q = self.q_stage(t, y)
            if it > 0:
                theta = norm / prev
                if theta >= 0.9:
                    raise _NewtonFailure(float(np.abs(R).max()), "Newton iteration diverges")
                eta = theta / (1.0 - theta)
                self.theta = theta
            if eta * norm <= tol or norm == 0.0:
                self.eta = max(eta, 1e-16) ** 0.8 if it == 0 else eta
                return y, self.sys.s - self.sys.K @ y + q, q, it + 1
            R = W0 @ y - coef * q - c_stage
            prev = norm
        raise _NewtonFailure(float(np.abs(R).max()), f"no convergence in {max_iter} iterations")

    def consistent_algebraic(self, t: float, y: np.ndarray) -> np.ndarray:
        """Solve f_alg(t, y) = 0 for the zero-capacity nodes, the others fixed.

        Temperature-dependent conductances are re-assembled at every Newton iterate (and at
        the result), so the solution satisfies the algebraic equations with the conductances
        of its own temperatures. They were held at the incoming y: from a uniform start a
        free-convection edge at a zero-capacity node was solved at its 1e-3 K floor, the
        first step then re-assembled it at the solved temperatures, the algebraic equation
        no longer held and exprb43 stopped at t = 0 with 'step size underflow' (a two-node
        network with an oil stream, residual 1.3e3 W at rtol 1e-7)."""
        if not self.has_alg:
            return y
        alg = self.alg
        y = y.copy()
        for _ in range(30):
            self.update_system(y)
            f, q = self.f(t, y)
            r = f[alg]
            self.refresh_jacobian(t, y, q)
            KmJ = self.KmJ.toarray() if sp.issparse(self.KmJ) else self.KmJ
            # f = -(K - Jq) y + ...  ->  df_alg/dy_alg = -(KmJ)[alg][:, alg]
            J_aa = -KmJ[np.ix_(alg, alg)]
            dy = np.linalg.solve(J_aa, -r)
            y[alg] += dy
            if np.max(np.abs(dy)) <= 1e-13 * max(1.0, float(np.max(np.abs(y)))):
                self.update_system(y)
                return y
        raise ConvergenceError("network consistent initialisation",
                               float(np.max(np.abs(r))),
                               "zero-capacity node temperatures did not converge",
                               {"time": t})


# ====================================================== the stepper interface
@dataclass
class _Trial:
    y1: np.ndarray
    f1: np.ndarray
    q1: np.ndarray
    err: float | None  # scaled error norm, None for fixed-step-only methods
    gen: float  # J
    to_b: float  # J
    to_s: float  # J
    dense: object = None  # a method's own dense output of the step (callable of t)


class _Method(abc.ABC):
    order = 1
    error_order: int | None = None  # order of the embedded solution (default: order)
    adaptive = True
    name = ""
    trial_first_step = False  # first step of a segment: try the whole segment

    @abc.abstractmethod
    def step(self, core: _Core, t: float, h: float, y0: np.ndarray, f0: np.ndarray,
             q0: np.ndarray) -> _Trial:
        """One trial step of size h from (t, y0)."""


def _audit(core: _Core, h: float, weights: Sequence[float], ys: Sequence[np.ndarray],
           qs: Sequence[np.ndarray]) -> tuple[float, float, float]:
    ybar = sum(w * y for w, y in zip(weights, ys, strict=True))
    gen = h * sum(w * float(q.sum()) for w, q in zip(weights, qs, strict=True))
    return gen, h * core.sys.to_boundaries(ybar), h * core.sys.to_streams(ybar)
