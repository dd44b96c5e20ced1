"""Steady state of the thermal network by Newton's method (:func:`solve_steady`).

Units: temperatures [K], heat rates [W], conductances [W/K].
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError, InputError
from .assemble import Assembler
from .audit import SteadyResult
from .graph import ThermalNetwork
from .stepper_core import _NewtonFailure
from .steppers import HeatFn, _as_heat_fn, _Core, _initial_vector


def solve_steady(network: ThermalNetwork, heat: HeatFn | None = None, T_guess=None,
                 t: float = 0.0, xtol: float = 1e-10, max_iter: int = 100,
                 heat_jacobian: Callable | None = None, jacobian: str = "fd") -> SteadyResult:
    """Steady state f(T) = -K(T) T + s + q(t, T) = 0 by damped Newton.

    The Jacobian is -K + dq/dT plus the conductances' own temperature derivatives
    (``Assembler.drift_jacobian``), so temperature-dependent edges converge quadratically
    too. Each Newton step is damped by backtracking (halving) until the residual's 2-norm
    decreases (Armijo, c = 1e-4) and every conductance model accepts the trial
    temperatures: a weakly cooled node under free convection otherwise overshoots by
    thousands of kelvin on the first step (from 300 K to 6800 K in a measured case), where
    the air properties stop. Converged when max |dT| <= xtol [K] (relative to the largest
    temperature / 1000 above 1000 K). Zero-capacity nodes are no different here. A failed
    line search or ``max_iter`` iterations raise ConvergenceError with the residual [W], as
    does a heat source that returns a non-finite value during the iterations (it escaped as
    the stepper core's private _NewtonFailure); a constant heat vector or dict with a
    non-finite entry is an InputError naming the node.
    """
    try:
        return _newton(network, heat, T_guess, t, xtol, max_iter, heat_jacobian, jacobian)
    except _NewtonFailure as exc:
        raise ConvergenceError("network steady Newton", exc.residual, exc.reason) from None


def _newton(network: ThermalNetwork, heat: HeatFn | None, T_guess, t: float, xtol: float,
            max_iter: int, heat_jacobian: Callable | None, jacobian: str) -> SteadyResult:
    """The damped Newton iteration of :func:`solve_steady` (its arguments)."""
    y = _initial_vector(network, 300.0 if T_guess is None else T_guess)
    heat, constant = _as_heat_fn(network, heat)
    if constant:
        jacobian = "none"
    asm = Assembler(network)
    core = _Core(network, asm, 0.0, 1.0, jacobian)
    core.set_heat(heat, heat_jacobian)
    core.update_system(y)
    f, q = core.f(t, y)
    res = float(np.max(np.abs(f)))
    for it in range(1, max_iter + 1):
        core.refresh_jacobian(t, y, q)
        KmJ = core.KmJ  # with the conductances' derivatives (_Core._k_minus_j)
        if sp.issparse(KmJ):
            dy = spla.spsolve(KmJ.tocsc(), f)
        else:
            dy = np.linalg.solve(KmJ, f)
        if not np.all(np.isfinite(dy)):
            break
        if np.max(np.abs(dy)) <= xtol * max(1.0, 1e-3 * float(np.max(np.abs(y)))):
            y = y + dy
            core.update_system(y)
            f, q = core.f(t, y)
            return SteadyResult(network.state_nodes, y, float(q.sum()),
                                core.sys.to_boundaries(y), core.sys.to_streams(y), it,
                                float(np.max(np.abs(f))))
        try:
            y, f, q = _damped_step(core, t, y, f, dy)
        except ConvergenceError:
            if not _at_round_off(KmJ, y, f, q):
                raise
            core.update_system(y)
            return SteadyResult(network.state_nodes, y, float(q.sum()),
                                core.sys.to_boundaries(y), core.sys.to_streams(y), it,
                                float(np.max(np.abs(f))))
        res = float(np.max(np.abs(f)))
    raise ConvergenceError("network steady Newton", res, f"no convergence in {max_iter} "
                           "iterations", {"temperatures": y})


def _at_round_off(KmJ, y: np.ndarray, f: np.ndarray, q: np.ndarray) -> bool:
    """Whether every node's heat residual [W] is at the round-off of the flows that meet
    there (|K - J| |T| + |q|, times 1000 eps): no step can lower it further, so a failed
    line search there is convergence, not failure (e.g. a hot node at 3000 K on a 0.1 W/K
    path, where one ulp of the flows is 1e-10 W and the Newton step 5e-10 K)."""
    flows = abs(KmJ) @ np.abs(y) + np.abs(q)
    return bool(np.all(np.abs(f) <= 1e3 * np.finfo(float).eps * np.asarray(flows).ravel()))


def _damped_step(core: _Core, t: float, y: np.ndarray, f: np.ndarray, dy: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(y, f, q) after the Newton step y + lam dy with the largest lam in 1, 1/2, ... 2^-30
    whose residual satisfies ||f(y + lam dy)||_2 <= (1 - 1e-4 lam) ||f(y)||_2 and whose
    temperatures every model accepts (an InputError of a conductance or heat model at a
    trial temperature halves lam). ConvergenceError when no lam qualifies."""
    norm0 = float(np.linalg.norm(f))
    lam = 1.0
    refused = ""
    for _ in range(31):
        y_try = y + lam * dy
        try:
            core.update_system(y_try)
            f_try, q_try = core.f(t, y_try)
        except (InputError, ValueError, FloatingPointError) as exc:
            refused = refused or f"; a model refused the full step ({exc})"
            lam *= 0.5
            continue
        norm = float(np.linalg.norm(f_try))
        if math.isfinite(norm) and norm <= (1.0 - 1e-4 * lam) * norm0:
            return y_try, f_try, q_try
        lam *= 0.5
    core.update_system(y)
    raise ConvergenceError("network steady Newton", float(np.max(np.abs(f))),
                           "line search failed: no step along the Newton direction lowers "
                           "the residual" + refused, {"temperatures": y})
