"""Compiled kernels of the ball skidding solver's Newton driver.

One job: the numba kernels (``cache=True``) of :mod:`thermobearing.skidding.ball_newton` (which
re-exports every name of this module): the block elimination of the structured Jacobian
(6x6 ball blocks :func:`_factor_blocks` / :func:`_inverse_small`, the 3x3 Schur complement on
the globals, the capped step :func:`_block_step`), the forward-difference blocks
(:func:`_fd_blocks`), the scaled residual norm (``_residual_norm_nb`` of
:mod:`.ball_residual_kernels`, imported), the rescaling of a handed-over Jacobian
(:func:`_rescale_blocks`) and of its factors (:func:`_rescale_factors`), the good-Broyden
update (:func:`_broyden_step`, :func:`_propose`), the cage-torque model of the compiled chord
phase (:func:`_torque_model`),
the chord / Broyden iterations of a warm start in one compiled loop (:func:`_chord_phase`,
which compiles the residual kernel :func:`~thermobearing.skidding.ball_residual_kernels.
_residual_one` into itself) and the exact torques put back at its returned state
(:func:`_exact_torques`). Numerics (Newton with a structured Jacobian, block elimination,
chord / good-Broyden steps; issue 5 item 4): :mod:`thermobearing.skidding.ball_newton`. All
quantities are the scaled, dimensionless residuals and unknowns of
:class:`~thermobearing.skidding.ball_residual.ball_residual_system`.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..contact_traction import refresh_stale_caches
from .ball_residual_kernels import _residual_norm_nb as _residual_norm  # one kernel for both
from .ball_residual_kernels import _residual_one


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
        for i in range(nb):          # element loop: a slice assignment from an array
            for j in range(nb):      # compiles numba's shape-mismatch message code
                Ainv[z, i, j] = inv[i, j]
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
def _column_factors(f: float, xs: np.ndarray, xs_old: np.ndarray, gs: np.ndarray,
                    gs_old: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Column factors of a rescaled Jacobian: f xs_c / xs_old_c (ball columns) and
    f gs_g / gs_old_g (global columns)."""
    rx = np.empty(xs.shape[0])
    rg = np.empty(gs.shape[0])
    for c in range(xs.shape[0]):
        rx[c] = f * xs[c] / xs_old[c]
    for g in range(gs.shape[0]):
        rg[g] = f * gs[g] / gs_old[g]
    return rx, rg


@numba.njit(cache=True)
def _rescale_blocks(A: np.ndarray, B: np.ndarray, C: np.ndarray, Dg: np.ndarray, f: float,
                    xs: np.ndarray, xs_old: np.ndarray, gs: np.ndarray, gs_old: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:meth:`JacobianBlocks.rescaled` compiled (six numpy operations cost ~20 us):
    column c of every block times (f xs_c) / xs_old_c (ball columns) or (f gs_g) / gs_old_g
    (global columns), the same operations as the numpy expressions it replaces."""
    nz, nb, ng = A.shape[0], A.shape[1], B.shape[2]
    rx, rg = _column_factors(f, xs, xs_old, gs, gs_old)
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
def _rescale_factors(A: np.ndarray, B: np.ndarray, C: np.ndarray, Dg: np.ndarray,
                     Ainv: np.ndarray, AiB: np.ndarray, Sinv: np.ndarray, f: float,
                     xs: np.ndarray, xs_old: np.ndarray, gs: np.ndarray, gs_old: np.ndarray
                     ) -> tuple:
    """:func:`_rescale_blocks` and the block-elimination factors (:func:`_factor_blocks`,
    :func:`_inverse_small`) of the rescaled Jacobian from those of the original, without a
    factorisation, in one compiled call. With the column factors of :func:`_rescale_blocks`,
    D_x = diag(f xs_c / xs_old_c) and D_g = diag(f gs_g / gs_old_g), the blocks are
    A' = A D_x, B' = B D_g, C' = C D_x, D' = D D_g, so A'^-1 = D_x^-1 A^-1,
    A'^-1 B' = D_x^-1 A^-1 B D_g, S' = D' - C' A'^-1 B' = S D_g and S'^-1 = D_g^-1 S^-1
    (the factors of the rescaled blocks to round-off). Returns (A', B', C', D', A'^-1,
    A'^-1 B', S'^-1)."""
    A2, B2, C2, Dg2 = _rescale_blocks(A, B, C, Dg, f, xs, xs_old, gs, gs_old)
    nz, nb, ng = Ainv.shape[0], Ainv.shape[1], AiB.shape[2]
    rx, rg = _column_factors(f, xs, xs_old, gs, gs_old)
    Ainv2 = np.empty_like(Ainv)
    AiB2 = np.empty_like(AiB)
    Sinv2 = np.empty_like(Sinv)
    for z in range(nz):
        for i in range(nb):
            for j in range(nb):
                Ainv2[z, i, j] = Ainv[z, i, j] / rx[i]
            for g in range(ng):
                AiB2[z, i, g] = AiB[z, i, g] * rg[g] / rx[i]
    for g in range(ng):
        for h in range(ng):
            Sinv2[g, h] = Sinv[g, h] / rg[g]
    return A2, B2, C2, Dg2, Ainv2, AiB2, Sinv2


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
    for i in range(nz):          # element loops: a slice assignment from an array compiles
        for j in range(nb):      # numba's shape-mismatch message code (seconds, once per kernel)
            z[i * nb + j] = dX[i, j]
    for g in range(ng):
        z[nz * nb + g] = dG[g]
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


def _refresh_caches() -> None:
    """numba's cache does not see edits of compiled callees in other files (see
    :func:`thermobearing.contact_traction.refresh_stale_caches`): the chord phase compiles
    the residual kernel into itself, so its cache follows the residual's modules."""
    from .. import contact_traction, film, hertz, traction
    from . import ball_residual_kernels

    refresh_stale_caches("ball_newton_kernels", (_block_step, _inverse_small, _factor_blocks,
                                                 _fd_blocks, _broyden_step,
                                                 _propose, _torque_model, _chord_phase,
                                                 _rescale_blocks, _rescale_factors,
                                                 _exact_torques),
                         (contact_traction, traction, hertz, film, ball_residual_kernels))


_refresh_caches()
