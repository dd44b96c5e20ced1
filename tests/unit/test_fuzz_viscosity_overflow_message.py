"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1, case 33): a steady run whose fixed-point
iteration passed 800 K stopped with the ball models' 4001-point pressure grid printed in
the error ("pressure = array([0.00000e+00, 1.25000e+06, ...], shape=(4001,))"). The
pressure-viscosity laws now name the first pressure at which the viscosity overflows,
with the law's parameters there."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing import load_lubricant
from thermobearing.errors import InputError
from thermobearing.viscosity_laws import barus_viscosity, roelands_viscosity


def test_lubricant_grid_overflow_names_one_pressure():
    oil = load_lubricant("ISO_VG32")
    grid = np.linspace(0.0, 5.0e9, 4001)   # the ball models' tabulation (ball_models.py)
    with pytest.raises(InputError) as err:
        oil.dynamic_viscosity(801.75, grid)   # the contact temperature the run reached
    text = str(err.value)
    assert "array(" not in text and "\n" not in text
    p_bad = float(err.value.value.split()[0])
    assert 0.0 < p_bad <= 5.0e9
    # the pressure named is the first one that overflows: the one before it is finite
    before = grid[np.searchsorted(grid, p_bad) - 1]
    assert np.isfinite(oil.dynamic_viscosity(801.75, before))


def test_law_messages_give_the_parameters():
    with pytest.raises(InputError, match=r"pressure = '5e\+08 Pa'.*eta0 = 1000 Pa s, z = 3"):
        roelands_viscosity(1.0e3, np.linspace(0.0, 5.0e9, 11), 3.0)
    with pytest.raises(InputError, match=r"pressure = '1e\+11 Pa'.*alpha = 2e-08 1/Pa"):
        barus_viscosity(0.1, 2.0e-8, np.array([1.0e9, 1.0e11]))
