"""Cold starts of the roller skidding solver at heavy load (skidding/roller.py,
roller_solvers.py): states that took the bracketed fallback (6-12 s of CPU each) now converge
by Newton accepted at the round-off floor, or by the bracketed solve started around the best
Newton iterate, to the same state.

The reference values are the full-bracket solutions (Brent over the whole cage-speed range,
rollers bisected from their full range) of the solver before this change, measured with
benchmarks/bm_roller_cold.py (NU214 with the paper 000 oil; a catalogue NU 206 with
ISO VG 68). The references are isothermal solves (eq. 35 without inlet heating): the NU 206
solves name ``thermal_reduction="none"`` (the solver's default is Gupta's reduction since
2026-11-24; the paper 000 oil of the NU214 has beta = 0, phi_T = 1 either way).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.skidding.roller import build_model, evaluate, solve_roller
from thermobearing.skidding.roller_loads import _load_distribution
from thermobearing.skidding.roller_solvers import _cage_bracket, _nested, _roller_speeds

RPM = math.pi / 30.0
#: the two ways a state below the reach of tol is found (Newton accepted at the per-equation
#: round-off floor, or the bracketed solve); which one a point takes depends on where the
#: stalled Newton iterate lands, i.e. on round-off (the compiled kernels round differently
#: on different CPUs), while the state is the same to ~1e-14: the tests pin the state
#: A round-off state whose shaft power and dissipation differ by more than 1e-6 is solved
#: again in the sliding speeds ("slides", skidding/roller_slides.py): the same speeds to
#: ~1e-12, the tractions that balance the equations.
AT_ROUND_OFF = ("newton_round_off", "bracketed", "slides")
#: full-bracket state (cage speed, roller 0, roller 5 [rad/s]) of the catalogue NU 206 at
#: 6 kN, 500 r/min, 20 degC, ISO VG 68 (benchmarks/bm_roller_cold.py, before this change)
REF_NU206_6KN = (21.91147050058534, 156.30182290412205, 2.5929986591055165)


@pytest.fixture(scope="module")
def nu206():
    from thermobearing.bearing_config import bearing_from_dict

    return bearing_from_dict({
        "name": "NU206", "kind": "cylindrical", "source": "catalogue", "estimate_missing": True,
        "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
        "roller_diameter": "7.5 mm", "roller_length": "7.5 mm", "n_rollers": 13})


@pytest.fixture(scope="module")
def vg68():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("ISO_VG68")


def _every_equation_within_its_floor(r):
    """The acceptance of a state below the reach of tol, re-checked from the result: within
    4 round-off floors with shaft power = dissipation to 1e-6, or the slide-variable solve
    within tol."""
    assert np.all(np.isfinite(r.residual))
    shaft = r.shaft_torque * r.inner_speed
    assert r.power_loss["total"] == pytest.approx(shaft, rel=1e-6)
    if r.extras["method"] == "slides":
        assert r.residual_norm <= 1e-9
    else:
        assert r.residual_norm <= 4.0 * r.extras["round_off_floor"]


def test_heavy_nu214_converges_by_newton_at_the_round_off_floor(nu214, oil):
    """NU214, 45 kN (about 0.3 C), 8000 r/min: Newton from pure rolling stalls at norm
    2.1e-9 (tol 1e-9) because one ulp of the cage speed changes the cage equation by ~0.02 N
    (round-off floor 6.9e-9 of the 11 kN roller load); the bracketed fallback took 5.7 s to
    find the same cage speed to the last bit. Now the Newton iterate is accepted."""
    r = solve_roller(nu214, oil, 8000.0 * RPM, 45000.0, 0.0, 313.15)
    assert r.extras["method"] in AT_ROUND_OFF
    _every_equation_within_its_floor(r)
    assert r.cage_speed == pytest.approx(363.0284843715619, rel=1e-12)
    assert r.roller_speed[0] == pytest.approx(3085.74211751333, rel=1e-12)
    assert r.roller_speed[5] == pytest.approx(1037.5176609347525, rel=1e-12)


def test_hot_nu206_converges_by_newton(nu206, vg68):
    """Catalogue NU 206, 13 kN, 8000 r/min, oil at 140 degC: formerly bracketed (4.8 s).
    Since eq. 35 takes the mean speed (2026-11-23) Newton ends below the tolerance itself or
    at the round-off floor (which one is round-off); the state is the bracketed one."""
    r = solve_roller(nu206, vg68, 8000.0 * RPM, 13000.0, 0.0, 413.15,
                     thermal_reduction="none")
    assert r.extras["method"] in ("newton", "newton_round_off")
    assert r.residual_norm <= max(1e-9, 4.0 * r.extras.get("round_off_floor", 0.0))
    assert r.cage_speed == pytest.approx(350.5835280083196, rel=1e-12)
    assert r.roller_speed[0] == pytest.approx(2500.8291664445233, rel=1e-12)
    assert r.roller_speed[5] == pytest.approx(385.2835366662159, rel=1e-12)


def test_newton_iterate_with_wrong_unloaded_rollers_is_not_accepted(nu206, vg68):
    """Catalogue NU 206, 13 kN, 500 r/min, 20 degC (formerly bracketed, 9.3 s): the stalled
    Newton iterate has a norm (1.1e-3) inside the round-off floor of the stiff loaded rollers
    (0.11), but its unloaded rollers turn at outer pure rolling (155 rad/s) where their
    moment balance is off by 0.037 N; in the cold oil they nearly stand (2.59 rad/s). The
    per-equation rule rejects that iterate; its cage speed with the rollers bisected there
    passes and is the reference state (an acceptance on the norm alone returned the
    unloaded rollers 60x too fast). That state had the speeds right but not the forces:
    shaft power 434.6 W against a dissipation of 8.2 W (the two most loaded rollers roll at
    one ulp of slide, where the cold film carries ~100 N); it is refused and the
    slide-variable solve gives the same speeds (cage to 1e-15, roller 5 to 7e-13) with
    6.24 W = 6.24 W (to 1e-15) at residual 4e-18."""
    r = solve_roller(nu206, vg68, 500.0 * RPM, 13000.0, 0.0, 293.15,
                     thermal_reduction="none")
    assert r.extras["method"] in AT_ROUND_OFF
    _every_equation_within_its_floor(r)
    assert r.cage_speed == pytest.approx(21.91147050058097, rel=1e-12)
    assert r.roller_speed[0] == pytest.approx(156.30182290414444, rel=1e-12)
    assert r.roller_speed[5] == pytest.approx(2.5929986591047944, rel=1e-12)


@pytest.mark.slow
def test_bracketed_solve_started_around_newton_reaches_the_reference(nu206, vg68):
    """Catalogue NU 206, 6 kN, 500 r/min, 20 degC: the Newton iterate is ~1e-13 of the cage
    speed off the root (1000 ulps), beyond the round-off floor; the bracketed solve started
    around it (1.3 s instead of 7.4 s) ends at the full-bracket state. Its shaft power and
    dissipation differed by 0.7 % (residual 2.6e-5): it is refused and solved in the sliding
    speeds (residual 8e-18, the same speeds to 5e-13)."""
    r = solve_roller(nu206, vg68, 500.0 * RPM, 6000.0, 0.0, 293.15,
                     thermal_reduction="none")
    assert r.extras["method"] in AT_ROUND_OFF
    _every_equation_within_its_floor(r)
    assert r.cage_speed == pytest.approx(REF_NU206_6KN[0], rel=1e-12)
    assert r.roller_speed[0] == pytest.approx(REF_NU206_6KN[1], rel=1e-12)
    assert r.roller_speed[5] == pytest.approx(REF_NU206_6KN[2], rel=1e-12)


def test_roller_bisection_from_a_guess_matches_the_full_bracket(nu214, oil):
    """_roller_speeds started around a guess (the previous cage iterate's spins) ends at the
    root of the full-range bisection, within its final bracket width (top speed x 2^-56)."""
    m = build_model(nu214, oil, 313.15)
    omega = 5000.0 * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    wc = 0.95 * m.theoretical_cage_speed_ratio * omega
    ld, fb = _load_distribution(m, omega, 2000.0, wc, None, psi, (0.0, 0.0))
    full = _roller_speeds(m, omega, wc, ld.inner_load, fb, psi, (0.0, 0.0))
    for guess in (full * (1.0 + 1e-12), full * 0.5, np.full(z, 3.0 * full.max())):
        warm = _roller_speeds(m, omega, wc, ld.inner_load, fb, psi, (0.0, 0.0), guess)
        top = 2.0 * (m.pitch_diameter - m.roller_diameter) / m.roller_diameter * omega
        np.testing.assert_allclose(warm, full, rtol=0.0, atol=4.0 * top * 2.0**-56)
    e = evaluate(m, omega, full, wc, ld.inner_load, fb, psi, (0.0, 0.0))
    assert np.all(np.isfinite(e.roller_eq))



@pytest.mark.parametrize("offset", [2e-13, -2e-13, 1.5e-12, -3e-11, 0.2])
def test_cage_bracket_starts_at_the_iterate(offset):
    """_cage_bracket on a falling function whose root is ``offset`` (relative) from the start:
    the start is one end and the bracket 1e-12 of it wide when the root is that near,
    16 times wider per round beyond; a root out of that reach gets the full range."""
    wc0, lo_c, hi_c = 20.0, 1e-5, 40.0
    root = wc0 * (1.0 + offset)
    calls = []

    def cage(w):
        calls.append(w)
        return root - w

    a, b, f_a, f_b = _cage_bracket(cage, wc0, lo_c, hi_c)
    assert f_a > 0.0 > f_b and a < root < b
    assert (f_a, f_b) == (cage(a), cage(b))
    if abs(offset) <= 1e-12:
        assert wc0 in (a, b)
        assert b - a == pytest.approx(1e-12 * wc0, rel=1e-3)
        assert len(calls) == 2 + 2
    elif abs(offset) < 1e-6:
        assert b - a < 32.0 * abs(root - wc0)
    else:
        assert (a, b) == (lo_c, hi_c)
    assert _cage_bracket(cage, None, lo_c, hi_c)[:2] == (lo_c, hi_c)


@pytest.mark.slow
@pytest.mark.parametrize("rpm, load", [(8000.0, 45000.0), (30000.0, 45000.0)])
def test_round_off_state_matches_the_full_bracket_solve(nu214, oil, rpm, load):
    """The Newton round-off state against the bracketed solve over the whole cage-speed
    range, computed here (~6 s each): CSR and roller speeds to 1e-8 relative (measured:
    <= 2e-15)."""
    r = solve_roller(nu214, oil, rpm * RPM, load, 0.0, 313.15)
    assert r.extras["method"] in AT_ROUND_OFF
    m = build_model(nu214, oil, 313.15)
    omega = rpm * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z

    def loads(wc, ring, wr=None):
        return _load_distribution(m, omega, load, wc, wr, psi, (0.0, 0.0), ring)

    ld0, _ = loads(m.theoretical_cage_speed_ratio * omega, None)
    x, _e, _norm, _it, ok, _ld, _floor = _nested(m, omega, loads, psi, (0.0, 0.0), 1e-9, 60,
                                                 ld0)
    assert ok
    assert r.cage_speed == pytest.approx(x[z], rel=1e-8)
    np.testing.assert_allclose(r.roller_speed, x[:z], rtol=1e-8)
