"""Moes' line film at a vanishing pressure-viscosity parameter: the isoviscous limit without
an overflow warning (h_rp**-3.5 overflowed to inf for L below ~1e-130, whose power is the
right limit 0)."""

import warnings

import pytest

from thermobearing.film import moes_line_central

ARGS = dict(entrainment_speed=5.0, dynamic_viscosity=0.01, load=2000.0, length=0.01,
            reduced_radius_x=0.005, effective_modulus=2.3e11)


def test_tiny_alpha_is_the_isoviscous_film_without_a_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        tiny = moes_line_central(pressure_viscosity_coefficient=1e-160, **ARGS)
    iso = moes_line_central(pressure_viscosity_coefficient=0.0, **ARGS)
    assert float(tiny) == pytest.approx(float(iso), rel=1e-9)
