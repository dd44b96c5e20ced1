"""Property tests, round 6: dimensional similarity of the paper 004 vibration model
(:func:`thermobearing.vibration.simulate`, session 24), beside the force balance and the
quasi-static mean of test_prop20_vibration.py and the record statistics of
test_prop23_vibration.py.

The model (paper 004 eqs. 4-22) holds no dimensioned constant of its own: with a time scale
1/s, a length scale L and a force scale F, the bearing with

    D, d_m, P_d, deviations -> L (.);     K_i, K_o -> K F / L^1.5;
    m_i, m_r -> m F / (L s^2);            J_r -> J F L / s^2;      c -> c F / (L s);
    m_u e -> m_u e F / s^2;               W -> F W;                omega_s -> s omega_s;
    traction slip speed dv_m -> L s dv_m (mu unchanged);
    duration, settle time, step -> (.) / s;  sampling rate -> s (.)

moves as the first one does at the times t / s: x -> L x, a -> L s^2 a, Q and F -> F (.)
(Buckingham's pi theorem: every term of the equations of motion scales by F, the Hertz law
Q = K delta^1.5 included; the sliding speeds of eqs. 4-8 by L s; the centrifugal force
m_r omega_c^2 d_m / 2 by F). With s, L^(1/2) and F powers of two every scaled input is exact
in floating point and every operation of the integrators (products, quotients, delta
sqrt(delta), the exact spin sub-flow exp(-lambda h) with lambda h unchanged) is exactly
scaled too, so the records agree to the last bit whatever the round-off of the CPU: this
matters, the model amplifies round-off at the contacts' opening and closing (a relative
4e-16 on the load moved the record by up to 9e-5 of its peak; scratch), so factors that are
not powers of two agree only to 5e-5 of the peak (60 draws, scratch). Measured with powers
of two: identical records (difference 0) for 150 draws, both integrators, point-sampled and
anti-aliased records, with off-size balls, an unbalance and the centrifugal force.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing import vibration as V
from thermobearing.errors import ValidityWarning
from thermobearing.traction import make_traction_law

BASE = V.paper004_parameters()


def _scaled(p: V.VibrationParameters, s: float, L: float, F: float) -> V.VibrationParameters:
    return dataclasses.replace(
        p, ball_diameter=L * p.ball_diameter, pitch_diameter=L * p.pitch_diameter,
        radial_clearance=L * p.radial_clearance,
        inner_stiffness=p.inner_stiffness * F / L**1.5,
        outer_stiffness=p.outer_stiffness * F / L**1.5,
        inner_ring_mass=p.inner_ring_mass * F / (L * s * s),
        ball_mass=p.ball_mass * F / (L * s * s), ball_inertia=p.ball_inertia * F * L / (s * s),
        support_damping=p.support_damping * F / (L * s),
        ball_damping=p.ball_damping * F / (L * s),
        ball_diameter_deviation=tuple(L * d for d in p.ball_diameter_deviation),
        unbalance=p.unbalance * F / (s * s))


@st.composite
def cases(draw):
    z = BASE.n_balls
    dev = () if draw(st.booleans()) else tuple(
        draw(st.lists(st.floats(-3e-6, 3e-6), min_size=z, max_size=z)))
    p = dataclasses.replace(BASE, radial_clearance=draw(st.floats(0.0, 3e-5)),
                            ball_diameter_deviation=dev,
                            unbalance=draw(st.sampled_from([0.0, 1e-5, 1e-4])),
                            centrifugal=draw(st.booleans()))
    run = {"shaft_speed": draw(st.floats(100.0, 400.0)),
           "radial_load": draw(st.floats(200.0, 5000.0)),
           "cage_slip": draw(st.floats(-0.1, 0.3)),
           "mu": draw(st.floats(0.005, 0.1)),
           # steep (split scheme, stiff spins) to mild (RK4)
           "dv_m": 10.0 ** draw(st.floats(-3.0, -0.7)),
           "method": draw(st.sampled_from(["auto", "rk4", "split"])),
           "anti_alias": draw(st.booleans())}
    return p, run


def _simulate(p, run, s=1.0, L=1.0, F=1.0):
    law = make_traction_law("linear_saturating", mu_max=run["mu"],
                            slip_speed_max=L * s * run["dv_m"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return V.simulate(p, s * run["shaft_speed"], F * run["radial_load"], traction=law,
                          cage_slip=run["cage_slip"], duration=0.01 / s, settle_time=0.01 / s,
                          sampling_rate=50_000.0 * s, max_step=1e-6 / s,
                          method=run["method"], anti_alias=run["anti_alias"])


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases(), st.integers(-3, 3), st.integers(-2, 2), st.integers(-4, 4))
def test_a_similar_bearing_moves_alike(case, i, j, k):
    p, run = case
    s, L, F = 2.0**i, 4.0**j, 2.0**k
    a = _simulate(p, run)
    b = _simulate(_scaled(p, s, L, F), run, s, L, F)
    assert a.method == b.method and a.step == b.step * s
    np.testing.assert_array_equal(b.time * s, a.time)
    pairs = {"acceleration_x": L * s * s, "acceleration_y": L * s * s, "displacement_x": L,
             "displacement_y": L, "first_ball_inner_load": F, "first_ball_inner_friction": F}
    for name, unit in pairs.items():
        got, ref = getattr(b, name) / unit, getattr(a, name)
        peak = float(np.max(np.abs(ref)))
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * peak, err_msg=name)
    assert b.cage_speed == a.cage_speed * s


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0.0, 3e-5), st.floats(100.0, 400.0), st.floats(200.0, 5000.0),
       st.integers(-3, 3), st.integers(-2, 2), st.integers(-4, 4))
def test_sunnersjos_model_is_similar_too(clearance, speed, load, i, j, k):
    """Sunnersjo's varying-compliance model (the reference of paper 004's Table 2) under the
    same scaling: a -> L s^2 a. Its series constant (K_i^-2/3 + K_o^-2/3)^-3/2 is a power
    that is exact only to an ulp under the scaling, so to 1e-9 of the peak (measured at most
    1.5e-12 of the peak on 200 draws, scratch)."""
    s, L, F = 2.0**i, 4.0**j, 2.0**k
    p = dataclasses.replace(BASE, radial_clearance=clearance)
    a = V.simulate_sunnersjo(p, speed, load, duration=0.01, settle_time=0.01,
                             sampling_rate=50_000.0, max_step=2e-6)
    b = V.simulate_sunnersjo(_scaled(p, s, L, F), s * speed, F * load, duration=0.01 / s,
                             settle_time=0.01 / s, sampling_rate=50_000.0 * s,
                             max_step=2e-6 / s)
    peak = float(np.max(np.abs(a)))
    np.testing.assert_allclose(b / (L * s * s), a, rtol=0, atol=1e-9 * peak)
