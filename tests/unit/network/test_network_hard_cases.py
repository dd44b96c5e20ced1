"""BM-3 hard cases run as tests (benchmarks/bm3_hard_cases.py, quick settings).

Ours (backward Euler and exprb43 at any step, TR-BDF2 under error control) must pass every
check;
explicit Euler and Crank-Nicolson must fail the same checks, so that they are seen to bite.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

BM3 = Path(__file__).resolve().parents[3] / "benchmarks" / "bm3_hard_cases.py"


@pytest.fixture(scope="module")
def bm3():
    spec = importlib.util.spec_from_file_location("bm3_hard_cases", BM3)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _by(records, method, setting=None):
    return [r for r in records if r["method"] == method
            and (setting is None or r["setting"] == setting)]


def test_tiny_and_zero_capacity_nodes(bm3):
    recs = bm3.case_tiny_capacity(quick=True)
    assert all(r["ok"] for r in _by(recs, "backward_euler"))
    assert all(not r["ok"] for r in _by(recs, "explicit_euler"))  # refused or blew up
    assert all(r["violation_K"] > 1.0 for r in _by(recs, "crank_nicolson"))  # rings
    # TR-BDF2 at a fixed 60 s: accurate at the end, bounded overshoot on the way (R(z) < 0)
    for r in _by(recs, "tr_bdf2"):
        assert r["max_error_K"] < 1e-3 and r["violation_K"] < 0.21 * 15.0
    # exprb43 is the exact flow on this linear network: within bounds, error ~ round-off
    for r in _by(recs, "exprb43"):
        assert r["ok"] and r["max_error_K"] < 1e-6


def test_step_size_sweep_maximum_principle(bm3):
    recs = bm3.case_dt_sweep(quick=True)
    assert all(r["ok"] for r in _by(recs, "backward_euler"))
    assert all(r["ok"] for r in _by(recs, "exprb43"))
    assert not any(r["ok"] for r in _by(recs, "crank_nicolson"))
    assert not any(r["ok"] for r in _by(recs, "explicit_euler"))


def test_load_drop_to_zero(bm3):
    recs = bm3.case_load_drop()
    assert _by(recs, "backward_euler")[0]["ok"]
    assert _by(recs, "tr_bdf2", "adaptive")[0]["ok"]
    assert all(r["ok"] for r in _by(recs, "exprb43"))
    assert not _by(recs, "crank_nicolson")[0]["ok"]


def test_steady_limit(bm3):
    recs = bm3.case_steady_limit()
    assert _by(recs, "backward_euler")[0]["ok"]
    assert _by(recs, "tr_bdf2")[0]["ok"]
    assert _by(recs, "exprb43")[0]["ok"]
    assert not _by(recs, "crank_nicolson")[0]["ok"]


@pytest.mark.slow
def test_full_bm3_with_one_second_steps(bm3):
    recs = bm3.case_tiny_capacity(quick=False) + bm3.case_dt_sweep(quick=False)
    assert all(r["ok"] for r in _by(recs, "backward_euler"))
    assert all(r["ok"] for r in recs if r["method"] == "tr_bdf2" and r["setting"].endswith("=1"))
