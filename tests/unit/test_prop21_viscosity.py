"""Property tests of the viscosity laws and the lubricant presets' consistency (session 21),
beside the monotonicity and error checks of test_property_lubricant.py.

Pressure laws (:mod:`thermobearing.viscosity_laws`, Roelands 1966, Barus 1893, Blok 1963):

- a Roelands oil and the Barus oil with its initial slope alpha = z S / p0
  (S = ln eta0 + 9.67) agree at small pressure, ln(eta_R / eta_B) = O(p^2); for z <= 1
  Roelands lies below Barus at every pressure ((1 + p/p0)^z - 1 <= z p / p0), above it
  for z > 1;
- Blok's asymptotic isoviscous alpha* (closed form with the upper incomplete gamma
  function) is 1 / int_0^inf eta0 / eta dp by quadrature (measured within 5e-15 over 200
  draws, z 0.3-1.5), below the initial slope for z < 1, equal at z = 1, above for z > 1;
  never NaN: z below 0.0058 gave Gamma(1/z) = inf times Q = 0 (alpha = 1e-10 1/Pa of an oil
  with S = 7: z = 0.0028), now alpha* underflows to 0;
- ASTM D341 through two points reproduces both (the Newton inverse of Z) on the scalar and
  the array paths.

Presets (:func:`thermobearing.lubricant.load_lubricant`): the initial slope of the
viscosity the oil gives, d ln eta / dp at p = 0 (central differences), is the alpha the
films use (:meth:`pressure_viscosity_coefficient`) wherever the oil is not beyond its
alpha correlation's data (the documented hold of the ASME 1953 fit's z below 2.4 mPa s,
where the viscosity's slope is the held z's and the films keep the fit's alpha); nu rho =
eta; the scalar and the array paths give the same numbers.

Every temperature law (ASTM D341, Vogel, exponential) with a positive slope thins the oil
as it heats at every pressure, and the pressure thickens it; a negative slope (B, b or
beta) is refused naming the field: it was accepted and the oil thickened as it heated.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy import integrate

from thermobearing.lubricant import load_lubricant, preset_names
from thermobearing.lubricant_properties import ALPHA_FIT_LOWEST_VISCOSITY
from thermobearing.viscosity_laws import (
    ROELANDS_P0,
    alpha_from_roelands_index,
    barus_viscosity,
    roelands_asymptotic_isoviscous_alpha,
    roelands_viscosity,
    walther_constants,
    walther_kinematic_viscosity,
)

PRESETS = {name: load_lubricant(name) for name in preset_names()}
ETA0 = st.floats(1e-3, 10.0)


@settings(max_examples=60, deadline=None)
@given(eta0=ETA0, z=st.floats(0.2, 1.5), log_p=st.floats(3.0, 9.6))
def test_roelands_against_barus_of_the_same_initial_slope(eta0, z, log_p):
    p = 10.0**log_p
    alpha = float(alpha_from_roelands_index(z, eta0))
    ln_r = math.log(float(roelands_viscosity(eta0, p, z)) / eta0)
    ln_b = math.log(float(barus_viscosity(eta0, alpha, p)) / eta0)
    x = p / ROELANDS_P0
    s = math.log(eta0) + 9.67
    # second-order term of S ((1 + x)^z - 1) - z S x: S z (z - 1) x^2 / 2
    if x < 1e-3:
        assert ln_r - ln_b == pytest.approx(s * z * (z - 1.0) * x * x / 2.0,
                                            rel=1e-2, abs=1e-13 * max(1.0, ln_b))
    if z <= 1.0:
        assert ln_r <= ln_b * (1.0 + 1e-12)
    else:
        assert ln_r >= ln_b * (1.0 - 1e-12)


def _blok_quadrature(eta0: float, z: float) -> float:
    """1 / int_0^inf eta0 / eta(p) dp, with p = p0 (e^x - 1)."""
    s = math.log(eta0) + 9.67

    def g(x):
        return math.exp(-s * (math.exp(z * x) - 1.0) + x)

    x_max = 1.0
    while g(x_max) > 1e-30:
        x_max *= 1.5
    val, _ = integrate.quad(g, 0.0, x_max, limit=500, epsabs=0.0, epsrel=1e-12)
    return 1.0 / (ROELANDS_P0 * val)


@settings(max_examples=30, deadline=None)
@given(eta0=ETA0, z=st.floats(0.3, 1.5))
def test_asymptotic_isoviscous_alpha_is_blok_integral(eta0, z):
    star = float(roelands_asymptotic_isoviscous_alpha(eta0, z))
    assert star == pytest.approx(_blok_quadrature(eta0, z), rel=1e-9)
    initial = float(alpha_from_roelands_index(z, eta0))
    if z < 1.0:
        assert star < initial
    elif z > 1.0:
        assert star > initial


def test_asymptotic_isoviscous_alpha_of_barus_like_and_tiny_indices():
    """z = 1 is Barus (alpha* = the initial slope); z down to 1e-6 is finite, >= 0 and
    falls with z (NaN below z = 0.0058 before)."""
    assert float(roelands_asymptotic_isoviscous_alpha(0.05, 1.0)) == pytest.approx(
        float(alpha_from_roelands_index(1.0, 0.05)), rel=1e-12)
    zs = [0.05, 0.01, 0.005, 0.003, 0.001, 1e-6]
    vals = [float(roelands_asymptotic_isoviscous_alpha(0.05, z)) for z in zs]
    assert all(math.isfinite(v) and v >= 0.0 for v in vals)
    assert all(b <= a for a, b in zip(vals, vals[1:], strict=False))
    assert vals[1] == pytest.approx(1.9032901144455e-87, rel=1e-9)
    arr = roelands_asymptotic_isoviscous_alpha(np.array([0.05, 1.0]), np.array([0.6, 0.001]))
    assert np.all(np.isfinite(arr))


def test_a_lubricant_with_a_small_alpha_has_a_finite_alpha_star():
    """alpha = 1e-10 1/Pa (accepted: the limits bound alpha from above only) at 40 degC on
    ISO VG 46's viscosity: z = 0.0028, alpha* finite and below the initial slope."""
    from dataclasses import replace

    oil = replace(PRESETS["ISO_VG46"], pressure_parameters={"alpha": 1e-10},
                  alpha_correlation=None)
    star = float(oil.pressure_viscosity_coefficient(313.15, "asymptotic_isoviscous"))
    assert math.isfinite(star)
    assert 0.0 <= star < float(oil.pressure_viscosity_coefficient(313.15))


