"""Compiled kernels of the coupled all-roller + cage integration (paper 003 eqs. 18-19):
the state derivative (:func:`_deriv_into`), the traction linearisation from the table
(:func:`_refresh_from_table`, :func:`_refresh_roller`), the stiff linear part of the ETDRK4
step (:func:`_stiff_rates`) and the time loop (:func:`_integrate`). The model, the
integrator's measurements and the Python driver are in
:mod:`~thermobearing.skidding.roller_dynamics_coupled` (module notes there). Units: SI.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .roller_dynamics_etd import set_coefficients
from .roller_dynamics_pocket import pocket_force_z
from .roller_dynamics_rhs import _CP, _ETA, _FLOOR, _HL, _JT, _KC, _MASS, _PDOF, _rhs_ring
from .roller_dynamics_table import table_eval_contacts
from .roller_dynamics_tilt import N_TILT_STATES, TP_TQ, tilt_clearance, tilt_rates

#: roller states per roller in the coupled model: X, X', alpha, alpha', z, z', psi, omega
N_ROLLER_STATES = 8


@njit(cache=True)
def _pocket_film_friction(force: float, spin: float, radius: float, length: float,
                          eta: float, clearance: float, k_w: float, k_cq: float,
                          smoothing: float) -> float:
    """Paper 000 eqs. 37-38 pocket-film friction [N], the formula of
    :func:`thermobearing.skidding.roller_fluid.pocket_forces` (tested equal)."""
    fn = math.sqrt(force * force + smoothing * smoothing)
    u = abs(spin) * radius
    inv_h = fn / (k_w * eta * max(u, 1e-9) * radius * length) + 1.0 / clearance
    return k_cq * eta * u * length * math.sqrt(radius * inv_h)


@njit(cache=True)
def pocket_damping(shear_spin_slope: float, half: float) -> float:
    """Raceway damping c_z [N s/m] of a roller's circumferential (pocket) speed z' from the
    spin slope dS/d omega [N s/rad] of the raceway shear S [N] (S = S_i + S_o, paper 000
    eqs. 22-31) and the roller radius ``half`` = D/2 [m]: c_z = max(-(dS/d omega)/(D/2), 0).

    Paper 003 eq. 18 puts the same raceway tractions T^i, T^o [N] in the roller's
    circumferential translation (lines 2-3) and, times D_w/2, in its spin (line 4). Each is
    a function of its contact's sliding speed V = u_race - u_roller [m/s]: a spin change
    d omega moves the roller surface by (D/2) d omega at both contacts, so dS/d omega =
    (D/2) (dT^i/du + dT^o/du); a translation z' of the roller centre moves it by +z' along
    the inner and -z' along the outer race velocity, so the net orbital force F_d = T^i -
    T^o changes by dF_d/dz' = dT^i/du + dT^o/du = (dS/d omega)/(D/2) [N s/m]. The same
    c_z as the reduced model's k_omega/(D/2)^2
    (:meth:`~thermobearing.skidding.roller_dynamics_model.DynamicsModel.circumferential_damping`,
    k_omega = -(D/2) dS/d omega). The rolling (film-pressure) share of F_d, whose slope
    the shear's does not carry, is left out: measured at paper 003's base case it lowers
    -dF_d/dz' by 0.8 / 1.0 / 2.7 % at N_i = 777 / 691 / 445 N and by 20 % for the unloaded
    rollers (0.046 against 0.057 N s/m). A slope that would drive the motion
    (dS/d omega > 0) gives 0. Before 2026-11-23 the coupled model used -dS/d omega itself
    (N s/rad taken as N s/m, 1/333 of this for the 6 mm roller)."""
    return max(-shear_spin_slope / half, 0.0)


@njit(cache=True)
def spin_pocket_coupling(shear_spin_slope: float, outer_shear_spin_slope: float,
                         half: float) -> float:
    """dS/dz' [N s/m]: the change of the raceway shear S = S_i + S_o [N] on the roller
    surface (paper 000 eqs. 22-31; paper 003 eq. 18 line 4, T^i + T^o) with the roller's
    pocket speed z' [m/s], from the spin slopes dS/d omega and dS_o/d omega [N s/rad] and
    the roller radius ``half`` = D/2 [m]:

        dS/dz' = (dS_i/d omega - dS_o/d omega) / (D/2),  dS_i/d omega = dS/d omega - dS_o/d omega.

    Each contact's shear is a function of its sliding speed V = u_race - u_roller. A spin
    change d omega lowers both V_i and V_o by (D/2) d omega; a pocket speed z' (the roller
    centre moving along +z, the inner race's direction relative to the cage) lowers V_i by
    z' and raises V_o by z' (the reasoning of :func:`pocket_damping`). So the spin feels z'
    through the *difference* of the two contacts' slopes (zero only where they are equal),
    which the summed shear cannot give: the outer shear is a column of its own in the table
    (:data:`~thermobearing.skidding.roller_dynamics_table.T_SHEAR_OUTER`). It is the
    reciprocal of the orbital force's spin slope, dF_d/d omega = dS_i/d omega - dS_o/d omega
    (F_d = T^i - T^o), up to F_d's film-pressure share (which the shear columns do not
    carry: 2 % for the most loaded roller, 20 % for the unloaded ones at the base case,
    so dF_d/d omega is not used for it). Measured at paper 003's base case
    (MIL-PRF-23699, 80 degC, 3 kN): -0.30 N s/m for the most loaded roller at 30000 r/min
    (the shear at z' = 0.5 m/s: paper 000's model 0.329 N, held 0.469 N, with this term
    0.318 N), -1.91 N s/m at 10000 r/min (z' = 0.5 m/s: 0.128 -> -0.760 N; this term gives
    -0.825 N). Before 2026-11-23 (evening) the spin equation held S at z' = 0."""
    return (shear_spin_slope - 2.0 * outer_shear_spin_slope) / half


