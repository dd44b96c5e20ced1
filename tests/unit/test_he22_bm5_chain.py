"""BM-5 (session 22): the warm map rows say which points the load-step rule started cold,
and the chain of +2 % steps (transient-like: each step warm from the last) is run and
counted."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest


@pytest.fixture(scope="module")
def bm5():
    path = Path(__file__).resolve().parents[2] / "benchmarks" / "bm5_skidding.py"
    spec = importlib.util.spec_from_file_location("bm5_skidding_he22", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_warm_rows_flag_rule_starts_and_run_the_chain(bm5):
    # 20 kN -> 10 kN (a fraction of 0.50: warm) -> 1 kN (0.87: cold by the rule)
    rows = bm5.run_map(16, [1650.0], [20e3, 10e3, 1e3], 353.15, True, chain=3)
    assert [r["ok"] for r in rows] == [True, True, True]
    assert [r["cold_by_rule"] for r in rows] == [False, False, True]
    for r in rows:
        ok, _, it, nev, _ = r["small_step"]
        assert ok and it >= 1 and nev >= 1
        steps = r["chain"]
        assert len(steps) == 2                       # steps 2 and 3 of the chain
        assert all(s[0] and s[3] >= 1 for s in steps)


def test_no_chain_by_default_of_run_map(bm5):
    rows = bm5.run_map(16, [1650.0], [20e3], 353.15, True)
    assert "chain" not in rows[0] and rows[0]["small_step"][0]
    cold = bm5.run_map(16, [1650.0], [20e3], 353.15, False)
    assert "small_step" not in cold[0] and not cold[0]["cold_by_rule"]
