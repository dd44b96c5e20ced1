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


# Values of the numpy implementation of ball_load_distribution (commit 87c0e55, before it was
# compiled), captured with that code at full precision. The compiled Newton first
# reproduced them to round-off. Now the weak ball-centring spring is Jacobian-only
# (it was a force in the residual of up to ~1e-5 N that entered the equilibrium) and the
# solver takes per-ball damped, Levenberg-Marquardt steps, so the solution must agree to the
# size of that removed force and the convergence tolerance (loads 2e-5 N of 300-1000 N,
# positions 1e-10 m, angles 1e-8 rad), in no more iterations than the reference took.
# (bearing, Fr [N], Fa [N], speed [r/min], gyroscopic, Z) ->
# (delta_a, delta_r, ball_x[1], ball_r[1], inner_load[0], outer_load[-1],
#  inner_contact_angle[0], gyroscopic_moment[0], iterations)
_NUMPY_REFERENCE = [
    (('QJ1044', 1000.0, 10000.0, 1800.0, 'none', None),
     (7.932145028785169e-05, 2.1038563870066163e-06, 5.540315775071178e-06, 0.1400303328040185,
      872.475176505212, 1029.968285295297, 0.7464141892435929, 0.0, 16)),
    (('QJ1044', 1000.0, 0.0, 0.0, 'none', None),
     (7.274371331743351e-21, 5.887763904377655e-05, 4.282228476854723e-20, 0.140027974514553,
      614.9180404134273, 341.1607790820516, 0.6575196152578514, 0.0, 16)),
    (('QJ1044', 0.0, 5000.0, 1800.0, 'shared', None),
     (7.320481035042943e-05, 1.343872654846244e-19, 2.9962859934098504e-06, 0.14002894622932144,
      394.32764467686206, 591.1762085188936, 0.7443979086716433, 1.018728355615911, 12)),
    (('QJ1044', 1000.0, -3000.0, 600.0, 'none', 8),
     (-7.790666773045908e-05, 5.6538957155586995e-06, -3.262422334966183e-05, 0.1400073471054065,
      920.6273437395118, 819.7023239952911, 0.7090649390792871, 0.0, 9)),
    (('QJ1044', 0.0, 0.0, 3000.0, 'none', None),
     (0.0, 0.0, 0.0, 0.14002944686277263,
      0.0, 623.9290501552169, 0.6981317007977318, 0.0, 4)),
    (('SKF6304', 500.0, 100.0, 3000.0, 'none', None),
     (-5.881485023683916e-06, 1.1730996345788062e-05, -3.7202514463040412e-06, 0.018003891918586964,
      324.67757144906864, 146.85117561687, 0.1618027793097347, 0.0, 68)),
    (('SKF6304', 300.0, 0.0, 0.0, 'shared', None),
     (-8.418728499923612e-05, 1.632969820416361e-05, -5.0512364710633615e-05, 0.018005881006382424,
      248.20443464598844, 41.536818155135514, 7.30800348108005e-09, 0.0, 62)),
]


@pytest.mark.parametrize("case,expected", _NUMPY_REFERENCE)
def test_compiled_distribution_reproduces_the_numpy_solution(case, expected):
    from thermobearing.geometry import load_bearing

    name, Fr, Fa, n, gyro, Z = case
    ld = ball_load_distribution(load_bearing(name), Fr, Fa, n * math.pi / 30,
                                gyroscopic=gyro, n_balls=Z)
    got = (ld.delta_a, ld.delta_r, ld.ball_x[1], ld.ball_r[1], ld.inner_load[0],
           ld.outer_load[-1], ld.inner_contact_angle[0], ld.gyroscopic_moment[0])
    atol = (1e-10, 1e-10, 1e-10, 1e-10, 2e-5, 2e-5, 1e-8, 1e-10)   # m, m, m, m, N, N, rad, N m
    for g, e, a in zip(got, expected[:8], atol, strict=True):
        assert g == pytest.approx(e, rel=0.0, abs=a)
    assert ld.iterations <= expected[8]


def test_arc_contacts_with_fixed_stiffness_scales_the_load():
    # Q = K delta^1.5: the same geometry with a doubled fixed K doubles every load
    from thermobearing.loads import arc_contacts

    b = qj_like()
    ld = ball_load_distribution(b, 1000.0, 5000.0, 0.0)
    arcs = ball_arcs(b)
    cf = arc_contacts(b, arcs, ld.ball_x, ld.ball_r, ld.delta_a, ld.delta_r, ld.azimuth)
    np.testing.assert_allclose(cf.load, ld.contacts.load, rtol=1e-14, atol=0)
    cf2 = arc_contacts(b, arcs, ld.ball_x, ld.ball_r, ld.delta_a, ld.delta_r, ld.azimuth,
                       stiffness=2.0 * cf.stiffness)
    np.testing.assert_allclose(cf2.load, 2.0 * cf.load, rtol=1e-14, atol=0)
