"""Ball skidding under sub-newton radial loads, where the cage nearly stops and the unloaded
balls are held in the outer groove by a centrifugal force of 1e-8 N (thermobearing.skidding.
ball_seat), and in cold oil. These stopped at residuals of 1e-9 to 2e-5 after every fallback
(SKF6304 at 963 r/min, 0.005 N; 7014C at 4925 r/min, 0.1 N; 7014C at 100 N in -20 degC ISO
VG100). The tests pin invariants of the converged state, not the solver's path."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import ValidityWarning
from thermobearing.skidding import solve
from thermobearing.state import OilSupply

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CASES = [
    ("SKF6304", "ISO_VG32", 20.0, 963.0, 0.005),
    ("SKF6304", "ISO_VG100", -20.0, 963.0, 0.05),
    ("spindle_7014C_catalogue.toml", "ISO_VG100", 20.0, 4925.0, 0.1),
    # cold oil (17 Pa s): the continuation in speed, whose steps stall at their round-off
    # floor or crawl (ball._warm_step_fallbacks); stopped at 1.0e-7 before
    ("spindle_7014C_catalogue.toml", "ISO_VG100", -20.0, 4925.0, 100.0),
]


@pytest.mark.parametrize(("name", "oil", "celsius", "rpm", "radial"), CASES)
def test_light_radial_load_converges(name, oil, celsius, rpm, radial) -> None:
    b = load_bearing(str(EXAMPLES / name) if name.endswith(".toml") else name)
    T = 273.15 + celsius
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = solve(b, load_lubricant(oil), rpm * math.pi / 30.0, radial, 0.0, T,
                  supply=OilSupply("jet", 1e-6, T))
    assert r.converged and r.residual_norm <= 1e-9
    heat = r.heat["total"]
    assert heat > 0.0
    assert abs(r.shaft_torque * r.inner_speed - heat) <= 1e-8 * heat
    # the cage turns forwards, well below pure rolling (it nearly stops under such a load)
    assert 0.0 < r.cage_speed_ratio < r.theoretical_cage_speed_ratio
    # no ball floats: every ball presses on the outer ring
    outer = r.ring == 1
    assert np.all(r.normal_load[:, outer].sum(axis=1) > 0.0)
    # the inner ring carries the radial load: sum_j Q_ij cos(alpha_ij) cos(psi_j) = F_r
    # (the traction forces' radial share is below 1e-8 of it at these loads)
    psi = 2.0 * math.pi * np.arange(b.n_balls) / b.n_balls
    inner = ~outer
    carried = np.sum(r.normal_load[:, inner] * np.cos(r.contact_angle[:, inner])
                     * np.cos(psi)[:, None])
    assert carried == pytest.approx(radial, rel=1e-6)
