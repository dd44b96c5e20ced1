"""The trust-region fallback of solve_ball.

At the BM-5 map point QJ1044 with 16 balls, 30 degC ISO VG46 (33 L/min jets), 3000 r/min,
Fr = 1 kN, Fa = 15.7 kN the damped Newton of ``newton_block`` stalls at a scaled residual of
1.9e-3 (measured: the line search accepts ~1e-3 of every Newton step) and the axial-load
continuation stalled the same way, so the point failed (also with earlier code);
Powell's hybrid method (``ball_newton.trust_region``, scipy's MINPACK hybrd) from the stalled
iterate converges. The map and its settings are those of benchmarks/bm5_skidding.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import ConvergenceError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball import newton_block, race_control_guess, solve_ball
from thermobearing.skidding.ball_models import default_ball_models
from thermobearing.skidding.ball_residual import ball_residual_system
from thermobearing.state import OilSupply

W3000 = 3000 * math.pi / 30
FA = 15703.478868388196          # 20 x 20 BM-5 map: geomspace(40 kN, 200 N, 18)[5]


@pytest.fixture(scope="module")
def setting():
    b = load_bearing("QJ1044")
    lub = load_lubricant("ISO_VG46")
    supply = OilSupply("jet", 33 / 60000, 303.15)
    return b, default_ball_models(b, lub, temperature=303.15, speed=W3000, supply=supply)


def test_newton_alone_stalls_there(setting):
    # the reason for the fallback: the damped Newton with the finite-difference Jacobian does
    # not converge at this point
    b, m = setting
    system = ball_residual_system(b, m, W3000, 1000.0, FA, 16)
    X0, G0, _ = race_control_guess(b, W3000, 1000.0, FA, 16)
    with pytest.raises(ConvergenceError) as info:
        newton_block(system, X0, G0, max_iter=60, analytic=False)
    X, G, nrm = info.value.iterate
    assert 1e-9 < nrm < 1e-2 and X.shape == (16, 6) and G.shape == (3,)


def test_newton_with_the_analytic_jacobian_converges_there(setting):
    # with the analytic Jacobian (skidding/ball_jacobian.py; exact where the
    # finite-difference spin columns straddle the Eyring knee) the same Newton converges
    b, m = setting
    system = ball_residual_system(b, m, W3000, 1000.0, FA, 16)
    X0, G0, _ = race_control_guess(b, W3000, 1000.0, FA, 16)
    X, G, nrm, it = newton_block(system, X0, G0, max_iter=60)
    assert nrm <= 1e-9 and it < 60
    r = solve_ball(b, m, W3000, 1000.0, FA, n_balls=16, theoretical_reference=0.45)
    assert "fallback" not in r.extra
    assert r.cage_speed_ratio == pytest.approx(G[2] / W3000, rel=1e-9)


def test_solve_ball_converges_through_the_fallback(setting, monkeypatch):
    # the fallback path, exercised with the finite-difference Jacobian (still the path of
    # models without the analytic one)
    from thermobearing.skidding import ball as ball_mod

    b, m = setting
    original = ball_mod.newton_block
    monkeypatch.setattr(ball_mod, "newton_block",
                        lambda *a, **k: original(*a, **{**k, "analytic": False}))
    r = solve_ball(b, m, W3000, 1000.0, FA, n_balls=16, theoretical_reference=0.45)
    assert r.converged and r.residual_norm <= 1e-9
    assert r.extra.get("fallback") == "trust_region"
    # the stall was detected early (stall_after=25: 36 Newton iterations measured, not 150)
    assert r.iterations < 60
    # the residual of the returned state, evaluated afresh in a new system
    system = ball_residual_system(b, m, W3000, 1000.0, FA, 16)
    R, Gc, G0, _ = system.evaluate(*r.unknowns)
    assert math.sqrt(np.sum(R ** 2) + np.sum((Gc.sum(0) + G0) ** 2)) <= 1e-9
    # issue 5: shaft torque x speed = total heat to 1e-8
    assert abs(r.shaft_torque * W3000 - r.heat["total"]) <= 1e-8 * r.heat["total"]
    assert 0.3 < r.cage_speed_ratio < 0.5
    # the warm +2 % step from there converges without the fallback
    r2 = solve_ball(b, m, W3000, 1000.0, 1.02 * FA + 20.0, n_balls=16, guess=r,
                    theoretical_reference=0.45)
    assert r2.residual_norm <= 1e-9 and "fallback" not in r2.extra
    assert r2.cage_speed_ratio == pytest.approx(r.cage_speed_ratio, rel=2e-3)
