"""Integration drivers of the paper 003 roller dynamics: the ``full`` model
(:func:`simulate_full`, scipy's Radau IIA over whole orbits [hairer_wanner1996]) and the
``reduced`` model (:func:`simulate_reduced`, frozen load states with the compiled fixed-step
ETDRK4 :func:`_etd_frozen`); :func:`simulate` dispatches. The models and their accuracy are
described in :mod:`thermobearing.skidding.roller_dynamics`; the right-hand side is
:mod:`~thermobearing.skidding.roller_dynamics_rhs`, the statistics
:mod:`~thermobearing.skidding.roller_dynamics_response`.

Stiff pocket damping (2026-11-24): at a frozen state the roller's circumferential slide in
its pocket is damped by the raceways, m z'' = ... - c_z z', c_z = k_omega/(D/2)^2 with k_omega
the spin stiffness of paper 000's traction model. At a heavily loaded, slowly turning roller
in a mineral oil the film's Newtonian shear makes it very stiff: NU 214 made NJ-type, ISO VG46
at 60 degC, 2000 r/min, 8 kN: k_omega = 9.3 N m s, c_z/m = 1.65e7 1/s on the most loaded
roller against the rib contact's step h = 4.2 us (h c_z/m = 70; classical RK4 is stable to
2.8 on a real eigenvalue, and the refinements below reach h c_z/m = 5.2 only), so every run
stopped with "RK4 diverged". The other rates there are below 3.6e4 1/s. The term is linear in
z' with a constant coefficient at a frozen state, so :func:`_etd_frozen` takes it exactly:
Cox and Matthews' ETDRK4 (:mod:`~thermobearing.skidding.roller_dynamics_etd`, the scheme of
the coupled model's stiff spin) with the linear rate lambda = -c_z/m on z' and classical RK4
(lambda = 0) on the other components. The explicit step is also held below the inverse of
the raceway traction's axial and skew damping rates (:func:`explicit_rate`), next to the
rib contact's frequency.

numba's cache does not notice edits of compiled callees in other files (the loop inlines the
right-hand side and the ETD coefficients):
:func:`thermobearing.contact_traction.refresh_stale_caches`. Units: SI.
"""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp

from ..contact_traction import refresh_stale_caches
from ..errors import ConvergenceError, InputError
from .roller_dynamics_etd import set_coefficients
from .roller_dynamics_model import DynamicsModel, load_states
from .roller_dynamics_response import RollerResponse, _post, _response
from .roller_dynamics_rhs import _params, _rhs, _roller_rhs


