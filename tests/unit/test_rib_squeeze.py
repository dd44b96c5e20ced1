"""Squeeze film of the rib gap (thermobearing.rib.face_squeeze), the roller dynamics'
``rib_squeeze`` option: the approach speed is the rate of paper 003 eq. 1's approach,
the force opposes a closing gap only, is the sphere-plane lubrication force and only
dissipates."""

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.rib import (
    _G_CA2,
    _G_CT,
    _G_S0,
    F_MSKEW,
    F_Q,
    F_RX,
    F_RY,
    F_Z,
    _support,
    face_contact,
    face_squeeze,
    rib_geometry,
    squeeze_forces,
)

ETA = 4.0e-4      # Pa s, about the base case's oil/air mixture
FLOOR = 1.0e-6    # m


def _delta(gp, side, a, x):
    """Approach of eq. 1 [m] (face_values' delta)."""
    return _support(gp, side, a)[0] - gp[_G_S0] + (side * x - gp[_G_CA2]) * gp[_G_CT]


@pytest.mark.parametrize("end_face", ["sphere", "cap"])
def test_approach_speed_is_the_rate_of_eq1_approach(end_face):
    # along a motion X(t), alpha(t) the squeeze force divided by its gap law is
    # d delta/dt, the central difference of eq. 1's approach along the same motion
    g = rib_geometry(load_bearing("CRB_50x75x16"), end_face=end_face)
    gp = g.params()
    for side in (-1, 1):
        for a0, x0, xd, ad in ((4e-3, 3e-6, 0.3, 40.0), (-9e-3, -2e-6, -0.1, -300.0),
                               (2e-2, 0.0, 0.05, 500.0)):
            dt = 1e-9
            rate = (_delta(gp, side, a0 + ad * dt, x0 + xd * dt)
                    - _delta(gp, side, a0 - ad * dt, x0 - xd * dt)) / (2 * dt)
            f_s, fx, m_skew, power = face_squeeze(gp, side, a0, x0, ad, xd, ETA, FLOOR)
            if rate <= 0.0:
                assert f_s == 0.0 and power == 0.0          # an opening gap cavitates
                continue
            v_n = power / f_s
            assert v_n == pytest.approx(rate, rel=1e-5)
            # force on the roller along -n: axial part -F side cos(theta_f), no pull
            assert f_s > 0.0
            assert fx == pytest.approx(-f_s * side * gp[_G_CT], rel=1e-12)
            # acting on the Hertz force's line: the skew moment per newton is the normal
            # force's (face_contact with mu = 0 in contact; the rib cone's normal there has
            # a circumferential part, so the moment is not z_K F_x alone)
            fc = face_contact(gp, side, a0, side * 40e-6, 0.0, 1000.0, 500.0, 0.0, 0.0,
                              0.0, 0.0)
            assert m_skew == pytest.approx(fc[F_MSKEW] / fc[F_Q] * f_s, rel=1e-9)
            assert m_skew == pytest.approx(fc[F_Z] * fx, rel=2e-3)


def test_sphere_plane_value_and_film_floor():
    # 6 pi eta R_x R_y v / h at the gap -delta, the floor in Hertz contact
    g = rib_geometry(load_bearing("CRB_50x75x16"))
    gp = g.params()
    side, a, xd = 1, 0.0, 0.2
    x_free = g.axial_clearance / 2 - 5e-6 / gp[_G_CT]       # 5 um gap at zero skew
    fc = face_contact(gp, side, a, x_free, 0.0, 1000.0, 500.0, 0.0, 0.0, 0.0, 0.0)
    gap = -_delta(gp, side, a, x_free)
    assert gap == pytest.approx(5e-6, rel=1e-6)
    v_n = xd * gp[_G_CT]
    f_s = face_squeeze(gp, side, a, x_free, 0.0, xd, ETA, FLOOR)[0]
    assert f_s == pytest.approx(6 * math.pi * ETA * fc[F_RX] * fc[F_RY] * v_n / gap,
                                rel=1e-9)
    x_in = g.axial_clearance / 2 + 2e-6                     # in Hertz contact
    f_in = face_squeeze(gp, side, a, x_in, 0.0, xd, ETA, FLOOR)[0]
    assert f_in == pytest.approx(f_s * gap / FLOOR, rel=1e-6)
    assert face_squeeze(gp, side, a, x_in, 0.0, xd, 0.0, FLOOR) == (0.0, 0.0, 0.0, 0.0)


def test_squeeze_forces_arrays_only_dissipate():
    g = rib_geometry(load_bearing("CRB_50x75x16"))
    rng = np.random.default_rng(2)
    a = rng.uniform(-1e-2, 1e-2, 200)
    x = rng.uniform(-2e-5, 2e-5, 200)
    ad = rng.uniform(-500, 500, 200)
    xd = rng.uniform(-0.5, 0.5, 200)
    fl, fr, pl, pr = squeeze_forces(g, a, x, ad, xd, ETA, FLOOR)
    assert fl.shape == (200,) and np.all(fl >= 0) and np.all(fr >= 0)
    assert np.all(pl >= 0) and np.all(pr >= 0) and np.any(pl > 0) and np.any(pr > 0)


def test_rib_squeeze_option_holds_the_10000_rpm_point_off_the_ribs():
    # paper 003's bearing at 10000 r/min, 3 kN, 0.11 g: without the film an unloaded
    # roller wedged between its ribs rattles (friction-driven) and drives the cage out of
    # its band (validation case SOURCE.md, 2026-11-23 evening); with the rib-gap squeeze
    # film the motion stays bounded, and the rollers stay off the ribs (measured cage
    # within 1.2 % of the quasi-static speed, contact fraction 0)
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding import roller_dynamics as rd
    from thermobearing.skidding.roller_dynamics_coupled import simulate_coupled

    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, 10000 * math.pi / 30, 3000.0, 0.11e-3, coupling="none",
                       rib_squeeze=True)
    assert m.rib_squeeze
    r = simulate_coupled(m, b, lub, n_orbits=1.0, warmup_orbits=2.0, fallback=False)
    wc = r.series["cage_speed"]
    assert np.max(np.abs(wc / m.cage_speed - 1.0)) < 0.05
    assert r.rib_contact_fraction < 0.01
    assert rd.build_model(b, lub, 10000 * math.pi / 30, 3000.0, 0.11e-3, coupling="none",
                          quasi_static=m.extras["quasi_static"]).rib_squeeze is False
