"""Residual of the ball/cage/ring equilibrium of the ball skidding solver (paper 002, QJ1044).

One job: evaluate the scaled residuals of :mod:`thermobearing.skidding.ball`'s unknowns
(:class:`ball_residual_system`) for the force models it balances (:class:`BallModels`).
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

Implementation: the residual of a batch of states is compiled (numba, ``cache=True``):
:func:`_ball_geometry` (arc contacts, Hamrock-Brewe Hertz, slip kinematics),
:func:`guarded_film` (Hamrock-Dowson film), :func:`_ball_forces` (the contact integration of
:mod:`thermobearing.contact_traction` -- the same kernel as ``integrate`` -- and the ball
balances), fused in :func:`_ball_residual_fused` when the film model and the viscosity are
compilable, else run in stages with the Python film callable / per-node viscosity between
them. The cage and drag torques are Python callables of the models, memoised per cage speed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numba
import numpy as np

from ..contact_traction import (
    _EMPTY,
    _EMPTY2,
    ContactTraction,
    _integrate_contacts,
    _node_pressures,
    _rule,
    refresh_stale_caches,
    viscosity_source,
)
from ..errors import InputError, check_positive
from ..hertz import _Q as _HB_Q
from ..loads import (
    INNER,
    ArcSet,
    ContactField,
    ball_arcs,
)
from ..traction import EYRING, _exp_fin, _log_pos

if TYPE_CHECKING:
    from .ball_newton import JacobianBlocks

__all__ = ["N_BALL", "N_GLOBAL", "BallModels", "ball_residual_system"]

N_BALL = 6
N_GLOBAL = 3


@dataclass(frozen=True)
class BallModels:
    """The force models the ball solver balances (all SI).

    Attributes
    ----------
    traction_law : a :mod:`thermobearing.traction` law (``shear_stress``).
    pocket_friction : ball-pocket friction coefficient mu_p [-] (paper 002 eq. 19's f_bp =
        mu_p F_bp).
    ball_drag : callable(u [m/s]) -> drag force on one ball [N], u = orbital speed of the ball
        centre relative to the oil (paper 002 eq. 10).
    cage_torque : callable(omega_c [rad/s]) -> resisting torque on the cage [N m] from the oil
        (cage churning, paper 002 eq. 15 / omega_c); heat = torque x omega_c.
    cage_guide_torque : callable(omega_c, omega_g) -> resisting torque on the cage from the
        guide land [N m] (paper 002 eq. 5), or None; heat = torque x (omega_c - omega_g).
    guide_on_inner_ring : the land is on the inner ring (its reaction then loads the shaft).
    inner_ring_torque : callable(omega_i) -> churning torque on the inner ring [N m] (paper 002
        eq. 17 / omega_i); enters only the shaft torque and the energy balance.
    film_thickness : callable(u_e [m/s], Q [N], rx [m], ry [m]) -> central film [m], or None
        when the traction law needs no film.
    temperature : contact temperature for the traction law [K].
    n_major, n_minor : quadrature nodes of the contact integration.
    oil_speed_ratio : speed of the oil the balls move through, as a fraction of the cage
        speed [-] (0: oil at rest).
    drag_radius : radius at which the drag law evaluates the ball speed [m]; the churning
        heat source uses the pitch radius d_m/2, so with ``drag_radius = d_m/2`` the drag force
        applied at the ball centre (radius b_r) is scaled by (d_m/2)/b_r so that its power is
        exactly the source's heat (an O(1e-5) correction). None: the ball-centre radius.
    """

    traction_law: Any
    pocket_friction: float
    ball_drag: Callable[[Any], Any]
    cage_torque: Callable[[float], float]
    cage_guide_torque: Callable[[float, float], float] | None = None
    guide_on_inner_ring: bool = False
    inner_ring_torque: Callable[[float], float] = lambda w: 0.0
    film_thickness: Callable[..., Any] | None = None
    temperature: float | None = None
    n_major: int = 8
    n_minor: int = 4
    oil_speed_ratio: float = 0.0
    drag_radius: float | None = None
    parameters: dict = field(default_factory=dict)


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
_NO_REUSE = np.zeros(1, dtype=np.int64)    # read only: a single state copies nothing
# float constants: D, d_m, E', m, J, F_s, M_s, T_s, v_eps, mu_p
(C_D, C_DM, C_EP, C_M, C_J, C_FS, C_MS, C_TS, C_VEPS, C_MUP) = range(10)
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
    vectorises (session 8). Equal to ``_hd1977_central_nb`` to ~1e-14 relative (the logs'
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
    filled for the results and details only (session 8: 64 atan2 less per evaluation)."""
    for n in range(geo.shape[1]):
        geo[G_ALPHA, n] = math.atan2(geo[G_NA, n], abs(geo[G_NR, n]))


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
            tr[lo:hi, :] = tr_ref
            continue
        _integrate_contacts(law_id, law_params, visc_mode, ln_tab, slope_tab, inv_dp,
                            eta_nodes[lo:hi] if eta_nodes.shape[0] > 0 else eta_nodes,
                            geo[G_Q, lo:hi], geo[G_A, lo:hi], geo[G_B, lo:hi],
                            geo[G_VY, lo:hi], geo[G_VX, lo:hi], geo[G_OMZ, lo:hi],
                            geo[G_OMX, lo:hi], geo[G_OMY, lo:hi], geo[G_CURV, lo:hi],
                            film[lo:hi], xg, yg, pshape, area_w, pidx, pshape_u, True, False,
                            tr[lo:hi], e3, e2)
    D, m, J = c[C_D], c[C_M], c[C_J]
    F_s, M_s, T_s = c[C_FS], c[C_MS], c[C_TS]
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
    Xb[0] = X
    Gb = np.empty((1, G.size))
    Gb[0] = G
    Fd = np.empty((1, nz))
    if Fd_in.size == 0:
        for j in range(nz):
            Fd[0, j] = fd_num / X[j, 1]
    else:
        Fd[0] = Fd_in
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
                                pshape_u, Fd, _NO_REUSE, _EMPTY_TR, geo, film, tr,
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
    from .. import contact_traction, film, hertz, traction

    refresh_stale_caches("ball_residual", (guarded_film, guarded_film_array, _ball_geometry,
                                           _ball_forces, _ball_residual_fused, _residual_one,
                                           _same_state, _residual_norm_nb,
                                           _energy_audit, _hd1977_central_vec, _film_rows,
                                           _hertz_rows, _hb_point, _ellipse_vec,
                                           _contact_angles),
                         (contact_traction, traction, hertz, film))


