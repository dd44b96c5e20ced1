"""A thermal runaway with an oil whose laws end below 300 degC (found by the scene fuzzer):
OIL_4109's Roelands pressure-viscosity law needs eta > 6.31e-5 Pa s, which it leaves near
226 degC, so a steady solve heading for a runaway (passes at 86, 186, 286 degC) stopped at
the next kinematics solve with 'eta0 = 1.76e-05 is not allowed', naming no scene field. The
runaway limit of a run is now the lower of 300 degC and the lubricant's own limit."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing.coupled import (
    RUNAWAY_TEMPERATURE,
    _check_runaway,
    _Linear,
    lubricant_temperature_limit,
)
from thermobearing.errors import ConvergenceError
from thermobearing.lubricant import load_lubricant


def test_limit_is_where_the_oil_laws_end():
    oil = load_lubricant("OIL_4109")
    limit = lubricant_temperature_limit(oil)
    assert 200.0 + 273.15 < limit < RUNAWAY_TEMPERATURE
    oil.pressure_viscosity_coefficient(limit)  # usable at the limit
    assert lubricant_temperature_limit(load_lubricant("ISO_VG46")) == RUNAWAY_TEMPERATURE


def test_runaway_message_names_the_lubricant_limit():
    lin = _Linear(np.array([1000.0, 0.0]), np.zeros((2, 2)), np.full(2, 300.0))
    T = np.array([559.0, 400.0])
    _check_runaway(["a.rollers", "a.oil"], T, None, 0, lin)  # below 300 degC
    with pytest.raises(ConvergenceError, match=r"'a\.rollers' reached 286 degC \(limit 226 "
                                               r"degC: the lubricant's viscosity laws end"):
        _check_runaway(["a.rollers", "a.oil"], T, None, 0, lin, 499.15)
