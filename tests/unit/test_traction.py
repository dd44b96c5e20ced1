"""Traction laws (thermobearing.traction): hand-checked values, derivatives, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.traction import (
    TRACTION,
    EyringLimitingShearTraction,
    fit_four_parameter,
    make_traction_law,
)


class BarusOil:
    """Test double of a Lubricant: eta = eta0 exp(alpha p), temperature-independent.

    Lets the Eyring law be checked by hand without depending on lubricant presets.
    """

    def __init__(self, eta0: float = 0.05, alpha: float = 2.0e-8) -> None:
        self.eta0, self.alpha = eta0, alpha

    def dynamic_viscosity(self, T, p=0.0):
        return self.eta0 * np.exp(self.alpha * np.asarray(p, dtype=float)) + 0.0 * np.asarray(T)


def test_registry_names():
    assert {"linear_saturating", "eyring_limiting_shear", "four_parameter"} <= set(TRACTION)
    with pytest.raises(UnknownNameError):
        make_traction_law("coulomb_magic")


def test_linear_saturating_hand_values():
    # paper 004 Fig. 3: mu = mu_m dv/dv_m below dv_m, mu_m above
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.2)
    s = np.array([0.0, 0.1, 0.2, 1.0])
    tau, dtau = law.shear_stress(s, 1.0e9)
    np.testing.assert_allclose(tau, [0.0, 0.025e9, 0.05e9, 0.05e9])
    np.testing.assert_allclose(dtau, [0.25e9, 0.25e9, 0.0, 0.0])
    np.testing.assert_allclose(law.coefficient([0.05]), [0.0125])


@pytest.mark.parametrize("mu", [-0.01, 1.2, float("nan")])
def test_friction_coefficient_outside_unit_interval_is_rejected(mu):
    with pytest.raises(InputError, match="mu_max"):
        make_traction_law("linear_saturating", mu_max=mu, slip_speed_max=0.1)
    with pytest.raises(InputError):
        make_traction_law("four_parameter", mu_zero=0.0, mu_max=mu, slip_speed_at_max=1.0,
                          mu_infinity=0.0)


def test_bad_parameter_names():
    with pytest.raises(InputError, match="parameters"):
        make_traction_law("linear_saturating", mu=0.1)


@pytest.mark.parametrize(
    ("mu0", "mumax", "um", "muinf"),
    [(0.010, 0.10, 0.5, 0.005),   # primer example (NASA input file)
     (0.0, 0.05, 1.0, 0.036),     # ADORE-like sample of primer 3.6 (A < 0 branch)
     (0.02, 0.06, 0.3, 0.02)],    # A = 0 branch
)
def test_four_parameter_fit(mu0, mumax, um, muinf):
    a, b, c, d = fit_four_parameter(mu0, mumax, um, muinf)
    law = make_traction_law("four_parameter", mu_zero=mu0, mu_max=mumax,
                            slip_speed_at_max=um, mu_infinity=muinf)
    mu = law.coefficient(np.array([0.0, um, 1e4]))
    np.testing.assert_allclose(mu, [mu0, mumax, muinf], rtol=1e-9, atol=1e-12)
    # zero slope at the peak: primer's relation C = B / (A + B u_m)
    assert c == pytest.approx(b / (a + b * um), rel=1e-9)
    _, dtau = law.shear_stress(np.array([um]), 1.0)
    assert abs(dtau[0]) < 1e-9
    # peak is a maximum
    assert law.coefficient(um * 0.9) < mumax and law.coefficient(um * 1.1) < mumax


def test_four_parameter_needs_a_peak():
    with pytest.raises(InputError, match="mu_max"):
        fit_four_parameter(0.05, 0.04, 1.0, 0.01)


def test_derivatives_match_finite_differences():
    laws = [
        make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.3),
        make_traction_law("four_parameter", mu_zero=0.01, mu_max=0.06, slip_speed_at_max=0.4,
                          mu_infinity=0.03),
        EyringLimitingShearTraction(BarusOil(), 0.075, 5e6, cap="smooth"),
        EyringLimitingShearTraction(BarusOil(), 0.075, 5e6, cap="min"),
        EyringLimitingShearTraction(BarusOil(), 0.075, None, cap="min"),
    ]
    s = np.array([0.013, 0.21, 0.77, 3.1])
    p, h, T = 8.0e8, 2.0e-7, 350.0
    for law in laws:
        tau, dtau = law.shear_stress(s, p, h, T)
        eps = 1e-7
        fd = (law.shear_stress(s + eps, p, h, T)[0] - law.shear_stress(s - eps, p, h, T)[0]) / (
            2 * eps)
        np.testing.assert_allclose(dtau, fd, rtol=1e-5, atol=1e-6 * np.max(tau))


def test_eyring_hand_values():
    # eta(p) = 0.05 exp(2e-8 * 5e8) = 0.05 e^10 = 1101.3 Pa s; h = 1 um
    law = EyringLimitingShearTraction(BarusOil(), limiting_shear_coefficient=0.075,
                                      eyring_stress=5.0e6)
    eta = 0.05 * math.exp(10.0)
    # tiny slip: Newtonian, tau = eta s / h
    tau = law.shear_stress(1e-6, 5e8, 1e-6, 300.0).stress
    assert float(tau) == pytest.approx(eta, rel=1e-6)
    # 1 m/s: tau0 asinh(eta/1e-6/tau0) = 5e6 asinh(220.3) = 3.04e7 Pa < tau_L = 3.75e7 Pa
    tau = law.shear_stress(1.0, 5e8, 1e-6, 300.0).stress
    assert float(tau) == pytest.approx(5e6 * math.asinh(eta / 1e-6 / 5e6), rel=1e-12)
    # 100 m/s: 5e6 asinh(22026) = 5.35e7 > tau_L: capped at Lambda p
    tau = law.shear_stress(100.0, 5e8, 1e-6, 300.0).stress
    assert float(tau) == pytest.approx(0.075 * 5e8)


def test_eyring_needs_film_and_temperature():
    law = EyringLimitingShearTraction(BarusOil())
    assert law.requires_film
    with pytest.raises(InputError, match="film_thickness"):
        law.shear_stress(1.0, 1e9, None, 300.0)
    with pytest.raises(InputError, match="temperature"):
        law.shear_stress(1.0, 1e9, 1e-6, None)
    with pytest.raises(InputError):
        law.shear_stress(1.0, 1e9, -1e-6, 300.0)
    with pytest.raises(InputError):
        EyringLimitingShearTraction(BarusOil(), limiting_shear_coefficient=1.5)
    with pytest.raises(InputError):
        EyringLimitingShearTraction(object())


def test_smooth_cap_is_below_both_limits():
    law = EyringLimitingShearTraction(BarusOil(), 0.075, 5e6, cap="smooth")
    s = np.logspace(-6, 2, 30)
    tau = law.shear_stress(s, 1e9, 5e-7, 330.0).stress
    assert np.all(tau <= 0.075 * 1e9) and np.all(np.diff(tau) > 0)


def test_negative_slide_speed_rejected():
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.2)
    with pytest.raises(InputError):
        law.shear_stress(-1.0, 1e9)


def test_real_lubricant_if_available():
    lub = pytest.importorskip("thermobearing.lubricant")
    oil = lub.load_lubricant("ISO_VG68")
    law = make_traction_law("eyring_limiting_shear", lubricant=oil)
    tau = law.shear_stress(np.array([1e-4, 1.0, 10.0]), 1.5e9, 3e-7, 330.0).stress
    assert np.all(np.isfinite(tau)) and np.all(np.diff(tau) > 0)
    assert tau[-1] <= 0.075 * 1.5e9 * (1 + 1e-12)


def test_misspelt_traction_parameter_lists_the_documented_ones():
    from thermobearing.errors import InputError
    from thermobearing.traction import make_traction_law

    with pytest.raises(InputError) as info:
        make_traction_law("linear_saturating", mu_mx=0.05)
    assert info.value.field == "traction[linear_saturating] parameters"
    assert "mu_max" in info.value.allowed and "slip_speed_max" in info.value.allowed


def test_vectorisable_log_and_asinh_match_the_c_library():
    # the Eyring fast path of the contact integration uses branch-free log / asinh
    # so that its node loop vectorises. The log (fdlibm's algorithm) must agree with the C
    # library's log (Python's math module) to 1 ulp; the asinh ln(x + sqrt(1 + x^2)) to 2 ulp
    # where asinh >= 0.5 and to 2.8e-16 absolute below (its documented accuracy: absolute,
    # not relative, at small arguments) over the range the traction law meets (asinh
    # arguments eta s / (h tau0): 0 .. ~1e12) and beyond
    import numba

    from thermobearing.traction import _asinh_abs, _log_pos

    @numba.njit(error_model="numpy")
    def both(x, out_log, out_asinh):
        for i in range(x.size):
            out_log[i] = _log_pos(x[i]) if x[i] > 0.0 else 0.0
            out_asinh[i] = _asinh_abs(x[i])

    rng = np.random.default_rng(5)
    x = np.concatenate([np.exp(rng.uniform(-40.0, 40.0, 200_000)),
                        [0.0, 5e-324 * 2**60, 1e-300, 1e-20, 1e-9, 0.1, 0.5, 1.0, 1.0 + 2e-16,
                         1.0 - 1e-16, 2.0, math.sqrt(2.0), 2.0**28 - 1.0, 2.0**28,
                         2.0**28 + 2.0, 1e12, 1e200, 1.7e308]])
    lg, ash = np.empty_like(x), np.empty_like(x)
    both(x, lg, ash)
    pos = x > 0.0
    ref_log = np.log(x[pos])
    ulp = np.abs(lg[pos] - ref_log) / np.spacing(np.maximum(np.abs(ref_log), 1e-300))
    assert ulp.max() <= 1.0
    ref_asinh = np.array([math.asinh(v) for v in x])
    err = np.abs(ash - ref_asinh)
    big = ref_asinh >= 0.5
    assert np.max(err[big] / np.spacing(ref_asinh[big])) <= 2.0
    assert np.max(err[~big]) <= 2.8e-16
    assert ash[x == 0.0][0] == 0.0
    # non-finite input gives nan, never a finite number
    bad = np.array([math.nan, math.inf])
    lg2, ash2 = np.empty(2), np.empty(2)
    both(bad, lg2, ash2)
    assert np.all(np.isnan(ash2))


def test_vectorisable_exp_matches_the_c_library():
    # the branch-free exp (fdlibm e_exp.c) of the ball residual's vectorised Hertz / film
    # loops: within 1 ulp of the C library's exp over its documented range -708..709
    import numba

    from thermobearing.traction import _exp_fin

    @numba.njit(error_model="numpy")
    def run(x, out):
        for i in range(x.size):
            out[i] = _exp_fin(x[i])

    rng = np.random.default_rng(6)
    x = np.concatenate([rng.uniform(-708.0, 709.0, 200_000), rng.uniform(-2.0, 2.0, 100_000),
                        [0.0, -0.0, 1e-300, -1e-20, 0.5 * math.log(2.0), -0.5 * math.log(2.0),
                         709.0, -708.0]])
    out = np.empty_like(x)
    run(x, out)
    ref = np.exp(x)
    assert np.max(np.abs(out - ref) / np.spacing(ref)) <= 1.0
    assert out[x == 0.0][0] == 1.0
