"""Ball skidding in very cold, still liquid oil: the isothermal viscosity table of the traction
law ends where the lubricant's pressure-viscosity law overflows (ISO VG100 at -37 degC:
Roelands eta is infinite from 4.46 GPa) instead of refusing the operating point for a
pressure no contact reaches. Invariants of the converged state, not a solver path."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import InputError, ValidityWarning
from thermobearing.skidding import solve
from thermobearing.skidding.ball_models import IsothermalViscosity, finite_pressure_limit
from thermobearing.state import OilSupply

T_COLD = 273.15 - 37.0


@pytest.fixture(scope="module")
def vg100():
    return load_lubricant("ISO_VG100")


def test_table_ends_at_the_finite_range(vg100) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        # the law itself overflows inside the former 0-5 GPa grid
        with pytest.raises(InputError, match="pressure"):
            vg100.dynamic_viscosity(T_COLD, np.linspace(0.0, 5e9, 11))
        p_lim = finite_pressure_limit(vg100, T_COLD, 5e9)
        assert 1e9 < p_lim < 5e9
        assert math.isfinite(float(vg100.dynamic_viscosity(T_COLD, p_lim)))
        with pytest.raises(InputError):
            vg100.dynamic_viscosity(T_COLD, p_lim * (1.0 + 1e-6))
        iso = IsothermalViscosity(vg100, T_COLD)
        assert iso.p_max == p_lim
        # interpolated ln eta against the law at contact pressures
        p = np.array([0.0, 0.5e9, 1.0e9, 2.0e9])
        exact = np.log(vg100.dynamic_viscosity(T_COLD, p))
        assert np.allclose(np.log(iso.dynamic_viscosity(T_COLD, p)), exact, rtol=1e-4)
        # beyond the table: the lubricant, which refuses naming the pressure
        with pytest.raises(InputError, match="pressure"):
            iso.dynamic_viscosity(T_COLD, 0.999 * 5e9)
        # a warm oil keeps the full grid
        assert finite_pressure_limit(vg100, 313.15, 5e9) == 5e9


def test_qj1044_solves_at_minus_37_degc(vg100) -> None:
    b = load_bearing("QJ1044")
    w = 1000.0 * math.pi / 30.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = solve(b, vg100, w, 0.0, 4000.0, T_COLD,
                  supply=OilSupply("jet", 1e-6, T_COLD))
    assert r.converged and r.residual_norm <= 1e-9
    heat = r.heat["total"]
    assert heat > 0.0
    assert abs(r.shaft_torque * r.inner_speed - heat) <= 1e-8 * heat
    # the cage turns forwards and no faster than pure rolling allows
    assert 0.0 < r.cage_speed_ratio < r.theoretical_cage_speed_ratio


def test_coulomb_traction_is_refused_saying_why() -> None:
    """The catalogue 6206 at 1132 r/min, 322 N radial, contacts at -38.24 degC in ISO VG46
    (a fuzzed steady scene): the Eyring traction saturates within ~1e-27 m/s of slip, a
    Coulomb step at every quadrature node; every fallback fails (residual 3.5e-2 to 1.5e-1)
    and the error says why, naming the contact temperature, with a finite residual."""
    from thermobearing.errors import ConvergenceError

    b = load_bearing(str(Path(__file__).resolve().parents[2] / "examples"
                         / "catalogue_bearing_6206.toml"))
    T = 273.15 - 38.24
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        with pytest.raises(ConvergenceError) as info:
            solve(b, load_lubricant("ISO_VG46"), 1132.21 * math.pi / 30.0, 321.938, 0.0, T,
                  supply=OilSupply("jet", 0.0662453e-3 / 60.0, 273.15 - 37.24))
    text = str(info.value)
    assert "contact temperature -38.24 degC" in text and "Coulomb step" in text
    assert math.isfinite(info.value.residual) and info.value.residual > 1e-9
