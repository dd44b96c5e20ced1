"""Roller cold start on the cusp of the thermal reduction (skidding.roller.COLD_LAG).

The cold guess puts every roller in pure rolling on the outer race; with the default thermal
reduction of the rolling force (gupta_1992, |SRR|^0.83) an unloaded roller's residual rises
as |d|^0.83 on either side of that speed, so the forward-difference Newton step is no
descent direction and Newton took no step from it. D1842926 at 8000 r/min, 1000 N, 20 degC
(OIL_4109) fell through every Newton attempt to the bracketed solve (1.85 s of CPU,
benchmarks/bm_roller_cold.py); the 0.8 guess with the rollers 1e-6 below outer-race rolling
converges (0.27 s) to the bracketed state within 1.6e-13.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, initial_guess, solve_model
from thermobearing.skidding.roller_loads import _gapped, _load_distribution
from thermobearing.skidding.roller_residual import evaluate

OMEGA = 8000.0 * math.pi / 30.0
LOAD = 1000.0


def _model(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return build_model(load_bearing("D1842926"), load_lubricant("OIL_4109"), 293.15, **kw)


def _unloaded_roller_changes(model, d: float) -> tuple[float, float]:
    # residual change of roller 10 (opposite the load, unloaded) when its speed moves by +-d
    z = model.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    x = initial_guess(model, OMEGA, 0.8)
    ld, fb = _load_distribution(model, OMEGA, LOAD, float(x[z]), x[:z], psi, (0.0, 0.0), None,
                                None)
    assert ld.inner_load[10] == 0.0
    mg = _gapped(model, ld)

    def r10(shift: float) -> float:
        w = x[:z].copy()
        w[10] += shift
        return float(evaluate(mg, OMEGA, w, x[z], ld.inner_load, fb, psi, (0.0, 0.0))
                     .roller_eq[10])

    base = r10(0.0)
    return r10(d) - base, r10(-d) - base


def test_the_cold_guess_sits_on_the_cusp_of_the_thermal_reduction():
    gupta = _model()
    assert gupta.thermal_reduction == "gupta_1992"
    for d in (1e-10 * OMEGA, 1e-8 * OMEGA):
        up, down = _unloaded_roller_changes(gupta, d)
        assert up > 0.0 and down > 0.0            # a minimum with a cusp, not a slope
    # the rise goes as |d|^0.83 (measured 0.83-0.84 between 1e-10 and 1e-8 of omega)
    small, big = (_unloaded_roller_changes(gupta, d * OMEGA)[0] for d in (1e-10, 1e-8))
    assert math.log10(big / small) / 2.0 == pytest.approx(0.83, abs=0.05)
    # without the reduction the roller equation is smooth: odd about the guess
    up, down = _unloaded_roller_changes(_model(thermal_reduction="none"), 1e-8 * OMEGA)
    assert up == pytest.approx(-down, rel=1e-5)


def test_the_cold_start_converges_by_newton_to_the_bracketed_state():
    model = _model()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ours = solve_model(model, OMEGA, LOAD)
        anchor = solve_model(model, OMEGA, LOAD, method="bracketed")
    assert ours.converged and ours.extras["method"] == "newton"
    assert ours.residual_norm <= 1e-9
    assert ours.cage_speed == pytest.approx(anchor.cage_speed, rel=1e-10)
    np.testing.assert_allclose(ours.roller_speed, anchor.roller_speed, rtol=1e-8)
