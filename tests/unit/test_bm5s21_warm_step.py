"""BM-5 warm step (session 21): the block-elimination factors kept with a Jacobian.

A warm start hands the previous solve's Jacobian over rescaled to the new loads; its factors
(A^-1, A^-1 B, C, S^-1) are rescaled with it instead of factorised again. These tests pin
that the rescaled factors are those of the rescaled blocks to round-off, that the factors are
computed once per Jacobian, that the rescaled residual of a reloaded system equals the numpy
expressions it replaces, and that a +2 % warm step ends at the same state with or without
the carried factors; and that BM-5's anchor subset spreads over speeds and loads.
"""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.ball import solve_ball
from thermobearing.skidding.ball_jacobian import analytic_blocks
from thermobearing.skidding.ball_models import default_ball_models
from thermobearing.skidding.ball_newton import (
    JacobianBlocks,
    _factor_blocks,
    _inverse_small,
    block_factors,
)
from thermobearing.skidding.ball_residual_kernels import _rescaled_residual, _residual_norm_nb
from thermobearing.state import OilSupply

W = 1650 * math.pi / 30


@pytest.fixture(scope="module")
def solved():
    """A converged QJ1044 state (Z = 16, 80 degC oil, 1650 r/min, 20 kN axial, 1 kN radial;
    a BM-5 map point) with the default compiled models (analytic Jacobian)."""
    b = load_bearing("QJ1044")
    lub = load_lubricant("ISO_VG46")
    supply = OilSupply("jet", 33 / 60000, 313.15)
    models = default_ball_models(b, lub, temperature=353.15, speed=W, supply=supply)
    r = solve_ball(b, models, W, 1000.0, 20e3, n_balls=16, theoretical_reference=0.45)
    return b, models, r


def _fresh_factors(blocks):
    Ainv, AiB, S, ok = _factor_blocks(blocks.A, blocks.B, np.ascontiguousarray(blocks.C),
                                      blocks.Dg)
    assert ok
    Sinv, ok = _inverse_small(S)
    assert ok
    return Ainv, AiB, Sinv


def test_rescaled_factors_equal_factors_of_rescaled_blocks(solved):
    _, _, r = solved
    system = r.extra["system"]
    J = analytic_blocks(system, *r.unknowns)
    assert block_factors(J) is not None
    for fr, fa in ((1000.0, 20420.0), (1000.0, 40e3), (5000.0, 200.0)):
        other = system.reloaded(fr, fa)
        assert other.F_s != system.F_s          # the Q_p column and the rows are rescaled
        Jr = J.rescaled(other)
        assert Jr.factors, "the factors are carried with the rescaled blocks"
        Ainv, AiB, _, Sinv = Jr.factors[0]
        ref = _fresh_factors(Jr)
        for got, want in zip((Ainv, AiB, Sinv), ref, strict=True):
            scale = np.max(np.abs(want))
            assert np.max(np.abs(got - want)) <= 1e-12 * scale
        # the blocks themselves are those of the plain rescaling
        plain = JacobianBlocks(J.A, J.B, J.C, J.Dg, J.F_s, J.xs, J.gs, J.Z).rescaled(other)
        assert not plain.factors
        for a, b in ((Jr.A, plain.A), (Jr.B, plain.B), (Jr.C, plain.C), (Jr.Dg, plain.Dg)):
            np.testing.assert_array_equal(a, b)


def test_factors_are_computed_once_per_jacobian(solved):
    _, _, r = solved
    J = analytic_blocks(r.extra["system"], *r.unknowns)
    assert not J.factors
    first = block_factors(J)
    assert block_factors(J) is first
    assert len(J.factors) == 1


def test_rescaled_residual_equals_numpy_expressions(solved):
    _, _, r = solved
    system = r.extra["system"]
    R, Gc, G0, _ = system.evaluate(*r.unknowns)
    f = 0.98
    R2, Gc2, G02, nrm = _rescaled_residual(R, Gc, f, 0.3, -0.2, 0.01)
    np.testing.assert_array_equal(R2, R * f)
    np.testing.assert_array_equal(Gc2, Gc * f)
    np.testing.assert_array_equal(G02, np.array([0.3, -0.2, 0.01]))
    assert nrm == _residual_norm_nb(R * f, Gc * f, np.array([0.3, -0.2, 0.01]))
    # a reloaded system's start residual equals a fresh evaluation at the new loads
    other = system.reloaded(1000.0, 20420.0)
    Rm, Gcm, G0m, _ = other.evaluate(*r.unknowns)
    fresh = type(system)(system.bearing, system.models, system.speed, 1000.0, 20420.0, 16)
    Rf, Gcf, G0f, _ = fresh.evaluate(*r.unknowns)
    assert np.max(np.abs(Rm - Rf)) <= 1e-13 * max(1.0, np.max(np.abs(Rf)))
    assert np.max(np.abs((Gcm.sum(0) + G0m) - (Gcf.sum(0) + G0f))) <= 1e-12


def test_warm_step_with_carried_factors_ends_at_the_same_state(solved):
    b, models, r = solved
    step = solve_ball(b, models, W, 1000.0, 1.02 * 20e3 + 20.0, n_balls=16, guess=r,
                      theoretical_reference=0.45)
    J = r.extra["jacobian"]
    assert J is not None and J.factors, "the solve's Jacobian keeps its factors"
    # the same warm step with the Jacobian stripped of its factors (factorised again)
    r.extra["jacobian"] = JacobianBlocks(J.A, J.B, J.C, J.Dg, J.F_s, J.xs, J.gs, J.Z)
    try:
        ref = solve_ball(b, models, W, 1000.0, 1.02 * 20e3 + 20.0, n_balls=16, guess=r,
                         theoretical_reference=0.45)
    finally:
        r.extra["jacobian"] = J
    assert step.residual_norm <= 1e-9 and ref.residual_norm <= 1e-9
    assert abs(step.cage_speed_ratio - ref.cage_speed_ratio) <= 1e-10 * ref.cage_speed_ratio
    assert abs(step.heat["total"] - ref.heat["total"]) <= 1e-9 * ref.heat["total"]
    gap = abs(step.shaft_torque * step.inner_speed - step.heat["total"])
    assert gap <= 1e-8 * step.heat["total"]


def test_bm5_anchor_subset_spreads_over_speeds_and_loads():
    """``--anchor-points 4`` on the anchor grids of the 10 x 10 (4 speeds x 3 loads) and
    20 x 20 maps (4 x 4): four distinct points at four speeds and at every load (a plain
    stride took all four at 40 kN)."""
    path = Path(__file__).resolve().parents[2] / "benchmarks" / "bm5_skidding.py"
    spec = importlib.util.spec_from_file_location("bm5_skidding", path)
    bm5 = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bm5)
    speeds = [300.0, 1200.0, 2100.0, 3000.0]
    for loads in ([40e3, 26.7e3, 13.3e3, 200.0], [40e3, 4130.0, 426.0]):
        pts = [(n, fa) for n in speeds for fa in loads]
        got = bm5.thin_anchor_points(pts, len(loads), 4)
        assert len(set(got)) == 4 and set(got) <= set(pts)
        assert sorted({n for n, _ in got}) == speeds
        assert sorted({fa for _, fa in got}) == sorted(loads)
        assert bm5.thin_anchor_points(pts, len(loads), 20) == pts
        for n in (1, 2, 6, 9):
            some = bm5.thin_anchor_points(pts, len(loads), n)
            assert len(set(some)) == n and set(some) <= set(pts)
