"""The memo of the theoretical cage speed ratio (ball_result.theoretical_csr).

CSR_th is a pure function of the zero-speed load distribution's inputs; the memo must return
the value of a fresh computation to the last bit, and bearings or loads that differ in any of
those inputs must not share an entry.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like
from thermobearing.loads import ball_load_distribution
from thermobearing.skidding import ball_result
from thermobearing.skidding.ball_result import theoretical_csr


def _direct(bearing, fr, fa, z=None):
    # the definition (paper 002 section 4.1): (1 - D cos(alpha)/d_m)/2 at the load-weighted
    # inner contact angle of the zero-speed distribution
    ld = ball_load_distribution(bearing, fr, fa, 0.0, n_balls=z)
    alpha = np.sum(ld.inner_load * ld.inner_contact_angle) / np.sum(ld.inner_load)
    return 0.5 * (1.0 - bearing.ball_diameter * math.cos(alpha) / bearing.pitch_diameter)


def test_memo_returns_the_fresh_value_and_keys_on_every_input():
    ball_result._CSR_TH_MEMO.clear()
    b = qj_like()
    first = theoretical_csr(b, 1000.0, 8000.0)
    assert len(ball_result._CSR_TH_MEMO) == 1
    assert first == _direct(b, 1000.0, 8000.0)
    assert theoretical_csr(b, 1000.0, 8000.0) == first            # hit: same bits
    assert len(ball_result._CSR_TH_MEMO) == 1
    # an equal but distinct bearing object hits the same entry
    assert theoretical_csr(qj_like(), 1000.0, 8000.0) == first
    assert len(ball_result._CSR_TH_MEMO) == 1
    # any changed input is a new entry with its own value
    others = [(qj_like(diametral_clearance=0.25e-3), 1000.0, 8000.0, None),
              (qj_like(inner_conformity=0.54), 1000.0, 8000.0, None),
              (b, 1000.0, 8000.5, None), (b, 1200.0, 8000.0, None), (b, 1000.0, 8000.0, 16)]
    for bb, fr, fa, z in others:
        v = theoretical_csr(bb, fr, fa, z)
        assert v == _direct(bb, fr, fa, z)
        assert v != first
    assert len(ball_result._CSR_TH_MEMO) == 1 + len(others)


def test_memo_is_bounded():
    ball_result._CSR_TH_MEMO.clear()
    b = qj_like()
    n = ball_result._CSR_TH_MEMO_SIZE
    for k in range(n):
        ball_result._CSR_TH_MEMO[("fake", k)] = 0.4
    theoretical_csr(b, 1000.0, 5000.0)
    assert len(ball_result._CSR_TH_MEMO) == n
    assert ("fake", 0) not in ball_result._CSR_TH_MEMO       # the oldest entry went
    assert ("fake", 1) in ball_result._CSR_TH_MEMO
    ball_result._CSR_TH_MEMO.clear()


def test_reloaded_system_knows_the_residual_of_the_previous_solution():
    # reloaded(): the loads enter the residual only through the constant global part and the
    # force / moment / torque scales, so the previous solution's residual at the new loads is
    # the old one rescaled; it must equal a fresh kernel evaluation to round-off
    from tests.unit.skidding.helpers import simple_models
    from thermobearing.skidding.ball import solve_ball
    from thermobearing.skidding.ball_residual import ball_residual_system

    b = qj_like()
    models = simple_models(b)
    w = 1800 * math.pi / 30
    r = solve_ball(b, models, w, 1000.0, 6000.0)
    X, G = r.unknowns
    new = r.extra["system"].reloaded(1000.0, 6200.0)
    n0 = new.n_eval
    R, Gc, G0, _ = new.evaluate(X, G)
    assert new.n_eval == n0                        # no kernel call
    fresh = ball_residual_system(b, models, w, 1000.0, 6200.0)
    Rf, Gcf, G0f, _ = fresh.evaluate(X, G)
    np.testing.assert_allclose(R, Rf, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(Gc, Gcf, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(G0, G0f, rtol=1e-14, atol=0)
    # the global residual is the load step: 200 N over the new force scale
    assert abs((Gc.sum(0) + G0)[0] - 200.0 / new.F_s) < 1e-6
    # and the warm start from it converges to the fresh cold solution
    r2 = solve_ball(b, models, w, 1000.0, 6200.0, guess=r)
    rc = solve_ball(b, models, w, 1000.0, 6200.0)
    assert r2.cage_speed_ratio == pytest.approx(rc.cage_speed_ratio, rel=1e-8)


def test_summary_angles_equal_the_load_distribution_helper():
    # the compiled summary of ball_result against loads.ring_weighted_angle (numpy)
    from tests.unit.skidding.helpers import simple_models
    from thermobearing.loads import ring_weighted_angle
    from thermobearing.skidding.ball import solve_ball

    b = qj_like()
    r = solve_ball(b, simple_models(b), 1500 * math.pi / 30, 1000.0, 3000.0)
    inner = r.ring == 0
    for sel, key in ((inner, "inner_contact_angle"), (~inner, "outer_contact_angle")):
        ref = ring_weighted_angle(r.normal_load, r.contact_angle, sel, float(b.contact_angle))
        np.testing.assert_allclose(r.extra[key], ref, rtol=1e-14, atol=0)
    np.testing.assert_allclose(r.spin_speed, np.linalg.norm(r.spin, axis=1), rtol=1e-14)
