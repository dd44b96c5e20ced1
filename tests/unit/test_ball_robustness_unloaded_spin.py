"""A practically unloaded ball bearing in cold oil (thermobearing.skidding.ball_damped_step):
the 7014C at 4925 r/min under 0.005 N radial with the contacts at -20 degC in ISO VG32 and
ISO VG100 stopped with a ConvergenceError (residual 8.4e-7 / 7.4e-6). One ball carries the
load, the cage nearly stops (CSR ~1e-5), the other balls are held in the outer groove by
centrifugal contacts of ~1e-8 N whose saturated traction leaves their spin free to within
the tolerance. Invariants of the converged state, not the solver's path."""

from __future__ import annotations

import functools
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import ValidityWarning
from thermobearing.skidding import solve
from thermobearing.skidding.ball_damped_step import regularised_step
from thermobearing.skidding.ball_jacobian import analytic_blocks
from thermobearing.state import OilSupply

BEARING = Path(__file__).resolve().parents[2] / "examples" / "spindle_7014C_catalogue.toml"
SPEED = 4925.0 * math.pi / 30.0
T = 273.15 - 20.0
RADIAL = 0.005


@functools.cache
def _target(oil):
    return _solve(oil)


def _solve(oil, speed=SPEED, guess=None, radial=RADIAL):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return solve(load_bearing(str(BEARING)), load_lubricant(oil), speed, radial, 0.0, T,
                     supply=OilSupply("jet", 1e-6, T), guess=guess)


@pytest.fixture(scope="module", params=["ISO_VG32", "ISO_VG100"])
def unloaded(request):
    return request.param, _target(request.param)


def test_unloaded_bearing_in_cold_oil_converges(unloaded) -> None:
    oil, r = unloaded
    assert r.converged and r.residual_norm <= 1e-9
    heat = r.heat["total"]
    assert heat > 0.0 and abs(r.shaft_torque * r.inner_speed - heat) <= 1e-8 * heat
    # the cage turns forwards but nearly stops: the traction of 5 mN contacts against the
    # cold oil's cage drag (measured CSR 2.1e-5 in VG32, 3.1e-6 in the thicker VG100)
    assert 0.0 < r.cage_speed_ratio < 1e-4
    # the inner ring carries the radial load through its contacts
    outer = r.ring == 1
    psi = 2.0 * math.pi * np.arange(r.normal_load.shape[0]) / r.normal_load.shape[0]
    carried = np.sum(r.normal_load[:, ~outer] * np.cos(r.contact_angle[:, ~outer])
                     * np.cos(psi)[:, None])
    assert carried == pytest.approx(RADIAL, rel=1e-6)
    # every ball presses on the outer ring (none floats)
    assert np.all(r.normal_load[:, outer].sum(axis=1) > 0.0)


def test_thicker_oil_slows_the_cage_more() -> None:
    vg32, vg100 = _target("ISO_VG32"), _target("ISO_VG100")
    assert vg100.cage_speed_ratio < vg32.cage_speed_ratio


def test_csr_grows_with_the_load_that_drives_the_cage(unloaded) -> None:
    """The cage is driven by the saturated traction of the loaded ball (about proportional
    to its load) against a cold-oil drag about proportional to its speed: ten times the
    load, about ten times the CSR (measured 11.6 in VG32, 10.2 in VG100; 0.001-0.5 N and
    -10 to -30 degC converge too)."""
    oil, r = unloaded
    ten = _solve(oil, radial=10.0 * RADIAL)
    assert ten.converged and ten.residual_norm <= 1e-9
    assert 8.0 < ten.cage_speed_ratio / r.cage_speed_ratio < 13.0


def test_csr_does_not_depend_on_the_start(unloaded) -> None:
    """Warm from the converged state 5 % slower (another path to the target speed): the same
    cage speed ratio (the free spins of the centrifugally held balls may differ)."""
    oil, r = unloaded
    slower = _solve(oil, 0.95 * SPEED)
    again = _solve(oil, SPEED, guess=slower)
    assert again.converged and again.residual_norm <= 1e-9
    assert again.cage_speed_ratio == pytest.approx(r.cage_speed_ratio, rel=1e-3)


def test_regularised_step_is_newton_on_a_regular_system() -> None:
    """At a well-loaded state (QJ1044, 4 kN axial, 40 degC) the step equals the Newton step
    J dy = -F of the assembled Jacobian."""
    b = load_bearing("QJ1044")
    w = 1800.0 * math.pi / 30.0
    r = solve(b, load_lubricant("ISO_VG68"), w, 0.0, 4000.0, 313.15,
              supply=OilSupply("jet", 1e-5, 313.15))
    system = r.extra["system"]
    X, G = r.unknowns
    G = G.copy()
    G[2] *= 1.0 + 1e-4                       # away from the root
    R, Gc, Gk, _ = system.evaluate(X, G)
    J = analytic_blocks(system, X, G)
    dX, dG = regularised_step(J, R, Gc, Gk)
    Z = system.Z
    n = 6 * Z + 3
    M = np.zeros((n, n))
    for z in range(Z):
        M[6 * z:6 * z + 6, 6 * z:6 * z + 6] = J.A[z]
        M[6 * z:6 * z + 6, 6 * Z:] = J.B[z]
        M[6 * Z:, 6 * z:6 * z + 6] = J.C[z]
    M[6 * Z:, 6 * Z:] = J.Dg
    F = np.concatenate([R.ravel(), Gc.sum(axis=0) + Gk])
    dy = np.linalg.solve(M, -F)
    got = np.concatenate([dX.ravel(), dG])
    assert np.allclose(got, dy, rtol=1e-6, atol=1e-9 * np.max(np.abs(dy)))
