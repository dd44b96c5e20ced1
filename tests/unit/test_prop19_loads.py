"""Property tests of the ball load distribution's symmetries (:func:`thermobearing.loads.
ball_load_distribution`, session 19), beside the ring equilibrium of test_property_loads.py.

- pure axial load (no radial): every ball carries the same load (axisymmetric problem);
- pure radial load along azimuth 0: the loads are mirror-symmetric, Q(psi) = Q(-psi);
- a four-point bearing under -F_a mirrors the state under +F_a (the other pair of arcs);
- the most loaded ball carries more under a larger radial load.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.geometry import load_bearing
from thermobearing.loads import ball_load_distribution

BEARINGS = {name: load_bearing(name) for name in ("QJ1044", "SKF6304")}
SCALE = {"QJ1044": 1e5, "SKF6304": 8e3}


def _mirror_index(azimuth):
    """Index j of the ball at -psi_i for each i (azimuths on a uniform circle from 0)."""
    z = azimuth.size
    return (-np.arange(z)) % z


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(BEARINGS)), frac=st.floats(0.01, 1.0),
       rpm=st.floats(0.0, 3000.0))
def test_pure_axial_load_shares_equally(name, frac, rpm):
    fa = frac * SCALE[name]
    ld = ball_load_distribution(BEARINGS[name], 0.0, fa, rpm * math.pi / 30)
    assert ld.converged
    q = ld.inner_load
    assert np.max(q) - np.min(q) <= 1e-6 * np.max(q) + ld.residual_norm
    assert math.isclose(float(np.mean(ld.inner_contact_angle)),
                        float(ld.inner_contact_angle[0]), rel_tol=1e-6)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(BEARINGS)), frac=st.floats(0.01, 1.0),
       axial=st.floats(0.0, 1.0), rpm=st.floats(0.0, 3000.0))
def test_radial_load_along_zero_is_mirror_symmetric(name, frac, axial, rpm):
    fr = frac * SCALE[name]
    ld = ball_load_distribution(BEARINGS[name], fr, axial * fr, rpm * math.pi / 30)
    assert ld.converged
    assert math.isclose(float(ld.azimuth[0]), 0.0, abs_tol=1e-15)
    j = _mirror_index(ld.azimuth)
    slack = 1e-6 * float(np.max(ld.inner_load)) + 10 * ld.residual_norm
    np.testing.assert_allclose(ld.inner_load[j], ld.inner_load, rtol=0, atol=slack)
    np.testing.assert_allclose(ld.outer_load[j], ld.outer_load, rtol=0, atol=slack)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(frac=st.floats(0.01, 1.0), radial=st.floats(0.0, 0.5), rpm=st.floats(0.0, 3000.0))
def test_four_point_axial_sign_mirrors_the_state(frac, radial, rpm):
    b = BEARINGS["QJ1044"]
    fa = frac * SCALE["QJ1044"]
    w = rpm * math.pi / 30
    plus = ball_load_distribution(b, radial * fa, fa, w)
    minus = ball_load_distribution(b, radial * fa, -fa, w)
    slack = 1e-6 * float(np.max(plus.inner_load)) + 10 * (plus.residual_norm
                                                           + minus.residual_norm)
    np.testing.assert_allclose(minus.inner_load, plus.inner_load, rtol=0, atol=slack)
    np.testing.assert_allclose(minus.outer_load, plus.outer_load, rtol=0, atol=slack)
    assert math.isclose(minus.delta_a, -plus.delta_a, rel_tol=1e-6, abs_tol=1e-12)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(BEARINGS)), frac=st.floats(0.01, 0.5),
       more=st.floats(1.1, 2.0))
def test_most_loaded_ball_rises_with_radial_load(name, frac, more):
    b = BEARINGS[name]
    fr = frac * SCALE[name]
    q1 = float(np.max(ball_load_distribution(b, fr, 0.0).inner_load))
    q2 = float(np.max(ball_load_distribution(b, fr * more, 0.0).inner_load))
    assert q2 > q1


@settings(max_examples=60, deadline=None)
@given(z=st.integers(8, 40), clearance=st.one_of(st.just(0.0), st.floats(1e-7, 2e-4)),
       load=st.floats(1.0, 5e5), body=st.one_of(st.just(0.0), st.floats(0.1, 2000.0)),
       more=st.floats(1.1, 3.0))
def test_roller_loads_mirror_symmetric_and_rising(z, clearance, load, body, more):
    """Roller bearing under F_r along azimuth 0 (roller 0 under the load): Q(psi) = Q(-psi),
    no sideways ring displacement, and the most loaded roller carries more under more load."""
    from thermobearing.hertz import line_contact_stiffness
    from thermobearing.loads_roller import roller_load_distribution

    k = float(line_contact_stiffness(0.013))
    ld = roller_load_distribution(z, clearance, load, k, k, body_force=body)
    j = _mirror_index(ld.azimuth)
    slack = 1e-9 * max(load, float(np.max(ld.outer_load))) + 1e-9
    np.testing.assert_allclose(ld.inner_load[j], ld.inner_load, rtol=0, atol=slack)
    np.testing.assert_allclose(ld.outer_load[j], ld.outer_load, rtol=0, atol=slack)
    assert abs(float(ld.ring_displacement[1])) <= 1e-9 * abs(float(ld.ring_displacement[0])) \
        + 1e-15
    ld2 = roller_load_distribution(z, clearance, load * more, k, k, body_force=body)
    assert np.max(ld2.inner_load) > np.max(ld.inner_load)
