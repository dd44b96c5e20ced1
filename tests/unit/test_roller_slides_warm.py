"""The slide-variable roller solve started around known slides and offsets (issue 5;
skidding/roller_slides.py, paper 000 Z + 1 equations, seed 000_3b5ca6eed61dd596.txt).

The root finder (false position with a bisection safeguard, warm brackets) must end at the
same sign change between adjacent floats as a bisection over the whole range, and the
solve at the same state: the pins below are the states of the full-range bisection solve
(before the warm starts), and the energy identity shaft power = dissipation.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.skidding.roller import build_model, solve_model
from thermobearing.skidding.roller_loads import _gapped, _load_distribution
from thermobearing.skidding.roller_slides import (
    _bracketed_roots,
    _roller_slides,
    evaluate_slides,
    solve_slides,
)
from thermobearing.skidding.roller_solvers import _force_scale

RPM = math.pi / 30.0
#: roots over the range the slides take (m/s): below the speeds' ulp, near 0, of either sign
ROOTS = np.array([1e-30, -3e-17, 0.4, 2.5e-16, -1e-38, 4.84, 6.6e-10])


@pytest.fixture(scope="module")
def nu206():
    from thermobearing.bearing_config import bearing_from_dict
    from thermobearing.lubricant import load_lubricant

    b = bearing_from_dict({
        "name": "NU206", "kind": "cylindrical", "source": "catalogue", "estimate_missing": True,
        "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
        "roller_diameter": "7.5 mm", "roller_length": "7.5 mm", "n_rollers": 13})
    return b, load_lubricant("ISO_VG68")


def _linear(y):
    return y - ROOTS  # exact sign: <= 0 up to the root's float, > 0 above


def _stiff(y):
    # saturates within 1e-30 of the root: false position fails, the safeguard bisects
    return np.arctan((y - ROOTS) / 1e-30)


@pytest.mark.parametrize("eq", [_linear, _stiff], ids=["linear", "stiff"])
def test_roots_are_the_sign_change_between_adjacent_floats(eq):
    lo, hi = np.full(ROOTS.size, -10.0), np.full(ROOTS.size, 10.0)
    active = np.ones(ROOTS.size, dtype=bool)
    cold = _bracketed_roots(eq, lo, hi, active)
    # the root's float is the lower end of the pair: the midpoint rounds to one of the two
    assert np.all(np.abs(cold - ROOTS) <= np.spacing(np.abs(ROOTS)))
    below = np.nextafter(np.minimum(cold, ROOTS), -np.inf)
    above = np.nextafter(np.maximum(cold, ROOTS), np.inf)
    assert np.all(eq(below) <= 0.0) and np.all(eq(above) > 0.0)
    # the same pair from brackets around guesses near, far and of the wrong sign
    for guess, width in ((ROOTS * (1.0 + 1e-9), 1e-6), (ROOTS * 1e8, 1e-6),
                         (-ROOTS, 1e-3), (np.full(ROOTS.size, 3.0), 1e-12)):
        np.testing.assert_array_equal(_bracketed_roots(eq, lo, hi, active, guess, width), cold)
    # and with the ends' values given
    np.testing.assert_array_equal(
        _bracketed_roots(eq, lo, hi, active, ends=(eq(lo), eq(hi))), cold)


def test_inactive_entries_do_not_hold_the_others():
    lo, hi = np.full(ROOTS.size, -10.0), np.full(ROOTS.size, 10.0)
    active = np.arange(ROOTS.size) % 2 == 0
    out = _bracketed_roots(_linear, lo, hi, active)
    assert np.all(np.abs(out - ROOTS)[active] <= np.spacing(np.abs(ROOTS[active])))


def _stuck_state(nu206, rpm, load, t_c, cage_offset):
    """Model, loads and the cage offset [rad/s] near a stuck cold state of the NU 206."""
    b, oil = nu206
    m = build_model(b, oil, t_c + 273.15)
    omega = rpm * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    wc_th = m.theoretical_cage_speed_ratio * omega
    delta = cage_offset * omega
    ld, fb = _load_distribution(m, omega, load, wc_th + delta, None, psi, (0.0, 0.0))
    return _gapped(m, ld), omega, ld, fb, psi, delta


def test_warm_roller_slides_equal_the_cold_ones(nu206):
    """Catalogue NU 206, 13 kN, 30000 r/min, ISO VG 68 at 20 degC, cage 8.8e-18 of the inner
    speed below epicyclic (the slide solve's root): the loaded rollers slide by 1e-17 to
    7e-10 m/s. Started around the slides of a nearby offset (1e-9 and 1e-3 away) the
    rollers end where the cold bisection over the whole range ends."""
    mg, omega, ld, fb, psi, delta = _stuck_state(nu206, 30000.0, 13e3, 20.0, -8.78825e-18)
    acc = (0.0, 0.0)
    cold_i, cold_o = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc)
    loaded = ld.inner_load > 0.0
    assert np.all(np.abs(cold_i[loaded]) < 1e-8)  # stuck: far below the speeds' ulp x 1e6
    for rel, width in ((1e-9, 4e-9), (1e-3, 4e-3)):
        near_i, _ = _roller_slides(mg, omega, delta * (1.0 + rel), ld.inner_load, fb, psi,
                                   acc)
        warm_i, warm_o = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc,
                                        near_i, width)
        np.testing.assert_allclose(warm_i, cold_i, rtol=1e-13, atol=0.0)
        np.testing.assert_allclose(warm_o, cold_o, rtol=1e-13, atol=0.0)
    e, _ = evaluate_slides(mg, omega, warm_i, delta, ld.inner_load, fb, psi, acc, warm_o)
    assert np.max(np.abs(e.roller_eq)) <= 1e-12 * float(np.max(ld.inner_load))


def test_slide_solve_from_a_start_equals_the_whole_range(nu206):
    """solve_slides from a start's cage speed (a bracket 1e-3 wide in asinh around its
    offset; one within 8 ulps of the epicyclic speed: a bracket as wide as those ulps)
    ends at the state of the bracket over the whole cage-speed range."""
    b, oil = nu206
    m = build_model(b, oil, 333.15)
    omega = 2000.0 * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    acc = (0.0, 0.0)
    wc_th = m.theoretical_cage_speed_ratio * omega

    def loads(wc, ring, wr=None):
        return _load_distribution(m, omega, 13e3, wc, wr, psi, acc, ring)

    ld0, _ = loads(wc_th, None)
    scale = lambda q: _force_scale(m, omega, q)  # noqa: E731
    full = solve_slides(m, omega, loads, psi, acc, ld0, None, scale)
    assert full is not None and full[2] <= 1e-12
    for wc0 in (wc_th, wc_th * (1.0 + 1e-12), float(full[0][z]) * (1.0 - 1e-15)):
        out = solve_slides(m, omega, loads, psi, acc, ld0, wc0, scale)
        assert out is not None and out[2] <= 1e-12
        assert out[0][z] == pytest.approx(full[0][z], rel=1e-15)
        np.testing.assert_allclose(out[0][:z], full[0][:z], rtol=1e-14)
        # the slides to 1e-9: a balance that is flat at round-off near its root changes
        # sign more than once among adjacent floats (measured: 1.1e-12 apart at 2.6e-8 m/s)
        np.testing.assert_allclose(out[1].v_i, full[1].v_i, rtol=1e-9, atol=1e-30)
        assert np.max(np.abs(out[1].roller_eq)) <= 1e-12 * float(np.max(ld0.inner_load))


#: (r/min, N, degC): cage speed ratio, roller 0 and roller 3 [rad/s], inner slide of roller
#: 0 [m/s] and shaft power [W] of the solve before the warm starts (full-range bisection of
#: every roller, Brent in asinh of the cage offset), catalogue NU 206 with ISO VG 68, isothermal
#: eq. 35 (thermal_reduction="none"; the solver's default is Gupta's since 2026-11-24)
REFERENCE = {
    (2000.0, 13e3, 60.0): (0.41847826086993406, 625.2072916161785, 30.804970762324167,
                           8.715415357271723e-15, 17.808071537567887),
    (500.0, 6e3, 20.0): (0.41847826086961665, 156.30182290413057, 2.592998659105265,
                         -1.7373491650783107e-16, 6.2121050150120745),
}


@pytest.mark.parametrize("rpm, load, t_c", sorted(REFERENCE))
def test_cold_heavy_points_keep_their_state(nu206, rpm, load, t_c):
    """The heavy cold points of benchmarks/bm_roller_cold.py --quick that the slide solve
    takes: the same state as before the warm starts, shaft power = dissipation to 1e-6."""
    b, oil = nu206
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = solve_model(build_model(b, oil, t_c + 273.15, thermal_reduction="none"),
                        rpm * RPM, load)
    csr, w0, w3, v0, power = REFERENCE[(rpm, load, t_c)]
    assert r.cage_speed_ratio == pytest.approx(csr, rel=1e-13)
    assert r.roller_speed[0] == pytest.approx(w0, rel=1e-13)
    assert r.roller_speed[3] == pytest.approx(w3, rel=1e-13)
    shaft = r.shaft_torque * r.inner_speed
    assert shaft == pytest.approx(power, rel=1e-9)
    assert r.power_loss["total"] == pytest.approx(shaft, rel=1e-6)
    if r.extras["method"] == "slides":
        assert r.inner_sliding_speed[0] == pytest.approx(v0, rel=1e-9)
        assert r.residual_norm <= 1e-9
