"""Compiled kernels (numba, ``cache=True``) of the ball-bearing load distribution.

One job: the ONE implementation of the raceway-arc contacts (:func:`_contacts_nb`, Hertz
constants :func:`_arc_stiffness_nb`), the gyroscopic friction (:func:`_gyro_friction_nb`),
the damped block Newton of the load distribution (:func:`_ld_solve` and its helpers) and
the rigid-pair start (:func:`_rigid_pair_nb`), plus the packing of the arcs into the table
the kernels read (:func:`_arc_table`). The Python driver, the result type and the public
functions are in :mod:`thermobearing.loads` (which re-exports these names).

Sources: Jones 1959 / Harris & Kotzalas 2007 vol. 2 ch. 1-3 (arc contacts, equilibrium of
every ball), Harris & Kotzalas 2007 vol. 1 eq. 3.32 (series contacts of the rigid-pair
start), Hamrock & Brewe 1983 (Hertz constants: the compiled fast path
``hertz._hamrock_brewe_point_nb``). See the docstring of :mod:`thermobearing.loads` for the
model and Newton's safeguards.

Caching: numba's cache notices edits of this file only, so the caches are flushed when
``hertz.py`` (whose compiled function the kernels call) changes
(:func:`thermobearing.contact_traction.refresh_stale_caches`, tag ``loads_kernels``; all the
kernels that call each other live in this one file). Units: SI (m, N, rad/s, kg).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .hertz import _hamrock_brewe_point_nb
from .loads_arcs import INNER, ArcSet

# ---------------------------------------------------------------------------------------------
# compiled kernels (numba, cache=True): the ONE implementation of the arc contacts, the
# rigid-pair start and the Newton iteration of the load distribution (no numpy twin). The
# arcs enter as a table (N_ARC_ROWS, k); see :func:`_arc_table`.
# ---------------------------------------------------------------------------------------------
(T_CX, T_CR, T_FREE, T_INNER, T_SIGN, T_RY, T_CONF) = range(7)
N_ARC_ROWS = 7
# rows of the contact-field array (7, Z, k)
(F_APPROACH, F_LOAD, F_NX, F_NR, F_DIST, F_ALPHA, F_K) = range(7)


def _arc_table(arcs: ArcSet) -> np.ndarray:
    """(N_ARC_ROWS, k) float table of the arcs for the compiled kernels: centre x, centre r,
    free distance, inner (1/0), sign (+1 inner / -1 outer, for R_x), R_y = f D/(2 f - 1),
    conformity f."""
    inner = arcs.ring == INNER
    ry = arcs.conformity * arcs.ball_diameter / (2.0 * arcs.conformity - 1.0)
    return np.ascontiguousarray(np.stack([
        arcs.centre_x, arcs.centre_r, arcs.free_distance, inner.astype(float),
        np.where(inner, 1.0, -1.0), ry, arcs.conformity]).astype(float))


@numba.njit(cache=True)
def _arc_stiffness_nb(alpha: float, sign: float, ry: float, D: float, dm: float,
                      ep: float) -> float:
    """Hertz K [N/m^1.5] (Q = K delta^1.5) of an arc contact at contact angle ``alpha``
    [rad]: R_x = D (d_m -+ D cos(alpha)) / (2 d_m) (:meth:`geometry.BallBearing.curvature`,
    upper sign inner ring, ``sign`` = +1), R_y = f D / (2 f - 1) and the Hamrock-Brewe 1983
    closed form (Hamrock 2004 ch. 17; :func:`thermobearing.hertz._hamrock_brewe_point_nb`,
    within about 1 % of the exact elliptic-integral solution; the exact form costs a root
    solve per contact). The ball skidding residual uses the same Hertz kernel."""
    rx = 0.5 * D * (1.0 - sign * (D * math.cos(alpha) / dm))
    return _hamrock_brewe_point_nb(rx, ry, ep)[3]


@numba.njit(cache=True)
def _contacts_nb(bx: np.ndarray, br: np.ndarray, da: float, dr: float, cpsi: np.ndarray,
                 tab: np.ndarray, D: float, dm: float, ep: float, K_fixed: np.ndarray,
                 out: np.ndarray) -> None:
    """Arc contacts of every (ball, arc) pair into ``out`` (7, Z, k): approach
    ``delta = L - (f - 1/2) D`` [m], load ``Q = K max(delta, 0)^1.5`` [N], unit vector
    (n_x, n_r) from the arc centre to the ball centre, L [m], contact angle
    ``atan2(n_x, |n_r|)`` [rad], K [N/m^1.5] (at the contact angle, or ``K_fixed[j, k]``
    when K_fixed is not empty). Inner-arc centres move with the ring (da, dr cos psi_j)."""
    nz = bx.size
    nk = tab.shape[1]
    fixed = K_fixed.shape[0] > 0
    for j in range(nz):
        for k in range(nk):
            inner = tab[T_INNER, k]
            cx = tab[T_CX, k] + inner * da
            cr = tab[T_CR, k] + inner * (dr * cpsi[j])
            dx, drr = bx[j] - cx, br[j] - cr
            L = math.hypot(dx, drr)
            nx, nr = dx / L, drr / L
            approach = L - tab[T_FREE, k]
            alpha = math.atan2(nx, abs(nr))
            if fixed:
                K = K_fixed[j, k]
            else:
                K = _arc_stiffness_nb(alpha, tab[T_SIGN, k], tab[T_RY, k], D, dm, ep)
            out[F_APPROACH, j, k] = approach
            out[F_LOAD, j, k] = K * max(approach, 0.0) ** 1.5
            out[F_NX, j, k] = nx
            out[F_NR, j, k] = nr
            out[F_DIST, j, k] = L
            out[F_ALPHA, j, k] = alpha
            out[F_K, j, k] = K


@numba.njit(cache=True)
def _gyro_friction_nb(cf: np.ndarray, tab: np.ndarray, D: float, J: float,
                      wm: np.ndarray, w_inner: float, gam0: float, alpha0: float,
                      mu: float, Mg: np.ndarray, fx: np.ndarray, fr: np.ndarray) -> None:
    """Transverse friction at the loaded contacts that carries the gyroscopic moment.

    Outer-race-control attitude ``tan(beta) = sin(alpha_o)/(cos(alpha_o) + gamma)`` (alpha_o
    the largest |angle| of the outer arcs) and spin (K2) of the primer
    ../shared/notes/over-skidding.md (sections 2.1, 2.3) with alpha_i = alpha_o = alpha_0 in
    the inner term (first order), ``M_g = J omega_R omega_m sin(beta)`` [N m] (section 3.3).
    The moment about the tangential axis is shared in proportion to normal load; the force on
    the ball at contact k [N] is along the in-plane tangent ``t = (n_r, -n_x)`` with
    ``(D/2) sum_k F_k = M_g`` and ``|F_k| <= mu Q_k``: (fx, fr) = F (n_r, -n_x).
    """
    nz, nk = cf.shape[1], cf.shape[2]
    ca0, sa0 = math.cos(alpha0), math.sin(alpha0)
    for j in range(nz):
        ao = 0.0
        for k in range(nk):
            if tab[T_INNER, k] == 0.0:
                ao = max(ao, abs(cf[F_ALPHA, j, k]))
        beta = math.atan2(math.sin(ao), math.cos(ao) + gam0)
        tb = math.tan(beta)
        denom = gam0 * math.cos(beta) * (
            (math.cos(ao) + tb * math.sin(ao)) / (1 + gam0 * math.cos(ao))
            + (ca0 + tb * sa0) / (1 - gam0 * ca0))
        wR = abs(w_inner) / max(denom, 1e-12)
        Mg[j] = J * wR * abs(wm[j]) * math.sin(beta)
        qtot = 0.0
        for k in range(nk):
            qtot += cf[F_LOAD, j, k]
        den = qtot if qtot > 0 else 1.0
        for k in range(nk):
            Q = cf[F_LOAD, j, k]
            F = min(2.0 * Mg[j] / D * Q / den, mu * Q)
            fx[j, k] = F * cf[F_NR, j, k]
            fr[j, k] = -F * cf[F_NX, j, k]


@numba.njit(cache=True)
def _ld_residual(bx: np.ndarray, br: np.ndarray, u: np.ndarray, K_fixed: np.ndarray,
                 cpsi: np.ndarray, tab: np.ndarray, c: np.ndarray, wm: np.ndarray,
                 gyro: bool, cf: np.ndarray, Rx: np.ndarray, Rr: np.ndarray,
                 Rg: np.ndarray, Fc: np.ndarray, Mg: np.ndarray, fx: np.ndarray,
                 fr: np.ndarray) -> float:
    """Force residuals of the load distribution at (ball positions, ring displacement u)
    [N]: per ball -sum_k Q_k n_k + F_c e_r (+ the gyroscopic friction); ring: applied load
    plus the reactions of the inner arcs. Fills the contact field ``cf`` (7, Z, k); returns
    the norm. c = (D, d_m, E', m, J, gamma_0, alpha_0, omega_i, mu, k_reg, F_a, F_r)."""
    D, dm, ep, m, J = c[0], c[1], c[2], c[3], c[4]
    gam0, alpha0, w_inner, mu = c[5], c[6], c[7], c[8]
    Fa, Fr = c[10], c[11]
    _contacts_nb(bx, br, u[0], u[1], cpsi, tab, D, dm, ep, K_fixed, cf)
    nz, nk = bx.size, tab.shape[1]
    if gyro:
        _gyro_friction_nb(cf, tab, D, J, wm, w_inner, gam0, alpha0, mu, Mg, fx, fr)
    else:
        Mg[:] = 0.0
    ra = Fa
    rrad = Fr
    acc = 0.0
    for j in range(nz):
        sx = sr = six = sir = rfx = rfr = 0.0
        for k in range(nk):
            Q = cf[F_LOAD, j, k]
            qx, qr = Q * cf[F_NX, j, k], Q * cf[F_NR, j, k]
            sx += qx
            sr += qr
            if tab[T_INNER, k] == 1.0:
                six += qx
                sir += qr
        Fc[j] = m * wm[j] ** 2 * br[j]
        Rx[j] = -sx
        Rr[j] = -sr + Fc[j]
        if gyro:
            gx = gr = 0.0
            for k in range(nk):
                gx += fx[j, k]
                gr += fr[j, k]
                if tab[T_INNER, k] == 1.0:
                    rfx -= fx[j, k]
                    rfr -= fr[j, k]
            Rx[j] += gx
            Rr[j] += gr
        ra += six + rfx
        rrad += (sir + rfr) * cpsi[j]
        acc += Rx[j] ** 2 + Rr[j] ** 2
    Rg[0], Rg[1] = ra, rrad
    return math.sqrt(acc + ra * ra + rrad * rrad)


@numba.njit(cache=True)
def _ld_newton_step(cf: np.ndarray, tab: np.ndarray, cpsi: np.ndarray, Rx: np.ndarray,
                    Rr: np.ndarray, Rg: np.ndarray, k_reg: float, k_ring: float,
                    dbx: np.ndarray, dbr: np.ndarray, du: np.ndarray) -> None:
    """Block-eliminated Newton step for (ball x, ball r) x Z and ring (delta_a, delta_r).

    Contact Hessian d(Q n)/d(b) = Q' n n^T + (Q/L)(I - n n^T), Q' = 1.5 K delta^0.5; ball
    block A = -sum_k H_k - k_reg I (dF_c/dr = m w^2 omitted: quasi-Newton), ring couplings
    through the inner arcs with P = diag(1, cos psi); Schur complement on the ring unknowns
    less ``k_ring`` I. ``k_reg`` and ``k_ring`` are Jacobian-only (Levenberg-Marquardt)
    springs: they hold a ball that touches nothing and move the ring towards contact when no
    ball touches; the converged solution does not depend on them."""
    nz, nk = Rx.size, tab.shape[1]
    s00 = s01 = s10 = s11 = 0.0          # S = Dm - sum C A^-1 B - k_ring I
    r0, r1 = -Rg[0], -Rg[1]
    ai = np.empty((nz, 4))
    bb = np.empty((nz, 4))
    for j in range(nz):
        hxx = hxr = hrr = ixx = ixr = irr = 0.0
        for k in range(nk):
            dlt = max(cf[F_APPROACH, j, k], 0.0)
            qp = 1.5 * cf[F_K, j, k] * math.sqrt(dlt)
            ql = cf[F_LOAD, j, k] / cf[F_DIST, j, k]
            nx, nr = cf[F_NX, j, k], cf[F_NR, j, k]
            a_ = qp * nx * nx + ql * (1 - nx * nx)
            b_ = (qp - ql) * nx * nr
            c_ = qp * nr * nr + ql * (1 - nr * nr)
            hxx += a_
            hxr += b_
            hrr += c_
            if tab[T_INNER, k] == 1.0:
                ixx += a_
                ixr += b_
                irr += c_
        a00, a01, a11 = -hxx - k_reg, -hxr, -hrr - k_reg
        det = a00 * a11 - a01 * a01
        i00, i01, i11 = a11 / det, -a01 / det, a00 / det     # A^-1 (symmetric)
        cp = cpsi[j]
        # B = Hi P, C = P Hi (= B^T)
        b00, b01, b10, b11 = ixx, ixr * cp, ixr, irr * cp
        # A^-1 B
        q00 = i00 * b00 + i01 * b10
        q01 = i00 * b01 + i01 * b11
        q10 = i01 * b00 + i11 * b10
        q11 = i01 * b01 + i11 * b11
        # C A^-1 B with C = B^T
        s00 -= b00 * q00 + b10 * q10
        s01 -= b00 * q01 + b10 * q11
        s10 -= b01 * q00 + b11 * q10
        s11 -= b01 * q01 + b11 * q11
        # Dm = -sum P Hi P
        s00 -= ixx
        s01 -= ixr * cp
        s10 -= ixr * cp
        s11 -= irr * cp * cp
        # rhs += C A^-1 R_b
        x0 = i00 * Rx[j] + i01 * Rr[j]
        x1 = i01 * Rx[j] + i11 * Rr[j]
        r0 += b00 * x0 + b10 * x1
        r1 += b01 * x0 + b11 * x1
        ai[j, 0], ai[j, 1], ai[j, 2] = i00, i01, i11
        bb[j, 0], bb[j, 1], bb[j, 2], bb[j, 3] = b00, b01, b10, b11
    s00 -= k_ring
    s11 -= k_ring
    det = s00 * s11 - s01 * s10
    du[0] = (s11 * r0 - s01 * r1) / det
    du[1] = (s00 * r1 - s10 * r0) / det
    for j in range(nz):
        i00, i01, i11 = ai[j, 0], ai[j, 1], ai[j, 2]
        b00, b01, b10, b11 = bb[j, 0], bb[j, 1], bb[j, 2], bb[j, 3]
        v0 = -Rx[j] - (b00 * du[0] + b01 * du[1])
        v1 = -Rr[j] - (b10 * du[0] + b11 * du[1])
        dbx[j] = i00 * v0 + i01 * v1
        dbr[j] = i01 * v0 + i11 * v1


@numba.njit(cache=True)
def _ld_ball_trial(bx: np.ndarray, br: np.ndarray, dbx: np.ndarray, dbr: np.ndarray,
                   lam: np.ndarray, arc: np.ndarray, bx2: np.ndarray, br2: np.ndarray) -> None:
    """Ball positions ``b + lam_j db_j`` with a curvature correction: a loaded ball is put back
    at the distances from the centres of its (up to two) most loaded arcs that the linear step
    predicts, ``L + lam_j (db_j . n)``: on that circle about the one arc centre, or at the
    intersection of the two circles nearest the straight trial. A straight step along the
    groove (the ball rolling down a flank to the groove bottom, or rolling along both arcs of
    a diagonal contact pair while the ring moves axially) otherwise climbs the arcs by
    s^2 / (2 L), which for a lightly loaded ball is a large load (SKF6304, 10 N at 10 r/min:
    22 um along the flank, 0.85 um into the race, 20 N against 9e-6 N). The correction is
    second order in the step, so Newton's local convergence is kept.
    ``arc`` rows: (count, c_x, c_r, L, db . n) of the first arc, then the same of the second."""
    for j in range(bx.size):
        x = bx[j] + lam[j] * dbx[j]
        r = br[j] + lam[j] * dbr[j]
        if arc[j, 0] > 0.0:
            ax, ar = arc[j, 1], arc[j, 2]
            la = arc[j, 3] + lam[j] * arc[j, 4]
            ex, er = x - ax, r - ar
            dist = math.hypot(ex, er)
            done = False
            if arc[j, 0] > 1.0 and la > 0.0:
                cx, cr = arc[j, 5], arc[j, 6]
                lb = arc[j, 7] + lam[j] * arc[j, 8]
                dx, dr = cx - ax, cr - ar
                d = math.hypot(dx, dr)
                if d > 0.0 and lb > 0.0:
                    a = (la * la - lb * lb + d * d) / (2.0 * d)
                    h2 = la * la - a * a
                    if h2 >= 0.0:
                        h = math.sqrt(h2)
                        px, pr = ax + a * dx / d, ar + a * dr / d
                        # the two intersections; keep the one nearer the straight trial
                        x1, r1 = px - h * dr / d, pr + h * dx / d
                        x2, r2 = px + h * dr / d, pr - h * dx / d
                        if (x1 - x) ** 2 + (r1 - r) ** 2 <= (x2 - x) ** 2 + (r2 - r) ** 2:
                            x, r = x1, r1
                        else:
                            x, r = x2, r2
                        done = True
            if not done and dist > 0.0 and la > 0.0:
                x = ax + ex * la / dist
                r = ar + er * la / dist
        bx2[j] = x
        br2[j] = r


@numba.njit(cache=True)
def _ld_damped_balls(bx: np.ndarray, br: np.ndarray, u: np.ndarray, dbx: np.ndarray,
                     dbr: np.ndarray, du: np.ndarray, K: np.ndarray, cpsi: np.ndarray,
                     tab: np.ndarray, c: np.ndarray, wm: np.ndarray, gyro: bool,
                     cf2: np.ndarray, Fc2: np.ndarray, Mg2: np.ndarray, fx: np.ndarray,
                     fr: np.ndarray, bx2: np.ndarray, br2: np.ndarray,
                     u2: np.ndarray) -> float:
    """Trial step with the ring moved by ``du`` and ball j by ``lam_j db_j``. Writes the trial
    into (bx2, br2, u2); returns its residual norm [N].

    lam_j starts at 1, or shorter where the step closes a contact that is open at the trial
    ring position: it then stops where that contact's approach is ``(|R_j| / K)^(2/3)``,
    the approach whose Hertz load equals the ball's residual force |R_j| (so the contact
    enters the next Jacobian loaded, instead of far beyond its first touch; a ball pinched
    between an open inner and a loaded outer contact otherwise crawls towards the inner one).
    lam_j is then halved (at most 30 times) until ball j's own force residual at the trial
    ring position is no larger than with the ball left in place or at the start, whichever is
    larger (twice that for a ball stopped at a contact)."""
    nz, nk = bx.size, tab.shape[1]
    Rx, Rr, Rg = np.empty(nz), np.empty(nz), np.empty(2)
    ref = np.empty(nz)
    app0 = np.empty((nz, nk))
    lam = np.ones(nz)
    event = np.zeros(nz, np.bool_)
    u2[0] = u[0] + du[0]
    u2[1] = u[1] + du[1]
    _ld_residual(bx, br, u, K, cpsi, tab, c, wm, gyro, cf2, Rx, Rr, Rg, Fc2, Mg2, fx, fr)
    for j in range(nz):
        ref[j] = math.hypot(Rx[j], Rr[j])
    _ld_residual(bx, br, u2, K, cpsi, tab, c, wm, gyro, cf2, Rx, Rr, Rg, Fc2, Mg2, fx, fr)
    # the two most loaded contacts of each ball at the trial ring position (the second only
    # if it carries at least 1 % of the first): arc centres, distances and the step's normal
    # components, for the curvature correction of _ld_ball_trial
    arc = np.zeros((nz, 9))
    for j in range(nz):
        ref[j] = max(ref[j], math.hypot(Rx[j], Rr[j]))
        k1 = k2 = -1
        for k in range(nk):
            app0[j, k] = cf2[F_APPROACH, j, k]
            q = cf2[F_LOAD, j, k]
            if q > 0.0:
                if k1 < 0 or q > cf2[F_LOAD, j, k1]:
                    k2 = k1
                    k1 = k
                elif k2 < 0 or q > cf2[F_LOAD, j, k2]:
                    k2 = k
        if k2 >= 0 and cf2[F_LOAD, j, k2] < 0.01 * cf2[F_LOAD, j, k1]:
            k2 = -1
        for slot, k in ((0, k1), (1, k2)):
            if k >= 0:
                dist, nx, nr = cf2[F_DIST, j, k], cf2[F_NX, j, k], cf2[F_NR, j, k]
                o = 1 + 4 * slot
                arc[j, 0] += 1.0
                arc[j, o] = bx[j] - dist * nx
                arc[j, o + 1] = br[j] - dist * nr
                arc[j, o + 2] = dist
                arc[j, o + 3] = dbx[j] * nx + dbr[j] * nr
    _ld_ball_trial(bx, br, dbx, dbr, lam, arc, bx2, br2)
    _ld_residual(bx2, br2, u2, K, cpsi, tab, c, wm, gyro, cf2, Rx, Rr, Rg, Fc2, Mg2, fx, fr)
    for j in range(nz):
        for k in range(nk):
            a0, a1 = app0[j, k], cf2[F_APPROACH, j, k]
            if a0 < 0.0 and K[j, k] > 0.0:
                target = (max(ref[j], 1e-300) / K[j, k]) ** (2.0 / 3.0)
                if a1 > target:
                    lj = (target - a0) / (a1 - a0)
                    if lj < lam[j]:
                        lam[j] = lj
                        event[j] = True
    n2 = np.inf
    for _ls in range(31):
        _ld_ball_trial(bx, br, dbx, dbr, lam, arc, bx2, br2)
        n2 = _ld_residual(bx2, br2, u2, K, cpsi, tab, c, wm, gyro, cf2, Rx, Rr, Rg, Fc2, Mg2,
                          fx, fr)
        done = True
        for j in range(nz):
            allowed = 2.0 * ref[j] if event[j] else ref[j]
            if math.hypot(Rx[j], Rr[j]) > allowed and lam[j] > 1e-9:
                lam[j] *= 0.5
                done = False
        if done:
            break
    return n2


@numba.njit(cache=True)
def _ld_solve(bx: np.ndarray, br: np.ndarray, u: np.ndarray, cpsi: np.ndarray,
              tab: np.ndarray, c: np.ndarray, wm: np.ndarray, gyro: bool, tol_abs: float,
              step_max: float, k_ring: float, max_iter: int, cf: np.ndarray,
              Fc: np.ndarray, Mg: np.ndarray) -> tuple[float, int, bool]:
    """Damped Newton of the load distribution in place on (bx, br, u): fresh Hertz K at the
    current contact angles for the residual and the step, K frozen in the backtracking line
    search on the residual norm (Armijo 1e-4, at most 30 halvings), each ball's step and the
    ring's capped at ``step_max``, per-ball damping tried first (:func:`_ld_damped_balls`),
    Levenberg-Marquardt springs (``c[9]`` on the balls, ``k_ring`` on the ring) relaxed after
    full steps. Returns (norm [N], iterations, converged); ``cf``, ``Fc``, ``Mg`` hold the
    last residual pass (at the solution when converged)."""
    nz, nk = bx.size, tab.shape[1]
    Rx, Rr, Rg = np.empty(nz), np.empty(nz), np.empty(2)
    fx, fr = np.empty((nz, nk)), np.empty((nz, nk))
    dbx, dbr, du = np.empty(nz), np.empty(nz), np.empty(2)
    bx2, br2, u2 = np.empty(nz), np.empty(nz), np.empty(2)
    cf2 = np.empty_like(cf)
    Fc2, Mg2 = np.empty(nz), np.empty(nz)
    Rx2, Rr2, Rg2 = np.empty(nz), np.empty(nz), np.empty(2)
    no_k = np.empty((0, 0))
    K = np.empty((nz, nk))
    k_reg = c[9]
    kb, kr = k_reg, k_ring
    it = 0
    norm = np.inf
    for _ in range(max_iter):
        it += 1
        norm = _ld_residual(bx, br, u, no_k, cpsi, tab, c, wm, gyro, cf, Rx, Rr, Rg, Fc, Mg,
                            fx, fr)
        if norm <= tol_abs:
            return norm, it, True
        for j in range(nz):     # element loops: a slice assignment from an array compiles
            for k in range(nk):  # numba's shape-mismatch message code (seconds)
                K[j, k] = cf[F_K, j, k]
        _ld_newton_step(cf, tab, cpsi, Rx, Rr, Rg, kb, kr, dbx, dbr, du)
        # each ball's step and the ring's capped at step_max on their own: a free ball's
        # large step must not shorten everyone else's
        for j in range(nz):
            cap = min(1.0, step_max / max(abs(dbx[j]), abs(dbr[j]), 1e-300))
            dbx[j] *= cap
            dbr[j] *= cap
        scale = min(1.0, step_max / max(abs(du[0]), abs(du[1]), 1e-300))
        du[0] *= scale
        du[1] *= scale
        # Per-ball damping first: a ball at the edge of the load zone whose
        # open contact is a fraction of a micrometre from closing has almost no stiffness
        # across it, so its Newton step can drive it deep into that contact; a global line
        # search then cuts every step and the loaded balls and the ring crawl. Each ball's
        # residual depends only on its own position and the ring, so each ball is
        # backtracked on its own residual at the trial ring position; the combined step is
        # kept when it passes the global Armijo test, otherwise the global backtracking
        # decides.
        n2 = _ld_damped_balls(bx, br, u, dbx, dbr, du, K, cpsi, tab, c, wm, gyro, cf2, Fc2,
                              Mg2, fx, fr, bx2, br2, u2)
        if n2 < (1.0 - 1e-4) * norm:
            for j in range(nz):
                bx[j] = bx2[j]
                br[j] = br2[j]
            u[0] = u2[0]
            u[1] = u2[1]
            kb = max(0.1 * kb, 1e-10 * k_reg)
            kr = max(0.1 * kr, 1e-10 * k_ring)
            continue
        lam = 1.0
        for _ls in range(30):
            for j in range(nz):
                bx2[j] = bx[j] + lam * dbx[j]
                br2[j] = br[j] + lam * dbr[j]
            u2[0] = u[0] + lam * du[0]
            u2[1] = u[1] + lam * du[1]
            n2 = _ld_residual(bx2, br2, u2, K, cpsi, tab, c, wm, gyro, cf2, Rx2, Rr2, Rg2,
                              Fc2, Mg2, fx, fr)
            if n2 < (1.0 - 1e-4 * lam) * norm or (n2 <= norm and lam == 1.0) or lam < 1e-6:
                break
            lam *= 0.5
        # Levenberg-Marquardt update of the Jacobian-only springs: relax them after a full
        # step, stiffen them (up to their start values) after a cut one
        if lam == 1.0:
            kb = max(0.1 * kb, 1e-10 * k_reg)
            kr = max(0.1 * kr, 1e-10 * k_ring)
        else:
            kb = min(4.0 * kb, k_reg)
            kr = min(4.0 * kr, k_ring)
        for j in range(nz):
            bx[j] += lam * dbx[j]
            br[j] += lam * dbr[j]
        u[0] += lam * du[0]
        u[1] += lam * du[1]
    return norm, it, False


@numba.njit(cache=True)
def _pair_state(u: np.ndarray, cpsi: np.ndarray, tab: np.ndarray, pi_: np.ndarray,
                po_: np.ndarray, keff: np.ndarray, A: np.ndarray, F: np.ndarray,
                Q: np.ndarray, ex: np.ndarray, er: np.ndarray, Jm: np.ndarray,
                res: np.ndarray) -> float:
    """Rigid-ball pairs at ring displacement u: pair loads Q (Z, p) [N], unit vectors
    (ex, er) from the outer to the inner arc centre, the ring residual ``res`` = F - sum Q e
    [N] and its Jacobian Jm (2, 2); returns the residual norm [N]."""
    nz, npair = Q.shape
    s0 = s1 = j00 = j01 = j11 = 0.0
    for j in range(nz):
        cp = cpsi[j]
        for p in range(npair):
            i, o = pi_[p], po_[p]
            dx = tab[T_CX, i] + u[0] - tab[T_CX, o]
            dr = tab[T_CR, i] + u[1] * cp - tab[T_CR, o]
            dist = math.hypot(dx, dr)
            zeta = max(dist - A[p], 0.0)
            q = keff[p] * zeta ** 1.5
            e0, e1 = dx / dist, dr / dist
            Q[j, p], ex[j, p], er[j, p] = q, e0, e1
            s0 += q * e0
            s1 += q * e1 * cp
            dq = 1.5 * keff[p] * math.sqrt(zeta)
            j00 += dq * e0 * e0
            j01 += dq * e0 * e1 * cp
            j11 += dq * e1 * e1 * cp * cp
    Jm[0, 0], Jm[0, 1], Jm[1, 0], Jm[1, 1] = -j00, -j01, -j01, -j11
    res[0], res[1] = F[0] - s0, F[1] - s1
    return math.hypot(res[0], res[1])


@numba.njit(cache=True)
def _rigid_pair_nb(cpsi: np.ndarray, tab: np.ndarray, D: float, dm: float, ep: float,
                   alpha0: float, F: np.ndarray, fc: np.ndarray, bx: np.ndarray,
                   br: np.ndarray, u: np.ndarray) -> None:
    """Compiled core of :func:`rigid_pair_guess` (writes bx, br (Z,) and u (2,))."""
    nz, nk = cpsi.size, tab.shape[1]
    n_in = 0
    for k in range(nk):
        if tab[T_INNER, k] == 1.0:
            n_in += 1
    n_out = nk - n_in
    ii = np.empty(n_in, np.int64)
    oo = np.empty(n_out, np.int64)
    a = b = 0
    for k in range(nk):
        if tab[T_INNER, k] == 1.0:
            ii[a] = k
            a += 1
        else:
            oo[b] = k
            b += 1
    npair = n_in * n_out
    pi_ = np.empty(npair, np.int64)
    po_ = np.empty(npair, np.int64)
    for x in range(n_in):
        for y in range(n_out):
            pi_[x * n_out + y] = ii[x]
            po_[x * n_out + y] = oo[y]
    Ki = np.empty(nk)
    for k in range(nk):
        Ki[k] = _arc_stiffness_nb(alpha0, tab[T_SIGN, k], tab[T_RY, k], D, dm, ep)
    keff = np.empty(npair)
    A = np.empty(npair)
    for p in range(npair):
        keff[p] = (Ki[pi_[p]] ** (-2 / 3) + Ki[po_[p]] ** (-2 / 3)) ** (-1.5)
        A[p] = (tab[T_CONF, pi_[p]] + tab[T_CONF, po_[p]] - 1.0) * D
    Q, ex, er = np.empty((nz, npair)), np.empty((nz, npair)), np.empty((nz, npair))
    Jm = np.empty((2, 2))
    u[0] = u[1] = 0.0
    scale = max(max(abs(F[0]), abs(F[1])), 1.0)
    k_reg = scale / (0.01 * D)
    u2, res, res2 = np.empty(2), np.empty(2), np.empty(2)
    for _ in range(200):
        n0 = _pair_state(u, cpsi, tab, pi_, po_, keff, A, F, Q, ex, er, Jm, res)
        if n0 <= 1e-10 * scale:
            break
        r0, r1 = -res[0], -res[1]
        m00, m01, m10, m11 = Jm[0, 0] - k_reg, Jm[0, 1], Jm[1, 0], Jm[1, 1] - k_reg
        det = m00 * m11 - m01 * m10
        if not (abs(det) > 0.0 and math.isfinite(det)):
            # singular 2 x 2 system (found by a property test: a deep-groove bearing under a
            # radial load of 1 N or less at rest, the axial row vanishing as the
            # regularisation decays): keep the last displacement as the start, the full
            # Newton of ball_load_distribution takes it from there
            break
        d0 = (m11 * r0 - m01 * r1) / det
        d1 = (m00 * r1 - m10 * r0) / det
        lam = min(1.0, 0.01 * D / max(max(abs(d0), abs(d1)), 1e-300))
        while lam > 1e-8:
            u2[0], u2[1] = u[0] + lam * d0, u[1] + lam * d1
            if _pair_state(u2, cpsi, tab, pi_, po_, keff, A, F, Q, ex, er, Jm, res2) <= n0:
                break
            lam *= 0.5
        u[0] += lam * d0
        u[1] += lam * d1
        k_reg *= 0.3
    _pair_state(u, cpsi, tab, pi_, po_, keff, A, F, Q, ex, er, Jm, res)
    Rm = 0.5 * dm
    o0 = oo[0]
    for j in range(nz):
        best = 0
        for p in range(1, npair):
            if Q[j, p] > Q[j, best]:
                best = p
        qb = Q[j, best]
        if qb > 0.0:
            ko = po_[best]
            lo = tab[T_FREE, ko] + (qb / Ki[ko]) ** (2 / 3)
            bx[j] = tab[T_CX, ko] + lo * ex[j, best]
            br[j] = tab[T_CR, ko] + lo * er[j, best]
        elif fc[j] > 0.0:
            # unloaded ball seated radially in the outer groove by the centrifugal force:
            # both outer arcs (gothic) or the single outer arc share F_c
            if n_out == 2:
                half = 0.5 * abs(tab[T_CX, oo[0]] - tab[T_CX, oo[1]])
                lo = tab[T_FREE, o0] + (0.5 * fc[j] / Ki[o0]) ** (2 / 3)
                bx[j] = 0.0
                br[j] = tab[T_CR, o0] + math.sqrt(max(lo * lo - half * half, 0.0))
            else:
                lo = tab[T_FREE, o0] + (fc[j] / Ki[o0]) ** (2 / 3)
                bx[j] = tab[T_CX, o0]
                br[j] = tab[T_CR, o0] + lo
        else:
            bx[j] = 0.0
            br[j] = Rm


def _refresh_caches() -> None:
    from . import hertz
    from .contact_traction import refresh_stale_caches

    refresh_stale_caches("loads_kernels", (_arc_stiffness_nb, _contacts_nb, _gyro_friction_nb,
                                           _ld_residual, _ld_newton_step, _ld_ball_trial,
                                           _ld_damped_balls, _ld_solve,
                                           _pair_state,
                                           _rigid_pair_nb), (hertz,))


_refresh_caches()
