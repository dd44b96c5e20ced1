"""Property tests of the raceway heat-source helpers (:mod:`thermobearing.heat_sources.raceway`,
session 19).

Blok's partition of the contact heat lies in (0, 1), is 1/2 for equal materials and surface
speeds, and is complementary when element and race swap (materials swapped, sliding
reversed). The roller rolling forces follow their correlations' exponents: paper 000 eq. 35,
Q_x = 18.4 G^-0.3 U^0.7 E' R_x l (u^0.7, eta^0.7, alpha^-0.3, independent of the load;
the speed's sign does not matter), and Martin's rigid-isoviscous force
Q_x = k_q l sqrt(eta U w / k_w) ~ (eta U)^0.5 w^0.5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.heat_sources.raceway import (
    blok_partition,
    rolling_force_paper000,
    rolling_force_rigid_isoviscous,
)


@dataclass(frozen=True)
class _Mat:
    thermal_conductivity: float
    density: float
    specific_heat: float


mats = st.builds(_Mat, st.floats(5.0, 100.0), st.floats(2000.0, 9000.0),
                 st.floats(300.0, 1000.0))


@settings(max_examples=80, deadline=None)
@given(u=st.floats(0.0, 50.0), v=st.floats(-20.0, 20.0), b=st.floats(1e-5, 1e-3),
       m1=mats, m2=mats)
def test_blok_partition_bounds_and_swap(u, v, b, m1, m2):
    share = float(blok_partition(u, v, b, m1, m2))
    assert 0.0 < share < 1.0
    swapped = float(blok_partition(u, -v, b, m2, m1))
    assert math.isclose(share + swapped, 1.0, rel_tol=1e-12)
    assert math.isclose(float(blok_partition(u, 0.0, b, m1, m1)), 0.5, rel_tol=1e-12)


@settings(max_examples=60, deadline=None)
@given(u=st.floats(0.1, 40.0), eta=st.floats(1e-3, 0.3), alpha=st.floats(5e-9, 3e-8),
       rx=st.floats(2e-3, 2e-2), length=st.floats(3e-3, 3e-2), factor=st.floats(1.5, 10.0))
def test_paper000_rolling_force_exponents(u, eta, alpha, rx, length, factor):
    def f(u_=u, eta_=eta, alpha_=alpha, length_=length):
        return float(rolling_force_paper000(u_, eta_, alpha_, 2.28e11, rx, length_))

    base = f()
    assert base > 0.0 and f(u_=-u) == base
    lf = math.log(factor)
    for got, n in ((f(u_=u * factor), 0.7), (f(eta_=eta * factor), 0.7),
                   (f(alpha_=alpha * factor), -0.3), (f(length_=length * factor), 1.0)):
        assert math.isclose(math.log(got / base) / lf, n, rel_tol=1e-9)


@settings(max_examples=60, deadline=None)
@given(us=st.floats(0.1, 40.0), eta=st.floats(1e-3, 0.3), q=st.floats(1.0, 2e4),
       rx=st.floats(2e-3, 2e-2), length=st.floats(3e-3, 3e-2), factor=st.floats(1.5, 10.0))
def test_martin_rolling_force_exponents(us, eta, q, rx, length, factor):
    def f(us_=us, eta_=eta, q_=q):
        return float(rolling_force_rigid_isoviscous(us_, eta_, q_, rx, length))

    base = f()
    assert base > 0.0 and f(us_=-us) == base
    lf = math.log(factor)
    for got, n in ((f(us_=us * factor), 0.5), (f(eta_=eta * factor), 0.5),
                   (f(q_=q * factor), 0.5)):
        assert math.isclose(math.log(got / base) / lf, n, rel_tol=1e-9)
    assert float(rolling_force_rigid_isoviscous(0.0, eta, q, rx, length)) == 0.0
    assert float(rolling_force_rigid_isoviscous(us, eta, 0.0, rx, length)) == 0.0