@njit(cache=True)
def unbalance_axial_shift(unb: np.ndarray, a: float, ad: float, psi: float, w: float
                          ) -> tuple[float, float, float, float]:
    """Axial offset of a roller's geometric centre from the centre of mass of roller + its
    unbalance mass, relative to the unskewed roller, and the offset's rate:
    (k (r_x - x_u) [m], k r_x' [m/s], r_z [m], dr_x/dpsi [m]) with ``unb`` = (k = m_u/(m +
    m_u), e_u [m], x_u [m], m_u [kg]), skew ``a`` [rad], skew rate ``ad`` [rad/s], unbalance
    phase ``psi`` [rad] and its rate ``w`` [rad/s].

    Paper 003 eq. 18 line 1 (m x'' = Q^X - F_cwx + ...): the unbalance mass's inertial force
    along the bearing axis. The mass sits at (x_u, e_u cos psi, e_u sin psi) in roller axes
    (its circumferential offset e_u sin psi is the one whose centrifugal force the skew and
    pocket equations carry, roller_dynamics_rhs), i.e. in the cage frame at
    r_x = x_u cos a + e_u sin(psi) sin a, r_z = -x_u sin a + e_u sin(psi) cos a (skew a rotation
    about the radial axis, rib.py's frame). The cage frame turns about the bearing axis, so its
    inertial forces have no axial part and the axial momentum of roller + mass is exact:
    (m + m_u) X_c'' = F_x with X_c = X_G + k (r_x - x_u); the contacts act at the geometric
    centre X_G. The same forces F_x (rib, raceway axial traction) then act on the skew with
    the arm of the centre of mass, -k r_z F_x (dr_x/da = r_z), and on the spin phase with
    -k (dr_x/dpsi) F_x (virtual work of F_x on X_G). ``unb`` all zeros: no unbalance.
    """
    k = unb[0]
    if k == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    e = unb[1]
    xu = unb[2]
    sa = math.sin(a)
    ca = math.cos(a)
    sp = math.sin(psi)
    r_x = xu * ca + e * sp * sa
    r_z = -xu * sa + e * sp * ca
    dpsi = e * math.cos(psi) * sa
    return k * (r_x - xu), k * (r_z * ad + dpsi * w), r_z, dpsi


