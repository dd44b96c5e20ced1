"""Seating of floating balls: a restart of the ball skidding Newton where a ball touches nothing.

One job: move every ball of an iterate that has no loaded contact onto the raceway arc its
force residual presses it against, at the Hertz approach that carries that force, and run
Newton again from there (:func:`seated_newton`, the first fallback of
:func:`~thermobearing.skidding.ball.solve_ball` after a failed cold start).

Why: a ball whose contacts are all open has, in the radial / axial rows of its force balance,
no stiffness but dF_c/db_r = m omega_c^2 (1e-6 N/m when the cage crawls). A lightly loaded
bearing whose cage nearly stops (SKF6304 at 963 r/min under 0.005 N radial: omega_c = 0.028
rad/s, CSR 2.7e-4) leaves the unloaded balls, placed by the race-control start for the
epicyclic cage speed, a few nanometres inside the outer groove after the cage slows down,
held by nothing against a centrifugal force of 5e-8 N. The Newton step across that gap is the
force over m omega_c^2 (the pitch radius), the cap cuts it to 20 um and the line search to a
step that lands within the 3e-12 m approach the force needs: Newton crawls and stalls at a
residual of F_c / F_s (1.2e-8 against the 1e-9 tolerance). Seated, the contact stiffness
1.5 K delta^0.5 makes the block regular and Newton converges in a few iterations.

The seat: for ball j with no contact load, arc k of the largest approach delta_k (the closest
arc), unit normal n_k from its centre to the ball centre; the force residual along it
F = F_s (R_a n_a + R_r n_r) [N] (the scaled residual's rows 0-1 are forces / F_s) is what the
contact must carry, so the ball moves along n_k by (F / K_k)^(2/3) - delta_k (Hertz,
Q = K delta^1.5, K of the arc at the current contact geometry). Only where F > 0, i.e. the
residual presses the ball into that arc. Units: m, N.
"""

from __future__ import annotations

import numpy as np

from ..errors import ConvergenceError
from .ball_residual_kernels import G_APPROACH, G_K, G_NA, G_NR, G_Q

__all__ = ["seat_floating_balls", "seated_newton"]


def seat_floating_balls(system, X: np.ndarray, G: np.ndarray) -> tuple[np.ndarray, int]:
    """(X with every floating ball seated, number of balls moved) -- module docstring.
    ``system``: :class:`~thermobearing.skidding.ball_residual.ball_residual_system`;
    X (Z, 6), G (3,) its unknowns (SI: m, rad/s, N)."""
    R, _, _, fields = system.evaluate_fields(np.asarray(X, float), np.asarray(G, float))
    geo = fields[0]                               # (N_GEO, Z, k)
    X = np.array(X, dtype=float, copy=True)
    moved = 0
    for j in range(X.shape[0]):
        if np.any(geo[G_Q, j] > 0.0):
            continue
        k = int(np.argmax(geo[G_APPROACH, j]))
        na, nr = float(geo[G_NA, j, k]), float(geo[G_NR, j, k])
        force = system.F_s * (float(R[j, 0]) * na + float(R[j, 1]) * nr)
        K = float(geo[G_K, j, k])
        if not (force > 0.0 and K > 0.0):
            continue
        shift = (force / K) ** (2.0 / 3.0) - float(geo[G_APPROACH, j, k])
        X[j, 0] += shift * na
        X[j, 1] += shift * nr
        moved += 1
    return X, moved


def seated_newton(system, err: ConvergenceError, *, tol: float, max_iter: int,
                  newton) -> tuple[np.ndarray, np.ndarray, float, int] | None:
    """Newton (``newton``: :func:`~thermobearing.skidding.ball_newton.newton_block`, passed
    in to keep the import graph flat) from the failed solve's last iterate (``err.iterate``)
    with its floating balls seated. Returns (X, G, residual norm, iterations), or None when
    no ball floats or that Newton fails too; in that case a better last iterate of it replaces
    ``err.iterate`` for the caller's next fallback."""
    last = getattr(err, "iterate", None)
    if last is None:
        return None
    X, G = np.asarray(last[0], float), np.asarray(last[1], float)
    if not (np.all(np.isfinite(X)) and np.all(np.isfinite(G))):
        return None
    try:
        Xs, moved = seat_floating_balls(system, X, G)
    except (FloatingPointError, ValueError):
        return None
    if moved == 0:
        return None
    try:
        return newton(system, Xs, G, tol=tol, max_iter=max_iter, stall_after=25)
    except ConvergenceError as err2:
        better = getattr(err2, "iterate", None)
        if better is not None and better[2] < last[2]:
            err.iterate = better
        return None
