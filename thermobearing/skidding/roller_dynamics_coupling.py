"""Rib moments and cage-bar friction fed back into the roller spins and cage speed.

Part of the paper 003 roller dynamics (:mod:`thermobearing.skidding.roller_dynamics`, module
notes there): Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear],
eq. 18 line 4 (spin) and eq. 19 (cage), closed with the quasi-static Z + 1 equations of
paper 000 (:mod:`thermobearing.skidding.roller`). Units: SI.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import ConvergenceError
from .roller_dynamics_integrate import _state_post
from .roller_dynamics_model import DynamicsModel, load_states
from .roller_dynamics_response import _mean
from .roller_dynamics_rhs import _params


def unbalance_orbital_force(m: DynamicsModel, cage_speed: float) -> float:
    """F_cv [N] of paper 003 eq. 18 (lines 2-3, along the azimuth direction like the
    roller's own centrifugal force F^m): the orbital centrifugal force of the unbalance mass,
    m_u (d_m/2) omega_c^2 (the paper adds it to the roller's; its axial offset x_u only tilts
    the roller, which is not followed). ``m.extras["orbital_unbalance"]`` False -> 0."""
    if not m.extras.get("orbital_unbalance", True):
        return 0.0
    return m.unbalance.mass * 0.5 * m.geom.pitch_diameter * cage_speed**2


def _race_eval(rm: Any, m: DynamicsModel, spins: np.ndarray, wc: float) -> Any:
    """Paper 000 Z + 1 residuals (:func:`thermobearing.skidding.roller.evaluate`) of the
    quasi-static model ``rm`` at roller spins ``spins`` (azimuth order of ``m``) and cage
    speed ``wc`` [rad/s], every roller's outward body force increased by the unbalance's
    orbital centrifugal force (:func:`unbalance_orbital_force`); no whirl."""
    from .roller import evaluate

    z = len(m.azimuth)
    body = np.full(z, unbalance_orbital_force(m, float(wc)))
    return evaluate(rm, m.inner_speed, np.asarray(spins, float), float(wc), m.inner_load,
                    body, m.azimuth, (0.0, 0.0))


def _race_eval_at(rm: Any, m: DynamicsModel, spins: np.ndarray, wc: float,
                  inner_load: np.ndarray, azimuth: np.ndarray) -> Any:
    """:func:`_race_eval` with the rollers at ``azimuth`` [rad] carrying ``inner_load`` [N]
    (the coupled all-roller integration, rollers moving with the cage)."""
    from .roller import evaluate

    z = len(azimuth)
    body = np.full(z, unbalance_orbital_force(m, float(wc)))
    return evaluate(rm, m.inner_speed, np.asarray(spins, float), float(wc),
                    np.asarray(inner_load, float), body, np.asarray(azimuth, float),
                    (0.0, 0.0))


def lagged_spins(m: DynamicsModel, n_grid: int = 2400, orbits: int = 6) -> np.ndarray:
    """Roller spins [rad/s] at the tabulated azimuths of ``m`` with the spin inertia along
    the orbit (paper 003 eq. 18 line 4 linearised about the quasi-static balance):

        J_p d omega / dt = -k(phi) (omega - omega_qs(phi)),   d phi / dt = omega_c,

    k(phi) the spin stiffness of the quasi-static traction model (``m.spin_k``) and
    omega_qs(phi) the (coupled) quasi-static spin of the roller sector nearest to phi
    (piecewise constant), integrated exactly (exponential per step of 2 pi / ``n_grid``)
    over ``orbits`` orbits to the periodic solution. An unloaded roller relaxes with
    J_p/k ~ 13 ms, longer than its 3.2 ms in the unloaded zone at the paper's base case, so
    it keeps most of the spin it had in the load zone. Cheap stand-in for the coupled
    integration's spins (:mod:`~thermobearing.skidding.roller_dynamics_coupled`); it keeps
    the quasi-static cage speed and ignores the rib/bar moments' time structure.
    """
    if m.spin_k is None:
        raise ConvergenceError("roller_dynamics.lagged_spins", float("nan"),
                               "the model carries no spin stiffness (build_model sets it)",
                               {})
    az = m.azimuth
    phi = np.linspace(0.0, 2.0 * np.pi, n_grid, endpoint=False)
    dist = np.abs((phi[:, None] - az[None, :] + np.pi) % (2.0 * np.pi) - np.pi)
    sector = np.argmin(dist, axis=1)
    decay = np.exp(-m.spin_k[sector] * (2.0 * np.pi / n_grid / m.cage_speed)
                   / m.polar_inertia)
    target = m.spin[sector]
    w = float(target[0])
    series = np.empty(n_grid)
    for _ in range(orbits):
        for i in range(n_grid):
            w = target[i] + (w - target[i]) * decay[i]
            series[i] = w
    idx = np.argmin(np.abs((az[:, None] - phi[None, :] + np.pi) % (2.0 * np.pi) - np.pi),
                    axis=1)
    return series[idx]


def race_spin_stiffness(rm: Any, m: DynamicsModel, spins: np.ndarray | None = None,
                        cage_speed: float | None = None) -> np.ndarray:
    """k_j = -dT_j/d omega_r [N m s] of the raceway + pocket moment T_j on every roller (the
    moment balance of paper 000 eqs. 22-31 times D/2), by a forward difference of the
    quasi-static model ``rm`` (:func:`thermobearing.skidding.roller.build_model`): the
    spin stiffness of the *same* traction model that set the spins. Floor 1e-12 N m s."""
    w = m.spin if spins is None else np.asarray(spins, float)
    wc = m.cage_speed if cage_speed is None else cage_speed
    h = 1e-4 * np.maximum(np.abs(w), 1.0)
    half = 0.5 * m.geom.roller_diameter
    e0 = _race_eval(rm, m, w, wc)
    e1 = _race_eval(rm, m, w + h, wc)
    return np.maximum(-(e1.roller_eq - e0.roller_eq) / h * half, 1e-12)


def couple_spins(m: DynamicsModel, bearing: Any, lubricant: Any, *, passes: int = 1,
                 periods: float = 10.0, tol: float = 1e-8, max_iter: int = 30
                 ) -> DynamicsModel:
    """Roller spins and cage speed with the rib contact fed back (paper 003 eqs. 18-19).

    The paper couples the rib moments of eq. 16 to the roller spin (eq. 18, line 4) and,
    through the rollers' orbital forces, to the cage (eq. 19). Here, per load state of the
    orbit, the time-mean rib moment about the roller axis M_j and circumferential force
    F_j over the periodic skew motion (reduced model) are added to the quasi-static
    Z + 1 equations of paper 000 (:mod:`thermobearing.skidding.roller`):

        T_j(omega_j, omega_c) + M_j(omega_j) = 0,   cage_eq(omega, omega_c) + sum F_j = 0,

    with M_j linearised in the spin (secant between the state's spin and the pure-rolling
    spin, or -10 % for rollers near rolling; slope clipped to <= 0), solved by Newton with
    the arrow-shaped Jacobian of that module; ``passes`` re-linearisations.
    With the pocket degree of freedom (``m.pocket_dof``) the time-mean cage-bar film
    friction of the rattling roller beyond the quasi-static one, Delta f_j
    (:func:`~thermobearing.skidding.roller_dynamics_pocket.extra_pocket_friction`), joins
    M_j as the moment -Delta f_j D/2 (paper 003 eq. 18 line 4, F^c D_w/2) and retards the
    cage as the quasi-static pocket friction does, -(D/d_m) sum Delta f_j (paper 000
    eq. 32 as in :mod:`thermobearing.skidding.roller_residual`).
    Returns a copy of ``m`` with the new spins, cage speed, outer loads and the spin
    stiffness of the traction model (``spin_k``); ``extras["coupling"]`` holds the
    iterations and residuals. ConvergenceError if Newton stalls. Costs ~10 reduced runs.
    """
    from dataclasses import replace as dc_replace

    from .roller import build_model as race_model

    rm = race_model(bearing, lubricant, m.extras.get("temperature", 353.15))
    half = 0.5 * m.geom.roller_diameter
    z = len(m.azimuth)
    force_scale = max(float(np.max(m.inner_load, initial=0.0)), 1.0)
    cur = m
    history = []
    d_over_dm = m.geom.roller_diameter / m.geom.pitch_diameter
    for _pass in range(passes):
        cur = dc_replace(cur, spin_k=race_spin_stiffness(rm, cur))
        c = _params(cur)
        states = load_states(cur)
        w_roll = ((cur.inner_speed - cur.cage_speed) * cur.geom.inner_raceway_diameter
                  / cur.geom.roller_diameter)
        m0 = np.zeros(z)
        slope = np.zeros(z)
        f_t = np.zeros(z)
        f_x = np.zeros(z)
        for n_i, n_o, w, _share, k, f_d in states:
            sel = ((np.round(cur.inner_load, 3) == round(n_i, 3))
                   & (np.round(cur.outer_load, 3) == round(n_o, 3))
                   & (np.round(cur.spin, 3) == round(w, 3)))
            # secant over a wide spin step: the mean of the impacting motion scatters by
            # ~10 %, so a small step would give a slope of noise; the moment falls with the
            # spin (friction opposes the slide), a positive slope is noise -> clipped to 0
            w2 = w_roll if abs(w_roll - w) > 0.1 * w else 0.9 * w
            p0, _ = _state_post(cur, c, n_i, n_o, w, periods, 2.0, 400, 100, k, f_d)
            p1, _ = _state_post(cur, c, n_i, n_o, w2, periods, 2.0, 400, 100, k, f_d)
            x0 = float(p0["pocket_extra"][0])
            a0 = _mean(p0["spin_moment"], p0["t"]) - x0 * half
            a1 = _mean(p1["spin_moment"], p1["t"]) - float(p1["pocket_extra"][0]) * half
            m0[sel] = a0
            slope[sel] = min((a1 - a0) / (w2 - w), 0.0)
            f_t[sel] = _mean(p0["tangential_force"], p0["t"])
            f_x[sel] = x0
        w_ref = cur.spin.copy()

        def resid(x: np.ndarray, cur: DynamicsModel = cur, m0: np.ndarray = m0,
                  slope: np.ndarray = slope, w_ref: np.ndarray = w_ref,
                  f_sum: float = float(np.sum(f_t) - d_over_dm * np.sum(f_x))
                  ) -> tuple[np.ndarray, Any]:
            e = _race_eval(rm, cur, x[:z], x[z])
            r = np.append(e.roller_eq + (m0 + slope * (x[:z] - w_ref)) / half,
                          e.cage_eq + f_sum)
            return r, e

        x = np.append(cur.spin, cur.cage_speed)
        r, e = resid(x)
        norm = float(np.linalg.norm(r)) / force_scale
        it = 0
        while norm > tol and it < max_iter:
            it += 1
            h = 1e-6 * np.maximum(np.abs(x[:z]), 1.0)
            xp = x.copy()
            xp[:z] += h
            rp, ep = resid(xp)
            diag = (rp[:z] - r[:z]) / h
            c_row = (ep.cage_terms - e.cage_terms) / h
            hc = 1e-6 * max(abs(x[z]), 1.0)
            xq = x.copy()
            xq[z] += hc
            rq, _ = resid(xq)
            b_col = (rq[:z] - r[:z]) / hc
            d_cc = (rq[z] - r[z]) / hc
            diag = np.where(np.abs(diag) > 1e-300, diag, 1e-300)
            denom = d_cc - np.sum(c_row * b_col / diag)
            if not np.isfinite(denom) or denom == 0.0:
                break
            dwc = (-r[z] + np.sum(c_row * r[:z] / diag)) / denom
            step = np.append((-r[:z] - b_col * dwc) / diag, dwc)
            lam = min(1.0, 0.5 * m.inner_speed / max(float(np.max(np.abs(step))), 1e-300))
            for _ in range(30):
                xn = x + lam * step
                if 0.0 < xn[z] < m.inner_speed and np.all(xn[:z] > 0.0):
                    rn, en = resid(xn)
                    nn = float(np.linalg.norm(rn)) / force_scale
                    if np.isfinite(nn) and nn < (1.0 - 1e-4 * lam) * norm:
                        break
                lam *= 0.5
            else:
                break
            x, r, e, norm = xn, rn, en, nn
        if norm > max(tol, 1e-6):
            raise ConvergenceError("roller_dynamics.couple_spins", norm,
                                   "Newton on the Z + 1 equations with the rib moments stalled",
                                   {"pass": _pass, "iterations": it})
        # spin_bias: the rib part only (the instantaneous rib moment of the full model's
        # spin DOF is measured against it; the pocket friction stays in the spins)
        bias = m0 + slope * (x[:z] - w_ref) + f_x * half
        history.append({"iterations": it, "residual": norm, "cage_speed": float(x[z]),
                        "mean_rib_moment": bias.copy(), "rib_tangential_force": f_t.copy(),
                        "pocket_extra_friction": f_x.copy()})
        cur = dc_replace(cur, spin=x[:z].copy(), cage_speed=float(x[z]),
                         outer_load=np.asarray(e.q_o, float).copy(),
                         pocket_force=np.asarray(e.pocket, float).copy())
    k = race_spin_stiffness(rm, cur)
    extras = dict(cur.extras)
    extras["coupling"] = {"passes": history, "cage_speed_quasi_static": m.cage_speed,
                          "spin_quasi_static": m.spin.copy()}
    return dc_replace(cur, spin_k=k, spin_bias=bias, extras=extras)
