"""Ball skidding states accepted at the round-off floor of their residual
(thermobearing.skidding.ball_round_off)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.bearing_config import load_bearing
from thermobearing.errors import ValidityWarning
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import solve
from thermobearing.skidding.ball_round_off import FLOOR_FACTOR, round_off_floor
from thermobearing.state import OilSupply

# a fuzzed oil-bath scene: SKF6304 at 10012 r/min, 573 N radial, contacts at -13.8 degC in
# ISO VG46 (the oil near its pour point); every fallback stops above the 1e-9 tolerance and
# the run stopped (2.3e-9 when found); the state is now accepted at its round-off floor with
# a residual of 3.4e-6 against a floor of 6.7e-5 (its CSR 0.3676007 is the 0.3676003 of the
# same point converged at -8 degC)
SPEED = 10012.1 * math.pi / 30
SUPPLY = OilSupply("oil_bath", 0.0, 356.63, level=0.0144324)


@pytest.fixture(scope="module")
def cold():
    return solve(load_bearing("SKF6304"), load_lubricant("ISO_VG46"), SPEED, 573.448, 0.0,
                 259.35, supply=SUPPLY)


def test_cold_oil_state_is_accepted_at_its_round_off_floor(cold):
    assert cold.converged and cold.extra["fallback"] == "round_off"
    floor = cold.extra["round_off_floor"]
    assert cold.residual_norm <= FLOOR_FACTOR * floor
    # the floor is real: recomputed at the accepted state from its Jacobian
    X, G = cold.unknowns
    again, _ = round_off_floor(cold.extra["system"], X, G)
    assert again == pytest.approx(floor, rel=1e-12)
    # measured: the energy identity closes to 3e-5 there (1e-8 is out of reach in double
    # precision at this floor); a warm oil gives a state inside the tolerance
    heat = cold.heat["total"]
    assert abs(cold.shaft_torque * cold.inner_speed - heat) / heat < 1e-4
    assert 0.0 < cold.cage_speed_ratio < 0.5


def test_warm_oil_needs_no_round_off_acceptance():
    warm = solve(load_bearing("SKF6304"), load_lubricant("ISO_VG46"), SPEED, 573.448, 0.0,
                 265.0, supply=SUPPLY)
    assert warm.converged and warm.extra.get("fallback") is None
    assert warm.residual_norm < 1e-9


def test_the_scene_path_says_so():
    from thermobearing.kinematic_models import KINEMATICS
    from thermobearing.state import OperatingPoint

    op = OperatingPoint(inner_speed=SPEED, radial_load=573.448, axial_load=0.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        res = KINEMATICS.get("skidding")(load_bearing("SKF6304"), load_lubricant("ISO_VG46"),
                                        op, contact_temperature=259.35,
                                        oil_temperature=259.35, supply=SUPPLY)
    assert res.converged
    texts = [str(w.message) for w in caught]
    assert any("accepted at the round-off floor" in t and "-13.8 degC" in t for t in texts)
    assert np.isfinite(res.cage_speed_ratio)
