"""Tests of thermobearing.vibration (paper 004 lumped model with cage slip)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from thermobearing import signal as S
from thermobearing import vibration as V
from thermobearing.errors import ConvergenceError, InputError
from thermobearing.traction import make_traction_law

WS = 2000.0 * 2.0 * math.pi / 60.0  # paper 004: 2000 r/min
LOAD = 2000.0  # paper 004: W = 2000 N


@pytest.fixture(scope="module")
def params():
    return V.paper004_parameters()


@pytest.fixture(scope="module")
def mild():
    # paper 004 Figs. 11-13 use mu_m = 0.01; dv_m is not given in the paper (estimated)
    return make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)


def test_table1_parameters(params):
    # paper 004 Table 1
    assert params.n_balls == 7
    assert params.ball_diameter == pytest.approx(9.525e-3)
    assert params.pitch_diameter == pytest.approx(36e-3)
    assert params.radial_clearance == pytest.approx(15e-6)
    assert params.inner_ring_mass == 0.4 and params.ball_inertia == 3.18e-8
    assert params.support_damping == 350.0
    # Hertz point-contact constants of a 6304 are of order 1e10 N/m^1.5 (Harris &
    # Kotzalas 2007 vol. 1 ch. 6 example values 1e10-3e10 for 10 mm balls)
    assert 1e10 < params.outer_stiffness < params.inner_stiffness < 5e10


def test_bpfo_no_slip_formula(params):
    # paper 004 eq. 27 and section 4.3: 85.5 Hz at 2000 r/min without slip (within 0.5 %)
    f = params.ball_pass_frequency_outer(2000.0 / 60.0)
    assert f == pytest.approx(85.5, rel=5e-3)
    assert params.ball_pass_frequency_outer(2000.0 / 60.0, 0.1) == pytest.approx(0.9 * f)


@pytest.mark.parametrize("slip", [0.0, 0.1])
def test_simulated_bpfo_follows_one_minus_slip(params, mild, slip):
    # the strongest line of the ring acceleration below 1.5 BPFO is the ball pass (Fig. 11)
    r = V.simulate(params, WS, LOAD, traction=mild, cage_slip=slip, duration=0.5,
                   settle_time=0.03, sampling_rate=25600.0)
    f_th = params.ball_pass_frequency_outer(WS / (2 * math.pi), slip)
    f, _ = S.spectral_peak(r.acceleration_x, r.sampling_rate, 0.5 * f_th, 1.5 * f_th)
    assert f == pytest.approx(f_th, rel=2e-3)
    assert r.ball_pass_frequency_outer == pytest.approx(f_th, rel=1e-12)


def test_mean_ring_position_is_static_equilibrium(params, mild):
    # time-averaged ring displacement = quasi-static Hertz solution sum K (x cos - Pd)^1.5 cos = W
    # averaged over the cage positions (balls in series contact: K = (Ki^-2/3 + Ko^-2/3)^-3/2)
    r = V.simulate(params, WS, LOAD, traction=mild, duration=0.2, settle_time=0.05)
    k = (params.inner_stiffness ** (-2 / 3) + params.outer_stiffness ** (-2 / 3)) ** -1.5
    z = params.n_balls

    def static_x(phase):
        th = 2 * math.pi * np.arange(z) / z + phase

        def residual(x):
            d = np.maximum(x * np.cos(th) - params.radial_clearance, 0.0)
            return float(np.sum(k * d**1.5 * np.cos(th))) - LOAD
        return brentq(residual, 0.0, 1e-3)

    x_static = np.mean([static_x(ph) for ph in np.linspace(0, 2 * math.pi / z, 16)])
    assert np.mean(r.displacement_x) == pytest.approx(x_static, rel=0.02)
    assert abs(np.mean(r.displacement_y)) < 0.05 * x_static
    # the ring does not accelerate on average
    assert abs(np.mean(r.acceleration_x)) < 0.05 * np.std(r.acceleration_x)


def test_split_and_rk4_agree(params):
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.1)
    kw = dict(traction=law, cage_slip=0.05, duration=0.01, settle_time=0.03)
    a = V.simulate(params, WS, LOAD, method="rk4", max_step=1.25e-6, **kw)
    b = V.simulate(params, WS, LOAD, method="split", max_step=2.5e-6, **kw)
    scale = np.max(np.abs(a.acceleration_x))
    assert np.max(np.abs(a.acceleration_x - b.acceleration_x)) < 1e-3 * scale


def test_paper_step_is_unstable_for_table1_bearing(params, mild):
    # the ball between two Hertz contacts rings at ~2.9e5 rad/s: omega h = 2.9 at 1e-5 s,
    # outside RK4's stability interval (2.83 on the imaginary axis)
    rep = V.stability_report(params, LOAD, mild)
    assert rep.ball_radial * 1e-5 > 2.83
    with pytest.raises(ConvergenceError):
        V.simulate(params, WS, LOAD, traction=mild, method="rk4", max_step=1e-5,
                   duration=0.02, settle_time=0.0)


def test_exact_spin_flow_matches_ode():
    # J w' = T(w) with frozen loads: compare the piecewise-exponential flow with a tight
    # numerical solution (Radau) of the same scalar ODE
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.05)
    tv, tmu = V.traction_table(law, 10.0)
    a_i, a_o, q_i, q_o, r, half_d, jr = 2.0, 2.1, 900.0, 950.0, 4.76e-3, 4.76e-3, 3.18e-8

    def torque(w):
        return V._torque(w, a_i, a_o, q_i, q_o, r, half_d, tv, tmu)

    for w0 in (300.0, 430.0, 600.0):
        for tau in (1e-7, 2e-6, 1e-4):
            exact = V._spin_flow(w0, tau, a_i, a_o, q_i, q_o, r, half_d, jr, tv, tmu)
            sol = solve_ivp(lambda t, w: [torque(w[0]) / jr], (0, tau), [w0], method="Radau",
                            rtol=1e-11, atol=1e-9)
            assert exact == pytest.approx(sol.y[0, -1], rel=1e-7, abs=1e-6)


def test_fig12_trend_rms_falls_with_slip(params, mild):
    # paper 004 Fig. 12(b): RMS of the x acceleration falls with the cage slip (mu_m = 0.01)
    rms = [V.simulate(params, WS, LOAD, traction=mild, cage_slip=s, duration=0.25,
                      settle_time=0.03).statistics_x.rms for s in (0.0, 0.05, 0.1)]
    assert rms[0] > rms[1] > rms[2]


def test_statistics_definitions():
    t = np.linspace(0, 1, 10001)[:-1]
    x = np.sin(2 * np.pi * 5 * t)
    st = V.statistics(x)
    assert st.ptp == pytest.approx(2.0, rel=1e-6)
    assert st.rms == pytest.approx(1 / math.sqrt(2), rel=1e-6)
    assert st.kurtosis == pytest.approx(1.5, rel=1e-6)  # sine: 3/2
    with pytest.raises(InputError):
        V.statistics(np.ones(100))


def test_off_size_ball_puts_cage_line_in_signal(params, mild):
    # one ball 2 um oversize: its passage modulates the ball pass at f_cage
    p = V.VibrationParameters(**{**params.__dict__,
                                 "ball_diameter_deviation": (2e-6,) + (0.0,) * 6})
    r = V.simulate(p, WS, LOAD, traction=mild, cage_slip=0.05, duration=1.0,
                   settle_time=0.03, sampling_rate=25600.0)
    fc = r.cage_speed / (2 * math.pi)
    f, _ = S.spectral_peak(r.acceleration_x, r.sampling_rate, 0.7 * fc, 1.3 * fc)
    assert f == pytest.approx(fc, rel=5e-3)


def test_bad_inputs(params, mild):
    with pytest.raises(InputError):
        V.simulate(params, -1.0, LOAD, traction=mild)
    with pytest.raises(InputError):
        V.simulate(params, WS, LOAD, traction=mild, cage_slip=1.2)
    with pytest.raises(InputError):
        V.simulate(params, WS, LOAD, traction=mild, method="euler")
    with pytest.raises(InputError):
        V.simulate(params, WS, LOAD, traction=mild, cage_speed=2 * WS)
    with pytest.raises(InputError):
        V.VibrationParameters(**{**params.__dict__, "ball_diameter_deviation": (1e-6,)})
    eyring = type("FilmLaw", (), {"requires_film": True})()
    with pytest.raises(InputError):
        V.traction_table(eyring, 1.0)


@pytest.mark.parametrize("slip", [-0.12, 0.0, 0.2, 0.4, 0.6])
def test_round_trip_csr_at_0db(params, mild, slip):
    # issue 8: simulated signals with known slip from -12 % (over-skidding) to +60 %, white
    # noise of the signal's power (SNR 0 dB): the analyser recovers the CSR within 0.5 %
    fs = 25600.0
    r = V.simulate(params, WS, LOAD, traction=mild, cage_slip=slip, duration=1.0,
                   settle_time=0.03, sampling_rate=fs)
    a = r.acceleration_x - r.acceleration_x.mean()
    rng = np.random.default_rng(int(round(1000 * (slip + 1))))
    x = a + rng.normal(scale=np.sqrt(np.mean(a * a)), size=a.size)
    est = S.estimate_cage_speed(x, fs, WS / (2 * math.pi), params.n_balls,
                                params.theoretical_cage_speed_ratio)
    csr_true = r.cage_speed / WS
    assert est.detected, est.reason
    assert abs(est.csr / csr_true - 1) < 0.005
    assert est.slip == pytest.approx(slip, abs=0.005)


def test_closed_loop_with_skidding_solver(params, mild):
    # issue 8 item 3: cage speed from the skidding solver (SKF 6304, ISO VG 68 at 50 degC,
    # jet 0.5 L/min: estimated conditions, paper 004 names no oil), vibration simulated with
    # it, acceleration + 0 dB noise through the analyser: the solver's CSR comes back
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.state import OilSupply

    fs = 25600.0
    supply = OilSupply("jet", 0.5e-3 / 60.0, 323.15)
    r, sk = V.simulate_with_skidding(load_bearing("SKF6304"), load_lubricant("ISO_VG68"), WS,
                                     LOAD, 323.15, supply=supply, traction=mild, params=params,
                                     duration=1.0, settle_time=0.03, sampling_rate=fs)
    assert sk.converged
    assert r.cage_speed == pytest.approx(sk.cage_speed_ratio * WS, rel=1e-12)
    a = r.acceleration_x - r.acceleration_x.mean()
    x = a + np.random.default_rng(4).normal(scale=np.sqrt(np.mean(a * a)), size=a.size)
    est = S.estimate_cage_speed(x, fs, WS / (2 * math.pi), params.n_balls,
                                params.theoretical_cage_speed_ratio)
    assert est.detected
    assert est.csr == pytest.approx(sk.cage_speed_ratio, rel=5e-3)


def test_sunnersjo_model_equilibrium_and_ball_pass(params):
    # Sunnersjo 1978: massless balls at pure rolling; the acceleration averages to zero and
    # its main low-frequency line is the ball pass Z f_c (85.8 Hz here)
    fs = 25600.0
    a = V.simulate_sunnersjo(params, WS, LOAD, duration=0.5, sampling_rate=fs)
    assert abs(a.mean()) < 0.05 * a.std()
    f_bp = params.ball_pass_frequency_outer(WS / (2 * math.pi))
    f, _ = S.spectral_peak(a, fs, 0.5 * f_bp, 1.5 * f_bp)
    assert f == pytest.approx(f_bp, rel=2e-3)


def test_unbalance_puts_shaft_line_in_signal(params, mild):
    # a rotating force m_u e omega_s^2 (here 1e-4 kg m: 4.4 N at 2000 r/min) at f_s
    p = V.VibrationParameters(**{**params.__dict__, "unbalance": 1e-4})
    r = V.simulate(p, WS, LOAD, traction=mild, duration=1.0, settle_time=0.03,
                   sampling_rate=25600.0)
    fsh = WS / (2 * math.pi)
    f, amp = S.spectral_peak(r.acceleration_x, r.sampling_rate, 0.8 * fsh, 1.2 * fsh)
    assert f == pytest.approx(fsh, rel=2e-3)
    # quasi-static (f_s far below the 3 kHz ring mode): the ring follows the force through
    # the radial bearing stiffness k, so the line is omega_s^2 F / k; k from the linearised
    # Stribeck estimate of stability_report, which is rough (load zone): within a factor 2
    k = p.inner_ring_mass * V.stability_report(p, LOAD, mild).ring ** 2
    expected = WS**2 * (1e-4 * WS**2) / k
    assert 0.5 * expected < amp < 2.0 * expected


def _paper004_rhs_numpy(t, y, p, load, wc):
    """Paper 004 eqs. 11-16 and 19-21 written out independently of the compiled kernel
    (friction omitted: it vanishes at s_c = 0, see the test below)."""
    z = p.n_balls
    th = 2.0 * np.pi * np.arange(z) / z + wc * t                       # eq. 12
    d = y[4:4 + z]
    d_in = y[0] * np.cos(th) + y[1] * np.sin(th) - d - p.radial_clearance / 2   # eqs. 11, 13
    d_out = d - p.radial_clearance / 2                                   # eq. 14
    q_in = p.inner_stiffness * np.clip(d_in, 0.0, None) ** 1.5          # eqs. 15-16
    q_out = p.outer_stiffness * np.clip(d_out, 0.0, None) ** 1.5
    dy = np.zeros_like(y)
    dy[0:2] = y[2:4]
    dy[2] = (load - p.support_damping * y[2] - np.sum(q_in * np.cos(th))) / p.inner_ring_mass
    dy[3] = (-p.support_damping * y[3] - np.sum(q_in * np.sin(th))) / p.inner_ring_mass
    dy[4:4 + z] = y[4 + z:4 + 2 * z]
    dy[4 + z:4 + 2 * z] = (q_in - q_out - p.ball_damping * y[4 + z:4 + 2 * z]) / p.ball_mass
    return dy


def test_kernel_matches_independent_equations_without_slip(params, mild):
    # At s_c = 0 the ball spin of simple kinematics makes both sliding speeds of eqs. 7-8 zero,
    # so the traction (eqs. 9-10) and the spin torque (eq. 22) vanish and the model is eqs.
    # 11-16 and 19-21. A plain RK4 of those equations from the same start (ring and balls at
    # rest at zero, paper 004 section 4) must give the kernel's ring x acceleration through
    # the start transient (drop through the clearance, first contacts) to round-off.
    h, n_out, sub = 5e-6, 600, 2
    r = V.simulate(params, WS, LOAD, traction=mild, cage_slip=0.0, duration=n_out * sub * h,
                   settle_time=0.0, sampling_rate=1.0 / (sub * h), method="rk4", max_step=h)
    wc = params.theoretical_cage_speed_ratio * WS
    y = np.zeros(4 + 2 * params.n_balls)
    ax = np.empty(n_out)
    t = 0.0
    f = _paper004_rhs_numpy
    for i in range(n_out):
        ax[i] = f(t, y, params, LOAD, wc)[2]
        for _ in range(sub):
            k1 = f(t, y, params, LOAD, wc)
            k2 = f(t + h / 2, y + h / 2 * k1, params, LOAD, wc)
            k3 = f(t + h / 2, y + h / 2 * k2, params, LOAD, wc)
            k4 = f(t + h, y + h * k3, params, LOAD, wc)
            y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            t += h
    assert np.max(np.abs(ax)) > 1e3  # the transient is in the window (W/m_i = 5000 m/s^2)
    assert np.max(np.abs(r.acceleration_x - ax)) < 1e-8 * np.max(np.abs(ax))
    # friction of ball 1: zero up to the round-off of a_i - r omega_j (eqs. 7, 9)
    assert np.max(np.abs(r.first_ball_inner_friction)) < 1e-12 * np.max(r.first_ball_inner_load)


def test_rms_fall_with_slip_is_kinematic(params, mild):
    # Measured finding (validation/cases/paper004_vibration_stats/SOURCE.md): the fall of RMS
    # with cage slip (paper 004 Fig. 12b) comes from the slower cage (a slower ball pass
    # excites the ring's free vibration less), not from the friction: with mu_m -> 0 the RMS
    # falls as much, within 5 % of the mu_m = 0.01 values.
    frictionless = make_traction_law("linear_saturating", mu_max=1e-9, slip_speed_max=0.1)
    kw = dict(duration=0.25, settle_time=0.05)
    r0 = [V.simulate(params, WS, LOAD, traction=frictionless, cage_slip=s, **kw)
          .statistics_x.rms for s in (0.0, 0.05, 0.1)]
    r1 = [V.simulate(params, WS, LOAD, traction=mild, cage_slip=s, **kw)
          .statistics_x.rms for s in (0.0, 0.05, 0.1)]
    assert r0[0] > r0[1] > r0[2]
    assert r0[2] < 0.8 * r0[0]
    assert np.allclose(r0, r1, rtol=0.05)


def test_friction_drags_ring_against_rolling_and_eq20_switch(params):
    # The balls orbit towards +theta (eq. 12) and the inner-race surface moves faster than
    # the balls' (Delta v_i > 0 with cage slip, eq. 7), so the friction on the ring at the
    # loaded contacts near theta = 0 acts along -e_theta = -y: the ring's mean position moves
    # to -y (friction rotates the load line against the rolling direction). eq20_as_text
    # (diagnostic) reverses that y force, so the offset reverses; without slip there is no
    # friction and the switch changes nothing.
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.1)
    kw = dict(traction=law, duration=0.1, settle_time=0.05)
    consistent = V.simulate(params, WS, LOAD, cage_slip=0.05, **kw)
    as_text = V.simulate(params, WS, LOAD, cage_slip=0.05, eq20_as_text=True, **kw)
    y1, y2 = consistent.displacement_y.mean(), as_text.displacement_y.mean()
    assert y1 < -0.5e-6 and y2 > 0.5e-6
    # the mean friction y force of about mu sum Q ~ 0.05 * 2.3 kN rotates the line by ~2 deg
    assert abs(math.degrees(math.atan2(y1, consistent.displacement_x.mean()))) < 5.0
    a = V.simulate(params, WS, LOAD, cage_slip=0.0, **kw).acceleration_x
    b = V.simulate(params, WS, LOAD, cage_slip=0.0, eq20_as_text=True, **kw).acceleration_x
    assert np.max(np.abs(a - b)) <= 1e-9 * np.max(np.abs(a))
