"""Tests of thermobearing.loads (quasi-static ball load distribution, gothic-arch arcs)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like
from thermobearing.loads import ball_arcs, ball_load_distribution


def test_arcs_reproduce_shim_angle_and_free_angle():
    # Centred ball, zero clearance: it touches both arcs of a ring at the shim angle theta_s
    # (primer over-skidding section 4: sin(theta_s) = (s/2)/((f - 1/2) D)).
    b = qj_like(diametral_clearance=0.0)
    arcs = ball_arcs(b)
    d = np.hypot(arcs.centre_x, arcs.centre_r - arcs.pitch_radius)
    assert np.allclose(d, arcs.free_distance, rtol=0, atol=1e-12)
    ang = np.degrees(np.arctan2(np.abs(arcs.centre_x), np.abs(arcs.centre_r - arcs.pitch_radius)))
    assert np.allclose(ang, 35.0, atol=1e-9)


def test_tiny_axial_load_gives_free_contact_angle():
    # Under a vanishing axial load the diagonal-pair angle is the free contact angle of the
    # geometry module (independent derivation: cos(a_f) = cos(theta_s) - P_d/(2A)).
    b = qj_like()
    ld = ball_load_distribution(b, 0.0, 1.0, 0.0)
    assert np.allclose(ld.inner_contact_angle, b.free_contact_angle, atol=2e-4)
    assert np.all(ld.n_contacts == 2)


def test_pure_axial_equilibrium_and_symmetry():
    b = qj_like()
    Fa = 20e3
    ld = ball_load_distribution(b, 0.0, Fa, 0.0)
    Qi = ld.inner_load
    assert np.ptp(Qi) < 1e-6 * Qi.max()           # all balls alike
    # Q sin(alpha) summed = Fa (textbook: Harris & Kotzalas vol. 1 eq. 7.1)
    assert np.isclose(np.sum(Qi * np.sin(ld.inner_contact_angle)), Fa, rtol=1e-6)
    assert ld.inner_contact_angle[0] > b.free_contact_angle   # angle grows with load


def test_radial_load_on_gothic_arch_gives_four_point_contact():
    b = qj_like()
    ld = ball_load_distribution(b, 10e3, 0.0, 0.0)
    assert ld.n_contacts[0] == 4                  # ball under the load touches all four arcs
    # radial equilibrium: sum over balls of radial components of the inner-arc loads
    cf = ld.contacts
    inner = ld.ring == 0
    fr = -np.sum(np.where(inner, cf.load * cf.normal_r, 0).sum(1) * np.cos(ld.azimuth))
    assert np.isclose(fr, 10e3, rtol=1e-6)


def test_centrifugal_force_splits_contact_angles_and_seats_unloaded_balls():
    b = qj_like()
    w = 1800 * math.pi / 30
    ld = ball_load_distribution(b, 0.0, 1000.0, w)
    assert np.all(ld.inner_contact_angle > ld.outer_contact_angle + math.radians(3))
    # light axial load at speed: the outer angle is held at the outer shim angle by the second
    # outer arc (three-point contact)
    assert np.all(ld.n_contacts == 3)
    # no load at all: every ball is held by centrifugal force in both outer arcs, each carrying
    # F_c / (2 cos(theta)) with theta the outer arc angle (hand statics)
    ld0 = ball_load_distribution(b, 0.0, 0.0, w)
    assert np.all(ld0.inner_load == 0)
    th = np.abs(ld0.contacts.contact_angle[0, 2])
    assert np.allclose(ld0.outer_load, ld0.centrifugal_force / np.cos(th), rtol=1e-5)


@pytest.mark.parametrize("Fr,Fa,n", [(0, 0, 0), (1000, 0, 0), (1000, 0, 1800), (0, 0, 1800),
                                     (1000, 500, 3000), (0, -5000, 900)])
def test_robust_no_nan(Fr, Fa, n):
    ld = ball_load_distribution(qj_like(), Fr, Fa, n * math.pi / 30)
    assert ld.converged and np.all(np.isfinite(ld.contacts.load))
    assert ld.extra["max_centring_force"] < 1e-2


def test_warm_start_is_cheaper():
    b = qj_like()
    w = 1500 * math.pi / 30
    ld = ball_load_distribution(b, 1000.0, 3000.0, w)
    ld2 = ball_load_distribution(b, 1000.0, 3100.0, w, guess=ld)
    assert ld2.iterations <= ld.iterations


def test_gyroscopic_friction_option_balances_the_ring():
    # "shared" gyroscopic moment carried by transverse friction (MESYS option, primer 2.3):
    # the moment is J w_R w_m sin(beta) > 0 and the axial ring balance still holds.
    b = qj_like()
    w = 1800 * math.pi / 30
    ld = ball_load_distribution(b, 0.0, 5000.0, w, gyroscopic="shared")
    assert np.all(ld.gyroscopic_moment > 0)
    # order of magnitude of the primer's table (about 0.3-0.8 N m at 1800 r/min, D = 35 mm)
    assert 0.1 < ld.gyroscopic_moment.mean() < 2.0
    assert ld.converged and ld.residual_norm < 1e-3
