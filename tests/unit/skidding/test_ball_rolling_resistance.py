"""EHL rolling resistance of the ball contacts in the ball skidding balance (opt-in,
BallParameters.rolling_resistance): analytic Jacobian against central differences, the energy
identity with the force on, the heat source booking exactly the solver's power, default off."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like
from tests.unit.skidding.test_ball_jacobian import _central_blocks
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball import solve_ball
from thermobearing.skidding.ball_jacobian import analytic_blocks, supports_analytic
from thermobearing.skidding.ball_models import (
    BallParameters,
    default_ball_models,
    heat_context_options,
    rolling_supply_factor,
)
from thermobearing.state import OilSupply

W1800 = 1800 * math.pi / 30
SUPPLY = OilSupply("jet", 33 / 60000, 313.15)


@pytest.fixture(scope="module")
def bearing():
    return qj_like()


def _models(bearing, temperature, speed, model="harris", reduction="none"):
    params = BallParameters(rolling_resistance=model, rolling_resistance_reduction=reduction)
    return default_ball_models(bearing, load_lubricant("ISO_VG46"), temperature=temperature,
                               speed=speed, supply=SUPPLY, params=params), params


@pytest.mark.parametrize("reduction, temperature, rpm, fa", [
    ("none", 303.15, 1800.0, 10e3), ("thermal", 330.0, 3000.0, 2e3)])
def test_analytic_blocks_with_rolling_resistance_equal_central_differences(
        bearing, reduction, temperature, rpm, fa):
    w = rpm * math.pi / 30
    models, _ = _models(bearing, temperature, w, reduction=reduction)
    r = solve_ball(bearing, models, w, 1000.0, fa, theoretical_reference=0.45)
    system = r.extra["system"]
    X, G = r.unknowns
    assert supports_analytic(system) and system.rolling
    J = analytic_blocks(system, X, G)
    ref = _central_blocks(system, X, G)
    # the rolling terms' part of the blocks: the difference to the same state without the
    # rolling force, analytic against central differences (measured: the part is ~1e-3 of
    # the scaled entries, ~5e-5 of the blocks' largest, and the two agree to ~3e-9 absolute,
    # ~4e-6 of the part)
    plain, _ = _models(bearing, temperature, w, model="none")
    from thermobearing.skidding.ball_residual import ball_residual_system

    s0 = ball_residual_system(bearing, plain, w, 1000.0, fa)
    J0 = analytic_blocks(s0, X, G)
    ref0 = _central_blocks(s0, X, G)
    for name, fd, fd0 in zip(("A", "B", "C", "Dg"), ref, ref0, strict=True):
        an = getattr(J, name)
        # the tolerance of test_ball_jacobian (finite-difference truncation and round-off)
        assert np.abs(an - fd).max() <= 2e-5 * np.abs(fd).max(), name
        part_fd = fd - fd0
        part_an = an - getattr(J0, name)
        assert np.abs(part_an - part_fd).max() <= 1e-4 * max(np.abs(part_fd).max(), 1e-300)
        if name in ("A", "B"):        # the rolling force enters the ball balances only
            assert np.abs(part_fd).max() > 1e-4


@pytest.mark.parametrize("reduction", ["none", "thermal", "skf", "thermal_starvation"])
def test_energy_identity_and_heat_source_with_rolling_resistance(bearing, reduction):
    from thermobearing.heat_sources import HeatContext, evaluate
    from thermobearing.state import OperatingPoint

    t = 318.15
    models, params = _models(bearing, t, W1800, reduction=reduction)
    r = solve_ball(bearing, models, W1800, 1000.0, 4e3, theoretical_reference=0.45)
    assert r.converged
    heat = r.heat
    assert heat["rolling_resistance"] > 0.0
    assert heat["rolling_resistance"] == pytest.approx(
        heat["rolling_resistance_inner"] + heat["rolling_resistance_outer"], rel=1e-12)
    # issue 5's identity: shaft torque x ring speed = total heat
    assert abs(r.shaft_torque * W1800 / heat["total"] - 1.0) < 1e-8
    # the registered source books exactly the solver's rolling-resistance power from the
    # kinematic state (factor from the options, and from the state's extras without them)
    lub = load_lubricant("ISO_VG46")
    factor = rolling_supply_factor(bearing, SUPPLY, W1800, params, lub, t)
    for opts in (heat_context_options(bearing, SUPPLY, W1800, params, factor),
                 heat_context_options(bearing, SUPPLY, W1800, params)):
        ctx = HeatContext.isothermal(t, bearing=bearing, lubricant=lub, supply=SUPPLY,
                                     operating=OperatingPoint(W1800, 0.0, 1000.0, 4e3),
                                     kinematics=r.kinematic_state,
                                     traction=r.extra["traction_law"], options=opts)
        src = evaluate(["ehl_rolling_resistance"], ctx)[0]
        assert src.total == pytest.approx(heat["rolling_resistance"], rel=1e-12)


def test_reductions_lower_the_force_and_default_is_off(bearing):
    t = 318.15
    off, params = _models(bearing, t, W1800, model="none")
    assert off.rolling_resistance is None
    assert "ehl_rolling_resistance" not in heat_context_options(bearing, SUPPLY, W1800, params)
    r0 = solve_ball(bearing, off, W1800, 1000.0, 4e3, theoretical_reference=0.45)
    assert "rolling_resistance" not in r0.heat
    q = {}
    for red in ("none", "thermal", "skf", "thermal_starvation"):
        m, _ = _models(bearing, t, W1800, reduction=red)
        q[red] = solve_ball(bearing, m, W1800, 1000.0, 4e3,
                            theoretical_reference=0.45).heat["rolling_resistance"]
    assert q["thermal"] < q["none"] and q["skf"] < q["none"]
    assert q["thermal_starvation"] < q["thermal"]


def test_unknown_option_names_are_refused():
    from thermobearing.errors import UnknownNameError

    with pytest.raises(UnknownNameError, match="rolling_resistance"):
        BallParameters(rolling_resistance="line")
    with pytest.raises(UnknownNameError, match="rolling_resistance_reduction"):
        BallParameters(rolling_resistance="harris", rolling_resistance_reduction="starved")
