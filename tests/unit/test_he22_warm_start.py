"""BM-5 warm starts (session 22): the start a guess gives, and when a guess is not used.

A warm start begins at the guess's unknowns; its first chord step with the handed-over
Jacobian is the tangent predictor (the residual at the guess is dF/dp dp, the step
-J^-1 dF/dp dp). Pinned here: a zero step gives back the previous state without an
evaluation, a +2 % step lands on the state of a cold solve, and the rule of
:func:`~thermobearing.skidding.ball.solve_ball` that starts cold across a load change of more
than :data:`~thermobearing.skidding.ball.COLD_LOAD_STEP` of the load
(:func:`~thermobearing.skidding.ball.load_step_fraction`).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball import COLD_LOAD_STEP, load_step_fraction, solve_ball
from thermobearing.skidding.ball_models import default_ball_models
from thermobearing.state import OilSupply

W = 1650 * math.pi / 30
FR = 1000.0


@pytest.fixture(scope="module")
def point():
    """A converged QJ1044 state (Z = 16, 80 degC oil, 1650 r/min, 20 kN axial, 1 kN radial;
    a BM-5 map point) with the default compiled models."""
    b = load_bearing("QJ1044")
    lub = load_lubricant("ISO_VG46")
    supply = OilSupply("jet", 33 / 60000, 313.15)
    models = default_ball_models(b, lub, temperature=353.15, speed=W, supply=supply)
    r = solve_ball(b, models, W, FR, 20e3, n_balls=16, theoretical_reference=0.45)
    return b, models, r


def _same_state(a, b, csr_rel=1e-8):
    assert abs(a.cage_speed_ratio - b.cage_speed_ratio) <= csr_rel * abs(b.cage_speed_ratio)
    # ball positions to far below a micron, spins relative to their size
    np.testing.assert_allclose(a.ball_x, b.ball_x, rtol=0, atol=1e-10)
    np.testing.assert_allclose(a.ball_r, b.ball_r, rtol=0, atol=1e-10)
    scale = np.max(np.abs(b.spin))
    np.testing.assert_allclose(a.spin, b.spin, rtol=0, atol=1e-7 * scale)


def test_zero_step_returns_the_previous_state(point):
    b, models, r = point
    again = solve_ball(b, models, W, FR, 20e3, n_balls=16, guess=r, theoretical_reference=0.45)
    assert again.iterations == 0
    assert again.extra["n_eval"] == 0          # the guess's residual is known (reloaded)
    np.testing.assert_array_equal(again.unknowns[0], r.unknowns[0])
    np.testing.assert_array_equal(again.unknowns[1], r.unknowns[1])
    assert again.cage_speed_ratio == r.cage_speed_ratio
    assert "start" not in again.extra


def test_small_step_warm_lands_on_the_cold_state(point):
    b, models, r = point
    fa = 1.02 * 20e3 + 20.0
    warm = solve_ball(b, models, W, FR, fa, n_balls=16, guess=r, theoretical_reference=0.45)
    cold = solve_ball(b, models, W, FR, fa, n_balls=16, theoretical_reference=0.45)
    assert warm.converged and cold.converged
    assert warm.residual_norm <= 1e-9 and cold.residual_norm <= 1e-9
    assert "start" not in warm.extra
    assert warm.extra.get("n_jacobian", 0) < cold.extra.get("n_jacobian", 0)
    _same_state(warm, cold)


def test_load_step_fraction(point):
    _, _, r = point
    assert load_step_fraction(r, FR, 20e3) == 0.0
    big = math.hypot(FR, 20e3)
    # a collinear load ratio of 4 (or 1/4) is a fraction of 0.75, the default limit
    assert load_step_fraction(r, 4 * FR, 80e3) == pytest.approx(0.75, rel=1e-14)
    assert load_step_fraction(r, 0.25 * FR, 5e3) == pytest.approx(0.75, rel=1e-14)
    assert COLD_LOAD_STEP == 0.75
    # a reversed axial load
    want = 40e3 / big
    assert load_step_fraction(r, FR, -20e3) == pytest.approx(want, rel=1e-14)
    assert load_step_fraction(r, 0.0, 0.0) == pytest.approx(1.0, rel=1e-14)
    assert load_step_fraction(None, FR, 1.0) == 0.0


def test_large_load_step_starts_cold_on_the_same_state(point):
    b, models, r = point
    fa = 2e3                                  # 20 kN -> 2 kN: a fraction of 0.89
    assert load_step_fraction(r, FR, fa) > COLD_LOAD_STEP
    ruled = solve_ball(b, models, W, FR, fa, n_balls=16, guess=r, theoretical_reference=0.45)
    assert ruled.extra.get("start") == "cold_load_step"
    cold = solve_ball(b, models, W, FR, fa, n_balls=16, theoretical_reference=0.45)
    assert ruled.iterations == cold.iterations
    np.testing.assert_array_equal(ruled.unknowns[0], cold.unknowns[0])
    forced = solve_ball(b, models, W, FR, fa, n_balls=16, guess=r, theoretical_reference=0.45,
                        cold_load_step=math.inf)
    assert "start" not in forced.extra
    _same_state(forced, cold)


def test_warm_only_steps_keep_their_guess(point):
    """cold_fallback=False (the steps of the continuations) never drops the guess."""
    b, models, r = point
    fa = 0.5 * 20e3                           # 0.50: below the limit; force it to 0.1
    res = solve_ball(b, models, W, FR, fa, n_balls=16, guess=r, theoretical_reference=0.45,
                     cold_fallback=False, cold_load_step=0.1)
    assert "start" not in res.extra
    assert res.converged


@pytest.mark.parametrize("bad", [-0.1, float("nan"), "0.5", None])
def test_bad_cold_load_step_is_refused(point, bad):
    b, models, r = point
    with pytest.raises(InputError, match="cold_load_step"):
        solve_ball(b, models, W, FR, 20e3, n_balls=16, guess=r, cold_load_step=bad)
