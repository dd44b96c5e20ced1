"""Analytic Jacobian of the ball skidding residual (forward-mode derivatives, compiled).

One job: the structured Jacobian blocks (A, B, C, Dg of
:class:`~thermobearing.skidding.ball_newton.JacobianBlocks`) of
:class:`~thermobearing.skidding.ball_residual.ball_residual_system` at one state, by the
chain rule through the same equations instead of nine perturbed residual evaluations
(:func:`analytic_blocks`). Issue 5 item 4 asks for "Newton with an analytic or structured
finite-difference Jacobian"; the finite-difference one costs 8-9 residual evaluations, this
one about two (measured in the tests / BM-5), so a warm start can afford a fresh Jacobian.

Chain (per ball j, raceway arc k; directions d = b_a, b_r, Omega_a, Omega_r, Omega_t of the
ball and delta_a, delta_r, omega_c of the ring and cage; the pocket force Q_p enters only the
pocket terms):

1. contact geometry (:func:`~thermobearing.skidding.ball_residual._ball_geometry`): arc
   centre -> ball centre distance L, normal (n_a, n_r), approach, contact angle, R_x, the
   Hamrock-Brewe stiffness K (Hamrock & Brewe 1983; ``hertz._hamrock_brewe_point_nb``'s
   formula as the residual evaluates it, ``ball_residual._hb_point``),
   Q = K delta^1.5 and the Hertz ellipse a, b ~ Q^(1/3) (Harris & Kotzalas 2007, ch. 6)
   -- differentiated by hand, the R_x dependence of K, a, b by a forward difference in R_x;
   the slip kinematics (V_x, V_y, spin components, entrainment speed) are bilinear in the
   unknowns and the normal and differentiated exactly;
2. film: Hamrock & Dowson 1977 h ~ u^0.67 W^-0.067 (``film._hd1977_central_nb``), so
   dh/du = 0.67 h/u, dh/dQ = -0.067 h/Q (0 under the speed / load floors and at the thickness
   floor), R_x by the same forward difference;
3. contact integration (:func:`thermobearing.contact_traction._integrate_contacts`, fast path
   of the Eyring law with the smooth cap, seed paper 002 eqs. 11-14 / Johnson 1985 ch. 7): per
   quadrature node t = -tau(s, p, eta(p)/h) dA dv/|dv| with the derivatives of tau (the law's
   own formula, :func:`_eyring_smooth_grad`) with respect to the slide speed, the pressure
   and eta/h; d ln eta/dp from the same viscosity table (piecewise-linear ln eta); the node
   velocities and weights scale with a and b. Gives d(F_x, F_y, M_x, M_y, M_z)/d(Q, a, b,
   V_y, V_x, omega_z, omega_x, omega_y, h) per contact (:func:`_contact_traction_jac`, in
   :mod:`thermobearing.skidding.ball_jacobian_traction`);
4. ball balances (:func:`~thermobearing.skidding.ball_residual._ball_forces`): products of
   the above with the contact normal and lever arms, the pocket friction, centrifugal force,
   ball drag and gyroscopic moment, all differentiated exactly; the cage and drag torques
   (Python model callables of the cage speed) by a forward difference in omega_c; the EHL
   rolling resistance when on (:func:`_rolling_jac`: its force by forward differences in
   u_e, V_y, Q, p0, R_x, chained with the geometry's derivatives).

Only the solver's default models have this path (compiled film, tabulated viscosity, Eyring
with the smooth cap and tau0 > 0, drag at a fixed radius); :func:`analytic_blocks` returns
None otherwise and the caller uses finite differences. Units: the blocks are derivatives of
the scaled residual with respect to the scaled unknowns (dimensionless), exactly as the
finite-difference blocks; tests compare both (agreement ~1e-6 relative, the
finite-difference truncation).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..contact_traction import refresh_stale_caches
from ..rolling_resistance import K_ON, N_KERNEL, contact_rolling_force
from ..traction import EYRING
from .ball_jacobian_traction import (  # noqa: F401  (re-exported for the tests)
    I_A,
    I_B,
    I_H,
    I_Q,
    I_VX,
    I_VY,
    I_WX,
    I_WY,
    I_WZ,
    N_IN,
    _contact_traction_jac,
    _eyring_smooth_grad,
    _jac_node_sums,
)
from .ball_residual import (
    A_INNER,
    A_RY,
    A_SIGN,
    A_WRACE,
    C_D,
    C_DM,
    C_EP,
    C_FS,
    C_J,
    C_M,
    C_MS,
    C_MUP,
    C_RR,
    C_TS,
    C_VEPS,
    G_A,
    G_APPROACH,
    G_B,
    G_CURV,
    G_K,
    G_L,
    G_NA,
    G_NR,
    G_OMX,
    G_OMY,
    G_OMZ,
    G_P0,
    G_PA,
    G_PR,
    G_Q,
    G_RX,
    G_UE,
    G_VX,
    G_VY,
    N_BALL,
    N_GEO,
    N_GLOBAL,
    _ball_geometry,
    _ellipse_vec,
    _hb_point,
    guarded_film,
)

__all__ = ["analytic_blocks", "supports_analytic"]

# directions of the geometry / kinematics derivative
D_BX, D_BR, D_OA, D_OR, D_OT, D_DA, D_DR, D_WC = range(8)
N_DIR = 8
_RX_STEP = 1e-7            # relative forward-difference step in R_x (Hertz constants, film)


@numba.njit(cache=True)
def _geometry_jac(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                  c: np.ndarray, film_params: np.ndarray, geo: np.ndarray,
                  film: np.ndarray, dgeo: np.ndarray, dnorm: np.ndarray,
                  dext: np.ndarray) -> None:
    """Forward-mode derivatives of the contact inputs of one state X (Z, 6), G (3,):
    ``dgeo[n, i, d]`` = d in_i / d dir_d (in = Q, a, b, V_y, V_x, omega_z, omega_x,
    omega_y, h; dir = b_a, b_r, Omega_a, Omega_r, Omega_t, delta_a, delta_r, omega_c, SI),
    ``dext[n, i, d]`` for (u_e, R_x) (the rolling resistance's further inputs) and
    ``dnorm[n, i, d]`` for (n_a, n_r, p_a, p_r) (normal and lever arm of the contact), n =
    ball * k + arc. ``geo`` / ``film`` are this state's fields from :func:`_ball_geometry` and
    :func:`guarded_film` (computed here)."""
    nz = X.shape[0]
    nk = arc.shape[1]
    Xb = np.empty((1, nz, X.shape[1]))
    for j in range(nz):     # element loops: a slice assignment from an array compiles numba's
        for i in range(X.shape[1]):          # shape-mismatch message code (seconds)
            Xb[0, j, i] = X[j, i]
    Gb = np.empty((1, G.size))
    for g in range(G.size):
        Gb[0, g] = G[g]
    _ball_geometry(Xb, Gb, cpsi, arc, c, geo)
    D, dm, ep = c[C_D], c[C_DM], c[C_EP]
    wc = G[2]
    umin, qmin, hmin = film_params[3], film_params[4], film_params[5]
    dx_ = np.empty(N_DIR)
    dr_ = np.empty(N_DIR)
    for j in range(nz):
        br = X[j, 1]
        Oa, Or, Ot = X[j, 2], X[j, 3], X[j, 4]
        for k in range(nk):
            n = j * nk + k
            ry = arc[A_RY, k]
            film[n] = guarded_film(geo[G_UE, n], geo[G_Q, n], geo[G_RX, n], ry, film_params)
            for d in range(N_DIR):
                for i in range(N_IN):
                    dgeo[n, i, d] = 0.0
                for i in range(4):
                    dnorm[n, i, d] = 0.0
                dext[n, 0, d] = 0.0
                dext[n, 1, d] = 0.0
                dx_[d] = 0.0
                dr_[d] = 0.0
            if geo[G_Q, n] <= 0.0:
                continue        # unloaded: no traction, Q and its derivative 0 (dgeo = 0)
            inner = arc[A_INNER, k]
            dx_[D_BX] = 1.0
            dx_[D_DA] = -inner
            dr_[D_BR] = 1.0
            dr_[D_DR] = -inner * cpsi[j]
            L, na, nr = geo[G_L, n], geo[G_NA, n], geo[G_NR, n]
            approach, rx = geo[G_APPROACH, n], geo[G_RX, n]
            Q, K = geo[G_Q, n], geo[G_K, n]
            a_e, b_e = geo[G_A, n], geo[G_B, n]
            pen = approach if approach > 0.0 else 0.0
            half = 0.5 * D - 0.5 * pen
            pa, pr = geo[G_PA, n], geo[G_PR, n]
            w_race = arc[A_WRACE, k]
            Rr = br + pr
            wa_rel = wc + Oa - w_race
            # R_x dependence of the Hertz constants and the film (forward difference)
            drx_step = rx * _RX_STEP
            rx2 = rx + drx_step
            r2, k2, e2, K2 = _hb_point(rx2, ry, ep)      # as the residual (ball_residual)
            dK_rx = (K2 - K) / drx_step
            if Q > 0.0:
                a2, b2, _ = _ellipse_vec(Q, r2, k2, e2, ep)
                da_rx = (a2 - a_e) / drx_step
                db_rx = (b2 - b_e) / drx_step
            else:
                da_rx = db_rx = 0.0
            h0 = film[n]
            ue = geo[G_UE, n]
            # film: h = max(HD(max(|u|, u_min), max(Q, Q_min), R_x), h_min)
            h_u = h_q = h_rx = 0.0
            if h0 > hmin:
                if abs(ue) > umin:
                    h_u = 0.67 * h0 / ue
                if Q > qmin:
                    h_q = -0.067 * h0 / Q
                h_rx = (guarded_film(ue, Q, rx2, ry, film_params) - h0) / drx_step
            for d in range(N_DIR):
                ddx, ddr = dx_[d], dr_[d]
                dbr = 1.0 if d == D_BR else 0.0
                dOa = 1.0 if d == D_OA else 0.0
                dOr = 1.0 if d == D_OR else 0.0
                dOt = 1.0 if d == D_OT else 0.0
                dwc = 1.0 if d == D_WC else 0.0
                if ddx != 0.0 or ddr != 0.0:
                    dL = na * ddx + nr * ddr
                    dna = (ddx - na * dL) / L
                    dnr = (ddr - nr * dL) / L
                    dpen = dL if approach > 0.0 else 0.0
                    sg = 1.0 if nr >= 0.0 else -1.0
                    dalpha = (abs(nr) * dna - na * sg * dnr) / (na * na + nr * nr)
                    # sin(alpha) = n_a (unit normal; the residual takes cos(alpha) = |n_r|)
                    drx = 0.5 * D * arc[A_SIGN, k] * (D / dm) * na * dalpha
                    dK = dK_rx * drx
                    dQ = pen ** 1.5 * dK + 1.5 * K * math.sqrt(pen) * dpen
                    if Q > 0.0:
                        da = a_e / (3.0 * Q) * dQ + da_rx * drx
                        db = b_e / (3.0 * Q) * dQ + db_rx * drx
                    else:
                        da = db = 0.0
                    dhalf = -0.5 * dpen
                    dpa = dhalf * na + half * dna
                    dpr = dhalf * nr + half * dnr
                else:
                    dna = dnr = dQ = da = db = dpa = dpr = drx = 0.0
                dRr = dbr + dpr
                dspin = dOa * pr + Oa * dpr - dOr * pa - Or * dpa
                dvt = dwc * Rr + wc * dRr + dspin
                dwa = dwc + dOa
                dVx = -dOt * (pr * nr + pa * na) - Ot * (dpr * nr + pr * dnr + dpa * na
                                                         + pa * dna)
                dVy = dvt - w_race * dRr
                dOmx = dwa * nr + wa_rel * dnr - dOr * na - Or * dna
                dOmy = dOt
                dOmz = -(dwa * na + wa_rel * dna + dOr * nr + Or * dnr)
                due = 0.5 * (dspin - dwc * Rr + (w_race - wc) * dRr)
                dh = h_u * due + h_q * dQ + h_rx * drx
                dgeo[n, I_Q, d] = dQ
                dgeo[n, I_A, d] = da
                dgeo[n, I_B, d] = db
                dgeo[n, I_VY, d] = dVy
                dgeo[n, I_VX, d] = dVx
                dgeo[n, I_WZ, d] = dOmz
                dgeo[n, I_WX, d] = dOmx
                dgeo[n, I_WY, d] = dOmy
                dgeo[n, I_H, d] = dh
                dnorm[n, 0, d] = dna
                dnorm[n, 1, d] = dnr
                dnorm[n, 2, d] = dpa
                dnorm[n, 3, d] = dpr
                dext[n, 0, d] = due
                dext[n, 1, d] = drx


@numba.njit(cache=True, error_model="numpy")
def _rolling_grad(ue: float, vy: float, q: float, p0: float, rx: float, ry: float,
                  kp: np.ndarray, out: np.ndarray) -> float:
    """F_R of :func:`thermobearing.rolling_resistance.contact_rolling_force` and its
    partial derivatives in (u_e, V_y, Q, p0, R_x) into ``out`` by forward differences
    (relative step ``_RX_STEP``, floored at the scale of each input: truncation ~1e-7
    relative, as the R_x differences above)."""
    f0 = contact_rolling_force(ue, vy, q, p0, rx, ry, kp)
    args = np.array([ue, vy, q, p0, rx])
    scale = np.array([abs(ue), abs(ue), q, p0, rx])
    for i in range(5):
        h = _RX_STEP * max(abs(args[i]), 1e-3 * scale[i], 1e-300)
        a = args.copy()
        a[i] += h
        out[i] = (contact_rolling_force(a[0], a[1], a[2], a[3], a[4], ry, kp) - f0) / h
    return f0


@numba.njit(cache=True, error_model="numpy")
def _rolling_jac(geo: np.ndarray, ci: int, ry: float, br: float, kp: np.ndarray,
                 dgeo: np.ndarray, dnorm: np.ndarray, dext: np.ndarray, dsum: np.ndarray,
                 grad: np.ndarray) -> None:
    """Derivatives of the EHL rolling-resistance terms of loaded contact ``ci``
    (``ball_residual_kernels._rolling_terms``: f_b = -F_R/2 sgn(u_e) at the contact point,
    P_b = F_R sgn(u_e) R_P / b_r at the ball centre) added to the ball
    balances' derivatives ``dsum`` (rows sft, sma, smr) in the N_DIR directions; the sign
    is piecewise constant (derivative 0 away from u_e = 0, where F_R vanishes)."""
    ue, vy = geo[G_UE, ci], geo[G_VY, ci]
    q, p0, a_e, b_e = geo[G_Q, ci], geo[G_P0, ci], geo[G_A, ci], geo[G_B, ci]
    pa, pr = geo[G_PA, ci], geo[G_PR, ci]
    f0 = _rolling_grad(ue, vy, q, p0, geo[G_RX, ci], ry, kp, grad)
    sb = 1.0 if ue > 0.0 else (-1.0 if ue < 0.0 else 0.0)
    sr = sb
    f_b = -0.5 * f0 * sb
    rp = br + pr
    for d in range(N_DIR):
        dq = dgeo[ci, I_Q, d]
        dp0 = p0 * (dq / q - dgeo[ci, I_A, d] / a_e - dgeo[ci, I_B, d] / b_e)
        df = (grad[0] * dext[ci, 0, d] + grad[1] * dgeo[ci, I_VY, d] + grad[2] * dq
              + grad[3] * dp0 + grad[4] * dext[ci, 1, d])
        dbr = 1.0 if d == D_BR else 0.0
        dpa, dpr = dnorm[ci, 2, d], dnorm[ci, 3, d]
        df_b = -0.5 * df * sb
        dp_b = 0.5 * (sb + sr) * (df * rp / br + f0 * ((dbr + dpr) / br - rp * dbr / (br * br)))
        dsum[2, d] += df_b + dp_b
        dsum[3, d] += dpr * f_b + pr * df_b
        dsum[4, d] += -dpa * f_b - pa * df_b


@numba.njit(cache=True)
def _jacobian_kernel(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                     c: np.ndarray, film_params: np.ndarray, law_params: np.ndarray,
                     ln_tab: np.ndarray, slope_tab: np.ndarray, inv_dp: float, p_max: float,
                     xg: np.ndarray, yg: np.ndarray, pshape: np.ndarray, area_w: np.ndarray,
                     pidx: np.ndarray, pshape_u: np.ndarray, fd_num: float, dfd_dwc: float,
                     dg0_dwc: float, xs: np.ndarray, gs: np.ndarray) -> tuple:
    """Blocks (A, B, C, Dg, ok) of the scaled Jacobian at (X, G) (see the module docstring;
    the same layout as ``ball_newton._fd_blocks``). ``fd_num`` = drag force at the drag
    radius times that radius [N m] and ``dfd_dwc`` its derivative in omega_c; ``dg0_dwc``
    = d/d omega_c of the constant global cage-torque residual (both from the Python models).
    ok is False when a contact pressure leaves the viscosity table (the caller then uses
    finite differences)."""
    nz = X.shape[0]
    nk = arc.shape[1]
    n = nz * nk
    geo = np.empty((N_GEO, n))
    film = np.empty(n)
    dgeo = np.empty((n, N_IN, N_DIR))
    dnorm = np.empty((n, 4, N_DIR))
    dext = np.empty((n, 2, N_DIR))
    A = np.zeros((nz, N_BALL, N_BALL))
    B = np.zeros((nz, N_BALL, N_GLOBAL))
    C = np.zeros((nz, N_GLOBAL, N_BALL))
    Dg = np.zeros((N_GLOBAL, N_GLOBAL))
    _geometry_jac(X, G, cpsi, arc, c, film_params, geo, film, dgeo, dnorm, dext)
    kp = c[C_RR:C_RR + N_KERNEL]
    rolling = kp[K_ON] != 0.0
    rgrad = np.empty(5)
    for i in range(n):
        if geo[G_Q, i] > 0.0 and 1.5 * geo[G_Q, i] / (math.pi * geo[G_A, i]
                                                      * geo[G_B, i]) > p_max:
            return A, B, C, Dg, False
    tr = np.empty((n, 5))
    tj = np.empty((n, 5, N_IN))
    _contact_traction_jac(law_params, ln_tab, slope_tab, inv_dp, geo[G_Q], geo[G_A],
                          geo[G_B], geo[G_VY], geo[G_VX], geo[G_OMZ], geo[G_OMX],
                          geo[G_OMY], geo[G_CURV], film, xg, yg, pshape, area_w, pidx,
                          pshape_u, tr, tj)
    D, m, J = c[C_D], c[C_M], c[C_J]
    F_s, M_s, T_s = c[C_FS], c[C_MS], c[C_TS]
    mup, veps = c[C_MUP], c[C_VEPS]
    wc = G[2]
    dtr = np.empty(5)
    # per ball: d(sum of the balances)/d dir (8 directions) and d/dQ_p (column 8)
    dsum = np.empty((8, N_DIR + 1))   # sfa, sfr, sft, sma, smr, smt, gfa, gfr
    for j in range(nz):
        for r in range(8):
            for d in range(N_DIR + 1):
                dsum[r, d] = 0.0
        for k in range(nk):
            ci = j * nk + k
            if geo[G_Q, ci] <= 0.0:
                continue        # an unloaded contact adds nothing to the balances' derivatives
            Q, na, nr = geo[G_Q, ci], geo[G_NA, ci], geo[G_NR, ci]
            pa, pr = geo[G_PA, ci], geo[G_PR, ci]
            Fx, Fy, Mx, Mz = tr[ci, 0], tr[ci, 1], tr[ci, 2], tr[ci, 4]
            fa = -Q * na + Fx * nr
            fr = -Q * nr - Fx * na
            ft = Fy
            inner = arc[A_INNER, k]
            for d in range(N_DIR):
                for i in range(5):
                    acc = 0.0
                    for q in range(N_IN):
                        acc += tj[ci, i, q] * dgeo[ci, q, d]
                    dtr[i] = acc
                dQ = dgeo[ci, I_Q, d]
                dna, dnr = dnorm[ci, 0, d], dnorm[ci, 1, d]
                dpa, dpr = dnorm[ci, 2, d], dnorm[ci, 3, d]
                dfa = -dQ * na - Q * dna + dtr[0] * nr + Fx * dnr
                dfr = -dQ * nr - Q * dnr - dtr[0] * na - Fx * dna
                dft = dtr[1]
                dsum[0, d] += dfa
                dsum[1, d] += dfr
                dsum[2, d] += dft
                dsum[3, d] += dpr * ft + pr * dft + dtr[2] * nr + Mx * dnr - dtr[4] * na \
                    - Mz * dna
                dsum[4, d] += -dpa * ft - pa * dft - dtr[2] * na - Mx * dna - dtr[4] * nr \
                    - Mz * dnr
                dsum[5, d] += dpa * fr + pa * dfr - dpr * fa - pr * dfa + dtr[3]
                dsum[6, d] += inner * dfa
                dsum[7, d] += inner * dfr
            if rolling:
                _rolling_jac(geo, ci, arc[A_RY, k], X[j, 1], kp, dgeo, dnorm, dext, dsum,
                             rgrad)
        # pocket friction f = mu Q_p w / sqrt(|w|^2 + v_eps^2), w = (D/2)(Omega_r, -Omega_a)
        br = X[j, 1]
        Qp = X[j, 5]
        sgn = 1.0 if Qp >= 0.0 else -1.0
        pct = -sgn * 0.5 * D
        wa_, wr_ = 0.5 * D * X[j, 3], -0.5 * D * X[j, 2]
        wden = math.sqrt(wa_ * wa_ + wr_ * wr_ + veps * veps)
        inv_w, inv_w3 = 1.0 / wden, 1.0 / (wden * wden * wden)
        fpa_q, fpr_q = mup * wa_ * inv_w, mup * wr_ * inv_w          # d/dQ_p
        fpa_wa = mup * Qp * (inv_w - wa_ * wa_ * inv_w3)
        fpa_wr = -mup * Qp * wa_ * wr_ * inv_w3
        fpr_wr = mup * Qp * (inv_w - wr_ * wr_ * inv_w3)
        fpr_wa = fpa_wr
        # d w_a / d Omega_r = D/2, d w_r / d Omega_a = -D/2
        fpa_oa, fpa_or = -0.5 * D * fpa_wr, 0.5 * D * fpa_wa
        fpr_oa, fpr_or = -0.5 * D * fpr_wr, 0.5 * D * fpr_wa
        # physical derivatives of the residual rows in the 8 directions + Q_p (index 8)
        dR = np.zeros((N_BALL, N_DIR + 1))
        dG = np.zeros((N_GLOBAL, N_DIR + 1))
        for d in range(N_DIR):
            dR[0, d] = dsum[0, d] / F_s
            dR[1, d] = dsum[1, d] / F_s
            dR[2, d] = dsum[2, d] / F_s
            dR[3, d] = dsum[3, d] / M_s
            dR[4, d] = dsum[4, d] / M_s
            dR[5, d] = dsum[5, d] / M_s
            dG[0, d] = -dsum[6, d] / F_s
            dG[1, d] = -dsum[7, d] * cpsi[j] / F_s
        dR[0, D_OA] += fpa_oa / F_s
        dR[0, D_OR] += fpa_or / F_s
        dR[0, 8] += fpa_q / F_s
        dR[1, D_OA] += fpr_oa / F_s
        dR[1, D_OR] += fpr_or / F_s
        dR[1, 8] += fpr_q / F_s
        dR[1, D_BR] += m * wc * wc / F_s                      # centrifugal force
        dR[1, D_WC] += 2.0 * m * wc * br / F_s
        dR[2, D_BR] += fd_num / (br * br) / F_s              # - F_d, F_d = fd_num / b_r
        dR[2, D_WC] -= dfd_dwc / br / F_s
        dR[2, 8] += 1.0 / F_s
        dR[3, D_OA] -= pct * fpr_oa / M_s
        dR[3, D_OR] -= pct * fpr_or / M_s
        dR[3, 8] -= pct * fpr_q / M_s
        dR[4, D_OA] += pct * fpa_oa / M_s
        dR[4, D_OR] += pct * fpa_or / M_s
        dR[4, 8] += pct * fpa_q / M_s
        dR[4, D_OT] += J * wc / M_s                            # gyroscopic moment
        dR[4, D_WC] += J * X[j, 4] / M_s
        dR[5, D_OR] -= J * wc / M_s
        dR[5, D_WC] -= J * X[j, 3] / M_s
        dG[2, D_BR] += -Qp / T_s
        dG[2, D_OA] += pct * fpr_oa / T_s
        dG[2, D_OR] += pct * fpr_or / T_s
        dG[2, 8] += (-br + pct * fpr_q) / T_s
        # scaled blocks: ball columns (b_a, b_r, Omega_a, Omega_r, Omega_t) = dirs 0..4,
        # Q_p = 8; globals (delta_a, delta_r, omega_c) = dirs 5..7
        for i in range(N_BALL):
            for col in range(5):
                A[j, i, col] = dR[i, col] * xs[col]
            A[j, i, 5] = dR[i, 8] * xs[5]
            for g in range(N_GLOBAL):
                B[j, i, g] = dR[i, 5 + g] * gs[g]
        for g in range(N_GLOBAL):
            for col in range(5):
                C[j, g, col] = dG[g, col] * xs[col]
            C[j, g, 5] = dG[g, 8] * xs[5]
            for h in range(N_GLOBAL):
                Dg[g, h] += dG[g, 5 + h] * gs[h]
    Dg[2, 2] += dg0_dwc * gs[2]
    return A, B, C, Dg, True


def supports_analytic(system) -> bool:
    """True when ``system`` runs the default compiled models this Jacobian covers: the fused
    kernel (compiled film, tabulated viscosity), the Eyring law with the smooth cap and
    tau0 > 0, and the ball drag at a fixed radius."""
    lp = getattr(system, "_law_params", None)
    return bool(system._fused and system._tab is not None and system._law_id == EYRING
                and lp is not None and lp[2] != 0.0 and lp[1] > 0.0
                and system.models.drag_radius is not None)


def analytic_blocks(system, X: np.ndarray, G: np.ndarray, *, wc_step: float = 1e-6):
    """Analytic structured Jacobian of ``system`` at (X, G) (SI unknowns).

    Returns a :class:`~thermobearing.skidding.ball_newton.JacobianBlocks` (the same layout
    and scaling as the finite-difference blocks), or None when the system's models are not
    covered (:func:`supports_analytic`) or a contact pressure leaves the viscosity table.
    The cage-speed dependence of the Python cage and drag torque models is a forward
    difference with relative step ``wc_step`` (two memoised model calls)."""
    from .ball_newton import JacobianBlocks

    if not supports_analytic(system):
        return None
    wc = float(G[2])
    t0 = system._cage_torques(wc)
    hw = wc_step * max(abs(wc), system.w_s * 1e-3)
    t1 = system._cage_torques(wc + hw)
    dfd = (t1[3] - t0[3]) / hw
    dg0 = -((t1[0] + t1[1]) - (t0[0] + t0[1])) / hw / system.T_s
    xs, gs = system.scales()
    ln_tab, slope_tab, inv_dp, p_max = system._tab
    A, B, C, Dg, ok = _jacobian_kernel(
        np.ascontiguousarray(X, dtype=float), np.ascontiguousarray(G, dtype=float),
        system._cpsi, system._arc, system._c, system._film_params, system._law_params,
        ln_tab, slope_tab, inv_dp, p_max, *system._rule, float(t0[3]), dfd, dg0, xs, gs)
    if not ok:
        return None
    return JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, system.Z)


def _refresh_caches() -> None:
    from .. import contact_traction, film, hertz, rolling_resistance, traction
    from . import ball_jacobian_traction, ball_residual_kernels

    refresh_stale_caches("ball_jacobian", (_geometry_jac, _jacobian_kernel, _rolling_grad,
                                           _rolling_jac),
                         (contact_traction, traction, hertz, film, ball_residual_kernels,
                          ball_jacobian_traction, rolling_resistance))


_refresh_caches()
