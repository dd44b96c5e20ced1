"""The tabulated viscosity of the ball skidding solver with an empty pressure range
(session 20 fuzzer): ``IsothermalViscosity`` divided by p_max for its grid step, a
ZeroDivisionError when p_max was 0 (asked for, or a Lubricant built in Python whose
pressure law overflows at every p > 0). The table is now the one point p = 0 and any
p > 0 goes to the lubricant's own law."""

from __future__ import annotations

import math
import sys

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.lubricant import Lubricant, load_lubricant
from thermobearing.skidding.ball_models import IsothermalViscosity


def test_p_max_zero_gives_a_one_point_table_and_the_lubricant_beyond_it() -> None:
    lub = load_lubricant("ISO_VG46")
    iso = IsothermalViscosity(lub, 330.0, p_max=0.0)
    assert iso.p_max == 0.0
    eta0 = float(lub.dynamic_viscosity(330.0, 0.0))
    assert float(iso.dynamic_viscosity(330.0, 0.0)) == pytest.approx(eta0, rel=1e-14)
    ln, slope, inv_dp = iso.viscosity_table(330.0, 0.0)
    assert ln.shape == (1,) and inv_dp == 0.0 and slope[0] == 0.0
    assert iso.viscosity_table(330.0, 1.0) is None  # beyond the table: not tabulated
    p = np.array([1e6, 1e8, 1e9])
    np.testing.assert_allclose(iso.dynamic_viscosity(330.0, p),
                               np.asarray(lub.dynamic_viscosity(330.0, p), float), rtol=1e-14)


def test_a_law_finite_only_at_zero_pressure_gives_the_one_point_table() -> None:
    """eta0 at the largest float with Barus alpha = 2e-8 1/Pa: exp(alpha p) overflows it for
    every p above a few nPa, so the finite range ends at 0."""
    lub = Lubricant(name="edge", source="test: an overflowing law", viscosity_law="isothermal",
                    viscosity_parameters={"eta0": sys.float_info.max},
                    density_reference=870.0, pressure_law="barus",
                    pressure_parameters={"alpha": 2e-8})
    iso = IsothermalViscosity(lub, 330.0)
    assert iso.p_max == 0.0
    assert math.isfinite(float(iso.dynamic_viscosity(330.0, 0.0)))
    with pytest.raises(InputError, match="pressure"):  # the lubricant names the pressure
        iso.dynamic_viscosity(330.0, 1e6)


@pytest.mark.parametrize("p_max", [-1.0, math.inf, math.nan])
def test_a_negative_or_non_finite_top_is_refused(p_max) -> None:
    with pytest.raises(InputError) as info:
        IsothermalViscosity(load_lubricant("ISO_VG46"), 330.0, p_max=p_max)
    assert info.value.field == "IsothermalViscosity.p_max"


def test_fewer_than_two_grid_points_are_refused() -> None:
    with pytest.raises(InputError) as info:
        IsothermalViscosity(load_lubricant("ISO_VG46"), 330.0, p_max=1e9, n=1)
    assert info.value.field == "IsothermalViscosity.n"
