"""Derivatives of the contact tractions for the ball solver's analytic Jacobian.

One job: step 3 of the chain of :mod:`thermobearing.skidding.ball_jacobian` -- the Eyring law
with the smooth cap and its partial derivatives (:func:`_eyring_smooth_grad`) and the contact
integration differentiated with respect to the contact inputs (:func:`_contact_traction_jac`,
the quadrature of :func:`thermobearing.contact_traction._integrate_contacts`, seed paper 002
eqs. 11-14 / Johnson 1985 ch. 7): d(F_x, F_y, M_x, M_y, M_z)/d(Q, a, b, V_y, V_x, omega_z,
omega_x, omega_y, h) per contact, in the input order ``I_Q ... I_H``.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..contact_traction import (
    _node_slip,
    _peak_pressure,
    _slip_coefficients,
    _store_forces,
    _table_viscosity,
    refresh_stale_caches,
)
from ..traction import _log_pos

# contact inputs of the traction derivative: Q, a, b, V_y, V_x, omega_z, omega_x, omega_y, h
I_Q, I_A, I_B, I_VY, I_VX, I_WZ, I_WX, I_WY, I_H = range(9)
N_IN = 9


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
        wyc, wzc, wxc = wy[c], wz[c], wx[c]
        ab, a2c, cx2, cy, cx, cy2 = _slip_coefficients(ac, bc, curv[c], wyc, wzc, wxc)
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
            xk2, dvx, dvy = _node_slip(vxc, vyc, cx2, cy, cx, cy2, xg[k], yg[k])
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
        _store_forces(tr, c, ac, bc, a2c, sx0, sx1, sx2, sy0, sy1, sy2)
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


def _refresh_caches() -> None:
    from .. import contact_traction, traction

    refresh_stale_caches("ball_jacobian_traction", (_eyring_smooth_grad, _jac_node_sums,
                                                    _contact_traction_jac),
                         (contact_traction, traction))


_refresh_caches()
