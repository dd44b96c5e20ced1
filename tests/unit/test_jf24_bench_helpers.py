"""Helpers of the benchmark scripts that compute something (not their timings).

BM-1 / BM-2's restarted ``solve_ivp`` driver: one call per load step gives both the grid
output and the end state the next step restarts from (it solved every step but the last a
second time for its end state, which doubled the anchors' times).
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def _load(name: str):
    if str(BENCH) not in sys.path:
        sys.path.insert(0, str(BENCH))
    spec = importlib.util.spec_from_file_location(name, BENCH / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def bm1():
    return _load("bm1_work_precision")


def test_segment_eval_ends_at_the_segment_end(bm1):
    grid = np.linspace(0.0, 60.0, 7)  # every 10 s
    te, n_out = bm1.segment_eval(grid, 0.0, 30.0, last=False)
    np.testing.assert_array_equal(te, [0.0, 10.0, 20.0, 30.0])
    assert n_out == 3  # 30 s is the next segment's first output point
    te, n_out = bm1.segment_eval(grid, 30.0, 60.0, last=True)
    np.testing.assert_array_equal(te, [30.0, 40.0, 50.0, 60.0])
    assert n_out == 4  # the last segment's end is output


def test_segment_eval_end_off_the_grid(bm1):
    grid = np.linspace(0.0, 60.0, 7)
    te, n_out = bm1.segment_eval(grid, 0.0, 25.0, last=False)
    np.testing.assert_array_equal(te, [0.0, 10.0, 20.0, 25.0])
    assert n_out == 3
    te, n_out = bm1.segment_eval(grid, 21.0, 29.0, last=False)  # no grid point inside
    np.testing.assert_array_equal(te, [29.0])
    assert n_out == 0


def test_restarted_driver_matches_its_plain_solves(bm1):
    """The driver's output on the grid and its restart states are those of plain per-step
    solve_ivp calls without t_eval (same steps: t_eval only samples the dense output), and
    every grid point is output once."""
    net, edges, heat, T0, grid = bm1.make_case(4)
    calls = [0]

    class Counted:  # the driver's heat, counting its calls
        def at_segment(self, k):
            q, jq = heat.at_segment(k)

            def counted(t, T):
                calls[0] += 1
                return q(t, T)

            return counted, jq

    Y, nfev = bm1.run_scipy((net, edges, Counted(), T0, grid), "LSODA", 1e-4, 1e-2)
    assert Y.shape == (grid.size, T0.size)
    assert nfev > 0
    plain_nfev = 0
    sys_ = bm1.assemble(net)
    K = sys_.K if sys_.dense else sys_.K.toarray()
    invC = 1.0 / sys_.C
    y = T0.copy()
    for k in range(len(edges) - 1):
        q, jq = heat.at_segment(k)

        def fun(t, T, q=q):
            return (sys_.s - K @ T + q(t, T)) * invC

        def jac(t, T, jq=jq):
            J = -K.copy()
            J[np.diag_indices_from(J)] += jq(t, T)
            return J * invC[:, None]

        r = solve_ivp(fun, (edges[k], edges[k + 1]), y, method="LSODA", rtol=1e-4,
                      atol=1e-2, jac=jac)
        y = r.y[:, -1]
        plain_nfev += r.nfev
        i = int(np.argmin(np.abs(grid - edges[k + 1])))
        if k < len(edges) - 2:
            # the driver's output at the next step's start is its restart state
            np.testing.assert_allclose(Y[i], y, rtol=0.0, atol=1e-9)
        else:
            np.testing.assert_allclose(Y[-1], y, rtol=0.0, atol=1e-9)
    # one solve per load step: the heat is called as often as by the plain solves
    assert nfev == plain_nfev
    assert calls[0] == plain_nfev


def test_time_at_error_interpolates_log_log_and_never_extrapolates(bm1):
    """BM-1 / BM-2's equal-error time: log-log interpolation on a solver's (error, time)
    points; outside the measured errors it is NaN (no extrapolation)."""
    curve = [{"max_error_K": 1e-2, "time_s": 1.0}, {"max_error_K": 1e-4, "time_s": 4.0},
             {"max_error_K": 0.0, "time_s": 9.0}]  # an error of 0 is left out (no log)
    assert bm1.time_at_error(curve, 1e-3) == pytest.approx(2.0, rel=1e-12)
    assert bm1.time_at_error(curve, 1e-2) == pytest.approx(1.0, rel=1e-12)
    assert np.isnan(bm1.time_at_error(curve, 1e-5))
    assert np.isnan(bm1.time_at_error(curve, 1e-1))
    assert np.isnan(bm1.time_at_error([], 1e-3))
