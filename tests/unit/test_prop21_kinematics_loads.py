"""Property tests of the race-control kinematics at and near zero contact angle and of the
ball load distribution's Stribeck limit and ball equilibrium (session 21), beside
test_property_kinematics.py (CSR bounds, zero spin at the controlling race) and
test_prop20_hertz_loads.py (the roller's Stribeck sum).

Kinematics (:mod:`thermobearing.kinematics`, Jones 1960 / Harris & Kotzalas 2007):

- zero contact angle (a deep-groove ball or a roller): outer- and inner-race control and
  pure rolling are one motion, beta = 0, CSR = (1 - g)/2, no spin at either contact, the
  element spin omega_R = -(1 - g^2) omega / (2 g) and equal entrainment speeds at both
  contacts, u = omega d_m (1 - g^2) / 4;
- equal angles a with the attitude beta = a (pure rolling): both entrainment speeds equal
  the element's surface speed |omega_R| D / 2 = omega d_m (1 - g^2 cos^2 a) / 4 (rolling
  without slip at both contact centres);
- the limit a -> 0 is continuous: the race-control states at a = 1e-9 rad are those at 0;
- turning the outer ring adds its speed to the orbital speed and nothing else.

Load distribution (:func:`thermobearing.loads.ball_load_distribution`): a ball bearing
without clearance at rest under a pure radial load has its contact angles at zero and its
most loaded ball at Stribeck's Q_max = F_r / sum_{cos psi > 0} cos^(5/2) psi (Harris &
Kotzalas 2007 vol. 1; Z Q_max / F_r = 4.337 for the SKF6304's 7 balls, Stribeck's "5"
with clearance); measured within 6.3e-12 over 10 N-5 kN, asserted 1e-9.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing
from thermobearing.kinematics import (
    element_kinematics,
    inner_race_control,
    outer_race_control,
    pure_rolling,
)
from thermobearing.loads import ball_load_distribution

BEARINGS = {name: load_bearing(name) for name in ("SKF6304", "QJ1044", "NU214")}


def _g(bearing):
    return float(bearing.element_diameter) / float(bearing.pitch_diameter)


@settings(max_examples=30, deadline=None)
@given(name=st.sampled_from(sorted(BEARINGS)), speed=st.floats(1.0, 3000.0),
       outer=st.floats(-500.0, 500.0))
def test_zero_contact_angle_is_one_motion(name, speed, outer):
    b = BEARINGS[name]
    g = _g(b)
    dm = float(b.pitch_diameter)
    w = speed - outer
    states = [f(b, speed, 0.0, 0.0, outer_speed=outer)
              for f in (outer_race_control, inner_race_control, pure_rolling)]
    for k in states:
        assert float(k.attitude_angle) == 0.0
        assert float(k.cage_speed_ratio) == pytest.approx((1.0 - g) / 2.0, rel=1e-14)
        assert float(k.orbital_speed) == pytest.approx(outer + w * (1.0 - g) / 2.0, rel=1e-13,
                                                       abs=1e-12 * abs(speed))
        assert abs(float(k.spin_inner)) <= 1e-13 * abs(w)
        assert abs(float(k.spin_outer)) <= 1e-13 * abs(w)
        assert float(k.element_spin) == pytest.approx(-(1.0 - g * g) * w / (2.0 * g),
                                                      rel=1e-13)
        u = abs(w) * dm * (1.0 - g * g) / 4.0
        assert float(k.entrainment_inner) == pytest.approx(u, rel=1e-13)
        assert float(k.entrainment_outer) == pytest.approx(u, rel=1e-13)


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(["SKF6304", "QJ1044"]), a=st.floats(0.0, 1.4),
       speed=st.floats(1.0, 3000.0))
def test_pure_rolling_entrainment_is_the_element_surface_speed(name, a, speed):
    b = BEARINGS[name]
    g = _g(b)
    k = element_kinematics(b, speed, a, a, attitude=a)
    surface = abs(float(k.element_spin)) * float(b.element_diameter) / 2.0
    u = speed * float(b.pitch_diameter) * (1.0 - (g * math.cos(a)) ** 2) / 4.0
    assert float(k.entrainment_inner) == pytest.approx(surface, rel=1e-12)
    assert float(k.entrainment_outer) == pytest.approx(surface, rel=1e-12)
    assert surface == pytest.approx(u, rel=1e-12)


@settings(max_examples=20, deadline=None)
@given(name=st.sampled_from(["SKF6304", "QJ1044"]), speed=st.floats(1.0, 3000.0),
       control=st.sampled_from([outer_race_control, inner_race_control]))
def test_race_control_is_continuous_at_zero_angle(name, speed, control):
    b = BEARINGS[name]
    k0 = control(b, speed, 0.0, 0.0)
    k1 = control(b, speed, 1e-9, 1e-9)
    for field in ("cage_speed_ratio", "element_spin", "entrainment_inner", "entrainment_outer",
                  "attitude_angle"):
        v0, v1 = float(getattr(k0, field)), float(getattr(k1, field))
        assert abs(v1 - v0) <= 1e-8 * max(1.0, abs(v0)), field
    for field in ("spin_inner", "spin_outer"):
        assert abs(float(getattr(k1, field))) <= 1e-8 * speed, field


@settings(max_examples=30, deadline=None)
@given(name=st.sampled_from(["SKF6304", "QJ1044"]), ai=st.floats(0.0, 1.3),
       ao=st.floats(0.0, 1.3), speed=st.floats(1.0, 3000.0), outer=st.floats(-500.0, 500.0),
       control=st.sampled_from([outer_race_control, inner_race_control]))
def test_turning_the_outer_ring_adds_its_speed_to_the_orbit(name, ai, ao, speed, outer, control):
    b = BEARINGS[name]
    rel = control(b, speed - outer, ai, ao)
    k = control(b, speed, ai, ao, outer_speed=outer)
    assert float(k.orbital_speed) == pytest.approx(float(rel.orbital_speed) + outer, rel=1e-12,
                                                   abs=1e-12 * (abs(speed) + abs(outer)))
    for field in ("cage_speed_ratio", "element_spin", "spin_inner", "spin_outer",
                  "entrainment_inner", "entrainment_outer"):
        v, v_rel = float(getattr(k, field)), float(getattr(rel, field))
        assert v == pytest.approx(v_rel, rel=1e-12, abs=1e-12 * (abs(speed) + abs(outer))), \
            field


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(log_load=st.floats(1.0, 3.7))
def test_ball_stribeck_sum_without_clearance(log_load):
    b = BEARINGS["SKF6304"].with_clearance(0.0)
    fr = 10.0**log_load
    ld = ball_load_distribution(b, fr, 0.0)
    assert ld.converged
    z = b.n_elements
    c = np.cos(2.0 * math.pi * np.arange(z) / z)
    q_max = fr / float(np.sum(c[c > 1e-12] ** 2.5))
    assert np.max(np.abs(np.asarray(ld.inner_contact_angle))) <= 1e-12
    assert float(np.max(ld.inner_load)) == pytest.approx(q_max, rel=1e-9)
    assert z * q_max / fr == pytest.approx(4.3373, abs=1e-4)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(["SKF6304", "QJ1044"]), log_fr=st.floats(1.0, 4.0),
       log_fa=st.floats(0.0, 3.5), negative=st.booleans(), speed=st.floats(0.0, 1.0))
def test_every_ball_is_in_equilibrium_with_its_centrifugal_force(name, log_fr, log_fa,
                                                                 negative, speed):
    """Each ball of the quasi-static distribution (no gyroscopic moment): the arc forces
    -Q n and the centrifugal force m omega_m^2 r_b (radially outward) add up to zero, from
    the returned contact field only (measured 1.4e-9 of the largest force over 60 random
    states to 20000 r/min (SKF6304) / 5000 r/min (QJ1044); the solver's tolerance is 1e-9 of
    its load scale)."""
    b = BEARINGS[name]
    fa = 10.0**log_fa * (-1.0 if negative and name == "QJ1044" else 1.0)
    rpm = speed * (20000.0 if name == "SKF6304" else 5000.0)
    ld = ball_load_distribution(b, 10.0**log_fr, fa, rpm * math.pi / 30.0)
    assert ld.converged
    c = ld.contacts
    fx = -np.sum(c.load * c.normal_x, axis=1)
    fr = -np.sum(c.load * c.normal_r, axis=1) + np.asarray(ld.centrifugal_force)
    scale = float(np.max(c.load) + np.max(ld.centrifugal_force))
    assert float(np.max(np.abs(fx))) <= 1e-7 * scale
    assert float(np.max(np.abs(fr))) <= 1e-7 * scale
