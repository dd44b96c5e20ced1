"""Quasi-static load distribution of ball bearings: every raceway arc treated on its own.

The inner ring is displaced axially (``delta_a``) and radially (``delta_r``, in the direction
of the radial load, azimuth 0) against the outer ring; every ball finds the centre position
(axial ``x``, radial ``r``) where the contact forces from the raceway arcs, the centrifugal
force and (optionally) the transverse friction that carries the gyroscopic moment are in
balance. Newton iterates on all ball positions and the two ring displacements together; the
ball blocks are 2 x 2 and independent except through the ring unknowns, so each step is
solved by block elimination (Schur complement on the ring unknowns).

Raceway geometry (Jones 1959 in the form of Harris & Kotzalas 2007, vol. 2, ch. 1-3; the
gothic-arch extension of the over-skidding primer ../shared/notes/over-skidding.md
section 4, where every arc is an independent contact): arc k of radius ``f_k D`` has its
curvature centre ``c_k`` in the axial plane of the ball (outer arcs fixed, inner arcs moving
with the inner ring). With ``L = |b - c_k|`` the ball centre distance, the elastic approach is
``delta_k = L - (f_k - 1/2) D`` and the normal load ``Q_k = K_k max(delta_k, 0)^{3/2}`` acts
on the ball along ``-(b - c_k)/L`` (towards the arc centre). The contact angle of arc k is the
angle of ``b - c_k`` to the radial plane. A four-point (gothic-arch) bearing has four arcs per
ball, so two-, three- and four-point contact appear whenever the geometry and loads give them.

Implementation: the arc contacts, the rigid-pair start, the gyroscopic friction and the
damped block Newton are compiled (numba, ``cache=True``: :func:`_contacts_nb`,
:func:`_rigid_pair_nb`, :func:`_gyro_friction_nb`, :func:`_ld_solve`), one code path that
:func:`arc_contacts`, :func:`rigid_pair_guess` and :func:`ball_load_distribution` call; the
Hertz constants are the compiled Hamrock-Brewe fast path of :mod:`thermobearing.hertz` that
the ball skidding residual also uses.

Newton's safeguards (session 11): the springs that keep the block system regular (on a
ball that touches nothing, on the ring when no ball touches) are Jacobian-only
Levenberg-Marquardt terms, relaxed after every full step, so the solution is the one of
the contact forces alone; each ball is damped on its own residual before a global line
search is tried (:func:`_ld_damped_balls`), its step stops where an open contact would
close, and it follows the arcs of its (up to two) most loaded contacts
(:func:`_ld_ball_trial`). A cold start that fails is repeated from the balls seated in the
outer groove by their centrifugal force, then with a softer ring spring. The solutions
agree with the former numpy implementation to 2e-5 N and 1e-10 m in no more iterations
(tests/unit/test_loads.py).

Units: SI throughout (m, N, rad/s, kg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from .errors import ConvergenceError, InputError, check_finite, check_positive
from .hertz import _hamrock_brewe_point_nb

__all__ = [
    "ArcSet",
    "BallLoadDistribution",
    "ContactField",
    "arc_contacts",
    "ball_arcs",
    "ball_load_distribution",
    "ring_weighted_angle",
]

INNER = 0
OUTER = 1
_EMPTY2 = np.empty((0, 0))


@dataclass(frozen=True)
class ArcSet:
    """Raceway arcs of a ball bearing in the axial plane of one ball, inner ring centred.

    Attributes
    ----------
    ring : (k,) int, 0 = inner ring arc, 1 = outer ring arc.
    centre_x : (k,) axial coordinate of the arc's curvature centre [m].
    centre_r : (k,) radial coordinate (from the bearing axis) of the curvature centre [m].
    free_distance : (k,) ``(f_k - 1/2) D``: centre distance at which contact starts [m].
    conformity : (k,) ``f_k = r_k / D`` [-].
    ball_diameter, pitch_radius : D and d_m / 2 [m].
    effective_modulus : E' of the ball-ring pair [Pa] (cached from the bearing).
    """

    ring: np.ndarray
    centre_x: np.ndarray
    centre_r: np.ndarray
    free_distance: np.ndarray
    conformity: np.ndarray
    ball_diameter: float
    pitch_radius: float
    effective_modulus: float = 0.0

    @property
    def n_arcs(self) -> int:
        return int(self.ring.size)


def ball_arcs(bearing) -> ArcSet:
    """Build the raceway arcs of a :class:`thermobearing.geometry.BallBearing`.

    Geometry
    --------
    - ``four_point``: two arcs per ring whose curvature centres are offset axially by
      ``+-s/2`` (``s = bearing.gothic_arch_offset``); each arc passes through the groove bottom
      (diameters ``inner_raceway_diameter``, ``outer_raceway_diameter`` of the geometry
      module), so the radial play of the centred ball is half the diametral clearance and the
      centred ball touches both arcs of a ring at the shim angle
      ``sin(theta_s) = (s/2) / ((f - 1/2) D)`` when the clearance is zero (primer section 4,
      checked in ``tests/unit/test_loads.py``).
    - ``deep_groove`` / ``angular_contact``: one arc per ring; the curvature centres are placed
      so that, with the inner ring shifted axially until contact, the line of centres makes
      the free contact angle ``bearing.free_contact_angle`` (Harris & Kotzalas 2007, vol. 1,
      eq. 2.29: ``cos(alpha_f) = 1 - P_d / (2 A)``, ``A = (f_i + f_o - 1) D``); the inner
      ring's zero axial displacement is that touching position.
    """
    D = float(bearing.ball_diameter)
    Rm = 0.5 * float(bearing.pitch_diameter)
    fi = float(bearing.inner_conformity)
    fo = float(bearing.outer_conformity)
    kind = bearing.kind
    if kind == "four_point":
        s = float(bearing.gothic_arch_offset)
        ri, ro = fi * D, fo * D
        if not (0.0 <= 0.5 * s < min((fi - 0.5), (fo - 0.5)) * D):
            raise InputError("bearing.gothic_arch_offset", s,
                             "0 <= s/2 < (f - 1/2) D for both rings")
        di = float(bearing.inner_raceway_diameter)
        do = float(bearing.outer_raceway_diameter)
        # arc through the groove bottom (x = 0): |(0, d/2) - (+-s/2, r_c)| = f D
        rci = 0.5 * di + np.sqrt(ri * ri - 0.25 * s * s)
        rco = 0.5 * do - np.sqrt(ro * ro - 0.25 * s * s)
        ring = np.array([INNER, INNER, OUTER, OUTER])
        cx = np.array([0.5 * s, -0.5 * s, -0.5 * s, 0.5 * s])
        cr = np.array([rci, rci, rco, rco])
        conf = np.array([fi, fi, fo, fo])
    elif kind in ("deep_groove", "angular_contact"):
        alpha_f = float(bearing.free_contact_angle)
        li, lo = (fi - 0.5) * D, (fo - 0.5) * D
        ring = np.array([INNER, OUTER])
        cx = np.array([li * np.sin(alpha_f), -lo * np.sin(alpha_f)])
        cr = np.array([Rm + li * np.cos(alpha_f), Rm - lo * np.cos(alpha_f)])
        conf = np.array([fi, fo])
    else:
        raise InputError("bearing.kind", kind, "deep_groove, angular_contact or four_point")
    return ArcSet(ring=ring, centre_x=cx, centre_r=cr, free_distance=(conf - 0.5) * D,
                  conformity=conf, ball_diameter=D, pitch_radius=Rm,
                  effective_modulus=float(bearing.effective_modulus))


@dataclass(frozen=True)
class ContactField:
    """Contact state of every (ball, arc) pair; arrays of shape (Z, k).

    Attributes
    ----------
    approach : elastic approach delta_k [m] (negative = open gap).
    load : normal load Q_k [N].
    normal_x, normal_r : unit vector from the arc centre to the ball centre; the contact
        point lies at ``b + (D/2) n`` and the force on the ball is ``-Q n``.
    distance : |b - c_k| [m].
    contact_angle : signed contact angle atan2(n_x, |n_r|) [rad].
    stiffness : K_k with Q = K delta^1.5 [N/m^1.5].
    """

    approach: np.ndarray
    load: np.ndarray
    normal_x: np.ndarray
    normal_r: np.ndarray
    distance: np.ndarray
    contact_angle: np.ndarray
    stiffness: np.ndarray


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


def arc_contacts(bearing, arcs: ArcSet, ball_x, ball_r, delta_a, delta_r, azimuth,
                 stiffness=None) -> ContactField:
    """Approach, normal load and direction of every (ball, arc) contact.

    The contact law of the module docstring (Jones 1959 in Harris & Kotzalas 2007 vol. 2,
    ch. 1-3; Hertz K by Hamrock-Brewe), through the compiled kernel of the load
    distribution.

    Parameters
    ----------
    bearing : BallBearing (for the Hertz stiffness).
    arcs : ArcSet from :func:`ball_arcs`.
    ball_x, ball_r : (Z,) ball centre axial / radial coordinate [m].
    delta_a, delta_r : inner ring axial and radial displacement [m] (radial along azimuth 0).
    azimuth : (Z,) ball azimuth psi_j [rad].
    stiffness : optional (Z, k) or (k,) fixed Hertz K [N/m^1.5]; computed at the current
        contact angle when None.
    """
    bx = np.ascontiguousarray(ball_x, dtype=float).ravel()
    br = np.ascontiguousarray(ball_r, dtype=float).ravel()
    nz, nk = bx.size, arcs.n_arcs
    K = _EMPTY2 if stiffness is None else np.ascontiguousarray(
        np.broadcast_to(np.asarray(stiffness, float), (nz, nk)))
    out = np.empty((7, nz, nk))
    _contacts_nb(bx, br, float(delta_a), float(delta_r),
                 np.ascontiguousarray(np.cos(np.asarray(azimuth, float))), _arc_table(arcs),
                 arcs.ball_diameter, 2.0 * arcs.pitch_radius, arcs.effective_modulus, K, out)
    return ContactField(*out)


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
        K[:, :] = cf[F_K]
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
        # Per-ball damping first (session 11): a ball at the edge of the load zone whose
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
            bx[:] = bx2
            br[:] = br2
            u[:] = u2
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

    refresh_stale_caches("loads", (_arc_stiffness_nb, _contacts_nb, _gyro_friction_nb,
                                   _ld_residual, _ld_newton_step, _ld_ball_trial,
                                   _ld_damped_balls, _ld_solve,
                                   _pair_state,
                                   _rigid_pair_nb), (hertz,))


_refresh_caches()


@dataclass(frozen=True)
class BallLoadDistribution:
    """Result of :func:`ball_load_distribution`.

    Attributes
    ----------
    azimuth : (Z,) [rad].  ball_x, ball_r : (Z,) ball centre position [m].
    delta_a, delta_r : inner ring displacement [m].
    contacts : ContactField (Z, k) at the solution; ``ring`` : (k,) 0 inner / 1 outer.
    inner_load, outer_load : (Z,) resultant normal load on the inner / outer ring arcs [N].
    inner_contact_angle, outer_contact_angle : (Z,) load-weighted contact angle of the
        loaded arcs of each ring [rad] (nominal where the ring is unloaded).
    centrifugal_force, gyroscopic_moment : (Z,) [N], [N m].
    converged, iterations, residual_norm : solver diagnostics (residual in N).
    """

    azimuth: np.ndarray
    ball_x: np.ndarray
    ball_r: np.ndarray
    delta_a: float
    delta_r: float
    contacts: ContactField
    ring: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_contact_angle: np.ndarray
    outer_contact_angle: np.ndarray
    centrifugal_force: np.ndarray
    gyroscopic_moment: np.ndarray
    converged: bool
    iterations: int
    residual_norm: float
    extra: dict = field(default_factory=dict)

    @property
    def n_contacts(self) -> np.ndarray:
        """(Z,) number of loaded arcs of each ball (2, 3 or 4 for a gothic arch)."""
        return np.sum(self.contacts.load > 0.0, axis=1)


def ring_weighted_angle(Q: np.ndarray, alpha: np.ndarray, sel: np.ndarray,
                        default: float) -> np.ndarray:
    """Load-weighted |contact angle| of the arcs in ``sel`` per ball; ``default`` if unloaded."""
    w = np.where(sel[None, :], Q, 0.0)
    tot = w.sum(axis=1)
    mean = np.sum(w * np.abs(alpha), axis=1) / np.where(tot > 0, tot, 1.0)
    return np.where(tot > 0, mean, default)


def ball_load_distribution(bearing, radial_load: float, axial_load: float,
                           inner_speed: float = 0.0, *, orbital_speed=None,
                           gyroscopic: str = "none", friction_coefficient: float = 0.1,
                           n_balls: int | None = None, guess: BallLoadDistribution | None = None,
                           tol: float = 1e-9, max_iter: int = 100) -> BallLoadDistribution:
    """Quasi-static load distribution of a ball bearing with centrifugal and gyroscopic effects.

    Newton on the ball positions and the ring displacement (block elimination, backtracking
    line search), compiled (numba; :func:`_ld_solve`); Jones 1959 / Harris & Kotzalas 2007
    vol. 2 ch. 1-3 with every raceway arc an independent contact (module docstring).

    Parameters
    ----------
    bearing : BallBearing.
    radial_load : F_r on the inner ring along azimuth 0 [N] (>= 0).
    axial_load : F_a on the inner ring along +x [N] (either sign for a four-point bearing).
    inner_speed : inner ring speed [rad/s]; sets the ball orbital speed for the centrifugal
        force ``F_c = m omega_m^2 r_b`` (Harris & Kotzalas 2007 vol. 2 eq. 3.4, actual orbit
        radius) and the gyroscopic moment.
    orbital_speed : (Z,) or scalar ball orbital speed [rad/s]; default the epicyclic value at the
        nominal contact angle, ``omega_i (1 - gamma cos alpha_0) / 2``.
    gyroscopic : ``"none"`` or ``"shared"``: the gyroscopic moment ``J omega_R omega_m sin(beta)``
        (primer section 3.3, with outer-race-control spin ``beta``) is carried by transverse
        friction at the loaded contacts in proportion to their normal load (MESYS option
        "shared by both contacts", primer section 2.3), capped by ``friction_coefficient * Q``.
    n_balls : override of Z (benchmarks), default ``bearing.n_balls``.
    guess : previous result for a warm start.
    tol : convergence tolerance on the force residual relative to the load scale.

    Returns
    -------
    BallLoadDistribution

    Raises
    ------
    ConvergenceError
        with the residual norm and the last iterate when Newton fails.
    """
    check_positive("radial_load", radial_load, allow_zero=True)
    check_finite("axial_load", axial_load)
    check_finite("inner_speed", inner_speed)
    if gyroscopic not in ("none", "shared"):
        raise InputError("gyroscopic", gyroscopic, "'none' or 'shared'")
    arcs = ball_arcs(bearing)
    tab = _arc_table(arcs)
    Z = int(n_balls or bearing.n_balls)
    psi = 2.0 * np.pi * np.arange(Z) / Z
    cpsi = np.cos(psi)
    D, Rm = arcs.ball_diameter, arcs.pitch_radius
    m = float(bearing.ball_mass)
    J = float(bearing.ball_inertia)
    alpha0 = float(bearing.contact_angle)
    gam0 = D * np.cos(alpha0) / (2.0 * Rm)
    wm = (np.full(Z, 0.5 * inner_speed * (1.0 - gam0)) if orbital_speed is None
          else np.broadcast_to(np.asarray(orbital_speed, float), (Z,)).copy())
    inner = arcs.ring == INNER
    # load scale for the residual; Jacobian-only (Levenberg-Marquardt) springs on the balls
    # (holds a ball that touches nothing) and on the ring (moves it towards contact when no
    # ball touches), relaxed by the solver after full steps: the solution does not depend on
    # them. Session 11: the ball spring was a force in the residual (centred on the pitch
    # circle) that pulled balls resting in a groove up its flank with more than their
    # centrifugal force and stalled Newton (SKF6304, 21.9 kN + 6.3 kN at 10 r/min), and the
    # ring spring stayed at its start value, so Newton converged linearly.
    F_scale = max(abs(axial_load) / Z, radial_load / Z, m * np.max(wm) ** 2 * Rm, 1.0)
    k_reg = 1.0e-5 * F_scale / D
    step_max = 0.02 * D
    k_ring = max(abs(axial_load), abs(radial_load), F_scale) / (0.01 * D)
    if guess is not None and guess.ball_x.size == Z:
        bx, br = guess.ball_x.copy(), guess.ball_r.copy()
        u = np.array([guess.delta_a, guess.delta_r])
    else:
        bx, br, u = rigid_pair_guess(bearing, arcs, axial_load, radial_load, psi, m * wm**2)
    c = np.array([D, 2.0 * Rm, arcs.effective_modulus, m, J, gam0, alpha0,
                  float(inner_speed), float(friction_coefficient), k_reg, float(axial_load),
                  float(radial_load)])
    cf = np.empty((7, Z, arcs.n_arcs))
    Fc, Mg = np.empty(Z), np.empty(Z)
    tol_abs = tol * F_scale * np.sqrt(2 * Z + 2)
    wmc = np.ascontiguousarray(wm, dtype=float)
    norm, it, ok = _ld_solve(bx, br, u, cpsi, tab, c, wmc, gyroscopic == "shared", tol_abs,
                             step_max, k_ring, int(max_iter), cf, Fc, Mg)
    if not ok and np.isfinite(norm) and guess is None and np.any(wm != 0.0):
        # second start (session 11): every ball seated in the outer groove by its
        # centrifugal force, the ring at the rigid-pair displacement. The rigid-pair start
        # places the balls without the centrifugal force; where it is comparable with the
        # load (a four-point bearing under a few newtons of axial load at 16-100 r/min:
        # 0.015-0.55 N per ball) it must move them into a third arc along the direction that
        # the diagonal contact pair leaves soft to first order, and Newton crawls there
        # (QJ1044, 2.15 N axial at 35.5 r/min: stall at 0.30 N); from the seat the ring's
        # inner arcs close on the balls and Newton converges in 7-11 iterations.
        bx_s, br_s, _ = rigid_pair_guess(bearing, arcs, 0.0, 0.0, psi, m * wm**2)
        _, _, u_s = rigid_pair_guess(bearing, arcs, axial_load, radial_load, psi, m * wm**2)
        norm_s, it2, ok_s = _ld_solve(bx_s, br_s, u_s, cpsi, tab, c, wmc,
                                      gyroscopic == "shared", tol_abs, step_max, k_ring,
                                      int(max_iter), cf, Fc, Mg)
        it += it2
        if ok_s or norm_s < norm:
            bx, br, u, norm, ok = bx_s, br_s, u_s, norm_s, ok_s
    if not ok and np.isfinite(norm):
        # the ring spring k_ring, sized by the load, can be far stiffer than the bearing's
        # own stiffness (a four-point bearing under a few newtons of axial load; a deep-groove
        # bearing under a light radial load, whose axial stiffness is only the geometric Q/L
        # of the loaded balls), and the line search then never relaxes it: retry from the
        # last iterate with the spring 1e-6 as stiff (the solution does not depend on it)
        norm, it2, ok = _ld_solve(bx, br, u, cpsi, tab, c, wmc, gyroscopic == "shared",
                                  tol_abs, step_max, 1e-6 * k_ring, int(max_iter), cf, Fc, Mg)
        it += it2
    if not ok:
        raise ConvergenceError("ball_load_distribution", norm,
                               f"no convergence in {max_iter} Newton iterations",
                               {"delta_a": u[0], "delta_r": u[1], "radial_load": radial_load,
                                "axial_load": axial_load, "inner_speed": inner_speed})
    if not np.isfinite(norm):
        raise ConvergenceError("ball_load_distribution", norm, "non-finite residual",
                               {"axial_load": axial_load, "radial_load": radial_load})
    cf = ContactField(*cf)
    Q = cf.load
    ai = ring_weighted_angle(Q, cf.contact_angle, inner, alpha0)
    ao = ring_weighted_angle(Q, cf.contact_angle, ~inner, alpha0)
    return BallLoadDistribution(
        azimuth=psi, ball_x=bx, ball_r=br, delta_a=float(u[0]), delta_r=float(u[1]),
        contacts=cf, ring=arcs.ring, inner_load=np.sum(np.where(inner, Q, 0.0), axis=1),
        outer_load=np.sum(np.where(~inner, Q, 0.0), axis=1), inner_contact_angle=ai,
        outer_contact_angle=ao, centrifugal_force=Fc, gyroscopic_moment=Mg, converged=True,
        iterations=it, residual_norm=norm)


def rigid_pair_guess(bearing, arcs: ArcSet, axial_load: float, radial_load: float,
                     psi: np.ndarray, centrifugal_per_radius) -> tuple:
    """Starting point: ring displacement of the rigid-ball (Stribeck/Jones) model.

    Each ball is the link of every inner/outer arc pair; with the centre distance
    ``|c_i - c_o|`` the pair's total approach is ``zeta = |c_i - c_o| - (f_i + f_o - 1) D`` and
    its load ``K_eff zeta^1.5`` with ``K_eff = (K_i^(-2/3) + K_o^(-2/3))^(-3/2)`` (Harris &
    Kotzalas 2007 vol. 1 eq. 3.32, series contacts; K at the nominal contact angle). The ring
    displacement balancing the external load is found by damped Newton on these two
    unknowns (compiled, :func:`_rigid_pair_nb`); balls are then placed on the line of
    centres of their most loaded pair, split by the Hertz approaches, or seated in the outer
    groove by the centrifugal force when no pair is loaded.

    ``centrifugal_per_radius`` : m omega_m^2 [N/m], scalar or (Z,). Returns (ball_x [m],
    ball_r [m], (delta_a, delta_r) [m]).
    """
    Z = np.asarray(psi).size
    fc = np.ascontiguousarray(np.broadcast_to(np.asarray(centrifugal_per_radius, float),
                                              (Z,))) * arcs.pitch_radius
    bx, br, u = np.empty(Z), np.empty(Z), np.empty(2)
    _rigid_pair_nb(np.ascontiguousarray(np.cos(psi), dtype=float), _arc_table(arcs),
                   arcs.ball_diameter, 2.0 * arcs.pitch_radius, arcs.effective_modulus,
                   float(bearing.contact_angle),
                   np.array([axial_load, radial_load], float), fc, bx, br, u)
    return bx, br, u
