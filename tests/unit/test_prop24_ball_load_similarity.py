"""Property tests, round 6: geometric similarity of the ball load distribution
(:func:`thermobearing.loads.ball_load_distribution`, session 24), beside the ring
equilibrium of test_property_loads.py, the symmetries of test_prop19_loads.py and the
Stribeck sum and ball equilibrium of test_prop21_kinematics_loads.py.

A bearing made L times larger in every length (envelope, ball and pitch diameters,
clearance, gothic-arch offset, shoulders, cage, roughness; conformities and angles are
ratios) of the same materials, loaded by L^2 F_r and L^2 F_a and turning at omega / L, is
the first bearing seen at another scale (Hertz: Q = K delta^1.5 with K ~ E' R^0.5, so
K delta^1.5 ~ L^2; centrifugal force m omega_m^2 r_b ~ L^3 L^-2 L = L^2; gyroscopic moment
J omega_R omega_m ~ L^5 L^-2 = L^3, a force times a length): every ball load scales by L^2,
the contact angles are the same, the ring displacement scales by L, the centrifugal forces
by L^2 and the gyroscopic moments by L^3.

The solve is a Newton iteration to a force residual of 1e-9 of the load scale, so the two
solutions agree to that tolerance, not to round-off: measured on 200 draws (scratch),
ball loads 1.1e-8 of the largest, contact angles 5.6e-7 rad (the load-weighted angle of a
lightly loaded ball moves most), ring displacement 4.6e-10 of the largest component (and
1.5e-7 at 10 N radial and axial on SKF6304 at 1246 rad/s, where the centrifugal forces
dominate and the ring floats on the solver's tolerance; 400 more draws). Asserted: 1e-6,
1e-5 rad, 1e-5.

Defect found (loads.ball_load_distribution, fixed): a ball that carries no load reports the
nominal contact angle, but one left at a round-off load (1.5e-17 N beside 1.4e4 N) reported
its geometric angle, so the same unloaded balls of SKF6304 at 15.2 kN radial / 4.2 kN axial
had an outer contact angle of 0 rad and, the bearing scaled by 1.22 (loads by 1.49), 0.178
rad; those angles go on to race control and the skidding solver. Arc loads below 1e-12 of
the largest now count as unloaded for the angles.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing
from thermobearing.errors import ValidityWarning
from thermobearing.loads import ball_load_distribution

BEARING_LENGTHS = ("bore", "outer_diameter", "width", "ball_diameter", "pitch_diameter",
                   "diametral_clearance", "gothic_arch_offset", "inner_shoulder_diameter",
                   "outer_shoulder_diameter", "raceway_roughness", "element_roughness")
CAGE_LENGTHS = ("width", "inner_diameter", "outer_diameter", "pocket_clearance",
                "guide_land_diameter", "guide_clearance", "land_width")


def _times(value, factor):
    return None if value is None else value * factor


def _scaled(bearing, L: float):
    cage = bearing.cage
    cage_kw = {f: _times(getattr(cage, f), L) for f in CAGE_LENGTHS}
    cage_kw["mass"] = _times(cage.mass, L**3)
    return dataclasses.replace(bearing, cage=dataclasses.replace(cage, **cage_kw),
                               **{f: _times(getattr(bearing, f), L) for f in BEARING_LENGTHS})


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@example(name="SKF6304", size=1.221020420499981, fr=15158.824274953751, fa=4186.8,
         backwards=False, speed=0.0, gyroscopic="none")
@given(name=st.sampled_from(["SKF6304", "QJ1044"]), size=st.floats(0.1, 10.0),
       fr=st.floats(10.0, 3e4), fa=st.floats(10.0, 2e4), backwards=st.booleans(),
       speed=st.one_of(st.just(0.0), st.floats(10.0, 3000.0)),
       gyroscopic=st.sampled_from(["none", "shared"]))
def test_a_similar_ball_bearing_carries_the_load_alike(name, size, fr, fa, backwards, speed,
                                                       gyroscopic):
    b = load_bearing(name)
    if backwards and name == "QJ1044":   # a four-point bearing takes thrust either way
        fa = -fa
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ref = ball_load_distribution(b, fr, fa, speed, gyroscopic=gyroscopic)
        got = ball_load_distribution(_scaled(b, size), size**2 * fr, size**2 * fa,
                                     speed / size, gyroscopic=gyroscopic)
    assert ref.converged and got.converged
    top = float(max(np.max(ref.inner_load), np.max(ref.outer_load)))
    for field in ("inner_load", "outer_load", "centrifugal_force"):
        np.testing.assert_allclose(getattr(got, field) / size**2, getattr(ref, field), rtol=0,
                                   atol=1e-6 * top, err_msg=field)
    np.testing.assert_allclose(got.gyroscopic_moment / size**3, ref.gyroscopic_moment, rtol=0,
                               atol=1e-6 * top * b.ball_diameter)
    for field in ("inner_contact_angle", "outer_contact_angle"):
        np.testing.assert_allclose(getattr(got, field), getattr(ref, field), rtol=0, atol=1e-5,
                                   err_msg=field)
    shift = max(abs(ref.delta_a), abs(ref.delta_r))
    assert abs(got.delta_a / size - ref.delta_a) <= 1e-5 * shift
    assert abs(got.delta_r / size - ref.delta_r) <= 1e-5 * shift


def test_balls_at_a_round_off_load_report_the_nominal_angle():
    """The module docstring's case: the four unloaded balls report 0 rad at both sizes."""
    b = load_bearing("SKF6304")
    size = 1.221020420499981
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        for bearing, f in ((b, 1.0), (_scaled(b, size), size**2)):
            r = ball_load_distribution(bearing, 15158.824274953751 * f, 4186.8 * f, 0.0)
            unloaded = r.outer_load < 1e-12 * float(np.max(r.outer_load))
            assert np.count_nonzero(unloaded) == 4
            assert np.all(r.outer_contact_angle[unloaded] == b.contact_angle)
            assert np.all(r.inner_contact_angle[unloaded] == b.contact_angle)
