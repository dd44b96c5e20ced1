"""Property tests: scaling invariants of Hertz contact and closed-form EHL films, and their
behaviour on inputs outside their validity.

Hertz (Johnson 1985 section 4.2; Hamrock, Schmid & Jacobson 2004 ch. 17; module
:mod:`thermobearing.hertz`): point contact a, b, p_max ~ Q^(1/3), approach ~ Q^(2/3), and the
load is the integral of the semi-ellipsoidal pressure, Q = (2/3) pi a b p_max; line contact
b, p_max ~ Q^(1/2), Q = (pi/2) b p_max l. Hamrock & Dowson (1977, Part III) central film
H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k)): the exponents are recovered by
finite differences of ln h. Moes (1992) line film: rises with speed and viscosity, falls
weakly with load.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing import film, hertz
from thermobearing.errors import InputError, ValidityWarning

EP = 2.28e11  # E' of steel on steel [Pa] (Hamrock convention)

loads = st.floats(1.0, 1e5)
radii = st.floats(1e-3, 5e-2)
ratios = st.floats(1.0, 60.0)
methods = st.sampled_from(["exact", "hamrock_brewe", "brewe_hamrock_1977"])


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")  # scaling laws
@settings(max_examples=60, deadline=None)
@given(q=loads, rx=radii, ratio=ratios, method=methods, factor=st.floats(1.5, 100.0))
def test_point_contact_power_laws(q, rx, ratio, method, factor):
    c1 = hertz.point_contact(q, rx, rx * ratio, EP, method=method)
    c2 = hertz.point_contact(q * factor, rx, rx * ratio, EP, method=method)
    third = factor ** (1.0 / 3.0)
    assert c2.a / c1.a == pytest.approx(third, rel=1e-9)
    assert c2.b / c1.b == pytest.approx(third, rel=1e-9)
    assert c2.max_pressure / c1.max_pressure == pytest.approx(third, rel=1e-9)
    assert c2.approach / c1.approach == pytest.approx(third**2, rel=1e-9)
    # load = integral of p_max sqrt(1 - x^2/b^2 - y^2/a^2) over the ellipse
    assert 2.0 / 3.0 * math.pi * c1.a * c1.b * c1.max_pressure == pytest.approx(q, rel=1e-9)
    assert c1.a >= c1.b > 0.0 and c1.ellipticity >= 1.0


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")  # scaling laws
@settings(max_examples=40, deadline=None)
@given(q=loads, rx=radii, ratio=ratios)
def test_point_contact_exact_ellipticity_grows_with_conformity(q, rx, ratio):
    """k = a/b of the exact solution rises with R_y/R_x (the ellipticity equation is
    monotonic, Hamrock & Brewe 1983); the closed forms stay within their stated errors."""
    c = hertz.point_contact(q, rx, rx * ratio, EP)
    c_more = hertz.point_contact(q, rx, rx * ratio * 1.1, EP)
    assert c_more.ellipticity > c.ellipticity or ratio == 1.0
    hb = hertz.point_contact(q, rx, rx * ratio, EP, method="hamrock_brewe")
    # module docstring: Hamrock-Brewe within 2.6 % (a), 1.2 % (b), 1.7 % (p) for ratio <= 100
    assert hb.a == pytest.approx(c.a, rel=0.027)
    assert hb.b == pytest.approx(c.b, rel=0.013)
    assert hb.max_pressure == pytest.approx(c.max_pressure, rel=0.018)


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")  # scaling laws
@settings(max_examples=40, deadline=None)
@given(q=loads, length=st.floats(2e-3, 5e-2), rx=radii, factor=st.floats(1.5, 100.0))
def test_line_contact_power_laws(q, length, rx, factor):
    c1 = hertz.line_contact(q, length, rx, EP)
    c2 = hertz.line_contact(q * factor, length, rx, EP)
    half = math.sqrt(factor)
    assert c2.half_width / c1.half_width == pytest.approx(half, rel=1e-12)
    assert c2.max_pressure / c1.max_pressure == pytest.approx(half, rel=1e-12)
    assert 0.5 * math.pi * c1.half_width * c1.max_pressure * length == pytest.approx(q, rel=1e-12)
    # Palmgren: delta ~ Q^0.9
    assert c2.approach / c1.approach == pytest.approx(factor**0.9, rel=1e-12)


def test_hertz_zero_load_gives_zeros_never_nan():
    c = hertz.point_contact(np.array([0.0, 10.0]), 0.005, 0.05, EP)
    for v in (c.a, c.b, c.max_pressure, c.approach):
        assert np.all(np.isfinite(v)) and v[0] == 0.0
    line = hertz.line_contact(np.array([0.0, 10.0]), 0.01, 0.005, EP)
    assert np.all(np.isfinite(line.max_pressure)) and line.max_pressure[0] == 0.0


@pytest.mark.parametrize("field, kwargs", [
    ("load", dict(load=-1.0)), ("load", dict(load=math.nan)),
    ("rx", dict(rx=0.0)), ("rx", dict(rx=-0.01)), ("ry", dict(ry=math.inf)),
    ("effective_modulus", dict(effective_modulus=0.0)),
])
def test_point_contact_bad_input_names_field(field, kwargs):
    args = dict(load=100.0, rx=0.005, ry=0.05, effective_modulus=EP) | kwargs
    with pytest.raises(InputError, match=field):
        hertz.point_contact(**args)


# ----------------------------------------------------------------------------------- films
def _hd(u=5.0, eta=0.02, alpha=2e-8, q=1000.0, rx=0.01, ry=0.1):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return float(film.hamrock_dowson_1977_central(u, eta, alpha, q, rx, ry,
                                                      effective_modulus=EP))


@settings(max_examples=40, deadline=None)
@given(u=st.floats(0.05, 50.0), eta=st.floats(1e-3, 1.0), alpha=st.floats(5e-9, 3e-8),
       q=st.floats(10.0, 5e4), rx=st.floats(2e-3, 5e-2), ratio=st.floats(1.0, 50.0))
def test_hamrock_dowson_exponents_recovered(u, eta, alpha, q, rx, ratio):
    """d ln h / d ln x by central differences: 0.67 (u and eta0: both through U), 0.53
    (alpha, through G), -0.067 (load) -- the exponents of Hamrock & Dowson (1977)."""
    ry = rx * ratio
    base = dict(u=u, eta=eta, alpha=alpha, q=q, rx=rx, ry=ry)
    step = 1e-3
    for name, expo in (("u", 0.67), ("eta", 0.67), ("alpha", 0.53), ("q", -0.067)):
        up = dict(base, **{name: base[name] * math.exp(step)})
        dn = dict(base, **{name: base[name] * math.exp(-step)})
        slope = (math.log(_hd(**up)) - math.log(_hd(**dn))) / (2 * step)
        assert slope == pytest.approx(expo, abs=1e-9)
    h = _hd(**base)
    assert h > 0.0 and math.isfinite(h)
    # minimum film below the central one where Hamrock & Dowson fitted both (k 1-8)
    k = 1.03 * ratio**0.64
    if k <= 8.0:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            hmin = float(film.hamrock_dowson_1977_minimum(u, eta, alpha, q, rx, ry,
                                                          effective_modulus=EP))
        assert 0.0 < hmin < h * 1.05   # the two fits cross within ~5 % at the fit edges


@settings(max_examples=40, deadline=None)
@given(u=st.floats(0.05, 50.0), eta=st.floats(1e-3, 1.0), alpha=st.floats(5e-9, 3e-8),
       q=st.floats(10.0, 5e4), length=st.floats(5e-3, 3e-2), rx=st.floats(2e-3, 3e-2))
def test_moes_line_film_monotonic(u, eta, alpha, q, length, rx):
    """Moes (1992) central film: grows with speed and viscosity, falls with load, and
    its load sensitivity is weak (|d ln h/d ln w| <= 1: the rigid-isoviscous limit M^-1, i.e.
    h ~ w^-1, bounds it)."""
    def h(**kw):
        args = dict(u=u, eta=eta, alpha=alpha, q=q) | kw
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            return float(film.moes_line_central(args["u"], args["eta"], args["alpha"],
                                                args["q"], length, rx, effective_modulus=EP))
    h0 = h()
    assert 0.0 < h0 < math.inf
    assert h(u=u * 1.1) > h0
    assert h(eta=eta * 1.1) > h0
    assert h(q=q * 1.1) < h0
    slope = (math.log(h(q=q * 1.01)) - math.log(h0)) / math.log(1.01)
    assert -1.0 <= slope < 0.0


def test_film_outside_fitted_range_warns():
    """U far below the Hamrock-Dowson fit (1e-12..1e-10) warns with ValidityWarning."""
    with pytest.warns(ValidityWarning, match="U in"):
        film.hamrock_dowson_1977_central(1e-4, 0.01, 2e-8, 1000.0, 0.01, 0.1,
                                         effective_modulus=EP)


def test_film_limits_are_not_nan():
    """u = 0 gives h = 0 and Q = 0 gives +inf (documented), never NaN."""
    h = film.hamrock_dowson_1977_central(np.array([0.0, 5.0, 5.0]), 0.02, 2e-8,
                                         np.array([100.0, 0.0, 100.0]), 0.01, 0.1,
                                         effective_modulus=EP)
    assert h[0] == 0.0 and h[1] == math.inf and 0.0 < h[2] < math.inf


@pytest.mark.parametrize("func", [film.wilson_sheu_1983, film.gupta_1992])
@pytest.mark.parametrize("field", ["entrainment_speed", "slide_to_roll"])
def test_thermal_reduction_rejects_nan(func, field):
    """Defect found by this test: a NaN entrainment speed or slide-to-roll ratio gave
    phi_T = NaN silently (thermal_loading had no finite check); now InputError names it."""
    kw = dict(entrainment_speed=5.0, dynamic_viscosity=0.02,
              temperature_viscosity_coefficient=0.03, thermal_conductivity=0.13,
              slide_to_roll=0.1)
    kw[field] = math.nan
    with pytest.raises(InputError, match=field):
        func(**kw)


@settings(max_examples=40, deadline=None)
@given(u=st.floats(0.0, 1e3), s=st.floats(0.0, 2.0), p=st.floats(0.0, 3e9))
def test_thermal_reduction_in_unit_interval(u, s, p):
    """phi_T in (0, 1], 1 at u = 0, non-increasing in u (Wilson & Sheu 1983; Gupta et al.
    1992, clipped at 0.05)."""
    kw = dict(dynamic_viscosity=0.02, temperature_viscosity_coefficient=0.03,
              thermal_conductivity=0.13, slide_to_roll=s)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        for phi_of in (lambda v: film.wilson_sheu_1983(entrainment_speed=v, **kw),
                       lambda v: film.gupta_1992(entrainment_speed=v, max_pressure=p, **kw)):
            phi, phi_fast = float(phi_of(u)), float(phi_of(u * 1.5 + 1e-3))
            assert 0.0 < phi <= 1.0 and 0.0 < phi_fast <= 1.0
            assert phi_fast <= phi + 1e-15
            assert float(phi_of(0.0)) == pytest.approx(1.0)


def test_gupta_overflowing_thermal_loading_is_clipped_not_nan():
    """An entrainment speed so large that L overflows gave inf/inf = NaN; the limit of the
    formula is 0, clipped to 0.05 with a ValidityWarning."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)   # the overflow of L itself
        with pytest.warns(ValidityWarning):
            phi = film.gupta_1992(1e200, 0.02, 0.03, 0.13, 0.1, max_pressure=1e9)
    assert float(phi) == 0.05


def test_point_contact_far_beyond_small_contact_warns():
    """Defect found by this test: Hertz returned a contact whose half-width is 15 % of
    the reduced radius (SKF6304 inner contact, 50 kN on one ball, p_0 = 8.7 GPa) without a
    word; the half-space assumption needs a << R. Now a ValidityWarning beyond 0.1 R_x (the
    package's guard), none at bearing loads (1 kN: p_0 = 2.4 GPa)."""
    from thermobearing.geometry import load_bearing

    b = load_bearing("SKF6304")
    rx, ry = b.curvature("inner", 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        hertz.point_contact(1000.0, rx, ry, b.effective_modulus)
    with pytest.warns(ValidityWarning, match="not small"):
        hertz.point_contact(5e4, rx, ry, b.effective_modulus)
    with pytest.warns(ValidityWarning, match="not small"):
        hertz.line_contact(1e7, 0.01, 0.005, EP)
