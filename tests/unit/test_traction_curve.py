"""Tests of thermobearing.traction_curve (slide-to-roll traction-coefficient curves).

Reference numbers: the oil 4109 regression as transcribed in oil_coe_model.m
(github.com/Shane1911/Harris_model, commit e79b410; see the module docstring for its status),
evaluated by hand at the transcription's own example contact: Q = 29 N, R = 10 mm,
E' = 2.26e11 Pa, u = 30 m/s, eta0 = 0.033 Pa s, beta = 0.0215 1/K, k = 0.0966 W/(m K).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError, ValidityWarning
from thermobearing.traction_curve import (
    TRACTION_CURVES,
    FixedFourCoefficientCurve,
    Oil4109Wang,
    four_coefficient_traction,
    get_traction_curve,
    traction_coefficient,
)

EXAMPLE = dict(load=29.0, entrainment_speed=30.0, reduced_radius=0.01, effective_modulus=2.26e11)


def _at(theta_c: float) -> dict[str, float]:
    return dict(EXAMPLE, temperature=273.15 + theta_c)


def test_groups_by_hand() -> None:
    # W = 29 / (2.26e11 * 1e-4) = 1.2832e-6; U = 0.033 * 30 / 2.26e9 = 4.3805e-10;
    # T = 25 * sqrt(0.0966 * 0.033 * 0.0215) / 2.26e9 = 25 * 8.2787e-3 / 2.26e9 = 9.158e-11
    w, u, t = Oil4109Wang().groups(**_at(25.0))
    assert w == pytest.approx(1.2832e-6, rel=1e-4)
    assert u == pytest.approx(4.3805e-10, rel=1e-4)
    assert t == pytest.approx(9.158e-11, rel=1e-3)


def test_coefficients_by_hand_25C() -> None:
    # hand evaluation of eqs. 3-5 with the groups above:
    # W_c = 7.956e12 T^2 + 5553.09 T + 1.758455e-6 = 6.67e-8 + 5.086e-7 + 1.7585e-6 = 2.334e-6
    # k = |W_c/W - 1| = 0.819; A = -4.7935e-8 * W^(0.0068361 k) U^-0.40475 T^-0.18338
    #   = -4.7935e-8 * 0.9271 * 6191 * 69.15 = -0.01903 (slide-rule accuracy, +-1 %)
    # B = 8.37449e-15 * W^(0.0141 k) U^-0.58683 T^-0.81736 = 0.356, C = 41.4
    co = Oil4109Wang().coefficients(**_at(25.0))
    assert float(co.a) == pytest.approx(-0.01903, rel=0.01)
    assert float(co.b) == pytest.approx(0.356, rel=0.01)
    assert float(co.c) == pytest.approx(41.4, rel=0.01)
    assert float(co.d) == -float(co.a)  # eq. 5: the curve starts at zero traction


def test_coefficients_match_a_line_by_line_evaluation() -> None:
    # eqs. 2-5 written out once more with math.pow, at 75 degC and a roller-like contact
    q, ue, r, e, th = 4000.0, 25.0, 5.7e-3, 2.396e11, 75.0
    w = q / (e * r * r)
    u = 0.033 * ue / (e * r)
    t = th * math.sqrt(0.0966 * 0.033 * 0.0215) / (e * r)
    wc = 7.956015e12 * t * t + 5553.09 * t + 1.758455e-6
    k = abs(wc / w - 1.0)
    a = -4.793526e-8 * w ** (0.0068361 * k) * u ** -0.4047492 * t ** -0.1833848
    b = 8.37449e-15 * w ** (0.01409715 * k) * u ** -0.5868325 * t ** -0.8173636
    c = 1.180823e-4 * w ** (0.006321 * k) * u ** -0.20617 * t ** -0.3631740
    co = Oil4109Wang().coefficients(q, ue, r, e, 273.15 + th)
    assert [float(x) for x in co] == pytest.approx([a, b, c, -a], rel=1e-12)


def test_curve_shape_and_temperature_trend() -> None:
    # the transcription plots mu(s) for 25/75/125 degC: lower traction when hotter
    s = np.array([0.01, 0.02, 0.05, 0.1, 0.2])
    mus = [Oil4109Wang().traction(s, **_at(th))[0] for th in (25.0, 75.0, 125.0)]
    assert np.all(mus[0] > mus[1]) and np.all(mus[1] > mus[2])
    # at 25 degC: mu(0.05) = (-0.0189 + 0.356*0.05) e^{-41.4*0.05} + 0.0189 = 0.0188 (hand)
    assert mus[0][2] == pytest.approx(0.0188, abs=2e-4)
    assert np.all(mus[0] < 0.0195)  # levels off near D = 0.019


def test_four_coefficient_form() -> None:
    a, b, c, d = -0.02, 0.4, 40.0, 0.02
    s = np.linspace(-0.3, 0.3, 61)
    mu, dmu = four_coefficient_traction(s, a, b, c, d)
    assert mu[30] == 0.0  # s = 0
    np.testing.assert_allclose(mu, -mu[::-1], atol=1e-15)  # odd
    # slope against central differences
    h = 1e-7
    sp = np.array([-0.2, -0.01, 0.003, 0.05, 0.25])
    fd = (four_coefficient_traction(sp + h, a, b, c, d)[0]
          - four_coefficient_traction(sp - h, a, b, c, d)[0]) / (2 * h)
    np.testing.assert_allclose(four_coefficient_traction(sp, a, b, c, d)[1], fd, rtol=1e-6)
    # initial slope B - C A and the maximum of (A + B s) e^{-Cs} at s* = 1/C - A/B
    assert dmu[30] == pytest.approx(b - c * a)
    s_star = 1.0 / c - a / b
    assert four_coefficient_traction(s_star, a, b, c, d)[1] == pytest.approx(0.0, abs=1e-12)
    # large slip: mu -> D
    assert four_coefficient_traction(5.0, a, b, c, d)[0] == pytest.approx(d, abs=1e-12)


def test_errors_and_warnings() -> None:
    curve = Oil4109Wang()
    with pytest.raises(InputError, match="temperature"):
        curve.coefficients(29.0, 30.0, 0.01, 2.26e11, 273.15)  # 0 degC: T = 0
    with pytest.raises(InputError, match="load"):
        curve.coefficients(0.0, 30.0, 0.01, 2.26e11, 300.0)
    with pytest.raises(InputError, match="entrainment_speed"):
        curve.coefficients(29.0, -1.0, 0.01, 2.26e11, 300.0)
    with pytest.raises(InputError, match="reduced_radius"):
        curve.coefficients(29.0, 30.0, float("nan"), 2.26e11, 300.0)
    with pytest.warns(ValidityWarning, match="degC"):
        curve.coefficients(29.0, 30.0, 0.01, 2.26e11, 273.15 + 10.0)
    with pytest.warns(ValidityWarning, match="beyond 0.2"):
        traction_coefficient("oil4109_wang", 0.3, 29.0, 30.0, 0.01, 2.26e11, 300.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        traction_coefficient("oil4109_wang", 0.1, 29.0, 30.0, 0.01, 2.26e11, 300.0)
    with pytest.raises(InputError):
        Oil4109Wang(beta=0.0)


def test_fixed_curve_and_lookup() -> None:
    with pytest.raises(InputError, match="source"):
        FixedFourCoefficientCurve(-0.02, 0.4, 40.0, 0.02, source=" ")
    with pytest.raises(InputError):
        FixedFourCoefficientCurve(-0.02, 0.4, -1.0, 0.02, source="x")
    fixed = FixedFourCoefficientCurve(-0.02, 0.4, 40.0, 0.02, source="test values", s_max=0.1)
    assert get_traction_curve(fixed) is fixed
    mu = traction_coefficient(fixed, 0.05, 1.0, 1.0, 1.0, 1.0, 300.0)
    assert mu == pytest.approx(four_coefficient_traction(0.05, -0.02, 0.4, 40.0, 0.02)[0])
    with pytest.warns(ValidityWarning):
        traction_coefficient(fixed, 0.2, 1.0, 1.0, 1.0, 1.0, 300.0)
    assert isinstance(get_traction_curve("curve:oil4109_wang"), Oil4109Wang)
    assert "oil4109_wang" in TRACTION_CURVES
    with pytest.raises(UnknownNameError):
        get_traction_curve("curve:no_such_oil")
    with pytest.raises(InputError):
        get_traction_curve(3.0)