def simulate_full(m: DynamicsModel, *, n_orbits: float = 2.0, warmup_periods: float = 3.0,
                  rtol: float = 1e-6, samples_per_period: int = 64,
                  start_azimuth: float = 0.0, spin_dof: bool = False) -> RollerResponse:
    """Integrate X, alpha, z (pocket) and psi of one roller over ``n_orbits`` orbits
    (Radau), the load state (raceway loads, spin, quasi-static pocket force) following the
    azimuth.

    ``spin_dof=False`` (default): the spin follows the orbit's spins of the model (for a
    coupled model, :func:`couple_spins`, the quasi-static balance of the raceway, pocket
    and mean rib moments). ``spin_dof=True`` adds omega_r as a degree of freedom,
    J_p omega_r' = -k (omega_r - omega(phi)) - M_bias(phi) + M_rib,x(t), with k the spin
    stiffness of the quasi-static traction model: for unloaded rollers J_p/k is ~13 ms,
    three orbits at the base case, so that option needs many more orbits to settle.
    The first ``warmup_periods`` spin periods are integrated and discarded; statistics
    are taken over the following ``n_orbits`` orbits. ConvergenceError if the integrator
    fails.
    """
    t0 = time.process_time()
    n_calls = [0]
    g = m.geom
    c = _params(m)

    # state: X, X', alpha, alpha', z, z', psi (, omega_r with spin_dof)
    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        n_calls[0] += 1
        phi = start_azimuth + m.cage_speed * t
        n_i, n_o, w_qs = m.at(phi)
        w = y[7] if spin_dof else w_qs
        k = m.stiffness_at(phi)
        d = _roller_rhs(m, c, y, n_i, n_o, w, y[6], m.pocket_force_at(phi),
                        m.circumferential_damping(k))
        if not spin_dof:
            return np.array([d[0], d[1], d[2], d[3], d[4], d[5], w])
        wdot = (-k * (y[7] - w_qs) - m.bias_at(phi) + d[6]) / m.polar_inertia
        return np.array([d[0], d[1], d[2], d[3], d[4], d[5], w, wdot])

    _, _, w0 = m.at(start_azimuth)
    f0 = m.pocket_force_at(start_azimuth)
    z0 = math.copysign(0.5 * m.pocket_clearance, f0) if m.pocket_dof else 0.0
    period = 2.0 * math.pi / max(abs(w0), 1.0)
    t_warm = warmup_periods * period
    t_end = t_warm + n_orbits * 2.0 * math.pi / m.cage_speed
    n_out = int(samples_per_period * (t_end - t_warm) / period) + 2
    t_eval = np.linspace(t_warm, t_end, n_out)
    n_y = 8 if spin_dof else 7
    atol = np.array([1e-9, 1e-6, 1e-7, 1e-3, 1e-9, 1e-6, 1e-6, 1e-2])[:n_y]
    y0 = np.array([0.0, 0.0, 0.0, 0.0, z0, 0.0, 0.0, w0])[:n_y]
    sol = solve_ivp(rhs, (0.0, t_end), y0,
                    method="Radau", rtol=rtol, atol=atol, t_eval=t_eval,
                    max_step=period / 8.0)
    if not sol.success:
        raise ConvergenceError("roller_dynamics.full", float("nan"), sol.message,
                               {"t": sol.t[-1] if sol.t.size else 0.0})
    y = sol.y
    phis = start_azimuth + m.cage_speed * sol.t
    spin = (y[7] if spin_dof else np.array([m.at(p)[2] for p in phis]))
    post = _post(m, sol.t, y[0], y[1], y[2], y[3], spin, y[4], y[5],
                 np.array([m.pocket_force_at(p) for p in phis]))
    return _response(post, "full", time.process_time() - t0, n_calls[0], g)


#: a frozen state whose fixed-step integration diverges is repeated with a step this many
#: times finer, up to RK4_REFINEMENTS times (a safety net: before the pocket damping was
#: taken exactly (module notes), CRB 50x75x16 at 3 kN and 20000 r/min with ISO VG46 at
#: 80 degC diverged at 400 and 1600 steps per spin period and gave the same rib heat at
#: 6400 and 25600)
RK4_REFINE_FACTOR = 4
RK4_REFINEMENTS = 3


def simulate_reduced(m: DynamicsModel, *, periods: float = 20.0, warmup_periods: float = 3.0,
                     steps_per_period: int = 400, samples_per_period: int = 100
                     ) -> RollerResponse:
    """Skew and axial motion at the orbit's distinct frozen load states (the ``reduced`` model of
    :mod:`thermobearing.skidding.roller_dynamics`).

    Each state is integrated with ETDRK4 (the pocket's raceway damping exact, RK4 on the rest;
    module notes) at a fixed step of 1/``steps_per_period`` spin period, and at most
    1/:func:`explicit_rate` (the rib contact's axial frequency at a 20 um approach, ~6e5
    rad/s at paper 003's base case: h <= 1.6 us, or the raceway traction's axial or skew
    damping rate if larger; RK4 is stable to h omega < 2.8) for
    ``warmup_periods`` + ``periods`` spin periods; statistics over the last ``periods``,
    averaged with the states' orbit shares. The mean rib spin moment changes the spin
    quasi-statically by M / k_omega before the slip is evaluated. A state whose integration
    diverges is repeated at a step :data:`RK4_REFINE_FACTOR` times finer, up to
    :data:`RK4_REFINEMENTS` times.
    """
    t0 = time.process_time()
    n_calls = 0
    weights = []
    c = _params(m)
    for n_i, n_o, w_qs, share, k, f_d in load_states(m):
        spp = int(steps_per_period)
        for attempt in range(RK4_REFINEMENTS + 1):
            try:
                post, calls = _state_post(m, c, n_i, n_o, w_qs, periods, warmup_periods,
                                          spp, samples_per_period, k, f_d)
                break
            except ConvergenceError as exc:
                if attempt == RK4_REFINEMENTS:
                    raise ConvergenceError(
                        "roller_dynamics.reduced", exc.residual,
                        f"ETDRK4 diverged at {steps_per_period} to {spp} steps per spin period "
                        f"({RK4_REFINEMENTS} refinements by {RK4_REFINE_FACTOR})",
                        exc.state) from None
                spp *= RK4_REFINE_FACTOR
        n_calls += calls
        weights.append((share, post))
    return _response(weights[0][1], "reduced", time.process_time() - t0, n_calls, m.geom,
                     weights)


