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
tolerance after every fallback when found; accepted now at 3.4e-6 against a floor of 6.7e-5).
The same rule as the roller solver's ``newton_round_off`` acceptance
(:mod:`thermobearing.skidding.roller_solvers`), with one more condition: the three global
equations (inner-ring axial / radial force balance, cage torque balance), which set the
cage speed, must each be met to max(tol, FLOOR_FACTOR x their own floor) -- the round-off is
allowed only in the balls' own rows, where the steep traction sits.

Checked (the catalogue 6206 at 1132 r/min, 322 N radial, ISO VG46, contacts at -20 to
-35 degC, accepted with residuals of 7e-6 to 4.5e-2 against floors of 5e-5 to 1.3; the
SKF6304 case above): the global rows of every accepted state are met to < 1e-10 (their
floors are 1e-11 to 1e-15), the residual is in single balls' spin / pocket rows; the CSR of
the accepted state agrees with solves converged to < 1e-9 with another quadrature of the
contact (6 x 3 or 10 x 5 nodes instead of 8 x 4) to 3e-5 at -30 degC (0.313997 accepted at
1.8e-3 against 0.314004 and 0.313976) and 2e-5 at -35 degC, with an independent start
(temperature continuation from -20 degC) to 1e-6, and with Newton from 1e-3 perturbations of
it to 6e-4; the SKF6304's accepted CSR 0.3676007 is the 0.3676003 of the same bearing
converged at -8 degC. So those are solutions of the model to the resolution of its
traction. Units: the scaled residual of
:class:`~thermobearing.skidding.ball_residual.ball_residual_system` (forces / F_s, moments /
(F_s D/2), cage torque / T_s).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

#: a residual within this factor of its one-ulp floor is accepted (as the roller solver)
FLOOR_FACTOR = 4.0


def equation_floors(system: Any, X: np.ndarray, G: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray, Any] | None:
    """(one-ulp floor of each ball equation (Z, 6), of each global equation (3,), the
    Jacobian blocks they were taken from) at (X, G), scaled residual; None when no analytic
    Jacobian exists there."""
    from .ball_jacobian import analytic_blocks

    J = analytic_blocks(system, X, G)
    if J is None:
        return None
    xs, gs = system.scales()
    ux = np.spacing(np.abs(np.asarray(X, float))) / xs          # (Z, 6) scaled ulps
    ug = np.spacing(np.abs(np.asarray(G, float))) / gs          # (3,)
    balls = np.einsum("zij,zj->zi", np.abs(J.A), ux) + np.abs(J.B) @ ug      # (Z, 6)
    globals_ = np.einsum("zij,zj->i", np.abs(J.C), ux) + np.abs(J.Dg) @ ug  # (3,)
    return balls, globals_, J


def round_off_floor(system: Any, X: np.ndarray, G: np.ndarray) -> tuple[float, Any]:
    """(2-norm of the per-equation one-ulp floor of the scaled residual at (X, G), the
    Jacobian blocks it was taken from); (nan, None) when no analytic Jacobian exists there."""
    floors = equation_floors(system, X, G)
    if floors is None:
        return float("nan"), None
    balls, globals_, J = floors
    return float(np.sqrt(np.sum(balls**2) + np.sum(globals_**2))), J


def accept_at_round_off(system: Any, tol: float, errors: Iterable[BaseException]
                        ) -> tuple[np.ndarray, np.ndarray, float, float, Any] | None:
    """The best iterate that the failed attempts ``errors`` carry (``err.iterate`` = (X, G,
    norm), re-evaluated on ``system``, the target operating point) if its residual norm is
    at most max(tol, FLOOR_FACTOR x its one-ulp floor) and each global equation's residual
    at most max(tol, FLOOR_FACTOR x that equation's floor); else None. Returns (X, G, norm,
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
    floors = equation_floors(system, best[0], best[1])
    if floors is None:
        return None
    balls, globals_, J = floors
    floor = float(np.sqrt(np.sum(balls**2) + np.sum(globals_**2)))
    if not (np.isfinite(floor) and best[2] <= max(tol, FLOOR_FACTOR * floor)):
        return None
    # the equations that set the cage speed and the ring position: met to their own floor
    _, Gc, G0, _ = system.evaluate(best[0], best[1])
    ring_cage = np.abs(np.asarray(Gc, float).sum(axis=0) + np.asarray(G0, float))
    if not np.all(ring_cage <= np.maximum(tol, FLOOR_FACTOR * globals_)):
        return None
    return best[0], best[1], best[2], floor, J


__all__ = ["FLOOR_FACTOR", "accept_at_round_off", "equation_floors", "round_off_floor"]
