"""Residual of the ball/cage/ring equilibrium of the ball skidding solver (paper 002, QJ1044).

One job: evaluate the scaled residuals of :mod:`thermobearing.skidding.ball`'s unknowns
(:class:`ball_residual_system`) for the force models it balances (:class:`BallModels`). The
unknowns (per ball the centre position, the angular velocity relative to the cage frame and
the cage-pocket force; the inner-ring displacements and the cage speed) and the equations
(paper 002 Fig. 1(c), eqs. 5-10 and 19; primer ../shared/notes/over-skidding.md sections
3.3-3.4) are written out once, in the docstring of
:mod:`thermobearing.skidding.ball_residual_kernels`.

Implementation: the residual of a batch of states is compiled (numba, ``cache=True``) in
:mod:`thermobearing.skidding.ball_residual_kernels` (re-exported here):
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

import numpy as np

from ..contact_traction import (
    _EMPTY,
    _EMPTY2,
    ContactTraction,
    _node_pressures,
    _rule,
    viscosity_source,
)
from ..errors import InputError, check_positive
from ..loads import (
    INNER,
    ArcSet,
    ContactField,
    ball_arcs,
)
from ..traction import EYRING
from .ball_residual_kernels import (  # noqa: F401  (the compiled kernels, re-exported)
    _EMPTY_TR,
    _NO_REUSE,
    _NO_TAB,
    _TINY,
    _TWO_OVER_PI,
    A_CR,
    A_CURV,
    A_CX,
    A_FREE,
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
    G_ALPHA,
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
    N_C,
    N_GEO,
    N_GLOBAL,
    N_POCKET,
    P_FC,
    P_FPA,
    P_FPR,
    P_S,
    P_WA,
    P_WN,
    P_WR,
    _ball_forces,
    _ball_geometry,
    _ball_residual_fused,
    _contact_angles,
    _ellipse_vec,
    _energy_audit,
    _film_rows,
    _hb_point,
    _hd1977_central_vec,
    _hertz_rows,
    _refresh_caches,
    _rescaled_residual,
    _residual_norm_nb,
    _residual_one,
    _rolling_audit,
    _rolling_terms,
    _same_state,
    guarded_film,
    guarded_film_array,
)

if TYPE_CHECKING:
    from .ball_newton import JacobianBlocks

__all__ = ["N_BALL", "N_GLOBAL", "BallModels", "ball_residual_system"]


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
    rolling_resistance : parameters of the EHL rolling resistance of the raceway contacts
        (:func:`thermobearing.rolling_resistance.kernel_parameters`), or None (none: the
        default). The force and where it acts: ``ball_residual_kernels._rolling_terms``.
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
    rolling_resistance: np.ndarray | None = None



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
        fc = self.m * (0.5 * w) * (0.5 * w) * self.Rm   # (inf, not OverflowError, past 1e154)
        if not math.isfinite(fc):   # 1e300 r/min stopped here with a bare OverflowError
            raise InputError("speed", self.speed, "a finite speed [rad/s] at which the balls' "
                             "centrifugal force m (w/2)^2 R_m is a finite number")
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
        self._c = np.zeros(N_C)
        self._c[:C_RR] = (self.D, self.dm, self.Ep, self.m, self.J, self.F_s, self.M_s,
                          self.T_s, self.veps, float(models.pocket_friction))
        if models.rolling_resistance is not None:
            from ..rolling_resistance import kernel_parameters_checked

            self._c[C_RR:] = kernel_parameters_checked(models.rolling_resistance)
        self.rolling = bool(self._c[C_RR] != 0.0)
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
            # a writable C-contiguous copy (a read-only broadcast view would compile the
            # kernels once more for read-only arrays)
            Fd_b = np.array(np.broadcast_to(Fd, batch + (Z,)).reshape(n_states, Z), order="C")
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

    def last_fields(self, X: np.ndarray, G: np.ndarray):
        """(R, Gc, G0, fields) as :meth:`evaluate_fields` when (X, G) are the very arrays of
        the last state evaluated or stored (:meth:`store_last`; identity, no comparison),
        else None. The contact-angle row of the fields' geo is left as the residual left it
        (the result kernel ``ball_result._result_kernel`` fills it)."""
        last = self._last
        if last is None or last[0] is not X or last[1] is not G:
            return None
        self.last_norm = last[4]
        return (*last[2], last[5])

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
                eta_nodes = np.array(np.broadcast_to(np.asarray(
                    md.traction_law.lubricant.dynamic_viscosity(md.temperature, pn),
                    dtype=float), pn.shape), order="C")       # writable, as the kernel's
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
        rr_force, rr_heat, rr_shaft = _rolling_audit(X, geo, self._arc, self._c)
        shaft += rr_shaft
        det = dict(cf=cf, wc=wc, a=geo[G_A], b=geo[G_B], p0=geo[G_P0], rx=geo[G_RX], ry=ry,
                   film=film, Vx=geo[G_VX], Vy=geo[G_VY], Om_x=geo[G_OMX], Om_y=geo[G_OMY],
                   Om_z=geo[G_OMZ], ue=geo[G_UE], tr=ctr, Fd=Fd, u_ball=u_ball,
                   pocket_heat=pocket_heat, contact_heat=ctr.heat, drag_heat=drag_heat,
                   cage_heat=cage_heat, guide_heat=guide_heat,
                   inner_churn_heat=inner_torque * wi, shaft_torque=shaft,
                   pocket_sliding=pocket[:, P_WN], Fc=pocket[:, P_FC],
                   rolling_force=rr_force, rolling_heat=rr_heat)
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
            # the drag model called with a float (~14 -> ~5 us per new cage speed
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
            t = new._cage_torques(float(G[2]))
            R, Gc, G0, nrm = _rescaled_residual(R, Gc, self.F_s / new.F_s, new._g0a,
                                                new._g0r, -(t[0] + t[1]) / new.T_s)
            new._last = (X, G, (R, Gc, G0), details, nrm, fields)
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
