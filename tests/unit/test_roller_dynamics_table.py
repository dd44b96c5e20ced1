"""Tests of thermobearing.skidding.roller_dynamics_table (paper 000 traction tabulated for
the paper 003 coupled roller dynamics)."""

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model as race_model
from thermobearing.skidding.roller_dynamics_table import (
    build_traction_table,
    table_eval,
)
from thermobearing.skidding.roller_residual import evaluate

SPEED = 30000 * math.pi / 30
CAGE = 1362.8           # quasi-static cage speed of the paper 003 base case [rad/s]
BODY = 6.5              # unbalance orbital force at 0.11 g [N] (constant here)


@pytest.fixture(scope="module")
def setup():
    b = load_bearing("CRB_50x75x16")
    rm = race_model(b, load_lubricant("MIL_PRF_23699"), 353.15)
    tab = build_traction_table(rm, SPEED, lambda wc: BODY, (6500.0, 17600.0), 777.3, CAGE)
    return rm, tab


def _direct(rm, w, n, wc):
    e = evaluate(rm, SPEED, w, wc, n, np.full(w.size, BODY), np.zeros(w.size), (0.0, 0.0))
    return np.stack([e.roller_eq + e.friction, e.pocket, e.q_o, e.outer.shear_force], -1)


def test_table_nodes_reproduce_evaluate(setup):
    # on a grid node (spin, load and cage layer) the interpolation returns the tabulated
    # evaluate() value itself
    rm, tab = setup
    w = tab.spin0 + tab.spin_step * np.array([5.0, 40.0, 150.0])
    n = tab.loads[[0, 3, 10]]
    got = tab(w, n, float(tab.cage[1]))
    ref = _direct(rm, w, n, float(tab.cage[1]))
    assert np.allclose(got, ref, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("thermal, free_bound", [("none", 1e-3), ("gupta_1992", 1e-2)])
def test_table_interpolation_error(setup, thermal, free_bound):
    # random states inside the grid against direct evaluate(): unloaded rollers (N_i = 0,
    # most of the orbit) to < 1e-3 N with the isothermal eq. 35 (measured 1.4e-6 N; spin
    # stiffness ~1.6e-4 N s/rad, i.e. < 6 rad/s of spin), to < 1e-2 N with the default Gupta
    # inlet heating (measured 6.2e-3 N at 15779 rad/s: phi_T ~ 1/(1 + c S^0.83) has a cusp
    # at S = 0 of the outer contact, which the cubic over the 50 rad/s spin step rounds
    # off; 6.2e-3 N is ~40 rad/s of spin at 1.5e-4 N s/rad, inside one spin step);
    # loaded rollers to < 0.6 N of a ~110 N range (measured 0.35 N at the kinks of the
    # film/traction regime switches in N_i, either setting; loaded spin stiffness
    # 0.023 N s/rad: < 25 rad/s, 0.08 m/s of slip); Q_o = N_i + body + centrifugal exactly
    rm, tab = setup
    if thermal != rm.thermal_reduction:
        rm = race_model(load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699"), 353.15,
                        thermal_reduction=thermal)
        tab = build_traction_table(rm, SPEED, lambda wc: BODY, (6500.0, 17600.0), 777.3, CAGE)
    rng = np.random.default_rng(3)
    w = rng.uniform(6600.0, 17500.0, 400)
    wc = CAGE * 1.013
    free = _direct(rm, w, np.zeros(w.size), wc)
    assert np.max(np.abs(tab(w, 0.0, wc) - free)[:, :2]) < free_bound
    n = rng.uniform(0.0, 777.3, w.size)
    ref = _direct(rm, w, n, wc)
    err = np.abs(tab(w, n, wc) - ref)
    assert np.max(err[:, :2]) < 0.6
    assert np.max(err[:, 2]) < 1e-6 * np.max(ref[:, 2])


def test_table_reports_out_of_grid(setup):
    _, tab = setup
    args = (tab.spin0, tab.spin_step, tab.loads, tab.cage, tab.values)
    assert table_eval(*args, 12000.0, 100.0, CAGE)[3] == 0
    assert table_eval(*args, 100.0, 100.0, CAGE)[3] == 1          # spin below the grid
    assert table_eval(*args, 12000.0, 2000.0, CAGE)[3] == 2       # load above N_max
    assert table_eval(*args, 12000.0, 100.0, 2.0 * CAGE)[3] == 3  # cage speed
    with pytest.raises(ValueError):
        tab(np.array([100.0]), 0.0, CAGE)


def test_table_refuses_clearance_film_model(setup):
    import dataclasses

    from thermobearing.errors import InputError

    rm, _ = setup
    with pytest.raises(InputError, match="clearance_film"):
        build_traction_table(dataclasses.replace(rm, clearance_film=True), SPEED,
                             lambda wc: BODY, (6500.0, 17600.0), 777.3, CAGE)


def test_table_is_c1_in_the_cage_speed(setup):
    # the coupled model's refresh takes forward-difference slopes in omega_c (step 1e-4
    # omega_c ~ 0.14 rad/s): the interpolant must be continuous with a continuous slope
    # across layers and layer midpoints (the former nearest-layer quadratic jumped by up to
    # 0.11 N at midpoints, a 10x spurious slope; module notes)
    _, tab = setup
    rng = np.random.default_rng(5)
    w = rng.uniform(7000.0, 17000.0, 100)
    n = rng.uniform(0.0, 777.3, 100)
    dc = float(tab.cage[1] - tab.cage[0])
    eps = 1e-3
    for x in (1.5, 2.0, 2.5):
        wc = float(tab.cage[0]) + x * dc
        lo, mid, hi = (tab(w, n, wc + d) for d in (-eps, 0.0, eps))
        assert np.max(np.abs(hi - lo)[:, :2]) < 1e-3             # no jump (slope ~0.08 N s/rad)
        left, right = (mid - lo) / eps, (hi - mid) / eps
        assert np.max(np.abs(right - left)[:, :2]) < 1e-3         # slope continuous
    # Q_o's centrifugal part ~ omega_c^2 is reproduced exactly (Catmull-Rom holds quadratics)
    wc = float(tab.cage[0]) + 1.37 * dc
    rm = setup[0]
    ref = _direct(rm, w[:5], n[:5], wc)
    assert np.allclose(tab(w[:5], n[:5], wc)[:, 2], ref[:, 2], rtol=1e-9)
