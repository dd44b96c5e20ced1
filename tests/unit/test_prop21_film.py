"""Property tests of the closed-form EHL films' scaling laws (:mod:`thermobearing.film`,
session 21), beside the Hamrock-Dowson central exponents of test_property_contact.py.

- power-law films: the exponents in speed, viscosity, load and alpha are recovered exactly
  from two evaluations: Hamrock-Dowson (1977) minimum U^0.68 G^0.49 W^-0.073, Dowson-
  Higginson U^0.70 G^0.54 W'^-0.13, Pan-Hamrock (1989) minimum U^0.694 G^0.568 W'^-0.128 and
  central U^0.692 G^0.470 W'^-0.166;
- every film depends on speed and viscosity only through U = eta u / (E' R_x): scaling the
  speed by c or the viscosity by c gives the same film;
- Moes (1992) line film: its local exponents lie between those of its four asymptotes,
  d ln h / d ln u in [0.6 (elastic-isoviscous), 1 (rigid-isoviscous)], d ln h / d ln w in
  [-1, 0], d ln h / d ln alpha in [0, 0.75] (elastic-piezoviscous) (measured over 2e4 draws
  of U 1e-14..1e-7, W' 1e-7..1e-2, G 1..3e4: [0.600, 1.000], [-1.000, -0.013],
  [0, 0.732]); far in the elastic-piezoviscous corner it is H_EP = 1.311 M^-1/8 L^3/4 and in
  the rigid-isoviscous one H_RI = 3 / M.
"""

from __future__ import annotations

import math
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.film import (
    dowson_higginson_minimum,
    hamrock_dowson_1977_central,
    hamrock_dowson_1977_minimum,
    moes_line_central,
    pan_hamrock_central,
    pan_hamrock_minimum,
)

EP = 2.28e11
LINE_FILMS = {  # name: (function, speed/viscosity exponent, alpha exponent, load exponent)
    "dowson_higginson_minimum": (dowson_higginson_minimum, 0.70, 0.54, -0.13),
    "pan_hamrock_minimum": (pan_hamrock_minimum, 0.694, 0.568, -0.128),
    "pan_hamrock_central": (pan_hamrock_central, 0.692, 0.470, -0.166),
}


def _quiet(fn, *args, **kwargs) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # outside a fit's range: warned, not wrong
        return float(fn(*args, **kwargs))


def _exponent(f, x: float, factor: float) -> float:
    return math.log(f(x * factor) / f(x)) / math.log(factor)


@settings(max_examples=40, deadline=None)
@given(u=st.floats(0.1, 50.0), eta=st.floats(1e-3, 0.5), alpha=st.floats(5e-9, 4e-8),
       q=st.floats(10.0, 1e4), rx=st.floats(1e-3, 3e-2), ratio=st.floats(1.5, 20.0),
       factor=st.floats(1.5, 20.0))
def test_hamrock_dowson_minimum_exponents(u, eta, alpha, q, rx, ratio, factor):
    def h(u=u, eta=eta, alpha=alpha, q=q):
        return _quiet(hamrock_dowson_1977_minimum, u, eta, alpha, q, rx, ratio * rx,
                      effective_modulus=EP)

    assert _exponent(lambda v: h(u=v), u, factor) == pytest.approx(0.68, abs=1e-9)
    assert _exponent(lambda v: h(eta=v), eta, factor) == pytest.approx(0.68, abs=1e-9)
    assert _exponent(lambda v: h(alpha=v), alpha, factor) == pytest.approx(0.49, abs=1e-9)
    assert _exponent(lambda v: h(q=v), q, factor) == pytest.approx(-0.073, abs=1e-9)


@pytest.mark.parametrize("name", sorted(LINE_FILMS))
@settings(max_examples=30, deadline=None)
@given(u=st.floats(0.1, 50.0), eta=st.floats(1e-3, 0.5), alpha=st.floats(5e-9, 4e-8),
       w=st.floats(100.0, 1e5), length=st.floats(5e-3, 3e-2), rx=st.floats(1e-3, 3e-2),
       factor=st.floats(1.5, 20.0))
