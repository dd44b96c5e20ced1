"""Steady state of the thermal network by Newton's method (:func:`solve_steady`).

Units: temperatures [K], heat rates [W], conductances [W/K].
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError
from .assemble import Assembler
from .audit import SteadyResult
from .graph import ThermalNetwork
from .steppers import HeatFn, _as_heat_fn, _Core, _initial_vector


def solve_steady(network: ThermalNetwork, heat: HeatFn | None = None, T_guess=None,
                 t: float = 0.0, xtol: float = 1e-10, max_iter: int = 100,
                 heat_jacobian: Callable | None = None, jacobian: str = "fd") -> SteadyResult:
    """Steady state f(T) = -K(T) T + s + q(t, T) = 0 by Newton's method.

    The Jacobian is -K + dq/dT (conductances' own temperature dependence is left out of
    the Jacobian, so T-dependent edges converge linearly, not quadratically). Converged
    when max |dT| <= xtol [K]. Zero-capacity nodes are no different here.
    """
    y = _initial_vector(network, 300.0 if T_guess is None else T_guess)
    heat, constant = _as_heat_fn(network, heat)
    if constant:
        jacobian = "none"
    asm = Assembler(network)
    core = _Core(network, asm, 0.0, 1.0, jacobian)
    core.set_heat(heat, heat_jacobian)
    res = math.inf
    for it in range(1, max_iter + 1):
        core.update_system(y)
        f, q = core.f(t, y)
        res = float(np.max(np.abs(f)))
        core.refresh_jacobian(t, y, q)
        KmJ = core.KmJ
        if sp.issparse(KmJ):
            dy = spla.spsolve(KmJ.tocsc(), f)
        else:
            dy = np.linalg.solve(KmJ, f)
        if not np.all(np.isfinite(dy)):
            break
        y = y + dy
        if np.max(np.abs(dy)) <= xtol * max(1.0, 1e-3 * float(np.max(np.abs(y)))):
            core.update_system(y)
            f, q = core.f(t, y)
            return SteadyResult(network.state_nodes, y, float(q.sum()),
                                core.sys.to_boundaries(y), core.sys.to_streams(y), it,
                                float(np.max(np.abs(f))))
    raise ConvergenceError("network steady Newton", res, f"no convergence in {max_iter} "
                           "iterations", {"temperatures": y})
