"""Property tests of :func:`thermobearing.skidding.solve` on the ball (QJ1044, SKF6304) and
roller (NU214, D1842926) presets over speed, load and oil temperature, cold and warm starts.

Invariants of a converged state (README promises; paper 002 / paper 000 models):

- every returned float finite, contact loads >= 0, sliding speeds finite;
- 0 < CSR < 1 for an inner-ring-driven bearing with the outer ring fixed;
- the theoretical CSR inside its geometric bounds: ball (1 - gamma cos alpha)/2 with
  gamma = D/d_m, so (1 - D/d_m)/2 <= CSR_th <= 1/2; roller (1 - D/d_m)/2 (paper 000 eq. 40);
- ring equilibrium from the returned fields only. Ball (inner-ring arcs, contact force on the
  ball -Q n + F_x t with the transverse traction F_x of the kinematic state; the signed
  contact angle alpha of the result): F_a = -sum (Q sin alpha + F_x cos alpha),
  F_r = sum cos(psi) (Q cos alpha - F_x sin alpha), to the solver tolerance (scaled by the
  load). Roller: sum Q_i cos(psi) = F_r (paper 000 eqs. 20/23);
- a failure is a ConvergenceError with a residual that is not NaN, never NaN in a result.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.errors import ConvergenceError, ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import solve
from thermobearing.state import OilSupply

RPM = math.pi / 30.0
BALL = {name: load_bearing(name) for name in ("QJ1044", "SKF6304")}
ROLLER = {name: load_bearing(name) for name in ("NU214", "D1842926")}
VG68 = load_lubricant("ISO_VG68")
ROLLER_OIL = {"NU214": load_lubricant("PAPER000_OIL"), "D1842926": load_lubricant("OIL_4109")}


def _supply(temperature):
    return OilSupply("jet", 33 / 60000, temperature)


def _ball_solve(name, rpm, fr, fa, t_c, **kw):
    t = t_c + 273.15
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return solve(BALL[name], VG68, rpm * RPM, fr, fa, t, supply=_supply(t), **kw)


def check_ball_invariants(r, fr, fa, name):
    b = BALL[name]
    assert r.converged
    for v in (r.cage_speed_ratio, r.theoretical_cage_speed_ratio, r.residual_norm,
              r.kinematic_cage_speed_ratio, r.cage_speed, r.shaft_torque, r.delta_a, r.delta_r):
        assert math.isfinite(v)
    for arr in (r.normal_load, r.contact_angle, r.sliding_speed, r.transverse_sliding_speed,
                r.spin, r.entrainment_speed, r.pocket_force, r.ball_x, r.ball_r):
        assert np.all(np.isfinite(arr))
    assert all(math.isfinite(v) for v in r.heat.values())
    assert 0.0 < r.cage_speed_ratio < 1.0
    gamma = b.ball_diameter / b.pitch_diameter
    assert 0.5 * (1.0 - gamma) - 1e-12 <= r.theoretical_cage_speed_ratio <= 0.5 + 1e-12
    assert np.all(r.normal_load >= 0.0)
    st_ = r.kinematic_state
    inner = r.ring == 0
    q, al = r.normal_load, r.contact_angle
    fx = np.stack([c.traction.result.transverse_force for c in st_.contacts], axis=1)
    fa_s = -np.sum((q * np.sin(al) + fx * np.cos(al))[:, inner])
    fr_s = np.sum(((q * np.cos(al) - fx * np.sin(al))[:, inner]).T * np.cos(st_.azimuth))
    # residual scaled by F_s (the solver's force scale, about the largest ball load): 1e-9
    # of it, plus round-off of the sums; 1e-7 of the load covers both with margin
    slack = 1e-7 * max(fr, abs(fa), 100.0)
    assert abs(fa_s - fa) <= slack
    assert abs(fr_s - fr) <= slack


# load and speed ranges: QJ1044 (220 mm bore, C of the 400 kN class): to 4000 r/min, loads
# up to 100 kN radial / 200 kN axial; SKF6304 (C = 16.8 kN): to 20000 r/min, 30 kN / 10 kN.
# Light loads below ~0.3 % of C are left out here (the seeded probe below covers them) --
# this test asks that every point in range either converges with the invariants or raises
# a ConvergenceError with a residual.
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(BALL)), log_rpm=st.floats(math.log(10.0), math.log(20000.0)),
       fr_frac=st.one_of(st.just(0.0), st.floats(0.005, 1.0)),
       fa_frac=st.one_of(st.just(0.0), st.floats(0.005, 1.0)), negative=st.booleans(),
       t_c=st.floats(0.0, 140.0))
def test_ball_solve_converges_with_invariants_or_says_why(name, log_rpm, fr_frac, fa_frac,
                                                          negative, t_c):
    rpm_max, fr_max, fa_max = {"QJ1044": (4000.0, 1e5, 2e5),
                               "SKF6304": (20000.0, 3e4, 1e4)}[name]
    rpm = min(math.exp(log_rpm), rpm_max)
    fr, fa = fr_frac * fr_max, fa_frac * fa_max
    if negative and name == "QJ1044":
        fa = -fa
    try:
        r = _ball_solve(name, rpm, fr, fa, t_c)
    except ConvergenceError as err:
        assert not math.isnan(err.residual)
        if fr == 0.0 and fa == 0.0:
            assert err.residual == math.inf and "inner ring" in str(err)
        return
    check_ball_invariants(r, fr, fa, name)


@pytest.mark.parametrize("name, rpm, fr, fa, t_c", [
    ("QJ1044", 300.0, 5000.0, 2000.0, 40.0), ("QJ1044", 1500.0, 0.0, 20000.0, 80.0),
    ("QJ1044", 3000.0, 20000.0, -5000.0, 120.0), ("QJ1044", 10.0, 50000.0, 0.0, 0.0),
    ("SKF6304", 3000.0, 1000.0, 0.0, 40.0), ("SKF6304", 10000.0, 2000.0, 500.0, 90.0),
    ("SKF6304", 300.0, 5000.0, 100.0, 140.0), ("SKF6304", 20000.0, 100.0, 0.0, 20.0),
])
def test_ball_solve_grid_converges(name, rpm, fr, fa, t_c):
    """Ordinary operating points must converge (the property test above accepts failures)."""
    check_ball_invariants(_ball_solve(name, rpm, fr, fa, t_c), fr, fa, name)


@pytest.mark.parametrize("rpm, fr, fa", [(10.0, 1000.0, 0.0), (10.0, 15000.0, 100.0),
                                         (10.0, 5000.0, 0.0), (100.0, 5000.0, 0.0),
                                         (100.0, 15000.0, 0.0), (300.0, 1000.0, 100.0),
                                         (10.0, 5000.0, 100.0), (30.0, 1000.0, 100.0),
                                         (30.0, 5000.0, 100.0)])
def test_deep_groove_low_speed_converges(rpm, fr, fa):
    """Defects found by this test: the SKF6304 at 10-300 r/min under 1-15 kN radial load
    failed with ConvergenceError. (1) At 10 r/min the cold start stood at 1e-6..5e-7 after
    150 iterations, converging only linearly (the unloaded balls are held by a centrifugal
    contact of ~1e-3 N), and the continuation then failed at 0.40 / 0.72: a cold start that
    hits the iteration limit below 1e-2 now gets more Newton iterations from its last
    iterate. (2) At 100-300 r/min Newton met a singular ball block (an unloaded ball losing
    that contact along a step) and gave up at once (2.0e-4 at 100 r/min, 5 kN): it now takes
    damped steps with the last good factorisation, and the iterate reaches the fallbacks.
    (3) The last three points (1-5 kN radial with 100 N axial at 10-30 r/min) stalled at
    2.5e-8 .. 6.2e-7 until the load distribution that starts the solver
    stopped pulling the unloaded balls up their groove flanks (loads.py)."""
    r = _ball_solve("SKF6304", rpm, fr, fa, 40.0)
    check_ball_invariants(r, fr, fa, "SKF6304")


@pytest.mark.parametrize("name, rpm, fr, fa, t_c", [
    # SKF6304, 21.4 kN + 37 N, 1231 r/min, 26 degC: ~13 s CPU (slow)
    pytest.param("SKF6304", 1230.724071006954, 21445.099494558173, 36.85524752432373,
                 26.21535976081373, marks=pytest.mark.slow),
    ("QJ1044", 25.494333451043417, 73141.19514807193, -69370.13988833768, 136.28429038166476),
])
def test_stalled_newton_points_converge_without_the_stall_rule(name, rpm, fr, fa, t_c):
    """Points of the random probe that failed through every fallback (final residuals
    1.1e-3 and 6.0e-7): the damped Newton's stall rule stopped them, the trust-region
    fallback did not reach the tolerance, and the continuation failed too. Newton iterations
    without the stall rule from the best iterate, tried after the trust region, converge
    (307 / 286 more iterations, measured on one x86-64 machine; the path taken depends on
    round-off, the convergence is what is asked)."""
    check_ball_invariants(_ball_solve(name, rpm, fr, fa, t_c), fr, fa, name)


@pytest.mark.parametrize("rpm, fr, fa, t_c, csr", [
    (1510.6048702365651, 1.902654029285824, 0.0, 35.002567590481576, 9.082e-4),
    (3380.2734102008462, 0.0, -1.1268599366221774, 82.48432835431878, 1.1319e-3),
])
def test_nearly_stalled_cage_converges_by_the_continuation_in_speed(rpm, fr, fa, t_c, csr):
    """QJ1044 at 1.9 N radial, 1511 r/min, 35 degC, and at -1.13 N axial, 3380 r/min,
    82 degC: the traction of the few loaded balls barely turns the cage against the drag, so
    every start, the restarts, the trust region and the continuation in axial load failed
    (best 3.3e-5 and 3.8e-3). A continuation in speed from a quarter of the speed (from a
    sixteenth if that fails), warm-started step by step, reaches them (~1 s each): the cage
    turns at 0.091 % / 0.113 % of the shaft speed (a hand continuation in speed from 80 r/min
    gives 0.0009082 for the first). Which fallback reaches them depends on round-off; the
    state is pinned."""
    r = _ball_solve("QJ1044", rpm, fr, fa, t_c)
    check_ball_invariants(r, fr, fa, "QJ1044")
    assert r.cage_speed_ratio == pytest.approx(csr, rel=2e-3)


@pytest.mark.parametrize("name, rpm, fr, fa, t_c", [
    ("QJ1044", 63.672776703535376, 95.01279747271084, -11.656930368526035, 106.16282068053458),
    ("QJ1044", 198.7891532224581, 132.53113679030767, 0.0, 64.13113846805669),
    ("SKF6304", 70.96875525812881, 121.484868574429, 2.95462529462894, 135.4898762229222),
])
def test_light_load_points_converge_through_the_fallbacks(name, rpm, fr, fa, t_c):
    """Points of the random probe under light loads (95-133 N radial) that failed before the
    continuation retried failed steps. QJ1044, 132.5 N at 199 r/min: the cold start sits at
    1.5e-2 (the unloaded balls' spin / pocket-friction balance: their churning drag, 0.144
    N, exceeds the traction their centrifugal contacts carry, 0.092 N), and the continuation
    in axial load failed on the warm step 251 -> 158 N although a cold start at 160 N
    converges. The continuation now retries a failed step cold, then halves it; the state is
    marked ``"continuation"``. Which fallback reaches the root depends on round-off in the
    compiled kernels (the SKF6304 point converges by the continuation on one x86-64 machine
    and by the Newton restart on another, where the compiled kernels round differently), so
    the test asks that the cold start does not converge plainly and that a fallback recovers
    the point with the invariants."""
    r = _ball_solve(name, rpm, fr, fa, t_c)
    check_ball_invariants(r, fr, fa, name)
    assert r.extra.get("fallback") in ("continuation", "newton_restart", "trust_region")


@pytest.mark.parametrize("name, rpm, fr, fa, t_c", [
    ("QJ1044", 46.59985437797942, 2.322471332414693, 0.0, 18.014249724403722),
    ("SKF6304", 46.39835042989977, 9115.666601244337, 2494.2805171883797, 90.22107768877245),
    ("SKF6304", 83.94415645584766, 4188.788083839123, 0.0, 72.49645099902192),
    ("QJ1044", 35.5459707281424, 0.0, 2.150154110935353, 23.03101730637418),
])
def test_ball_points_found_by_the_probe_converge(name, rpm, fr, fa, t_c):
    """QJ1044, 2.3 N radial at 47 r/min: failed at 1.8e-1 after the continuation, converges
    with the Newton restart / singular-block fallback. SKF6304, 9.1 kN + 2.5 kN at 46 r/min,
    90 degC: the cold start's load distribution crawled at 3e-5 N against its 5e-6 N
    tolerance (ConvergenceError); as a starting point it is now taken at tol 1e-6. SKF6304,
    4.19 kN at 84 r/min, 72.5 degC (failed at 0.35 until fixed with the load
    distribution's start, loads.py). QJ1044, 2.15 N pure axial at 35.5 r/min (the
    cold start's load distribution used to stop at 0.30 N: the centrifugal force, 0.07 N
    per ball, moves every ball into a third arc; now a second start seats the balls in the
    outer groove, loads.py)."""
    check_ball_invariants(_ball_solve(name, rpm, fr, fa, t_c), fr, fa, name)


@pytest.mark.parametrize("name", sorted(BALL))
def test_ball_zero_load_is_a_clear_convergence_error(name):
    """Defect found by this test: the SKF6304 with no load "converged" to CSR = 0 (or
    -0.0) with every ball in the outer groove; the QJ1044 raised. Both now raise with
    residual inf and the reason."""
    with pytest.raises(ConvergenceError, match="no ball touches the inner ring") as info:
        _ball_solve(name, 3000.0, 0.0, 0.0, 40.0)
    assert info.value.residual == math.inf


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(BALL)), rpm=st.floats(200.0, 3000.0),
       fr=st.floats(500.0, 5000.0), step=st.floats(0.8, 1.25), t_c=st.floats(20.0, 100.0))
def test_ball_warm_start_matches_cold(name, rpm, fr, step, t_c):
    """Warm start from the previous result (guess=) lands on the cold-start solution of the
    new point (same equations: CSR to ~1e-7 of itself, set by the 1e-9 residual)."""
    fa = 0.3 * fr
    try:
        first = _ball_solve(name, rpm, fr, fa, t_c)
        cold = _ball_solve(name, rpm * step, fr * step, fa, t_c)
    except ConvergenceError:
        return
    warm = _ball_solve(name, rpm * step, fr * step, fa, t_c, guess=first)
    check_ball_invariants(warm, fr * step, fa, name)
    assert warm.cage_speed_ratio == pytest.approx(cold.cage_speed_ratio, rel=1e-6)


# --------------------------------------------------------------------------------- rollers
def _roller_solve(name, rpm, fr, t_c, **kw):
    return solve(ROLLER[name], ROLLER_OIL[name], rpm * RPM, fr, 0.0, t_c + 273.15, **kw)


def check_roller_invariants(r, fr, name):
    b = ROLLER[name]
    assert r.converged
    for v in (r.cage_speed_ratio, r.theoretical_cage_speed_ratio, r.residual_norm, r.slip,
              r.cage_speed):
        assert math.isfinite(v)
    for arr in (r.roller_speed, r.inner_load, r.outer_load, r.inner_sliding_speed,
                r.outer_sliding_speed, r.inner_entrainment_speed, r.outer_entrainment_speed,
                r.pocket_normal_force, r.pocket_friction, r.residual):
        assert np.all(np.isfinite(arr))
    assert 0.0 < r.cage_speed_ratio < 1.0
    gamma = b.roller_diameter / b.pitch_diameter
    assert r.theoretical_cage_speed_ratio == pytest.approx(0.5 * (1.0 - gamma), rel=1e-12)
    assert np.all(r.inner_load >= 0.0) and np.all(r.outer_load >= 0.0)
    # ring equilibrium (radial): sum Q_i (cos psi, sin psi) = (F_r, 0)
    assert np.sum(r.inner_load * np.cos(r.azimuth)) == pytest.approx(fr, rel=1e-8)
    assert abs(np.sum(r.inner_load * np.sin(r.azimuth))) <= 1e-8 * fr
    if r.extras["method"] == "newton":
        assert r.residual_norm <= 1e-9
    else:
        assert r.residual_norm <= max(1e-9, 4.0 * r.extras["round_off_floor"])


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(ROLLER)), log_rpm=st.floats(math.log(10.0), math.log(20000.0)),
       log_fr=st.floats(math.log(50.0), math.log(20000.0)), t_c=st.floats(0.0, 140.0))
def test_roller_solve_invariants(name, log_rpm, log_fr, t_c):
    fr = math.exp(log_fr)
    try:
        r = _roller_solve(name, math.exp(log_rpm), fr, t_c)
    except ConvergenceError as err:
        assert not math.isnan(err.residual)
        return
    check_roller_invariants(r, fr, name)


@pytest.mark.parametrize("name, rpm, fr, t_c", [
    ("NU214", 1000.0, 2000.0, 40.0), ("NU214", 10000.0, 100.0, 80.0),
    ("D1842926", 13218.0, 2000.0, 80.0), ("D1842926", 10.0, 20000.0, 140.0),
])
def test_roller_solve_grid_and_warm_start(name, rpm, fr, t_c):
    r = _roller_solve(name, rpm, fr, t_c)
    check_roller_invariants(r, fr, name)
    warm = _roller_solve(name, rpm * 1.05, fr * 1.1, t_c, guess=r)
    cold = _roller_solve(name, rpm * 1.05, fr * 1.1, t_c)
    check_roller_invariants(warm, fr * 1.1, name)
    assert warm.cage_speed_ratio == pytest.approx(cold.cage_speed_ratio, rel=1e-6)


@pytest.mark.parametrize("name", sorted(ROLLER))
def test_roller_zero_load_is_a_clear_input_error(name):
    from thermobearing.errors import InputError

    with pytest.raises(InputError, match="none touches the inner ring") as info:
        _roller_solve(name, 1000.0, 0.0, 40.0)
    assert info.value.field == "radial_load and axial_load"


@pytest.mark.slow
@pytest.mark.parametrize("rpm", [10.0, 1000.0, 10000.0])
def test_roller_heavy_load_bracketed_to_round_off(rpm):
    """Defect found by this test: NU214, 100 kN (about 0.7 C): the bracketed fallback
    stopped Brent at 1e-10 of the inner speed, where the cage equation still had 4.2 kN of
    residual (norm 0.18 at 1000 r/min) and reported it as converged. Brent now goes to a few
    ulps: measured norms 1.0e-6, 3.6e-6, 4.5e-6 (10 / 1000 / 10000 r/min), each within 4x
    the residual that one-ulp speed changes make there (extras['round_off_floor'])."""
    r = _roller_solve("NU214", rpm, 1e5, 40.0)
    check_roller_invariants(r, 1e5, "NU214")
    # bracketed, or Newton accepted at the same per-equation round-off floor (which of the
    # two depends on round-off in the compiled kernels), or -- since a state beyond tol is
    # accepted only when shaft power = dissipation to 1e-6 -- the solve in the sliding
    # speeds (skidding/roller_slides.py), whose residual is at round-off
    assert r.extras["method"] in ("bracketed", "newton_round_off", "slides")
    if r.extras["method"] != "slides":
        assert r.residual_norm <= 4.0 * r.extras["round_off_floor"]
    assert r.residual_norm < 1e-5
    shaft = r.shaft_torque * r.inner_speed
    assert shaft == pytest.approx(r.power_loss["total"], rel=1e-6)


def test_warm_start_from_another_bearing_is_handled():
    """Defects found by this test: a warm start from another bearing's result crashed
    with bare Python errors -- ball from a ball result of a different ball count:
    UnboundLocalError; ball from a roller result: AttributeError; roller from a roller result
    of a different roller count: IndexError; roller from a ball result: TypeError. Now: the
    ball solver starts cold from a result of another ball count (as its code intended), a
    wrong type or size is an InputError naming the guess."""
    from thermobearing.errors import InputError

    ball_qj = _ball_solve("QJ1044", 1000.0, 2000.0, 500.0, 40.0)
    cold = _ball_solve("SKF6304", 1000.0, 2000.0, 500.0, 40.0)
    warm = _ball_solve("SKF6304", 1000.0, 2000.0, 500.0, 40.0, guess=ball_qj)
    assert warm.cage_speed_ratio == pytest.approx(cold.cage_speed_ratio, rel=1e-9)
    roller_nu = _roller_solve("NU214", 1000.0, 2000.0, 40.0)
    with pytest.raises(InputError, match="guess"):
        _ball_solve("SKF6304", 1000.0, 2000.0, 500.0, 40.0, guess=roller_nu)
    with pytest.raises(InputError, match="x0"):
        _roller_solve("D1842926", 1000.0, 2000.0, 40.0, guess=roller_nu)
    with pytest.raises(InputError, match="x0"):
        _roller_solve("NU214", 1000.0, 2000.0, 40.0, guess=ball_qj)


def _probe_points(name, seed, n):
    """The seeded random probe: log-uniform speed over the bearing's range,
    radial / axial load either 0 or log-uniform from 1 N to the range's top (QJ1044: axial of
    either sign), oil 0-140 degC."""
    rng = np.random.default_rng(seed)
    rpm_max, fr_max, fa_max = {"QJ1044": (4000.0, 1e5, 2e5), "SKF6304": (20000.0, 3e4, 1e4)}[name]
    pts = []
    for _ in range(n):
        rpm = math.exp(rng.uniform(math.log(10.0), math.log(rpm_max)))
        fr = rng.choice([0.0, math.exp(rng.uniform(0.0, math.log(fr_max)))])
        fa = rng.choice([0.0, math.exp(rng.uniform(0.0, math.log(fa_max)))]) * (
            rng.choice([-1, 1]) if name == "QJ1044" else 1)
        pts.append((rpm, float(fr), float(fa), rng.uniform(0.0, 140.0)))
    return pts


@pytest.mark.slow
@pytest.mark.parametrize("name, seed, n, allowed", [("QJ1044", 1, 150, 0),
                                                    ("SKF6304", 2, 120, 1)])
def test_random_probe_failure_count(name, seed, n, allowed):
    """Regression guard with the measured numbers (~1 min): every converged point
    of the seeded probe satisfies the invariants, zero-load points raise with residual inf,
    and at most ``allowed`` loaded points fail (measured after the fixes: QJ1044 12 of 150 --
    11 of them below 140 N of load, one 73 kN / -69 kN point stalling at 6e-7; SKF6304 4 of
    120, at 17-84 r/min or 21 kN; before the fixes 13 and 16 loaded points failed and the
    SKF6304 returned CSR = 0 at zero load). With the load distribution's second start
    (loads.py) and a continuation in axial load that retries a failed step cold, then halves
    it: QJ1044 3 (1.9 N at 1511 r/min, -1.13 N axial at 3380 r/min, 73 kN / -69 kN at
    25 r/min); SKF6304 2 (21.4 kN + 37 N at 1231 r/min, 22.7 kN + 58 N at 16.6 r/min). With
    Newton iterations without the stall rule after a failed trust region: QJ1044 2 (the
    first two, final residuals 3.3e-5 and 3.8e-3), SKF6304 1 (22.7 kN + 58 N at 16.6 r/min,
    1.2e-2). With the continuation in speed as the last fallback: QJ1044 0, SKF6304 1 (the
    same point, 2.8x its C0, 3.0e-5); 6 s and 10 s of CPU for the two probes."""
    failures = []
    for rpm, fr, fa, t_c in _probe_points(name, seed, n):
        try:
            r = _ball_solve(name, rpm, fr, fa, t_c)
        except ConvergenceError as err:
            assert not math.isnan(err.residual)
            if fr == 0.0 and fa == 0.0:
                assert err.residual == math.inf
            else:
                failures.append((rpm, fr, fa, t_c, err.residual))
            continue
        check_ball_invariants(r, fr, fa, name)
    assert len(failures) <= allowed, failures
