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
   V_y, V_x, omega_z, omega_x, omega_y, h) per contact (:func:`_contact_traction_jac`);
4. ball balances (:func:`~thermobearing.skidding.ball_residual._ball_forces`): products of
   the above with the contact normal and lever arms, the pocket friction, centrifugal force,
   ball drag and gyroscopic moment, all differentiated exactly; the cage and drag torques
   (Python model callables of the cage speed) by a forward difference in omega_c.

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

from ..contact_traction import _peak_pressure, _table_viscosity, refresh_stale_caches
from ..rolling_resistance import K_ON, N_KERNEL, contact_rolling_force
from ..traction import EYRING, _log_pos
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

# contact inputs of the traction derivative: Q, a, b, V_y, V_x, omega_z, omega_x, omega_y, h
I_Q, I_A, I_B, I_VY, I_VX, I_WZ, I_WX, I_WY, I_H = range(9)
N_IN = 9
# directions of the geometry / kinematics derivative
D_BX, D_BR, D_OA, D_OR, D_OT, D_DA, D_DR, D_WC = range(8)
N_DIR = 8
_RX_STEP = 1e-7            # relative forward-difference step in R_x (Hertz constants, film)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _eyring_smooth_grad(lam: float, tau0: float, inv_tau0: float, s: float, p: float,
                        rate: float) -> tuple[float, float, float, float]:
    """The Eyring law with the smooth cap (:func:`thermobearing.traction._eyring_smooth_node`
    without the weight) and its partial derivatives: (tau [Pa], dtau/ds [Pa s/m], dtau/dp
    [-], dtau/d(rate) [m/s]) at slide speed s >= 0 [m/s], pressure p >= 0 [Pa], rate =
    eta/h [Pa s/m]. tau_E = tau0 asinh(rate s / tau0), tau_L = Lambda p,
    tau = tau_E tau_L / sqrt(tau_L^2 + tau_E^2): dtau/dtau_E = tau_L^3 / (..)^(3/2),
    dtau/dtau_L = tau_E^3 / (..)^(3/2), dtau_E/ds = rate / sqrt(1 + x^2),
    dtau_E/drate = s / sqrt(1 + x^2), x = rate s / tau0 (seed paper 002 eqs. 11-14).
    Branch-free (the node loop of :func:`_contact_traction_jac` vectorises);
    log1p(y) = log(u) + (y - (u - 1)) / u, u = 1 + y, with the log of
    :func:`thermobearing.traction._log_pos`."""
    x = rate * s * inv_tau0
    x2 = x * x
    sq = math.sqrt(1.0 + x2)
    # asinh(x) = log1p(x + x^2 / (1 + sqrt(1 + x^2))) (x >= 0), reusing the square root
    y = x + x2 / (1.0 + sq)
    u = 1.0 + y
    tau_e = tau0 * (_log_pos(u) + (y - (u - 1.0)) / u)
    tau_l = lam * p
    inv = 1.0 / math.sqrt(tau_l * tau_l + tau_e * tau_e)
    tau = tau_e * tau_l * inv
    inv3 = inv * inv * inv
    d_e = tau_l * tau_l * tau_l * inv3
    d_l = tau_e * tau_e * tau_e * inv3
    if not tau_l > 0.0:
        tau = tau_e * 1e-150
        d_e = 1e-150
        d_l = 0.0
    inv_sq = 1.0 / sq
    return tau, d_e * rate * inv_sq, d_l * lam, d_e * s * inv_sq


