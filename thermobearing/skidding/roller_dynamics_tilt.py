"""The roller's radial position and tilt in the coupled model (paper 003 eq. 18, 6 DOF).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], eq. 18 moves
each roller in six degrees of freedom. The coupled model
(:mod:`~thermobearing.skidding.roller_dynamics_coupled`) integrates the axial position X, the
skew alpha (rotation about the radial axis y), the pocket position z and the spin; with
``tilt=True`` (:func:`~thermobearing.skidding.roller_dynamics_setup.build_model`) it adds
the radial position y_r and the tilt alpha_e (rotation about the circumferential axis z,
positive turning the roller's +x end outwards) with their speeds. Units: SI.

Forces and moments (cage frame; y_r = 0 where the roller touches the outer raceway without
load, positive outwards)::

    m y_r''     = m omega_c^2 d_m/2 + m_u omega_c^2 d_m/2 + F_cw cos(psi)
                  + sum_k (q_i,k - q_o,k)                                       (eq. 18 y, z)
    J_t alpha_e'' = sum_k x_k (q_i,k - q_o,k) + x_u (F_cw cos(psi) + m_u omega_c^2 d_m/2)
                  + t_q F_rib,x + J_p Omega alpha'                              (eq. 18 tilt)
    J_t alpha''  += -J_p Omega alpha_e'                                         (gyroscopic)

(the equations above write the unbalance's radial force as F_cw cos(psi) in the paper's
form; its sign in this model's phase convention is below.)

* raceway slices (:func:`raceway_slices`): the effective length L_e cut into n slices of
  width w at x_k; outer approach d_o,k = y_r + alpha_e x_k - c(x_k), inner approach
  d_i,k = -(y_r + alpha_e x_k) - g_i(phi) - c(x_k), c the roller's crown drop
  (:func:`thermobearing.hertz.crown_drop`; 0 for the straight roller), each slice
  q = (w/L_e) K_l(L_e) d^(10/9) (Palmgren's line contact, :func:`thermobearing.hertz.
  line_contact_stiffness`; the slicing of :func:`thermobearing.hertz.sliced_roller_contact`).
  g_i(phi) = P_d/2 - delta_r cos(phi) is the inner gap of the prescribed ring at the
  roller's azimuth: delta_r and P_d/2 solved from the quasi-static solution's total approach
  delta_o(Q_o) + delta_i(Q_i) at its two most loaded azimuths (:func:`tilt_parameters`),
  so a roller at rest in the load zone carries the quasi-static loads.
* raceway squeeze film: a slice whose gap closes (d' > 0) is opposed by the line
  contact's Reynolds squeeze film (:mod:`~thermobearing.skidding.roller_dynamics_raceway_film`,
  [hamrock2004]: w' = 3 sqrt(2) pi eta (R_x/h)^(3/2) h' per unit length) with the contact's
  own R_x (D/2 with the race's radius) at h = max(-d, h_c), h_c the rolling contact's
  central film thickness of that race (``DynamicsModel.raceway_film``; without it the cage
  bars' film floor ``squeeze_floor``, the estimate before session 24); an opening gap
  cavitates. It is the only normal damping of the raceway contacts (elastic Hertz slices
  otherwise): without it an unloaded roller rattles in the radial play (validation case
  SOURCE.md, "Tilt and radial play"; ``raceway_squeeze`` False: undamped).
* unbalance: the spinning mass's force F_cw = m_u e_u Omega^2 (Omega = omega_c - omega_r,
  the spin in the inertial frame) has the radial part -F_cw cos(psi) at x_u; its orbital
  force m_u omega_c^2 d_m/2 acts at x_u too (paper 003 eq. 18: x_u F_cw cos psi and x_u F_cv,
  the tilt moments the previous model did not integrate). The sign: the coupled model's
  phase psi advances at +omega_r with the circumferential force F_cw sin(psi)
  (:mod:`~thermobearing.skidding.roller_dynamics_rhs`), while the roller turns about -x
  (rolling sense: the surface at the inner raceway moves along +z); the mass's physical
  angle from +y towards +z is then pi - psi, which keeps the circumferential force and
  puts the mass at y = -e_u cos(psi): the force vector turns with the roller.
* rib: the tilt moves the end-face contact point (rho = R_s sin theta_f below the roller
  axis) axially; for the paper's sphere the support function along the rib normal changes
  by side sin(theta_f) (R_s - L_r/2) alpha_e to first order (sphere centres at
  x = -+(R_s - L_r/2) move radially by -+(R_s - L_r/2) alpha_e), i.e. the tilt acts on both
  faces as the axial shift t_q alpha_e, t_q = tan(theta_f)(R_s - L_r/2) (1.555 mm/rad at
  the base case). Paper 003 eq. 1 has no term linear in the tilt (eq. 11 only moves
  H_contact). The faces are therefore evaluated at X + t_q alpha_e, X' + t_q alpha_e'
  (:func:`~thermobearing.skidding.roller_dynamics_rhs._rhs_ring`), and by virtual work the
  rib's axial force F_rib,x (normal + friction) acts on the tilt with t_q F_rib,x. To
  second order the sphere's support grows on both faces by cos(theta_f)(R_s - L_r/2)
  (1 - cos alpha_e) (the centres' x = -+(R_s - L_r/2) cos alpha_e; the tilt's counterpart of
  eq. 1's skew term, 0.15 um at 1e-3 rad, 1.3 um at 3e-3 rad): the faces see the clearance
  less that (:func:`tilt_clearance`, ``dca`` of :func:`thermobearing.rib.face_values`): each
  face's contact point moves towards its rib by (R_s - L_r/2)(1 - cos alpha_e), at the rate
  the face kernel then takes as part of its axial speed, and by virtual work each face's
  axial force F_x,K acts on the tilt with the arm K (R_s - L_r/2) sin alpha_e (K = -+1; its
  normal part -Q_K cos(theta_f)(R_s - L_r/2) sin alpha_e restores the tilt). The exact
  tilted sphere's support (centre (x_0 cos alpha_e cos alpha, x_0 sin alpha_e, -x_0 cos
  alpha_e sin alpha)) differs from this by the cone's curvature (the linear term times
  cos phi, 0.5 % at the rib skew) and fourth-order terms. The rib faces'
  power balance is that of the face kernel in these coordinates (the normal force's work on
  the tilt is Q d delta/dt's tilt part).
  Eq. 4's C_af = (H_rollercm - D_w/2) tan theta_f (the radial position's effect on the
  approach, ~0.2 um in the unloaded zone) and eq. 11's tilt term in H_contact are left
  out (measured: no change beyond the scatter, SOURCE.md). Left out with them, to keep
  the faces' energy bookkeeping closed: the rib forces' radial components on y_r (the
  normal force's Q sin theta_f, 1.6 N at a 300 N impact, and the friction's radial part
  at the skew-offset point, up to mu Q = 15 N) and the moment of that radial friction
  about the tilt axis (arm ~L_r/2: <= 0.045 N m against the normal force's ~R_s
  sin(theta_f) Q = 0.47 N m): the face kernel's kinematics carry neither y_r' nor the
  contact point's radial speed from the tilt rate.
* gyroscopic coupling of a spinning symmetric body (Euler's equations): with the spin
  angular momentum J_p Omega along the roller axis e_1 ~ (1, alpha_e, -alpha), dH/dt =
  J_p Omega (alpha_e' y - alpha' z) + J_t (alpha'' y + alpha_e'' z) = M, so
  J_t alpha'' = M_y - J_p Omega alpha_e' and J_t alpha_e'' = M_z + J_p Omega alpha' (energy
  neutral). The cage frame's own turn adds -J_p Omega omega_c (alpha, alpha_e) to the two
  moments, ~1e-4 N m/rad x 5e-3 rad at the base case (against the unbalance's 0.1 N m):
  left out.
* traction: the raceway tractions stay on the quasi-static loads per azimuth (the table),
  as without tilt.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit

from ..errors import InputError
from ..hertz import crown_drop, line_contact_stiffness
from .roller_dynamics_raceway_film import line_squeeze_coefficient

#: slices of the raceway line contacts along the roller (odd: one at the middle)
TILT_SLICES = 15

# indices of the tilt parameter vector (tilt_parameters; TP_FLOOR / TP_FLOOR_I the outer /
# inner squeeze film's smallest gap); then n slice centres x_k [m] and n crown drops c(x_k) [m]
(TP_JT, TP_MASS, TP_JP, TP_TQ, TP_XU, TP_MUE, TP_MU, TP_DM2, TP_KS, TP_CO, TP_CI, TP_FLOOR,
 TP_RH, TP_N, TP_FLOOR_I, TP_HEAD) = range(16)

#: states per roller of the tilt block: y_r, y_r', alpha_e, alpha_e'
N_TILT_STATES = 4


def _palmgren_approach(load: float, k_l: float) -> float:
    """Approach d [m] of the straight slice law at total load ``load`` [N] (d = (Q/K_l)^0.9)."""
    return (max(load, 0.0) / k_l) ** 0.9


def tilt_parameters(m: Any, bearing: Any, n_slices: int = TILT_SLICES
                    ) -> tuple[np.ndarray, np.ndarray]:
    """(tilt parameter vector, inner gap g_i [m] at ``m.azimuth`` + the wrap) of the
    :class:`~thermobearing.skidding.roller_dynamics_model.DynamicsModel` ``m`` (module
    notes). The gap comes from the quasi-static solution's loads at its two most loaded
    distinct azimuths: delta_o(Q_o) + delta_i(Q_i) = delta_r cos(phi) - P_d/2 (with fewer
    loaded azimuths P_d is the bearing's ``diametral_clearance`` and delta_r follows from the
    loaded one, 0 without)."""
    if isinstance(n_slices, bool) or not isinstance(n_slices, int) or n_slices < 3:
        raise InputError("n_slices", n_slices, "an integer >= 3")
    g = m.geom
    le = float(m.effective_length)
    w = le / n_slices
    xs = (np.arange(n_slices) + 0.5) * w - 0.5 * le
    crown = getattr(bearing, "crown_radius", None)
    drop = np.zeros(n_slices) if crown is None else np.asarray(crown_drop(xs, 0.0, crown))
    k_l = float(line_contact_stiffness(le))
    r = 0.5 * g.roller_diameter
    ri = 0.5 * g.inner_raceway_diameter
    ro = 0.5 * m.outer_raceway_diameter
    rx_i = r * ri / (ri + r)
    rx_o = r * ro / (ro - r)
    # squeeze film of the slices: c'(h) = c'(1 m) h^-1.5 per unit length
    # (line_squeeze_coefficient), times the slice width w; the kernel divides by h^1.5
    squeeze = bool(getattr(m, "raceway_squeeze", True))
    film = getattr(m, "raceway_film", None)
    floor_o, floor_i = ((m.squeeze_floor, m.squeeze_floor) if film is None
                        else (float(film[0]), float(film[1])))
    tp = np.zeros(TP_HEAD + 2 * n_slices)
    tp[TP_JT] = m.transverse_inertia
    tp[TP_MASS] = m.roller_mass
    tp[TP_JP] = m.polar_inertia
    tp[TP_TQ] = math.tan(g.rib_angle) * (g.crown_radius - 0.5 * g.roller_length)
    tp[TP_XU] = m.unbalance.axial_position
    tp[TP_MUE] = m.unbalance.mass * m.unbalance.radius
    tp[TP_MU] = m.unbalance.mass
    tp[TP_DM2] = 0.5 * g.pitch_diameter
    tp[TP_KS] = k_l * w / le
    tp[TP_CO] = w * line_squeeze_coefficient(m.pocket_viscosity, rx_o, 1.0) if squeeze else 0.0
    tp[TP_CI] = w * line_squeeze_coefficient(m.pocket_viscosity, rx_i, 1.0) if squeeze else 0.0
    tp[TP_FLOOR] = floor_o
    tp[TP_FLOOR_I] = floor_i
    tp[TP_RH] = g.crown_radius - 0.5 * g.roller_length
    tp[TP_N] = n_slices
    tp[TP_HEAD:TP_HEAD + n_slices] = xs
    tp[TP_HEAD + n_slices:] = drop
    approach = np.array([_palmgren_approach(qo, k_l) + _palmgren_approach(qi, k_l)
                         for qi, qo in zip(m.inner_load, m.outer_load, strict=True)])
    order = np.argsort(-np.asarray(m.inner_load, float), kind="stable")
    i0 = int(order[0])
    i1 = next((int(i) for i in order[1:]
               if abs(math.cos(m.azimuth[i]) - math.cos(m.azimuth[i0])) > 1e-9
               and m.inner_load[i] > 0.0), None)
    c0 = math.cos(m.azimuth[i0])
    if m.inner_load[i0] > 0.0 and i1 is not None:
        c1 = math.cos(m.azimuth[i1])
        delta_r = (approach[i0] - approach[i1]) / (c0 - c1)
        half_play = delta_r * c0 - approach[i0]
    else:
        # fewer than two loaded azimuths: the bearing's radial play, the ring's shift from
        # the one loaded roller (none: centred)
        half_play = 0.5 * float(bearing.diametral_clearance)
        delta_r = ((approach[i0] + half_play) / c0
                   if m.inner_load[i0] > 0.0 and c0 > 0.0 else 0.0)
    gap = half_play - delta_r * np.cos(m.azimuth)
    return tp, np.append(gap, gap[0])


def start_states(m: Any, tp: np.ndarray, gap: np.ndarray) -> np.ndarray:
    """(Z, 4) start of the tilt block: y_r at the quasi-static outer load's approach
    (the roller resting on the outer raceway), no tilt, at rest."""
    k_l = tp[TP_KS] * tp[TP_N]
    out = np.zeros((len(m.azimuth), N_TILT_STATES))
    for j, qo in enumerate(m.outer_load):
        out[j, 0] = _palmgren_approach(float(qo), k_l)
    return out


@njit(cache=True)
def raceway_slices(tp: np.ndarray, yr: float, yrd: float, ae: float, aed: float,
                   gap: float) -> tuple[float, float, float, float]:
    """(radial force on the roller [N, + outwards], its tilt moment about z [N m], outer and
    inner raceway loads [N]) of the sliced line contacts (module notes): elastic slices
    q = k_s d^(10/9) plus the squeeze film of a closing gap, at radial position ``yr`` [m]
    and speed ``yrd`` [m/s], tilt ``ae`` [rad] and rate ``aed`` [rad/s], inner gap ``gap``
    [m]. Slice k at x_k: outer approach yr + ae x_k - c_k, inner -(yr + ae x_k) - gap - c_k;
    a slice's force acts at x_k, so the tilt moment is sum x_k (q_i - q_o)."""
    n = int(tp[TP_N])
    ks = tp[TP_KS]
    floor_o = tp[TP_FLOOR]
    floor_i = tp[TP_FLOOR_I]
    f = 0.0
    mt = 0.0
    n_o = 0.0
    n_i = 0.0
    for k in range(n):
        x = tp[TP_HEAD + k]
        c = tp[TP_HEAD + n + k]
        u = yr + ae * x
        v = yrd + aed * x
        d_o = u - c
        d_i = -u - gap - c
        q_o = ks * d_o ** (10.0 / 9.0) if d_o > 0.0 else 0.0
        q_i = ks * d_i ** (10.0 / 9.0) if d_i > 0.0 else 0.0
        n_o += q_o
        n_i += q_i
        if v > 0.0:        # outer gap closing
            q_o += tp[TP_CO] * v / max(-d_o, floor_o) ** 1.5
        elif v < 0.0:      # inner gap closing
            q_i -= tp[TP_CI] * v / max(-d_i, floor_i) ** 1.5
        f += q_i - q_o
        mt += x * (q_i - q_o)
    return f, mt, n_o, n_i


