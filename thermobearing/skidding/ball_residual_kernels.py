"""Compiled residual kernels of the ball skidding solver (paper 002, QJ1044).

One job: the numba kernels (``cache=True``) that evaluate the scaled residuals of the ball/cage/
ring equilibrium for a batch of states -- the ONE implementation of the residual; the Python
side (:class:`~thermobearing.skidding.ball_residual.ball_residual_system`, the force models
:class:`~thermobearing.skidding.ball_residual.BallModels`) lives in
:mod:`thermobearing.skidding.ball_residual`, which re-exports every name of this module.
Per ball j the unknowns are x_j = (b_a, b_r, Omega_a, Omega_r, Omega_t, Q_p) (ball-centre
position [m], angular velocity relative to the cage frame [rad/s], cage-pocket normal force
[N]); the globals are the inner-ring displacements (delta_a, delta_r) [m] and the cage speed
omega_c [rad/s]. Equations per ball (paper 002, Fig. 1(c) and eq. 9 in steady state;
primer ../shared/notes/over-skidding.md section 3.4 in vector form):

    sum_k (-Q_k n_k + F_k) + m omega_c^2 b_r e_r - F_drag e_t + Q_p e_t + f_p = 0
    sum_k (p_k x F_k + M_k) + p_p x f_p - omega_c e_a x (J Omega)            = 0

with F_k, M_k the traction force and moment of contact k integrated over the Hertz ellipse
with slip and spin by :func:`thermobearing.contact_traction.integrate` (the same code path as
the raceway heat source, so heat = force x sliding speed), the centrifugal force, the
churning drag of the ball (paper 002 eq. 10), the pocket force and its friction f_p
(paper 002 eqs. 6-8 and 19) and the gyroscopic moment ``omega_c e_a x J Omega``
(= J omega_R omega_m sin(beta) about the tangential axis; primer section 3.3). Globals: inner
ring force balance (F_a, F_r) and the cage torque balance (pocket forces against the
cage-guide and cage-churning torque, paper 002 eqs. 5 and 8).

Kernels: :func:`_ball_geometry` (arc contacts, Hamrock-Brewe Hertz, slip kinematics),
:func:`guarded_film` (Hamrock-Dowson film), :func:`_ball_forces` (the contact integration of
:mod:`thermobearing.contact_traction` -- the same kernel as ``integrate`` -- and the ball
balances), fused in :func:`_ball_residual_fused` when the film model and the viscosity are
compilable (the caller else runs them in stages with the Python film callable / per-node
viscosity between them); :func:`_residual_one` (one state, the Newton iterations' call) and
:func:`_energy_audit` (pocket / drag heat and shaft torque of a state). numba's cache does not
see edits of compiled callees in other files: :func:`_refresh_caches` (end of the module).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..contact_traction import _integrate_contacts, refresh_stale_caches
from ..hertz import _Q as _HB_Q
from ..rolling_resistance import K_ON, N_KERNEL, contact_rolling_force
from ..traction import _exp_fin, _log_pos

__all__ = ["N_BALL", "N_GLOBAL", "guarded_film", "guarded_film_array"]

# unknowns per ball (b_a, b_r, Omega_a, Omega_r, Omega_t, Q_p) and globals (delta_a, delta_r,
# omega_c): the layout of X (Z, N_BALL) and G (N_GLOBAL,) the kernels read
N_BALL = 6
N_GLOBAL = 3

# ---------------------------------------------------------------------------------------------
# compiled kernels (numba, cache=True): the ONE implementation of the residual. Per-contact
# fields of stage 1 live in rows of a (N_GEO, B*Z*k) array (contiguous rows for the contact
# integration); the film between the stages is compiled (film model with ``kernel_params``)
# or any Python callable.
# ---------------------------------------------------------------------------------------------
(G_APPROACH, G_Q, G_NA, G_NR, G_L, G_ALPHA, G_K, G_RX, G_A, G_B, G_P0, G_PA, G_PR, G_VX, G_VY,
 G_OMX, G_OMY, G_OMZ, G_UE, G_CURV) = range(20)
N_GEO = 20
# per-ball outputs: pocket sign s, pocket sliding components (wa, wr) and magnitude, pocket
# friction (fpa, fpr), centrifugal force
P_S, P_WA, P_WR, P_WN, P_FPA, P_FPR, P_FC = range(7)
N_POCKET = 7
_EMPTY_TR = np.zeros((0, 6))
_NO_REUSE = np.zeros(1, dtype=np.int64)    # a single state copies nothing
_TRUE, _FALSE = np.bool_(True), np.bool_(False)   # typed bool in compiled calls
# float constants: D, d_m, E', m, J, F_s, M_s, T_s, v_eps, mu_p, then from C_RR the
# N_KERNEL parameters of the EHL rolling resistance (rolling_resistance.kernel_parameters;
# all zero: none)
(C_D, C_DM, C_EP, C_M, C_J, C_FS, C_MS, C_TS, C_VEPS, C_MUP) = range(10)
C_RR = 10
N_C = C_RR + N_KERNEL
# arc table rows: centre x, centre r, free distance, inner (1/0), sign (+1 inner / -1 outer),
# R_y, deformed-surface curvature 1/R_d, race speed
(A_CX, A_CR, A_FREE, A_INNER, A_SIGN, A_RY, A_CURV, A_WRACE) = range(8)


_TINY = 1e-300
_TWO_OVER_PI = 2.0 / math.pi


@numba.njit(cache=True, inline="always", error_model="numpy")
def _hd1977_central_vec(u: float, eta0: float, alpha: float, q: float, rx: float, ry: float,
                        ep: float) -> float:
    """Hamrock & Dowson 1977 central film [m] -- the formula of
    :func:`thermobearing.film._hd1977_central_nb` (H_c = 2.69 U^0.67 G^0.53 W^-0.067
    (1 - 0.61 exp(-0.73 k)), k = 1.03 (R_y/R_x)^0.64, U = eta0 |u| / (E' R_x), G = alpha E',
    W = Q / (E' R_x^2), h = H_c R_x) with the powers as exp(sum of exponent x log), by the
    branch-free log / exp of :mod:`thermobearing.traction`, so that a loop over contacts
    vectorises. Equal to ``_hd1977_central_nb`` to ~1e-14 relative (the logs'
    rounding times the exponents; test); 0 for U = 0 or G = 0, +inf for W = 0 as there.
    u [m/s], eta0 [Pa s], alpha [1/Pa], q [N], rx, ry [m], ep [Pa]."""
    big_u = eta0 * abs(u) / (ep * rx)
    big_g = alpha * ep
    big_w = q / (ep * rx * rx)
    kk = 1.03 * _exp_fin(0.64 * _log_pos(ry / rx))
    h = rx * 2.69 * _exp_fin(0.67 * _log_pos(max(big_u, _TINY))
                             + 0.53 * _log_pos(max(big_g, _TINY))
                             - 0.067 * _log_pos(max(big_w, _TINY))) * (
        1.0 - 0.61 * _exp_fin(-0.73 * kk))
    if not big_g > 0.0:
        h = 0.0
    if not big_w > 0.0:
        h = math.inf
    if not big_u > 0.0:
        h = 0.0
    return h


@numba.njit(cache=True, inline="always", error_model="numpy")
def guarded_film(u: float, q: float, rx: float, ry: float, fp: np.ndarray) -> float:
    """Central film [m] of the solver's film model: Hamrock-Dowson 1977 (the formula of
    :func:`thermobearing.film._hd1977_central_nb`, evaluated as :func:`_hd1977_central_vec`)
    at max(|u|, u_min), max(Q, Q_min), floored at h_min; fp = (eta0 [Pa s], alpha [1/Pa],
    E' [Pa], u_min [m/s], Q_min [N], h_min [m])."""
    h = _hd1977_central_vec(max(abs(u), fp[3]), fp[0], fp[1], max(q, fp[4]), rx, ry, fp[2])
    return max(h, fp[5])


@numba.njit(cache=True, error_model="numpy")
def _film_rows(geo: np.ndarray, ry: np.ndarray, fp: np.ndarray, film: np.ndarray) -> None:
    """:func:`guarded_film` (the same operations) of every contact of ``geo`` (N_GEO, n)
    with R_y per contact ``ry`` (n,) into ``film`` (n,) (a vectorised loop)."""
    # the parameters as scalars: loaded in the loop they would alias ``film`` for LLVM
    eta0, alpha, ep, u_min, q_min, h_min = fp[0], fp[1], fp[2], fp[3], fp[4], fp[5]
    for n in range(film.size):
        h = _hd1977_central_vec(max(abs(geo[G_UE, n]), u_min), eta0, alpha,
                                max(geo[G_Q, n], q_min), geo[G_RX, n], ry[n], ep)
        film[n] = max(h, h_min)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _hb_point(rx: float, ry: float, ep: float) -> tuple[float, float, float, float]:
    """Hamrock-Brewe 1983 closed form of :func:`thermobearing.hertz._hamrock_brewe_point_nb`
    -- (R [m], k [-], E [-], K [N/m^1.5]): 1/R = 1/R_x + 1/R_y, k = (R_big/R_small)^(2/pi),
    E = 1 + (pi/2 - 1)/ratio, script-K = pi/2 + (pi/2 - 1) ln(ratio), K = pi k E'
    (2 E R / (9 script-K^3))^(1/2) -- with the power by the branch-free log / exp of
    :mod:`thermobearing.traction` (vectorisable; equal to the scalar function to ~1e-15
    relative, test). rx, ry [m], ep = E' [Pa]. Reference: Hamrock & Brewe 1983 (J. Lubr.
    Technol. 105), as ``hertz``."""
    r_red = 1.0 / (1.0 / rx + 1.0 / ry)
    ratio = max(rx, ry) / min(rx, ry)
    lr = _log_pos(ratio)
    k_el = _exp_fin(_TWO_OVER_PI * lr)
    big_k = 0.5 * math.pi + _HB_Q * lr
    big_e = 1.0 + _HB_Q / ratio
    K = math.pi * k_el * ep * math.sqrt(2.0 * big_e * r_red / (9.0 * (big_k * big_k * big_k)))
    return r_red, k_el, big_e, K


@numba.njit(cache=True, inline="always", error_model="numpy")
def _ellipse_vec(q: float, r_red: float, k_el: float, big_e: float,
                 ep: float) -> tuple[float, float, float]:
    """The Hertz ellipse of :func:`thermobearing.hertz._ellipse_nb` -- (a, b [m], p_max
    [Pa]): b = (6 E Q R / (pi k E'))^(1/3), a = k b (= (6 k^2 E Q R / (pi E'))^(1/3)),
    p_max = 3 Q / (2 pi a b); zeros at zero load -- with the cube root by the branch-free
    log / exp (vectorisable; ~1e-15 relative, test). q [N] >= 0."""
    loaded = q > 0.0
    b3 = 6.0 * big_e * q * r_red / (math.pi * k_el * ep)
    b3 = max(b3, _TINY)
    b_e = _exp_fin(_log_pos(b3) * (1.0 / 3.0))
    b_e += (b3 / (b_e * b_e) - b_e) * (1.0 / 3.0)       # one Newton step: ~1 ulp
    if not loaded:
        b_e = 0.0
    a_e = k_el * b_e
    p0 = 3.0 * q / (2.0 * math.pi * (a_e * b_e))
    if not loaded:
        p0 = 0.0
    return a_e, b_e, p0


@numba.njit(cache=True, error_model="numpy")
def _hertz_rows(geo: np.ndarray, ry: np.ndarray, ep: float) -> None:
    """Stage 1b of :func:`_ball_geometry` (a vectorised loop over the contacts): from R_x
    (row G_RX), R_y (``ry``) and the approach delta, the Hamrock-Brewe constants
    (:func:`_hb_point`), the load Q = K delta^1.5 (Hertz) and the ellipse
    (:func:`_ellipse_vec`) into rows G_Q, G_K, G_A, G_B, G_P0."""
    for n in range(geo.shape[1]):
        r_red, k_el, big_e, K = _hb_point(geo[G_RX, n], ry[n], ep)
        pen = max(geo[G_APPROACH, n], 0.0)
        Q = K * (pen * math.sqrt(pen))
        a_e, b_e, p0 = _ellipse_vec(Q, r_red, k_el, big_e, ep)
        geo[G_Q, n] = Q
        geo[G_K, n] = K
        geo[G_A, n] = a_e
        geo[G_B, n] = b_e
        geo[G_P0, n] = p0


@numba.njit(cache=True)
def guarded_film_array(u: np.ndarray, q: np.ndarray, rx: np.ndarray, ry: np.ndarray,
                       fp: np.ndarray) -> np.ndarray:
    """:func:`guarded_film` over flat arrays (ry may have length 1)."""
    out = np.empty(u.size)
    one = ry.size == 1
    for i in range(u.size):
        out[i] = guarded_film(u[i], q[i], rx[i], ry[0 if one else i], fp)
    return out


_NO_TAB = (np.zeros(0), np.zeros(0), 0.0, 0.0)


@numba.njit(cache=True)
def _same_state(X: np.ndarray, Xr: np.ndarray, G: np.ndarray, Gr: np.ndarray) -> bool:
    """X == Xr and G == Gr element by element (shapes (Z, 6), (3,); compiled)."""
    if X.shape != Xr.shape or G.size != Gr.size:
        return False
    for j in range(X.shape[0]):
        for i in range(X.shape[1]):
            if X[j, i] != Xr[j, i]:
                return False
    for g in range(G.size):
        if G[g] != Gr[g]:
            return False
    return True


@numba.njit(cache=True)
def _residual_norm_nb(R: np.ndarray, Gc: np.ndarray, G0: np.ndarray) -> float:
    """sqrt(|R|^2 + |sum_z Gc_z + G0|^2) of one state (compiled)."""
    acc = 0.0
    for j in range(R.shape[0]):
        for i in range(R.shape[1]):
            acc += R[j, i] * R[j, i]
    for g in range(G0.size):
        t = G0[g]
        for j in range(Gc.shape[0]):
            t += Gc[j, g]
        acc += t * t
    return math.sqrt(acc)

@numba.njit(cache=True)
def _rescaled_residual(R: np.ndarray, Gc: np.ndarray, f: float, g0a: float, g0r: float,
                       g0c: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """A state's residual at other loads (``ball_residual_system.reloaded``, compiled): R f,
    Gc f, the constant global part (g0a, g0r, g0c) and the norm of :func:`_residual_norm_nb`
    (the same operations as the numpy expressions it replaces, one call instead of four)."""
    R2 = np.empty_like(R)
    Gc2 = np.empty_like(Gc)
    for j in range(R.shape[0]):
        for i in range(R.shape[1]):
            R2[j, i] = R[j, i] * f
        for g in range(Gc.shape[1]):
            Gc2[j, g] = Gc[j, g] * f
    G0 = np.empty(3)
    G0[0], G0[1], G0[2] = g0a, g0r, g0c
    return R2, Gc2, G0, _residual_norm_nb(R2, Gc2, G0)


@numba.njit(cache=True)
def _ball_geometry(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                   c: np.ndarray, geo: np.ndarray) -> np.ndarray:
    """Stage 1: raceway-arc contacts (``loads.arc_contacts`` geometry, Hamrock-Brewe Hertz
    constants as ``loads._arc_stiffness_nb``, the Hertz ellipse) and the slip kinematics of every
    (state, ball, arc) contact, written into ``geo`` (N_GEO, B*Z*k); see the module
    docstring of :mod:`thermobearing.contact_traction` for the contact frame. The Hertz part
    runs in a second, vectorised loop (:func:`_hertz_rows`). Returns R_y per contact (n,)."""
    nb, nz = X.shape[0], X.shape[1]
    nk = arc.shape[1]
    D, dm, ep = c[C_D], c[C_DM], c[C_EP]
    ry = np.empty(nb * nz * nk)
    for i in range(nb):
        da, dr_, wc = G[i, 0], G[i, 1], G[i, 2]
        for j in range(nz):
            bx, br = X[i, j, 0], X[i, j, 1]
            Oa, Or, Ot = X[i, j, 2], X[i, j, 3], X[i, j, 4]
            for k in range(nk):
                n = (i * nz + j) * nk + k
                inner = arc[A_INNER, k]
                cx = arc[A_CX, k] + inner * da
                cr = arc[A_CR, k] + inner * (dr_ * cpsi[j])
                dx, dr = bx - cx, br - cr
                L = math.sqrt(dx * dx + dr * dr)            # (no overflow: lengths ~mm)
                na, nr = dx / L, dr / L                      # arc centre -> ball centre
                approach = L - arc[A_FREE, k]
                # contact angle alpha = atan2(n_a, |n_r|) (row G_ALPHA: by _contact_angles,
                # for the results only); cos(alpha) = |n_r| (n is a unit vector)
                rx = 0.5 * D * (1.0 - arc[A_SIGN, k] * (D * abs(nr) / dm))
                ry[n] = arc[A_RY, k]
                pen = max(approach, 0.0)
                half = 0.5 * D - 0.5 * pen                   # lever to the contact centre
                pa, pr = half * na, half * nr                # contact point - ball centre
                w_race = arc[A_WRACE, k]
                Rr = br + pr
                # Omega x p, p = (pa, pr, 0): (-Ot pr, Ot pa, Oa pr - Or pa)
                spin_t = Oa * pr - Or * pa
                vt_b = wc * Rr + spin_t
                # element minus race; contact frame e_x = (nr, -na, 0), e_y = e_t, e_z = -n
                wa_rel = wc + Oa - w_race
                geo[G_APPROACH, n] = approach
                geo[G_NA, n] = na
                geo[G_NR, n] = nr
                geo[G_L, n] = L
                geo[G_RX, n] = rx
                geo[G_PA, n] = pa
                geo[G_PR, n] = pr
                geo[G_VX, n] = (-Ot * pr) * nr - (Ot * pa) * na
                geo[G_VY, n] = vt_b - w_race * Rr
                geo[G_OMX, n] = wa_rel * nr - Or * na
                geo[G_OMY, n] = Ot
                geo[G_OMZ, n] = -(wa_rel * na + Or * nr)
                geo[G_UE, n] = 0.5 * (spin_t + (w_race - wc) * Rr)
                geo[G_CURV, n] = arc[A_CURV, k]
    _hertz_rows(geo, ry, ep)
    return ry


@numba.njit(cache=True)
def _contact_angles(geo: np.ndarray) -> None:
    """Row G_ALPHA of ``geo`` (N_GEO, n): the contact angle alpha = atan2(n_a, |n_r|) [rad]
    of every contact (the angle of the arc centre -> ball centre line to the radial plane;
    ``loads.arc_contacts``). Not part of the residual (whose R_x uses cos(alpha) = |n_r|):
    filled for the results and details only (64 atan2 less per evaluation)."""
    for n in range(geo.shape[1]):
        geo[G_ALPHA, n] = math.atan2(geo[G_NA, n], abs(geo[G_NR, n]))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _rolling_terms(geo: np.ndarray, n: int, ry: float, br: float,
                   kp: np.ndarray) -> tuple[float, float, float, float]:
    """EHL rolling resistance of contact n (loaded): (f_b, P_b, f_r, F_R) [N] along e_t.

    F_R = :func:`thermobearing.rolling_resistance.contact_rolling_force` (the heat
    source's code path). The film's Poiseuille shear f_p = F_R/2 acts on each surface in
    the direction of the inlet pressure gradient, i.e. against the entrainment u_e (the
    pressure-driven part -(h/2) dp/dx of the Reynolds shear is the same on both surfaces;
    as the roller solver, paper 000 eq. 5, and the ``ehl_rolling_resistance`` source's
    carried forces): f_b = f_r = -f_p sgn(u_e) on the ball and on the race at the contact
    point. The film pressure balances their sum (the film carries no net tangential force);
    its rolling-direction resultant acts through each body's centre (normals of a sphere /
    a ring pass through it; paper 000's roller share, see ``skidding.roller_fluid``): on
    the ball P_b = -(f_b + f_r) R_P / b_r, R_P = b_r + p_r the contact point's radius --
    the share (1 - D cos(alpha)/d_m) at the inner race -- and the rest through the bearing
    axis on the ring (no torque). The film's forces then do work f_b u_b + f_r u_r =
    -f_p |u_b + u_r| = -F_R |u_e| on the bodies in every state, the heat booked, so the
    energy identity holds. The force is continuous in the state: sgn(u_e) changes only
    where F_R ~ |u_e|^0.66 vanishes. (It used the sign of each surface's own speed, u_b =
    u_e + V_y/2 and u_r = u_e - V_y/2: a force jumping by F_R where a ball's surface speed
    crosses 0 -- the nearly stopped unloaded balls of a radially loaded bearing at low
    speed sit there, and Newton stalled at residuals of 1e-9..1e-4.)"""
    f_r_total = contact_rolling_force(geo[G_UE, n], geo[G_VY, n], geo[G_Q, n],
                                      geo[G_P0, n], geo[G_RX, n], ry, kp)
    ue = geo[G_UE, n]
    se = 1.0 if ue > 0.0 else (-1.0 if ue < 0.0 else 0.0)
    f_b = -0.5 * f_r_total * se
    f_r = f_b
    p_b = -(f_b + f_r) * (br + geo[G_PR, n]) / br
    return f_b, p_b, f_r, f_r_total


@numba.njit(cache=True)
def _rolling_audit(X: np.ndarray, geo: np.ndarray, arc: np.ndarray,
                   c: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """EHL rolling resistance of a state: force F_R per contact (Z, k) [N], heat per contact
    -(f_b u_b + f_r u_r) = F_R |u_e| (Z, k) [W] and the torque the shaft supplies against
    the Poiseuille shear on the inner race, sum of -R_P f_r [N m] (:func:`_rolling_terms`).
    geo (N_GEO, Z, k)."""
    nz, nk = X.shape[0], arc.shape[1]
    kp = c[C_RR:C_RR + N_KERNEL]
    force = np.zeros((nz, nk))
    heat = np.zeros((nz, nk))
    shaft = 0.0
    flat = geo.reshape(geo.shape[0], nz * nk)
    if kp[K_ON] == 0.0:
        return force, heat, shaft
    for j in range(nz):
        for k in range(nk):
            n = j * nk + k
            if flat[G_Q, n] <= 0.0:
                continue
            f_b, _, f_r, f_tot = _rolling_terms(flat, n, arc[A_RY, k], X[j, 1], kp)
            force[j, k] = f_tot
            ub = flat[G_UE, n] + 0.5 * flat[G_VY, n]
            ur = flat[G_UE, n] - 0.5 * flat[G_VY, n]
            heat[j, k] = -(f_b * ub + f_r * ur)
            if arc[A_INNER, k] == 1.0:
                shaft += -(X[j, 1] + flat[G_PR, n]) * f_r
    return force, heat, shaft


@numba.njit(cache=True)
def _ball_forces(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                 c: np.ndarray, geo: np.ndarray, film: np.ndarray, law_id: int,
                 law_params: np.ndarray, visc_mode: int, ln_tab: np.ndarray,
                 slope_tab: np.ndarray, inv_dp: float, eta_nodes: np.ndarray,
                 xg: np.ndarray, yg: np.ndarray, pshape: np.ndarray, area_w: np.ndarray,
                 pidx: np.ndarray, pshape_u: np.ndarray, Fd: np.ndarray,
                 reuse: np.ndarray, tr_ref: np.ndarray, tr: np.ndarray,
                 pocket: np.ndarray, R: np.ndarray, Gc: np.ndarray) -> None:
    """Stage 2: tractions of every contact (:func:`thermobearing.contact_traction.
    _integrate_contacts`, the code path of ``contact_traction.integrate``) into ``tr``
    (B*Z*k, 6), then the ball force/moment balances (scaled) into R (B, Z, 6), the per-ball
    contributions to the globals into Gc (B, Z, 3) and the pocket quantities into ``pocket``
    (B, Z, N_POCKET). Equations: module docstring. States with ``reuse[i]`` = 1 have the
    contact inputs of an already evaluated state whose tractions are ``tr_ref`` (Z*k, 6)
    (the Jacobian's pocket-force column: Q_p enters no contact); they are copied."""
    nb, nz = X.shape[0], X.shape[1]
    nk = arc.shape[1]
    per = nz * nk
    e3 = np.empty((0, 5, 5))
    e2 = np.empty((0, 5))
    for i in range(nb):
        lo, hi = i * per, (i + 1) * per
        if reuse[i] == 1:
            for r in range(per):                 # element loops, not tr[lo:hi] = tr_ref:
                for q in range(6):               # numba's slice assignment compiles its
                    tr[lo + r, q] = tr_ref[r, q]  # shape-mismatch message code (~1-3 s)
            continue
        # _TRUE / _FALSE: a literal True / False would be typed Literal[bool] and compile
        # _integrate_contacts a second time beside the Python callers' bool
        _integrate_contacts(law_id, law_params, visc_mode, ln_tab, slope_tab, inv_dp,
                            eta_nodes[lo:hi] if eta_nodes.shape[0] > 0 else eta_nodes,
                            geo[G_Q, lo:hi], geo[G_A, lo:hi], geo[G_B, lo:hi],
                            geo[G_VY, lo:hi], geo[G_VX, lo:hi], geo[G_OMZ, lo:hi],
                            geo[G_OMX, lo:hi], geo[G_OMY, lo:hi], geo[G_CURV, lo:hi],
                            film[lo:hi], xg, yg, pshape, area_w, pidx, pshape_u, _TRUE,
                            _FALSE, tr[lo:hi], e3, e2)
    D, m, J = c[C_D], c[C_M], c[C_J]
    F_s, M_s, T_s = c[C_FS], c[C_MS], c[C_TS]
    kp = c[C_RR:C_RR + N_KERNEL]
    rolling = kp[K_ON] != 0.0
    for i in range(nb):
        wc = G[i, 2]
        for j in range(nz):
            sfa = sfr = sft = sma = smr = smt = gfa = gfr = 0.0
            for k in range(nk):
                n = (i * nz + j) * nk + k
                Q, na, nr = geo[G_Q, n], geo[G_NA, n], geo[G_NR, n]
                pa, pr = geo[G_PA, n], geo[G_PR, n]
                Fx, Fy, Mx, My, Mz = tr[n, 0], tr[n, 1], tr[n, 2], tr[n, 3], tr[n, 4]
                # contact force on the ball in (a, r, t)
                fa = -Q * na + Fx * nr
                fr = -Q * nr - Fx * na
                ft = Fy
                sfa += fa
                sfr += fr
                sft += ft
                # moment about the ball centre: p x F + M, p = (pa, pr, 0)
                sma += pr * ft + Mx * nr - Mz * na
                smr += -pa * ft - Mx * na - Mz * nr
                smt += pa * fr - pr * fa + My
                if rolling and Q > 0.0:
                    # EHL rolling resistance (_rolling_terms): Poiseuille shear on the ball
                    # surface at the contact point, the film pressure's share at the centre
                    f_b, p_b, _, _ = _rolling_terms(geo, n, arc[A_RY, k], X[i, j, 1], kp)
                    sft += f_b + p_b
                    sma += pr * f_b
                    smr += -pa * f_b
                inner = arc[A_INNER, k]
                gfa += fa * inner
                gfr += fr * inner
            # pocket: contact point p_c = (0, 0, -s D/2), friction f = mu Q_p w_hat with
            # w = Omega x (D/2) e_t = (D/2)(Or, -Oa, 0) (ball surface velocity rel. cage)
            br = X[i, j, 1]
            Qp = X[i, j, 5]
            sgn = 1.0 if Qp >= 0.0 else -1.0
            wa_, wr_ = 0.5 * D * X[i, j, 3], -0.5 * D * X[i, j, 2]
            wn = math.hypot(wa_, wr_)
            wden = math.sqrt(wn * wn + c[C_VEPS] * c[C_VEPS])
            fpa = c[C_MUP] * Qp * wa_ / wden
            fpr = c[C_MUP] * Qp * wr_ / wden
            pct = -sgn * 0.5 * D
            Fc = m * wc * wc * br
            R[i, j, 0] = (sfa + fpa) / F_s
            R[i, j, 1] = (sfr + fpr + Fc) / F_s
            R[i, j, 2] = (sft - Fd[i, j] + Qp) / F_s
            # gyroscopic: required moment omega_c e_a x J Omega = J wc (0, -Ot, Or)
            R[i, j, 3] = (sma - pct * fpr) / M_s
            R[i, j, 4] = (smr + pct * fpa + J * wc * X[i, j, 4]) / M_s
            R[i, j, 5] = (smt - J * wc * X[i, j, 3]) / M_s
            # globals: ring force (reaction of the inner contacts), cage torque from ball j
            # (force -(fpa, fpr, Qp) at (ba, br, pct))
            Gc[i, j, 0] = -gfa / F_s
            Gc[i, j, 1] = -gfr * cpsi[j] / F_s
            Gc[i, j, 2] = (-br * Qp + pct * fpr) / T_s
            pocket[i, j, P_S] = sgn
            pocket[i, j, P_WA] = wa_
            pocket[i, j, P_WR] = wr_
            pocket[i, j, P_WN] = wn
            pocket[i, j, P_FPA] = fpa
            pocket[i, j, P_FPR] = fpr
            pocket[i, j, P_FC] = Fc


@numba.njit(cache=True)
def _ball_residual_fused(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                         c: np.ndarray, film_params: np.ndarray, law_id: int,
                         law_params: np.ndarray, ln_tab: np.ndarray, slope_tab: np.ndarray,
                         inv_dp: float, p_max: float, xg: np.ndarray, yg: np.ndarray,
                         pshape: np.ndarray, area_w: np.ndarray, pidx: np.ndarray,
                         pshape_u: np.ndarray, Fd: np.ndarray, reuse: np.ndarray,
                         tr_ref: np.ndarray, geo: np.ndarray, film: np.ndarray,
                         tr: np.ndarray,
                         pocket: np.ndarray, R: np.ndarray, Gc: np.ndarray) -> bool:
    """Stage 1, the compiled film (:func:`guarded_film`) and stage 2 in one call, with the
    film law's viscosity from the table (``visc_mode`` 1) when ``ln_tab`` is not empty.
    Returns False (nothing written to R) when a node pressure leaves the table's range
    [0, p_max]: the caller then takes the staged path."""
    ry = _ball_geometry(X, G, cpsi, arc, c, geo)
    n = geo.shape[1]
    visc_mode = 0
    if ln_tab.size > 0:
        visc_mode = 1
        for i in range(n):
            if geo[G_P0, i] > p_max:
                return False
    _film_rows(geo, ry, film_params, film)
    _ball_forces(X, G, cpsi, arc, c, geo, film, law_id, law_params, visc_mode, ln_tab,
                 slope_tab, inv_dp, np.empty((0, 0)), xg, yg, pshape, area_w, pidx, pshape_u,
                 Fd, reuse, tr_ref, tr, pocket, R, Gc)
    return True



@numba.njit(cache=True)
def _residual_one(X: np.ndarray, G: np.ndarray, cpsi: np.ndarray, arc: np.ndarray,
                  c: np.ndarray, film_params: np.ndarray, law_id: int,
                  law_params: np.ndarray, ln_tab: np.ndarray, slope_tab: np.ndarray,
                  inv_dp: float, p_max: float, xg: np.ndarray, yg: np.ndarray,
                  pshape: np.ndarray, area_w: np.ndarray, pidx: np.ndarray,
                  pshape_u: np.ndarray, fd_num: float, Fd_in: np.ndarray,
                  G0: np.ndarray) -> tuple:
    """One state through :func:`_ball_residual_fused` with the Python around it compiled
    (the Newton iterations' call): checks that X (Z, 6) and G (3,) are finite, the drag
    force on each ball F_d = ``fd_num`` / b_r (drag at the drag radius times that radius,
    ``Fd_in`` empty) or ``Fd_in`` (Z,), allocates the outputs and returns
    (status, R (Z, 6), Gc (Z, 3), norm, geo, film, tr, pocket (Z, N_POCKET), Fd (Z,)) with
    norm = sqrt(|R|^2 + |sum_z Gc_z + G0|^2); status 0 ok, 1 non-finite unknowns (nothing
    evaluated), 2 a node pressure beyond the viscosity table (the caller takes the staged
    path). Same kernels and inputs as the batch path, so the same numbers."""
    nz, nk = X.shape[0], arc.shape[1]
    n = nz * nk
    tot = 0.0
    for j in range(nz):
        for i in range(X.shape[1]):
            tot += X[j, i]
    for g in range(G.size):
        tot += G[g]
    Xb = np.empty((1, nz, X.shape[1]))
    for j in range(nz):        # element loops, as in _ball_forces (no slice assignment)
        for i in range(X.shape[1]):
            Xb[0, j, i] = X[j, i]
    Gb = np.empty((1, G.size))
    for g in range(G.size):
        Gb[0, g] = G[g]
    Fd = np.empty((1, nz))
    for j in range(nz):
        Fd[0, j] = fd_num / X[j, 1] if Fd_in.size == 0 else Fd_in[j]
    # writable arrays, as the batch path passes them (a module-level array would enter as a
    # read-only constant and compile _ball_residual_fused a second time)
    no_reuse = np.zeros(1, dtype=np.int64)
    empty_tr = np.empty((0, 6))
    geo = np.empty((N_GEO, n))
    film = np.empty(n)
    tr = np.empty((n, 6))
    pocket = np.empty((1, nz, N_POCKET))
    R = np.empty((1, nz, X.shape[1]))
    Gc = np.empty((1, nz, G.size))
    if not math.isfinite(tot):
        return 1, R[0], Gc[0], math.inf, geo, film, tr, pocket[0], Fd[0]
    if not _ball_residual_fused(Xb, Gb, cpsi, arc, c, film_params, law_id, law_params, ln_tab,
                                slope_tab, inv_dp, p_max, xg, yg, pshape, area_w, pidx,
                                pshape_u, Fd, no_reuse, empty_tr, geo, film, tr,
                                pocket, R, Gc):
        return 2, R[0], Gc[0], math.inf, geo, film, tr, pocket[0], Fd[0]
    acc = 0.0
    for j in range(nz):
        for i in range(X.shape[1]):
            acc += R[0, j, i] * R[0, j, i]
    for g in range(G.size):
        t = G0[g]
        for j in range(nz):
            t += Gc[0, j, g]
        acc += t * t
    return 0, R[0], Gc[0], math.sqrt(acc), geo, film, tr, pocket[0], Fd[0]



@numba.njit(cache=True)
def _energy_audit(X: np.ndarray, wc: float, geo: np.ndarray, tr: np.ndarray,
                  pocket: np.ndarray, Fd: np.ndarray, inner_f: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray, float]:
    """Per-ball pocket heat -f_p . v_rel (v_rel = -s w: ball surface relative to the cage,
    paper 002 eq. 19) [W] and drag power F_d omega_c b_r [W] (Z,), and the torque of the
    balls on the inner ring [N m]: sum over inner contacts of R_P F_t + M_x n_r - M_z n_a
    (R_P = b_r + p_r, the contact point's radius; the reaction of -(R_P x F)_a - M_a).
    geo (N_GEO, Z, k), tr (Z, k, 6), pocket (Z, N_POCKET)."""
    nz, nk = X.shape[0], inner_f.size
    pocket_heat = np.empty(nz)
    drag_heat = np.empty(nz)
    shaft = 0.0
    for j in range(nz):
        s = pocket[j, P_S]
        pocket_heat[j] = -(pocket[j, P_FPA] * (-s * pocket[j, P_WA])
                           + pocket[j, P_FPR] * (-s * pocket[j, P_WR]))
        drag_heat[j] = Fd[j] * wc * X[j, 1]
        for k in range(nk):
            if inner_f[k] == 1.0:
                rp = X[j, 1] + geo[G_PR, j, k]
                shaft += rp * tr[j, k, 1] + (tr[j, k, 2] * geo[G_NR, j, k]
                                             - tr[j, k, 4] * geo[G_NA, j, k])
    return pocket_heat, drag_heat, shaft


def _refresh_caches() -> None:
    from .. import contact_traction, film, hertz, rolling_resistance, traction

    refresh_stale_caches("ball_residual_kernels", (guarded_film, guarded_film_array,
                                                   _ball_geometry, _ball_forces,
                                                   _ball_residual_fused, _residual_one,
                                                   _same_state, _residual_norm_nb,
                                                   _rescaled_residual,
                                                   _energy_audit, _hd1977_central_vec,
                                                   _film_rows, _hertz_rows, _hb_point,
                                                   _ellipse_vec, _contact_angles,
                                                   _rolling_terms, _rolling_audit),
                         (contact_traction, traction, hertz, film, rolling_resistance))


_refresh_caches()
