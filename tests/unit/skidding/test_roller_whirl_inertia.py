"""Tests of the two readings of the whirl inertia in the rollers' radial balance
(skidding/whirl.py ``Whirl.radial_inertia``; paper 000 eqs. 1-4, 20/23)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.skidding.roller import build_model, solve_model, solve_roller
from thermobearing.skidding.whirl import Whirl

OMEGA = 5000.0 * math.pi / 30.0  # paper 000: n_i = 5000 r/min
T = 313.15
OPTS = dict(viscosity=0.08, limiting_shear_coefficient=1.0, ring_support="films",
            film_pressure="regime_min", pocket_film="two_faces")


def test_unknown_radial_inertia_is_an_error():
    with pytest.raises(InputError, match="radial_inertia"):
        Whirl(6e-5, radial_inertia="uniform")


def test_radial_acceleration_equal_to_the_projection_changes_nothing(nu214, oil):
    # solve_model with radial_acceleration = a_w . e_j (the projection) is the default path
    m = build_model(nu214, oil, T, **OPTS)
    psi = 2.0 * math.pi * np.arange(18) / 18
    acc = (-15.0, 8.0)
    a = solve_model(m, OMEGA, 150.0, azimuth=psi, whirl_acceleration=acc)
    b = solve_model(m, OMEGA, 150.0, azimuth=psi, whirl_acceleration=acc,
                    radial_acceleration=acc[0] * np.cos(psi) + acc[1] * np.sin(psi))
    assert b.cage_speed == pytest.approx(a.cage_speed, rel=1e-12)
    np.testing.assert_allclose(b.outer_load, a.outer_load, rtol=1e-12)


def test_in_phase_radial_inertia_is_a_breathing_centrifugal_load(nu214, oil):
    # a uniform radial acceleration a (eq. 4's e_y'' = -e omega_w^2 sin, here its peak
    # -16.4 m/s^2 at e = 6e-5 m) acts on every roller like a centrifugal force changed by
    # -m_r a: each roller's radial balance (eq. 20) and the ring equilibrium hold with it
    m = build_model(nu214, oil, T, **OPTS)
    r = solve_model(m, OMEGA, 150.0, radial_acceleration=np.full(18, -16.4))
    assert r.converged
    psi = r.azimuth
    np.testing.assert_allclose(np.sum(r.inner_load * np.cos(psi)), 150.0, rtol=1e-8)
    # roller radial balance (eq. 20): Q_o - Q_i = m_r (d_m/2 omega_c^2 - a)
    fb = nu214.roller_mass * (0.5 * nu214.pitch_diameter * r.cage_speed**2 + 16.4)
    np.testing.assert_allclose(r.outer_load - r.inner_load, fb, rtol=1e-9)


def test_in_phase_whirl_fluctuation_is_first_order(nu214, oil):
    # Paper 000 eqs. 20/23 as printed (in phase): every roller's centrifugal load breathes by
    # m_r e omega_w^2 (0.22 N at 6e-5 m), a first-order forcing: the fluctuation grows
    # nearly linearly with e (measured 2.85 / 7.91 r/min at 2e-5 / 6e-5 m, 36 samples; the
    # projected tangential part adds a second-order share) and is about four times that of
    # the translating (projected) whirl (2.00 r/min at 6e-5 m; paper 000 Table 2: 5.07).
    fl = {}
    for e, mode in ((2e-5, "in_phase"), (6e-5, "in_phase"), (6e-5, "projected")):
        r = solve_roller(nu214, oil, OMEGA, 200.0, 0.0, T,
                         whirl=Whirl(e, n_samples=8, radial_inertia=mode), **OPTS)
        assert r.converged
        fl[(e, mode)] = r.cage_speed_stats.fluctuation
    assert 2.5 < fl[(6e-5, "in_phase")] / fl[(2e-5, "in_phase")] <= 3.0
    assert fl[(6e-5, "in_phase")] > 3.0 * fl[(6e-5, "projected")]
