"""Newton driver of the ball skidding solver: damped Newton with block elimination.

One job: solve :class:`~thermobearing.skidding.ball_residual.ball_residual_system` from a
start (:func:`newton_block`). Numerics (issue 5 item 4): Newton with a structured Jacobian
(:class:`JacobianBlocks`), analytic (:mod:`~thermobearing.skidding.ball_jacobian`, session 7)
where the default compiled models run, else by forward differences -- the six per-ball
columns are perturbed for all balls at once (ball blocks are independent except through the
globals), three more evaluations give the global columns; the 6x6 ball blocks are eliminated
and the 3x3 Schur complement on the globals is solved; backtracking line search on the scaled
residual norm. Warm starts take chord / good-Broyden steps with the handed-over Jacobian in
one compiled loop (:func:`_chord_phase`). Failure raises ConvergenceError with the residual
norm and the state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from ..contact_traction import refresh_stale_caches
from ..errors import ConvergenceError, InputError
from .ball_jacobian import analytic_blocks, supports_analytic
from .ball_residual import N_BALL, N_GLOBAL, _residual_one, ball_residual_system

__all__ = ["JacobianBlocks", "chord_polish", "newton_block", "trust_region"]

# largest Newton step per scaled unknown (positions in microns, spins / (omega_i d_m / D),
# pocket force / F_s; ring displacement in microns, cage speed / omega_i). Spins 0.5 (0.2
# until session 5): light-load cold starts crept at the cap, every damped step scaled to
# 1/5 of the Newton step by one ball's axial spin, with a fresh Jacobian each time (12 such
# iterations at 300 r/min, Fa = 0, hot oil). Measured on 540 cold starts (Z = 8/16/32,
# 300-3000 r/min x 10, Fa = 0 and 200 N-40 kN x 8, cold and hot oil, newton_block alone):
# 0.2: 2 failures, 52993 evaluations; 0.5: none, 45315; 1.0: failures (3 of 120 on the
# 5 x 5 maps).
_CAP_X = np.array([20.0, 20.0, 0.5, 0.5, 0.5, 5.0])
_CAP_G = np.array([20.0, 20.0, 0.1])
_NO_HIST = np.empty((0, 0))


@numba.njit(cache=True)
def _block_step(Ainv: np.ndarray, Ainv_B: np.ndarray, C: np.ndarray, Sinv: np.ndarray,
                R: np.ndarray, gres: np.ndarray, cap_x: np.ndarray,
                cap_g: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Newton step by block elimination (compiled): with the factors of :func:`newton_block`
    (A^-1, A^-1 B, C, S^-1, S = D - C A^-1 B), ball residuals R (Z, 6) and global residuals
    ``gres`` (3,):  dG = S^-1 (-g + sum_z C_z A_z^-1 R_z),  dX_z = -A_z^-1 (R_z + B_z dG).
    Also returns max |step| / cap over all unknowns."""
    nz, nb = R.shape
    ng = gres.size
    air = np.empty((nz, nb))
    rhs = -gres.copy()
    for z in range(nz):
        for i in range(nb):
            acc = 0.0
            for j in range(nb):
                acc += Ainv[z, i, j] * R[z, j]
            air[z, i] = acc
        for g in range(ng):
            acc = 0.0
            for i in range(nb):
                acc += C[z, g, i] * air[z, i]
            rhs[g] += acc
    dG = np.empty(ng)
    big = 0.0
    for g in range(ng):
        acc = 0.0
        for h in range(ng):
            acc += Sinv[g, h] * rhs[h]
        dG[g] = acc
        big = max(big, abs(acc) / cap_g[g])
    dX = np.empty((nz, nb))
    for z in range(nz):
        for i in range(nb):
            acc = air[z, i]
            for g in range(ng):
                acc += Ainv_B[z, i, g] * dG[g]
            dX[z, i] = -acc
            big = max(big, abs(dX[z, i]) / cap_x[i])
    return dX, dG, big


@numba.njit(cache=True)
def _inverse_small(M: np.ndarray) -> tuple[np.ndarray, bool]:
    """Inverse of a small square matrix (a 6x6 ball block, the 3x3 Schur complement) by
    Gauss-Jordan with partial pivoting, compiled (numpy's inv costs ~15 us of Python per
    call). Returns (M^-1, ok); ok is False for a zero or non-finite pivot (the caller then
    falls back to numpy's inv / pinv, or reports the singular ball block)."""
    n = M.shape[0]
    w = np.empty((n, 2 * n))
    for i in range(n):
        for j in range(n):
            w[i, j] = M[i, j]
            w[i, n + j] = 1.0 if i == j else 0.0
    out = np.empty((n, n))
    for col in range(n):
        piv = col
        best = abs(w[col, col])
        for r in range(col + 1, n):
            if abs(w[r, col]) > best:
                best = abs(w[r, col])
                piv = r
        if not (best > 0.0 and math.isfinite(best)):
            return out, False
        if piv != col:
            for j in range(2 * n):
                t = w[col, j]
                w[col, j] = w[piv, j]
                w[piv, j] = t
        inv_p = 1.0 / w[col, col]
        for j in range(2 * n):
            w[col, j] *= inv_p
        for r in range(n):
            if r != col:
                f = w[r, col]
                if f != 0.0:
                    for j in range(2 * n):
                        w[r, j] -= f * w[col, j]
    for i in range(n):
        for j in range(n):
            out[i, j] = w[i, n + j]
    return out, True


