"""Lumped-parameter vibration model of a radially loaded ball bearing with cage slip.

Model of Luo et al. 2022 (seed paper 004, ``../shared/seeds/004_0105d7aba121b014.txt``):

* inner ring: two translations x, y (mass m_i, support damping c), radial load W along +x;
* every ball j: radial displacement d_j (mass m_r, damping c) and spin omega_j (inertia J_r);
* balls at theta_j = 2 pi (j - 1)/Z + omega_ca t (eq. 12), omega_ca = (1 - s_c) omega_ct
  (eqs. 1-3), i.e. the cage speed is *given* (from a slip or from the skidding solver);
* Hertz contacts with clearance and loss of contact (eqs. 11-16):
  delta_in = x cos theta + y sin theta - d_j - P_d/2, delta_out = d_j - P_d/2,
  Q = K max(delta, 0)^1.5 for each contact separately;
* sliding speeds (eqs. 4-8): dv_i = (omega_s - omega_ca) d_m (1 - gamma)/2 - omega_j r,
  dv_o = omega_ca d_m (1 + gamma)/2 - omega_j r, r = D cos(alpha)/2;
* friction F = mu(|dv|) Q sign(dv) (eqs. 9-10) with a traction law of
  :mod:`thermobearing.traction` (paper 004: ``linear_saturating``, Fig. 3);
* equations of motion (eqs. 17-22):
  m_i x'' + c x' + sum Q_in cos theta - sum F_in sin theta = W,
  m_i y'' + c y' + sum Q_in sin theta + sum F_in cos theta = 0,
  m_r d_j'' + c d_j' + Q_out - Q_in = 0,   J_r omega_j' = (F_in + F_out) D/2.

Sign note (eqs. 18-20): the friction on the ball at the inner contact points along the
orbital direction e_theta = (-sin theta, cos theta) when Delta v_i > 0; its reaction drags the
ring, F_in (sin theta, -cos theta). That is eq. 19 (N_x - F_x with F_x = sum F_in sin theta)
and eq. 20 with F_y = -sum F_in cos theta; the consistent form is used here. The seed's text
drops every minus sign (eq. 1 reads "(1 D/d_m cos alpha)"), so whether the paper prints
F_y = + or - sum F_in cos theta cannot be told from it. ``simulate(..., eq20_as_text=True)``
takes the + sign (the friction then pushes the ring along the rolling direction: physically
inconsistent) as a diagnostic only: with it, the kurtosis rises with slip and with mu_m as
paper 004's Fig. 12 says, and with the consistent sign it does not (measured,
``validation/cases/paper004_vibration_stats/SOURCE.md``).

Contact switch (eq. 15): the paper writes one coefficient lambda_j = 1 only if BOTH
deformations are positive. Read literally, a ball that is not already pressed into the outer
race is never loaded: from the paper's start (everything at zero) no contact ever closes and the
ring falls through the bearing (measured with an independent script, SOURCE.md). Each contact
is therefore switched on its own (delta > 0), which is what eq. 15's sentence "contact
deformation is not allowed to be below zero" asks for.

Optional extensions (off by default, so the paper's model is the default): per-ball diameter
deviations (off-size balls, paper 004 introduction refs 10-14: they put the cage frequency
into the signal), a rotating unbalance force at the shaft frequency and the centrifugal
force of the balls.

Integrators
-----------
``rk4``: classical Runge-Kutta at a fixed step (the paper's method, 1e-5 s).
``split``: Strang splitting (Strang 1968, SIAM J. Numer. Anal. 5: 506): the ball-spin
equations, the stiff part, are advanced over half steps by their *exact* solution with the
contact loads frozen (the torque is piecewise linear in omega_j because the traction law
is tabulated piecewise linearly, so the flow is a chain of exponentials); the mechanical
degrees of freedom take a full RK4 step with the spins frozen. Stability argument: the spin
relaxation rate lambda = (d mu/d dv)(Q_in + Q_out) r D/(2 J_r) reaches 1e6-1e7 1/s for the
paper's bearing (|lambda| h = 10-100 at 1e-5 s, outside RK4's stability interval
[-2.79, 0]), so plain RK4 at 1e-5 s chatters in the spins unless the traction slope is
small; the exact sub-flow is unconditionally stable and monotone. The remaining explicit
part is oscillatory with the largest frequency of the ball between its two contacts
(``stability_report``); RK4 is stable for omega h < 2.83. The scheme is second order
overall. Both share one right-hand side (numba).

Measured (``benchmarks/bm8_vibration.py``, SKF 6304, 2000 r/min, 2000 N, s_c = 5 %): RK4 at the
paper's 1e-5 s diverges from rest (ball radial mode: at s_c = 0 the start transient's ball-load
overshoot, 3991 N against 1481 N steady, puts omega h at 3.49; at the steady loads it is 2.96,
marginal, and a settled record at 1e-5 s equals the converged one; paper004_vibration_stats
SOURCE.md, "Last check"). With the paper's mild slope (mu_m = 0.01, dv_m = 0.1 m/s) both
schemes are limited by the same mechanical error and RK4 is 1.3-1.4
times cheaper at equal accuracy (the cost of the exact spin flows); with a steep slope (mu_m =
0.05, dv_m = 0.01 m/s) RK4 needs 3e-7 s and the split scheme is 4-7 times cheaper at errors of
1e-4-1e-3 (CPU time, one run; the ratios move by some 20 % between runs on a shared machine).
``method="auto"`` picks between them from :func:`stability_report`.

Example (issue 8's loop: simulate a slipping bearing, measure its cage speed back)::

    from thermobearing import signal as S, vibration as V
    from thermobearing.traction import make_traction_law
    p = V.paper004_parameters(ball_diameter_deviation=(2e-6,) + (0.0,) * 6)  # one big ball
    law = make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)
    r = V.simulate(p, 188.5, 2000.0, traction=law, cage_slip=0.08, duration=2.0,
                   sampling_rate=25600.0, anti_alias=True)  # 1800 r/min, 2000 N, as a DAQ
    r.statistics_x  # PTP, RMS, kurtosis [m/s^2, m/s^2, -] (paper 004 Table 2's indicators)
    est = S.estimate_cage_speed(r.acceleration_x, r.sampling_rate, 30.0, p.n_balls,
                                p.theoretical_cage_speed_ratio)
    est.csr, est.slip  # 0.3383, 0.080 ((1 - 0.08) x 0.3677)

Modules: :mod:`thermobearing.vibration_params` (parameter set, traction table),
:mod:`thermobearing.vibration_kernels` (compiled right-hand side and integrators),
:mod:`thermobearing.vibration_results` (result type, statistics, spectrum); this module keeps
the stability estimate and the drivers :func:`simulate` / :func:`simulate_with_skidding` and
re-exports the names of all three.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from .errors import InputError, ValidityWarning, check_positive, check_range

# split modules (names re-exported: callers import them from here)
from .vibration_kernels import (  # noqa: F401
    _C,
    _CB,
    _CF,
    _COSA,
    _D,
    _DM,
    _FYS,
    _J,
    _KI,
    _KO,
    _MI,
    _MR,
    _PD,
    _UNB,
    _W,
    _WC,
    _WS,
    _Z,
    _integrate,
    _loads,
    _mu_signed,
    _rhs,
    _spin_flow,
    _spin_sub,
    _torque,
)
from .vibration_params import VibrationParameters, paper004_parameters, traction_table
from .vibration_results import (
    VibrationResult,
    VibrationStatistics,
    amplitude_spectrum,
    statistics,
)

__all__ = [
    "StabilityReport",
    "VibrationParameters",
    "VibrationResult",
    "VibrationStatistics",
    "amplitude_spectrum",
    "paper004_parameters",
    "simulate",
    "simulate_sunnersjo",
    "simulate_with_skidding",
    "stability_report",
    "statistics",
    "traction_table",
]

METHODS = ("auto", "split", "rk4")


@dataclass(frozen=True)
class StabilityReport:
    """Largest rates of the linearised model at the static load [1/s].

    ball_radial : sqrt((k_in + k_out)/m_r) of the most loaded ball [rad/s].
    ring : sqrt(k_ring/m_i), k_ring the radial stiffness of the ring [rad/s].
    spin : (d mu / d dv) (Q_in + Q_out) r D / (2 J_r) of the most loaded ball [1/s].
    damping : c / m_r [1/s]. rk4_max_step : 2.79 / max(|rates|) [s] (RK4 stability bound
    on the real axis; 2.83 on the imaginary axis).
    """

    ball_radial: float
    ring: float
    spin: float
    damping: float
    rk4_max_step: float
    split_max_step: float


def stability_report(params: VibrationParameters, radial_load: float,
                     traction: Any) -> StabilityReport:
    """Stiffness of the model from a static (Stribeck-type) load estimate.

    Q_max ~ 5 W / (Z cos alpha) (Stribeck; Harris & Kotzalas 2007 vol. 1 ch. 7); the contact
    stiffness dQ/d delta = 1.5 K^(2/3) Q^(1/3); the inner and the outer contact act in
    series on the ring and in parallel on the ball.
    """
    check_positive("radial_load", radial_load)
    q = 5.0 * radial_load / (params.n_balls * math.cos(params.contact_angle))
    ki = 1.5 * params.inner_stiffness ** (2 / 3) * q ** (1 / 3)
    ko = 1.5 * params.outer_stiffness ** (2 / 3) * q ** (1 / 3)
    w_ball = math.sqrt((ki + ko) / params.ball_mass)
    k_series = ki * ko / (ki + ko)
    w_ring = math.sqrt(2.0 * k_series / params.inner_ring_mass)
    tv, tmu = traction_table(traction, 10.0)
    slope = float(np.max(np.diff(tmu) / np.diff(tv))) if tv.size > 1 else 0.0
    r = 0.5 * params.ball_diameter * math.cos(params.contact_angle)
    spin = slope * 2.0 * q * r * params.ball_diameter / (2.0 * params.ball_inertia)
    damp = params.ball_damping / params.ball_mass
    rk4 = 2.79 / max(w_ball, spin, damp, w_ring)
    split = 2.79 / max(w_ball, damp, w_ring)
    return StabilityReport(w_ball, w_ring, spin, damp, rk4, split)


def simulate(params: VibrationParameters, shaft_speed: float, radial_load: float, *,
             traction: Any, cage_slip: float = 0.0, cage_speed: float | None = None,
             duration: float = 0.25, settle_time: float = 0.05,
             sampling_rate: float = 100_000.0, method: str = "auto",
             max_step: float | None = None, eq20_as_text: bool = False,
             anti_alias: bool = False) -> VibrationResult:
    """Integrate the paper 004 model and return the ring acceleration.

    Parameters
    ----------
    params : :class:`VibrationParameters`.
    shaft_speed : omega_s of the inner ring [rad/s] (> 0).
    radial_load : W [N] (> 0), along +x.
    traction : a traction law of :mod:`thermobearing.traction` (pressure-independent),
        e.g. ``make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)``.
    cage_slip : s_c [-] in (-1, 1) (paper 004 eq. 3: omega_ca = (1 - s_c) omega_ct);
        negative is over-skidding. Ignored when ``cage_speed`` is given.
    cage_speed : omega_ca [rad/s], e.g. from the skidding solver (CSR * omega_s).
    duration : recorded time after settling [s]; settle_time : discarded start [s]
        (the ring starts at rest at x = y = 0, the balls at d = 0 with the spin of eq. 4-8
        balance, as in paper 004 section 4).
    sampling_rate : output rate [Hz]; the step is 1/(sampling_rate k) with the smallest
        integer k that keeps it <= ``max_step`` [s]. The samples are the model state at
        those instants (point sampling, as paper 004's statistics are computed): the
        model rings at the ball's radial frequency between its contacts (tens of kHz,
        :func:`stability_report`), so at a rate below twice that frequency the record holds
        alias lines -- a ``ValidityWarning`` says so. Use ``anti_alias=True`` for a record as
        a data-acquisition system with an anti-aliasing filter takes it (e.g. to feed
        :func:`thermobearing.signal.estimate_cage_speed`: a point-sampled 25.6 kHz record
        of an off-size ball made it report half or a third of the cage speed).
    anti_alias : record at an integer multiple q of ``sampling_rate`` that is at least 2.5
        times the ball's radial frequency and reduce to ``sampling_rate`` with a zero-phase
        low-pass FIR (``scipy.signal.resample_poly``, Kaiser window): accelerations and
        displacements are filtered, the ball-1 load and friction are taken every q-th
        sample. Default False (point sampling, the validated statistics).
    method : "split", "rk4" (paper 004's scheme) or "auto": RK4 when its stability bound
        (:func:`stability_report`) is at least half that of the split scheme (a mild traction
        slope: RK4 is fourth order and cheaper at equal accuracy), else "split" (a steep
        traction slope makes the spin equations stiff; see the module notes and bm8).
    max_step : [s]; None: 1e-5 s (paper 004) or 0.85 times the explicit stability bound of
        :func:`stability_report` for the method, whichever is smaller.
    eq20_as_text : diagnostic only (default False). True reverses the sign of the y component
        of the inner-contact friction on the ring, i.e. eq. 20 read as the seed's text shows it
        (N_y - F_y with F_y = + sum F_in cos theta): the friction then pushes the ring along the
        direction of rolling instead of dragging it, which is physically inconsistent (module
        notes). It exists to measure what paper 004's Fig. 12 trends would be under that
        reading (``validation/cases/paper004_vibration_stats/SOURCE.md``); never use it for
        predictions.

    Raises
    ------
    ConvergenceError : the integration diverged (a step above the stability bound).

    Warns
    -----
    ValidityWarning : a ``max_step`` that makes the step larger than the explicit stability
        bound of the method (:func:`stability_report`): RK4 above its bound for the spin
        equations chatters without diverging (measured: RMS 68 m/s^2 instead of 0.50 with a
        steep traction law at 3.3e-6 s, bound 2.7e-7 s); a point-sampled record below twice
        the ball's radial frequency (see ``sampling_rate``).
    """
    if method not in METHODS:
        raise InputError("method", method, f"one of {METHODS}")
    if not isinstance(params, VibrationParameters):  # e.g. the BallBearing itself
        raise InputError("params", type(params).__name__,
                         "a VibrationParameters (VibrationParameters.from_bearing(bearing, "
                         "inner_ring_mass=..., support_damping=...) or paper004_parameters())")
    check_positive("shaft_speed", shaft_speed)
    check_positive("radial_load", radial_load)
    check_positive("duration", duration)
    check_positive("settle_time", settle_time, allow_zero=True)
    check_positive("sampling_rate", sampling_rate)
    rep = stability_report(params, radial_load, traction)
    if method == "auto":
        method = "rk4" if rep.rk4_max_step >= 0.5 * rep.split_max_step else "split"
    if max_step is None:
        max_step = min(1e-5, 0.85 * (rep.split_max_step if method == "split"
                                     else rep.rk4_max_step))
    check_positive("max_step", max_step)
    wct = params.theoretical_cage_speed_ratio * shaft_speed
    if cage_speed is None:
        check_range("cage_slip", cage_slip, -1.0, 1.0, low_inclusive=False,
                    high_inclusive=False)
        wc = (1.0 - cage_slip) * wct
    else:
        check_range("cage_speed", cage_speed, 0.0, shaft_speed, low_inclusive=False,
                    high_inclusive=False, unit="rad/s")
        wc = float(cage_speed)
        cage_slip = 1.0 - wc / wct
    z = params.n_balls
    dev = np.zeros(z) if not params.ball_diameter_deviation else np.array(
        params.ball_diameter_deviation, dtype=float)
    tv, tmu = traction_table(traction, 2.0 * shaft_speed * params.pitch_diameter)
    P = np.array([z, params.ball_diameter, params.pitch_diameter,
                  math.cos(params.contact_angle), params.radial_clearance,
                  params.inner_stiffness, params.outer_stiffness, params.inner_ring_mass,
                  params.ball_mass, params.ball_inertia, params.support_damping,
                  params.ball_damping, shaft_speed, wc, radial_load, params.unbalance,
                  1.0 if params.centrifugal else 0.0, -1.0 if eq20_as_text else 1.0],
                 dtype=float)
    f_ball = rep.ball_radial / (2.0 * math.pi)
    q_rec = 1
    if anti_alias:
        q_rec = max(1, math.ceil(2.5 * f_ball / sampling_rate))
    elif sampling_rate < 2.0 * f_ball:
        warnings.warn(ValidityWarning(
            f"vibration.simulate: the record is point-sampled at {sampling_rate:g} Hz, below "
            f"twice the ball's radial frequency ({f_ball:.4g} Hz, stability_report): model "
            f"content above {sampling_rate / 2:g} Hz aliases into it (alias lines in a "
            "spectrum or an envelope analysis); anti_alias=True records it as a "
            "data-acquisition system with an anti-aliasing filter would"), stacklevel=2)
    dt_out = 1.0 / (sampling_rate * q_rec)
    sub = max(1, math.ceil(dt_out / max_step * (1 - 1e-12)))
    h = dt_out / sub
    bound = rep.split_max_step if method == "split" else rep.rk4_max_step
    if h > bound:
        warnings.warn(ValidityWarning(
            f"vibration.simulate: step {h:.3g} s (max_step {max_step:.3g} s) is above the "
            f"{method} stability bound {bound:.3g} s of this case (ball radial "
            f"{rep.ball_radial:.3g} rad/s, spin relaxation {rep.spin:.3g} 1/s, "
            "stability_report): the integration may diverge or, worse, chatter to a bounded "
            f"but wrong record; use max_step <= {0.85 * bound:.3g} s"
            + (" or method='split'" if method == "rk4" and rep.split_max_step > bound
               else "") + " (max_step=None picks a stable step)"), stacklevel=2)
    y = np.zeros(4 + 3 * z)
    g = params.gamma
    # spin of equal-load balance of eqs. 4-8: dv_i = -dv_o (pure rolling when s_c = 0)
    y[4 + 2 * z:] = params.pitch_diameter * ((shaft_speed - wc) * (1 - g) + wc * (1 + g)) / (
        2.0 * params.ball_diameter * math.cos(params.contact_angle))
    n_settle = int(round(settle_time * sampling_rate)) * q_rec
    n_rec = int(round(duration * sampling_rate))
    if n_rec < 4:
        raise InputError("duration", duration, f"at least 4 samples at {sampling_rate:g} Hz")
    n_rec *= q_rec
    mth = 1 if method == "split" else 0
    start = time.perf_counter()
    evals = 0
    scratch = [np.empty(max(n_settle, 1)) for _ in range(6)]
    if n_settle:
        evals += _integrate(mth, y, 0.0, h, sub, n_settle, P, dev, tv, tmu, *scratch)
    out = [np.empty(n_rec) for _ in range(6)]
    evals += _integrate(mth, y, n_settle * dt_out, h, sub, n_rec, P, dev, tv, tmu, *out)
    wall = time.perf_counter() - start
    if not np.all(np.isfinite(out[0])):
        from .errors import ConvergenceError

        raise ConvergenceError(f"vibration.{method}", math.inf,
                               f"the integration diverged (non-finite acceleration) at step "
                               f"{h:.3g} s; the {method} stability bound of this case is "
                               f"{bound:.3g} s: use max_step <= {0.85 * bound:.3g} s or "
                               "max_step=None", {"step": h, "stability": rep})
    if q_rec > 1:
        from scipy.signal import resample_poly

        out = [resample_poly(a, 1, q_rec, padtype="line") for a in out[:4]] + [
            a[::q_rec] for a in out[4:]]
        n_settle //= q_rec
        n_rec //= q_rec
        dt_out *= q_rec
    t = (n_settle + np.arange(n_rec)) * dt_out
    return VibrationResult(t, float(sampling_rate), out[0], out[1], out[2], out[3], out[4],
                           out[5], float(shaft_speed), float(wc), float(cage_slip),
                           float(radial_load), method, h, int(evals), wall, params)


def simulate_with_skidding(bearing: Any, lubricant: Any, shaft_speed: float,
                           radial_load: float, temperature: float, *, supply: Any,
                           traction: Any, params: VibrationParameters | None = None,
                           skidding_options: dict | None = None, **simulate_options: Any
                           ) -> tuple[VibrationResult, Any]:
    """Vibration of a bearing whose cage speed comes from the skidding solver.

    Calls :func:`thermobearing.skidding.solve` (quasi-dynamic traction/drag balance, axial
    load 0: the planar model of paper 004 is for radial load) and runs :func:`simulate` with
    ``cage_speed = CSR * shaft_speed``. ``params`` defaults to
    :meth:`VibrationParameters.from_bearing` with paper 004 Table 1's ring mass (0.4 kg) and
    damping (350 N s/m), which are estimates for any other bearing, and a 0 deg contact
    angle: the result's ``cage_slip`` is then against (1 - D/d_m)/2, not against the
    nominal-angle CSR_th that ``thermobearing cage-speed`` and the skidding result use (the
    cage speed itself is the solver's). Returns (vibration result,
    skidding result); raises :class:`~thermobearing.errors.ConvergenceError` when the
    skidding solver did not converge.
    """
    from . import skidding
    from .errors import ConvergenceError

    sk = skidding.solve(bearing, lubricant, shaft_speed, radial_load, 0.0, temperature,
                        supply=supply, **(skidding_options or {}))
    if not getattr(sk, "converged", False):
        raise ConvergenceError("skidding.solve", float(getattr(sk, "residual_norm", math.inf)),
                               "the cage speed for the vibration model is not available")
    if params is None:
        params = VibrationParameters.from_bearing(bearing, inner_ring_mass=0.4,
                                                  support_damping=350.0)
    result = simulate(params, shaft_speed, radial_load, traction=traction,
                      cage_speed=float(sk.cage_speed_ratio) * shaft_speed, **simulate_options)
    return result, sk


# Sunnersjo's 2-DOF reference model lives in vibration_sunnersjo.py (re-exported here)
from .vibration_sunnersjo import simulate_sunnersjo  # noqa: E402
