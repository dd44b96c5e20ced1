"""Tests of the ball skidding / over-skidding solver (thermobearing.skidding.ball)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like, simple_models
from thermobearing.contact_traction import integrate_contact_set
from thermobearing.errors import ConvergenceError, InputError
from thermobearing.skidding.ball import race_control_guess, solve_ball

W1800 = 1800 * math.pi / 30


@pytest.fixture(scope="module")
def bearing():
    return qj_like()


@pytest.fixture(scope="module")
def models(bearing):
    return simple_models(bearing)


def test_race_control_guess_has_no_outer_spin(bearing, models):
    # Outer race control (primer 2.3): zero spin at the outer contact of a two-point ball.
    from thermobearing.skidding.ball import ball_residual_system

    X, G, ld = race_control_guess(bearing, W1800, 0.0, 36e3)
    sys_ = ball_residual_system(bearing, models, W1800, 0.0, 36e3)
    _, _, _, det = sys_.evaluate(X, G, details=True)
    outer = sys_.arcs.ring == 1
    loaded = det["cf"].load > 0
    wz = np.abs(det["Om_z"][loaded & outer[None, :]])
    roll = np.abs(det["Om_x"][loaded & outer[None, :]])
    assert np.max(wz / roll) < 2e-3


def test_heavy_axial_load_rolls_at_theoretical_csr(bearing, models):
    r = solve_ball(bearing, models, W1800, 1000.0, 36e3)
    assert r.converged and r.residual_norm < 1e-9
    # paper 002 section 4.1: pure rolling at 36 kN; the epicyclic CSR within 1 %
    assert abs(r.over_skid) < 0.01


def test_energy_balance_closes(bearing, models):
    # shaft torque x inner speed == all heat: raceway (F's contact integration on the
    # KinematicState, the raceway heat-source path), pocket friction, ball drag, cage drag.
    for Fa in (36e3, 3e3, 0.0):
        r = solve_ball(bearing, models, W1800, 1000.0, Fa)
        ks = r.kinematic_state
        q_race = sum(float(np.sum(integrate_contact_set(models.traction_law, cs,
                                                        n_major=models.n_major,
                                                        n_minor=models.n_minor).heat))
                     for cs in ks.contacts)
        total = q_race + r.heat["ball_pocket"] + r.heat["ball_drag"] + r.heat["cage"]
        assert math.isclose(r.shaft_torque * W1800, total, rel_tol=1e-8)
        assert math.isclose(r.heat["total"], total, rel_tol=1e-10)


def test_over_skidding_emerges_at_light_axial_load(bearing, models):
    # No fitted curve: gyroscopic slip (attitude well below the contact angle) and the
    # centrifugal split of the contact angles raise the CSR above the theoretical value.
    prev = None
    out = {}
    for Fa in (36e3, 10e3, 4e3):
        prev = solve_ball(bearing, models, W1800, 1000.0, Fa, guess=prev)
        out[Fa] = prev
    r = out[4e3]
    assert r.over_skid > 0.01
    assert np.mean(r.attitude_angle) < math.radians(20)          # attitude < contact angle
    assert np.mean(r.extra["inner_contact_angle"] - r.extra["outer_contact_angle"]) > 0.05
    assert abs(out[36e3].over_skid) < abs(r.over_skid)


def test_radial_load_only_skids_and_no_load_is_robust(bearing, models):
    r = solve_ball(bearing, models, W1800, 1000.0, 0.0)
    assert r.cage_speed_ratio < r.theoretical_cage_speed_ratio
    assert np.all(np.isfinite(r.spin))
    # no external load: centrifugal force holds every ball in the outer groove, nothing
    # drives the cage in this model -> a clear ConvergenceError (never NaN)
    with pytest.raises(ConvergenceError, match="no ball touches the inner ring") as info:
        solve_ball(bearing, models, W1800, 0.0, 0.0)
    assert info.value.state["radial_load"] == 0.0
    # centrifugal force larger than the inner-contact load (light thrust at high speed)
    r3 = solve_ball(bearing, models, 3000 * math.pi / 30, 0.0, 300.0)
    assert np.all(np.isfinite(r3.spin))
    assert np.all(r3.normal_load[:, r3.ring == 1].sum(1) > r3.normal_load[:, r3.ring == 0].sum(1))


def test_warm_start_reduces_iterations(bearing, models):
    r1 = solve_ball(bearing, models, W1800, 1000.0, 8e3)
    r2 = solve_ball(bearing, models, W1800, 1000.0, 8.2e3, guess=r1)
    assert r2.iterations < r1.iterations


def test_bad_input():
    with pytest.raises(InputError):
        solve_ball(qj_like(), None, -1.0, 0.0, 0.0)


def test_energy_balance_with_registered_heat_sources():
    # Issue 5 "Energy": shaft torque x inner-ring speed equals the total heat of the heat
    # sources (owner F) run on the solver's KinematicState, to 1e-8 relative.
    from thermobearing.geometry import load_bearing
    from thermobearing.heat_sources import HeatContext, evaluate
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding import solve
    from thermobearing.skidding.ball_models import BallParameters, heat_context_options
    from thermobearing.state import OilSupply, OperatingPoint
    from thermobearing.traction import make_traction_law  # noqa: F401 - law comes from models

    b = load_bearing("QJ1044")
    lub = load_lubricant("ISO_VG46")
    T = 318.15
    supply = OilSupply("jet", 33 / 60000, T)
    params = BallParameters()
    for fa in (20e3, 2e3):
        r = solve(b, lub, W1800, 1000.0, fa, T, supply=supply, params=params)
        ctx = HeatContext.isothermal(
            T, bearing=b, lubricant=lub, supply=supply,
            operating=OperatingPoint(W1800, 0.0, 1000.0, fa), kinematics=r.kinematic_state,
            traction=r.extra["traction_law"],
            options=heat_context_options(b, supply, W1800, params))
        names = ["raceway_traction", "churning_elements", "churning_cage", "churning_inner_ring",
                 "cage_guide", "pocket_friction"]
        total = sum(h.total for h in evaluate(names, ctx))
        assert math.isclose(r.shaft_torque * W1800, total, rel_tol=1e-8)


def test_ball_result_has_the_common_element_speeds_name():
    """skidding.solve promises per-element speeds on both result types: the ball result's
    ``element_speeds`` is its spin speed about each ball's own axis (the roller result's
    alias of its roller speeds)."""
    import math

    from thermobearing.bearing_config import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding import solve
    from thermobearing.state import OilSupply

    res = solve(load_bearing("SKF6304"), load_lubricant("ISO_VG68"), 2000 * math.pi / 30,
                2000.0, 0.0, 323.15, supply=OilSupply("jet", 1e-5, 323.15))
    assert res.element_speeds.shape == (res.spin_speed.size,)
    assert np.array_equal(res.element_speeds, res.spin_speed)
    assert np.all(res.element_speeds > 0)
    assert np.all(res.orbital_speed == res.cage_speed)
