"""Property tests of the roller end-face / rib contact (:mod:`thermobearing.rib`, paper 003
eqs. 1-17 and 24; session 20). Geometry: the CRB_50x75x16 preset, both end-face shapes
("sphere", "cap") and both sliding readings ("offset", "radial_plane").

Mirror symmetry. Reflecting the roller in its radial plane (x -> -x) swaps the two faces:
the state (skew alpha, shift X, skew rate, axial speed) becomes (-alpha, -X, -alpha', -X')
with the spin and the rib speed unchanged (angular velocities are axial vectors: their x
components keep their sign, y and z flip). The left face then carries what the right one
carried: the same load, heat, radial and circumferential forces and spin moment, the
opposite axial force and skew moment.

Power balance. Each face's forces act between the roller and the rib; their power on the
two bodies plus the heat booked by the face plus the elastic power Q d delta/dt add up to
zero. On the roller: F_x X' + M_spin omega_r + M_skew alpha' (its centre moves along x
only; M . omega with omega = (-omega_r cos alpha, alpha', omega_r sin alpha)). On the rib,
which turns at omega_i - omega_c about the bearing axis (d_i/2 + D_w/2 below the roller
axis): minus each force times the rib's velocity at its point -- the friction at the
contact point (or its projection on the radial plane), the drag of eq. 14 at the rib
mid-height. d delta/dt is the finite-difference rate of the public
:meth:`RibGeometry.approach`. The normal force acts along the rib cone's own normal at the
contact point, n = (+-cos theta_f, -sin theta_f cos phi, -sin theta_f sin phi), phi the
point's angle about the bearing axis (session 21; paper 003 eq. 1 takes phi = 0, the planar
normal of the roller's radial plane, on which the rib's velocity at the skew-offset point
has a part omega sin(theta_f) z_K: 0.5 % of the face's heat at 0.01 rad skew went unbooked).
The rib's rotation slides the cone within itself, so the normal force does no work on it and
the balance closes with the rib's full velocity.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from thermobearing import rib as R
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing

with warnings.catch_warnings():
    warnings.simplefilter("ignore", ValidityWarning)
    BASE = R.rib_geometry(load_bearing("CRB_50x75x16"))
GEOMS = {(ef, sl): R.with_changes(BASE, end_face=ef, slide=sl)
         for ef in R.END_FACES for sl in R.SLIDES}

state = dict(
    key=st.sampled_from(sorted(GEOMS)), skew=st.floats(-0.03, 0.03),
    shift=st.floats(-4e-5, 4e-5), skew_rate=st.floats(-50.0, 50.0),
    spin=st.floats(-3000.0, 3000.0), rib_speed=st.floats(-500.0, 500.0),
    axial_speed=st.floats(-0.01, 0.01), mu=st.floats(0.0, 0.2), drag=st.floats(0.0, 0.5),
    sreg=st.sampled_from([0.0, R.SIGN_REGULARISATION]))

#: (sign of the mirrored value) per F_* column: Q, F_x, F_y, F_z, M_skew, M_spin, v_t, v_z,
#: R_x, R_y, H, z_K, heat, circumferential friction
MIRROR = {R.F_Q: 1, R.F_FX: -1, R.F_FY: 1, R.F_FZ: 1, R.F_MSKEW: -1, R.F_MSPIN: 1,
          R.F_VT: 1, R.F_VZ: 1, R.F_RX: 1, R.F_RY: 1, R.F_H: 1, R.F_Z: 1, R.F_HEAT: 1,
          R.F_FRZ: 1}


@settings(max_examples=150, deadline=None)
@given(**state, side=st.sampled_from([-1, 1]))
def test_mirror_swaps_the_faces(key, skew, shift, skew_rate, spin, rib_speed, axial_speed,
                                mu, drag, sreg, side):
    gp = GEOMS[key].params()
    a = R.face_values(gp, side, skew, shift, skew_rate, spin, rib_speed, axial_speed, mu,
                      drag, sreg)
    b = R.face_values(gp, -side, -skew, -shift, -skew_rate, spin, rib_speed, -axial_speed,
                      mu, drag, sreg)
    for col, sign in MIRROR.items():
        assert math.isclose(a[col], sign * b[col], rel_tol=1e-12, abs_tol=1e-300), col


def test_mirror_through_rib_forces():
    """The public wrapper: both faces at once, arrays of states."""
    g = GEOMS[("sphere", "offset")]
    rng = np.random.default_rng(20)
    a, x, ad = rng.uniform(-0.02, 0.02, 50), rng.uniform(-3e-5, 3e-5, 50), rng.uniform(
        -20, 20, 50)
    kw = dict(inner_speed=600.0, cage_speed=250.0, roller_spin=3000.0, mixture_viscosity=0.01)
    f = R.rib_forces(g, a, x, skew_rate=ad, **kw)
    m = R.rib_forces(g, -a, -x, skew_rate=-ad, **kw)
    assert np.any(f.normal_right > 0) and np.any(f.normal_left > 0)
    np.testing.assert_allclose(m.normal_left, f.normal_right, rtol=1e-12)
    np.testing.assert_allclose(m.heat_left, f.heat_right, rtol=1e-12)
    np.testing.assert_allclose(m.pv_left, f.pv_right, rtol=1e-12)
    np.testing.assert_allclose(m.axial_force, -f.axial_force, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(m.skew_moment, -f.skew_moment, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(m.spin_moment, f.spin_moment, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(m.tangential_force, f.tangential_force, rtol=1e-12, atol=1e-9)


def _powers(g, side, skew, shift, skew_rate, spin, rib_speed, axial_speed, mu, drag, sreg):
    """(roller power, rib power, heat, Q d delta/dt, the normal force's power on the rib)
    [W] of one face."""
    gp = g.params()
    o = R.face_values(gp, side, skew, shift, skew_rate, spin, rib_speed, axial_speed, mu,
                      drag, sreg)
    o0 = R.face_values(gp, side, skew, shift, skew_rate, spin, rib_speed, axial_speed, mu,
                       0.0, sreg)
    q = o[R.F_Q]
    st_f = math.sin(g.rib_angle)
    r_y = o[R.F_H] - 0.5 * g.roller_diameter
    r_z = o[R.F_Z]
    r_axis = 0.5 * g.inner_raceway_diameter + 0.5 * g.roller_diameter
    # the rib cone's normal at the contact point (its angle about the bearing axis)
    phi = math.atan2(r_z, r_axis + r_y)
    n_y, n_z = -st_f * math.cos(phi), -st_f * math.sin(phi)
    drag_f = o[R.F_FRZ] - o0[R.F_FRZ]        # the drag alone (Q and the friction unchanged)
    fric_y = o0[R.F_FY] + q * n_y            # radial force minus the normal force's part
    fric_z = o0[R.F_FZ] + q * n_z
    assert math.isclose(fric_z, o0[R.F_FRZ], rel_tol=1e-9, abs_tol=1e-12 * (q + 1e-300))
    v_z = 0.0 if g.slide == "radial_plane" else r_z
    g_y = -(0.5 * g.roller_diameter - 0.5 * g.rib_height)
    # rib velocity at (y, z) from the roller axis: omega (0, -z, y + r_axis); the rib takes
    # minus the forces on the roller: Q n at the contact point
    normal_on_rib = q * rib_speed * (n_y * (-r_z) + n_z * (r_y + r_axis))
    p_rib = normal_on_rib - (fric_y * (-rib_speed * v_z) + fric_z * rib_speed * (r_y + r_axis)
                             + drag_f * rib_speed * (g_y + r_axis))
    p_roller = o[R.F_FX] * axial_speed + spin * o[R.F_MSPIN] + skew_rate * o[R.F_MSKEW]
    h_a, h_x = 1e-6, 1e-7
    k = 0 if side < 0 else 1

    def approach(a, x):
        return float(g.approach(a, x)[k])

    rate = ((approach(skew + h_a, shift) - approach(skew - h_a, shift)) / (2 * h_a) * skew_rate
            + (approach(skew, shift + h_x) - approach(skew, shift - h_x)) / (2 * h_x)
            * axial_speed)
    return p_roller, p_rib, o[R.F_HEAT], q * rate, normal_on_rib


@settings(max_examples=150, deadline=None)
@given(**state, side=st.sampled_from([-1, 1]))
def test_power_of_the_face_forces_is_the_booked_heat(key, skew, shift, skew_rate, spin,
                                                     rib_speed, axial_speed, mu, drag, sreg,
                                                     side):
    """P_roller + P_rib + heat + Q d delta/dt = 0 to round-off and the finite-difference error
    of the elastic term."""
    g = GEOMS[key]
    # the finite difference of the approach must not straddle the cap's sphere/blend seam
    # (the support function is C1 there, its second derivative jumps)
    assume(len({bool(g.contact_point(a, side)[2]) for a in (skew - 1e-6, skew + 1e-6)}) == 1)
    p_rol, p_rib, heat, elastic, _ = _powers(g, side, skew, shift, skew_rate, spin,
                                             rib_speed, axial_speed, mu, drag, sreg)
    assert heat >= 0.0
    # round-off of the moments (Q times arms that cancel) against the speeds
    q = R.face_values(g.params(), side, skew, shift, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)[R.F_Q]
    reach = (q + drag) * ((abs(spin) + abs(skew_rate) + abs(rib_speed)) * g.pitch_diameter
                          + abs(axial_speed))
    scale = max(abs(p_rol), abs(p_rib), heat, abs(elastic), 1e-9 * reach, 1e-12)
    # the approach is a difference of terms of the size of the crown radius (0.3 m): its
    # round-off, 0.3 eps = 7e-17 m, over the steps 2e-6 rad and 2e-7 m
    fd_error = q * (abs(skew_rate) * 7e-17 / 2e-6 + abs(axial_speed) * 7e-17 / 2e-7)
    assert abs(p_rol + p_rib + heat + elastic) <= 1e-9 * scale + 4 * fd_error


@pytest.mark.parametrize("end_face", ["sphere", "cap"])
@pytest.mark.parametrize("side", [-1, 1])
def test_rib_normal_does_no_work_on_the_rib(end_face, side):
    """At 0.01 rad skew, X = 10 um (towards the loaded face), omega_i - omega_c = 300 rad/s,
    mu = 0.1 (CRB_50x75x16, rib angle 0.3 deg) with the roller at rest in the cage frame:
    the heat is the rib's power alone. The planar normal of paper 003 eq. 1 would take
    Q omega sin(theta_f) z_K, 0.52 % (sphere) / 0.38 % (cap) of the heat, on the rib's
    rotation (session 20); the cone's normal takes none, and the balance closes to round-off
    (no finite-difference term: the gap is not moving)."""
    g = GEOMS[(end_face, "offset")]
    p_rol, p_rib, heat, elastic, normal_on_rib = _powers(
        g, side, side * 0.01, side * 1e-5, 0.0, 0.0, 300.0, 0.0, 0.1, 0.0, 0.0)
    assert heat > 0.0 and elastic == 0.0 and p_rol == 0.0
    assert abs(normal_on_rib) <= 1e-13 * heat
    assert abs(p_rib + heat) <= 1e-12 * heat
    # what the planar normal would have taken (the session-20 measurement)
    o = R.face_values(g.params(), side, side * 0.01, side * 1e-5, 0.0, 0.0, 300.0, 0.0, 0.1,
                      0.0, 0.0)
    planar = o[R.F_Q] * math.sin(g.rib_angle) * 300.0 * o[R.F_Z]
    assert planar / heat == pytest.approx(0.0052 if end_face == "sphere" else 0.0038,
                                                 rel=0.1)


@settings(max_examples=60, deadline=None)
@given(key=st.sampled_from(sorted(GEOMS)), skew=st.floats(0.0, 0.04), more=st.floats(1e-4, 0.02),
       shift=st.floats(-4e-5, 4e-5), dx=st.floats(1e-8, 2e-5))
def test_approach_rises_with_skew_and_towards_the_rib(key, skew, more, shift, dx):
    """Both faces approach their ribs as |alpha| grows (a crowned face, R_s > L_r/2, paper
    003 eq. 1); the right face approaches as X grows, the left one recedes."""
    g = GEOMS[key]
    left0, right0 = (float(v) for v in g.approach(skew, shift))
    left1, right1 = (float(v) for v in g.approach(skew + more, shift))
    leftn, rightn = (float(v) for v in g.approach(-(skew + more), shift))
    assert left1 > left0 and right1 > right0
    assert math.isclose(leftn, left1, rel_tol=1e-12, abs_tol=1e-18)
    assert math.isclose(rightn, right1, rel_tol=1e-12, abs_tol=1e-18)
    left2, right2 = (float(v) for v in g.approach(skew, shift + dx))
    assert right2 > right0 and left2 < left0
