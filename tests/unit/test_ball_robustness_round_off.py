"""Is a ball skidding state accepted at the round-off floor of its residual a solution?
(thermobearing.skidding.ball_round_off). The catalogue 6206 at 1132 r/min, 322 N radial,
ISO VG46 with the contacts at -30 degC is accepted with a scaled residual of 1.8e-3 (forces
/ F_s = 35.8 N) against a one-ulp floor of 0.13: the Eyring traction is a Coulomb step
there (ball_coulomb). Checked independently: the residual re-evaluated at the returned
state, the ring and cage equations met to round-off, the CSR of a solve converged below the
tolerance with another contact quadrature. Invariants, not a solver path."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import ConvergenceError, ValidityWarning
from thermobearing.skidding import solve
from thermobearing.skidding.ball_models import BallParameters
from thermobearing.skidding.ball_round_off import (
    FLOOR_FACTOR,
    accept_at_round_off,
    round_off_floor,
)
from thermobearing.state import OilSupply

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "catalogue_bearing_6206.toml"
SPEED = 1132.21 * math.pi / 30.0
RADIAL = 321.938
T_CONTACT = 273.15 - 30.0


def _solve(params=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return solve(load_bearing(str(EXAMPLE)), load_lubricant("ISO_VG46"), SPEED, RADIAL,
                     0.0, T_CONTACT, supply=OilSupply("jet", 0.0662453e-3 / 60.0, T_CONTACT),
                     params=params)


@pytest.fixture(scope="module")
def accepted():
    return _solve()


def test_accepted_state_is_a_solution_of_the_ring_and_cage_balance(accepted) -> None:
    r = accepted
    assert r.converged and r.extra["fallback"] == "round_off"
    system = r.extra["system"]
    X, G = r.unknowns
    R, Gc, G0, _ = system.evaluate(X, G)
    # the reported residual is the residual of the returned state
    assert float(system.last_norm) == pytest.approx(r.residual_norm, rel=1e-12)
    assert r.residual_norm <= FLOOR_FACTOR * r.extra["round_off_floor"]
    # inner-ring force balance and cage torque balance (they set the CSR) to the tolerance;
    # the rest of the residual is in single balls' rows, where the traction steps
    assert np.all(np.abs(Gc.sum(axis=0) + G0) <= 1e-9)
    heat = r.heat["total"]
    assert heat > 0.0 and abs(r.shaft_torque * r.inner_speed - heat) <= 1e-8 * heat


def test_accepted_csr_matches_a_converged_solve_with_another_quadrature(accepted) -> None:
    """10 x 5 contact nodes instead of 8 x 4: converges below the tolerance (measured
    2.2e-10) to a CSR 3e-5 from the accepted one (0.313976 / 0.313997); the quadrature
    itself moves the CSR by about 1e-4 at converged points."""
    other = _solve(BallParameters(n_major=10, n_minor=5))
    assert other.converged and other.residual_norm <= 1e-9
    assert other.extra.get("fallback") != "round_off"
    assert accepted.cage_speed_ratio == pytest.approx(other.cage_speed_ratio, rel=1e-3)
    # the cold oil slows the cage well below pure rolling (0.3965) at this point
    assert 0.25 < accepted.cage_speed_ratio < 0.38


def test_ring_out_of_balance_is_not_accepted_whatever_the_floor(accepted) -> None:
    """The same state against a radial load 1 mN higher: the norm is still far inside
    FLOOR_FACTOR x the one-ulp floor of the ball rows (1.8e-3 against 0.53), but the ring's
    radial balance is off by 1e-3 N / F_s = 2.8e-5, far above its own floor (1.7e-11)."""
    system = accepted.extra["system"]
    X, G = accepted.unknowns
    off = system.reloaded(RADIAL + 1e-3, 0.0)
    off.evaluate(X, G)
    norm = float(off.last_norm)
    floor, _ = round_off_floor(off, X, G)
    assert norm <= FLOOR_FACTOR * floor          # the norm alone would pass
    err = ConvergenceError("skidding.ball", norm, "test", {})
    err.iterate = (X, G, norm)
    assert accept_at_round_off(off, 1e-9, [err]) is None
    # the state at its own load is accepted
    err.iterate = (X, G, accepted.residual_norm)
    assert accept_at_round_off(system, 1e-9, [err]) is not None