def simulate(m: DynamicsModel, model: str = "reduced", **options: Any) -> RollerResponse:
    """Dispatch to :func:`simulate_full` or :func:`simulate_reduced`."""
    if model == "full":
        return simulate_full(m, **options)
    if model == "reduced":
        return simulate_reduced(m, **options)
    raise InputError("model", model, ("full", "reduced"))


def explicit_rate(m: DynamicsModel, n_i: float, n_o: float) -> float:
    """Largest rate [1/s] the explicit part of :func:`_etd_frozen` integrates at the frozen
    raceway loads ``n_i``, ``n_o`` [N]: the rib contact's axial frequency at a 20 um approach,
    omega_c = sqrt(1.5 K sqrt(20 um) / m) (the slope of eq. 6's Hertz force K delta^1.5),
    and the raceway traction's damping of the axial slide and of the skew rate,
    (N_i + N_o) mu_t / (s_0 m) and (N_i + N_o) mu_t l^2 / (s_0 J_t) (the slopes at zero slide
    of the tanh law of :mod:`~thermobearing.skidding.roller_dynamics_rhs`, l = L_e/(2 sqrt 3);
    the isotropic law's slope is not larger). The pocket's raceway damping is not among them:
    it is integrated exactly (module notes)."""
    omega_c = math.sqrt(1.5 * m.geom.stiffness * math.sqrt(20e-6) / m.roller_mass)
    grip = (abs(n_i) + abs(n_o)) * m.traction_limit / m.traction_speed
    arm = m.effective_length / (2.0 * math.sqrt(3.0))
    return max(omega_c, grip / m.roller_mass, grip * arm * arm / m.transverse_inertia)


def pocket_rate(m: DynamicsModel, k: float) -> float:
    """lambda = -c_z / m [1/s]: the linear rate of the pocket slide speed z' under the
    raceway damping c_z = k_omega/(D/2)^2 (``k`` = k_omega [N m s],
    :meth:`~thermobearing.skidding.roller_dynamics_model.DynamicsModel.circumferential_damping`),
    taken exactly by :func:`_etd_frozen`; 0 with the pocket degree of freedom off (z = 0)."""
    if not m.pocket_dof:
        return 0.0
    return -m.circumferential_damping(k) / m.roller_mass


def _state_post(m: DynamicsModel, c: np.ndarray, n_i: float, n_o: float, w: float,
                periods: float, warmup_periods: float, steps_per_period: int,
                samples_per_period: int, k: float = 0.0, f_d: float = 0.0
                ) -> tuple[dict[str, np.ndarray], int]:
    """ETDRK4 run of the skew/axial/pocket motion at one frozen load state and spin ``w``
    [rad/s] with spin stiffness ``k`` [N m s] (raceway damping of the pocket motion) and
    quasi-static pocket force ``f_d`` [N]: (post-processed samples, right-hand-side calls).
    The step: 1/``steps_per_period`` spin period, at most 1/:func:`explicit_rate`.
    ConvergenceError if it diverges."""
    h_max = 1.0 / explicit_rate(m, n_i, n_o)
    period = 2.0 * math.pi / max(abs(w), 1.0)
    n_per = max(steps_per_period, int(math.ceil(period / h_max)))
    h = period / n_per
    n_warm = int(round(warmup_periods * n_per))
    n_keep = int(round(periods * n_per))
    every = max(1, n_per // samples_per_period)
    z0 = math.copysign(0.5 * m.pocket_clearance, f_d) if m.pocket_dof else 0.0
    rows = _etd_frozen(c, float(n_i), float(n_o), float(w), float(f_d), pocket_rate(m, k),
                       z0, h, n_warm, n_keep, every)
    if not np.all(np.isfinite(rows)):
        raise ConvergenceError("roller_dynamics.reduced", float("inf"),
                               "ETDRK4 diverged (reduce the step: steps_per_period)",
                               {"state": (n_i, n_o, w)})
    spin = np.full(rows.shape[0], w)
    post = _post(m, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4], spin,
                 rows[:, 5], rows[:, 6], f_d)
    return post, 4 * (n_warm + n_keep)


