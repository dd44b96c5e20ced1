"""Property tests of the traction laws' limits (:mod:`thermobearing.traction`, session 21),
beside the derivatives, bounds and fits of test_prop19_traction.py.

Film law (``eyring_limiting_shear``; Johnson & Tevaarwerk 1977, Bair & Winer 1979), with
the Newtonian stress tau_N = eta dv / h:

- small slide: Newtonian, tau -> tau_N and d tau / d dv -> eta / h at dv = 0 (both caps,
  Eyring or Newtonian film): tau0 asinh(x / tau0) = x (1 - x^2 / (6 tau0^2) + ...);
- large slide: the limiting shear stress, tau -> Lambda p, for both caps and both films,
  whatever the size of tau_N. The smooth cap tau_N / sqrt(1 + (tau_N / tau_L)^2) of a
  Newtonian film returned 0 above tau_N = 1.3e154 Pa (tau_N^2 overflowed), where a Barus
  oil at a few GPa or a Newtonian film at any large slide takes it; fixed in
  ``_law_stress`` (the smaller stress over the larger);
- the stress is non-decreasing in the slide and never above Lambda p.

Slip-curve laws (tau = mu p): the four-parameter curve tends to mu_infinity p at large
slip and starts at mu_zero p; the linear-saturating law is mu_m p at and beyond dv_m.

Contact integral (:func:`thermobearing.contact_traction.integrate`): a uniform slide
beyond saturation gives F = -mu_m Q and heat mu_m Q V exactly (the quadrature carries the
Hertz load exactly), for point and line contacts; a large uniform slide of a film contact
gives -Lambda Q.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.contact_traction import integrate
from thermobearing.lubricant import load_lubricant
from thermobearing.traction import (
    EYRING,
    EyringLimitingShearTraction,
    FourParameterTraction,
    LinearSaturatingTraction,
    _call_kernel,
)


def _eyring(lam, tau0, smooth):
    """The film law's compiled kernel at a given eta / h (a film law without a lubricant)."""
    params = np.array([lam, 0.0 if tau0 is None else tau0, 1.0 if smooth else 0.0,
                       0.0 if tau0 is None else 1.0 / tau0])

    def stress(s, p, rate):
        out = _call_kernel(EYRING, params, np.atleast_1d(float(s)), np.atleast_1d(float(p)),
                           np.atleast_1d(float(rate)), np.ones(1))
        return float(out.stress[0]), float(out.dstress_dspeed[0])

    return stress


LAMBDA = st.floats(0.02, 0.15)
TAU0 = st.one_of(st.none(), st.floats(1e5, 5e7))
PRESSURE = st.floats(1e7, 4e9)


@settings(max_examples=60, deadline=None)
@given(lam=LAMBDA, tau0=TAU0, smooth=st.booleans(), p=PRESSURE, log_rate=st.floats(3.0, 20.0))
def test_film_law_is_newtonian_at_small_slide(lam, tau0, smooth, p, log_rate):
    rate = 10.0**log_rate                      # eta / h [Pa s / m]
    law = _eyring(lam, tau0, smooth)
    tau_l = lam * p
    scale = tau_l if tau0 is None else min(tau_l, tau0)
    s = 1e-4 * scale / rate                    # tau_N = 1e-4 of the smaller stress scale
    tau, dtau = law(s, p, rate)
    assert tau == pytest.approx(rate * s, rel=1e-6)
    _, d0 = law(0.0, p, rate)
    assert d0 == pytest.approx(rate, rel=1e-12)
    assert dtau == pytest.approx(rate, rel=1e-6)


@settings(max_examples=60, deadline=None)
@given(lam=LAMBDA, tau0=TAU0, smooth=st.booleans(), p=PRESSURE, log_rate=st.floats(3.0, 20.0),
       log_excess=st.floats(4.0, 300.0))
def test_film_law_reaches_the_limiting_shear_at_large_slide(lam, tau0, smooth, p, log_rate,
                                                             log_excess):
    """tau_N from 1e4 to 1e300 times tau_L: a Newtonian film within 1e-6 of tau_L (the
    smooth cap's (tau_L / tau_N)^2 / 2); an Eyring film's tau_E grows only as
    tau0 ln(2 tau_N / tau0) and may stay below tau_L, so it is held to its cap of tau_E
    (min or smooth) to 1e-12, finite and never above tau_L."""
    rate = 10.0**log_rate
    tau_l = lam * p
    law = _eyring(lam, tau0, smooth)
    s = 10.0**log_excess * tau_l / rate
    if not math.isfinite(s) or not math.isfinite(rate * s):
        return
    tau, dtau = law(s, p, rate)
    assert math.isfinite(tau) and math.isfinite(dtau)
    assert tau <= tau_l * (1.0 + 1e-15)
    if tau0 is None:
        assert tau == pytest.approx(tau_l, rel=1e-6)
    else:
        tau_e = tau0 * math.asinh(rate * s / tau0)
        expected = min(tau_e, tau_l) if not smooth else tau_e / math.sqrt(
            1.0 + (tau_e / tau_l) ** 2)
        assert tau == pytest.approx(expected, rel=1e-12)
    assert dtau >= 0.0


