"""cage_force_balance at a stuck cold state puts the rollers in balance in the sliding speeds
(issue 5; skidding/roller_diagnostics.py, roller_slides.py; paper 000 eqs. 28/31-32, seed
000_3b5ca6eed61dd596.txt).

Defect found: under heavy load in cold oil the rollers' spins bisected to adjacent floats
left tractions that balance nothing, and at the solved cage speed the diagnostic reported a
cage equation of 409 N (drive 522 N) for a catalogue NU 206 at 13 kN, 30000 r/min, ISO VG 68
at 20 degC, whose solution closes it to 1e-14 N.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.skidding.roller import build_model, cage_force_balance, solve_model
from thermobearing.skidding.roller_diagnostics import _balanced_rollers
from thermobearing.skidding.roller_loads import _gapped, _load_distribution
from thermobearing.skidding.roller_residual import evaluate
from thermobearing.skidding.roller_solvers import _roller_speeds

RPM = math.pi / 30.0


@pytest.fixture(scope="module")
def stuck():
    from thermobearing.bearing_config import bearing_from_dict
    from thermobearing.lubricant import load_lubricant

    b = bearing_from_dict({
        "name": "NU206", "kind": "cylindrical", "source": "catalogue", "estimate_missing": True,
        "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
        "roller_diameter": "7.5 mm", "roller_length": "7.5 mm", "n_rollers": 13})
    m = build_model(b, load_lubricant("ISO_VG68"), 293.15)
    omega = 30000.0 * RPM
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = solve_model(m, omega, 13e3)
    return m, omega, r


def test_rollers_are_balanced_at_the_solved_cage_speed(stuck):
    m, omega, r = stuck
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    acc = (0.0, 0.0)
    ld, fb = _load_distribution(m, omega, 13e3, r.cage_speed, None, psi, acc)
    mg = _gapped(m, ld)
    wr, e = _balanced_rollers(mg, omega, r.cage_speed, ld.inner_load, fb, psi, acc)
    q_max = float(np.max(ld.inner_load))
    assert np.max(np.abs(e.roller_eq)) <= 1e-12 * q_max
    np.testing.assert_allclose(wr, r.roller_speed, rtol=1e-13)
    # the spins bisected in the speed form: the loaded rollers' balances stay far off
    wr_s = _roller_speeds(mg, omega, r.cage_speed, ld.inner_load, fb, psi, acc)
    e_s = evaluate(mg, omega, wr_s, r.cage_speed, ld.inner_load, fb, psi, acc)
    assert np.max(np.abs(e_s.roller_eq)) > 1e-3 * q_max


def test_cage_equation_changes_sign_between_floats_around_the_solution(stuck):
    """The cage offset of the root is below one ulp of the cage speed: the cage equation of
    the diagnostic changes sign between two adjacent floats within 2 of the solution's cage
    speed, and the drive of the loaded rollers stays within the range those floats span
    (not the 522 N of the unbalanced rollers)."""
    m, omega, r = stuck
    speeds = [r.cage_speed]
    for _ in range(2):
        speeds.insert(0, float(np.nextafter(speeds[0], -np.inf)))
        speeds.append(float(np.nextafter(speeds[-1], np.inf)))
    balances = [cage_force_balance(m, omega, 13e3, w) for w in speeds]
    res = np.array([cb.residual for cb in balances])
    assert np.all(np.diff(res) < 0.0)  # falls with the cage speed
    assert res[0] > 0.0 > res[-1]
    at = balances[2]
    np.testing.assert_allclose(at.roller_speed, r.roller_speed, rtol=1e-13)
    assert at.n_loaded == int(np.count_nonzero(r.inner_load > 0.0))
    assert abs(at.residual) < abs(res[0]) + abs(res[-1])
    assert at.drag == pytest.approx(balances[0].drag, rel=1e-9)