@njit(cache=True)
def _interp_sorted(x: float, xp: np.ndarray, fp: np.ndarray) -> float:
    """np.interp(x, xp, fp) for ascending ``xp`` (binary search; numba's np.interp costs
    ~0.5 us a call, this a few ns); clamped to the end values outside [xp[0], xp[-1]]."""
    n = xp.shape[0]
    if x <= xp[0]:
        return fp[0]
    if x >= xp[n - 1]:
        return fp[n - 1]
    lo = 0
    hi = n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xp[mid] <= x:
            lo = mid
        else:
            hi = mid
    return fp[lo] + (fp[hi] - fp[lo]) * (x - xp[lo]) / (xp[hi] - xp[lo])


@njit(cache=True)
def _deriv_into(p: np.ndarray, y: np.ndarray, dy: np.ndarray, z_n: int, phi0: np.ndarray,
                az: np.ndarray, load: np.ndarray, lin: np.ndarray, w0: np.ndarray,
                wc0: float, q_o: np.ndarray, c_z: np.ndarray, polar: float, cage_j: float,
                half: float, dm_half: float, t_c: float, film: np.ndarray,
                ring_mass: float, land: np.ndarray, unb: np.ndarray, tp: np.ndarray,
                gap: np.ndarray) -> None:
    """dy[:] = time derivative of the coupled state (roller_dynamics_coupled module notes).
    ``lin`` (Z, 7): S0, dS/dw, dS/dwc, F_d0, dF_d/dw, dF_d/dwc, dS/dz' of the last refresh
    (:func:`spin_pocket_coupling`; z' the roller's pocket speed);
    ``c_z`` (Z,): each roller's raceway damping of its pocket speed z' [N s/m]
    (:func:`pocket_damping`);
    ``film``: pocket length, eta, clearance, k_w, k_c + k_q/2, smoothing; ``ring_mass`` [kg]
    of the axially free inner ring (0: held); ``land``: (viscous coefficient [N m s], guide
    ring speed [rad/s]) of the cage-land drag torque k (omega_g - omega_c) (zeros: none);
    ``tp``: the tilt parameters (:func:`~thermobearing.skidding.roller_dynamics_tilt.
    tilt_parameters`; one element: no tilt) and ``gap`` the inner gap [m] at ``az``: the
    rollers' y_r, y_r', alpha_e, alpha_e' follow the ring's X, X' in ``y``."""
    n = N_ROLLER_STATES
    th = y[z_n * n]
    wc = y[z_n * n + 1]
    x_ring = y[z_n * n + 2]
    xd_ring = y[z_n * n + 3]
    torque = -t_c
    f_ring = 0.0
    two_pi = 2.0 * math.pi
    tilt = tp.shape[0] > 1
    tq = tp[TP_TQ] if tilt else 0.0
    for j in range(z_n):
        b = j * n
        w = y[b + 7]
        phi = (phi0[j] + th) % two_pi
        n_i = _interp_sorted(phi, az, load)
        dw = w - w0[j]
        dc = wc - wc0
        s = lin[j, 0] + lin[j, 1] * dw + lin[j, 2] * dc + lin[j, 6] * y[b + 5]
        f_d = lin[j, 3] + lin[j, 4] * dw + lin[j, 5] * dc
        # the unbalance mass's axial excursion (unbalance_axial_shift): y[b], y[b + 1] are the
        # axial position and speed of the roller + mass's centre of mass, the contacts see the
        # geometric centre's
        sh, shd, r_z, dpsi = unbalance_axial_shift(unb, y[b + 2], y[b + 3], y[b + 6], w)
        tb = z_n * n + 4 + N_TILT_STATES * j
        x_t = 0.0
        xd_t = 0.0
        dca = 0.0
        dca_rate = 0.0
        if tilt:
            x_t = tq * y[tb + 2]
            xd_t = tq * y[tb + 3]
            dca, dca_rate = tilt_clearance(tp, y[tb + 2], y[tb + 3])
        r = _rhs_ring(p, y[b] - sh - x_ring, y[b + 1] - shd - xd_ring, y[b + 2], y[b + 3],
                      y[b + 4], y[b + 5], n_i, q_o[j], w, y[b + 6], f_d, c_z[j], xd_ring,
                      x_t, xd_t, dca, dca_rate)
        fz_bar, _, ff, fb = pocket_force_z(y[b + 4], y[b + 5], y[b + 2], p[_HL], p[_CP],
                                           p[_KC], p[_ETA], half, p[_FLOOR])
        f_bar = _pocket_film_friction(ff - fb, w, half, film[0], film[1], film[2], film[3],
                                      film[4], film[5])
        dy[b] = y[b + 1]
        dy[b + 1] = r[1]
        dy[b + 2] = r[2]
        dy[b + 3] = r[3]
        dy[b + 4] = r[4]
        dy[b + 5] = r[5]
        dy[b + 6] = w
        dy[b + 7] = (half * (s - f_bar) + r[6]) / polar
        if unb[0] > 0.0:
            # roller + mass's centre of mass accelerates under the axial force F_x (rib and
            # raceway axial traction, r[1] m); F_x's virtual work on X_G adds its moment
            # about the centre of mass to the skew and a torque to the spin phase
            f_ax = r[1] * p[_MASS]
            dy[b + 1] = f_ax / (p[_MASS] + unb[3])
            dy[b + 3] = r[3] - unb[0] * r_z * f_ax / p[_JT]
            dy[b + 7] = (half * (s - f_bar) + r[6] - unb[0] * dpsi * f_ax) / polar
        if tilt:
            ydd, edd, gyro = tilt_rates(tp, y[tb], y[tb + 1], y[tb + 2], y[tb + 3],
                                        _interp_sorted(phi, az, gap), r[8], r[9], y[b + 6],
                                        w, wc, y[b + 3])
            dy[tb] = y[tb + 1]
            dy[tb + 1] = ydd
            dy[tb + 2] = y[tb + 3]
            dy[tb + 3] = edd
            dy[b + 3] += gyro
        torque += -fz_bar * dm_half - f_bar * half
        f_ring += r[7]
    dy[z_n * n] = wc
    dy[z_n * n + 1] = (torque + land[0] * (land[1] - wc)) / cage_j
    dy[z_n * n + 2] = xd_ring
    dy[z_n * n + 3] = f_ring / ring_mass if ring_mass > 0.0 else 0.0


