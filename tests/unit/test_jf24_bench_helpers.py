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


def test_bm8_anchor_csr_reads_the_ball_pass_line():
    """BM-8's anchor estimate: the highest envelope-spectrum line in the ball-pass window,
    over Z and the shaft frequency, to the FFT bin; a stronger line outside the window (the
    shaft's fifth harmonic, 150 Hz beyond its 25-109 Hz) is not taken."""
    bm8 = _load("bm8_vibration")
    fs, n = 1000.0, 2000  # 0.5 Hz bins
    shaft, z, csr = 30.0, 7, 0.4
    t = np.arange(n) / fs
    f_bp = z * 0.37 * shaft  # the cage 7.5 % slower than pure rolling: 77.7 Hz
    env = np.cos(2 * np.pi * f_bp * t) + 3.0 * np.cos(2 * np.pi * 5 * shaft * t)
    spec = np.abs(np.fft.rfft(env * np.hanning(n)))
    got = bm8.anchor_csr(spec, n, fs, shaft, z, csr)
    assert abs(got * z * shaft - f_bp) <= 0.5 * fs / n  # within half a bin
    assert abs(got / 0.37 - 1.0) < 0.25 / f_bp + 1e-12
    assert np.isnan(bm8.anchor_csr(spec, n, fs, shaft, z, csr, search=(10.0, 10.001)))


def test_bm5_csr_difference_over_the_points_both_solved():
    """BM-5's same-state check: the largest relative cage-speed difference of an anchor's
    solution from newton_block's, over the points where both converged only."""
    bm5 = _load("bm5_skidding")
    res = [((300.0, 4e4), {"newton": (True, [1.0], 1e-12, 10.0),
                           "root_hybr": (True, [2.0], 1e-9, 10.0 * (1 + 2e-8))}),
           ((300.0, 200.0), {"newton": (True, [1.0], 1e-12, 5.0),
                             "root_hybr": (False, [9.0], 1e-3, 7.0)}),  # failed: left out
           ((3000.0, 200.0), {"newton": (False, [1.0], 1e-3, float("nan")),
                              "root_hybr": (True, [2.0], 1e-9, 50.0)})]  # newton failed
    assert bm5.csr_difference(res, "root_hybr") == pytest.approx(2e-8, rel=1e-6)
    assert np.isnan(bm5.csr_difference(res[1:], "root_hybr"))


def test_bench_table_shows_the_cpu_time_its_ratio_is_formed_from():
    """BM-E2E / BM-7 records carry wall time in time_s and CPU time in cpu_s, their ratios
    being of CPU times: the table shows the CPU time (it showed the wall time beside them)."""
    from thermobearing.commands.bench import record_line

    line = record_line({"case": "qj1044_rig", "method": "ours", "setting": "s",
                        "time_s": 0.2751, "cpu_s": 0.1696, "max_error_K": 8.64e-07,
                        "ratio_vs_anchor": 24.66})
    assert line.endswith("cpu 0.1696 s  error 8.64e-07  ratio 24.7")
    assert "0.2751" not in line
    plain = record_line({"case": "c", "method": "m", "setting": "s", "time_s": 0.0109,
                         "error": 7.37e-05, "ratio_vs_anchor": 4.08})
    assert plain.endswith("time 0.0109 s  error 7.37e-05  ratio 4.08")


def test_rib_benchmark_compare_matches_nodes_by_operating_state_and_temperature():
    """bm_rib_friction's comparison of two paths (and of a path against the reference):
    node heat and slide changes over the nodes both ran (same speed, load and temperature
    node), failed nodes left out, the booked heat per step end, and the CPU ratios."""
    rib = _load("bm_rib_friction")

    def node(rpm, load, temp, heat, slide, cpu=1.0, failed=False):
        return {"speed_rpm": rpm, "radial_load": load, "temperature": temp, "heat": heat,
                "slide": slide, "cpu_s": cpu, "failed": failed}

    ref = {"cpu_s": 40.0, "booked_rib_W": [2.0, 4.0], "final_rollers_degC": 90.0,
           "nodes": [node(20000.0, 3000.0, 355.0, 10.0, 1.0, 10.0),
                     node(5000.0, 2000.0, 350.0, 4.0, 0.5, 10.0),
                     node(5000.0, 2000.0, 345.0, 3.0, 0.4, 10.0, failed=True)]}
    path = {"cpu_s": 10.0, "booked_rib_W": [2.02, 3.96], "final_rollers_degC": 90.01,
            "nodes": [node(20000.0, 3000.0, 355.0, 10.1, 0.99, 2.0),
                      node(5000.0, 2000.0, 350.0, 4.0, 0.5, 3.0),
                      node(5000.0, 2000.0, 345.0, 9.0, 9.0, 5.0),  # the reference failed
                      node(10000.0, 6000.0, 360.0, 7.0, 0.7, 5.0)]}  # not in the reference
    c = rib.compare(ref, path)
    assert c["common_nodes"] == 2
    assert c["max_node_heat_change"] == pytest.approx(0.01, rel=1e-9)
    assert c["max_node_slide_change"] == pytest.approx(0.01, rel=1e-9)
    assert c["max_booked_rib_change"] == pytest.approx(0.01, rel=1e-9)
    assert c["ratio_scene_cpu"] == pytest.approx(4.0)
    assert c["ratio_dynamics_cpu"] == pytest.approx(30.0 / 15.0)
    assert c["final_rollers_change_K"] == pytest.approx(0.01, abs=1e-12)