@numba.njit(cache=True, fastmath={"reassoc"})
def _jac_node_sums(xg: np.ndarray, yg: np.ndarray, px_k: np.ndarray, py_k: np.ndarray,
                   kxx_k: np.ndarray, kyy_k: np.ndarray, kxy_k: np.ndarray,
                   exg_k: np.ndarray, eyg_k: np.ndarray, exh_k: np.ndarray,
                   eyh_k: np.ndarray, ext_k: np.ndarray, eyt_k: np.ndarray) -> tuple:
    """The 43 node sums of :func:`_contact_traction_jac` for one contact (the tractions'
    6 and the derivatives' 37 monomial sums) from the per-node values, with the additions
    free to be reassociated (numba fastmath 'reassoc' only) so that LLVM vectorises them
    (the order changes the sums at round-off)."""
    sx0 = sx1 = sx2 = sy0 = sy1 = sy2 = 0.0
    # kxx sums over 1, x2, y, x4, x2y, y2
    xx_1 = xx_x2 = xx_y = xx_x4 = xx_x2y = xx_y2 = 0.0
    # kxy sums over 1, x, x2, x3, x4, y, xy, x2y
    xy_1 = xy_x = xy_x2 = xy_x3 = xy_x4 = xy_y = xy_xy = xy_x2y = 0.0
    # kyy sums over 1, x, x2, x3, x4
    yy_1 = yy_x = yy_x2 = yy_x3 = yy_x4 = 0.0
    # e_x sigma sums over 1, x2, y and e_y sigma over 1, x2, x; sigma = gp, th, tw
    pxg_1 = pxg_x2 = pxg_y = pyg_1 = pyg_x2 = pyg_x = 0.0
    pxh_1 = pxh_x2 = pxh_y = pyh_1 = pyh_x2 = pyh_x = 0.0
    pxt_1 = pxt_x2 = pxt_y = pyt_1 = pyt_x2 = pyt_x = 0.0
    for k in range(xg.size):
        xk, yk = xg[k], yg[k]
        xk2 = xk * xk
        px, py = px_k[k], py_k[k]
        kxx, kyy, kxy = kxx_k[k], kyy_k[k], kxy_k[k]
        sx0 += px
        sx1 += px * xk2
        sx2 += px * yk
        sy0 += py
        sy1 += py * xk2
        sy2 += py * xk
        xk3 = xk2 * xk
        xk4 = xk2 * xk2
        xy = xk * yk
        x2y = xk2 * yk
        xx_1 += kxx
        xx_x2 += kxx * xk2
        xx_y += kxx * yk
        xx_x4 += kxx * xk4
        xx_x2y += kxx * x2y
        xx_y2 += kxx * yk * yk
        xy_1 += kxy
        xy_x += kxy * xk
        xy_x2 += kxy * xk2
        xy_x3 += kxy * xk3
        xy_x4 += kxy * xk4
        xy_y += kxy * yk
        xy_xy += kxy * xy
        xy_x2y += kxy * x2y
        yy_1 += kyy
        yy_x += kyy * xk
        yy_x2 += kyy * xk2
        yy_x3 += kyy * xk3
        yy_x4 += kyy * xk4
        exg, eyg = exg_k[k], eyg_k[k]
        exh, eyh = exh_k[k], eyh_k[k]
        ext, eyt = ext_k[k], eyt_k[k]
        pxg_1 += exg
        pxg_x2 += exg * xk2
        pxg_y += exg * yk
        pyg_1 += eyg
        pyg_x2 += eyg * xk2
        pyg_x += eyg * xk
        pxh_1 += exh
        pxh_x2 += exh * xk2
        pxh_y += exh * yk
        pyh_1 += eyh
        pyh_x2 += eyh * xk2
        pyh_x += eyh * xk
        pxt_1 += ext
        pxt_x2 += ext * xk2
        pxt_y += ext * yk
        pyt_1 += eyt
        pyt_x2 += eyt * xk2
        pyt_x += eyt * xk
    return (sx0, sx1, sx2, sy0, sy1, sy2, xx_1, xx_x2, xx_y, xx_x4, xx_x2y, xx_y2, xy_1,
            xy_x, xy_x2, xy_x3, xy_x4, xy_y, xy_xy, xy_x2y, yy_1, yy_x, yy_x2, yy_x3,
            yy_x4, pxg_1, pxg_x2, pxg_y, pyg_1, pyg_x2, pyg_x, pxh_1, pxh_x2, pxh_y, pyh_1,
            pyh_x2, pyh_x, pxt_1, pxt_x2, pxt_y, pyt_1, pyt_x2, pyt_x)