def test_newtonian_smooth_cap_beyond_the_square_root_of_the_largest_float():
    """The regression: tau_N = 1e160 Pa (above sqrt(max float) = 1.3e154) gave 0; it is
    tau_L = Lambda p, and the stress stays at tau_L up to tau_N = 1e300 Pa."""
    law = _eyring(0.075, None, True)
    for rate in (1e150, 1e160, 1e200, 1e300):
        tau, dtau = law(1.0, 1e9, rate)
        assert tau == pytest.approx(0.075e9, rel=1e-15), rate
        assert 0.0 <= dtau < 1e-100


@settings(max_examples=40, deadline=None)
@given(lam=LAMBDA, tau0=TAU0, smooth=st.booleans(), p=PRESSURE, log_rate=st.floats(3.0, 20.0),
       s=st.lists(st.floats(0.0, 1e3), min_size=2, max_size=12))
def test_film_law_is_monotone_and_bounded(lam, tau0, smooth, p, log_rate, s):
    law = _eyring(lam, tau0, smooth)
    taus = [law(v, p, 10.0**log_rate)[0] for v in sorted(s)]
    assert all(b >= a * (1.0 - 1e-14) for a, b in zip(taus, taus[1:], strict=False))
    assert max(taus) <= lam * p * (1.0 + 1e-15)


@settings(max_examples=40, deadline=None)
@given(mu0=st.floats(0.0, 0.05), extra=st.floats(0.005, 0.1), um=st.floats(1e-3, 10.0),
       minf=st.floats(0.0, 0.05), p=PRESSURE)
def test_four_parameter_limits(mu0, extra, um, minf, p):
    law = FourParameterTraction(mu0, max(mu0, minf) + extra, um, minf)
    assert float(law.shear_stress(0.0, p).stress) == pytest.approx(mu0 * p, rel=1e-12,
                                                                    abs=1e-12 * p)
    far = float(law.shear_stress(1e4 * um, p).stress)
    assert far == pytest.approx(minf * p, rel=1e-9, abs=1e-12 * p)


@settings(max_examples=30, deadline=None)
@given(mu=st.floats(0.005, 0.2), dv=st.floats(1e-4, 1.0), q=st.floats(1.0, 1e5),
       a=st.floats(1e-4, 5e-3), ratio=st.floats(0.05, 1.0), beyond=st.floats(1.0, 100.0),
       kind=st.sampled_from(["point", "line"]), n=st.sampled_from([(16, 8), (8, 4), (32, 16)]))
def test_uniform_saturated_slide_gives_mu_q(mu, dv, q, a, ratio, beyond, kind, n):
    law = LinearSaturatingTraction(mu, dv)
    v = beyond * dv
    ct = integrate(law, normal_load=q, semi_major=a, semi_minor=ratio * a, sliding_speed=v,
                   kind=kind, n_major=n[0], n_minor=n[1])
    assert float(ct.rolling_force) == pytest.approx(-mu * q, rel=1e-12)
    assert float(ct.transverse_force) == pytest.approx(0.0, abs=1e-12 * mu * q)
    assert float(ct.heat) == pytest.approx(mu * q * v, rel=1e-12)


@settings(max_examples=15, deadline=None)
@given(lam=st.floats(0.03, 0.12), q=st.floats(100.0, 1e4), t_c=st.floats(40.0, 100.0),
       h=st.floats(5e-8, 1e-6), cap=st.sampled_from(["min", "smooth"]))
def test_film_contact_at_large_slide_carries_lambda_q(lam, q, t_c, h, cap):
    """A ball contact of 0.5 x 0.1 mm (mean pressure Q / (pi a b)) slid at 50 m/s: the
    Newtonian stress of an ISO VG 46 oil at the Hertz pressures is 1e4-1e9 times tau_L, so
    every node is at the limit (within the smooth cap's (tau_L / tau_N)^2 / 2)."""
    oil = load_lubricant("ISO_VG46")
    law = EyringLimitingShearTraction(oil, lam, None, cap)
    ct = integrate(law, normal_load=q, semi_major=5e-4, semi_minor=1e-4, sliding_speed=50.0,
                   film_thickness=h, temperature=t_c + 273.15)
    assert float(ct.rolling_force) == pytest.approx(-lam * q, rel=1e-6)
