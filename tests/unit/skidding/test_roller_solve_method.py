"""``solve_model(method=...)`` of the roller skidding solver (skidding/roller.py), what a
round-off state's residual norm means (``extras["residual_note"]``), and the records of
benchmarks/bm_roller_cold.py as ``thermobearing bench`` reads them.

The bracketed-only solve is the anchor of benchmarks/bm_roller_cold.py: Brent over the whole
cage-speed range with every roller bisected over its whole range, then a Newton polish.
"""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from thermobearing.commands.bench import _parse_records
from thermobearing.errors import UnknownNameError
from thermobearing.skidding.roller import SOLVE_METHODS, build_model, solve_model

RPM = math.pi / 30.0
BM = Path(__file__).resolve().parents[3] / "benchmarks" / "bm_roller_cold.py"


@pytest.fixture(scope="module")
def bm():
    spec = importlib.util.spec_from_file_location("bm_roller_cold", BM)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_bracketed_only_reaches_the_default_state(nu214, oil):
    """NU214, 2000 r/min, 1 kN, 60 degC, both to tol 1e-12: Newton from the cold guess and
    the bracketed solve over the whole range end at the same state (measured 7.5e-15
    relative; 2.0 s, the bracketed solve's cost, at load average 1.5)."""
    m = build_model(nu214, oil, 333.15)
    omega = 2000.0 * RPM
    ours = solve_model(m, omega, 1000.0, tol=1e-12)
    anchor = solve_model(m, omega, 1000.0, tol=1e-12, method="bracketed")
    # (Newton meets tol 1e-12 here; should round-off stall it on another CPU, it is
    # accepted at the floor and the state is the same)
    assert ours.extras["method"] in ("newton", "newton_round_off")
    assert anchor.extras["method"] == anchor.extras["start"] == "bracketed"
    assert anchor.extras["attempts"] == 0  # no Newton attempt before the bracketed solve
    assert anchor.residual_norm <= max(1e-12, 4.0 * anchor.extras["round_off_floor"])
    assert ours.cage_speed == pytest.approx(anchor.cage_speed, rel=1e-12)
    np.testing.assert_allclose(ours.roller_speed, anchor.roller_speed, rtol=1e-12)
    if ours.extras["method"] == "newton":
        # within tol: no equation at the round-off floor, and the note says so
        assert ours.extras["round_off_equations"] == ()
        assert "within the tolerance" in ours.extras["residual_note"]


def test_unknown_method_names_the_known_ones(nu214, oil):
    m = build_model(nu214, oil, 333.15)
    with pytest.raises(UnknownNameError) as info:
        solve_model(m, 2000.0 * RPM, 1000.0, method="brent")
    msg = str(info.value)
    assert "brent" in msg and all(name in msg for name in SOLVE_METHODS)


def test_round_off_note_names_the_equations_at_their_floor(nu214, oil):
    """NU214, 45 kN, 8000 r/min, 40 degC: Newton accepted at the round-off floor (norm
    2.1e-9 > tol 1e-9); the note names the equations beyond tol and their size, and every
    one of them is beyond tol of the force scale."""
    r = solve_model(build_model(nu214, oil, 313.15), 8000.0 * RPM, 45000.0)
    assert r.extras["method"] in ("newton_round_off", "bracketed")
    idx = r.extras["round_off_equations"]
    assert len(idx) >= 1
    note = r.extras["residual_note"]
    assert "round-off floor" in note and "not a distance from the root" in note
    scale = float(np.linalg.norm(r.residual)) / r.residual_norm
    assert np.all(np.abs(r.residual[list(idx)]) > 1e-9 * scale)
    others = np.delete(r.residual, list(idx))
    assert np.all(np.abs(others) <= 1e-9 * scale)


def test_bench_reads_one_record_per_point(bm, capsys):
    """``bm_roller_cold.py --json --quick --bearing D1842926 --limit 1``: stdout holds the
    records only (the table goes to stderr) and ``thermobearing bench`` parses them (one
    point, ours + the bracketed anchor + hybr: 2.2 s measured at load average 1.5, 7-8 s
    beside a full benchmark run at load 4-5)."""
    bm.main(["--json", "--quick", "--bearing", "D1842926", "--limit", "1"])
    out = capsys.readouterr()
    records = _parse_records(out.out)
    assert len(records) == 1
    rec = records[0]
    for key in ("benchmark", "case", "method", "setting", "time_s", "error",
                "ratio_vs_anchor", "anchor_time_s", "hybr_time_s", "hybr_outcome"):
        assert key in rec
    assert rec["benchmark"] == "bm_roller_cold"
    assert rec["case"] == "D1842926 2000rpm 5000N 60C"
    assert rec["anchor_converged"] is True
    assert rec["ratio_vs_anchor"] == pytest.approx(rec["anchor_time_s"] / rec["time_s"])
    # ours against the bracketed anchor: Newton within tol 1e-9 (measured 3.7e-8, the
    # roller speeds of the unloaded zone)
    assert 0.0 <= rec["error"] < 1e-6
    assert "bracketed/ours median" in out.err


def test_state_error_is_the_largest_relative_difference(bm):
    ref = np.array([2.0, 100.0])
    assert bm.state_error(10.0, ref, 10.0, ref) == 0.0
    assert bm.state_error(10.0, [2.0 * (1 + 3e-9), 100.0], 10.0, ref) == pytest.approx(3e-9)
    assert bm.state_error(10.0 * (1 - 5e-7), ref, 10.0, ref) == pytest.approx(5e-7)
