"""Smoke test of the BM-7 / BM-E2E helpers (benchmarks/_protocol.py, benchmarks/bm_e2e.py).

One 3-min load step of the default scene with race-control kinematics (cheap): the L0
driver, the L1 run reduced to the step-end grid, and the solve_ivp driver of BM-E2E on
the same chain. No wall-clock assertions: only that the drivers produce comparable,
finite results, and that two integrators of the same chain agree.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"
sys.path.insert(0, str(BENCH))

import _protocol as P  # noqa: E402
import bm_e2e  # noqa: E402


@pytest.fixture(scope="module")
def scene():
    one_step = P.default_scene(stride=22)  # the first step only: 0 kN axial, 3 min
    sc = P.with_models(one_step, kinematics="race_control")
    return P.with_solver(sc, chunk=90.0)


def test_l0_and_l1_on_one_grid(scene):
    l1 = P.run_l1("L1 race_control", scene)
    l0 = P.run_l0("L0 skf", scene, "skf_four_term")
    assert l1.nodes == l0.nodes and len(l1.nodes) == 8
    assert l1.temperatures.shape == l0.temperatures.shape == (1, 8)
    assert l1.losses.shape == l0.losses.shape == (1, 2)
    # heat flows in: every node warms above the 35 degC start within 3 min
    assert np.all(l1.temperatures > 308.15) and np.all(l0.temperatures > 308.15)
    dT, dP = P.errors(l0, l1)
    assert np.isfinite(dT) and np.isfinite(dP) and dT > 0 and dP > 0
    assert P.errors(l1, l1) == (0.0, 0.0)


def test_scipy_driver_matches_ours(scene):
    grid = bm_e2e.chunk_grid(scene)
    np.testing.assert_allclose(grid, [90.0, 180.0])
    _, T_ours, _ = bm_e2e.run_ours(scene)
    _, T_lsoda, st = bm_e2e.run_scipy(scene, "LSODA", 1e-6, 1e-4)
    assert T_ours.shape == T_lsoda.shape == (2, 8)
    assert st["nfev"] > 0
    # same chain, two integrators (ours: affine heat per 90-s chunk at rtol 1e-4): agree
    # well inside the 1-K budget of BM-7 (measured ~1e-3 K when written)
    assert np.max(np.abs(T_ours - T_lsoda)) < 0.05
