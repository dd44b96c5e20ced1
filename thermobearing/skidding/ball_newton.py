"""Newton driver of the ball skidding solver: damped Newton with block elimination.

One job: solve :class:`~thermobearing.skidding.ball_residual.ball_residual_system` from a
start (:func:`newton_block`). Numerics (issue 5 item 4): Newton with a structured
forward-difference Jacobian (:class:`JacobianBlocks`) -- the six per-ball columns are
perturbed for all balls at once (ball blocks are independent except through the globals),
three more evaluations give the global columns; the 6x6 ball blocks are eliminated and the
3x3 Schur complement on the globals is solved; backtracking line search on the scaled
residual norm. Failure raises ConvergenceError with the residual norm and the state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError
from .ball_residual import N_BALL, N_GLOBAL, ball_residual_system

__all__ = ["JacobianBlocks", "newton_block"]

# largest Newton step per scaled unknown (positions in microns, spins / (omega_i d_m / D),
# pocket force / F_s; ring displacement in microns, cage speed / omega_i)
_CAP_X = np.array([20.0, 20.0, 0.2, 0.2, 0.2, 5.0])
_CAP_G = np.array([20.0, 20.0, 0.1])


# ---------------------------------------------------------------------------------------------
# Newton with block elimination
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class JacobianBlocks:
    """Structured Jacobian of the scaled residual in the scaled unknowns.

    A (Z, 6, 6) ball blocks, B (Z, 6, 3) ball rows / global columns, C (Z, 3, 6) global
    rows / ball columns, Dg (3, 3); with the scales it was taken at (F_s, xs, gs) so that a
    later solve can reuse it as a chord Jacobian (:meth:`rescaled`).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    Dg: np.ndarray
    F_s: float
    xs: np.ndarray
    gs: np.ndarray
    Z: int

    def rescaled(self, system: ball_residual_system) -> JacobianBlocks:
        """The same physical Jacobian in the scaling of ``system``.

        Every residual row is divided by a multiple of F_s (forces F_s, moments F_s D/2,
        cage torque F_s d_m/2) and column c is multiplied by the unknown's scale, so
        J_new = J_old (F_s,old / F_s,new) (scale_new / scale_old) column by column.
        """
        xs, gs = system.scales()
        f = self.F_s / system.F_s
        rx, rg = f * xs / self.xs, f * gs / self.gs
        return JacobianBlocks(self.A * rx, self.B * rg, self.C * rx, self.Dg * rg, system.F_s,
                              xs, gs, self.Z)