@njit(cache=True)
def _refresh_from_table(y: np.ndarray, z_n: int, phi0: np.ndarray, az: np.ndarray,
                        load: np.ndarray, spin0: float, spin_step: float, loads: np.ndarray,
                        cage: np.ndarray, values: np.ndarray, lin: np.ndarray,
                        w0: np.ndarray, q_o: np.ndarray, c_z: np.ndarray, half: float
                        ) -> tuple[float, int]:
    """The traction linearisation of every roller from the table (the same value and
    forward-difference slopes as the ``evaluate`` refresh of :func:`simulate_coupled`) and
    its pocket damping c_z [N s/m] (:func:`pocket_damping`, ``half`` = D/2 [m]);
    returns (omega_c of the linearisation, table status: 0 ok, 1-3 outside the grid)."""
    wc0 = y[z_n * N_ROLLER_STATES + 1]
    for j in range(z_n):
        st = _refresh_roller(j, y, z_n, phi0, az, load, spin0, spin_step, loads, cage,
                             values, lin, w0, wc0, q_o, c_z, half)
        if st != 0:
            return wc0, st
    return wc0, 0


@njit(cache=True)
def _refresh_roller(j: int, y: np.ndarray, z_n: int, phi0: np.ndarray, az: np.ndarray,
                    load: np.ndarray, spin0: float, spin_step: float, loads: np.ndarray,
                    cage: np.ndarray, values: np.ndarray, lin: np.ndarray, w0: np.ndarray,
                    wc0: float, q_o: np.ndarray, c_z: np.ndarray, half: float) -> int:
    """Roller ``j``'s row of :func:`_refresh_from_table` at its present spin and azimuth and
    the cage speed ``wc0`` of the linearisation (``half`` = D/2 [m] for its pocket damping
    c_z [N s/m], :func:`pocket_damping`); returns the table status (0 ok)."""
    n = N_ROLLER_STATES
    th = y[z_n * n]
    dc = 1e-4 * max(abs(wc0), 1.0)
    w = y[j * n + 7]
    phi = (phi0[j] + th) % (2.0 * math.pi)
    n_i = _interp_sorted(phi, az, load)
    dw = 1e-4 * max(abs(w), 1.0)
    s0, f0, q0, so0, st0 = table_eval_contacts(spin0, spin_step, loads, cage, values, w,
                                               n_i, wc0)
    s1, f1, _, so1, st1 = table_eval_contacts(spin0, spin_step, loads, cage, values, w + dw,
                                              n_i, wc0)
    s2, f2, _, _, st2 = table_eval_contacts(spin0, spin_step, loads, cage, values, w, n_i,
                                            wc0 + dc)
    st = max(st0, max(st1, st2))
    if st != 0:
        return st
    w0[j] = w
    lin[j, 0] = s0
    lin[j, 1] = (s1 - s0) / dw
    lin[j, 2] = (s2 - s0) / dc
    lin[j, 3] = f0
    lin[j, 4] = (f1 - f0) / dw
    lin[j, 5] = (f2 - f0) / dc
    lin[j, 6] = spin_pocket_coupling(lin[j, 1], (so1 - so0) / dw, half)
    q_o[j] = q0
    c_z[j] = pocket_damping(lin[j, 1], half)
    return 0


