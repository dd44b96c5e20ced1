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

Units: SI throughout (m, N, rad/s, kg).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .errors import ConvergenceError, InputError, check_finite, check_positive
from .hertz import _hamrock_brewe_kke, _reduced_unchecked, _stiffness_from

__all__ = [
    "ArcSet",
    "BallLoadDistribution",
    "ContactField",
    "arc_contacts",
    "ball_arcs",
    "ball_load_distribution",
]

INNER = 0
OUTER = 1


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


def _stiffness(bearing, arcs: ArcSet, contact_angle: np.ndarray) -> np.ndarray:
    """Hertz K of every arc at its contact angle (geometry.curvature + hertz, owner B).

    The Hamrock-Brewe closed-form ellipticity is used (within about 1 % of the exact
    elliptic-integral solution, Hamrock 2004 ch. 17) because this runs inside every Newton
    residual; the exact form costs a root solve per contact.
    """
    return _arc_hertz(arcs, float(bearing.pitch_diameter), contact_angle)[5]


def _arc_hertz(arcs: ArcSet, pitch_diameter: float, contact_angle: np.ndarray) -> tuple:
    """Hertz constants of every arc contact at ``contact_angle`` (no input checks).

    R_x = D (d_m -+ D cos(alpha)) / (2 d_m) (:meth:`geometry.BallBearing.curvature`, upper
    sign inner ring), R_y = f D / (2 f - 1), and the Hamrock-Brewe closed form through the
    unchecked cores of :mod:`thermobearing.hertz` (the bearing's radii and E' were validated
    when it was built). Returns (R_x, R_y, R, k, E, K) with Q = K delta^1.5; the ball
    skidding residual uses the same function.
    """
    D = arcs.ball_diameter
    sign = np.where(arcs.ring == INNER, 1.0, -1.0)
    rx = 0.5 * D * (1.0 - sign * (D * np.cos(contact_angle) / pitch_diameter))
    ry = arcs.conformity * D / (2.0 * arcs.conformity - 1.0)
    r, ratio = _reduced_unchecked(rx, ry)
    k, big_k, big_e = _hamrock_brewe_kke(ratio)
    return rx, ry, r, k, big_e, _stiffness_from(r, k, big_k, big_e, arcs.effective_modulus)