@njit(cache=True)
def tilt_clearance(tp: np.ndarray, ae: float, aed: float) -> tuple[float, float]:
    """The tilt's symmetric share of both faces' approach over cos(theta_f) [m],
    (R_s - L_r/2)(1 - cos alpha_e) at tilt ``ae`` [rad] (module notes: the sphere's
    second-order term, the tilt's counterpart of eq. 1's skew term), and its rate [m/s] at
    the tilt rate ``aed`` [rad/s]: each face's contact point moves towards its rib by it."""
    return tp[TP_RH] * (1.0 - math.cos(ae)), tp[TP_RH] * math.sin(ae) * aed


@njit(cache=True)
def tilt_rates(tp: np.ndarray, yr: float, yrd: float, ae: float, aed: float, gap: float,
               f_rib: float, f_rib_diff: float, psi: float, spin: float, wc: float,
               skew_rate: float) -> tuple[float, float, float]:
    """(y_r'' [m/s^2], alpha_e'' [rad/s^2], gyroscopic skew acceleration [rad/s^2]) of one
    roller (module notes): raceway slices (:func:`raceway_slices`), centrifugal force of
    roller and unbalance mass at the cage speed ``wc`` [rad/s], the unbalance's spinning
    force at phase ``psi`` [rad] and spin ``spin`` [rad/s] (rolling sense, cage frame), the
    rib's axial force ``f_rib`` [N] on the tilt (arm t_q) and, through the approach's
    second-order term (:func:`tilt_clearance`), the right face's axial force minus the left
    face's ``f_rib_diff`` [N] with the arm (R_s - L_r/2) sin alpha_e (each face's contact
    point moves towards its rib: virtual work), and the gyroscopic coupling with
    the skew rate ``skew_rate`` [rad/s]; the third entry is added to the skew's alpha''."""
    f_s, m_s, _, _ = raceway_slices(tp, yr, yrd, ae, aed, gap)
    omega = wc - spin                               # spin in the inertial frame
    f_cw = -tp[TP_MUE] * omega * omega * math.cos(psi)
    f_orb = tp[TP_MU] * wc * wc * tp[TP_DM2]
    f_cent = tp[TP_MASS] * wc * wc * tp[TP_DM2]
    gyro = tp[TP_JP] * omega
    ydd = (f_cent + f_orb + f_cw + f_s) / tp[TP_MASS]
    m_rib = tp[TP_TQ] * f_rib + f_rib_diff * tp[TP_RH] * math.sin(ae)
    edd = (m_s + tp[TP_XU] * (f_cw + f_orb) + m_rib + gyro * skew_rate) / tp[TP_JT]
    return ydd, edd, -gyro * aed / tp[TP_JT]


def _refresh_caches() -> None:
    """Flush the kernels' numba caches when roller_dynamics_pocket (imported constant)
    changed (:func:`thermobearing.contact_traction.refresh_stale_caches`)."""
    from ..contact_traction import refresh_stale_caches
    from . import roller_dynamics_pocket

    refresh_stale_caches("roller_dynamics_tilt", (raceway_slices, tilt_clearance, tilt_rates),
                         (roller_dynamics_pocket,))


_refresh_caches()