def newton_block(system: ball_residual_system, X0: np.ndarray, G0: np.ndarray, *,
                 tol: float = 1e-9, max_iter: int = 60, fd_step: float = 1e-6,
                 max_step: float = 1.0, reuse_ratio: float = 0.25,
                 polish_ratio: float = 1e-2, give_up: tuple[int, float] | None = None,
                 jacobian: JacobianBlocks | None = None):
    """Damped Newton on (X, G) with the structured finite-difference Jacobian.

    The Jacobian (6x6 ball blocks, ball-global couplings, 3x3 Schur complement) needs
    N_BALL + N_GLOBAL = 9 perturbed states whatever Z is; they are evaluated as one batch
    (:meth:`ball_residual_system.evaluate` on (9, Z, 6)). It is reused for the next step
    (chord / Shamanskii step) while the full step cut the residual norm below
    ``reuse_ratio`` times its previous value; a stale step that does not reduce the norm is
    discarded and the Jacobian refreshed (good-Broyden updates of the chord Jacobian were
    tried and removed: no fewer iterations on +2 % warm steps, and they stalled a Z = 32
    cold start that plain chord steps solve in 41 iterations). A solve that ends on a
    linearly converging chord step takes one more (``polish_ratio``) so that the residual, and with
    it the energy balance, ends well below ``tol``. ``give_up = (n, f)``: raise
    ConvergenceError when the residual norm is still above f times its start after n
    iterations (used for warm starts, which then restart cold). ``jacobian``: blocks of an
    earlier solve (warm start, rescaled to this system by :meth:`JacobianBlocks.rescaled`)
    used as the first chord Jacobian. The last fresh Jacobian is left in ``system.last_jacobian``.

    Returns (X, G, residual_norm, iterations). Raises ConvergenceError.
    """
    xs, gs = system.scales()
    Z = system.Z
    X, G = X0.copy(), G0.copy()
    nb = N_BALL + N_GLOBAL
    eye_x = np.zeros((N_BALL, 1, N_BALL))
    eye_x[np.arange(N_BALL), 0, np.arange(N_BALL)] = fd_step * xs
    eye_g = np.zeros((nb, N_GLOBAL))
    eye_g[N_BALL + np.arange(N_GLOBAL), np.arange(N_GLOBAL)] = fd_step * gs

    def norm_of(R, Gc, Gk):
        return float(np.sqrt(np.sum(R * R) + np.sum((Gc.sum(0) + Gk) ** 2)))

    def jacobian_fd(X, G, R, Gc, Gk):
        Xb = np.empty((nb, Z, N_BALL))
        Xb[:] = X
        Xb[:N_BALL] += eye_x
        Gb = G + eye_g
        Rb, Gcb, Gkb, _ = system.evaluate(Xb, Gb)
        dR = (Rb - R) / fd_step                      # (9, Z, 6): column c in axis 0
        A = np.moveaxis(dR[:N_BALL], 0, -1)          # (Z, 6, 6)
        B = np.moveaxis(dR[N_BALL:], 0, -1)          # (Z, 6, 3)
        C = np.moveaxis((Gcb[:N_BALL] - Gc) / fd_step, 0, -1)   # (Z, 3, 6)
        Dg = (((Gcb[N_BALL:].sum(1) + Gkb[N_BALL:]) - (Gc.sum(0) + Gk)) / fd_step).T
        blocks = JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, Z)
        system.last_jacobian = blocks
        return factor(blocks, R, Gc, Gk, G)

    def factor(blocks, R, Gc, Gk, G):
        try:
            Ainv = np.linalg.inv(blocks.A)
        except np.linalg.LinAlgError:
            raise ConvergenceError("skidding.ball", norm_of(R, Gc, Gk), "singular ball block",
                                   {"cage_speed": G[2]}) from None
        Ainv_B = Ainv @ blocks.B
        S = blocks.Dg - np.einsum("zgi,zij->gj", blocks.C, Ainv_B)
        return Ainv, Ainv_B, blocks.C, S

    def step(jac, R, Gc, Gk):
        Ainv, Ainv_B, C, S = jac
        Ainv_R = np.einsum("zij,zj->zi", Ainv, R)
        rhs = -(Gc.sum(0) + Gk) + np.einsum("zgi,zi->g", C, Ainv_R)
        try:
            dG = np.linalg.solve(S, rhs)
        except np.linalg.LinAlgError:
            dG = np.linalg.lstsq(S, rhs, rcond=None)[0]
        return -Ainv_R - np.einsum("zij,j->zi", Ainv_B, dG), dG

    R, Gc, Gk, _ = system.evaluate(X, G)
    nrm = norm_of(R, Gc, Gk)
    it = 0
    jac = None
    if jacobian is not None and jacobian.Z == Z:
        system.last_jacobian = jacobian.rescaled(system)
        if nrm > tol:
            try:
                jac = factor(system.last_jacobian, R, Gc, Gk, G)
            except ConvergenceError:
                jac = None
    last_ratio, polished, nrm0 = 1.0, False, nrm
    while it < max_iter:
        if nrm <= tol:
            # a chord iteration converges linearly and stops just below tol,
            # where a Newton step would overshoot by orders of magnitude: one more step
            # with the current Jacobian (the energy balance closes with the residual)
            if polished or last_ratio < polish_ratio or jac is None:
                break
            polished = True
        if give_up is not None and it >= give_up[0] and nrm > give_up[1] * nrm0:
            raise ConvergenceError("skidding.ball", nrm, f"slow progress: residual still "
                                   f"{nrm / nrm0:.2f} x its start after {it} iterations",
                                   {"iteration": it, "cage_speed": G[2]})
        it += 1
        stale = jac is not None
        if jac is None:
            jac = jacobian_fd(X, G, R, Gc, Gk)
        dX, dG = step(jac, R, Gc, Gk)
        big = max(np.max(np.abs(dX) / _CAP_X), np.max(np.abs(dG) / _CAP_G))
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        if stale:
            # chord step: full step only (a step the cap would shorten refreshes
            # the Jacobian: measured, capped chord steps can stall a cold start), accepted
            # if it reduces the norm, else discarded and the Jacobian refreshed
            ok, nn = False, np.inf
            if lam == 1.0:
                try:
                    Rn, Gcn, Gkn, _ = system.evaluate(X + dX * xs, G + dG * gs)
                    nn = norm_of(Rn, Gcn, Gkn)
                    ok = bool(np.isfinite(nn) and nn < nrm)
                except (InputError, FloatingPointError, ValueError):
                    ok = False
            if ok:
                X, G, R, Gc, Gk = X + dX * xs, G + dG * gs, Rn, Gcn, Gkn
                if nn > reuse_ratio * nrm:
                    jac = None
                nrm, last_ratio = nn, nn / nrm
            else:
                jac = None
                it -= 1
            continue
        while True:
            Xn = X + lam * dX * xs
            Gn = G + lam * dG * gs
            ok = True
            try:
                Rn, Gcn, Gkn, _ = system.evaluate(Xn, Gn)
                nn = norm_of(Rn, Gcn, Gkn)
                ok = np.isfinite(nn)
            except (InputError, FloatingPointError, ValueError):
                ok, nn = False, np.inf
            if ok and (nn < (1 - 1e-4 * lam) * nrm or lam < 1e-3):
                break
            lam *= 0.5
            if lam < 1e-6:
                break
        if not ok or lam < 1e-6:
            raise ConvergenceError("skidding.ball", nrm, "line search failed",
                                   {"iteration": it, "cage_speed": G[2]})
        if not (lam == 1.0 and nn < reuse_ratio * nrm):
            jac = None
        X, G, R, Gc, Gk, nrm, last_ratio = Xn, Gn, Rn, Gcn, Gkn, nn, nn / nrm
    if not nrm <= tol:
        raise ConvergenceError("skidding.ball", nrm, f"no convergence in {max_iter} iterations",
                               {"cage_speed": G[2], "delta_a": G[0], "delta_r": G[1]})
    return X, G, nrm, it
