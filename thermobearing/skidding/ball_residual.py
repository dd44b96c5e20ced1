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
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..contact_traction import _integrate_core
from ..errors import InputError, check_positive
from ..hertz import _ellipse
from ..loads import (
    INNER,
    ArcSet,
    ContactField,
    _arc_hertz,
    ball_arcs,
)

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