@numba.njit(cache=True)
def _factor_blocks(A: np.ndarray, B: np.ndarray, C: np.ndarray, Dg: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """Factors of the block elimination (compiled): A_z^-1 (Z, 6, 6) by Gauss-Jordan with
    partial pivoting (:func:`_inverse_small`), A_z^-1 B_z (Z, 6, 3) and the Schur complement
    S = D - sum_z C_z A_z^-1 B_z (3, 3). Returns (Ainv, Ainv_B, S, ok); ok is False when a
    ball block is singular (a zero or non-finite pivot)."""
    nz, nb, ng = A.shape[0], A.shape[1], B.shape[2]
    Ainv = np.empty((nz, nb, nb))
    AiB = np.empty((nz, nb, ng))
    S = Dg.copy()
    for z in range(nz):
        inv, ok = _inverse_small(A[z])
        if not ok:
            return Ainv, AiB, S, False
        Ainv[z] = inv
        for i in range(nb):
            for g in range(ng):
                acc = 0.0
                for j in range(nb):
                    acc += Ainv[z, i, j] * B[z, j, g]
                AiB[z, i, g] = acc
        for g in range(ng):
            for h in range(ng):
                acc = 0.0
                for i in range(nb):
                    acc += C[z, g, i] * AiB[z, i, h]
                S[g, h] -= acc
    return Ainv, AiB, S, True


@numba.njit(cache=True)
def _fd_blocks(Rb: np.ndarray, Gcb: np.ndarray, Gkb: np.ndarray, R: np.ndarray,
               Gc: np.ndarray, Gk: np.ndarray, h: float
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Forward-difference blocks of the structured Jacobian (compiled) from the batch of
    N_BALL + N_GLOBAL perturbed states (state c = unknown c perturbed by h in scaled units,
    for every ball at once): A (Z, 6, 6) = dR_z/dx_z, B (Z, 6, 3) = dR_z/dG, C (Z, 3, 6) =
    dGc_z/dx_z, Dg (3, 3) = d(sum_z Gc_z + Gk)/dG."""
    nbx, nz, nb = Rb.shape[0] - Gkb.shape[1], R.shape[0], R.shape[1]
    ng = Gk.size
    A = np.empty((nz, nb, nb))
    B = np.empty((nz, nb, ng))
    C = np.empty((nz, ng, nb))
    Dg = np.empty((ng, ng))
    for z in range(nz):
        for i in range(nb):
            for c in range(nbx):
                A[z, i, c] = (Rb[c, z, i] - R[z, i]) / h
            for g in range(ng):
                B[z, i, g] = (Rb[nbx + g, z, i] - R[z, i]) / h
        for g in range(ng):
            for c in range(nbx):
                C[z, g, c] = (Gcb[c, z, g] - Gc[z, g]) / h
    for g in range(ng):
        base = Gk[g]
        for z in range(nz):
            base += Gc[z, g]
        for gg in range(ng):
            t = Gkb[nbx + gg, g]
            for z in range(nz):
                t += Gcb[nbx + gg, z, g]
            Dg[g, gg] = (t - base) / h
    return A, B, C, Dg


@numba.njit(cache=True)
def _residual_norm(R: np.ndarray, Gc: np.ndarray, Gk: np.ndarray) -> float:
    """sqrt(|R|^2 + |sum_z Gc_z + Gk|^2) of one state (compiled)."""
    acc = 0.0
    for z in range(R.shape[0]):
        for i in range(R.shape[1]):
            acc += R[z, i] * R[z, i]
    for g in range(Gk.size):
        t = Gk[g]
        for z in range(Gc.shape[0]):
            t += Gc[z, g]
        acc += t * t
    return math.sqrt(acc)


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
        A, B, C, Dg = _rescale_blocks(self.A, self.B, self.C, self.Dg, self.F_s / system.F_s,
                                      xs, self.xs, gs, self.gs)
        return JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, self.Z)


@numba.njit(cache=True)
def _rescale_blocks(A: np.ndarray, B: np.ndarray, C: np.ndarray, Dg: np.ndarray, f: float,
                    xs: np.ndarray, xs_old: np.ndarray, gs: np.ndarray, gs_old: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:meth:`JacobianBlocks.rescaled` compiled (session 8; six numpy operations cost ~20 us):
    column c of every block times (f xs_c) / xs_old_c (ball columns) or (f gs_g) / gs_old_g
    (global columns), the same operations as the numpy expressions it replaces."""
    nz, nb, ng = A.shape[0], A.shape[1], B.shape[2]
    rx = np.empty(nb)
    rg = np.empty(ng)
    for c in range(nb):
        rx[c] = f * xs[c] / xs_old[c]
    for g in range(ng):
        rg[g] = f * gs[g] / gs_old[g]
    A2 = np.empty_like(A)
    B2 = np.empty_like(B)
    C2 = np.empty_like(C)
    Dg2 = np.empty_like(Dg)
    for z in range(nz):
        for i in range(nb):
            for c in range(nb):
                A2[z, i, c] = A[z, i, c] * rx[c]
            for g in range(ng):
                B2[z, i, g] = B[z, i, g] * rg[g]
        for g in range(ng):
            for c in range(nb):
                C2[z, g, c] = C[z, g, c] * rx[c]
    for g in range(ng):
        for h in range(ng):
            Dg2[g, h] = Dg[g, h] * rg[h]
    return A2, B2, C2, Dg2


@numba.njit(cache=True)
def _broyden_step(hist: np.ndarray, m: int, dX: np.ndarray, dG: np.ndarray,
                  cap_x: np.ndarray, cap_g: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Good-Broyden step from the chord step z = -J0^-1 F(x_n+1) and the previous steps
    s_0..s_n = hist[:m] (scaled unknowns), Kelley 1995 (Iterative Methods for Linear and
    Nonlinear Equations, SIAM, algorithm ``brsol`` with full steps):
    z <- z + s_(j+1) (s_j . z) / |s_j|^2 (j < n), then s_(n+1) = z / (1 - s_n . z / |s_n|^2).
    Returns (dX, dG, max |step| / cap); big = -1 when the denominator is below 0.1 (the
    caller then takes the plain chord step and starts a new history)."""
    nz, nb = dX.shape
    ng = dG.size
    n = nz * nb + ng
    z = np.empty(n)
    z[:nz * nb] = dX.ravel()
    z[nz * nb:] = dG
    for j in range(m - 1):
        dot = 0.0
        nrm = 0.0
        for i in range(n):
            dot += hist[j, i] * z[i]
            nrm += hist[j, i] * hist[j, i]
        f = dot / nrm
        for i in range(n):
            z[i] += hist[j + 1, i] * f
    dot = 0.0
    nrm = 0.0
    for i in range(n):
        dot += hist[m - 1, i] * z[i]
        nrm += hist[m - 1, i] * hist[m - 1, i]
    den = 1.0 - dot / nrm
    if abs(den) < 0.1:
        return dX, dG, -1.0
    big = 0.0
    out_x = np.empty((nz, nb))
    out_g = np.empty(ng)
    for a in range(nz):
        for b in range(nb):
            v = z[a * nb + b] / den
            out_x[a, b] = v
            big = max(big, abs(v) / cap_x[b])
    for g in range(ng):
        v = z[nz * nb + g] / den
        out_g[g] = v
        big = max(big, abs(v) / cap_g[g])
    return out_x, out_g, big


@numba.njit(cache=True)
def _propose(Ainv: np.ndarray, Ainv_B: np.ndarray, C: np.ndarray, Sinv: np.ndarray,
             R: np.ndarray, Gc: np.ndarray, Gk: np.ndarray, cap_x: np.ndarray,
             cap_g: np.ndarray, hist: np.ndarray, m: int, xs: np.ndarray, gs: np.ndarray,
             X: np.ndarray, G: np.ndarray) -> tuple:
    """One Newton-type step in one compiled call: the global residual sum_z Gc_z + Gk, the
    block-elimination step (:func:`_block_step`), with m > 0 its good-Broyden correction
    from the history (:func:`_broyden_step`), and the full-step state X + dX xs, G + dG gs.
    Returns (dX, dG, max |step| / cap, X_new, G_new, degenerate) with degenerate True when
    the Broyden denominator was too small (the plain step is returned; the caller starts a
    new history)."""
    nz, nb = R.shape
    ng = Gk.size
    gres = np.empty(ng)
    for g in range(ng):
        t = Gk[g]
        for z in range(nz):
            t += Gc[z, g]
        gres[g] = t
    dX, dG, big = _block_step(Ainv, Ainv_B, C, Sinv, R, gres, cap_x, cap_g)
    degenerate = False
    if m > 0:
        bX, bG, bbig = _broyden_step(hist, m, dX, dG, cap_x, cap_g)
        if bbig < 0.0:
            degenerate = True
        else:
            dX, dG, big = bX, bG, bbig
    Xn = np.empty((nz, nb))
    for z in range(nz):
        for i in range(nb):
            Xn[z, i] = X[z, i] + dX[z, i] * xs[i]
    Gn = np.empty(ng)
    for g in range(ng):
        Gn[g] = G[g] + dG[g] * gs[g]
    return dX, dG, big, Xn, Gn, degenerate


_PH_DONE, _PH_REFRESH, _PH_HANDBACK = 0, 1, 2


@numba.njit(cache=True)
def _torque_model(tq: np.ndarray, wc: float) -> tuple[float, float]:
    """The constant cage-torque residual g0_2 = -(t_churn + t_guide) / T_s and the drag term
    fd (drag force at the drag radius times that radius) at cage speed wc from the model of
    :func:`_run_chord_phase`: t_churn = t_c0 (wc/wc0)^p (paper 002 eqs. 12-15: mu_v is a power
    of N_Re in each flow regime, so the churning torque mu_v omega^2 is a power of omega) or
    linear, t_guide linear (Petroff, paper 002 eq. 5), fd = fd_0 (wc/wc0)^q (q = 2 for the
    drag of eq. 10) or linear."""
    wc0 = tq[0]
    d = wc - wc0
    ratio = math.log(wc / wc0) if wc / wc0 > 0.0 else 0.0
    tc = tq[2] * math.exp(tq[3] * ratio) if tq[9] == 1.0 else tq[2] + tq[3] * d
    fd = tq[6] * math.exp(tq[7] * ratio) if tq[10] == 1.0 else tq[6] + tq[7] * d
    return -(tc + tq[4] + tq[5] * d) / tq[8], fd


@numba.njit(cache=True)
def _chord_phase(Ainv, AiB, C, Sinv, X, G, R, Gc, G0, nrm, hist, m, xs, gs, cap_x, cap_g,
                 tol, polish_ratio, polish_below, keep_ratio, refresh_rate, it, max_iter,
                 give_n, give_f, nrm0, last_ratio, polished, tq, cpsi, arc, c, film_params,
                 law_id, law_params, ln_tab, slope_tab, inv_dp, p_max, xg, yg, pshape,
                 area_w, pidx, pshape_u):
    """The chord / good-Broyden iterations of a warm start (:func:`newton_block` with the
    handed-over Jacobian) in one compiled loop: the same step (:func:`_propose`), residual
    (``ball_residual._residual_one``) and acceptance rules as the Python loop, without its
    per-iteration interpreter cost (~30 us against ~85 us of residual, measured). The cage
    and drag torques of the Python models enter through a model in the cage speed about
    tq[0] (``tq`` = (omega_c0, half-width of the range, churning torque t_c0 and exponent
    (or slope), guide torque t_g0 and slope, drag term fd_0 and exponent (or slope), T_s,
    1/0 power law / linear for the churning torque, the same for the drag; see
    :func:`_torque_model`); the caller replaces them by the exact values at the end.

    Hands back (status 2, nothing done for the step) before anything the Python loop does
    differently: a damped step (the cap), a cage speed outside the model range, the staged
    residual path or non-finite unknowns, the give-up test. Status 0: converged by the
    Python loop's rule; 1: the Jacobian is to be refreshed (a rejected chord step, a poor
    contraction, or the ``refresh_rate`` rule of :func:`newton_block`'s ``warm_refresh``).
    Returns (status, X, G, R, Gc, G0, norm, m, iterations, evaluations, last_ratio, polished,
    accepted, geo, film, tr, pocket, Fd) with the fields of the last accepted state."""
    n_eval = 0
    status = _PH_HANDBACK
    geo = np.empty((0, 0))
    film = np.empty(0)
    tr = np.empty((0, 6))
    pocket = np.empty((0, 7))
    Fd = np.empty(0)
    no_fd = np.empty(0)
    accepted = False
    wc_c, rng = tq[0], tq[1]
    nb = X.shape[0] * X.shape[1]
    while it < max_iter:
        if nrm <= tol:
            if polished or last_ratio < polish_ratio or nrm <= polish_below:
                status = _PH_DONE
                break
            polished = True
        if give_n >= 0 and it >= give_n and nrm > give_f * nrm0:
            break
        dX, dG, big, Xf, Gf, degenerate = _propose(Ainv, AiB, C, Sinv, R, Gc, G0, cap_x, cap_g,
                                                   hist, m, xs, gs, X, G)
        if degenerate:
            m = 0
        if big > 1.0:
            break
        d = Gf[2] - wc_c
        if abs(d) > rng:
            break
        G0n = np.empty(3)
        G0n[0] = G0[0]
        G0n[1] = G0[1]
        G0n[2], fd_num = _torque_model(tq, Gf[2])
        st, Rn, Gcn, nn, geo_n, film_n, tr_n, pocket_n, Fd_n = _residual_one(
            Xf, Gf, cpsi, arc, c, film_params, law_id, law_params, ln_tab, slope_tab, inv_dp,
            p_max, xg, yg, pshape, area_w, pidx, pshape_u, fd_num, no_fd, G0n)
        if st != 0:
            break
        n_eval += 1
        if math.isfinite(nn) and nn < nrm:
            it += 1
            X, G, R, Gc, G0 = Xf, Gf, Rn, Gcn, G0n
            geo, film, tr, pocket, Fd = geo_n, film_n, tr_n, pocket_n, Fd_n
            accepted = True
            refresh = nn > keep_ratio * nrm
            if not refresh and m < hist.shape[0]:
                for i in range(dX.shape[0]):
                    for j in range(dX.shape[1]):
                        hist[m, i * dX.shape[1] + j] = dX[i, j]
                for g in range(dG.size):
                    hist[m, nb + g] = dG[g]
                m += 1
            if (not refresh and refresh_rate > 0.0 and nn > polish_below
                    and math.log(polish_below / nn) < refresh_rate * math.log(nn / nrm)):
                refresh = True
            last_ratio = nn / nrm
            nrm = nn
            if refresh:
                status = _PH_REFRESH
                break
        else:
            status = _PH_REFRESH         # a chord step that does not lower the norm
            break
    return (status, X, G, R, Gc, G0, nrm, m, it, n_eval, last_ratio, polished, accepted, geo,
            film, tr, pocket, Fd)



def _refresh_caches() -> None:
    """numba's cache does not see edits of compiled callees in other files (see
    :func:`thermobearing.contact_traction.refresh_stale_caches`): the chord phase compiles
    the residual kernel into itself, so its cache follows the residual's modules."""
    from .. import contact_traction, film, hertz, traction
    from . import ball_residual

    refresh_stale_caches("ball_newton", (_block_step, _inverse_small, _factor_blocks,
                                         _fd_blocks, _residual_norm, _broyden_step, _propose,
                                         _torque_model, _chord_phase, _rescale_blocks,
                                         _exact_torques),
                         (contact_traction, traction, hertz, film, ball_residual))



@numba.njit(cache=True)
def _exact_torques(R: np.ndarray, Gc: np.ndarray, X: np.ndarray, Fd: np.ndarray,
                   fd_num: float, F_s: float, g0a: float, g0r: float, g0c: float) -> tuple:
    """The chord phase's returned state with the exact cage / drag torques (compiled; the
    numpy version cost ~10 us): the ball drag F_d = fd_num / b_r in the tangential ball rows
    (R_t = (F_t - F_d + Q_p) / F_s, so R_t += (F_d,model - F_d) / F_s), the constant global
    residual (g0a, g0r, g0c) and the norm. Returns (R, G0, F_d, norm); R is a new array."""
    nz = X.shape[0]
    R2 = R.copy()
    Fd_exact = np.empty(nz)
    for j in range(nz):
        Fd_exact[j] = fd_num / X[j, 1]
        R2[j, 2] += (Fd[j] - Fd_exact[j]) / F_s
    Gk = np.empty(3)
    Gk[0], Gk[1], Gk[2] = g0a, g0r, g0c
    return R2, Gk, Fd_exact, _residual_norm(R2, Gc, Gk)

def _run_chord_phase(system, kargs, jac, X, G, R, Gc, Gk, nrm, hist, m, it, *, tol,
                     polish_ratio, polish_below, keep_ratio, refresh_rate, max_iter, give_up,
                     nrm0, last_ratio, polished):
    """:func:`_chord_phase` with the torque model (:func:`_torque_model`) fitted to the Python
    models' exact values at omega_c0 and omega_c0 + h (h = 1e-3 omega_c0; the churning torque
    and the drag term as powers of omega_c when both values have one sign, else linear; the
    guide torque linear), used within +-10 % of omega_c0, and the exact torques put back at
    the returned state (its residual and norm are then those of
    :meth:`ball_residual_system.evaluate`, and it becomes the system's last state). For the
    default models (paper 002 eqs. 5, 10, 12-15) the model is exact within one flow regime
    to round-off; for others, or across a regime change, the exact residual at the end is
    larger than the phase's and the Python loop goes on from there. The model is kept on the
    system (``_torque_fit``, shared with its ``reloaded`` copies) and reused while omega_c0 is
    within 5 % of the centre it was fitted at (session 8)."""
    wc0 = float(G[2])
    held = system._torque_fit
    if held and abs(wc0 - held[0]) <= 0.05 * abs(held[0]):
        # the model of an earlier solve of this system (the same models and speed: a warm
        # start's system shares it, see ``reloaded``), centred within 5 % of wc0: exact for
        # the default models within a flow regime, so refitting would give the same model
        # (session 8: saves a Python torque evaluation per warm start)
        tq = held[1].copy()
        tq[8] = system.T_s
    else:
        h = 1e-3 * max(abs(wc0), 1e-3 * system.w_s)
        t0, t1 = system._cage_torques(wc0), system._cage_torques(wc0 + h)
        lr = math.log1p(h / wc0) if wc0 != 0.0 else 0.0

        def fit(a, b):
            # (value, exponent, 1.0) for a power law through both points, else (value,
            # slope, 0.0)
            if lr != 0.0 and a != 0.0 and b / a > 0.0:
                return a, math.log(b / a) / lr, 1.0
            return a, (b - a) / h, 0.0

        tc, pc, pw_c = fit(t0[0], t1[0])
        fd, pf, pw_f = fit(t0[3], t1[3])
        tq = np.array([wc0, 0.1 * abs(wc0), tc, pc, t0[1], (t1[1] - t0[1]) / h, fd, pf,
                       system.T_s, pw_c, pw_f])
        held[:] = [wc0, tq.copy()]
    give_n, give_f = give_up if give_up is not None else (-1, 0.0)
    (status, X, G, R, Gc, G0m, nrm_m, m, it, n_ev, last_ratio, polished, accepted, geo, film,
     tr, pocket, Fd) = _chord_phase(*jac, X, G, R, Gc, Gk, nrm, hist, m, *system.scales(),
                                    _CAP_X, _CAP_G, tol, polish_ratio, polish_below,
                                    keep_ratio, refresh_rate, it, max_iter, give_n, give_f,
                                    nrm0, last_ratio, polished, tq, *kargs)
    system.n_eval += n_ev
    if accepted:
        t = system._cage_torques(float(G[2]))
        R, Gk, Fd_exact, nrm = _exact_torques(R, Gc, X, Fd, t[3], system.F_s, system._g0a,
                                              system._g0r, -(t[0] + t[1]) / system.T_s)
        system.store_last(X, G, R, Gc, Gk, nrm, geo, film, tr, pocket, Fd_exact, t[4])
    return status, X, G, R, Gc, Gk, nrm, m, it, last_ratio, polished


def newton_block(system: ball_residual_system, X0: np.ndarray, G0: np.ndarray, *,
                 tol: float = 1e-9, max_iter: int = 60, fd_step: float = 1e-7,
                 max_step: float = 1.0, reuse_ratio: float = 0.25,
                 polish_ratio: float = 1e-2, give_up: tuple[int, float] | None = None,
                 jacobian: JacobianBlocks | None = None, broyden_warm: bool = True,
                 polish_below: float = 0.2e-9, broyden_reuse_ratio: float = 0.5,
                 stall_after: int = 0, analytic: bool = True, warm_refresh: float = 0.0,
                 compiled_chord: bool = True):
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

    Warm starts (``jacobian`` given, ``broyden_warm``): while that handed-over Jacobian is in
    use, the chord steps are good-Broyden steps (:func:`_broyden_step`, Kelley's stored-step
    form; the chord iteration contracted only ~5x per step on +2 % load steps) and are kept
    while each cuts the norm below ``broyden_reuse_ratio`` (0.5, measured on the BM-5 quick
    map: 0.25 -> 0.5 saved 11 % of the evaluations of the +2 % steps in cold oil, 0.7 lost
    some again); a fresh Jacobian ends the Broyden phase. The polishing step is skipped
    when the norm is already below ``polish_below`` (the energy balance closes to ~1e-9).

    ``fd_step``: forward-difference step in scaled unknowns (1e-7; 1e-6 until session 5). With
    1e-6 some states got a Jacobian poor enough that Newton with a fresh Jacobian at every
    iterate converged only linearly (ratio 0.55: QJ1044, Z = 16, 600 r/min, 1 kN, hot oil),
    and the Z = 32 hot-oil cold starts at 300 r/min, 200 N and 0 N needed a load continuation
    that ended at the 150-iteration limit (one of them failed); with 1e-7 (and 1e-8) those
    converge quadratically, the 120 cold starts of the BM-5 5 x 5 maps (Z = 8, 16, 32, cold and
    hot oil) all converge without continuation, with 3-9 % fewer evaluations at Z = 8/16.

    ``stall_after``: raise ConvergenceError after that many consecutive damped steps shorter
    than 1e-2 of the Newton step that each lower a norm already below 1e-2 by less than 1 %
    (0: never; :func:`~thermobearing.skidding.ball.solve_ball` uses 25 for cold starts and
    then calls :func:`trust_region`; 8 cut two slow cold starts of the BM-5 maps that converge
    in 33 iterations, and 16 was the least that kept them). Every ConvergenceError for too
    many iterations, a failed line search or a stall carries the last iterate as
    ``err.iterate = (X, G, norm)``.

    ``analytic`` (session 7): a fresh Jacobian is the analytic one of
    :func:`~thermobearing.skidding.ball_jacobian.analytic_blocks` (forward-mode derivatives
    through the compiled residual; about 2-3 residual evaluations of CPU instead of the
    batch of nine perturbed states) when the system's models have it, else the finite
    differences. Counted in ``system.n_jac``, not in ``n_eval``.

    ``warm_refresh`` (session 7, warm starts with the analytic Jacobian): after an accepted
    chord / Broyden step with contraction rho = |F_new| / |F_old|, the steps still needed at
    that rate are log(polish_below / |F_new|) / log(rho); when that exceeds ``warm_refresh``
    the handed-over Jacobian is dropped and an analytic one taken at the current iterate
    (Newton then converges in 1-2 evaluations). 0 disables it (the default of
    :func:`~thermobearing.skidding.ball.solve_ball`). Measured on the BM-5 maps (Z = 16, +2 %
    steps): it saves evaluations (5 x 5 map, a Jacobian counted as 2.3 evaluations: off 6.5 /
    6.35, 4: 6.1 / 5.9 cold / hot oil) but not CPU -- interleaved in one process, 4 cost 6-12 %
    more than off on the 20 x 20 map (1.24 / 1.02 against 1.11 / 0.93 ms) and 3-6 % more on the
    5 x 5 map: a refresh costs more than its 2-2.2 evaluations of kernel time (the Newton step
    after it and the torque models run outside the compiled chord loop).

    Returns (X, G, residual_norm, iterations). Raises ConvergenceError.
    """
    xs, gs = system.scales()
    Z = system.Z
    X, G = X0.copy(), G0.copy()
    nb = N_BALL + N_GLOBAL
    norm_of = _residual_norm

    def jacobian_fd(X, G, R, Gc, Gk):
        blocks = analytic_blocks(system, X, G) if analytic else None
        if blocks is not None:
            system.n_jac += 1
            system.last_jacobian = blocks
            return factor(blocks, R, Gc, Gk, G)
        eye_x = np.zeros((N_BALL, 1, N_BALL))
        eye_x[np.arange(N_BALL), 0, np.arange(N_BALL)] = fd_step * xs
        eye_g = np.zeros((nb, N_GLOBAL))
        eye_g[N_BALL + np.arange(N_GLOBAL), np.arange(N_GLOBAL)] = fd_step * gs
        Xb = np.empty((nb, Z, N_BALL))
        Xb[:] = X
        Xb[:N_BALL] += eye_x
        Gb = G + eye_g
        Rb, Gcb, Gkb, _ = system.evaluate(Xb, Gb)
        A, B, C, Dg = _fd_blocks(Rb, Gcb, Gkb, R, Gc, Gk, fd_step)
        blocks = JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, Z)
        system.last_jacobian = blocks
        return factor(blocks, R, Gc, Gk, G)

    def factor(blocks, R, Gc, Gk, G):
        C = np.ascontiguousarray(blocks.C)
        Ainv, Ainv_B, S, ok = _factor_blocks(np.ascontiguousarray(blocks.A),
                                             np.ascontiguousarray(blocks.B), C,
                                             np.ascontiguousarray(blocks.Dg))
        if not ok:
            raise ConvergenceError("skidding.ball", norm_of(R, Gc, Gk), "singular ball block",
                                   {"cage_speed": G[2]})
        Sinv, ok = _inverse_small(S)
        if not ok:
            try:
                Sinv = np.linalg.inv(S)
            except np.linalg.LinAlgError:
                Sinv = np.linalg.pinv(S)   # least-squares step of a singular Schur complement
        return Ainv, Ainv_B, C, np.ascontiguousarray(Sinv)

    can_analytic = analytic and supports_analytic(system)
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
    crawl = 0
    # Broyden (good) updates of the warm start's chord Jacobian, in Kelley's stored-step
    # form: only while the Jacobian handed over from the previous solve is in use
    broyden = jac is not None and broyden_warm
    hist = np.empty((max_iter + 1, Z * N_BALL + N_GLOBAL)) if broyden else None
    m = 0                                     # steps in the Broyden history
    kargs = system.chord_kernel_args() if (broyden and compiled_chord) else None
    phases = 0
    while it < max_iter:
        if kargs is not None and broyden and jac is not None and phases < 2:
            # the chord / Broyden steps in one compiled loop (same rules; hands back to
            # this loop for anything else)
            phases += 1
            status, X, G, R, Gc, Gk, nrm, m, it, last_ratio, polished = _run_chord_phase(
                system, kargs, jac, X, G, R, Gc, Gk, nrm, hist, m, it, tol=tol,
                polish_ratio=polish_ratio, polish_below=polish_below,
                keep_ratio=broyden_reuse_ratio,
                refresh_rate=warm_refresh if can_analytic else 0.0, max_iter=max_iter,
                give_up=give_up, nrm0=nrm0, last_ratio=last_ratio, polished=polished)
            if status == _PH_REFRESH:
                jac = None
        if nrm <= tol:
            # a chord iteration converges linearly and stops just below tol,
            # where a Newton step would overshoot by orders of magnitude: one more step
            # with the current Jacobian (the energy balance closes with the residual)
            if polished or last_ratio < polish_ratio or jac is None or nrm <= polish_below:
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
            broyden = False
        dX, dG, big, Xf, Gf, degenerate = _propose(
            *jac, R, Gc, Gk, _CAP_X, _CAP_G, hist if broyden else _NO_HIST,
            m if broyden else 0, xs, gs, X, G)
        if degenerate:                    # degenerate update: plain chord step, new history
            m = 0
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        if stale:
            # chord step: full step only (a step the cap would shorten refreshes
            # the Jacobian: measured, capped chord steps can stall a cold start), accepted
            # if it reduces the norm, else discarded and the Jacobian refreshed
            ok, nn = False, math.inf
            if lam == 1.0:
                try:
                    Rn, Gcn, Gkn, _ = system.evaluate(Xf, Gf)
                    nn = _residual_norm(Rn, Gcn, Gkn)
                    ok = math.isfinite(nn) and nn < nrm
                except (InputError, FloatingPointError, ValueError):
                    ok = False
            if ok:
                X, G, R, Gc, Gk = Xf, Gf, Rn, Gcn, Gkn
                if nn > (broyden_reuse_ratio if broyden else reuse_ratio) * nrm:
                    jac = None
                elif broyden and m < hist.shape[0]:
                    hist[m, :Z * N_BALL] = dX.ravel()
                    hist[m, Z * N_BALL:] = dG
                    m += 1
                if (broyden and warm_refresh and can_analytic and jac is not None
                        and nn > polish_below and 0.0 < nn < nrm
                        and math.log(polish_below / nn) < warm_refresh * math.log(nn / nrm)):
                    # the chord / Broyden steps at this contraction rate would need more than
                    # ``warm_refresh`` further evaluations: a fresh analytic Jacobian here
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
                ok = math.isfinite(nn)
            except (InputError, FloatingPointError, ValueError):
                ok, nn = False, np.inf
            if ok and (nn < (1 - 1e-4 * lam) * nrm or lam < 1e-3):
                break
            lam *= 0.5
            if lam < 1e-6:
                break
        if not ok or lam < 1e-6:
            err = ConvergenceError("skidding.ball", nrm, "line search failed",
                                   {"iteration": it, "cage_speed": G[2]})
            err.iterate = (X, G, nrm)
            raise err
        if not (lam == 1.0 and nn < reuse_ratio * nrm):
            jac = None
        # stall close to a root: short damped steps that gain < 1 % each (measured at the
        # fallback point of :func:`trust_region`: 140 such iterations at 1.9e-3)
        crawl = crawl + 1 if (lam < 1e-2 and nn > 0.99 * nrm and nn < 1e-2) else 0
        X, G, R, Gc, Gk, nrm, last_ratio = Xn, Gn, Rn, Gcn, Gkn, nn, nn / nrm
        if stall_after and crawl >= stall_after:
            err = ConvergenceError("skidding.ball", nrm, f"stalled: {crawl} damped steps "
                                   "below 1e-2 of the Newton step, each gaining < 1 %",
                                   {"iteration": it, "cage_speed": G[2]})
            err.iterate = (X, G, nrm)
            raise err
    if not nrm <= tol:
        err = ConvergenceError("skidding.ball", nrm, f"no convergence in {max_iter} iterations",
                               {"cage_speed": G[2], "delta_a": G[0], "delta_r": G[1]})
        err.iterate = (X, G, nrm)       # the last iterate, for a fallback (solve_ball)
        raise err
    return X, G, nrm, it


def trust_region(system: ball_residual_system, X: np.ndarray, G: np.ndarray, *,
                 tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray, float, int]:
    """Powell's hybrid method (dogleg trust region with Broyden updates of a finite-difference
    Jacobian; MINPACK ``hybrd`` through :func:`scipy.optimize.root`, method "hybr") on the
    same scaled residual, from (X, G): the fallback of :func:`~thermobearing.skidding.ball.
    solve_ball` when the damped Newton of :func:`newton_block` stalls close to a root.

    Measured (session 6): at QJ1044 with Z = 16, 30 degC oil, 3000 r/min, Fa = 15.7 kN,
    Fr = 1 kN (a BM-5 20 x 20 map point) the damped Newton stalls at a scaled residual of
    1.9e-3 (the line search accepts steps of ~1e-3 of the Newton step: the finite-difference
    ball blocks of the balls near psi = 180 deg change by up to 44 % between steps 1e-6 and
    1e-7 in the spin columns, so the Newton direction is poor there), while hybr from the
    stalled iterate reaches 5e-12 in 663 evaluations with the ball unknowns practically
    unchanged. The cause is the model, not a bug: at those balls' 1.05-GPa contacts
    eta(p0)/h = 1.6e12 Pa s/m, so the Eyring stress saturates (tau0 = 5 MPa) within ~3 um/s
    of slip, and a quadrature node near the zero-slip line puts an asinh knee of that width
    into the residual (a spin step of 1e-7 scaled moves the slip by ~0.5 um/s). Returns
    (X, G, residual norm, evaluations); raises ConvergenceError when the result is not below
    ``tol`` (in this solver's norm)."""
    from scipy.optimize import root

    n = system.Z * N_BALL + N_GLOBAL

    def f(y):
        return system.full_residual(y, X, G)

    try:
        sol = root(f, np.zeros(n), method="hybr", options={"xtol": 1e-13, "maxfev": 100 * n})
        Xn, Gn = system.unscale(sol.x, X, G)
        R, Gc, Gk, _ = system.evaluate(Xn, Gn)
        nrm = _residual_norm(R, Gc, Gk)
    except (InputError, FloatingPointError, ValueError):
        nrm, sol = math.inf, None
    if not nrm <= tol:
        raise ConvergenceError("skidding.ball", nrm, "trust-region fallback (hybr) did not "
                               "reach the tolerance", {"cage_speed": G[2]})
    return Xn, Gn, nrm, int(sol.nfev)


def chord_polish(system: ball_residual_system, X: np.ndarray, G: np.ndarray,
                 blocks: JacobianBlocks) -> tuple[np.ndarray, np.ndarray, float, bool]:
    """One more chord step from a converged state (X, G) with the Jacobian ``blocks`` (at
    the scaling of ``system``): returns (X, G, residual norm, taken); the step is taken only
    when it lowers the scaled residual norm. Used by :func:`~thermobearing.skidding.ball.
    solve_ball` when the energy identity of a converged state is not yet tight enough."""
    R, Gc, Gk, _ = system.evaluate(X, G)
    nrm = _residual_norm(R, Gc, Gk)
    if blocks is None or blocks.Z != system.Z:
        return X, G, nrm, False
    C = np.ascontiguousarray(blocks.C)
    Ainv, Ainv_B, S, ok = _factor_blocks(np.ascontiguousarray(blocks.A),
                                         np.ascontiguousarray(blocks.B), C,
                                         np.ascontiguousarray(blocks.Dg))
    if not ok:
        return X, G, nrm, False
    Sinv, ok = _inverse_small(S)
    if not ok:
        return X, G, nrm, False
    xs, gs = system.scales()
    _, _, _, Xn, Gn, _ = _propose(Ainv, Ainv_B, C, np.ascontiguousarray(Sinv), R, Gc, Gk,
                                  _CAP_X, _CAP_G, _NO_HIST, 0, xs, gs, X, G)
    try:
        Rn, Gcn, Gkn, _ = system.evaluate(Xn, Gn)
    except (InputError, FloatingPointError, ValueError):
        return X, G, nrm, False
    nn = _residual_norm(Rn, Gcn, Gkn)
    if math.isfinite(nn) and nn < nrm:
        return Xn, Gn, nn, True
    system.evaluate(X, G)          # the returned state is again the last one evaluated
    return X, G, nrm, False


_refresh_caches()