def arc_contacts(bearing, arcs: ArcSet, ball_x, ball_r, delta_a, delta_r, azimuth,
                 stiffness=None) -> ContactField:
    """Approach, normal load and direction of every (ball, arc) contact.

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
    bx = np.asarray(ball_x, float)[:, None]
    br = np.asarray(ball_r, float)[:, None]
    inner = (arcs.ring == INNER)[None, :]
    cx = arcs.centre_x[None, :] + np.where(inner, delta_a, 0.0)
    cr = arcs.centre_r[None, :] + np.where(inner, delta_r * np.cos(azimuth)[:, None], 0.0)
    dx, dr = bx - cx, br - cr
    L = np.hypot(dx, dr)
    nx, nr = dx / L, dr / L
    approach = L - arcs.free_distance[None, :]
    alpha = np.arctan2(nx, np.abs(nr))
    K = _stiffness(bearing, arcs, alpha) if stiffness is None else np.broadcast_to(
        stiffness, alpha.shape)
    Q = K * np.maximum(approach, 0.0) ** 1.5
    return ContactField(approach, Q, nx, nr, L, alpha, np.array(K, float))


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
    Z = int(n_balls or bearing.n_balls)
    psi = 2.0 * np.pi * np.arange(Z) / Z
    D, Rm = arcs.ball_diameter, arcs.pitch_radius
    m = float(bearing.ball_mass)
    J = float(bearing.ball_inertia)
    alpha0 = float(bearing.contact_angle)
    gam0 = D * np.cos(alpha0) / (2.0 * Rm)
    wm = (np.full(Z, 0.5 * inner_speed * (1.0 - gam0)) if orbital_speed is None
          else np.broadcast_to(np.asarray(orbital_speed, float), (Z,)).copy())
    inner = arcs.ring == INNER
    # load scale for the residual and a weak centring spring that holds balls which touch
    # nothing (zero speed, no load); its force at the solution is reported in ``extra``.
    F_scale = max(abs(axial_load) / Z, radial_load / Z, m * np.max(wm) ** 2 * Rm, 1.0)
    k_reg = 1.0e-5 * F_scale / D
    step_max = 0.02 * D
    # Jacobian-only ring regularisation: moves the ring towards contact when no ball touches
    # (the converged solution is not changed by it)
    k_ring = max(np.max(np.abs([axial_load, radial_load])), F_scale) / (0.01 * D)

    if guess is not None and guess.ball_x.size == Z:
        bx, br = guess.ball_x.copy(), guess.ball_r.copy()
        u = np.array([guess.delta_a, guess.delta_r])
    else:
        bx, br, u = rigid_pair_guess(bearing, arcs, axial_load, radial_load, psi, m * wm**2)
    x_rest = np.zeros(Z)
    r_rest = np.full(Z, Rm)
    F_app = np.array([axial_load, radial_load])
    cpsi = np.cos(psi)
    K_fixed = None

    def residual(bx, br, u, K):
        cf = arc_contacts(bearing, arcs, bx, br, u[0], u[1], psi, stiffness=K)
        Q, nx, nr = cf.load, cf.normal_x, cf.normal_r
        Fc = m * wm**2 * br
        Rx = -np.sum(Q * nx, axis=1) - k_reg * (bx - x_rest)
        Rr = -np.sum(Q * nr, axis=1) + Fc - k_reg * (br - r_rest)
        Mg = np.zeros(Z)
        if gyroscopic == "shared":
            Mg, fx, fr = _gyro_friction(cf, arcs, D, J, wm, inner_speed, gam0, alpha0,
                                        friction_coefficient)
            Rx += fx.sum(axis=1)
            Rr += fr.sum(axis=1)
            ring_fx = -np.sum(np.where(inner, fx, 0.0), axis=1)
            ring_fr = -np.sum(np.where(inner, fr, 0.0), axis=1)
        else:
            ring_fx = ring_fr = np.zeros(Z)
        Qi = np.where(inner[None, :], Q, 0.0)
        Ra = F_app[0] + np.sum(Qi * nx) + ring_fx.sum()
        Rrad = F_app[1] + np.sum((np.sum(Qi * nr, axis=1) + ring_fr) * cpsi)
        return cf, Rx, Rr, np.array([Ra, Rrad]), Fc, Mg

    it = 0
    norm = np.inf
    for _ in range(max_iter):
        it += 1
        cf, Rx, Rr, Rg, Fc, Mg = residual(bx, br, u, K_fixed)
        K_fixed = cf.stiffness
        norm = float(np.sqrt(np.sum(Rx**2 + Rr**2) + np.sum(Rg**2)))
        if norm <= tol * F_scale * np.sqrt(2 * Z + 2):
            break
        dbx, dbr, du = _newton_step(cf, inner, cpsi, Rx, Rr, Rg, m * wm**2, k_reg, k_ring)
        scale = min(1.0, step_max / max(np.max(np.abs(dbx)), np.max(np.abs(dbr)),
                                        np.max(np.abs(du)), 1e-300))
        # backtracking on the residual norm
        lam = scale
        for _ in range(30):
            _, rx2, rr2, rg2, _, _ = residual(bx + lam * dbx, br + lam * dbr, u + lam * du,
                                              K_fixed)
            n2 = float(np.sqrt(np.sum(rx2**2 + rr2**2) + np.sum(rg2**2)))
            if n2 < (1.0 - 1e-4 * lam) * norm or (n2 <= norm and lam == scale) or lam < 1e-6:
                break
            lam *= 0.5
        bx, br, u = bx + lam * dbx, br + lam * dbr, u + lam * du
        K_fixed = None
    else:
        raise ConvergenceError("ball_load_distribution", norm,
                               f"no convergence in {max_iter} Newton iterations",
                               {"delta_a": u[0], "delta_r": u[1], "radial_load": radial_load,
                                "axial_load": axial_load, "inner_speed": inner_speed})
    if not np.isfinite(norm):
        raise ConvergenceError("ball_load_distribution", norm, "non-finite residual",
                               {"axial_load": axial_load, "radial_load": radial_load})
    Q = cf.load
    ai = ring_weighted_angle(Q, cf.contact_angle, inner, alpha0)
    ao = ring_weighted_angle(Q, cf.contact_angle, ~inner, alpha0)
    reg = k_reg * np.hypot(bx - x_rest, br - r_rest)
    return BallLoadDistribution(
        azimuth=psi, ball_x=bx, ball_r=br, delta_a=float(u[0]), delta_r=float(u[1]),
        contacts=cf, ring=arcs.ring, inner_load=np.sum(np.where(inner, Q, 0.0), axis=1),
        outer_load=np.sum(np.where(~inner, Q, 0.0), axis=1), inner_contact_angle=ai,
        outer_contact_angle=ao, centrifugal_force=Fc, gyroscopic_moment=Mg, converged=True,
        iterations=it, residual_norm=norm, extra={"max_centring_force": float(np.max(reg))})


def contact_hessian(cf: ContactField) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """d(Q n)/d(b) of every contact as the symmetric 2x2 blocks (hxx, hxr, hrr), (Z, k).

    ``Q n`` with ``n = (b - c)/L``: ``H = Q' n n^T + (Q/L)(I - n n^T)``, ``Q' = 1.5 K delta^0.5``.
    """
    dlt = np.maximum(cf.approach, 0.0)
    Qp = 1.5 * cf.stiffness * np.sqrt(dlt)
    QL = cf.load / cf.distance
    nx, nr = cf.normal_x, cf.normal_r
    return (Qp * nx * nx + QL * (1 - nx * nx), (Qp - QL) * nx * nr,
            Qp * nr * nr + QL * (1 - nr * nr))


def _newton_step(cf, inner, cpsi, Rx, Rr, Rg, dFc_dr, k_reg, k_ring):
    """Block-eliminated Newton step for (ball x, ball r) x Z and ring (delta_a, delta_r)."""
    hxx, hxr, hrr = contact_hessian(cf)
    # ball block A = dR_ball/db = -sum_k H_k + diag(0, m w^2) - k_reg I
    A = np.empty((cpsi.size, 2, 2))
    A[:, 0, 0] = -hxx.sum(1) - k_reg
    A[:, 0, 1] = A[:, 1, 0] = -hxr.sum(1)
    A[:, 1, 1] = -hrr.sum(1) - k_reg  # d(F_c)/dr = m w^2 omitted (quasi-Newton)
    Hi = np.zeros((cpsi.size, 2, 2))
    Hi[:, 0, 0] = np.where(inner, hxx, 0).sum(1)
    Hi[:, 0, 1] = Hi[:, 1, 0] = np.where(inner, hxr, 0).sum(1)
    Hi[:, 1, 1] = np.where(inner, hrr, 0).sum(1)
    P = np.zeros((cpsi.size, 2, 2))
    P[:, 0, 0] = 1.0
    P[:, 1, 1] = cpsi
    B = Hi @ P                        # dR_ball/du
    C = P @ Hi                        # dR_ring/db_j
    Dm = -np.sum(P @ Hi @ P, axis=0)  # dR_ring/du
    Rb = np.stack([Rx, Rr], axis=1)[:, :, None]
    Ainv = np.linalg.inv(A)
    S = Dm - np.sum(C @ Ainv @ B, axis=0) - k_ring * np.eye(2)
    rhs = -Rg + np.sum(C @ Ainv @ Rb, axis=0)[:, 0]
    du = np.linalg.solve(S, rhs)
    db = Ainv @ (-Rb - B @ du[None, :, None])
    return db[:, 0, 0], db[:, 1, 0], du


def _gyro_friction(cf, arcs, D, J, wm, w_inner, gam0, alpha0, mu):
    """Transverse friction at the loaded contacts that carries the gyroscopic moment.

    Outer-race-control attitude ``tan(beta) = sin(alpha_o)/(cos(alpha_o) + gamma)`` and spin
    (K2) of the primer (section 2.1, 2.3), ``M_g = J omega_R omega_m sin(beta)`` (section 3.3).
    The moment about the tangential axis is shared in proportion to normal load; the force on
    the ball at contact k is along the in-plane tangent ``t = (-n_r, n_x)`` with
    ``(D/2) sum_k F_k = M_g`` and ``|F_k| <= mu Q_k``.
    """
    Q = cf.load
    ao = np.abs(cf.contact_angle[:, arcs.ring == OUTER]).max(axis=1)
    beta = np.arctan2(np.sin(ao), np.cos(ao) + gam0)
    # spin magnitude from (K2) with alpha_i = alpha_o = alpha_0 (first-order)
    denom = gam0 * np.cos(beta) * (
        (np.cos(ao) + np.tan(beta) * np.sin(ao)) / (1 + gam0 * np.cos(ao))
        + (np.cos(alpha0) + np.tan(beta) * np.sin(alpha0)) / (1 - gam0 * np.cos(alpha0)))
    wR = np.abs(w_inner) / np.maximum(denom, 1e-12)
    Mg = J * wR * np.abs(wm) * np.sin(beta)
    Qtot = Q.sum(axis=1)
    F = 2.0 * Mg[:, None] / D * Q / np.where(Qtot > 0, Qtot, 1.0)[:, None]
    F = np.minimum(F, mu * Q)
    # moment about y of force (fx, fr) at p = (D/2) n: (D/2)(n_r f_x - n_x f_r) > 0 for t=(n_r,-n_x)
    fx, fr = F * cf.normal_r, -F * cf.normal_x
    return Mg, fx, fr


def rigid_pair_guess(bearing, arcs: ArcSet, axial_load: float, radial_load: float,
                     psi: np.ndarray, centrifugal_per_radius) -> tuple:
    """Starting point: ring displacement of the rigid-ball (Stribeck/Jones) model.

    Each ball is the link of every inner/outer arc pair; with the centre distance
    ``|c_i - c_o|`` the pair's total approach is ``zeta = |c_i - c_o| - (f_i + f_o - 1) D`` and
    its load ``K_eff zeta^1.5`` with ``K_eff = (K_i^(-2/3) + K_o^(-2/3))^(-3/2)`` (Harris &
    Kotzalas 2007 vol. 1 eq. 3.32, series contacts). The ring displacement balancing the
    external load is found by damped Newton on these two unknowns; balls are then placed on
    the line of centres of their most loaded pair, split by the Hertz approaches, or seated in
    the outer groove by the centrifugal force when no pair is loaded.
    """
    Z = psi.size
    D = arcs.ball_diameter
    ii = np.flatnonzero(arcs.ring == INNER)
    oo = np.flatnonzero(arcs.ring == OUTER)
    pi_, po_ = np.meshgrid(ii, oo, indexing="ij")
    pi_, po_ = pi_.ravel(), po_.ravel()
    Ki = _stiffness(bearing, arcs, np.full((1, arcs.n_arcs), float(bearing.contact_angle)))[0]
    Keff = (Ki[pi_] ** (-2 / 3) + Ki[po_] ** (-2 / 3)) ** (-1.5)
    A = (arcs.conformity[pi_] + arcs.conformity[po_] - 1.0) * D
    cpsi = np.cos(psi)[:, None]
    F = np.array([axial_load, radial_load], float)

    def pair_state(u):
        cix = arcs.centre_x[pi_][None, :] + u[0]
        cir = arcs.centre_r[pi_][None, :] + u[1] * cpsi
        dx = cix - arcs.centre_x[po_][None, :]
        dr = cir - arcs.centre_r[po_][None, :]
        dist = np.hypot(dx, dr)
        zeta = dist - A[None, :]
        Q = Keff[None, :] * np.maximum(zeta, 0.0) ** 1.5
        ex, er = dx / dist, dr / dist     # unit vector from c_o to c_i
        R = F - np.array([np.sum(Q * ex), np.sum(Q * er * cpsi)])
        dQ = 1.5 * Keff[None, :] * np.sqrt(np.maximum(zeta, 0.0))
        J = -np.array([[np.sum(dQ * ex * ex), np.sum(dQ * ex * er * cpsi)],
                       [np.sum(dQ * ex * er * cpsi), np.sum(dQ * er * er * cpsi**2)]])
        return R, J, Q, zeta, ex, er

    u = np.zeros(2)
    scale = max(np.max(np.abs(F)), 1.0)
    k_reg = scale / (0.01 * D)
    for _ in range(200):
        R, J, Q, zeta, ex, er = pair_state(u)
        n0 = np.linalg.norm(R)
        if n0 <= 1e-10 * scale:
            break
        du = np.linalg.solve(J - k_reg * np.eye(2), -R)
        lam = min(1.0, 0.01 * D / max(np.max(np.abs(du)), 1e-300))
        while lam > 1e-8 and np.linalg.norm(pair_state(u + lam * du)[0]) > n0:
            lam *= 0.5
        u = u + lam * du
        k_reg *= 0.3
    R, J, Q, zeta, ex, er = pair_state(u)
    # ball positions
    best = np.argmax(Q, axis=1)
    rows = np.arange(Z)
    Qb = Q[rows, best]
    ko = po_[best]
    cox = arcs.centre_x[ko]
    cor = arcs.centre_r[ko]
    Lo = arcs.free_distance[ko] + (Qb / Ki[ko]) ** (2 / 3)
    bx = cox + Lo * ex[rows, best]
    br = cor + Lo * er[rows, best]
    # unloaded balls: seated radially in the outer groove by the centrifugal force
    fc = np.broadcast_to(np.asarray(centrifugal_per_radius, float), (Z,)) * arcs.pitch_radius
    free = Qb <= 0.0
    if np.any(free):
        no = oo.size
        Ko = Ki[oo[0]]
        # radial seat: both outer arcs (gothic) or the single outer arc share F_c
        if no == 2:
            half = 0.5 * abs(arcs.centre_x[oo[0]] - arcs.centre_x[oo[1]])
            Lo_f = arcs.free_distance[oo[0]] + (0.5 * fc / Ko) ** (2 / 3)
            r_seat = arcs.centre_r[oo[0]] + np.sqrt(np.maximum(Lo_f**2 - half**2, 0.0))
            x_seat = np.zeros(Z)
        else:
            Lo_f = arcs.free_distance[oo[0]] + (fc / Ko) ** (2 / 3)
            x_seat = np.full(Z, arcs.centre_x[oo[0]])
            r_seat = arcs.centre_r[oo[0]] + Lo_f
        seat = free & (fc > 0)
        bx = np.where(seat, x_seat, np.where(free, 0.0, bx))
        br = np.where(seat, r_seat, np.where(free, arcs.pitch_radius, br))
    return bx, br, u
