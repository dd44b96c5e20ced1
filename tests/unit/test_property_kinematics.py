"""Property tests: race-control kinematics and the contact traction integral.

Kinematics (:mod:`thermobearing.kinematics`, Jones 1960 / Harris & Kotzalas 2007 in the
module's re-derived form): for contact angles in [0, pi/2) and gamma' = D/d_m < 1 the cage
speed ratio of outer- and inner-race control lies in (0, 1); with equal inner and outer angles
it is (1 - g cos a)/2 whatever the attitude; the controlling race has zero spin; everything
scales linearly with the ring speed.

Contact traction (:func:`thermobearing.contact_traction.integrate`, the one code path of the
skidding solvers and the raceway heat source): the shear heat is the power of the tractions
against the relative motion, heat = -(F_y V_y + F_x V_x + M_z Omega_z + M_x Omega_x +
M_y Omega_y) >= 0 (the module's identity, exact at any node count; dissipation is never
negative), and zero load gives zero.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing import kinematics as kin
from thermobearing.contact_traction import integrate
from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.traction import make_traction_law

BEARINGS = {name: load_bearing(name) for name in ("QJ1044", "SKF6304")}
angles = st.floats(0.0, 1.5)


@settings(max_examples=80, deadline=None)
@given(g=st.floats(0.01, 0.35), ai=angles, delta=st.floats(-0.6, 0.6))
def test_race_control_csr_in_unit_interval(g, ai, delta):
    """Real bearings: gamma' = D/d_m ~0.05-0.35 and inner/outer angles that differ by a few
    tens of degrees at most (centrifugal splitting). IRC needs cos(a_i - a_o) > g cos a_o
    (else the formula's cage runs backwards: e.g. g = 0.5, a_i = 86 deg, a_o = 0 gives
    CSR < 0, a geometry no bearing has)."""
    ao = min(max(ai + delta, 0.0), 1.5)
    for control in ("outer_race", "inner_race"):
        csr = float(kin.race_control_cage_ratio(g, ai, ao, control))
        assert 0.0 < csr < 1.0


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(sorted(BEARINGS)), a=st.floats(0.0, 1.4),
       beta=st.floats(-1.5, 1.5), speed=st.floats(1.0, 2000.0))
def test_equal_angles_csr_independent_of_attitude(name, a, beta, speed):
    b = BEARINGS[name]
    g = b.ball_diameter / b.pitch_diameter
    k = kin.element_kinematics(b, speed, a, a, attitude=beta)
    assert float(k.cage_speed_ratio) == pytest.approx(0.5 * (1 - g * math.cos(a)), rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(sorted(BEARINGS)), ai=st.floats(0.0, 1.4),
       ao=st.floats(0.0, 1.4), speed=st.floats(1.0, 2000.0), factor=st.floats(0.1, 10.0))
def test_race_control_zero_spin_and_linear_in_speed(name, ai, ao, speed, factor):
    b = BEARINGS[name]
    o = kin.outer_race_control(b, speed, ai, ao)
    i = kin.inner_race_control(b, speed, ai, ao)
    scale = abs(float(o.element_spin)) + speed
    assert abs(float(o.spin_outer)) <= 1e-9 * scale
    assert abs(float(i.spin_inner)) <= 1e-9 * (abs(float(i.element_spin)) + speed)
    o2 = kin.outer_race_control(b, speed * factor, ai, ao)
    assert float(o2.cage_speed_ratio) == pytest.approx(float(o.cage_speed_ratio), rel=1e-12)
    assert float(o2.element_spin) == pytest.approx(factor * float(o.element_spin), rel=1e-9)
    for v in (o.orbital_speed, o.element_spin, o.spin_to_roll_inner, o.spin_to_roll_outer,
              o.entrainment_inner, o.entrainment_outer):
        assert math.isfinite(float(v))


@pytest.mark.parametrize("attitude", [math.nan, math.inf])
def test_attitude_must_be_finite(attitude):
    """Defect found by this test: a NaN attitude gave NaN kinematics silently and an
    infinite one a RuntimeWarning and NaN; now InputError names the attitude."""
    with pytest.raises(InputError, match="attitude"):
        kin.element_kinematics(BEARINGS["QJ1044"], 100.0, attitude=attitude)


# ------------------------------------------------------------------------- contact traction
LAW = make_traction_law("eyring_limiting_shear", lubricant=load_lubricant("ISO_VG68"))


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), n=st.integers(1, 8), t_c=st.floats(20.0, 120.0))
def test_traction_heat_is_power_of_tractions_and_non_negative(seed, n, t_c):
    rng = np.random.default_rng(seed)
    kw = dict(normal_load=rng.uniform(0.0, 5000.0, n), semi_major=rng.uniform(5e-4, 3e-3, n),
              semi_minor=rng.uniform(1e-4, 4e-4, n), sliding_speed=rng.normal(0, 0.5, n),
              transverse_sliding_speed=rng.normal(0, 0.2, n), spin_speed=rng.normal(0, 50, n),
              roll_speed=rng.normal(0, 20, n), tilt_speed=rng.normal(0, 20, n),
              deformed_radius=rng.choice([np.inf, 0.02], n),
              film_thickness=rng.uniform(5e-8, 5e-7, n), temperature=t_c + 273.15)
    r = integrate(LAW, **kw)
    power = (r.rolling_force * kw["sliding_speed"]
             + r.transverse_force * kw["transverse_sliding_speed"]
             # M_x (moment_transverse, the Heathcote lever) with Omega_x = roll_speed, M_y
             # (moment_rolling) with Omega_y = tilt_speed: the conjugate pairs of the module
             + r.moment_normal * kw["spin_speed"] + r.moment_transverse * kw["roll_speed"]
             + r.moment_rolling * kw["tilt_speed"])
    for arr in (r.rolling_force, r.transverse_force, r.moment_normal, r.heat):
        assert np.all(np.isfinite(arr))
    assert np.all(r.heat >= 0.0)
    np.testing.assert_allclose(r.heat, -power, rtol=1e-9, atol=1e-12)
    zero = kw["normal_load"] == 0.0
    assert np.all(r.heat[zero] == 0.0)


def test_nan_film_is_refused():
    """Defect found by this test: a NaN film thickness at a loaded contact passed the
    `h <= 0` check and gave NaN tractions and heat silently."""
    with pytest.raises(InputError, match="film_thickness"):
        integrate(LAW, normal_load=[1000.0, 500.0], semi_major=[2e-3, 1.5e-3],
                  semi_minor=[3e-4, 2e-4], sliding_speed=[0.1, 0.0],
                  film_thickness=[math.nan, 1e-7], temperature=323.15)


@pytest.mark.parametrize("law", [
    make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.1),
    make_traction_law("four_parameter", mu_zero=0.0, mu_max=0.07, slip_speed_at_max=0.5,
                      mu_infinity=0.04),
    LAW,
])
@pytest.mark.parametrize("pressure", [math.nan, math.inf])
def test_traction_law_rejects_non_finite_pressure(law, pressure):
    """Defect found by this test: the pressure-proportional laws (paper 004's linear
    saturating, the ADORE-type four-parameter curve) returned NaN / inf stress for a NaN / inf
    pressure; the Eyring law already refused it through the lubricant."""
    with pytest.raises(InputError, match="pressure"):
        law.shear_stress(0.1, pressure, 1e-7, 323.15)


@settings(max_examples=40, deadline=None)
@given(s=st.floats(0.0, 20.0), p=st.floats(1e6, 3e9), ds=st.floats(1e-4, 1.0))
def test_traction_laws_bounded_and_monotone_below_peak(s, p, ds):
    """tau / p never above the law's maximum coefficient; the linear-saturating and Eyring
    laws are non-decreasing in the sliding speed (paper 004 Fig. 3; Johnson & Tevaarwerk 1977
    with the limiting shear cap)."""
    lin = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.1)
    t1, t2 = lin.shear_stress(s, p).stress, lin.shear_stress(s + ds, p).stress
    assert 0.0 <= t1 <= t2 <= 0.05 * p * (1 + 1e-12)
    e1 = LAW.shear_stress(s, p, 1e-7, 323.15).stress
    e2 = LAW.shear_stress(s + ds, p, 1e-7, 323.15).stress
    assert 0.0 <= e1 <= e2 * (1 + 1e-12) and e2 <= 0.075 * p * (1 + 1e-9)
