"""Property tests of the shaft link (thermobearing.network.shaft, session 22).

- fin_span_conductances: the two-port of a convecting shaft span (Incropera et al. 2007,
  sec. 3.6.2, Table 3.4 case C) tends to the adiabatic rod k A / L with no loss as h -> 0,
  each end's loss tends to half the span's surface convection h pi d L / 2, the coupling
  falls and the loss rises with h, and the two-port reproduces the fin's end heat
  q_a = k A m [cosh(mL) theta_a - theta_b] / sinh(mL) for any end temperatures;
- kept_lengths: the shaft is counted once: the kept lengths add up to the length of the
  union of the pieces, no node keeps more than its piece, pieces that do not overlap keep
  all of it.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.network.shaft import (
    axial_shaft_conductance,
    fin_span_conductances,
    kept_lengths,
)

rod = dict(k=st.floats(10.0, 400.0), d=st.floats(0.005, 0.5), length=st.floats(0.01, 3.0))


@settings(max_examples=100, deadline=None)
@given(**rod, h=st.floats(1e-9, 500.0), more=st.floats(1.01, 10.0),
       ta=st.floats(-50.0, 50.0), tb=st.floats(-50.0, 50.0))
def test_fin_span_two_port(k, d, length, h, more, ta, tb):
    g_ab, g_end = fin_span_conductances(k, d, length, h)
    g0 = axial_shaft_conductance(k, d, length)
    assert 0.0 < g_ab <= g0 * (1 + 1e-12)
    assert g_end > 0.0
    g_ab2, g_end2 = fin_span_conductances(k, d, length, h * more)
    assert g_ab2 <= g_ab * (1 + 1e-12) and g_end2 >= g_end * (1 - 1e-12)
    area = math.pi * d * d / 4.0
    m = math.sqrt(4.0 * h / (k * d))
    ml = m * length
    q_a = k * area * m * (math.cosh(ml) * ta - tb) / math.sinh(ml)
    two_port = g_ab * (ta - tb) + g_end * ta
    assert two_port == pytest.approx(q_a, rel=1e-9, abs=1e-12 * g0 * (abs(ta) + abs(tb)))


@settings(max_examples=60, deadline=None)
@given(**rod, log_h=st.floats(-300.0, -8.0))
def test_fin_span_tends_to_the_adiabatic_rod(k, d, length, log_h):
    h = 10.0**log_h
    g_ab, g_end = fin_span_conductances(k, d, length, h)
    assert g_ab == pytest.approx(axial_shaft_conductance(k, d, length), rel=1e-6)
    assert g_end == pytest.approx(h * math.pi * d * length / 2.0, rel=1e-6)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(-2.0, 2.0), st.floats(0.01, 1.0)), min_size=1,
                max_size=6))
def test_kept_lengths_count_the_shaft_once(pieces):
    xs = [x for x, _ in pieces]
    ls = [L for _, L in pieces]
    kept = kept_lengths(xs, ls)
    ivals = sorted((x - 0.5 * L, x + 0.5 * L) for x, L in pieces)
    union, (lo, hi) = 0.0, ivals[0]
    for a, b in ivals[1:]:
        if a > hi:
            union += hi - lo
            lo, hi = a, b
        else:
            hi = max(hi, b)
    union += hi - lo
    assert sum(kept) == pytest.approx(union, rel=1e-9)
    for i, (x, L) in enumerate(pieces):
        assert 0.0 <= kept[i] <= L * (1 + 1e-9)
        alone = all(abs(x - y) >= 0.5 * (L + M) for j, (y, M) in enumerate(pieces) if j != i)
        if alone:
            assert kept[i] == pytest.approx(L, rel=1e-9)


def test_a_long_convecting_span_decouples_its_ends():
    """Defect found: math.sinh(mL) overflowed beyond mL ~ 710 (OverflowError from a scene's
    shaft_link with h = 5000 W/(m^2 K), a 5 mm shaft of k = 15 W/(m K), 3 m spacing: mL =
    1549); the ends are decoupled there, each losing k A m to the ambient."""
    k, d, length, h = 15.0, 0.005, 3.0, 5000.0
    g_ab, g_end = fin_span_conductances(k, d, length, h)
    kam = k * math.pi * d * d / 4.0 * math.sqrt(4.0 * h / (k * d))
    assert g_ab == 0.0
    assert g_end == pytest.approx(kam, rel=1e-12)
    # just below the old overflow the coupling is the closed form's
    length = 700.0 / math.sqrt(4.0 * h / (k * d))
    g_ab, _ = fin_span_conductances(k, d, length, h)
    assert g_ab == pytest.approx(kam / math.sinh(700.0), rel=1e-9)