_refresh_caches()

# ---------------------------------------------------------------------------------------------
# the residual system
# ---------------------------------------------------------------------------------------------
class ball_residual_system:  # noqa: N801 - used like a function returning an object
    """Residual of the ball/cage/ring equilibrium at one operating point.

    ``evaluate(X, G)`` with X (Z, 6) ball unknowns (SI) and G (3,) globals (SI) returns the
    scaled ball residuals (Z, 6), the per-ball contributions to the global residuals (Z, 3),
    the constant part of the global residuals (3,) and a dict of details.
    """

    def __init__(self, bearing, models: BallModels, speed: float, radial_load: float,
                 axial_load: float, n_balls: int | None = None) -> None:
        self.bearing = bearing
        self.models = models
        self.speed = float(speed)
        self.Fr = float(radial_load)
        self.Fa = float(axial_load)
        self.arcs: ArcSet = ball_arcs(bearing)
        self.Z = int(n_balls or bearing.n_balls)
        self.psi = 2.0 * np.pi * np.arange(self.Z) / self.Z
        self.D = self.arcs.ball_diameter
        self.Rm = self.arcs.pitch_radius
        self.m = float(bearing.ball_mass)
        self.J = float(bearing.ball_inertia)
        self.Ep = float(bearing.effective_modulus)
        self.inner = self.arcs.ring == INNER
        self.rd = 2.0 * self.arcs.conformity * self.D / (2.0 * self.arcs.conformity + 1.0)
        w = abs(self.speed)
        fc = self.m * (0.5 * w) ** 2 * self.Rm
        self.F_s = max(abs(self.Fa) / self.Z, self.Fr / self.Z, fc, 10.0)
        self.M_s = self.F_s * 0.5 * self.D
        self.T_s = self.F_s * self.Rm
        self.w_s = max(w, 1e-3)
        self._g0a, self._g0r = self.Fa / self.F_s, self.Fr / self.F_s
        self.last_norm = math.inf
        self.n_eval = 0
        self.n_jac = 0               # analytic Jacobians (skidding.ball_jacobian) taken
        # constants of the residual, computed once (validated here, used unchecked inside)
        arcs = self.arcs
        self.cx0 = arcs.centre_x.astype(float)
        self.cr0 = arcs.centre_r.astype(float)
        self.free = arcs.free_distance.astype(float)
        self.inner_f = self.inner.astype(float)
        self.cpsi = np.cos(self.psi)
        self.dm = float(bearing.pitch_diameter)
        self.ry = arcs.conformity * self.D / (2.0 * arcs.conformity - 1.0)
        check_positive("skidding.ball R_y", self.ry)
        self.curv = 1.0 / self.rd                          # deformed-surface curvature [1/m]
        self._ry_zk = np.broadcast_to(self.ry, (self.Z, self.ry.size))   # read-only view
        self.w_race = np.where(self.inner, self.speed, 0.0)
        self.veps = 1e-6 * max(abs(self.speed) * self.Rm, 1e-3)
        self._torque_memo: dict[float, tuple] = {}
        # the chord phase's cage-torque model ([centre omega_c, model array] of
        # ball_newton._run_chord_phase), shared with the reloaded copies like the memo
        self._torque_fit: list = []
        self._inner_torque_memo: float | None = None
        self.last_jacobian: JacobianBlocks | None = None
        # (X, G, (R, Gc, G0), details builder, norm, fields) of the last state, fields =
        # (geo (N_GEO, Z, k), tractions (Z, k, 6), pocket, F_d, u_ball, film (Z, k) or None)
        self._last = None
        self._scales = None          # (xs, gs) of :meth:`scales` at the current loads
        self._last_tr = None         # (X, G, tractions (Z*k, 6)) of the last single state
        check_positive("skidding.ball effective_modulus", self.Ep)
        check_positive("skidding.ball ball_mass", self.m)
        if models.n_major < 2 or models.n_minor < 1:
            raise InputError("skidding.ball n_major/n_minor", (models.n_major, models.n_minor),
                             "n_major >= 2 and n_minor >= 1")
        if getattr(models.traction_law, "requires_film", False) and models.film_thickness is None:
            raise InputError("skidding.ball film_thickness", None,
                             "a film-thickness model: the traction law shears a fluid film")
        law = models.traction_law
        if not hasattr(law, "kernel"):
            raise InputError("skidding.ball traction_law", type(law).__name__,
                             "a registered traction law (traction.TRACTION)")
        self._law_id, self._law_params = law.kernel
        if self._law_id == EYRING and models.temperature is None:
            raise InputError("skidding.ball temperature", None,
                             "a contact temperature [K] for the film traction law")
        # constants of the compiled kernels
        self._c = np.array([self.D, self.dm, self.Ep, self.m, self.J, self.F_s, self.M_s,
                            self.T_s, self.veps, float(models.pocket_friction)])
        self._arc = np.ascontiguousarray(np.stack([
            self.cx0, self.cr0, self.free, self.inner_f, np.where(self.inner, 1.0, -1.0),
            np.broadcast_to(self.ry, self.cx0.shape), np.broadcast_to(self.curv,
                                                                      self.cx0.shape),
            self.w_race]).astype(float))
        self._cpsi = np.ascontiguousarray(self.cpsi, dtype=float)
        self._rule = _rule("point", models.n_major, models.n_minor)
        fp = getattr(models.film_thickness, "kernel_params", None)
        self._film_params = None if fp is None else np.asarray(fp, dtype=float)
        self._tab = None
        if self._law_id == EYRING:
            mode, ln_tab, slope_tab, inv_dp = viscosity_source(law, models.temperature, 0.0)
            if mode == 1:
                p_max = (ln_tab.size - 1) / inv_dp / float(np.max(self._rule[2]))
                self._tab = (ln_tab, slope_tab, inv_dp, p_max)
        # one fused compiled call when the film is compiled and the viscosity (if any) tabulated
        self._fused = self._film_params is not None and (self._law_id != EYRING
                                                         or self._tab is not None)

    # -- kinematics and forces ------------------------------------------------------------
    def evaluate(self, X: np.ndarray, G: np.ndarray, details: bool = False):
        """Scaled residuals; see the class docstring.

        X may carry leading batch dimensions, (..., Z, 6) with G (..., 3): every state of
        the batch is evaluated in the same compiled call (the structured Jacobian evaluates
        its nine perturbed states at once). ``details`` needs a single state.
        """
        X = np.asarray(X, dtype=float)
        G = np.asarray(G, dtype=float)
        if X.ndim == 2:
            return self._evaluate_one(X, G, details)
        batch = X.shape[:-2]
        if details:
            raise InputError("skidding.ball evaluate(details=True)", X.shape,
                             "a single state (Z, 6)")
        n_states = batch[0] if len(batch) == 1 else int(np.prod(batch))
        self.n_eval += n_states
        # a sum is finite iff every term is (the unknowns are far below overflow)
        if not (math.isfinite(X.sum()) and math.isfinite(G.sum())):
            raise InputError("skidding.ball unknowns", "non-finite values", "finite values")
        md = self.models
        Z = self.Z
        nk = self._arc.shape[1]
        Xb = np.ascontiguousarray(X.reshape(n_states, Z, N_BALL))
        Gb = np.ascontiguousarray(G.reshape(n_states, N_GLOBAL))
        # drag on each ball (Python model callable) applied at the ball centre, and the cage
        # torques: memoised per cage speed
        per_wc = [self._cage_torques(w) for w in Gb[:, 2].tolist()]
        if md.drag_radius is None:
            wc1 = G[..., 2:3]                                 # (..., 1)
            u_ball = (wc1 * (1.0 - md.oil_speed_ratio)) * X[..., 1]
            Fd = np.asarray(md.ball_drag(np.abs(u_ball)), float) * np.sign(u_ball)
            Fd_b = np.ascontiguousarray(np.broadcast_to(Fd, batch + (Z,)).reshape(n_states, Z))
        else:
            # drag force at the drag radius times r_drag (memoised), over the ball radius
            fd_num = np.array([t[3] for t in per_wc])
            Fd_b = fd_num[:, None] / Xb[:, :, 1]
        n = n_states * Z * nk
        geo = np.empty((N_GEO, n))
        film = np.empty(n)
        tr = np.empty((n, 6))
        pocket = np.empty((n_states, Z, N_POCKET))
        R = np.empty((n_states, Z, N_BALL))
        Gc = np.empty((n_states, Z, N_GLOBAL))
        reuse, tr_ref = self._reuse_flags(Xb, Gb)
        self._kernels(Xb, Gb, Fd_b, reuse, tr_ref, geo, film, tr, pocket, R, Gc)
        G0 = np.empty((n_states, N_GLOBAL))
        G0[:, 0] = self.Fa / self.F_s
        G0[:, 1] = self.Fr / self.F_s
        G0[:, 2] = [-(t[0] + t[1]) / self.T_s for t in per_wc]
        G0 = G0.reshape(batch + (N_GLOBAL,))
        R = R.reshape(batch + (Z, N_BALL))
        Gc = Gc.reshape(batch + (Z, N_GLOBAL))
        return R, Gc, G0, None

    def _kernels(self, Xb, Gb, Fd_b, reuse, tr_ref, geo, film, tr, pocket, R, Gc):
        """Fill the output arrays: the fused compiled kernel when the traction law and film
        have one, else the staged path. Returns the film array the residual used."""
        if self._fused:
            ln_tab, slope_tab, inv_dp, p_max = self._tab if self._tab else (_EMPTY, _EMPTY,
                                                                             0.0, 0.0)
            if _ball_residual_fused(Xb, Gb, self._cpsi, self._arc, self._c,
                                    self._film_params, self._law_id, self._law_params,
                                    ln_tab, slope_tab, inv_dp, p_max, *self._rule, Fd_b,
                                    reuse, tr_ref, geo, film, tr, pocket, R, Gc):
                return film
        return self._staged(Xb, Gb, Fd_b, reuse, tr_ref, geo, film, tr, pocket, R, Gc)

    def _evaluate_one(self, X: np.ndarray, G: np.ndarray, details: bool):
        """:meth:`evaluate` of a single state (Z, 6), (3,): the Newton iterations' call, with
        the Python around the compiled kernel kept short (:func:`_residual_one`; the same
        kernels and inputs as the batch path). Also sets ``last_norm``, the scaled residual
        norm of this state."""
        last = self._last
        if (last is not None and G[2] == last[1][2] and _same_state(X, last[0], G, last[1])):
            # the last state evaluated (the converged one for the details; a warm start's
            # start, see :meth:`reloaded`): its residual and details from that pass
            self.last_norm = last[4]
            return (*last[2], last[3]() if details else None)
        self.n_eval += 1
        md = self.models
        Z = self.Z
        nk = self._arc.shape[1]
        wc = float(G[2])
        torques = self._torque_memo.get(wc)
        if torques is None:
            torques = self._cage_torques(wc)
        G0 = np.array([self._g0a, self._g0r, -(torques[0] + torques[1]) / self.T_s])
        if md.drag_radius is None:
            u_ball = (wc * (1.0 - md.oil_speed_ratio)) * X[:, 1]
            Fd_in = np.ascontiguousarray(
                np.asarray(md.ball_drag(np.abs(u_ball)), float) * np.sign(u_ball))
            fd_num = 0.0
        else:
            # drag force at the drag radius times r_drag (memoised), over the ball radius
            Fd_in, fd_num, u_ball = _EMPTY, torques[3], torques[4]
        status = 2
        if self._fused:
            ln_tab, slope_tab, inv_dp, p_max = self._tab if self._tab else _NO_TAB
            status, R, Gc, nrm, geo, film, tr, pocket, Fd = _residual_one(
                np.ascontiguousarray(X, dtype=float), np.ascontiguousarray(G, dtype=float),
                self._cpsi, self._arc, self._c, self._film_params, self._law_id,
                self._law_params, ln_tab, slope_tab, inv_dp, p_max, *self._rule, fd_num,
                Fd_in, G0)
            if status == 1:
                raise InputError("skidding.ball unknowns", "non-finite values", "finite values")
            film_out = film
        if status == 2:
            # staged path (Python film / per-node viscosity, or a pressure beyond the table)
            if not (math.isfinite(X.sum()) and math.isfinite(G.sum())):
                raise InputError("skidding.ball unknowns", "non-finite values", "finite values")
            Xb = np.ascontiguousarray(X, dtype=float).reshape(1, Z, N_BALL)
            Gb = np.ascontiguousarray(G, dtype=float).reshape(1, N_GLOBAL)
            Fd_b = (Fd_in.reshape(1, Z) if md.drag_radius is None
                    else fd_num / Xb[:, :, 1])
            n = Z * nk
            geo = np.empty((N_GEO, n))
            film = np.empty(n)
            tr = np.empty((n, 6))
            pocket3 = np.empty((1, Z, N_POCKET))
            R3 = np.empty((1, Z, N_BALL))
            Gc3 = np.empty((1, Z, N_GLOBAL))
            film_out = self._staged(Xb, Gb, Fd_b, _NO_REUSE, _EMPTY_TR, geo, film, tr,
                                    pocket3, R3, Gc3)
            R, Gc, pocket, Fd = R3[0], Gc3[0], pocket3[0], Fd_b[0]
            nrm = _residual_norm_nb(R, Gc, G0)
        if md.drag_radius is None:
            Fd = Fd_in

        fields = (geo.reshape(N_GEO, Z, nk), tr.reshape(Z, nk, 6), pocket, Fd, u_ball,
                  None if film_out is None else film_out.reshape(Z, nk))

        def make_details():
            return self._details(X, G, *fields)

        Xc, Gcp = X.copy(), G.copy()
        self._last = (Xc, Gcp, (R, Gc, G0), make_details, nrm, fields)
        self._last_tr = (Xc, Gcp, tr)
        self.last_norm = nrm
        return R, Gc, G0, (make_details() if details else None)

    def evaluate_fields(self, X: np.ndarray, G: np.ndarray):
        """(R, Gc, G0, fields) of one state (Z, 6), (3,) -- the memo when (X, G) is the last
        state evaluated -- with fields = (geo (N_GEO, Z, k), tractions (Z, k, 6), pocket
        (Z, N_POCKET), F_d (Z,), u_ball, film (Z, k) or None), the arrays the details are built
        from (:meth:`_details`); the result building reads them without the details dict."""
        R, Gc, G0, _ = self._evaluate_one(np.asarray(X, dtype=float),
                                          np.asarray(G, dtype=float), False)
        fields = self._last[5]
        _contact_angles(fields[0].reshape(N_GEO, -1))
        return R, Gc, G0, fields

    def chord_kernel_args(self):
        """Arguments of the compiled residual :func:`_residual_one` after (X, G) and before
        the drag inputs, for compiled callers (``ball_newton._chord_phase``); None when the
        system does not run the fused kernel with the ball drag at a fixed radius."""
        if not (self._fused and self._tab is not None and self.models.drag_radius is not None):
            return None
        return (self._cpsi, self._arc, self._c, self._film_params, self._law_id,
                self._law_params, *self._tab, *self._rule)

    def store_last(self, X, G, R, Gc, G0, nrm, geo, film, tr, pocket, Fd, u_ball) -> None:
        """Make (X, G) the last evaluated state (the memo of :meth:`evaluate` and the
        details of the result) from fields computed by a compiled caller with the same
        kernel (``ball_newton._chord_phase``); X, G must not be modified afterwards."""
        Z, nk = self.Z, self._arc.shape[1]
        fields = (geo.reshape(N_GEO, Z, nk), tr.reshape(Z, nk, 6), pocket, Fd, u_ball,
                  film.reshape(Z, nk))

        def make_details():
            return self._details(X, G, *fields)

        self._last = (X, G, (R, Gc, G0), make_details, nrm, fields)
        self._last_tr = (X, G, tr)
        self.last_norm = nrm

    def _staged(self, Xb, Gb, Fd_b, reuse, tr_ref, geo, film, tr, pocket, R, Gc):
        """The residual in stages: compiled geometry, the film model and the film law's
        viscosity in Python (any callables), compiled forces. Returns the film (or None)."""
        md = self.models
        _ball_geometry(Xb, Gb, self._cpsi, self._arc, self._c, geo)
        n = geo.shape[1]
        pshape = self._rule[2]
        out_film = None
        if self._film_params is not None:
            ry = np.ascontiguousarray(np.tile(self._arc[A_RY], n // self._arc.shape[1]))
            film[:] = guarded_film_array(geo[G_UE], geo[G_Q], geo[G_RX], ry, self._film_params)
            out_film = film
        elif md.film_thickness is not None:
            Q = geo[G_Q]
            ry = np.tile(self._arc[A_RY], n // self._arc.shape[1])
            h = md.film_thickness(np.abs(geo[G_UE]), Q, geo[G_RX], ry)
            film[:] = np.broadcast_to(np.asarray(h, dtype=float), Q.shape)
            if not np.all(film[Q > 0] > 0):
                raise InputError("skidding.ball film_thickness", "values <= 0 at loaded "
                                 "contacts", "a film thickness > 0 [m]")
            out_film = film
        else:
            film[:] = 1.0        # unused by laws without a film
        visc_mode, ln_tab, slope_tab, inv_dp = 0, _EMPTY, _EMPTY, 0.0
        eta_nodes = _EMPTY2
        if self._law_id == EYRING:
            pn = _node_pressures(geo[G_Q], geo[G_A], geo[G_B], pshape, True)
            visc_mode, ln_tab, slope_tab, inv_dp = viscosity_source(
                md.traction_law, md.temperature, float(pn.max()) if pn.size else 0.0)
            if visc_mode == 2:
                eta_nodes = np.ascontiguousarray(np.broadcast_to(np.asarray(
                    md.traction_law.lubricant.dynamic_viscosity(md.temperature, pn),
                    dtype=float), pn.shape))
        _ball_forces(Xb, Gb, self._cpsi, self._arc, self._c, geo, film, self._law_id,
                     self._law_params, visc_mode, ln_tab, slope_tab, inv_dp, eta_nodes,
                     *self._rule, Fd_b, reuse, tr_ref, tr, pocket, R, Gc)
        return out_film

    def _reuse_flags(self, Xb, Gb):
        """Per state of the batch: 1 if its contact inputs (ball positions and spins, ring
        displacements, cage speed) equal those of the last single state evaluated, whose
        tractions are then copied (the Jacobian's Q_p column), else 0."""
        ref = self._last_tr
        nb = Xb.shape[0]
        reuse = np.zeros(nb, dtype=np.int64)
        if ref is None or nb == 1:
            return reuse, _EMPTY_TR
        Xr, Gr, tr_ref = ref
        same = (Xb[:, :, :N_BALL - 1] == Xr[:, :N_BALL - 1]).all(axis=(1, 2)) & (
            Gb == Gr).all(axis=1)
        reuse[same] = 1
        return reuse, tr_ref

    def _details(self, X, G, geo, tr, pocket, Fd, u_ball, film):
        """Heat, shaft torque and the contact fields of one evaluated state (energy audit)."""
        md = self.models
        wi = self.speed
        t_churn, t_guide, wg = self._cage_torques(float(G[2]))[:3]
        wc = float(G[2])
        _contact_angles(geo.reshape(N_GEO, -1))
        approach, Q, na, nr = geo[G_APPROACH], geo[G_Q], geo[G_NA], geo[G_NR]
        cf = ContactField(approach, Q, na, nr, geo[G_L], geo[G_ALPHA], geo[G_K])
        ry = self._ry_zk
        ctr = ContactTraction(tr[..., 0], tr[..., 1], tr[..., 2], tr[..., 3], tr[..., 4],
                              tr[..., 5])
        # heat and shaft torque (energy audit): pocket heat, drag power (given to the oil,
        # all dissipated) and the torque of the balls on the inner ring, compiled
        pocket_heat, drag_heat, shaft = _energy_audit(X, wc, geo, tr, pocket,
                                                      np.asarray(Fd, dtype=float),
                                                      self.inner_f)
        cage_heat = t_churn * wc
        guide_heat = t_guide * (wc - wg)
        inner_torque = self._inner_torque()
        if md.guide_on_inner_ring:
            inner_torque += t_guide       # the land's reaction on the inner ring
        shaft += inner_torque
        det = dict(cf=cf, wc=wc, a=geo[G_A], b=geo[G_B], p0=geo[G_P0], rx=geo[G_RX], ry=ry,
                   film=film, Vx=geo[G_VX], Vy=geo[G_VY], Om_x=geo[G_OMX], Om_y=geo[G_OMY],
                   Om_z=geo[G_OMZ], ue=geo[G_UE], tr=ctr, Fd=Fd, u_ball=u_ball,
                   pocket_heat=pocket_heat, contact_heat=ctr.heat, drag_heat=drag_heat,
                   cage_heat=cage_heat, guide_heat=guide_heat,
                   inner_churn_heat=inner_torque * wi, shaft_torque=shaft,
                   pocket_sliding=pocket[:, P_WN], Fc=pocket[:, P_FC])
        return det

    def _cage_torques(self, wc: float):
        """(churning torque, guide torque, guide speed, ball drag force at the drag radius
        times the drag radius, ball speed at the drag radius) at cage speed wc (memoised:
        the Jacobian's ball columns and the line search revisit the same wc; the last two
        are None without a fixed ``drag_radius``)."""
        hit = self._torque_memo.get(wc)
        if hit is not None:
            return hit
        md = self.models
        t_churn = float(md.cage_torque(wc))
        wg = self.speed if md.guide_on_inner_ring else 0.0
        t_guide = 0.0 if md.cage_guide_torque is None else float(md.cage_guide_torque(wc, wg))
        fd_num = u_ball = None
        if md.drag_radius is not None:
            # the drag model called with a float (session 8: ~14 -> ~5 us per new cage speed
            # for the default model; a model returning a size-1 array is accepted too)
            u = wc * (1.0 - md.oil_speed_ratio) * md.drag_radius
            u_ball = np.array([u])
            sign = 1.0 if u > 0.0 else (-1.0 if u < 0.0 else 0.0)
            fd_num = (np.asarray(md.ball_drag(abs(u)), dtype=float).item() * sign
                      * md.drag_radius)
        if len(self._torque_memo) > 64:
            self._torque_memo.clear()
        self._torque_memo[wc] = (t_churn, t_guide, wg, fd_num, u_ball)
        return self._torque_memo[wc]

    def _inner_torque(self) -> float:
        """Churning torque on the inner ring at the ring speed [N m] (memoised)."""
        if self._inner_torque_memo is None:
            self._inner_torque_memo = float(self.models.inner_ring_torque(self.speed))
        return self._inner_torque_memo

    def reloaded(self, radial_load: float, axial_load: float) -> ball_residual_system:
        """The same system (bearing, models, speed, Z) at other loads: a copy that shares the
        load-independent constants and the cage-speed memo (warm starts)."""
        new = object.__new__(type(self))             # copy.copy without its protocol
        new.__dict__.update(self.__dict__)
        new._set_loads(radial_load, axial_load)
        new.n_eval = 0
        new.n_jac = 0
        new.last_jacobian = None
        new._last = None
        new._last_tr = None
        if self._last is not None:
            # the last evaluated state (a warm start's solution) at the new loads without the
            # kernel: the loads enter only the constant global part G0 and the scales (every
            # row is a force, moment or torque over F_s, F_s D/2 or F_s d_m/2, all
            # proportional to F_s); the contact fields, tractions and details do not depend
            # on them. Equal to a fresh evaluation to round-off (a few ulp).
            X, G, (R, Gc, _), details, _, fields = self._last
            f = self.F_s / new.F_s
            t = new._cage_torques(float(G[2]))
            G0 = np.array([new._g0a, new._g0r, -(t[0] + t[1]) / new.T_s])
            R, Gc = R * f, Gc * f
            new._last = (X, G, (R, Gc, G0), details, _residual_norm_nb(R, Gc, G0), fields)
            new._last_tr = self._last_tr
        return new

    def _set_loads(self, radial_load: float, axial_load: float) -> None:
        """Loads and the scales that depend on them (forces F_s, moments, cage torque)."""
        self.Fr = float(radial_load)
        self.Fa = float(axial_load)
        fc = self.m * (0.5 * abs(self.speed)) ** 2 * self.Rm
        self.F_s = max(abs(self.Fa) / self.Z, self.Fr / self.Z, fc, 10.0)
        self.M_s = self.F_s * 0.5 * self.D
        self.T_s = self.F_s * self.Rm
        self._g0a, self._g0r = self.Fa / self.F_s, self.Fr / self.F_s
        self._scales = None
        c = self._c.copy()
        c[C_FS], c[C_MS], c[C_TS] = self.F_s, self.M_s, self.T_s
        self._c = c

    # -- full residual vector (for scipy comparisons) -------------------------------------
    def full_residual(self, y: np.ndarray, x_ref: np.ndarray, g_ref: np.ndarray) -> np.ndarray:
        """Residual of the flat scaled unknown vector ``y`` (Z*6 + 3,)."""
        X, G = self.unscale(y, x_ref, g_ref)
        R, Gc, G0, _ = self.evaluate(X, G)
        return np.concatenate([R.ravel(), Gc.sum(0) + G0])

    # scaling of the unknowns: positions in microns from a reference, spins by omega_i d_m/D,
    # pocket force by F_s, ring displacement in microns, cage speed by omega_i
    def scales(self):
        """(xs (6,), gs (3,)), computed once per loads (read them, do not modify them)."""
        if self._scales is None:
            ws = self.w_s * 2.0 * self.Rm / self.D
            self._scales = (np.array([1e-6, 1e-6, ws, ws, ws, self.F_s]),
                            np.array([1e-6, 1e-6, self.w_s]))
        return self._scales

    def unscale(self, y, x_ref, g_ref):
        xs, gs = self.scales()
        Z = self.Z
        X = x_ref + y[: Z * N_BALL].reshape(Z, N_BALL) * xs
        G = g_ref + y[Z * N_BALL:] * gs
        return X, G
