"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1, case 33): a steady run whose fixed-point
iteration passed 800 K stopped with the ball models' 4001-point pressure grid printed in
the error ("pressure = array([0.00000e+00, 1.25000e+06, ...], shape=(4001,))"). The
pressure-viscosity laws now name the first pressure at which the viscosity overflows,
with the law's parameters there. (That ISO VG 32 overflow at 800 K came from the ASME fit's
Roelands z growing without bound in a thin oil, held since at the fit's lowest viscosity;
the grid's overflow is now that of a cold ISO VG 1500, whose z of 1.46 overflows a
Roelands viscosity above about 3 GPa.)"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermobearing import load_lubricant
from thermobearing.errors import InputError
from thermobearing.lubricant import lubricant_from_dict
from thermobearing.viscosity_laws import barus_viscosity, roelands_viscosity


def _vg1500():
    return lubricant_from_dict({
        "name": "ISO_VG1500_fuzz", "source": "fuzz input", "kind": "mineral",
        "viscosity": {"law": "astm_d341", "nu40": "1500 mm**2/s", "nu100": "63 mm**2/s"},
        "pressure_viscosity": {"law": "roelands", "alpha_correlation": "asme1953_mineral_fit"},
        "density": {"value": "900 kg/m**3", "reference_temperature": "15 degC",
                    "temperature_law": "astm_d1250_lube", "pressure_law": "dowson_higginson"},
        "thermal": {"model": "cragoe"}})


def test_lubricant_grid_overflow_names_one_pressure():
    oil = _vg1500()
    grid = np.linspace(0.0, 5.0e9, 4001)   # the ball models' tabulation (ball_models.py)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the alpha fit beyond its 5000 mPa s
        with pytest.raises(InputError) as err:
            oil.dynamic_viscosity(253.15, grid)   # a cold start at -20 degC
        text = str(err.value)
        assert "array(" not in text and "\n" not in text
        p_bad = float(err.value.value.split()[0])
        assert 0.0 < p_bad <= 5.0e9
        # the pressure named is the first one that overflows: the one before it is finite
        before = grid[np.searchsorted(grid, p_bad) - 1]
        assert np.isfinite(oil.dynamic_viscosity(253.15, before))


def test_hot_mineral_oil_grid_stays_finite():
    """ISO VG 32 at the 801.75 K of the original case: finite on the whole grid, falling
    with temperature (the z held below the alpha fit's 2.4 mPa s)."""
    oil = load_lubricant("ISO_VG32")
    grid = np.linspace(0.0, 5.0e9, 4001)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hot = oil.dynamic_viscosity(801.75, grid)
        warm = oil.dynamic_viscosity(573.15, grid)
    assert np.all(np.isfinite(hot)) and np.all(hot < warm)


def test_law_messages_give_the_parameters():
    with pytest.raises(InputError, match=r"pressure = '5e\+08 Pa'.*eta0 = 1000 Pa s, z = 3"):
        roelands_viscosity(1.0e3, np.linspace(0.0, 5.0e9, 11), 3.0)
    with pytest.raises(InputError, match=r"pressure = '1e\+11 Pa'.*alpha = 2e-08 1/Pa"):
        barus_viscosity(0.1, 2.0e-8, np.array([1.0e9, 1.0e11]))
