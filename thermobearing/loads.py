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

Newton's safeguards: the springs that keep the block system regular (on a
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

Modules: :mod:`thermobearing.loads_arcs` (raceway arcs, contact-field type),
:mod:`thermobearing.loads_kernels` (the compiled kernels); this module keeps the Python
driver, the result type and the public functions, and re-exports the names of both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from .errors import ConvergenceError, InputError, check_finite, check_positive

# split modules (names re-exported: callers import them from here)
from .loads_arcs import INNER, OUTER, ArcSet, ContactField, ball_arcs  # noqa: F401
from .loads_kernels import (  # noqa: F401
    F_ALPHA,
    F_APPROACH,
    F_DIST,
    F_K,
    F_LOAD,
    F_NR,
    F_NX,
    N_ARC_ROWS,
    T_CONF,
    T_CR,
    T_CX,
    T_FREE,
    T_INNER,
    T_RY,
    T_SIGN,
    _arc_stiffness_nb,
    _arc_table,
    _contacts_nb,
    _gyro_friction_nb,
    _ld_ball_trial,
    _ld_damped_balls,
    _ld_newton_step,
    _ld_residual,
    _ld_solve,
    _pair_state,
    _rigid_pair_nb,
)

__all__ = [
    "ArcSet",
    "BallLoadDistribution",
    "ContactField",
    "ROUND_OFF_LOAD",
    "arc_contacts",
    "ball_arcs",
    "ball_load_distribution",
    "ring_weighted_angle",
]

_EMPTY2 = np.empty((0, 0))


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


#: arc loads below this fraction of the largest are round-off for the contact angles
#: (:func:`ring_weighted_angle`, and the compiled summary of the skidding result
#: ``skidding.ball_result._summary``): far below the solver's force tolerance (1e-9 of the
#: load scale), a load the equilibrium cannot tell from zero
ROUND_OFF_LOAD = 1e-12


def ring_weighted_angle(Q: np.ndarray, alpha: np.ndarray, sel: np.ndarray,
                        default: float) -> np.ndarray:
    """Load-weighted |contact angle| of the arcs in ``sel`` per ball [rad]: sum Q |alpha| /
    sum Q over those arcs; ``default`` [rad] if the ball carries no load on them. Q (Z, k)
    [N], alpha (Z, k) [rad], sel (k,) bool. An arc loaded by round-off (Q at most
    :data:`ROUND_OFF_LOAD` of the largest load in ``Q``: an unloaded ball resting at
    1.5e-17 N beside 1.4e4 N) counts as unloaded: its geometric angle replaced ``default``
    by round-off (SKF6304 at 15.2 kN / 4.2 kN: the unloaded balls' outer angle 0 rad, the
    same bearing scaled by 1.22 in size and 1.49 in load 0.178 rad)."""
    Q = np.asarray(Q, dtype=float)
    Q = np.where(Q > ROUND_OFF_LOAD * float(np.max(Q, initial=0.0)), Q, 0.0)
    w = np.where(sel[None, :], Q, 0.0)
    tot = w.sum(axis=1)
    mean = np.sum(w * np.abs(alpha), axis=1) / np.where(tot > 0, tot, 1.0)
    return np.where(tot > 0, mean, default)


