"""Result of the ball skidding solver: the converged state, its heat and kinematic state.

One job: build :class:`BallSkiddingResult` from a converged solution of
:class:`~thermobearing.skidding.ball_residual.ball_residual_system` (:func:`_result`: CSR,
contact angles, heat by component, the lazily built
:class:`~thermobearing.state.KinematicState` for the heat sources) and the reference line
CSR_th of paper 002 (:func:`theoretical_csr`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np

from ..loads import ROUND_OFF_LOAD, ball_arcs, ball_load_distribution
from .ball_residual import (
    C_RR,
    G_ALPHA,
    G_NA,
    G_NR,
    G_OMZ,
    G_Q,
    G_UE,
    G_VX,
    G_VY,
    _energy_audit,
    _rolling_audit,
    ball_residual_system,
)

__all__ = ["BallSkiddingResult", "theoretical_csr"]

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
    unknowns : (X, G), the solver's per-ball and global unknowns (warm starts).
    extra : solver details (evaluations, fallback used, residual vector, operating contact
        angles, the traction law, the system).
    kinematic_state : :class:`thermobearing.state.KinematicState` for the heat sources (built
        on first access: its validation costs more than a warm-started solve).

    Properties: ``slip`` = 1 - CSR/CSR_th [-]; ``orbital_speed`` (Z,) [rad/s] (the balls
    orbit with the cage in steady state); ``element_speeds`` (Z,) = ``spin_speed``, each
    ball's angular speed about its own axis relative to the cage [rad/s] (the common
    skidding-result name, as the roller result's alias of its roller speeds).
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
        """(Z,) orbital speed of the balls [rad/s]: the cage speed (steady state)."""
        return np.full(self.ball_x.shape, self.cage_speed)

    @property
    def element_speeds(self) -> np.ndarray:
        """(Z,) angular speed of each ball about its own axis relative to the cage [rad/s]
        (``spin_speed``; the common skidding-result name)."""
        return self.spin_speed


@functools.lru_cache(maxsize=16)
def _race_names_cached(inner: tuple) -> tuple:
    names = []
    for k, inn in enumerate(inner):
        race = "inner" if inn else "outer"
        nth = sum(1 for j in range(k) if inner[j] == inn)
        names.append(race if nth == 0 else f"{race}_{nth + 1}")
    return tuple(names)


def _race_names(inner: np.ndarray) -> list:
    """Contact-set names per arc: inner, inner_2, outer, outer_2 ... (cached per layout)."""
    return list(_race_names_cached(tuple(bool(v) for v in inner)))


@numba.njit(cache=True)
def _summary(Q: np.ndarray, alpha: np.ndarray, inner_f: np.ndarray, a0: float,
             X: np.ndarray, contact_heat: np.ndarray, round_off: float) -> tuple:
    """Compiled summary of a converged state: per ball the load-weighted |contact angle| of
    the inner and of the outer arcs [rad] (a0 where a ring is unloaded, an arc loaded by
    round-off -- at most ``round_off`` (``loads.ROUND_OFF_LOAD``) of the largest load --
    counting as unloaded, as :func:`thermobearing.loads.ring_weighted_angle`), their means
    weighted by the inner-ring load over the balls that touch the inner ring (a0 if none),
    per ball the spin magnitude |Omega| [rad/s], attitude beta = atan2(Omega_r, -Omega_a)
    and yaw atan2(Omega_t, |(Omega_a, Omega_r)|) [rad], and the raceway heat per arc summed
    over the balls [W]."""
    nz, nk = Q.shape
    ai, ao = np.empty(nz), np.empty(nz)
    spin, beta, yaw = np.empty(nz), np.empty(nz), np.empty(nz)
    per_arc = np.zeros(nk)
    q_max = 0.0
    for j in range(nz):
        for k in range(nk):
            q_max = max(q_max, Q[j, k])
    q_floor = round_off * q_max
    wsum = wai = wao = 0.0
    for j in range(nz):
        ti = to = si = so = 0.0
        for k in range(nk):
            per_arc[k] += contact_heat[j, k]
            q = Q[j, k]
            if not q > q_floor:
                continue
            if inner_f[k] == 1.0:
                ti += q
                si += q * abs(alpha[j, k])
            else:
                to += q
                so += q * abs(alpha[j, k])
        ai[j] = si / ti if ti > 0 else a0
        ao[j] = so / to if to > 0 else a0
        if ti > 0:
            wsum += ti
            wai += ti * ai[j]
            wao += ti * ao[j]
        oa, orr, ot = X[j, 2], X[j, 3], X[j, 4]
        spin[j] = math.sqrt(oa * oa + orr * orr + ot * ot)
        beta[j] = math.atan2(orr, -oa)
        yaw[j] = math.atan2(ot, math.hypot(oa, orr))
    if wsum > 0:
        ai_m, ao_m = wai / wsum, wao / wsum
    else:
        ai_m = ao_m = a0
    return ai, ao, ai_m, ao_m, spin, beta, yaw, per_arc


@numba.njit(cache=True)
def _result_kernel(X: np.ndarray, wc: float, geo: np.ndarray, tr: np.ndarray,
                   pocket: np.ndarray, Fd: np.ndarray, inner_f: np.ndarray, a0: float,
                   gamma: float, round_off: float) -> tuple:
    """The numbers of a result in one compiled call (was :func:`_summary` and
    ``ball_residual._energy_audit`` through the details dict): the summary of
    :func:`_summary`, the raceway heat summed over all / inner / outer arcs [W], the pocket
    and drag heat summed over the balls [W] and the balls' torque on the inner ring [N m] of
    :func:`~thermobearing.skidding.ball_residual._energy_audit`, and the pure-rolling CSR at
    the load-weighted operating angles (1 - gamma cos a_i) / (1 + cos(a_i - a_o)) (primer
    over-skidding section 5) [-]. geo (N_GEO, Z, k), tr (Z, k, 6), pocket (Z, N_POCKET).
    First fills geo's contact-angle row alpha = atan2(n_a, |n_r|) [rad] (as
    ``ball_residual_kernels._contact_angles``; the residual leaves it empty)."""
    for j in range(geo.shape[1]):
        for k in range(geo.shape[2]):
            geo[G_ALPHA, j, k] = math.atan2(geo[G_NA, j, k], abs(geo[G_NR, j, k]))
    ai, ao, ai_m, ao_m, spin, beta, yaw, per_arc = _summary(
        geo[G_Q], geo[G_ALPHA], inner_f, a0, X, tr[:, :, 5], round_off)
    pocket_heat, drag_heat, shaft = _energy_audit(X, wc, geo, tr, pocket, Fd, inner_f)
    race = race_in = race_out = 0.0
    for k in range(per_arc.size):
        race += per_arc[k]
        race_in += per_arc[k] * inner_f[k]
        race_out += per_arc[k] * (1.0 - inner_f[k])
    kin = (1.0 - gamma * math.cos(ai_m)) / (1.0 + math.cos(ai_m - ao_m))
    return (ai, ao, spin, beta, yaw, race, race_in, race_out, pocket_heat.sum(),
            drag_heat.sum(), shaft, kin)


def _result(system: ball_residual_system, X, G, nrm, iters, wall, theoretical_reference):
    """:class:`BallSkiddingResult` of the converged state (X, G) of ``system`` (its fields
    from the memo of the last evaluation when (X, G) is that state). Heat by component
    [W]: raceway (inner / outer arcs), ball-pocket (paper 002 eq. 19), ball drag (eq. 10),
    cage churning (eq. 15), cage guide (eq. 5), inner-ring churning (eq. 17); the shaft torque
    is the balls' torque on the inner ring plus the ring's churning (and the guide land's
    reaction when the land is on the inner ring)."""
    got = system.last_fields(X, G)
    R, Gc, G0, fields = got if got is not None else system.evaluate_fields(X, G)
    geo, tr, pocket, Fd = fields[0], fields[1], fields[2], fields[3]
    b = system.bearing
    wi, wc = system.speed, float(G[2])
    csr = wc / wi
    (ai, ao, spin, beta, yaw, race, race_in, race_out, pocket_heat, drag_heat, shaft_balls,
     kin) = _result_kernel(X, wc, geo, tr, pocket, np.asarray(Fd, dtype=float),
                           system.inner_f, float(b.contact_angle),
                           float(b.ball_diameter / b.pitch_diameter), ROUND_OFF_LOAD)
    if theoretical_reference is None:
        theoretical_reference = theoretical_csr(b, system.Fr, system.Fa, system.Z)
    th = float(theoretical_reference)
    t_churn, t_guide, wg = system._cage_torques(wc)[:3]
    inner_torque = system._inner_torque()
    if system.models.guide_on_inner_ring:
        inner_torque += t_guide       # the land's reaction on the inner ring
    heat = {"raceway": race, "raceway_inner": race_in, "raceway_outer": race_out,
            "ball_pocket": pocket_heat, "ball_drag": drag_heat, "cage": t_churn * wc,
            "cage_guide": t_guide * (wc - wg), "inner_ring_churning": inner_torque * wi}
    heat["total"] = (race + pocket_heat + drag_heat + heat["cage"] + heat["cage_guide"]
                     + heat["inner_ring_churning"])
    if system.rolling:
        # EHL rolling resistance (BallModels.rolling_resistance): the heat of the film's
        # Poiseuille shear per arc and the torque the shaft supplies against it on the
        # inner race (ball_residual_kernels._rolling_audit)
        _, rr_heat, rr_shaft = _rolling_audit(X, geo, system._arc, system._c)
        per_arc = rr_heat.sum(axis=0)
        heat["rolling_resistance"] = float(per_arc.sum())
        heat["rolling_resistance_inner"] = float(per_arc[system.inner].sum())
        heat["rolling_resistance_outer"] = float(per_arc[~system.inner].sum())
        heat["total"] += heat["rolling_resistance"]
        shaft_balls += rr_shaft
    names = system.__dict__.get("_race_names")
    if names is None:
        names = system._race_names = _race_names(system.inner)

    def build_state():
        return _kinematic_state(system, X, system._details(X, G, *fields), names, heat)

    return BallSkiddingResult(
        cage_speed_ratio=csr, theoretical_cage_speed_ratio=th,
        kinematic_cage_speed_ratio=kin, over_skid=csr / th - 1.0, converged=True,
        residual_norm=float(nrm), iterations=int(iters), wall_time=float(wall), inner_speed=wi,
        cage_speed=wc, ball_x=X[:, 0].copy(), ball_r=X[:, 1].copy(), delta_a=float(G[0]),
        delta_r=float(G[1]), spin=X[:, 2:5].copy(), spin_speed=spin, attitude_angle=beta,
        yaw_angle=yaw, pocket_force=X[:, 5].copy(), normal_load=geo[G_Q],
        contact_angle=geo[G_ALPHA], ring=system.arcs.ring, sliding_speed=geo[G_VY],
        transverse_sliding_speed=geo[G_VX], spin_speed_contact=geo[G_OMZ],
        entrainment_speed=geo[G_UE], heat=heat, shaft_torque=shaft_balls + inner_torque,
        state_builder=build_state, unknowns=(X, G),
        extra={"n_eval": system.n_eval, "n_jacobian": system.n_jac,
               "inner_contact_angle": ai, "outer_contact_angle": ao,
               "race_names": list(names), "residual": R,
               "traction_law": system.models.traction_law,
               "jacobian": system.last_jacobian, "system": system})


def _kinematic_state(system: ball_residual_system, X, det, names, heat):
    """The :class:`~thermobearing.state.KinematicState` of a converged solution. Each contact
    set carries the tractions the solver integrated (``ContactSet.traction``: the law, the
    quadrature and a ``ContactTraction`` per ball, from the same kernel the raceway heat
    source would call at these fields), so that source does not integrate them again."""
    from ..contact_traction import ContactTraction
    from ..state import ContactSet, KinematicState, PrecomputedTraction

    cf = det["cf"]
    Q = cf.load
    md = system.models
    tr = det["tr"]
    sets = []
    for k, name in enumerate(names):
        pre = PrecomputedTraction(md.traction_law, md.n_major, md.n_minor, ContactTraction(
            tr.transverse_force[:, k], tr.rolling_force[:, k], tr.moment_transverse[:, k],
            tr.moment_rolling[:, k], tr.moment_normal[:, k], tr.heat[:, k]))
        sets.append(ContactSet(
            race=name, normal_load=Q[:, k], semi_major=det["a"][:, k], semi_minor=det["b"][:, k],
            max_pressure=det["p0"][:, k], contact_angle=np.abs(cf.contact_angle[:, k]),
            entrainment_speed=np.abs(det["ue"][:, k]), sliding_speed=det["Vy"][:, k],
            transverse_sliding_speed=det["Vx"][:, k], spin_speed=det["Om_z"][:, k],
            roll_speed=det["Om_x"][:, k], tilt_speed=det["Om_y"][:, k],
            deformed_radius=system.rd[k],
            film_thickness=None if det["film"] is None else np.maximum(det["film"][:, k], 0.0),
            temperature=md.temperature,
            reduced_radius_x=det["rx"][:, k], reduced_radius_y=det["ry"][:, k], traction=pre))
    wc = float(det["wc"])
    return KinematicState(
        inner_speed=system.speed, outer_speed=0.0, cage_speed=wc,
        orbital_speed=np.full(system.Z, wc), element_spin=np.linalg.norm(X[:, 2:5], axis=1),
        contacts=tuple(sets), attitude_angle=np.arctan2(X[:, 3], -X[:, 2]),
        azimuth=system.psi, pocket_normal_force=np.abs(X[:, 5]),
        pocket_sliding_speed=det["pocket_sliding"], element_drag_force=np.abs(det["Fd"]),
        origin="skidding", extras=_state_extras(system, heat, det, names))


def _state_extras(system: ball_residual_system, heat, det, names) -> dict:
    """Extras of the kinematic state: the solver's heat and shaft torque, and with the EHL
    rolling resistance on, its parameters (``rolling_resistance.kernel_parameters``: the
    ``ehl_rolling_resistance`` source takes its bearing-level factor from them) and the
    rolling force F_R the solver balanced per contact set (``raceway_rolling_force``: race
    name -> (Z,) [N]; the source books F_R |u_e| of exactly these forces, against the
    entrainment as the solver applies them, ``ball_residual_kernels._rolling_terms``)."""
    out = {"solver_heat": heat, "shaft_torque": det["shaft_torque"]}
    if system.rolling:
        out["rolling_resistance"] = system._c[C_RR:].copy()
        force = det["rolling_force"]
        out["raceway_rolling_force"] = {name: np.array(force[:, k], dtype=float)
                                        for k, name in enumerate(names)}
    return out


def theoretical_csr(bearing, radial_load, axial_load, n_balls=None) -> float:
    """Paper 002's CSR_th: (1 - gamma cos alpha)/2 at the quasi-static contact angle.

    alpha is the load-weighted inner contact angle of the zero-speed load distribution under
    the same radial and axial load (paper 002 section 4.1: CSR_th follows the contact-angle
    distribution at 1 kN radial load and the applied axial load). Memoised on the exact
    inputs of that distribution (raceway arcs, D, d_m, E', nominal angle, loads, Z: see
    :func:`_theoretical_key`), so a protocol or sweep that revisits a load step does not
    solve it again; the value is the same to the last bit.
    """
    key = _theoretical_key(bearing, radial_load, axial_load, n_balls)
    hit = _CSR_TH_MEMO.get(key)
    if hit is not None:
        return hit
    ld = ball_load_distribution(bearing, radial_load, axial_load, 0.0, n_balls=n_balls)
    w = ld.inner_load
    alpha = (float(np.sum(w * ld.inner_contact_angle) / np.sum(w)) if np.sum(w) > 0
             else float(bearing.contact_angle))
    g = bearing.ball_diameter * np.cos(alpha) / bearing.pitch_diameter
    value = float(0.5 * (1.0 - g))
    if len(_CSR_TH_MEMO) >= _CSR_TH_MEMO_SIZE:
        _CSR_TH_MEMO.pop(next(iter(_CSR_TH_MEMO)))      # oldest first
    _CSR_TH_MEMO[key] = value
    return value


# memo of theoretical_csr: a pure function of its key (bounded, oldest entry dropped)
_CSR_TH_MEMO: dict[tuple, float] = {}
_CSR_TH_MEMO_SIZE = 512


def _theoretical_key(bearing, radial_load, axial_load, n_balls) -> tuple:
    """Everything the zero-speed load distribution of :func:`theoretical_csr` depends on:
    the raceway arcs (ring, centres, free distances, conformities; D, d_m/2, E'), the
    nominal contact angle (start and unloaded default), d_m, the loads and Z (at zero speed
    the ball mass and inertia do not enter)."""
    arcs = ball_arcs(bearing)
    return (arcs.ring.tobytes(), arcs.centre_x.tobytes(), arcs.centre_r.tobytes(),
            arcs.free_distance.tobytes(), arcs.conformity.tobytes(), arcs.ball_diameter,
            arcs.pitch_radius, arcs.effective_modulus, float(bearing.contact_angle),
            float(bearing.ball_diameter), float(bearing.pitch_diameter), float(radial_load),
            float(axial_load), int(n_balls or bearing.n_balls))


def _refresh_caches() -> None:
    """numba's cache does not see edits of compiled callees in other files: the result kernel
    compiles ``ball_residual_kernels._energy_audit`` into itself (see
    :func:`thermobearing.contact_traction.refresh_stale_caches`)."""
    from ..contact_traction import refresh_stale_caches
    from . import ball_residual_kernels

    refresh_stale_caches("ball_result", (_summary, _result_kernel), (ball_residual_kernels,))


_refresh_caches()