@settings(max_examples=60, deadline=None)
@given(t1=st.floats(250.0, 400.0), dt=st.floats(5.0, 150.0), log_nu1=st.floats(-6.5, -1.0),
       log_drop=st.floats(0.01, 3.0))
def test_d341_line_through_two_points_reproduces_them(t1, dt, log_nu1, log_drop):
    t2 = t1 + dt
    nu1 = 10.0**log_nu1
    nu2 = nu1 * 10.0**-log_drop
    if nu2 < 2.1e-7:
        return
    a, b = walther_constants(nu1, t1, nu2, t2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")        # below 0.21 cSt in between: warned, not wrong
        assert walther_kinematic_viscosity(t1, a, b) == pytest.approx(nu1, rel=1e-10)
        assert walther_kinematic_viscosity(t2, a, b) == pytest.approx(nu2, rel=1e-10)
        arr = walther_kinematic_viscosity(np.array([t1, t2]), a, b)
    np.testing.assert_allclose(arr, [nu1, nu2], rtol=1e-10)


def _held(oil, t: float) -> bool:
    """The oil's alpha correlation is past its data at t (its z is held there)."""
    lowest = ALPHA_FIT_LOWEST_VISCOSITY.get(str(oil.alpha_correlation))
    return lowest is not None and float(oil.dynamic_viscosity(t)) < lowest


@pytest.mark.parametrize("name", sorted(PRESETS))
@settings(max_examples=25, deadline=None)
@given(t_c=st.floats(-10.0, 180.0))
def test_initial_slope_of_the_viscosity_is_the_films_alpha(name, t_c):
    oil = PRESETS[name]
    t = t_c + 273.15
    try:
        eta0 = float(oil.dynamic_viscosity(t))
    except Exception:   # outside the preset's liquid range: test_property_lubricant's subject
        return
    dp = 1e4
    slope = (math.log(float(oil.dynamic_viscosity(t, dp)))
             - math.log(float(oil.dynamic_viscosity(t, -dp)))) / (2.0 * dp)
    alpha = float(oil.pressure_viscosity_coefficient(t))
    if _held(oil, t):
        # the viscosity follows the held z; the films keep the correlation's alpha
        z = float(oil.roelands_index(t))
        assert slope == pytest.approx(z * (math.log(eta0) + 9.67) / ROELANDS_P0, rel=1e-6)
        assert slope <= alpha * (1.0 + 1e-9)
    else:
        assert slope == pytest.approx(alpha, rel=1e-6)


@pytest.mark.parametrize("name", sorted(PRESETS))
@settings(max_examples=15, deadline=None)
@given(t_c=st.floats(0.0, 150.0), p=st.floats(0.0, 2e9))
def test_scalar_and_array_paths_agree_and_nu_rho_is_eta(name, t_c, p):
    oil = PRESETS[name]
    t = t_c + 273.15
    eta = float(oil.dynamic_viscosity(t))
    nu = float(oil.kinematic_viscosity(t))
    rho = float(oil.density(t))
    assert nu * rho == pytest.approx(eta, rel=1e-12)
    arr = oil.dynamic_viscosity(np.array([t, t]), np.array([0.0, p]))
    assert float(arr[0]) == pytest.approx(eta, rel=1e-13)
    assert float(arr[1]) == pytest.approx(float(oil.dynamic_viscosity(t, p)), rel=1e-13)
    dens = oil.density(np.array([t]), np.array([p]))
    assert float(dens[0]) == pytest.approx(float(oil.density(t, p)), rel=1e-13)
    assert float(oil.kinematic_viscosity(np.array([t]))[0]) == pytest.approx(nu, rel=1e-13)


LAWS = {
    # a grade of 5-1000 cSt at 40 degC thinning 3-5.4 times to 100 degC (A and B together)
    "astm_d341": lambda a, b: dict(zip("AB", walther_constants(
        10.0 ** (0.7 + 2.3 * a) * 1e-6, 313.15, 10.0 ** (0.7 + 2.3 * a) * 1e-6 / (2.0 * b + 2.4),
        373.15), strict=True)),
    "vogel": lambda a, b: {"a": 1e-4 * (1.0 + a), "b": 900.0 * b, "c": 150.0},
    "exponential": lambda a, b: {"eta0": 0.033 * (1.0 + a), "beta": 0.032 * b, "T0": 303.15},
}


@pytest.mark.parametrize("law", sorted(LAWS))
@settings(max_examples=25, deadline=None)
@given(a=st.floats(0.0, 1.0), b=st.floats(0.3, 1.5), t=st.floats(260.0, 420.0),
       dt=st.floats(0.5, 40.0), p=st.floats(0.0, 1e9))
def test_every_law_thins_with_temperature_and_thickens_with_pressure(law, a, b, t, dt, p):
    from thermobearing.errors import InputError
    from thermobearing.lubricant import Lubricant

    try:
        oil = Lubricant(name="x", source="property test", viscosity_law=law,
                        viscosity_parameters=LAWS[law](a, b), density_reference=870.0,
                        pressure_parameters={"alpha": 2e-8})
    except InputError as exc:
        # an oil too thin at 40 degC for this alpha (its Roelands z > 1.5) is refused at
        # construction (test_thin_oil_with_a_mineral_alpha_is_refused)
        assert "pressure_viscosity.alpha" in str(exc)
        assume(False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cold, hot = (float(oil.dynamic_viscosity(x, p)) for x in (t, t + dt))
        assert hot < cold
        assert float(oil.dynamic_viscosity(t, p + 1e7)) > float(oil.dynamic_viscosity(t, p))


@pytest.mark.parametrize(("law", "key"), [("astm_d341", "B"), ("vogel", "b"),
                                          ("exponential", "beta")])
def test_a_viscosity_rising_with_temperature_is_refused(law, key):
    """A negative temperature slope (a sign slip) made the oil thicken as it heats:
    exponential beta = -0.032 1/K gave 0.030 Pa s at 300 K and 0.148 Pa s at 350 K."""
    from thermobearing.errors import InputError
    from thermobearing.lubricant import Lubricant

    params = LAWS[law](0.0, 1.0)
    params[key] = -params[key]
    with pytest.raises(InputError, match=f"viscosity.{key}"):
        Lubricant(name="x", source="property test", viscosity_law=law,
                  viscosity_parameters=params, density_reference=870.0,
                  pressure_parameters={"alpha": 2e-8})


def test_thin_oil_with_a_mineral_alpha_is_refused():
    """A Roelands oil given by alpha takes z = alpha p0 / (ln eta0 + 9.67) at its reference
    temperature; a 0.6 cSt oil with alpha = 2e-8 1/Pa got z = 3.1 (a given z is limited to
    1.5) and its viscosity overflowed at contact pressures: refused, naming alpha and z."""
    from thermobearing.errors import InputError
    from thermobearing.lubricant import Lubricant

    thin = {"a": 1e-4, "b": 270.0, "c": 150.0}
    with pytest.raises(InputError, match=r"pressure_viscosity\.alpha.*gives z = "):
        Lubricant(name="x", source="property test", viscosity_law="vogel",
                  viscosity_parameters=thin, density_reference=870.0,
                  pressure_parameters={"alpha": 2e-8})
    oil = Lubricant(name="x", source="property test", viscosity_law="vogel",
                    viscosity_parameters=thin, density_reference=870.0,
                    pressure_parameters={"alpha": 5e-9})
    assert float(oil.roelands_index(313.15)) <= 1.5