@njit(cache=True)
def _stiff_rates(p: np.ndarray, lin: np.ndarray, w0: np.ndarray, c_z: np.ndarray,
                 polar: float, half: float, z_n: int, h: float, lam: np.ndarray,
                 y_ref: np.ndarray, coef: np.ndarray) -> None:
    """The linear part the ETDRK4 step of :func:`_integrate` treats exactly (module notes,
    "Stiff spin"): per roller the spin's relaxation under the linearised raceway shear,
    lam = (D/2) dS/d omega / J_p about y_ref = w0 (the refresh's spin; a positive slope, a
    shear that would drive the spin away, is left to the explicit stages), and the pocket
    speed's raceway damping lam = -c_z / m about 0 (pocket DOF on). Fills ``lam`` [1/s],
    ``y_ref`` and the (n, 6) ETDRK4 coefficients ``coef`` for step ``h`` [s]; every other
    component gets lam = 0 (classical RK4)."""
    for j in range(z_n):
        _stiff_roller(j, p, lin, w0, c_z, polar, half, h, lam, y_ref, coef)
    for q in range(coef.shape[0]):
        if coef[q, 0] == 0.0 and lam[q] == 0.0:
            set_coefficients(coef, q, 0.0, h)


@njit(cache=True)
def _stiff_roller(j: int, p: np.ndarray, lin: np.ndarray, w0: np.ndarray, c_z: np.ndarray,
                  polar: float, half: float, h: float, lam: np.ndarray, y_ref: np.ndarray,
                  coef: np.ndarray) -> None:
    """Roller ``j``'s entries of :func:`_stiff_rates`."""
    b = j * N_ROLLER_STATES
    lam[b + 7] = min(half * lin[j, 1] / polar, 0.0)
    y_ref[b + 7] = w0[j]
    set_coefficients(coef, b + 7, lam[b + 7], h)
    lam[b + 5] = -c_z[j] / p[_MASS] if p[_PDOF] > 0.5 else 0.0
    set_coefficients(coef, b + 5, lam[b + 5], h)


