"""The end-face / rib contact on the rib *cone* (session 21, :mod:`thermobearing.rib` module
notes "Contact normal"): the approach is the depth of the face's deepest point past the cone
of revolution about the bearing axis, found here by brute force over the face; the normal
force acts along the cone's normal there, so it does no work on the rib's rotation nor on
the roller's spin; the booked heat is the friction force times the sliding speed.
Geometry: CRB_50x75x16 (paper 003's bearing), both end-face shapes."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.optimize import minimize

from thermobearing import rib as R
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing

with warnings.catch_warnings():
    warnings.simplefilter("ignore", ValidityWarning)
    BASE = R.rib_geometry(load_bearing("CRB_50x75x16"))
GEOMS = {ef: R.with_changes(BASE, end_face=ef) for ef in R.END_FACES}
SKEWS = (0.0, 0.004, -0.008, 0.0101, 0.02, -0.03)


def _depth(g, side, a):
    """Largest g(P) = side ct P_x - st (r(P) - rc0) over the end face [m], by a bounded
    quasi-Newton search over the face's own parameters (polar angle chi from the roller
    axis, azimuth psi about it) on the sphere and, for the cap, on the chamfer torus;
    r(P) the distance from the bearing axis, rc0 = d_i/2 + D_w/2 below the roller axis."""
    ct, st = math.cos(g.rib_angle), math.sin(g.rib_angle)
    c, s = math.cos(a), math.sin(a)
    rc0 = 0.5 * g.inner_raceway_diameter + 0.5 * g.roller_diameter
    rs, hl = g.crown_radius, 0.5 * g.roller_length

    def depth(local):
        xl, yl, zl = local          # roller axes, x towards the face
        px = side * xl
        r_x, r_z = px * c + zl * s, -px * s + zl * c
        return side * ct * r_x - st * (math.hypot(rc0 + yl, r_z) - rc0)

    def sphere(p):
        chi, psi = p
        return (hl - rs + rs * math.cos(chi), rs * math.sin(chi) * math.cos(psi),
                rs * math.sin(chi) * math.sin(psi))

    pieces = [(sphere, (0.0, math.pi / 2))]
    if g.end_face == "cap":
        rc = g.chamfer
        rt = 0.5 * g.roller_diameter - rc
        xt = math.sqrt((rs - rc) ** 2 - rt**2)
        chi_t = math.atan2(rt, xt)          # the seam: sphere normal = torus normal

        def torus(p):
            chi, psi = p
            rho = rt + rc * math.sin(chi)
            return (hl - rs + xt + rc * math.cos(chi), rho * math.cos(psi),
                    rho * math.sin(psi))

        pieces = [(sphere, (0.0, chi_t)), (torus, (chi_t, math.pi / 2))]
    best = -math.inf
    for shape, (lo, hi) in pieces:
        starts = [x for x in (0.004, 0.008, 0.015, 0.5 * (lo + hi)) if lo < x < hi]
        for chi0 in starts:
            for psi0 in (math.pi - 0.3, math.pi, math.pi + 0.3):   # below the roller axis
                r = minimize(lambda p, shape=shape: -depth(shape(p)), (chi0, psi0),
                             method="L-BFGS-B", bounds=[(lo, hi), (0.5 * math.pi,
                                                                   1.5 * math.pi)],
                             options={"ftol": 1e-15, "gtol": 1e-14, "maxiter": 500})
                best = max(best, -float(r.fun))
    return best


@pytest.mark.parametrize("end_face", R.END_FACES)
@pytest.mark.parametrize("side", [-1, 1])
def test_approach_is_the_depth_of_the_deepest_face_point(end_face, side):
    """approach(alpha) - approach(0) equals the brute-force depth change to 1e-14 m
    (measured 5e-17 m); paper 003 eq. 1's sphere term, the planar normal's, differs from it
    by 0.75 / 2.9 / 6.5 um at 0.0101 / 0.02 / 0.03 rad."""
    g = GEOMS[end_face]
    k = 0 if side < 0 else 1
    d0 = _depth(g, side, 0.0)
    base = float(g.approach(0.0, 0.0)[k])
    for a in SKEWS:
        got = float(g.approach(a, 0.0)[k]) - base
        want = _depth(g, side, a) - d0
        assert got == pytest.approx(want, abs=1e-14), (a, got, want)
    # the cone matters: at 0.02 rad the deepest point is 2.9 um short of eq. 1's sphere
    # term (R_s - L_r/2)(1 - cos alpha) cos(theta_f)
    if end_face == "sphere":
        eq1 = 0.297 * (1 - math.cos(0.02)) * math.cos(g.rib_angle)
        assert eq1 - (_depth(g, side, 0.02) - d0) == pytest.approx(2.93e-6, rel=0.01)


@pytest.mark.parametrize("end_face", R.END_FACES)
@pytest.mark.parametrize("side", [-1, 1])
def test_normal_force_works_on_neither_rib_rotation_nor_spin(end_face, side):
    """With mu = 0 and no drag the face force is the normal force -Q n: its power on the
    rib's velocity at the contact point, omega (0, -z_K, y + rc0), and its moment about the
    roller axis (its power on the spin) vanish to round-off."""
    g = GEOMS[end_face]
    gp = g.params()
    rc0 = 0.5 * g.inner_raceway_diameter + 0.5 * g.roller_diameter
    om, wr = 300.0, 3000.0
    for a in SKEWS:
        o = R.face_values(gp, side, side * abs(a), side * 2e-5, 7.0, wr, om, 0.003, 0.0,
                          0.0, 0.0)
        q = o[R.F_Q]
        assert q > 0.0
        r_y = o[R.F_H] - 0.5 * g.roller_diameter
        r_z = o[R.F_Z]
        force = np.array([o[R.F_FX], o[R.F_FY], o[R.F_FZ]])
        assert np.linalg.norm(force) == pytest.approx(q, rel=1e-12)
        v_rib = om * np.array([0.0, -r_z, r_y + rc0])
        assert abs(force @ v_rib) <= 1e-13 * q * np.linalg.norm(v_rib)
        assert abs(o[R.F_MSPIN]) <= 1e-13 * q * g.crown_radius
        # the normal is the cone's: turned about the bearing axis by the point's angle
        phi = math.atan2(r_z, rc0 + r_y)
        n = np.array([side * math.cos(g.rib_angle), -math.sin(g.rib_angle) * math.cos(phi),
                      -math.sin(g.rib_angle) * math.sin(phi)])
        np.testing.assert_allclose(force, -q * n, rtol=0, atol=1e-12 * q)


@pytest.mark.parametrize("end_face", R.END_FACES)
def test_heat_is_friction_force_times_sliding_speed(end_face):
    """F_HEAT of a face without drag is |friction force| x |v_i - v_r| (eq. 12 x eq. 24),
    the friction force being the face force less the normal force of the same state, and
    it lies in the contact's tangent plane."""
    g = GEOMS[end_face]
    gp = g.params()
    rng = np.random.default_rng(21)
    for _ in range(40):
        side = int(rng.choice([-1, 1]))
        a = side * rng.uniform(0.0, 0.03)
        args = (side, a, side * rng.uniform(0.0, 4e-5), rng.uniform(-50, 50),
                rng.uniform(-3000, 3000), rng.uniform(-500, 500), rng.uniform(-0.01, 0.01))
        mu = rng.uniform(0.01, 0.2)
        for sreg in (0.0, R.SIGN_REGULARISATION):
            o = R.face_values(gp, *args, mu, 0.0, sreg)
            o0 = R.face_values(gp, *args, 0.0, 0.0, sreg)
            fric = (np.array([o[R.F_FX], o[R.F_FY], o[R.F_FZ]])
                    - np.array([o0[R.F_FX], o0[R.F_FY], o0[R.F_FZ]]))
            heat = float(np.linalg.norm(fric)) * o[R.F_VT]
            assert o[R.F_HEAT] == pytest.approx(heat, rel=1e-10, abs=1e-12)
            if o[R.F_Q] > 0.0:
                normal = -np.array([o0[R.F_FX], o0[R.F_FY], o0[R.F_FZ]]) / o0[R.F_Q]
                assert abs(fric @ normal) <= 1e-12 * (np.linalg.norm(fric) + 1e-300)
