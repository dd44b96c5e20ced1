"""A regularised (Levenberg-Marquardt) Newton step of the ball skidding system near a root.

One job: the step of :func:`~thermobearing.skidding.ball_newton.newton_block` close to a root
where the per-unknown step cap would cut the Newton step (``newton_block(near_root_below=...)``,
used by the fallbacks of :func:`~thermobearing.skidding.ball.solve_ball`).

Why: a ball held only by a centrifugal contact of ~1e-8 N when the cage nearly stops (7014C
at 4925 r/min under 0.005 N radial in -20 degC oil, CSR ~1e-4) has a saturated traction, so
its spin changes the scaled residual by less than 1e-10 over thousands of rad/s: the
Jacobian has one singular value of ~3e-12 per such ball (19 of 123), and the Newton step
asks those balls for spin changes of ~2000 rad/s to cancel residual components of ~1e-11.
The cap then scales the whole step to ~6 % and Newton crawls linearly (ratio 0.94: 280
iterations from 2.7e-6 to 1e-9, continuation steps give up); the uncapped step converges but
flings the spins of those balls to 1e14-1e30 rad/s over a few continuation steps (measured).
The regularised step leaves the directions the residual cannot see where they are and takes
the Newton step in the others. They are the near-null directions of single ball blocks A_z
(6 x 6, the ball's residual in its own unknowns), so the regularisation is per block, in
the block elimination of the Newton step (:func:`~thermobearing.skidding.ball_newton_kernels.
_block_step`) with the Tikhonov pseudo-inverse

    A_z^+ = V diag(s_k / (s_k^2 + mu_z^2)) U^T,   mu_z = rel s_max(A_z),

A_z = U diag(s) V^T, in place of A_z^-1: dG = S^-1 (-g + sum_z C_z A_z^+ R_z) with S = D -
sum_z C_z A_z^+ B_z, dX_z = -A_z^+ (R_z + B_z dG). A regular block (every s_k >> mu_z) gives
the Newton step. The residual components along the dropped directions stay (they are below
the tolerance where this is used). 6 x 6 decompositions: a dense SVD of the whole (6 Z + 3)
Jacobian cost 0.5 s of CPU on its first call (the threaded BLAS starting up). Units: scaled
unknowns and residual of :class:`~thermobearing.skidding.ball_residual.ball_residual_system`.
"""

from __future__ import annotations

import numpy as np

from .ball_newton_kernels import _block_step

__all__ = ["REL_REGULARISATION", "regularised_step"]

#: mu_z / s_max(A_z): directions of a ball block with singular values far below this are left
#: alone. The 7014C's free spins sit at ~1e-12 of s_max (measured)
REL_REGULARISATION = 1e-9


def regularised_step(blocks, R: np.ndarray, Gc: np.ndarray, Gk: np.ndarray,
                     rel: float = REL_REGULARISATION) -> tuple[np.ndarray, np.ndarray]:
    """(dX (Z, 6), dG (3,)) in scaled unknowns -- module docstring. ``blocks``:
    :class:`~thermobearing.skidding.ball_newton.JacobianBlocks` at the current state; R (Z,
    6) ball residuals, Gc (Z, 3) per-ball global contributions, Gk (3,) constant global part
    (scaled). Raises numpy.linalg.LinAlgError when the Schur complement is singular."""
    A, B, C, Dg = (np.asarray(m, float) for m in (blocks.A, blocks.B, blocks.C, blocks.Dg))
    U, s, Vt = np.linalg.svd(A)                                  # (Z, 6, 6), (Z, 6)
    mu = rel * s[:, :1]
    Apinv = np.einsum("zji,zj,zkj->zik", Vt, s / (s * s + mu * mu), U)
    AiB = Apinv @ B                                              # (Z, 6, 3)
    S = Dg - np.einsum("zgi,zih->gh", C, AiB)
    Sinv = np.linalg.inv(S)
    gres = np.asarray(Gc, float).sum(axis=0) + np.asarray(Gk, float)
    big = np.full(6, np.inf)
    dX, dG, _ = _block_step(np.ascontiguousarray(Apinv), np.ascontiguousarray(AiB),
                            np.ascontiguousarray(C), np.ascontiguousarray(Sinv),
                            np.ascontiguousarray(R, dtype=float), gres, big, big[:3])
    return dX, dG
