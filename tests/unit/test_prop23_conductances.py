"""Property tests, round 5: conductance models of the thermal network
(:mod:`thermobearing.network.conductances`).

Invariants:

- the heat flow q = G(Ta, Tb) (Ta - Tb) of a convection law grows strictly with the surface
  temperature Ta at a fixed fluid temperature (free convection: Churchill & Chu 1975, Nu
  rising with Ra ~ |dT|; forced convection of oil on a plate or on balls hotter than the oil:
  the oil thins near the wall, Whitaker 1972 (mu/mu_s)^(1/4) >= 1): a network of such edges
  has a monotone heat-flow law and so one steady state;
- free convection and the flat-plate law use the film temperature and |Ta - Tb|, so they are
  symmetric in the two temperatures;
- elliptic constriction resistance R = K(e) / (2 pi k a): the circle gives 1/(4 k a)
  (Carslaw & Jaeger 1959), R is symmetric in the semi-axes, scales as 1/k and, at a fixed
  aspect ratio, as 1/a, and falls when either semi-axis grows (a larger contact conducts
  better: Rayleigh's monotonicity of resistance in the contact region).
"""

from __future__ import annotations

import math
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import ValidityWarning
from thermobearing.network.conductances import (
    NaturalConvectionCylinder,
    OilForcedConvectionPlate,
    OilForcedConvectionSphere,
    elliptic_constriction_resistance,
)


def _flow(model, ta, tb):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return model.conductance(ta, tb) * (ta - tb)


@settings(max_examples=60, deadline=None)
@given(d=st.floats(0.05, 1.0), area=st.floats(0.01, 3.0), tb=st.floats(260.0, 330.0),
       low=st.floats(-50.0, 150.0), gap=st.floats(0.01, 100.0))
def test_free_convection_flow_grows_with_the_surface_temperature(d, area, tb, low, gap):
    """q(Ta1) < q(Ta2) for Ta1 < Ta2 (Churchill-Chu); G(Ta, Tb) = G(Tb, Ta)."""
    m = NaturalConvectionCylinder(d, area)
    lo, hi = tb + low, tb + low + gap
    assert _flow(m, lo, tb) < _flow(m, hi, tb)
    assert m.conductance(lo, tb) == pytest.approx(m.conductance(tb, lo), rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(length=st.floats(0.01, 0.2), v=st.floats(0.1, 20.0), area=st.floats(1e-3, 0.1),
       tb=st.floats(290.0, 370.0),
       low=st.floats(-40.0, 80.0), gap=st.floats(0.01, 40.0))
def test_oil_plate_flow_grows_with_the_surface_temperature(length, v, area, tb, low, gap):
    """Flat plate in oil: q monotone in Ta, G symmetric (film temperature)."""
    m = OilForcedConvectionPlate("ISO_VG46", length, v, area)
    lo, hi = tb + low, tb + low + gap
    assert _flow(m, lo, tb) < _flow(m, hi, tb)
    assert m.conductance(lo, tb) == pytest.approx(m.conductance(tb, lo), rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(d=st.floats(0.003, 0.05), v=st.floats(0.1, 20.0), z=st.integers(6, 40),
       tb=st.floats(280.0, 380.0),
       low=st.floats(0.0, 80.0), gap=st.floats(0.01, 40.0))
def test_oil_sphere_flow_grows_with_the_ball_temperature(d, v, z, tb, low, gap):
    """Balls at or above the oil temperature (Whitaker's mu/mu_s >= 1): q monotone in Ta."""
    m = OilForcedConvectionSphere("ISO_VG46", d, v, z)
    lo, hi = tb + low, tb + low + gap
    assert _flow(m, lo, tb) < _flow(m, hi, tb)


@settings(max_examples=200, deadline=None)
@given(a=st.floats(1e-6, 1e-2), ratio=st.floats(1e-3, 1.0), k=st.floats(1.0, 400.0),
       grow=st.floats(1.01, 3.0))
def test_constriction_resistance_limits_symmetry_scaling_and_monotonicity(a, ratio, k, grow):
    """Circle 1/(4 k a); R(a, b) = R(b, a); R(k) ~ 1/k; R(s a, s b) = R(a, b)/s; growing
    either semi-axis lowers R."""
    b = a * ratio

    def r(x, y, kk=k):
        return float(elliptic_constriction_resistance(x, y, kk))

    assert r(a, a) == pytest.approx(1.0 / (4.0 * k * a), rel=1e-12)
    assert r(a, b) == pytest.approx(r(b, a), rel=1e-14)
    assert r(a, b, 2.0 * k) == pytest.approx(0.5 * r(a, b), rel=1e-12)
    assert r(grow * a, grow * b) == pytest.approx(r(a, b) / grow, rel=1e-12)
    assert r(a, b * min(grow, 1.0 / ratio)) < r(a, b) or math.isclose(ratio, 1.0)
    assert r(a * grow, b) < r(a, b)
