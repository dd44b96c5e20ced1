"""An arc loaded by round-off counts as unloaded for the reported contact angles, in the
load distribution (loads.ring_weighted_angle) and in the compiled summary of the skidding
result (skidding.ball_result._summary) alike.

The load distribution of SKF6304 at 15.2 kN radial / 4.2 kN axial scaled by 1.22 left its
unloaded balls at 1.5e-17 N beside 1.4e4 N (commit 9ef3b4b); the skidding summary decided
"loaded" by a load > 0 and would have reported such a ball's geometric angle. Solver output
of the skidding model was checked for such loads (scratch, 95 points: SKF6304 and QJ1044 at
50 / 1500 / 8000 r/min, 0 / 2 / 15.2 kN radial, 0 / 0.5 / 4.2 kN axial, at sizes 1 and
1.22): its smallest non-zero ring load was 4.5e-9 of the largest (SKF6304 at 50 r/min,
15.2 kN / 4.2 kN: the centrifugal load of an unloaded ball; 4.1e-6 at 1500 r/min), above the
1e-12 floor, so no reported angle changed; the summary now applies the same rule as the
helper it must equal.
"""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing.loads import ROUND_OFF_LOAD, ring_weighted_angle
from thermobearing.skidding.ball_result import _summary

A0 = 0.3                                   # nominal contact angle [rad]


def _case(q_small: float):
    # 3 balls x 2 arcs (inner, outer); ball 1's inner arc carries q_small at 0.9 rad
    Q = np.array([[1.4e4, 1.4e4], [q_small, 50.0], [0.0, 20.0]])
    alpha = np.array([[0.25, 0.26], [0.9, 0.31], [0.4, 0.32]])
    inner_f = np.array([1.0, 0.0])
    X = np.zeros((3, 6))
    X[:, 2] = -100.0
    heat = np.ones((3, 2))
    return Q, alpha, inner_f, X, heat


@pytest.mark.parametrize("q_small", [1.5e-17, 0.0, ROUND_OFF_LOAD * 1.4e4])
def test_round_off_load_reports_the_nominal_angle(q_small):
    Q, alpha, inner_f, X, heat = _case(q_small)
    ai, ao, ai_m, ao_m, spin, beta, yaw, per_arc = _summary(Q, alpha, inner_f, A0, X, heat,
                                                            ROUND_OFF_LOAD)
    inner = inner_f == 1.0
    np.testing.assert_array_equal(ai, ring_weighted_angle(Q, alpha, inner, A0))
    np.testing.assert_array_equal(ao, ring_weighted_angle(Q, alpha, ~inner, A0))
    assert ai[1] == A0 and ai[2] == A0
    # the inner-load-weighted means are those of ball 0 alone
    assert ai_m == pytest.approx(0.25, abs=1e-15)
    assert ao_m == pytest.approx(0.26, abs=1e-15)
    # the heat per arc still sums every ball
    np.testing.assert_array_equal(per_arc, [3.0, 3.0])


def test_a_small_real_load_keeps_its_angle():
    # 1e-9 of the largest (the solver's force tolerance): a load, not round-off
    Q, alpha, inner_f, X, heat = _case(1e-9 * 1.4e4)
    ai, ao, ai_m, *_ = _summary(Q, alpha, inner_f, A0, X, heat, ROUND_OFF_LOAD)
    assert ai[1] == pytest.approx(0.9, abs=1e-15)
    np.testing.assert_array_equal(ai, ring_weighted_angle(Q, alpha, inner_f == 1.0, A0))
    assert ai_m == pytest.approx((1.4e4 * 0.25 + 1.4e-5 * 0.9) / (1.4e4 + 1.4e-5), rel=1e-14)


def test_nothing_loaded_reports_the_nominal_angle_everywhere():
    Q, alpha, inner_f, X, heat = _case(0.0)
    Q[:] = 0.0
    ai, ao, ai_m, ao_m, *_ = _summary(Q, alpha, inner_f, A0, X, heat, ROUND_OFF_LOAD)
    assert np.all(ai == A0) and np.all(ao == A0) and ai_m == A0 and ao_m == A0
    np.testing.assert_array_equal(ring_weighted_angle(Q, alpha, inner_f == 1.0, A0), A0)