@njit(cache=True)
def _integrate(p: np.ndarray, y: np.ndarray, t: float, step0: int, n_steps: int, h: float,
               sub: int, z_n: int, phi0: np.ndarray, az: np.ndarray, load: np.ndarray,
               lin: np.ndarray, w0: np.ndarray, wc0: float, q_o: np.ndarray,
               c_z: np.ndarray, consts: np.ndarray, film: np.ndarray, use_table: bool,
               spin0: float, spin_step: float, loads: np.ndarray, cage: np.ndarray,
               values: np.ndarray, n_warm: int, every: int, samples: np.ndarray,
               sample_t: np.ndarray, sample_wc: np.ndarray, sample_ring: np.ndarray,
               n_sampled: int, etd: bool, spin_trust: float, tp: np.ndarray,
               gap: np.ndarray, sample_tilt: np.ndarray
               ) -> tuple[int, int, float, int, float]:
    """Steps ``step0`` .. ``step0 + n_steps - 1`` of the coupled state ``y`` (in place) at
    step ``h`` [s]: ETDRK4 (``etd``; :func:`_stiff_rates` the exact linear part, module
    notes, "Stiff spin") or classical RK4; the traction linearisation refreshed from the
    table every ``sub`` steps if ``use_table`` (else the caller's ``lin`` is used
    throughout) and, with ``spin_trust`` > 0 [rad/s], a roller's row as soon as its spin is
    more than ``spin_trust`` from the spin of its linearisation (roller_dynamics_coupled
    module notes, "Stiff spin"); samples (state with X, X' relative to the inner ring, t,
    omega_c) every ``every`` steps from step ``n_warm`` on. ``consts``: J_p, J_c, D/2,
    d_m/2, T_c, inner-ring mass (0: held), cage-land drag coefficient [N m s] and guide ring
    speed [rad/s]. Returns (status, steps done, t, samples written, omega_c of the
    linearisation); status 0 done, 1-3 the table's grid left (the step was not taken; the
    caller rebuilds the table), 4 the state became non-finite or a spin reversed.
    ``tp``, ``gap``: the tilt option (:func:`_deriv_into`); with it the samples' X, X' are
    those the rib faces see (plus t_q alpha_e, t_q alpha_e') and ``sample_tilt`` (samples,
    Z, 2) gets y_r [m] and alpha_e [rad]."""
    n = N_ROLLER_STATES
    m_y = y.shape[0]
    k1 = np.zeros(m_y)
    k2 = np.zeros(m_y)
    k3 = np.zeros(m_y)
    k4 = np.zeros(m_y)
    yt = np.zeros(m_y)
    ya = np.zeros(m_y)
    lam = np.zeros(m_y)
    y_ref = np.zeros(m_y)
    coef = np.zeros((m_y, 6))
    polar, cage_j, half, dm_half, t_c = consts[0], consts[1], consts[2], consts[3], consts[4]
    ring_mass = consts[5]
    land = consts[6:8]
    unb = consts[8:12]
    ring = z_n * n + 2
    if etd:
        _stiff_rates(p, lin, w0, c_z, polar, half, z_n, h, lam, y_ref, coef)
    for s in range(n_steps):
        step = step0 + s
        if use_table and step % sub == 0:
            wc0, st = _refresh_from_table(y, z_n, phi0, az, load, spin0, spin_step, loads,
                                          cage, values, lin, w0, q_o, c_z, half)
            if st != 0:
                return st, s, t, n_sampled, wc0
            if etd:
                _stiff_rates(p, lin, w0, c_z, polar, half, z_n, h, lam, y_ref, coef)
        elif use_table and spin_trust > 0.0:
            for j in range(z_n):
                if abs(y[j * n + 7] - w0[j]) > spin_trust:
                    st = _refresh_roller(j, y, z_n, phi0, az, load, spin0, spin_step, loads,
                                         cage, values, lin, w0, wc0, q_o, c_z, half)
                    if st != 0:
                        return st, s, t, n_sampled, wc0
                    if etd:
                        _stiff_roller(j, p, lin, w0, c_z, polar, half, h, lam, y_ref, coef)
        if etd:
            # ETDRK4 (roller_dynamics_etd): N = f - lam (y - y_ref), the linear part exact
            _deriv_into(p, y, k1, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                k1[q] -= lam[q] * (y[q] - y_ref[q])
                ya[q] = y_ref[q] + coef[q, 1] * (y[q] - y_ref[q]) + coef[q, 2] * k1[q]
            _deriv_into(p, ya, k2, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                k2[q] -= lam[q] * (ya[q] - y_ref[q])
                yt[q] = y_ref[q] + coef[q, 1] * (y[q] - y_ref[q]) + coef[q, 2] * k2[q]
            _deriv_into(p, yt, k3, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                k3[q] -= lam[q] * (yt[q] - y_ref[q])
                yt[q] = (y_ref[q] + coef[q, 1] * (ya[q] - y_ref[q])
                         + coef[q, 2] * (2.0 * k3[q] - k1[q]))
            _deriv_into(p, yt, k4, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                k4[q] -= lam[q] * (yt[q] - y_ref[q])
                y[q] = (y_ref[q] + coef[q, 0] * (y[q] - y_ref[q]) + coef[q, 3] * k1[q]
                        + 2.0 * coef[q, 4] * (k2[q] + k3[q]) + coef[q, 5] * k4[q])
        else:
            _deriv_into(p, y, k1, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                yt[q] = y[q] + 0.5 * h * k1[q]
            _deriv_into(p, yt, k2, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                yt[q] = y[q] + 0.5 * h * k2[q]
            _deriv_into(p, yt, k3, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                yt[q] = y[q] + h * k3[q]
            _deriv_into(p, yt, k4, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, polar,
                        cage_j, half, dm_half, t_c, film, ring_mass, land, unb, tp, gap)
            for q in range(m_y):
                y[q] += h / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
        t += h
        if (step >= n_warm and (step - n_warm) % every == 0
                and n_sampled < samples.shape[0]):
            for q in range(z_n * n):
                samples[n_sampled, q] = y[q]
            for j in range(z_n):         # geometric centre's X, X' relative to the ring
                b = j * n
                sh, shd, _, _ = unbalance_axial_shift(unb, y[b + 2], y[b + 3], y[b + 6],
                                                      y[b + 7])
                samples[n_sampled, b] -= y[ring] + sh
                samples[n_sampled, b + 1] -= y[ring + 1] + shd
                if tp.shape[0] > 1:
                    tb = z_n * n + 4 + N_TILT_STATES * j
                    samples[n_sampled, b] += tp[TP_TQ] * y[tb + 2]
                    samples[n_sampled, b + 1] += tp[TP_TQ] * y[tb + 3]
                    sample_tilt[n_sampled, j, 0] = y[tb]
                    sample_tilt[n_sampled, j, 1] = y[tb + 2]
            sample_t[n_sampled] = t
            sample_wc[n_sampled] = y[z_n * n + 1]
            sample_ring[n_sampled] = y[ring]
            n_sampled += 1
        if step % 200 == 0:
            for q in range(m_y):
                if not math.isfinite(y[q]):
                    return 4, s + 1, t, n_sampled, wc0
            for j in range(z_n):
                if y[j * n + 7] <= 0.0:
                    return 4, s + 1, t, n_sampled, wc0
    return 0, n_steps, t, n_sampled, wc0


def _refresh_caches() -> None:
    """Flush the kernels' numba caches when a module whose compiled functions they inline
    changed (roller_dynamics_rhs's ``_rhs_ring``, rib.py, roller_dynamics_pocket.py,
    roller_dynamics_table.py, roller_dynamics_etd.py;
    :func:`thermobearing.contact_traction.refresh_stale_caches`)."""
    from .. import rib
    from ..contact_traction import refresh_stale_caches
    from . import (
        roller_dynamics_etd,
        roller_dynamics_pocket,
        roller_dynamics_rhs,
        roller_dynamics_table,
        roller_dynamics_tilt,
    )

    refresh_stale_caches("roller_dynamics_coupled_kernels",
                         (pocket_damping, spin_pocket_coupling, _pocket_film_friction,
                          unbalance_axial_shift, _interp_sorted,
                          _deriv_into,
                          _refresh_from_table, _refresh_roller, _stiff_rates,
                          _stiff_roller, _integrate),
                         (roller_dynamics_rhs, rib, roller_dynamics_pocket,
                          roller_dynamics_table, roller_dynamics_etd, roller_dynamics_tilt))


_refresh_caches()
