"""Property tests, round 5: the 1-atm air table of :func:`air_properties`
(:mod:`thermobearing.lubricant_properties`), which the free-convection conductances use.

Invariants of a dilute gas (Incropera et al. 2007, Table A.4; kinetic theory, Chapman &
Cowling): at 1 atm and 250..1500 K air is an ideal gas to 0.2 % (compressibility factor
Z = p / (rho R T), R = 287.05 J/(kg K)); its viscosity and thermal conductivity rise with
temperature and its density falls; the Prandtl number is mu c_p / k.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.lubricant_properties import air_properties

_R_AIR = 287.05  # J/(kg K), dry air (M = 28.965 g/mol)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.floats(250.0, 1500.0), min_size=2, max_size=30, unique=True))
def test_air_is_an_ideal_gas_with_rising_transport_properties(temps):
    t = np.sort(np.asarray(temps))
    t = t[np.concatenate(([True], np.diff(t) > 1e-6))]
    a = air_properties(t)
    z = 101325.0 / (a.density * _R_AIR * t)
    assert np.all(np.abs(z - 1.0) < 2e-3), z
    if t.size > 1:
        assert np.all(np.diff(a.dynamic_viscosity) > 0.0)
        assert np.all(np.diff(a.thermal_conductivity) > 0.0)
        assert np.all(np.diff(a.density) < 0.0)
    np.testing.assert_allclose(a.prandtl, a.dynamic_viscosity * a.specific_heat
                               / a.thermal_conductivity, rtol=1e-12)