@numba.njit(cache=True, error_model="numpy")
def _contact_traction_jac(law_params: np.ndarray, ln_tab: np.ndarray, slope_tab: np.ndarray,
                          inv_dp: float, q: np.ndarray, a: np.ndarray, b: np.ndarray,
                          vy: np.ndarray, vx: np.ndarray, wz: np.ndarray, wx: np.ndarray,
                          wy: np.ndarray, curv: np.ndarray, h: np.ndarray, xg: np.ndarray,
                          yg: np.ndarray, pshape: np.ndarray, area_w: np.ndarray,
                          pidx: np.ndarray, pshape_u: np.ndarray, tr: np.ndarray,
                          out: np.ndarray) -> None:
    """Tractions and their derivatives for the Eyring smooth-cap law with tabulated viscosity
    (the fast path of :func:`thermobearing.contact_traction._integrate_contacts`, point
    contacts). Inputs as there (flat, one entry per contact). Writes ``tr[c]`` = (F_x, F_y,
    M_x, M_y, M_z) [N, N m] and ``out[c, i, j]`` = d tr_i / d in_j with in = (Q [N], a [m],
    b [m], V_y, V_x [m/s], omega_z, omega_x, omega_y [rad/s], h [m]).

    Per node (see the module docstring): d p_node = kxx d dv_x + kxy d dv_y + e_x sigma (and
    y), with k the slide-speed Jacobian of the node force and sigma its change through the
    pressure (gp), the viscosity over film (th) and the node area (tw). Every direction's
    d dv is a combination of the monomials 1, x^2, y (x component) and 1, x, x^2 (y
    component) with contact constants, so the node loop accumulates kxx, kxy, kyy against the
    monomial products the outputs need (19 sums) and e sigma against the output multipliers
    (18 sums), and the nine directions are assembled after it (13 % less time than
    accumulating every direction at every node, measured; equal to that to 4e-16)."""
    lam, tau0, inv_tau0 = law_params[0], law_params[1], law_params[3]
    nu = pshape_u.size
    nk = xg.size
    rate_u = np.empty(nu)
    lam_u = np.empty(nu)
    rate_k, lamk_k = np.empty(nk), np.empty(nk)
    px_k, py_k = np.empty(nk), np.empty(nk)
    kxx_k, kyy_k, kxy_k = np.empty(nk), np.empty(nk), np.empty(nk)
    exg_k, eyg_k, exh_k = np.empty(nk), np.empty(nk), np.empty(nk)
    eyh_k, ext_k, eyt_k = np.empty(nk), np.empty(nk), np.empty(nk)
    last = ln_tab.size - 1
    for c in range(q.size):
        for i in range(5):
            tr[c, i] = 0.0
            for j in range(N_IN):
                out[c, i, j] = 0.0
        p0 = _peak_pressure(q[c], a[c], b[c], True)
        if p0 == 0.0:
            continue
        ac, bc, qc = a[c], b[c], q[c]
        ab = ac * bc
        a2c = 0.5 * curv[c] * ac * ac
        wyc, wzc, wxc = wy[c], wz[c], wx[c]
        cx2, cy = wyc * a2c, wzc * bc
        cx, cy2 = wzc * ac, wxc * a2c
        inv_h = 1.0 / h[c]
        for u in range(nu):
            pu = p0 * pshape_u[u]
            rate_u[u] = _table_viscosity(pu, ln_tab, slope_tab, inv_dp) * inv_h
            iu = int(pu * inv_dp)
            if iu > last:
                iu = last
            lam_u[u] = slope_tab[iu] * inv_dp
        vxc, vyc = vx[c], vy[c]
        curv_a = curv[c] * ac
        for k in range(nk):
            rate_k[k] = rate_u[pidx[k]]
            lamk_k[k] = lam_u[pidx[k]]
        # per node, vectorised (no sums here): slide speed, the law and its derivatives
        for k in range(nk):
            xk, yk = xg[k], yg[k]
            xk2 = xk * xk
            dvx = vxc + cx2 * xk2 - cy * yk
            dvy = vyc + cx * xk - cy2 * xk2
            s = math.sqrt(dvx * dvx + dvy * dvy)
            pres = p0 * pshape[k]
            rate = rate_k[k]
            w = ab * area_w[k]
            tau, ts, tp, trr = _eyring_smooth_grad(lam, tau0, inv_tau0, s, pres, rate)
            inv_s = 1.0 / s
            ex, ey = dvx * inv_s, dvy * inv_s
            ratio = tau * inv_s
            ps = w * ratio
            if not s > 0.0:
                ex = 0.0
                ey = 0.0
                ratio = ts
                ps = 0.0
            px_k[k] = ps * dvx
            py_k[k] = ps * dvy
            kxx_k[k] = w * (ts * ex * ex + ratio * (1.0 - ex * ex))
            kyy_k[k] = w * (ts * ey * ey + ratio * (1.0 - ey * ey))
            kxy_k[k] = w * (ts - ratio) * ex * ey
            gp = w * pres * (tp + trr * rate * lamk_k[k])
            th = w * trr * rate
            tw = tau * w
            exg_k[k], eyg_k[k] = ex * gp, ey * gp
            exh_k[k], eyh_k[k] = ex * th, ey * th
            ext_k[k], eyt_k[k] = ex * tw, ey * tw
        (sx0, sx1, sx2, sy0, sy1, sy2, xx_1, xx_x2, xx_y, xx_x4, xx_x2y, xx_y2, xy_1, xy_x,
         xy_x2, xy_x3, xy_x4, xy_y, xy_xy, xy_x2y, yy_1, yy_x, yy_x2, yy_x3, yy_x4, pxg_1,
         pxg_x2, pxg_y, pyg_1, pyg_x2, pyg_x, pxh_1, pxh_x2, pxh_y, pyh_1, pyh_x2, pyh_x,
         pxt_1, pxt_x2, pxt_y, pyt_1, pyt_x2, pyt_x) = _jac_node_sums(
            xg, yg, px_k, py_k, kxx_k, kyy_k, kxy_k, exg_k, eyg_k, exh_k, eyh_k, ext_k, eyt_k)
        tr[c, 0] = -sx0
        tr[c, 1] = -sy0
        tr[c, 2] = a2c * sy1
        tr[c, 3] = -a2c * sx1
        tr[c, 4] = bc * sx2 - ac * sy2
        # per direction: S_px[m] for m = 1, x2, y and S_py[m] for m = 1, x2, x
        # ddx = al1 + alx2 x2 + aly y ; ddy = be1 + bex x + bex2 x2 ; sigma = g gp + hh th + t tw
        for d in range(N_IN):
            al1 = alx2 = aly = be1 = bex = bex2 = gg = hh = tt = 0.0
            if d == I_Q:
                gg = 1.0 / qc
            elif d == I_A:
                alx2 = wyc * curv_a
                bex = wzc
                bex2 = -wxc * curv_a
                tt = 1.0 / ac
                gg = -1.0 / ac
            elif d == I_B:
                aly = -wzc
                tt = 1.0 / bc
                gg = -1.0 / bc
            elif d == I_VY:
                be1 = 1.0
            elif d == I_VX:
                al1 = 1.0
            elif d == I_WZ:
                aly = -bc
                bex = ac
            elif d == I_WX:
                bex2 = -a2c
            elif d == I_WY:
                alx2 = a2c
            else:
                hh = -inv_h
            # px sums: kxx (ddx terms) x mult + kxy (ddy terms) x mult + e_x sigma x mult
            spx_1 = (al1 * xx_1 + alx2 * xx_x2 + aly * xx_y + be1 * xy_1 + bex * xy_x
                     + bex2 * xy_x2 + gg * pxg_1 + hh * pxh_1 + tt * pxt_1)
            spx_x2 = (al1 * xx_x2 + alx2 * xx_x4 + aly * xx_x2y + be1 * xy_x2 + bex * xy_x3
                      + bex2 * xy_x4 + gg * pxg_x2 + hh * pxh_x2 + tt * pxt_x2)
            spx_y = (al1 * xx_y + alx2 * xx_x2y + aly * xx_y2 + be1 * xy_y + bex * xy_xy
                     + bex2 * xy_x2y + gg * pxg_y + hh * pxh_y + tt * pxt_y)
            spy_1 = (al1 * xy_1 + alx2 * xy_x2 + aly * xy_y + be1 * yy_1 + bex * yy_x
                     + bex2 * yy_x2 + gg * pyg_1 + hh * pyh_1 + tt * pyt_1)
            spy_x2 = (al1 * xy_x2 + alx2 * xy_x4 + aly * xy_x2y + be1 * yy_x2 + bex * yy_x3
                      + bex2 * yy_x4 + gg * pyg_x2 + hh * pyh_x2 + tt * pyt_x2)
            spy_x = (al1 * xy_x + alx2 * xy_x3 + aly * xy_xy + be1 * yy_x + bex * yy_x2
                     + bex2 * yy_x3 + gg * pyg_x + hh * pyh_x + tt * pyt_x)
            out[c, 0, d] = -spx_1
            out[c, 1, d] = -spy_1
            out[c, 2, d] = a2c * spy_x2
            out[c, 3, d] = -a2c * spx_x2
            out[c, 4, d] = bc * spx_y - ac * spy_x
        out[c, 2, I_A] += curv_a * sy1
        out[c, 3, I_A] -= curv_a * sx1
        out[c, 4, I_A] -= sy2
        out[c, 4, I_B] += sx2


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
    (``ball_residual_kernels._rolling_terms``: f_b = -F_R/2 sgn(u_b) at the contact point,
    P_b = F_R/2 (sgn(u_b) + sgn(u_r)) R_P / b_r at the ball centre) added to the ball
    balances' derivatives ``dsum`` (rows sft, sma, smr) in the N_DIR directions; the signs
    are piecewise constant (derivative 0 away from u = 0)."""
    ue, vy = geo[G_UE, ci], geo[G_VY, ci]
    q, p0, a_e, b_e = geo[G_Q, ci], geo[G_P0, ci], geo[G_A, ci], geo[G_B, ci]
    pa, pr = geo[G_PA, ci], geo[G_PR, ci]
    f0 = _rolling_grad(ue, vy, q, p0, geo[G_RX, ci], ry, kp, grad)
    ub, ur = ue + 0.5 * vy, ue - 0.5 * vy
    sb = 1.0 if ub > 0.0 else (-1.0 if ub < 0.0 else 0.0)
    sr = 1.0 if ur > 0.0 else (-1.0 if ur < 0.0 else 0.0)
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
    from . import ball_residual_kernels

    refresh_stale_caches("ball_jacobian", (_eyring_smooth_grad, _contact_traction_jac,
                                           _jac_node_sums, _geometry_jac, _jacobian_kernel,
                                           _rolling_grad, _rolling_jac),
                         (contact_traction, traction, hertz, film, ball_residual_kernels,
                          rolling_resistance))


_refresh_caches()
