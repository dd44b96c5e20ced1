"""Property tests of the EHL rolling resistance of ball contacts and its reduction factors
(:mod:`thermobearing.rolling_resistance`, session 19).

F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47: the exponents in speed, viscosity, load
and pressure-viscosity coefficient are recovered exactly from two evaluations; the force
does not depend on the sign of the entrainment speed; the reductions (SKF inlet shear and
replenishment, Gupta's thermal factor) lie in (0, 1] and fall with speed; the thermal
reduction of the compiled kernel is film.gupta_1992's phi_T^(0.66/0.67).
"""

from __future__ import annotations

import math
import warnings

from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing import film
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.rolling_resistance import (
    THERMAL_EXPONENT,
    harris_rolling_force,
    kernel_parameters,
    rolling_force_array,
    skf_inlet_shear_factor,
    skf_replenishment_factor,
    supply_factor,
)

E_PRIME = 2.28e11
point = dict(u=st.floats(0.05, 50.0), q=st.floats(1.0, 2e4), rx=st.floats(2e-3, 2e-2),
             ratio=st.floats(1.5, 60.0), eta=st.floats(1e-3, 0.5), alpha=st.floats(5e-9, 3e-8))


@settings(max_examples=60, deadline=None)
@given(**point, factor=st.floats(1.5, 20.0))
def test_harris_exponents_and_sign(u, q, rx, ratio, eta, alpha, factor):
    def f(u_=u, q_=q, eta_=eta, alpha_=alpha):
        return float(harris_rolling_force(u_, q_, rx, rx * ratio, eta_, alpha_, E_PRIME))

    base = f()
    assert base > 0.0
    assert float(harris_rolling_force(-u, q, rx, rx * ratio, eta, alpha, E_PRIME)) == base
    lf = math.log(factor)
    for got, n in ((f(u_=u * factor), 0.66), (f(q_=q * factor), 0.47),
                   (f(eta_=eta * factor), 0.66), (f(alpha_=alpha * factor), 0.022)):
        assert math.isclose(math.log(got / base) / lf, n, rel_tol=1e-9)


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(["QJ1044", "SKF6304"]), rpm=st.floats(0.0, 2e4),
       more=st.floats(1.01, 3.0), nu=st.floats(1e-6, 1e-3),
       method=st.sampled_from(["jet", "oil_bath", "grease", "oil_air"]),
       reduction=st.sampled_from(["none", "thermal", "skf", "thermal_starvation"]))
def test_bearing_reductions_in_unit_interval_and_falling(name, rpm, more, nu, method,
                                                         reduction):
    b = load_bearing(name)
    w = rpm * math.pi / 30
    ish = skf_inlet_shear_factor(w, b.pitch_diameter, nu)
    rs = skf_replenishment_factor(w, nu, b.bore, b.outer_diameter, 3.0, method)
    sf = supply_factor(reduction, b, w, nu, method)
    for v in (ish, rs, sf):
        assert 0.0 < v <= 1.0
    assert skf_inlet_shear_factor(w * more, b.pitch_diameter, nu) <= ish
    assert skf_replenishment_factor(w * more, nu, b.bore, b.outer_diameter, 3.0, method) <= rs
    assert supply_factor(reduction, b, w * more, nu, method) <= sf
    if rpm == 0.0:
        assert ish == rs == sf == 1.0


@settings(max_examples=60, deadline=None)
@given(**point, s=st.floats(0.0, 1.0), p0=st.floats(0.0, 2.5e9), beta=st.floats(0.0, 0.06),
       k_f=st.floats(0.08, 0.2))
def test_kernel_thermal_reduction_is_gupta(u, q, rx, ratio, eta, alpha, s, p0, beta, k_f):
    plain = kernel_parameters("harris", viscosity=eta, pressure_viscosity=alpha,
                              effective_modulus=E_PRIME)
    hot = kernel_parameters("harris", viscosity=eta, pressure_viscosity=alpha,
                            effective_modulus=E_PRIME, reduction="thermal",
                            temperature_viscosity_coefficient=beta, thermal_conductivity=k_f)
    f0 = float(rolling_force_array(u, s * u, q, p0, rx, rx * ratio, plain))
    f1 = float(rolling_force_array(u, s * u, q, p0, rx, rx * ratio, hot))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        phi = float(film.gupta_1992(u, eta, beta, k_f, slide_to_roll=s, max_pressure=p0,
                                    effective_modulus=E_PRIME))
    assert 0.0 < f1 <= f0 * (1 + 1e-12)
    assert math.isclose(f1, f0 * phi ** THERMAL_EXPONENT, rel_tol=1e-12)
