"""Acceptance of a ball skidding state at the round-off floor of its residual.

One job: decide whether the best iterate of a solve that every fallback left just above the
tolerance is a root to the precision the residual can be evaluated with. One unit in the
last place (ulp) of an unknown changes the scaled residual by |dR_i/dx_j| ulp(x_j); the
per-equation floor is the sum of these changes over the unknowns equation i depends on,
taken from the analytic Jacobian blocks (:func:`~thermobearing.skidding.ball_jacobian.
analytic_blocks`, scaled residual in scaled unknowns). A state whose residual norm is within
:data:`FLOOR_FACTOR` times the floor's norm cannot be improved by any Newton step in double
precision: Newton stalls there because each step changes the unknowns by a few ulp. Cold,
very viscous oil makes the traction of a sliding contact so steep that one ulp of a ball's
speed moves its force balance by more than the tolerance allows (SKF6304 at 10012 r/min and
573 N radial with the contacts at -14 degC in ISO VG46: residual 2.3e-9 against the 1e-9
tolerance after every fallback). The same rule as the roller solver's ``newton_round_off``
acceptance (:mod:`thermobearing.skidding.roller_solvers`). Units: the scaled residual of
:class:`~thermobearing.skidding.ball_residual.ball_residual_system` (forces / F_s, moments /
(F_s D/2), cage torque / T_s).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

#: a residual within this factor of its one-ulp floor is accepted (as the roller solver)
FLOOR_FACTOR = 4.0


def round_off_floor(system: Any, X: np.ndarray, G: np.ndarray) -> tuple[float, Any]:
    """(2-norm of the per-equation one-ulp floor of the scaled residual at (X, G), the
    Jacobian blocks it was taken from); (nan, None) when no analytic Jacobian exists there."""
    from .ball_jacobian import analytic_blocks

    J = analytic_blocks(system, X, G)
    if J is None:
        return float("nan"), None
    xs, gs = system.scales()
    ux = np.spacing(np.abs(np.asarray(X, float))) / xs          # (Z, 6) scaled ulps
    ug = np.spacing(np.abs(np.asarray(G, float))) / gs          # (3,)
    balls = np.einsum("zij,zj->zi", np.abs(J.A), ux) + np.abs(J.B) @ ug      # (Z, 6)
    globals_ = np.einsum("zij,zj->i", np.abs(J.C), ux) + np.abs(J.Dg) @ ug  # (3,)
    return float(np.sqrt(np.sum(balls**2) + np.sum(globals_**2))), J


def accept_at_round_off(system: Any, tol: float, errors: Iterable[BaseException]
                        ) -> tuple[np.ndarray, np.ndarray, float, float, Any] | None:
    """The best iterate that the failed attempts ``errors`` carry (``err.iterate`` = (X, G,
    norm), re-evaluated on ``system``, the target operating point) if its residual norm is
    at most max(tol, FLOOR_FACTOR x its one-ulp floor); else None. Returns (X, G, norm,
    floor, Jacobian blocks)."""
    best = None
    for err in errors:
        it = getattr(err, "iterate", None)
        if it is None:
            continue
        X, G = np.asarray(it[0], float), np.asarray(it[1], float)
        if X.shape != (system.Z, 6) or not (np.all(np.isfinite(X))
                                            and np.all(np.isfinite(G))):
            continue
        system.evaluate(X, G)
        nrm = float(system.last_norm)
        if best is None or nrm < best[2]:
            best = (X, G, nrm)
    if best is None or not np.isfinite(best[2]):
        return None
    floor, J = round_off_floor(system, best[0], best[1])
    if not (np.isfinite(floor) and best[2] <= max(tol, FLOOR_FACTOR * floor)):
        return None
    return best[0], best[1], best[2], floor, J


__all__ = ["FLOOR_FACTOR", "accept_at_round_off", "round_off_floor"]