def test_line_film_exponents(name, u, eta, alpha, w, length, rx, factor):
    fn, e_u, e_g, e_w = LINE_FILMS[name]

    def h(u=u, eta=eta, alpha=alpha, w=w):
        return _quiet(fn, u, eta, alpha, w, length, rx, effective_modulus=EP)

    assert _exponent(lambda v: h(u=v), u, factor) == pytest.approx(e_u, abs=1e-9)
    assert _exponent(lambda v: h(eta=v), eta, factor) == pytest.approx(e_u, abs=1e-9)
    assert _exponent(lambda v: h(alpha=v), alpha, factor) == pytest.approx(e_g, abs=1e-9)
    assert _exponent(lambda v: h(w=v), w, factor) == pytest.approx(e_w, abs=1e-9)


@settings(max_examples=40, deadline=None)
@given(u=st.floats(0.01, 50.0), eta=st.floats(1e-3, 0.5), alpha=st.floats(0.0, 4e-8),
       w=st.floats(10.0, 1e5), rx=st.floats(1e-3, 3e-2), c=st.floats(0.1, 10.0))
def test_films_see_speed_and_viscosity_only_through_their_product(u, eta, alpha, w, rx, c):
    line = (moes_line_central, *(f for f, *_ in LINE_FILMS.values()))
    for fn in line:
        if alpha == 0.0 and fn is not moes_line_central:
            continue
        a = _quiet(fn, c * u, eta, alpha, w, 0.01, rx, effective_modulus=EP)
        b = _quiet(fn, u, c * eta, alpha, w, 0.01, rx, effective_modulus=EP)
        assert a == pytest.approx(b, rel=1e-12), fn.__name__
    if alpha > 0.0:
        for fn in (hamrock_dowson_1977_central, hamrock_dowson_1977_minimum):
            a = _quiet(fn, c * u, eta, alpha, w, rx, 4 * rx, effective_modulus=EP)
            b = _quiet(fn, u, c * eta, alpha, w, rx, 4 * rx, effective_modulus=EP)
            assert a == pytest.approx(b, rel=1e-12), fn.__name__


def _moes(big_u, big_w, big_g, rx=0.01, length=0.01):
    eta = 0.01
    return _quiet(moes_line_central, big_u * EP * rx / eta, eta, big_g / EP,
                  big_w * length * EP * rx, length, rx, effective_modulus=EP)


@settings(max_examples=60, deadline=None)
@given(log_u=st.floats(-14.0, -7.0), log_w=st.floats(-7.0, -2.0), log_g=st.floats(0.0, 4.5))
def test_moes_local_exponents_between_its_asymptotes(log_u, log_w, log_g):
    big_u, big_w, big_g = 10.0**log_u, 10.0**log_w, 10.0**log_g
    d = 1e-5

    def slope(i):
        args = [big_u, big_w, big_g]
        hi, lo = list(args), list(args)
        hi[i] *= 1.0 + d
        lo[i] *= 1.0 - d
        return (math.log(_moes(*hi)) - math.log(_moes(*lo))) / (2.0 * d)

    tol = 1e-6
    assert 0.6 - tol <= slope(0) <= 1.0 + tol
    assert -1.0 - tol <= slope(1) <= tol
    assert -tol <= slope(2) <= 0.75 + tol


def test_moes_tends_to_its_corner_asymptotes():
    """M = 1e8, L = 100 (elastic-piezoviscous, H_RP / H_EP = 6.7): H within 0.1 % of
    1.311 M^-1/8 L^3/4 (the rigid-piezoviscous asymptote's share, (H_RP / H_EP)^-3.5 2/7, is
    3e-4; at M = 1e6, L = 1e4 it is 1 %);
    M = 1e-3, L = 0 (rigid-isoviscous): H within 1e-6 of 3 / M."""
    def dimensionless(big_u, big_w, big_g):
        two_u = 2.0 * big_u
        return _moes(big_u, big_w, big_g) / 0.01 / math.sqrt(two_u), big_w / math.sqrt(two_u), \
            big_g * two_u**0.25

    big_u = 1e-12
    big_w = 1e8 * math.sqrt(2.0 * big_u)
    big_g = 100.0 / (2.0 * big_u) ** 0.25
    h, m, lam = dimensionless(big_u, big_w, big_g)
    assert h == pytest.approx(1.311 * m**-0.125 * lam**0.75, rel=1e-3)
    big_w = 1e-3 * math.sqrt(2.0 * big_u)
    h, m, _ = dimensionless(big_u, big_w, 0.0)
    assert h == pytest.approx(3.0 / m, rel=1e-6)
