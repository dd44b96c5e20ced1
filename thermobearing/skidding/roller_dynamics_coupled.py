"""All rollers and the cage integrated together (paper 003 eqs. 18-19, ring prescribed).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], integrate
every roller (eq. 18), the cage (eq. 19) and the inner ring (eq. 20) together with a stiff
variable-step method (GSTIFF [gear1971_dae]). The reduced and the one-roller "full" model of
:mod:`~thermobearing.skidding.roller_dynamics` prescribe the roller spins and the cage speed
(the quasi-static balance of :func:`~thermobearing.skidding.roller_dynamics.couple_spins`).
Here the spins and the cage speed are degrees of freedom:

* per roller j (Z of them): X, X', alpha, alpha', z, z' (the right-hand side of the one-roller
  model, :func:`~thermobearing.skidding.roller_dynamics._rhs`: rib eqs. 1-17, cage bars,
  unbalance), the unbalance phase psi and the spin omega_j,
  J_p omega_j' = (D/2)(S_j - f_bar,j) + M_rib,x,j, with S_j the raceway shear of paper 000's
  traction model (:func:`thermobearing.skidding.roller.evaluate`: roller moment balance
  plus its pocket friction) and f_bar,j the pocket-film friction (paper 000 eqs. 37-38,
  :func:`~thermobearing.skidding.roller_fluid.pocket_forces`) at the instantaneous bar force;
  the raceways' net orbital force F_d,j of the same evaluation drives z;
* cage: angle theta_c and speed omega_c, J_c omega_c' = sum_j [-F_bar,z,j d_m/2 - f_bar,j D/2]
  - T_c (eq. 19 line 3 with the bar forces of the rollers; T_c the quasi-static model's cage
  drag torque), roller azimuths phi_j = phi_j0 + theta_c;
* inner ring: prescribed (no whirl), its loads per azimuth from the quasi-static solution --
  eq. 20 is not integrated.

Integrator (ours): paper 000's traction evaluation costs ~4 ms per call (Python/numpy over Z
rollers), the rib contact needs steps <= 1/omega_rib (~1.6 us): the raceway shear and orbital
force are linearised in (omega_j, omega_c) -- value and finite-difference slopes from three
evaluations -- and refreshed every ``refresh`` seconds (default 20 us, 1/5 of the loaded
rollers' spin time constant J_p/k), the contact-resolved motion integrated by classical RK4
at the reduced model's step in between (a multirate, locally linearised scheme; the
linearisation makes the traction term implicit-free but exact at every refresh). Refresh
convergence is checked in the tests. Units: SI.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace
from typing import Any

import numpy as np
from numba import njit

from ..errors import ConvergenceError, check_positive
from .roller_dynamics import (
    DynamicsModel,
    RollerResponse,
    _params,
    _post,
    _response,
    _rhs,
)
from .roller_dynamics_pocket import pocket_force_z

#: roller states per roller in the coupled model: X, X', alpha, alpha', z, z', psi, omega
N_ROLLER_STATES = 8


def cage_inertia(bearing: Any) -> tuple[float, float, dict[str, str]]:
    """(mass [kg], polar moment of inertia [kg m^2], estimated-fields note) of the cage.

    The cage's own ``mass`` if given; else a ring of the cage's inner/outer diameter and
    width with Z pockets of D x L_r through its radial wall removed, density of its material
    (estimated). J_c = m (r_o^2 + r_i^2) / 2 (thick ring).
    """
    cage = bearing.cage
    r_o, r_i = 0.5 * cage.outer_diameter, 0.5 * cage.inner_diameter
    note = {}
    mass = getattr(cage, "mass", None)
    if not mass:
        ring = math.pi * (r_o**2 - r_i**2) * cage.width
        pockets = bearing.n_rollers * bearing.roller_diameter * bearing.roller_length * (
            r_o - r_i)
        mass = cage.material.density * (ring - pockets)
        note["cage_mass"] = ("ring of the cage diameters and width minus Z pockets D x L_r "
                             "through the wall, cage material density (estimated)")
    return float(mass), float(0.5 * mass * (r_o**2 + r_i**2)), note


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
def _deriv(p: np.ndarray, y: np.ndarray, z_n: int, phi0: np.ndarray, az: np.ndarray,
           load: np.ndarray, lin: np.ndarray, w0: np.ndarray, wc0: float,
           q_o: np.ndarray, c_z: np.ndarray, polar: float, cage_j: float, half: float,
           dm_half: float, t_c: float, film: np.ndarray) -> np.ndarray:
    """Time derivative of the coupled state (module notes). ``lin`` (Z, 6): S0, dS/dw,
    dS/dwc, F_d0, dF_d/dw, dF_d/dwc of the last refresh; ``film``: pocket length, eta,
    clearance, k_w, k_c + k_q/2, smoothing."""
    n = N_ROLLER_STATES
    dy = np.zeros_like(y)
    th = y[z_n * n]
    wc = y[z_n * n + 1]
    torque = -t_c
    two_pi = 2.0 * math.pi
    for j in range(z_n):
        b = j * n
        w = y[b + 7]
        phi = (phi0[j] + th) % two_pi
        n_i = np.interp(phi, az, load)
        dw = w - w0[j]
        dc = wc - wc0
        s = lin[j, 0] + lin[j, 1] * dw + lin[j, 2] * dc
        f_d = lin[j, 3] + lin[j, 4] * dw + lin[j, 5] * dc
        r = _rhs(p, y[b], y[b + 1], y[b + 2], y[b + 3], y[b + 4], y[b + 5], n_i, q_o[j], w,
                 y[b + 6], f_d, c_z[j])
        fz_bar, _, ff, fb = pocket_force_z(y[b + 4], y[b + 5], y[b + 2], p[_HLI], p[_CPI],
                                           p[_KCI], p[_ETAI], half, p[_FLI])
        f_bar = _pocket_film_friction(ff - fb, w, half, film[0], film[1], film[2], film[3],
                                      film[4], film[5])
        dy[b] = r[0]
        dy[b + 1] = r[1]
        dy[b + 2] = r[2]
        dy[b + 3] = r[3]
        dy[b + 4] = r[4]
        dy[b + 5] = r[5]
        dy[b + 6] = w
        dy[b + 7] = (half * (s - f_bar) + r[6]) / polar
        torque += -fz_bar * dm_half - f_bar * half
    dy[z_n * n] = wc
    dy[z_n * n + 1] = torque / cage_j
    return dy


def _indices() -> tuple[int, int, int, int, int]:
    from . import roller_dynamics as rd

    return rd._HL, rd._CP, rd._KC, rd._ETA, rd._FLOOR


_HLI, _CPI, _KCI, _ETAI, _FLI = _indices()


def simulate_coupled(m: DynamicsModel, bearing: Any, lubricant: Any, *,
                     n_orbits: float = 2.0, warmup_orbits: float = 2.0,
                     refresh: float = 20e-6, steps_per_period: int = 400,
                     samples_per_period: int = 100, phase_spread: bool = True
                     ) -> RollerResponse:
    """Integrate all Z rollers and the cage together (module notes) from the coupled
    quasi-static state of ``m`` (:func:`~thermobearing.skidding.roller_dynamics.build_model`),
    ``warmup_orbits`` discarded, statistics over the next ``n_orbits`` cage orbits.

    ``refresh`` [s]: interval of the raceway-traction linearisation. ``phase_spread``: the
    rollers' unbalance phases spread by the golden angle (True) or all equal (False).
    Returns a :class:`~thermobearing.skidding.roller_dynamics.RollerResponse` (``model`` =
    "coupled", means over all rollers and the time) whose ``series`` holds ``t`` [s],
    ``cage_speed`` [rad/s] and ``spin`` (time x Z) [rad/s]. ``cost_s``: CPU seconds.
    ConvergenceError if the state becomes non-finite or a spin reverses.
    """
    from .roller import build_model as race_model
    from .roller_dynamics_coupling import _race_eval_at
    from .roller_fluid import martin_coefficients

    check_positive("refresh", refresh)
    t0 = time.process_time()
    rm = race_model(bearing, lubricant, m.extras.get("temperature", 353.15))
    z_n = len(m.azimuth)
    n = N_ROLLER_STATES
    half = 0.5 * m.geom.roller_diameter
    c = _params(m)
    _, j_c, _ = cage_inertia(bearing)
    k_w, k_q, k_c, _ = martin_coefficients()
    film = np.array([m.pocket_length, m.pocket_viscosity, m.pocket_clearance, k_w,
                     k_c + 0.5 * k_q, 1e-4])
    az = np.append(m.azimuth, m.azimuth[0] + 2.0 * math.pi)
    load = np.append(m.inner_load, m.inner_load[0])
    phi0 = m.azimuth.copy()
    y = np.zeros(z_n * n + 2)
    golden = math.pi * (3.0 - math.sqrt(5.0))
    for j in range(z_n):
        b = j * n
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        y[b + 4] = math.copysign(0.5 * m.pocket_clearance, f_d) if m.pocket_dof else 0.0
        y[b + 6] = golden * j if phase_spread else 0.0
        y[b + 7] = m.spin[j]
    y[z_n * n + 1] = m.cage_speed
    omega_rib = math.sqrt(1.5 * m.geom.stiffness * math.sqrt(20e-6) / m.roller_mass)
    period = 2.0 * math.pi / max(float(np.max(m.spin)), 1.0)
    h = min(period / steps_per_period, 1.0 / omega_rib)
    sub = max(1, int(round(refresh / h)))
    orbit = 2.0 * math.pi / m.cage_speed
    n_warm = int(math.ceil(warmup_orbits * orbit / h))
    n_keep = int(math.ceil(n_orbits * orbit / h))
    every = max(1, int(period / samples_per_period / h))
    rows, times, wcs = [], [], []
    n_eval = 0
    t = 0.0
    lin = np.zeros((z_n, 6))
    w0 = np.zeros(z_n)
    q_o = np.zeros(z_n)
    c_z = np.zeros(z_n)
    wc0 = 0.0
    for step in range(n_warm + n_keep):
        if step % sub == 0:
            w0 = y[7::n][:z_n].copy()
            wc0 = float(y[z_n * n + 1])
            phi = np.mod(phi0 + y[z_n * n], 2.0 * math.pi)
            n_i = np.interp(phi, az, load)
            dw = 1e-4 * np.maximum(np.abs(w0), 1.0)
            dc = 1e-4 * max(abs(wc0), 1.0)
            e0 = _race_eval_at(rm, m, w0, wc0, n_i, phi)
            e1 = _race_eval_at(rm, m, w0 + dw, wc0, n_i, phi)
            e2 = _race_eval_at(rm, m, w0, wc0 + dc, n_i, phi)
            n_eval += 3
            s0 = e0.roller_eq + e0.friction
            lin[:, 0] = s0
            lin[:, 1] = (e1.roller_eq + e1.friction - s0) / dw
            lin[:, 2] = (e2.roller_eq + e2.friction - s0) / dc
            lin[:, 3] = e0.pocket
            lin[:, 4] = (e1.pocket - e0.pocket) / dw
            lin[:, 5] = (e2.pocket - e0.pocket) / dc
            q_o = np.asarray(e0.q_o, float)
            c_z = np.maximum(-lin[:, 1], 0.0)
        args = (c, y, z_n, phi0, az, load, lin, w0, wc0, q_o, c_z, m.polar_inertia, j_c,
                half, 0.5 * m.geom.pitch_diameter, float(rm.cage_drag_torque), film)
        k1 = _deriv(*args)
        k2 = _deriv(c, y + 0.5 * h * k1, *args[2:])
        k3 = _deriv(c, y + 0.5 * h * k2, *args[2:])
        k4 = _deriv(c, y + h * k3, *args[2:])
        y = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        t += h
        if step >= n_warm and (step - n_warm) % every == 0:
            rows.append(y[: z_n * n].reshape(z_n, n).copy())
            times.append(t)
            wcs.append(y[z_n * n + 1])
        if step % 200 == 0 and (not np.all(np.isfinite(y)) or np.any(y[7::n][:z_n] <= 0.0)):
            raise ConvergenceError("roller_dynamics.coupled", float("inf"),
                                   "state not finite or a roller spin reversed",
                                   {"t": t, "step": step})
    traj = np.array(rows)                       # (time, Z, 8)
    tt = np.array(times)
    wc_t = np.array(wcs)
    mm = replace(m, cage_speed=float(np.mean(wc_t)))
    weights = []
    for j in range(z_n):
        r = traj[:, j, :]
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        weights.append((1.0 / z_n, _post(mm, tt, r[:, 0], r[:, 1], r[:, 2], r[:, 3],
                                         r[:, 7], r[:, 4], r[:, 5], f_d)))
    cost = time.process_time() - t0
    resp = _response(weights[0][1], "coupled", cost, 4 * (n_warm + n_keep), m.geom, weights)
    return replace(resp, series={"t": tt, "cage_speed": wc_t, "spin": traj[:, :, 7],
                                 "traction_evaluations": np.array([n_eval]),
                                 "step": np.array([h]), "refresh_steps": np.array([sub])})


__all__ = ["N_ROLLER_STATES", "cage_inertia", "simulate_coupled"]
