"""Quasi-dynamic skidding / over-skidding solver of ball bearings (paper 002, QJ1044).

Steady state in the frame that turns with the cage. Every ball orbits with the cage (its
mean advance in the pocket is zero) and carries, per ball j, six unknowns

    x_j = (b_a, b_r, Omega_a, Omega_r, Omega_t, Q_p)

- ball-centre axial / radial position (b_a, b_r) [m] (the contact angles and loads follow from
  the raceway arcs of :mod:`thermobearing.loads`, every arc independent: two-, three- and
  four-point contact of a gothic-arch bearing come out of the geometry);
- the ball's angular velocity relative to the cage frame Omega [rad/s] in the local axes
  (a = bearing axis, r = radial, t = orbital direction), i.e. spin magnitude, attitude (pitch)
  angle beta = atan2(-Omega_r, Omega_a) and yaw angle (Omega_t, the "gyro-slip");
- the cage-pocket normal force Q_p [N] (positive: the cage pushes the ball forward);

and three global unknowns, the inner-ring displacements (delta_a, delta_r) [m] and the cage
speed omega_c [rad/s]. Equations per ball (paper 002, Fig. 1(c) and eq. 9 in steady state;
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

Nothing about over-skidding is imposed: the attitude angle, the contact angles (centrifugal
splitting of alpha_i / alpha_o, three-point contact against the outer shim angle) and the
rolling-direction slip all come out of these balances.

Numerics (issue 5 item 4): Newton with a structured forward-difference Jacobian -- the six
per-ball columns are perturbed for all balls at once (ball blocks are independent except
through the globals), three more evaluations give the global columns; the 6x6 ball blocks
are eliminated and the 3x3 Schur complement on the globals is solved; backtracking line
search on the scaled residual norm; warm starts; continuation in axial load from a
well-loaded state when a cold start fails. Failure raises ConvergenceError with the residual
norm and the state.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..contact_traction import _integrate_core
from ..errors import ConvergenceError, InputError, check_finite, check_positive
from ..hertz import _ellipse
from ..loads import (
    INNER,
    ArcSet,
    ContactField,
    _arc_hertz,
    ball_arcs,
    ball_load_distribution,
)

__all__ = ["BallModels", "BallSkiddingResult", "solve_ball", "ball_residual_system"]

N_BALL = 6
N_GLOBAL = 3
# largest Newton step per scaled unknown (positions in microns, spins / (omega_i d_m / D),
# pocket force / F_s; ring displacement in microns, cage speed / omega_i)
_CAP_X = np.array([20.0, 20.0, 0.2, 0.2, 0.2, 5.0])
_CAP_G = np.array([20.0, 20.0, 0.1])


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


@dataclass(frozen=True)
class BallSkiddingResult:
    """Converged state of :func:`solve_ball` (arrays per ball, shape (Z,) or (Z, k)).

    Attributes
    ----------
    cage_speed_ratio : CSR = omega_c / omega_i [-].
    theoretical_cage_speed_ratio : (1 - gamma cos alpha)/2 at the quasi-static (zero-speed)
        contact angle of the load distribution -- the CSR_th line of paper 002 Fig. 10 [-].
    kinematic_cage_speed_ratio : pure-rolling (outer-race-control) CSR at the *operating*
        inner/outer contact angles of the loaded balls (primer section 5, solver lesson) [-].
    over_skid : CSR / CSR_th - 1 [-] (positive: over-skidding, negative: skidding).
    converged, residual_norm, iterations, wall_time : solver diagnostics.
    cage_speed : omega_c [rad/s]; inner_speed [rad/s].
    ball_x, ball_r : ball-centre position [m]; delta_a, delta_r : ring displacement [m].
    spin : Omega (Z, 3) relative to the cage [rad/s]; spin_speed |Omega| [rad/s];
    attitude_angle : beta = atan2(-Omega_r, Omega_a) [rad]; yaw_angle [rad].
    pocket_force : Q_p [N].
    normal_load, contact_angle : (Z, k) per raceway arc [N], [rad]; ring (k,) 0/1.
    sliding_speed, transverse_sliding_speed, spin_speed_contact, entrainment_speed : (Z, k).
    heat : dict of total heat by component [W]; shaft_torque [N m].
    kinematic_state : :class:`thermobearing.state.KinematicState` for the heat sources (built
        on first access: its validation costs more than a warm-started solve).
    """

    cage_speed_ratio: float
    theoretical_cage_speed_ratio: float
    kinematic_cage_speed_ratio: float
    over_skid: float
    converged: bool
    residual_norm: float
    iterations: int
    wall_time: float
    inner_speed: float
    cage_speed: float
    ball_x: np.ndarray
    ball_r: np.ndarray
    delta_a: float
    delta_r: float
    spin: np.ndarray
    spin_speed: np.ndarray
    attitude_angle: np.ndarray
    yaw_angle: np.ndarray
    pocket_force: np.ndarray
    normal_load: np.ndarray
    contact_angle: np.ndarray
    ring: np.ndarray
    sliding_speed: np.ndarray
    transverse_sliding_speed: np.ndarray
    spin_speed_contact: np.ndarray
    entrainment_speed: np.ndarray
    heat: dict
    shaft_torque: float
    state_builder: Callable[[], Any] = field(repr=False, default=None, compare=False)
    unknowns: np.ndarray = field(repr=False, default=None)
    extra: dict = field(default_factory=dict, repr=False)

    @functools.cached_property
    def kinematic_state(self) -> Any:
        """:class:`thermobearing.state.KinematicState` of this solution (built once)."""
        return self.state_builder()

    @property
    def slip(self) -> float:
        """Cage slip relative to CSR_th: 1 - CSR/CSR_th (positive = skidding) [-]."""
        return -self.over_skid

    @property
    def orbital_speed(self) -> np.ndarray:
        return np.full(self.ball_x.shape, self.cage_speed)


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
        self.n_eval = 0
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
        self.w_race = np.where(self.inner, self.speed, 0.0)
        self.veps = 1e-6 * max(abs(self.speed) * self.Rm, 1e-3)
        self._torque_memo: dict[float, tuple[float, float, float]] = {}
        self.last_jacobian: JacobianBlocks | None = None
        self._last = None            # (X, G, (R, Gc, G0), details builder) of the last state
        check_positive("skidding.ball effective_modulus", self.Ep)
        check_positive("skidding.ball ball_mass", self.m)
        if models.n_major < 2 or models.n_minor < 1:
            raise InputError("skidding.ball n_major/n_minor", (models.n_major, models.n_minor),
                             "n_major >= 2 and n_minor >= 1")
        if getattr(models.traction_law, "requires_film", False) and models.film_thickness is None:
            raise InputError("skidding.ball film_thickness", None,
                             "a film-thickness model: the traction law shears a fluid film")

    # -- kinematics and forces ------------------------------------------------------------
    def evaluate(self, X: np.ndarray, G: np.ndarray, details: bool = False):
        """Scaled residuals; see the class docstring.

        X may carry leading batch dimensions, (..., Z, 6) with G (..., 3): every state of
        the batch is evaluated in the same numpy pass (the structured Jacobian evaluates its
        nine perturbed states at once). ``details`` needs a single state.
        """
        X = np.asarray(X, dtype=float)
        G = np.asarray(G, dtype=float)
        batch = X.shape[:-2]
        last = self._last
        if (details and last is not None and np.array_equal(X, last[0])
                and np.array_equal(G, last[1])):
            # the converged state was the last one evaluated: its details from that pass
            return (*last[2], last[3]())
        self.n_eval += int(np.prod(batch)) if batch else 1
        if not (np.all(np.isfinite(X)) and np.all(np.isfinite(G))):
            raise InputError("skidding.ball unknowns", "non-finite values", "finite values")
        md = self.models
        D = self.D
        e2 = (...,) + (None, None)
        wc = G[..., 2][e2]                                    # (..., 1, 1)
        br = X[..., 1:2]                                      # (..., Z, 1)
        # raceway arcs (loads.arc_contacts, the same geometry; Hertz constants unchecked)
        cx = self.cx0 + self.inner_f * G[..., 0][e2]
        cr = self.cr0 + self.inner_f * (G[..., 1][e2] * self.cpsi[:, None])
        dx, dr = X[..., 0:1] - cx, br - cr
        L = np.hypot(dx, dr)
        na, nr = dx / L, dr / L                               # (..., Z, k) arc centre -> ball
        approach = L - self.free
        alpha = np.arctan2(na, np.abs(nr))
        rx, _, r_red, k_el, big_e, K = _arc_hertz(self.arcs, self.dm, alpha)
        Q = K * np.maximum(approach, 0.0) ** 1.5
        a_ell, b_ell, p0 = _ellipse(Q, r_red, k_el, big_e, self.Ep)
        half = 0.5 * D - 0.5 * np.maximum(approach, 0.0)    # lever to the contact centre
        pa, pr = half * na, half * nr                         # contact point - ball centre
        Oa, Or, Ot = X[..., 2:3], X[..., 3:4], X[..., 4:5]
        w_race = self.w_race
        # absolute velocities (a, r, t components) at the contact point
        Rr = br + pr
        # Omega x p with p = (pa, pr, 0): (Or*0 - Ot*pr, Ot*pa - Oa*0, Oa*pr - Or*pa)
        vx_b = -Ot * pr
        vr_b = Ot * pa
        spin_t = Oa * pr - Or * pa
        vt_b = wc * Rr + spin_t
        # element minus race; contact frame: e_x = (nr, -na, 0), e_y = e_t, e_z = -n
        Vx = vx_b * nr - vr_b * na
        Vy = vt_b - w_race * Rr
        wa_rel = wc + Oa - w_race
        Om_x = wa_rel * nr - Or * na
        Om_y = np.broadcast_to(Ot, Q.shape)
        Om_z = -(wa_rel * na + Or * nr)
        ue = 0.5 * (spin_t + (w_race - wc) * Rr)
        film = None
        if md.film_thickness is not None:
            film = md.film_thickness(np.abs(ue), Q, rx, np.broadcast_to(self.ry, Q.shape))
            film = np.broadcast_to(np.asarray(film, dtype=float), Q.shape)
            if not np.all(film[Q > 0] > 0):
                raise InputError("skidding.ball film_thickness", "values <= 0 at loaded "
                                 "contacts", "a film thickness > 0 [m]")
        tr = _integrate_core(md.traction_law, Q, a_ell, b_ell, Vy, Vx, Om_z, Om_x, Om_y,
                             self.curv, film, md.temperature, "point", md.n_major,
                             md.n_minor, False)
        Fx, Fy = tr.transverse_force, tr.rolling_force
        Mx, My, Mz = tr.moment_transverse, tr.moment_rolling, tr.moment_normal
        # contact force on the ball in (a, r, t)
        Fa_k = -Q * na + Fx * nr
        Fr_k = -Q * nr - Fx * na
        Ft_k = Fy
        # moment about the ball centre: p x F_tan + M (e_x, e_y, e_z)
        # p x F with p = (pa, pr, 0), F = (Fa, Fr, Ft): (pr*Ft, -pa*Ft, pa*Fr - pr*Fa)
        Ma_k = pr * Ft_k + Mx * nr - Mz * na
        Mr_k = -pa * Ft_k - Mx * na - Mz * nr
        Mt_k = pa * Fr_k - pr * Fa_k + My
        # pocket: contact point p_c = (0, 0, -s D/2), friction f = mu Q_p w_hat with
        # w = Omega x (D/2) e_t = (D/2)(Or, -Oa, 0) (ball surface velocity at +t, rel. cage)
        Qp = X[..., 5]
        s = np.where(Qp >= 0.0, 1.0, -1.0)
        wa_, wr_ = 0.5 * D * X[..., 3], -0.5 * D * X[..., 2]
        wn = np.hypot(wa_, wr_)
        wden = np.sqrt(wn * wn + self.veps * self.veps)
        mu_p = md.pocket_friction
        fpa = mu_p * Qp * wa_ / wden
        fpr = mu_p * Qp * wr_ / wden
        pct = -s * 0.5 * D
        # p_c x f_p with p_c = (0, 0, pct), f = (fpa, fpr, 0): (-pct*fpr, pct*fpa, 0)
        Mpa, Mpr = -pct * fpr, pct * fpa
        # drag and centrifugal
        wc1 = G[..., 2:3]                                     # (..., 1)
        r_drag = X[..., 1] if md.drag_radius is None else md.drag_radius
        u_ball = (wc1 * (1.0 - md.oil_speed_ratio)) * r_drag
        Fd = np.asarray(md.ball_drag(np.abs(u_ball)), float) * np.sign(u_ball) * (
            r_drag / X[..., 1])
        Fc = self.m * wc1 * wc1 * X[..., 1]
        J = self.J
        R = np.empty(batch + (self.Z, N_BALL))
        R[..., 0] = (Fa_k.sum(-1) + fpa) / self.F_s
        R[..., 1] = (Fr_k.sum(-1) + fpr + Fc) / self.F_s
        R[..., 2] = (Ft_k.sum(-1) - Fd + Qp) / self.F_s
        # gyroscopic: required moment omega_c e_a x J Omega = J wc (0, -Ot, Or)
        R[..., 3] = (Ma_k.sum(-1) + Mpa) / self.M_s
        R[..., 4] = (Mr_k.sum(-1) + Mpr + J * wc1 * X[..., 4]) / self.M_s
        R[..., 5] = (Mt_k.sum(-1) - J * wc1 * X[..., 3]) / self.M_s
        # global contributions: ring force (reaction of inner contacts), cage torque
        Gc = np.empty(batch + (self.Z, N_GLOBAL))
        Gc[..., 0] = -(Fa_k @ self.inner_f) / self.F_s
        Gc[..., 1] = -(Fr_k @ self.inner_f) * self.cpsi / self.F_s
        # torque on the cage about the axis from ball j: force -(fpa, fpr, Qp) at (ba, br, pct)
        Gc[..., 2] = (-X[..., 1] * Qp + pct * fpr) / self.T_s
        G0 = np.empty(batch + (N_GLOBAL,))
        G0[..., 0] = self.Fa / self.F_s
        G0[..., 1] = self.Fr / self.F_s
        wcs = G[..., 2]
        G0[..., 2] = np.reshape([-sum(self._cage_torques(float(w))[:2]) / self.T_s
                                 for w in np.ravel(wcs)], wcs.shape)
        if batch:
            if details:
                raise InputError("skidding.ball evaluate(details=True)", X.shape,
                                 "a single state (Z, 6)")
            return R, Gc, G0, None

        def make_details():
            return self._details(X, G, approach, Q, na, nr, L, alpha, K, tr, s, wa_, wr_, fpa,
                                 fpr, Fd, br, pr, Ft_k, Mx, Mz, a_ell, b_ell, p0, rx, film, Vx,
                                 Vy, Om_x, Om_y, Om_z, ue, u_ball, wn, Fc)

        self._last = (X.copy(), G.copy(), (R, Gc, G0), make_details)
        return R, Gc, G0, (make_details() if details else None)

    def _details(self, X, G, approach, Q, na, nr, L, alpha, K, tr, s, wa_, wr_, fpa, fpr, Fd,
                 br, pr, Ft_k, Mx, Mz, a_ell, b_ell, p0, rx, film, Vx, Vy, Om_x, Om_y, Om_z, ue,
                 u_ball, wn, Fc):
        """Heat, shaft torque and the contact fields of one evaluated state (energy audit)."""
        md = self.models
        wi = self.speed
        t_churn, t_guide, wg = self._cage_torques(float(G[2]))
        wc = float(G[2])
        inn = self.inner[None, :]
        cf = ContactField(approach, Q, na, nr, L, alpha, K)
        ry = np.broadcast_to(self.ry, Q.shape)
        # heat and shaft torque (energy audit)
        contact_heat = tr.heat
        pocket_heat = -(fpa * (-s * wa_) + fpr * (-s * wr_))  # -f . v_rel, v_rel = -s w
        drag_heat = Fd * wc * X[:, 1]   # power given to the oil (all dissipated)
        cage_heat = t_churn * wc
        guide_heat = t_guide * (wc - wg)
        inner_torque = float(md.inner_ring_torque(wi))
        if md.guide_on_inner_ring:
            inner_torque += t_guide       # the land's reaction on the inner ring
        # torque on the inner ring from the balls = -sum (R_P x F_ball)_a - M_ball,a
        Rp_r = br + pr
        shaft = np.sum(np.where(inn, Rp_r * Ft_k + (Mx * nr - Mz * na), 0.0)) + inner_torque
        det = dict(cf=cf, wc=wc, a=a_ell, b=b_ell, p0=p0, rx=rx, ry=ry, film=film, Vx=Vx, Vy=Vy,
                   Om_x=Om_x, Om_y=Om_y, Om_z=Om_z, ue=ue, tr=tr, Fd=Fd, u_ball=u_ball,
                   pocket_heat=pocket_heat, contact_heat=contact_heat, drag_heat=drag_heat,
                   cage_heat=cage_heat, guide_heat=guide_heat,
                   inner_churn_heat=inner_torque * wi, shaft_torque=shaft,
                   pocket_sliding=wn, Fc=Fc)
        return det

    def _cage_torques(self, wc: float):
        """(churning torque, guide torque, guide speed) at cage speed wc (memoised: the
        Jacobian's ball columns and the line search revisit the same wc)."""
        hit = self._torque_memo.get(wc)
        if hit is not None:
            return hit
        md = self.models
        t_churn = float(md.cage_torque(wc))
        wg = self.speed if md.guide_on_inner_ring else 0.0
        t_guide = 0.0 if md.cage_guide_torque is None else float(md.cage_guide_torque(wc, wg))
        if len(self._torque_memo) > 64:
            self._torque_memo.clear()
        self._torque_memo[wc] = (t_churn, t_guide, wg)
        return t_churn, t_guide, wg

    # -- full residual vector (for scipy comparisons) -------------------------------------
    def full_residual(self, y: np.ndarray, x_ref: np.ndarray, g_ref: np.ndarray) -> np.ndarray:
        """Residual of the flat scaled unknown vector ``y`` (Z*6 + 3,)."""
        X, G = self.unscale(y, x_ref, g_ref)
        R, Gc, G0, _ = self.evaluate(X, G)
        return np.concatenate([R.ravel(), Gc.sum(0) + G0])

    # scaling of the unknowns: positions in microns from a reference, spins by omega_i d_m/D,
    # pocket force by F_s, ring displacement in microns, cage speed by omega_i
    def scales(self):
        ws = self.w_s * 2.0 * self.Rm / self.D
        xs = np.array([1e-6, 1e-6, ws, ws, ws, self.F_s])
        gs = np.array([1e-6, 1e-6, self.w_s])
        return xs, gs

    def unscale(self, y, x_ref, g_ref):
        xs, gs = self.scales()
        Z = self.Z
        X = x_ref + y[: Z * N_BALL].reshape(Z, N_BALL) * xs
        G = g_ref + y[Z * N_BALL:] * gs
        return X, G


# ---------------------------------------------------------------------------------------------
# Newton with block elimination
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class JacobianBlocks:
    """Structured Jacobian of the scaled residual in the scaled unknowns.

    A (Z, 6, 6) ball blocks, B (Z, 6, 3) ball rows / global columns, C (Z, 3, 6) global
    rows / ball columns, Dg (3, 3); with the scales it was taken at (F_s, xs, gs) so that a
    later solve can reuse it as a chord Jacobian (:meth:`rescaled`).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    Dg: np.ndarray
    F_s: float
    xs: np.ndarray
    gs: np.ndarray
    Z: int

    def rescaled(self, system: ball_residual_system) -> JacobianBlocks:
        """The same physical Jacobian in the scaling of ``system``.

        Every residual row is divided by a multiple of F_s (forces F_s, moments F_s D/2,
        cage torque F_s d_m/2) and column c is multiplied by the unknown's scale, so
        J_new = J_old (F_s,old / F_s,new) (scale_new / scale_old) column by column.
        """
        xs, gs = system.scales()
        f = self.F_s / system.F_s
        rx, rg = f * xs / self.xs, f * gs / self.gs
        return JacobianBlocks(self.A * rx, self.B * rg, self.C * rx, self.Dg * rg, system.F_s,
                              xs, gs, self.Z)


def newton_block(system: ball_residual_system, X0: np.ndarray, G0: np.ndarray, *,
                 tol: float = 1e-9, max_iter: int = 60, fd_step: float = 1e-6,
                 max_step: float = 1.0, reuse_ratio: float = 0.25,
                 polish_ratio: float = 1e-2, give_up: tuple[int, float] | None = None,
                 jacobian: JacobianBlocks | None = None):
    """Damped Newton on (X, G) with the structured finite-difference Jacobian.

    The Jacobian (6x6 ball blocks, ball-global couplings, 3x3 Schur complement) needs
    N_BALL + N_GLOBAL = 9 perturbed states whatever Z is; they are evaluated as one batch
    (:meth:`ball_residual_system.evaluate` on (9, Z, 6)). It is reused for the next step
    (chord / Shamanskii step) while the full step cut the residual norm below
    ``reuse_ratio`` times its previous value; a stale step that does not reduce the norm is
    discarded and the Jacobian refreshed (good-Broyden updates of the chord Jacobian were
    tried and removed: no fewer iterations on +2 % warm steps, and they stalled a Z = 32
    cold start that plain chord steps solve in 41 iterations). A solve that ends on a
    linearly converging chord step takes one more (``polish_ratio``) so that the residual, and with
    it the energy balance, ends well below ``tol``. ``give_up = (n, f)``: raise
    ConvergenceError when the residual norm is still above f times its start after n
    iterations (used for warm starts, which then restart cold). ``jacobian``: blocks of an
    earlier solve (warm start, rescaled to this system by :meth:`JacobianBlocks.rescaled`)
    used as the first chord Jacobian. The last fresh Jacobian is left in ``system.last_jacobian``.

    Returns (X, G, residual_norm, iterations). Raises ConvergenceError.
    """
    xs, gs = system.scales()
    Z = system.Z
    X, G = X0.copy(), G0.copy()
    nb = N_BALL + N_GLOBAL
    eye_x = np.zeros((N_BALL, 1, N_BALL))
    eye_x[np.arange(N_BALL), 0, np.arange(N_BALL)] = fd_step * xs
    eye_g = np.zeros((nb, N_GLOBAL))
    eye_g[N_BALL + np.arange(N_GLOBAL), np.arange(N_GLOBAL)] = fd_step * gs

    def norm_of(R, Gc, Gk):
        return float(np.sqrt(np.sum(R * R) + np.sum((Gc.sum(0) + Gk) ** 2)))

    def jacobian_fd(X, G, R, Gc, Gk):
        Xb = np.empty((nb, Z, N_BALL))
        Xb[:] = X
        Xb[:N_BALL] += eye_x
        Gb = G + eye_g
        Rb, Gcb, Gkb, _ = system.evaluate(Xb, Gb)
        dR = (Rb - R) / fd_step                      # (9, Z, 6): column c in axis 0
        A = np.moveaxis(dR[:N_BALL], 0, -1)          # (Z, 6, 6)
        B = np.moveaxis(dR[N_BALL:], 0, -1)          # (Z, 6, 3)
        C = np.moveaxis((Gcb[:N_BALL] - Gc) / fd_step, 0, -1)   # (Z, 3, 6)
        Dg = (((Gcb[N_BALL:].sum(1) + Gkb[N_BALL:]) - (Gc.sum(0) + Gk)) / fd_step).T
        blocks = JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, Z)
        system.last_jacobian = blocks
        return factor(blocks, R, Gc, Gk, G)

    def factor(blocks, R, Gc, Gk, G):
        try:
            Ainv = np.linalg.inv(blocks.A)
        except np.linalg.LinAlgError:
            raise ConvergenceError("skidding.ball", norm_of(R, Gc, Gk), "singular ball block",
                                   {"cage_speed": G[2]}) from None
        Ainv_B = Ainv @ blocks.B
        S = blocks.Dg - np.einsum("zgi,zij->gj", blocks.C, Ainv_B)
        return Ainv, Ainv_B, blocks.C, S

    def step(jac, R, Gc, Gk):
        Ainv, Ainv_B, C, S = jac
        Ainv_R = np.einsum("zij,zj->zi", Ainv, R)
        rhs = -(Gc.sum(0) + Gk) + np.einsum("zgi,zi->g", C, Ainv_R)
        try:
            dG = np.linalg.solve(S, rhs)
        except np.linalg.LinAlgError:
            dG = np.linalg.lstsq(S, rhs, rcond=None)[0]
        return -Ainv_R - np.einsum("zij,j->zi", Ainv_B, dG), dG

    R, Gc, Gk, _ = system.evaluate(X, G)
    nrm = norm_of(R, Gc, Gk)
    it = 0
    jac = None
    if jacobian is not None and jacobian.Z == Z:
        system.last_jacobian = jacobian.rescaled(system)
        if nrm > tol:
            try:
                jac = factor(system.last_jacobian, R, Gc, Gk, G)
            except ConvergenceError:
                jac = None
    last_ratio, polished, nrm0 = 1.0, False, nrm
    while it < max_iter:
        if nrm <= tol:
            # a chord iteration converges linearly and stops just below tol,
            # where a Newton step would overshoot by orders of magnitude: one more step
            # with the current Jacobian (the energy balance closes with the residual)
            if polished or last_ratio < polish_ratio or jac is None:
                break
            polished = True
        if give_up is not None and it >= give_up[0] and nrm > give_up[1] * nrm0:
            raise ConvergenceError("skidding.ball", nrm, f"slow progress: residual still "
                                   f"{nrm / nrm0:.2f} x its start after {it} iterations",
                                   {"iteration": it, "cage_speed": G[2]})
        it += 1
        stale = jac is not None
        if jac is None:
            jac = jacobian_fd(X, G, R, Gc, Gk)
        dX, dG = step(jac, R, Gc, Gk)
        big = max(np.max(np.abs(dX) / _CAP_X), np.max(np.abs(dG) / _CAP_G))
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        if stale:
            # chord step: full step only (a step the cap would shorten refreshes
            # the Jacobian: measured, capped chord steps can stall a cold start), accepted
            # if it reduces the norm, else discarded and the Jacobian refreshed
            ok, nn = False, np.inf
            if lam == 1.0:
                try:
                    Rn, Gcn, Gkn, _ = system.evaluate(X + dX * xs, G + dG * gs)
                    nn = norm_of(Rn, Gcn, Gkn)
                    ok = bool(np.isfinite(nn) and nn < nrm)
                except (InputError, FloatingPointError, ValueError):
                    ok = False
            if ok:
                X, G, R, Gc, Gk = X + dX * xs, G + dG * gs, Rn, Gcn, Gkn
                if nn > reuse_ratio * nrm:
                    jac = None
                nrm, last_ratio = nn, nn / nrm
            else:
                jac = None
                it -= 1
            continue
        while True:
            Xn = X + lam * dX * xs
            Gn = G + lam * dG * gs
            ok = True
            try:
                Rn, Gcn, Gkn, _ = system.evaluate(Xn, Gn)
                nn = norm_of(Rn, Gcn, Gkn)
                ok = np.isfinite(nn)
            except (InputError, FloatingPointError, ValueError):
                ok, nn = False, np.inf
            if ok and (nn < (1 - 1e-4 * lam) * nrm or lam < 1e-3):
                break
            lam *= 0.5
            if lam < 1e-6:
                break
        if not ok or lam < 1e-6:
            raise ConvergenceError("skidding.ball", nrm, "line search failed",
                                   {"iteration": it, "cage_speed": G[2]})
        if not (lam == 1.0 and nn < reuse_ratio * nrm):
            jac = None
        X, G, R, Gc, Gk, nrm, last_ratio = Xn, Gn, Rn, Gcn, Gkn, nn, nn / nrm
    if not nrm <= tol:
        raise ConvergenceError("skidding.ball", nrm, f"no convergence in {max_iter} iterations",
                               {"cage_speed": G[2], "delta_a": G[0], "delta_r": G[1]})
    return X, G, nrm, it


# ---------------------------------------------------------------------------------------------
# initial state from the load distribution and race control
# ---------------------------------------------------------------------------------------------
def race_control_guess(bearing, speed, radial_load, axial_load, n_balls=None):
    """Ball positions from :func:`ball_load_distribution` and outer-race-control spin.

    The spin vector follows the primer's (K1)-(K2) with the outer-race-control attitude
    tan(beta) = sin(alpha_o)/(cos(alpha_o) + gamma') (primer section 2.3), gamma' = D/d_m.
    """
    D = float(bearing.ball_diameter)
    dm = float(bearing.pitch_diameter)
    a0 = float(bearing.contact_angle)
    wm0 = 0.5 * speed * (1.0 - D * np.cos(a0) / dm)
    ld = ball_load_distribution(bearing, radial_load, axial_load, speed, orbital_speed=wm0,
                                n_balls=n_balls)
    ai, ao = ld.inner_contact_angle, ld.outer_contact_angle
    g = D / dm
    beta = np.arctan2(np.sin(ao), np.cos(ao) + g) * (1.0 if axial_load >= 0 else -1.0)
    ao = ao * (1.0 if axial_load >= 0 else -1.0)
    ai = ai * (1.0 if axial_load >= 0 else -1.0)
    T = np.tan(beta)
    ci, co = np.cos(ai), np.cos(ao)
    si, so = np.sin(ai), np.sin(ao)
    num = (1 - g * ci) * (co + T * so)
    wm = speed * num / (num + (1 + g * co) * (ci + T * si))
    wR = -speed / (g * np.cos(beta) * ((co + T * so) / (1 + g * co) + (ci + T * si) / (1 - g * ci)))
    # Omega = wR (cos beta, 0, -sin beta) in (a, r=z', t) -> components (a, r, t)
    X = np.zeros((ld.ball_x.size, N_BALL))
    X[:, 0], X[:, 1] = ld.ball_x, ld.ball_r
    X[:, 2] = wR * np.cos(beta)
    X[:, 3] = -wR * np.sin(beta)
    G = np.array([ld.delta_a, ld.delta_r, float(np.mean(wm))])
    return X, G, ld


# ---------------------------------------------------------------------------------------------
def solve_ball(bearing, models: BallModels, speed: float, radial_load: float,
               axial_load: float, *, n_balls: int | None = None,
               guess: BallSkiddingResult | None = None, tol: float = 1e-9,
               max_iter: int = 150, continuation: bool = True,
               theoretical_reference=None, warm_iterations: int = 25) -> BallSkiddingResult:
    """Solve the ball/cage/ring equilibrium at one operating point.

    Parameters
    ----------
    bearing : BallBearing.
    models : BallModels (traction law, drag, cage torque, pocket friction).
    speed : inner-ring speed [rad/s] (> 0; outer ring fixed).
    radial_load, axial_load : [N] on the inner ring.
    n_balls : override Z (benchmarks).
    guess : previous result for a warm start (its unknowns and its Jacobian, rescaled, as
        the first chord Jacobian).
    warm_iterations : iterations allowed from the warm start before the cold start.
    tol : tolerance on the scaled residual norm (forces / F_s, moments / (F_s D/2)).
    continuation : on a cold-start failure, continue from a higher axial load.

    Returns
    -------
    BallSkiddingResult
    """
    check_positive("speed", speed)
    check_positive("radial_load", radial_load, allow_zero=True)
    check_finite("axial_load", axial_load)
    t0 = time.perf_counter()
    system = ball_residual_system(bearing, models, speed, radial_load, axial_load, n_balls)
    iters = 0
    if guess is not None and guess.ball_x.size == system.Z:
        X0 = guess.unknowns[0].copy()
        G0 = guess.unknowns[1].copy()
        G0[2] = guess.cage_speed_ratio * speed
        X0[:, 2:5] *= speed / guess.inner_speed
        try:
            # a warm start that needs many iterations is further from the solution than
            # the race-control cold start (measured: a 0 -> 2 kN axial step of the QJ1044
            # took 47 warm iterations, 10 cold): give it a budget, then start cold. 25
            # (was 15): the default scene's 2 -> 4 kN step converges warm in 24 iterations
            # (209 evaluations, ~105 ms CPU) where 15 warm + a cold start cost 257
            # evaluations plus the at-speed load distribution (~210 ms CPU)
            X, G, nrm, iters = newton_block(system, X0, G0, tol=tol,
                                            max_iter=min(max_iter, warm_iterations),
                                            jacobian=guess.extra.get("jacobian"),
                                            give_up=(6, 0.5))
        except ConvergenceError:
            guess = None
    if guess is None:
        X0, G0, ld0 = race_control_guess(bearing, speed, radial_load, axial_load, n_balls)
        if not np.any(ld0.inner_load > 0.0):
            # e.g. no external load at speed: centrifugal force seats every ball in the outer
            # groove, no ball touches the inner ring and nothing in this model drives the
            # balls or the cage (no inner-ring oil drag): the steady state is undefined.
            raise ConvergenceError(
                "skidding.ball", float("inf"),
                "no ball touches the inner ring (centrifugal force holds every ball in the "
                "outer groove): nothing drives the cage, CSR undefined in this model",
                {"radial_load": radial_load, "axial_load": axial_load, "speed": speed})
        try:
            X, G, nrm, iters = newton_block(system, X0, G0, tol=tol, max_iter=max_iter)
        except ConvergenceError as err:
            if not continuation:
                raise
            X, G, nrm, iters, system.last_jacobian = _continuation(
                bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter, err)
    own_reference = theoretical_reference is None
    if own_reference and guess is not None:
        # CSR_th depends on the loads and the geometry only (a zero-speed load
        # distribution): reuse the warm start's when they are the same
        key = guess.extra.get("theoretical_key")
        if key is not None and key[0] is bearing and key[1:] == (float(radial_load),
                                                                   float(axial_load),
                                                                   system.Z):
            theoretical_reference = guess.theoretical_cage_speed_ratio
    res = _result(system, X, G, nrm, iters, time.perf_counter() - t0, theoretical_reference)
    if own_reference:
        res.extra["theoretical_key"] = (bearing, float(radial_load), float(axial_load),
                                        system.Z)
    return res


def _continuation(bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter,
                  err):
    """Continuation in axial load from a well-loaded state (issue 5 item 4)."""
    Z = int(n_balls or bearing.n_balls)
    fc = bearing.ball_mass * (0.25 * speed) ** 2 * 0.5 * bearing.pitch_diameter
    F_hi = max(abs(axial_load), Z * fc * 4.0, 5000.0) * (1 if axial_load >= 0 else -1)
    loads = np.concatenate([[F_hi], F_hi * np.geomspace(1.0, 1e-3, 13)[1:], [0.0]])
    loads = loads[np.abs(loads) > abs(axial_load)]
    loads = np.append(loads, axial_load)
    X = G = None
    total = 0
    jac = None
    for Fa in loads:
        system = ball_residual_system(bearing, models, speed, radial_load, Fa, n_balls)
        if X is None:
            X, G, _ = race_control_guess(bearing, speed, radial_load, Fa, n_balls)
        try:
            X, G, nrm, it = newton_block(system, X, G, tol=tol, max_iter=max_iter,
                                         jacobian=jac)
            jac = system.last_jacobian
        except ConvergenceError as e2:
            raise ConvergenceError("skidding.ball", e2.residual,
                                   f"continuation failed at axial load {Fa:.6g} N "
                                   f"(cold start: {err})", {**e2.state, "axial_load": Fa}) from None
        total += it
    return X, G, nrm, total, jac


def _result(system: ball_residual_system, X, G, nrm, iters, wall, theoretical_reference):

    R, Gc, G0, det = system.evaluate(X, G, details=True)
    b = system.bearing
    cf = det["cf"]
    Q = cf.load
    wi, wc = system.speed, G[2]
    csr = wc / wi
    inner = system.inner
    from ..loads import ring_weighted_angle

    a0 = float(b.contact_angle)
    ai = ring_weighted_angle(Q, cf.contact_angle, inner, a0)
    ao = ring_weighted_angle(Q, cf.contact_angle, ~inner, a0)
    loaded = (np.where(inner[None, :], Q, 0).sum(1) > 0)
    w = np.where(inner[None, :], Q, 0).sum(1)
    if np.any(loaded):
        ai_m = float(np.sum(w * ai) / np.sum(w))
        ao_m = float(np.sum(w * ao) / np.sum(w))
    else:
        ai_m = ao_m = a0
    g = b.ball_diameter / b.pitch_diameter
    kin = float((1 - g * np.cos(ai_m)) / (1 + np.cos(ai_m - ao_m)))
    if theoretical_reference is None:
        theoretical_reference = theoretical_csr(b, system.Fr, system.Fa, system.Z)
    th = float(theoretical_reference)
    Om = X[:, 2:5]
    spin = np.linalg.norm(Om, axis=1)
    beta = np.arctan2(Om[:, 1], -Om[:, 0])
    yaw = np.arctan2(Om[:, 2], np.hypot(Om[:, 0], Om[:, 1]))
    heat = {"raceway": float(np.sum(det["contact_heat"])),
            "raceway_inner": float(np.sum(np.where(inner[None, :], det["contact_heat"], 0))),
            "raceway_outer": float(np.sum(np.where(~inner[None, :], det["contact_heat"], 0))),
            "ball_pocket": float(np.sum(det["pocket_heat"])),
            "ball_drag": float(np.sum(det["drag_heat"])),
            "cage": float(det["cage_heat"]),
            "cage_guide": float(det["guide_heat"]),
            "inner_ring_churning": float(det["inner_churn_heat"])}
    heat["total"] = float(sum(v for k, v in heat.items()
                              if k not in ("raceway_inner", "raceway_outer")))
    names = []
    for k in range(system.arcs.n_arcs):
        race = ("inner" if inner[k] else "outer")
        nth = int(np.sum((inner == inner[k])[:k]))
        names.append(race if nth == 0 else f"{race}_{nth + 1}")

    def build_state():
        return _kinematic_state(system, X, det, names, heat)

    return BallSkiddingResult(
        cage_speed_ratio=float(csr), theoretical_cage_speed_ratio=th,
        kinematic_cage_speed_ratio=kin, over_skid=float(csr / th - 1.0), converged=True,
        residual_norm=float(nrm), iterations=int(iters), wall_time=float(wall), inner_speed=wi,
        cage_speed=float(wc), ball_x=X[:, 0].copy(), ball_r=X[:, 1].copy(), delta_a=float(G[0]),
        delta_r=float(G[1]), spin=Om.copy(), spin_speed=spin, attitude_angle=beta,
        yaw_angle=yaw, pocket_force=X[:, 5].copy(), normal_load=Q, contact_angle=cf.contact_angle,
        ring=system.arcs.ring, sliding_speed=det["Vy"], transverse_sliding_speed=det["Vx"],
        spin_speed_contact=det["Om_z"], entrainment_speed=det["ue"], heat=heat,
        shaft_torque=float(det["shaft_torque"]), state_builder=build_state, unknowns=(X, G),
        extra={"n_eval": system.n_eval, "inner_contact_angle": ai, "outer_contact_angle": ao,
               "race_names": names, "residual": R,
               "traction_law": system.models.traction_law,
               "jacobian": system.last_jacobian})


def _kinematic_state(system: ball_residual_system, X, det, names, heat):
    """The :class:`~thermobearing.state.KinematicState` of a converged solution."""
    from ..state import ContactSet, KinematicState

    cf = det["cf"]
    Q = cf.load
    sets = []
    for k, name in enumerate(names):
        sets.append(ContactSet(
            race=name, normal_load=Q[:, k], semi_major=det["a"][:, k], semi_minor=det["b"][:, k],
            max_pressure=det["p0"][:, k], contact_angle=np.abs(cf.contact_angle[:, k]),
            entrainment_speed=np.abs(det["ue"][:, k]), sliding_speed=det["Vy"][:, k],
            transverse_sliding_speed=det["Vx"][:, k], spin_speed=det["Om_z"][:, k],
            roll_speed=det["Om_x"][:, k], tilt_speed=det["Om_y"][:, k],
            deformed_radius=system.rd[k],
            film_thickness=None if det["film"] is None else np.maximum(det["film"][:, k], 0.0),
            temperature=system.models.temperature,
            reduced_radius_x=det["rx"][:, k], reduced_radius_y=det["ry"][:, k]))
    wc = float(det["wc"])
    return KinematicState(
        inner_speed=system.speed, outer_speed=0.0, cage_speed=wc,
        orbital_speed=np.full(system.Z, wc), element_spin=np.linalg.norm(X[:, 2:5], axis=1),
        contacts=tuple(sets), attitude_angle=np.arctan2(X[:, 3], -X[:, 2]),
        azimuth=system.psi, pocket_normal_force=np.abs(X[:, 5]),
        pocket_sliding_speed=det["pocket_sliding"], element_drag_force=np.abs(det["Fd"]),
        origin="skidding", extras={"solver_heat": heat, "shaft_torque": det["shaft_torque"]})


def theoretical_csr(bearing, radial_load, axial_load, n_balls=None) -> float:
    """Paper 002's CSR_th: (1 - gamma cos alpha)/2 at the quasi-static contact angle.

    alpha is the load-weighted inner contact angle of the zero-speed load distribution under
    the same radial and axial load (paper 002 section 4.1: CSR_th follows the contact-angle
    distribution at 1 kN radial load and the applied axial load).
    """
    ld = ball_load_distribution(bearing, radial_load, axial_load, 0.0, n_balls=n_balls)
    w = ld.inner_load
    alpha = (float(np.sum(w * ld.inner_contact_angle) / np.sum(w)) if np.sum(w) > 0
             else float(bearing.contact_angle))
    g = bearing.ball_diameter * np.cos(alpha) / bearing.pitch_diameter
    return float(0.5 * (1.0 - g))
