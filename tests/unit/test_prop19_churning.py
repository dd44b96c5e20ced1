"""Property tests of the churning model of paper 002 eqs. 12-17 and its oil fractions
(:mod:`thermobearing.heat_sources.churning`, session 19).

The friction coefficient mu_v(N_Re, N_Ta) of eqs. 12-14 is continuous inside each flow regime
and jumps at the regime boundaries. The jumps are the paper's own (its printed formulas are
discontinuous there), so they are pinned at the values the formulas give rather than
asserted away:

- N_Ta = 41 with N_Re <= 2500 (laminar -> Taylor vortices): eq. 13 / eq. 12 = 1.3 exactly;
- N_Re = 2500 with N_Ta > 41 (vortices -> turbulence): eq. 14 / eq. 13 =
  3.0 / (1.3 (N_Ta / 41)^0.539474) with N_Ta = 2500 sqrt(c / R), i.e. a function of the gap
  ratio c / R only: a jump up below c / R = 0.00597 and a fall above it (0.34-0.87 for the
  cage, ring and element gaps of the bearings in configs/bearings, e.g. QJ1044 cage 0.872);
- N_Ta = 41 with N_Re > 2500 (c / R < (41/2500)^2, laminar -> turbulence): eq. 14 / eq. 12 =
  3.0 (N_Re / 2500)^0.85596 > 3.

Inside a regime the churning power Q ~ mu_v omega^3 (eqs. 15, 17) grows like omega^2
(laminar), omega^2.539474 (vortices) and omega^2.85596 (turbulence).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from thermobearing.heat_sources.churning import (
    REYNOLDS_CRITICAL,
    TAYLOR_CRITICAL,
    cage_churning_power,
    inner_ring_churning_power,
    oil_bath_fraction,
    parker_oil_fraction,
    viscous_friction_coefficient,
)

EPS = 1e-9
TA_EXP, RE_EXP = 0.539474, 0.85596


def _omega_for_re(re, r, c, nu):
    return re * nu / (r * c)


@settings(max_examples=80, deadline=None)
@given(r=st.floats(0.01, 0.3), gap_ratio=st.floats(3e-4, 0.3), nu=st.floats(1e-6, 1e-3))
def test_taylor_onset_jump_is_the_papers_1_3(r, gap_ratio, nu):
    """Crossing N_Ta = 41 below N_Re = 2500: mu_v jumps by 1.3 (eq. 13 at N_Ta = 41 is
    1.3 mu_l, eq. 12 is mu_l); just below and above the boundary the regimes are 0 and 1."""
    c = gap_ratio * r
    re_at = TAYLOR_CRITICAL / math.sqrt(gap_ratio)
    assume(re_at * (1 + 1e-6) < REYNOLDS_CRITICAL)
    lo = viscous_friction_coefficient(r, _omega_for_re(re_at * (1 - EPS), r, c, nu), c, nu)
    hi = viscous_friction_coefficient(r, _omega_for_re(re_at * (1 + EPS), r, c, nu), c, nu)
    assert int(lo.regime) == 0 and int(hi.regime) == 1
    assert math.isclose(float(hi.mu_v) / float(lo.mu_v), 1.3, rel_tol=1e-6)


@settings(max_examples=80, deadline=None)
@given(r=st.floats(0.01, 0.3), gap_ratio=st.floats(3e-4, 0.3), nu=st.floats(1e-6, 1e-3))
def test_turbulence_onset_jump_depends_on_the_gap_ratio_only(r, gap_ratio, nu):
    """Crossing N_Re = 2500 above N_Ta = 41: mu_v(2500+) / mu_v(2500-) = 3.0 / (1.3
    (2500 sqrt(c/R) / 41)^0.539474), whatever R, nu; 1 only at c/R = 0.00597."""
    c = gap_ratio * r
    ta = REYNOLDS_CRITICAL * math.sqrt(gap_ratio)
    assume(ta > TAYLOR_CRITICAL * (1 + 1e-6))
    lo = viscous_friction_coefficient(r, _omega_for_re(2500 * (1 - EPS), r, c, nu), c, nu)
    hi = viscous_friction_coefficient(r, _omega_for_re(2500 * (1 + EPS), r, c, nu), c, nu)
    assert int(lo.regime) == 1 and int(hi.regime) == 2
    expected = 3.0 / (1.3 * (ta / TAYLOR_CRITICAL) ** TA_EXP)
    assert math.isclose(float(hi.mu_v) / float(lo.mu_v), expected, rel_tol=1e-6)


def test_turbulence_onset_is_continuous_only_at_one_gap_ratio():
    """3.0 = 1.3 (2500 sqrt(g) / 41)^0.539474 at g = (41/2500 (3/1.3)^(1/0.539474))^2 =
    0.00597; the jump factor falls monotonically with g through 1 there."""
    g_star = (TAYLOR_CRITICAL / REYNOLDS_CRITICAL * (3.0 / 1.3) ** (1 / TA_EXP)) ** 2
    assert math.isclose(g_star, 0.005972, rel_tol=1e-3)
    r, nu = 0.1, 1e-5
    ratios = []
    for g in (0.5 * g_star, g_star, 2.0 * g_star):
        c = g * r
        lo = viscous_friction_coefficient(r, _omega_for_re(2500 * (1 - EPS), r, c, nu), c, nu)
        hi = viscous_friction_coefficient(r, _omega_for_re(2500 * (1 + EPS), r, c, nu), c, nu)
        ratios.append(float(hi.mu_v) / float(lo.mu_v))
    assert ratios[0] > 1.0 > ratios[2]
    assert math.isclose(ratios[1], 1.0, rel_tol=1e-6)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.01, 0.3), gap_ratio=st.floats(1e-6, 2.6e-4), nu=st.floats(1e-6, 1e-3))
def test_narrow_gap_laminar_to_turbulent_jump(r, gap_ratio, nu):
    """c/R < (41/2500)^2: N_Ta reaches 41 only above N_Re = 2500, and mu_v jumps from eq. 12
    straight to eq. 14, by 3.0 (N_Re/2500)^0.85596 at N_Re = 41 / sqrt(c/R)."""
    c = gap_ratio * r
    re_at = TAYLOR_CRITICAL / math.sqrt(gap_ratio)
    assume(re_at > REYNOLDS_CRITICAL * (1 + 1e-6))
    lo = viscous_friction_coefficient(r, _omega_for_re(re_at * (1 - EPS), r, c, nu), c, nu)
    hi = viscous_friction_coefficient(r, _omega_for_re(re_at * (1 + EPS), r, c, nu), c, nu)
    assert int(lo.regime) == 0 and int(hi.regime) == 2
    expected = 3.0 * (re_at / REYNOLDS_CRITICAL) ** RE_EXP
    assert math.isclose(float(hi.mu_v) / float(lo.mu_v), expected, rel_tol=1e-6)


@settings(max_examples=80, deadline=None)
@given(r=st.floats(0.01, 0.3), gap_ratio=st.floats(1e-6, 0.3), nu=st.floats(1e-6, 1e-3),
       log_re=st.floats(-1.0, 6.0), factor=st.floats(1.0001, 1.5))
def test_churning_power_exponent_inside_a_regime(r, gap_ratio, nu, log_re, factor):
    """Two speeds in one regime: Q2/Q1 = (w2/w1)^n with n = 2 (laminar), 2.539474 (vortex),
    2.85596 (turbulent), for the cage (eq. 15) and the inner ring (eq. 17); Q >= 0 and the
    coefficient is the same at -omega (the flow does not know the sense of rotation)."""
    c = gap_ratio * r
    w1 = _omega_for_re(10.0 ** log_re, r, c, nu)
    w2 = factor * w1
    r1 = viscous_friction_coefficient(r, w1, c, nu)
    r2 = viscous_friction_coefficient(r, w2, c, nu)
    assume(int(r1.regime) == int(r2.regime))
    n = {0: 2.0, 1: 2.0 + TA_EXP, 2: 2.0 + RE_EXP}[int(r1.regime)]
    q1 = cage_churning_power(850.0, r1.mu_v, w1, 0.02, 2 * r)
    q2 = cage_churning_power(850.0, r2.mu_v, w2, 0.02, 2 * r)
    assert q1 > 0.0 and q2 > q1
    assert math.isclose(float(q2 / q1), factor ** n, rel_tol=1e-9)
    i1 = inner_ring_churning_power(850.0, r1.mu_v, -w1, 0.01, 0.005, 2 * r)
    i2 = inner_ring_churning_power(850.0, r2.mu_v, -w2, 0.01, 0.005, 2 * r)
    assert math.isclose(float(i2 / i1), factor ** n, rel_tol=1e-9)
    neg = viscous_friction_coefficient(r, -w1, c, nu)
    assert float(neg.mu_v) == float(r1.mu_v) and int(neg.regime) == int(r1.regime)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.01, 0.3), gap_ratio=st.floats(1e-6, 0.3), nu=st.floats(1e-6, 1e-3),
       log_re=st.floats(-1.0, 6.0), factor=st.floats(1.0001, 3.0))
def test_churning_power_falls_with_speed_only_at_the_turbulence_onset(r, gap_ratio, nu,
                                                                      log_re, factor):
    """Q(omega) rises with speed except across N_Re = 2500 when c/R > 0.00597 (the jump of
    eq. 14 / eq. 13 below 1): then Q2 / Q1 >= factor^2 x that jump (the least exponent 2
    times the fall)."""
    c = gap_ratio * r
    w1 = _omega_for_re(10.0 ** log_re, r, c, nu)
    w2 = factor * w1
    r1 = viscous_friction_coefficient(r, w1, c, nu)
    r2 = viscous_friction_coefficient(r, w2, c, nu)
    q1 = float(cage_churning_power(850.0, r1.mu_v, w1, 0.02, 2 * r))
    q2 = float(cage_churning_power(850.0, r2.mu_v, w2, 0.02, 2 * r))
    if int(r1.regime) == 1 and int(r2.regime) == 2:
        ta = REYNOLDS_CRITICAL * math.sqrt(gap_ratio)
        jump = 3.0 / (1.3 * (ta / TAYLOR_CRITICAL) ** TA_EXP)
        assert q2 >= q1 * factor ** 2 * min(jump, 1.0) * (1 - 1e-9)
    else:
        assert q2 > q1


@settings(max_examples=80, deadline=None)
@given(flow=st.floats(0.0, 1e-3), rpm=st.floats(1.0, 30000.0), dm=st.floats(0.02, 0.5),
       more=st.floats(1.0, 10.0))
def test_parker_fraction_in_unit_interval_and_monotone(flow, rpm, dm, more):
    """X = K Q^0.37 / (n d_m^1.7) capped at 1: in [0, 1], non-decreasing in the flow,
    non-increasing in the speed and the pitch diameter."""
    w = rpm * math.pi / 30.0
    x = parker_oil_fraction(flow, w, dm)
    assert 0.0 <= x <= 1.0
    assert parker_oil_fraction(flow * more, w, dm) >= x
    assert parker_oil_fraction(flow, w * more, dm) <= x
    assert parker_oil_fraction(flow, w, dm * more) <= x
    assert parker_oil_fraction(flow, -w, dm) == x


@settings(max_examples=80, deadline=None)
@given(ro=st.floats(0.02, 0.3), level=st.floats(-0.1, 1.0), r=st.floats(0.1, 1.0),
       dl=st.floats(0.0, 0.2))
def test_oil_bath_fraction_in_unit_interval_and_rising_with_the_level(ro, level, r, dl):
    """acos(clip((R_o - H)/r))/pi in [0, 1], non-decreasing in the level H; 1/2 when the
    level is at the bearing axis (H = R_o), 0 below the orbit, 1 above it."""
    h = level * 2 * ro
    rad = r * ro
    x = float(oil_bath_fraction(h, ro, rad))
    assert 0.0 <= x <= 1.0
    assert float(oil_bath_fraction(h + dl * ro, ro, rad)) >= x
    assert math.isclose(float(oil_bath_fraction(ro, ro, rad)), 0.5, rel_tol=1e-12)
    assert float(oil_bath_fraction(ro - rad * 1.0001, ro, rad)) == 0.0
    assert float(oil_bath_fraction(ro + rad * 1.0001, ro, rad)) == 1.0


def test_array_path_has_the_same_jumps():
    """The vectorised path (np.frompyfunc) gives the scalar path's values at the boundaries."""
    r, nu = 0.1, 1e-5
    for g in (1e-3, 1e-2, 1e-5):
        c = g * r
        re_t = TAYLOR_CRITICAL / math.sqrt(g)
        res = np.array([re_t * (1 - EPS), re_t * (1 + EPS), 2500 * (1 - EPS), 2500 * (1 + EPS)])
        w = _omega_for_re(res, r, c, nu)
        arr = viscous_friction_coefficient(np.full(4, r), w, c, nu)
        for i in range(4):
            one = viscous_friction_coefficient(r, float(w[i]), c, nu)
            assert float(one.mu_v) == float(arr.mu_v[i])