def ball_load_distribution(bearing, radial_load: float, axial_load: float,
                           inner_speed: float = 0.0, *, orbital_speed=None,
                           gyroscopic: str = "none", friction_coefficient: float = 0.1,
                           n_balls: int | None = None, guess: BallLoadDistribution | None = None,
                           tol: float = 1e-9, max_iter: int = 100,
                           continuation: bool = True) -> BallLoadDistribution:
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
    continuation : when Newton stalls from its starts (a sub-newton load on a bearing with
        clearance), follow the solution down from a multiple of the load
        (:func:`_load_continuation`); its own solves pass False.

    Returns
    -------
    BallLoadDistribution

    Raises
    ------
    ConvergenceError
        with the residual norm and the last iterate when Newton fails.
    """
    from .geometry_ball import BallBearing

    if not isinstance(bearing, BallBearing):  # was an AttributeError (no ball_diameter)
        raise InputError("bearing", type(bearing).__name__, "a BallBearing (roller bearings: "
                         "thermobearing.loads_roller)")
    for name, value in (("radial_load", radial_load), ("axial_load", axial_load),
                        ("inner_speed", inner_speed)):
        if np.ndim(value) != 0:  # an array was "truth value of an array is ambiguous"
            raise InputError(name, value, "one number (one operating point per call)")
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
    # them. The ball spring used to be a force in the residual (centred on the pitch
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
    elif radial_load == 0.0 and axial_load == 0.0:
        # no external load: the known solution, rings centred and every ball seated in the
        # outer groove by its centrifugal force alone (:func:`centred_seat`). The rigid-pair
        # start put the deep-groove ring at its axial touching position (the zero of
        # delta_a), where round-off loads every ball pinched between both arcs with ~1e-20 N:
        # the catalogue 6206 at 0.5-5 r/min then stopped at a residual of about the
        # centrifugal force (5e-8 N at 0.5 r/min)
        bx, br, u = centred_seat(arcs, Z, m * wm**2)
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
        # second start: every ball seated in the outer groove by its
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
    if not ok and np.isfinite(norm) and guess is None and continuation:
        # a sub-newton load on a bearing with clearance (SKF6304 under 0.06 N radial at
        # 2254 r/min: residual 3e-3 N): the load's direction is a near-mechanism held only
        # by the loaded balls' geometric stiffness Q/L, and Newton stalls from any start;
        # the same bearing under a larger multiple of the load converges, and its solution
        # is a start from which Newton follows the load down
        cont = _load_continuation(bearing, radial_load, axial_load, inner_speed,
                                  orbital_speed=orbital_speed, gyroscopic=gyroscopic,
                                  friction_coefficient=friction_coefficient,
                                  n_balls=n_balls, tol=tol, max_iter=max_iter)
        if cont is not None:
            return replace(cont, iterations=cont.iterations + it)
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
    # an arc loaded by round-off is unloaded for the angles (ring_weighted_angle)
    ai = ring_weighted_angle(Q, cf.contact_angle, inner, alpha0)
    ao = ring_weighted_angle(Q, cf.contact_angle, ~inner, alpha0)
    return BallLoadDistribution(
        azimuth=psi, ball_x=bx, ball_r=br, delta_a=float(u[0]), delta_r=float(u[1]),
        contacts=cf, ring=arcs.ring, inner_load=np.sum(np.where(inner, Q, 0.0), axis=1),
        outer_load=np.sum(np.where(~inner, Q, 0.0), axis=1), inner_contact_angle=ai,
        outer_contact_angle=ao, centrifugal_force=Fc, gyroscopic_moment=Mg, converged=True,
        iterations=it, residual_norm=norm)


#: load multiples tried as the start of the load continuation, and the largest ratio of
#: two successive loads on the way down (halved in log after a failed step, at most
#: ``_CONTINUATION_MAX_SOLVES`` solves in all)
_CONTINUATION_STARTS = (10.0, 1.0e2, 1.0e3, 1.0e4, 1.0e5, 1.0e6)
_CONTINUATION_RATIO = 0.3
_CONTINUATION_MAX_SOLVES = 60


def _load_continuation(bearing, radial_load: float, axial_load: float, inner_speed: float,
                       **options) -> BallLoadDistribution | None:
    """Continuation in the load magnitude for a state Newton cannot reach from its starts:
    the loads times the first of ``_CONTINUATION_STARTS`` that converges, then down to
    ``(radial_load, axial_load)`` in steps of at most ``_CONTINUATION_RATIO``, each solve
    warm-started from the one before (a failed step is retried at the square root of its
    ratio). None when no multiple converges or the path stalls; the caller then raises with
    its own residual. The converged result satisfies the same tolerance as a direct solve."""
    peak = max(float(radial_load), abs(float(axial_load)))
    if peak == 0.0:
        return None
    solves = 0
    guess = None
    scale = 1.0
    for start in _CONTINUATION_STARTS:
        solves += 1
        try:
            guess = ball_load_distribution(bearing, radial_load * start, axial_load * start,
                                           inner_speed, continuation=False, **options)
        except ConvergenceError:
            continue
        scale = start
        break
    if guess is None:
        return None
    ratio = _CONTINUATION_RATIO
    while scale > 1.0 and solves < _CONTINUATION_MAX_SOLVES:
        nxt = max(scale * ratio, 1.0)
        solves += 1
        try:
            guess = ball_load_distribution(bearing, radial_load * nxt, axial_load * nxt,
                                           inner_speed, guess=guess, continuation=False,
                                           **options)
        except ConvergenceError:
            ratio = math.sqrt(ratio)
            continue
        scale = nxt
    return guess if scale == 1.0 else None


def centred_seat(arcs: ArcSet, n_balls: int, centrifugal_per_radius) -> tuple:
    """The load distribution without external load: the inner ring centred on the outer
    ring (its arc centres moved axially onto the mean axial position of the outer ones, no
    radial displacement) and every ball in the groove bottom of the outer ring, pressed
    into it by its centrifugal force ``F_c = m omega_m^2 r_b`` alone (Harris & Kotzalas 2007
    vol. 2 eq. 3.4) through the Hertz law ``Q = K delta^1.5`` of the outer arcs (one arc:
    Q = F_c at contact angle 0; a gothic arch: two symmetric arcs at the angle theta of the
    seat, 2 Q cos(theta) = F_c). A radial clearance >= 0 keeps every ball off the inner ring
    (its gap is P_d/2 plus the outer approach), so this is the equilibrium: the ring carries
    nothing and each ball's radial balance is solved here by fixed-point iteration on
    r_b (contracting: d F_c / d r_b = m omega_m^2 is ~1e-9 of the contact stiffness).

    ``n_balls`` : Z; ``centrifugal_per_radius`` : m omega_m^2 [N/m], scalar or (Z,). Returns
    (ball_x [m], ball_r [m], (delta_a, delta_r) [m]) as :func:`rigid_pair_guess`."""
    tab = _arc_table(arcs)
    inner = arcs.ring == INNER
    outer = np.flatnonzero(~inner)
    u = np.array([float(np.mean(arcs.centre_x[outer]) - np.mean(arcs.centre_x[inner])), 0.0])
    D, dm, ep = arcs.ball_diameter, 2.0 * arcs.pitch_radius, arcs.effective_modulus
    k0 = outer[0]
    half = 0.5 * float(np.ptp(arcs.centre_x[outer]))     # 0 for one outer arc
    lo0 = float(arcs.free_distance[k0])
    theta = math.asin(min(half / lo0, 1.0))
    K = float(_arc_stiffness_nb(theta, -1.0, tab[T_RY, k0], D, dm, ep))
    n_arcs = outer.size
    mw2 = np.broadcast_to(np.asarray(centrifugal_per_radius, float), (int(n_balls),))
    cr = float(arcs.centre_r[k0])
    bx = np.full(mw2.shape, float(np.mean(arcs.centre_x[outer])))
    br = np.empty(mw2.shape)
    for j, c in enumerate(mw2):
        r = arcs.pitch_radius
        for _ in range(4):
            q = c * r / (n_arcs * math.cos(theta))   # load of each outer arc [N]
            lo = lo0 + (q / K) ** (2.0 / 3.0)
            r = cr + math.sqrt(max(lo * lo - half * half, 0.0))
        br[j] = r
    return bx, br, u


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