@njit(cache=True)
def _etd_frozen(p: np.ndarray, n_i: float, n_o: float, spin: float, f_d: float, lam: float,
                z0: float, h: float, n_warm: int, n_keep: int, every: int) -> np.ndarray:
    """Fixed-step ETDRK4 (Cox & Matthews 2002 eq. 26, :mod:`~thermobearing.skidding.
    roller_dynamics_etd`) at a frozen load state; returns (n_keep // every, 7) rows
    (t, X, X', alpha, alpha', z, z') after ``n_warm`` discarded steps (start at z0).

    y = (X, X', alpha, alpha', z, z'); y' = L y + N(t, y) with L = diag(0, 0, 0, 0, 0, lam),
    lam = -c_z/m [1/s] the pocket's raceway damping (:func:`pocket_rate`) and N the right-hand
    side :func:`~thermobearing.skidding.roller_dynamics_rhs._rhs` with c_z = 0 (exactly the
    rest, no cancellation). Per component u the stages

        a = E2 u + Q N(t, u),  b = E2 u + Q N(t + h/2, a),  c = E2 a + Q (2 N(b) - N(u)),
        u+ = E u + f1 N(u) + 2 f2 (N(a) + N(b)) + f3 N(c)   (N(a), N(b) at t + h/2, N(c) at t + h)

    with the coefficients of :func:`~thermobearing.skidding.roller_dynamics_etd.
    etd_coefficients`; lam = 0 gives classical RK4's (1, 1, h/2, h/6, h/6, h/6)."""
    coef = np.zeros((6, 6))
    for q in range(6):
        set_coefficients(coef, q, lam if q == 5 else 0.0, h)
    y = np.zeros(6)
    y[4] = z0
    nn = np.zeros((4, 6))
    st = np.zeros(6)
    sa = np.zeros(6)
    out = np.zeros((n_keep // every, 7))
    t = 0.0
    j = 0
    for step in range(n_warm + n_keep):
        for stage in range(4):
            tt = t + (0.0 if stage == 0 else (0.5 * h if stage < 3 else h))
            if stage == 0:
                for q in range(6):
                    st[q] = y[q]
            elif stage == 1:
                for q in range(6):
                    st[q] = coef[q, 1] * y[q] + coef[q, 2] * nn[0, q]
                    sa[q] = st[q]
            elif stage == 2:
                for q in range(6):
                    st[q] = coef[q, 1] * y[q] + coef[q, 2] * nn[1, q]
            else:
                for q in range(6):
                    st[q] = coef[q, 1] * sa[q] + coef[q, 2] * (2.0 * nn[2, q] - nn[0, q])
            r = _rhs(p, st[0], st[1], st[2], st[3], st[4], st[5], n_i, n_o, spin, spin * tt,
                     f_d, 0.0)
            for q in range(6):
                nn[stage, q] = r[q]
        for q in range(6):
            y[q] = (coef[q, 0] * y[q] + coef[q, 3] * nn[0, q]
                    + 2.0 * coef[q, 4] * (nn[1, q] + nn[2, q]) + coef[q, 5] * nn[3, q])
        t += h
        if step >= n_warm and (step - n_warm) % every == 0 and j < out.shape[0]:
            out[j, 0] = t
            for q in range(6):      # element loop: a slice assignment from an array
                out[j, 1 + q] = y[q]  # compiles numba's shape-mismatch message code
            j += 1
    return out


def _refresh_caches() -> None:
    """Flush the ETDRK4 kernel's numba cache when its inlined callees changed (rhs, rib,
    pocket, ETD-coefficient modules;
    :func:`thermobearing.contact_traction.refresh_stale_caches`)."""
    from .. import rib
    from . import roller_dynamics_etd, roller_dynamics_pocket, roller_dynamics_rhs

    refresh_stale_caches("roller_dynamics_integrate", (_etd_frozen,),
                         (roller_dynamics_rhs, rib, roller_dynamics_pocket, roller_dynamics_etd))


_refresh_caches()
