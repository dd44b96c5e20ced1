"""Tests of thermobearing.skidding.roller_dynamics_pocket (roller / cage-bar contact)."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from thermobearing.skidding import roller_dynamics_pocket as rp
from thermobearing.skidding.roller_fluid import pocket_forces

L = 6e-3          # roller length [m]
K = 2e7           # bar stiffness over the whole length [N/m]
C = 0.2e-3        # pocket circumferential clearance [m]


def test_bar_contact_translation_hand_values():
    # centred, not skewed: no contact
    assert rp.bar_contact(0.0, 0.0, 0.5 * L, C, K) == (0.0, 0.0, 0.0, 0.0)
    # pushed 10 um into the front bar over its whole length: F = -K d, no moment
    fz, my, ff, fb = rp.bar_contact(0.5 * C + 10e-6, 0.0, 0.5 * L, C, K)
    assert fz == pytest.approx(-K * 10e-6, rel=1e-12)
    assert ff == pytest.approx(K * 10e-6, rel=1e-12) and fb == 0.0 and my == 0.0
    fz, my, ff, fb = rp.bar_contact(-0.5 * C - 4e-6, 0.0, 0.5 * L, C, K)
    assert fz == pytest.approx(K * 4e-6, rel=1e-12) and ff == 0.0


def test_bar_contact_skew_hand_values():
    # zero clearance, skew a: each bar carries a triangle, int_0^{L/2} k_l a x dx = K a L / 8,
    # restoring moment 2 int_0^{L/2} k_l a x^2 dx = K a L^2 / 12 (k_l = K / L)
    a = 1e-3
    fz, my, ff, fb = rp.bar_contact(0.0, a, 0.5 * L, 0.0, K)
    assert ff == pytest.approx(K * a * L / 8, rel=1e-12)
    assert fb == pytest.approx(K * a * L / 8, rel=1e-12)
    assert fz == pytest.approx(0.0, abs=1e-9)
    assert my == pytest.approx(-K * a * L**2 / 12, rel=1e-12)
    # the same against a numerical integral with clearance and a shift (partial contact)
    z, a = 0.09e-3, 0.02
    k_l = K / L

    def dens(x):
        return k_l * max(z - a * x - 0.5 * C, 0.0), k_l * max(-(z - a * x) - 0.5 * C, 0.0)

    front = quad(lambda x: dens(x)[0], -0.5 * L, 0.5 * L, points=[(z - 0.5 * C) / a])[0]
    rear = quad(lambda x: dens(x)[1], -0.5 * L, 0.5 * L, points=[(z + 0.5 * C) / a])[0]
    mom = quad(lambda x: -x * (dens(x)[1] - dens(x)[0]), -0.5 * L, 0.5 * L,
               points=[(z - 0.5 * C) / a, (z + 0.5 * C) / a])[0]
    fz, my, ff, fb = rp.bar_contact(z, a, 0.5 * L, C, K)
    assert ff == pytest.approx(front, rel=1e-8) and fb == pytest.approx(rear, rel=1e-8)
    assert fz == pytest.approx(rear - front, rel=1e-8)
    assert my == pytest.approx(mom, rel=1e-8)


def test_squeeze_film_matches_reynolds_integral():
    # long rigid cylinder approaching a plane: p from h^3 p' = 12 eta h0' x, w' = int p dx;
    # the closed form 3 sqrt(2) pi eta (R/h0)^1.5 h0' (module notes) against quadrature
    eta, r, h0, v = 0.01, 3e-3, 2e-6, 1.0   # v = -dh0/dt (approach) [m/s]

    def h(x):
        return h0 + x * x / (2 * r)

    def p(x):  # pressure: zero at infinity, from the Reynolds equation
        return quad(lambda s: 12 * eta * v * s / h(s) ** 3, x, np.inf)[0]

    scale = math.sqrt(2 * r * h0)
    w = 2 * quad(p, 0, 200 * scale, limit=200)[0]
    c = rp.squeeze_coefficient(h0, eta, r, 1.0, 1e-9)
    assert c * v == pytest.approx(w, rel=2e-3)
    # floor
    assert rp.squeeze_coefficient(1e-9, eta, r, 1.0, 1e-6) == rp.squeeze_coefficient(
        1e-6, eta, r, 1.0, 1e-6)


def test_squeeze_only_on_approach():
    eta, r = 0.01, 3e-3
    z = 0.5 * C - 5e-6          # 5 um from the front bar
    closing = rp.pocket_force_z(z, 0.5, 0.0, 0.5 * L, C, K, eta, r, 1e-6)
    opening = rp.pocket_force_z(z, -0.5, 0.0, 0.5 * L, C, K, eta, r, 1e-6)
    c_f = rp.squeeze_coefficient(5e-6, eta, r, L, 1e-6)
    c_b = rp.squeeze_coefficient(0.5 * C + z, eta, r, L, 1e-6)
    assert closing[0] == pytest.approx(-c_f * 0.5, rel=1e-12)   # front film resists
    assert closing[2] == pytest.approx(c_f * 0.5, rel=1e-12)
    assert opening[0] == pytest.approx(c_b * 0.5, rel=1e-12)    # rear gap closes instead
    assert opening[3] == pytest.approx(c_b * 0.5, rel=1e-12) and opening[2] == 0.0
    arr = rp.bar_forces(np.array([z, z]), np.array([0.5, -0.5]), 0.0, 0.5 * L, C, K, eta, r,
                        1e-6)
    assert arr[0][0] == pytest.approx(closing[0]) and arr[0][1] == pytest.approx(opening[0])


def test_extra_pocket_friction():
    t = np.linspace(0.0, 1e-3, 2001)
    w = np.full(t.shape, 8000.0)
    args = (6e-3, 5.4e-3, 0.008, C)
    # steady force -> nothing extra
    assert rp.extra_pocket_friction(np.full(t.shape, 3.0), t, w, 3.0, *args) == pytest.approx(
        0.0, abs=1e-15)
    # a force alternating between 0 and 10 N: the mean of the pocket film friction of
    # paper 000 eqs. 37-38 (pocket_forces) minus its value at the steady 2 N
    f = np.where(np.sin(2 * np.pi * 5e3 * t) > 0, 10.0, 0.0)
    got = rp.extra_pocket_friction(f, t, w, 2.0, *args)
    fr = pocket_forces(f, w, *args).friction
    f0 = pocket_forces(np.array([2.0]), np.array([8000.0]), *args).friction[0]
    assert got == pytest.approx(np.trapezoid(fr, t) / t[-1] - f0, rel=1e-12)
    assert got > 0
