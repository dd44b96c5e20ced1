"""Tests of thermobearing.loads_roller (cylindrical roller bearing load distribution)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.loads_roller import (
    LINE_CONTACT_EXPONENT,
    roller_body_force,
    roller_film_load_distribution,
    roller_load_distribution,
    split_roller_interference,
)

K = 1.0e10  # N/m^(10/9), order of a 13 mm steel roller (Palmgren)


def test_stribeck_constant_line_contact():
    # Zero clearance, no body force: Z Q_max / F_r = 4.08 for line contacts
    # (Stribeck's number for line contacts, Harris & Kotzalas 2007 vol. 1: 4.08).
    z, fr = 18, 5000.0
    r = roller_load_distribution(z, 0.0, fr, K, K)
    assert z * r.inner_load.max() / fr == pytest.approx(4.08, rel=0.01)


@pytest.mark.parametrize("offset", np.linspace(0.0, 2 * math.pi / 18, 7))
def test_ring_equilibrium_and_roller_equilibrium(offset):
    z = 18
    psi = 2 * math.pi * np.arange(z) / z + offset
    fb = 10.0 + 0.3 * np.cos(psi)  # centrifugal plus a whirl-like radial part [N]
    r = roller_load_distribution(z, 25e-6, 150.0, K, 0.8 * K, body_force=fb, azimuth=psi)
    force = np.array([np.sum(r.inner_load * np.cos(psi)), np.sum(r.inner_load * np.sin(psi))])
    np.testing.assert_allclose(force, [150.0, 0.0], atol=1e-6)
    # each roller: Q_o - Q_i = F_j (eq. 1 of the module), all rollers here have F_j > 0
    np.testing.assert_allclose(r.outer_load - r.inner_load, fb, atol=1e-6)
    # load-deflection law on both contacts
    np.testing.assert_allclose(r.inner_load, K * r.inner_deflection**LINE_CONTACT_EXPONENT,
                               rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(r.outer_load,
                               0.8 * K * r.outer_deflection**LINE_CONTACT_EXPONENT,
                               rtol=1e-6, atol=1e-6)
    assert 1 <= r.n_loaded <= 3  # clearance 25 um at 150 N: a narrow load zone


def test_single_roller_under_load_with_clearance():
    # A roller right under the load and a clearance much larger than the contact approach:
    # that roller alone carries F_r, the others only their centrifugal force.
    r = roller_load_distribution(18, 25e-6, 100.0, K, K, body_force=8.0)
    assert r.n_loaded == 1
    assert r.inner_load[0] == pytest.approx(100.0, rel=1e-9)
    np.testing.assert_allclose(r.outer_load[1:], 8.0)
    assert r.ring_displacement[0] > 12.5e-6
    assert r.ring_displacement[1] == pytest.approx(0.0, abs=1e-15)


def test_split_equal_stiffness_no_body_force_halves_the_interference():
    d = np.array([1e-6, 2e-6, -1e-6])
    di, do = split_roller_interference(d, 0.0, K, K)
    np.testing.assert_allclose(di[:2], d[:2] / 2, rtol=1e-9)
    np.testing.assert_allclose(do[:2], d[:2] / 2, rtol=1e-9)
    assert di[2] == 0.0 and do[2] == 0.0


def test_body_force_alone_loads_outer_contact():
    di, do = split_roller_interference(np.array([-5e-6]), np.array([12.0]), K, K)
    assert di[0] == 0.0
    assert K * do[0] ** LINE_CONTACT_EXPONENT == pytest.approx(12.0, rel=1e-9)


def test_zero_radial_load_gives_body_force_only():
    r = roller_load_distribution(12, 20e-6, 0.0, K, K, body_force=5.0)
    assert r.n_loaded == 0
    np.testing.assert_allclose(r.outer_load, 5.0)


def test_body_force_centrifugal_and_whirl():
    psi = np.array([0.0, math.pi / 2, math.pi])
    f = roller_body_force(0.0135, 0.0975, 120.0, psi, whirl_acceleration=(-10.0, 0.0))
    fc = 0.0135 * 0.0975 / 2 * 120.0**2
    # d'Alembert force -m a: +m*10 outward at psi = 0, -m*10 at psi = pi
    np.testing.assert_allclose(f, [fc + 0.135, fc, fc - 0.135])


def test_bad_inputs():
    with pytest.raises(InputError):
        roller_load_distribution(2, 0.0, 10.0, K, K)
    with pytest.raises(InputError):
        roller_load_distribution(10, -1e-6, 10.0, K, K)
    with pytest.raises(InputError):
        roller_load_distribution(10, 0.0, 10.0, K, K, azimuth=np.zeros(3))


def _rigid_films(a_inner: float, a_outer: float):
    # rigid-isoviscous line-contact films h = A / Q (Martin 1916: h0 = 2.448 eta U R l / Q)
    return (lambda q: a_inner / np.asarray(q), lambda q: a_outer / np.asarray(q))


@pytest.mark.parametrize("fr", [0.0, 150.0, 2000.0])
def test_film_load_distribution_fills_the_gaps_and_balances_the_ring(fr):
    # Every roller fills its radial gap with its two films minus the Hertz approaches,
    # h_i(Q_i) + h_o(Q_i + F) - (Q_i/K)^(9/10) - (Q_o/K)^(9/10) = P_d/2 - delta . e_j,
    # and the ring is in equilibrium on all 18 film loads (F_r along psi = 0).
    z, pd, fb = 18, 2.5e-5, 7.0
    fi, fo = _rigid_films(2.0e-4, 3.0e-4)  # 20 N at 10 um inner, 30 N at 10 um outer
    r = roller_film_load_distribution(z, pd, fr, fi, fo, K, K, body_force=fb)
    psi = r.azimuth
    assert np.all(r.loaded) and np.all(r.inner_load > 0.0)
    assert np.sum(r.inner_load * np.cos(psi)) == pytest.approx(fr, abs=1e-6 * max(fr, 1.0))
    assert abs(np.sum(r.inner_load * np.sin(psi))) < 1e-6 * max(fr, 1.0)
    assert r.outer_load == pytest.approx(r.inner_load + fb, rel=1e-12)
    gap = -r.interference
    filled = (fi(r.inner_load) + fo(r.outer_load) - (r.inner_load / K) ** 0.9
              - (r.outer_load / K) ** 0.9)
    assert filled == pytest.approx(gap, rel=1e-9, abs=1e-15)
    if fr == 0.0:
        assert np.ptp(r.inner_load) < 1e-9 * r.inner_load.mean()
        assert np.hypot(*r.ring_displacement) < 1e-15
    else:
        # the roller under the load carries the most, the one opposite the least
        assert np.argmax(r.inner_load) == 0 and np.argmin(r.inner_load) == z // 2
        assert r.ring_displacement[0] > 0.0


def test_film_load_distribution_warm_start_gives_the_same_answer():
    fi, fo = _rigid_films(2.0e-4, 3.0e-4)
    cold = roller_film_load_distribution(18, 2.5e-5, 150.0, fi, fo, K, K, body_force=7.0)
    warm = roller_film_load_distribution(18, 2.5e-5, 150.0, fi, fo, K, K, body_force=7.0,
                                         x0=tuple(cold.ring_displacement),
                                         q0=cold.inner_load * 1.1)
    assert warm.inner_load == pytest.approx(cold.inner_load, rel=1e-9)
