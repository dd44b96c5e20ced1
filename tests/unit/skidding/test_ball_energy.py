"""Energy identity of the ball solver at a low-speed, high-load state (issue 5: shaft torque x
inner-ring speed = total heat to 1e-8 relative at every converged state).

At 300 r/min, 40 kN axial load and hot oil the heat is small (~70 W) against the contact
forces, so a residual just inside the scaled tolerance (4e-10) left the identity at 7.3e-8
(session-4 code, finite-difference step 1e-6, measured); solve_ball now takes a chord step
more where the identity is above ``energy_tol`` (2e-9).
"""

from __future__ import annotations

import math

import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball import solve_ball
from thermobearing.skidding.ball_models import default_ball_models
from thermobearing.state import OilSupply


@pytest.fixture(scope="module")
def setup():
    w = 300 * math.pi / 30
    b = load_bearing("QJ1044")
    models = default_ball_models(b, load_lubricant("ISO_VG46"), temperature=353.15, speed=w,
                                 supply=OilSupply("jet", 33 / 60000, 313.15))
    return b, models, w


def _identity(r, w):
    return abs(r.shaft_torque * w / r.heat["total"] - 1.0)


def test_low_speed_high_load_state_closes_the_energy_balance(setup):
    b, models, w = setup
    r = solve_ball(b, models, w, 1000.0, 40e3, n_balls=16)
    assert _identity(r, w) < 2e-9
    # a +2 % warm step from it
    r2 = solve_ball(b, models, w, 1000.0, 40820.0, n_balls=16, guess=r)
    assert _identity(r2, w) < 2e-9


def test_chord_polish_tightens_a_loose_converged_state(setup):
    # a state just inside the solver tolerance (the converged one with the cage speed moved by
    # 2e-9 relative): its energy identity is loose; one chord step restores it
    from thermobearing.skidding.ball_newton import chord_polish
    from thermobearing.skidding.ball_result import _result

    b, models, w = setup
    r = solve_ball(b, models, w, 1000.0, 40e3, n_balls=16)
    system = r.extra["system"]
    X, G = r.unknowns
    Gp = G.copy()
    Gp[2] *= 1.0 + 2e-9
    loose = _result(system, X, Gp, 0.0, 0, 0.0, r.theoretical_cage_speed_ratio)
    assert _identity(loose, w) > 1e-8
    X2, G2, nrm, taken = chord_polish(system, X, Gp, system.last_jacobian)
    assert taken and nrm < 1e-9
    tight = _result(system, X2, G2, nrm, 1, 0.0, r.theoretical_cage_speed_ratio)
    # measured 7.7e-10 with the finite-difference chord Jacobian, 2.2e-9 with the analytic
    # one (session 7; the converged state itself is at 1.3e-9 there, its residual 1.4e-11):
    # inside the 1e-8 either way, from 1.6e-5 before the step
    assert _identity(tight, w) < 5e-9
    assert tight.cage_speed_ratio == pytest.approx(r.cage_speed_ratio, rel=1e-10)
