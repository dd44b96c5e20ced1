"""One thermal default for the roller rolling force: ``skidding.solve`` called directly applies
the line-contact rolling-resistance heat source's default inlet-heating reduction
(``heat_sources.raceway.DEFAULT_THERMAL_REDUCTION``, Gupta et al. 1992), so the public API,
a scene's skidding chain and the heat source's own formulas apply the same rolling force.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing import skidding
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.heat_sources import HeatContext, evaluate, raceway
from thermobearing.lubricant import load_lubricant
from thermobearing.state import OilSupply, OperatingPoint

RPM = math.pi / 30.0
T = 323.15
SUPPLY = OilSupply("jet", 2e-3 / 60.0, T)
SPEED = 4000.0 * RPM
LOAD = 10e3


@pytest.fixture(scope="module")
def solves():
    """NU 214, 10 kN, 4000 r/min, ISO VG 46 at 50 degC, jet: the default, the heat
    source's name given explicitly, and the isothermal solve."""
    bearing, lub = load_bearing("NU214"), load_lubricant("ISO_VG46")
    out = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        for key, opts in (("default", {}), ("named", {"thermal_reduction": "gupta_1992"}),
                          ("none", {"thermal_reduction": "none"})):
            out[key] = skidding.solve(bearing, lub, SPEED, LOAD, 0.0, T, supply=SUPPLY, **opts)
    return bearing, lub, out


def test_direct_solve_default_is_the_heat_sources_reduction(solves):
    _, _, res = solves
    default, named, iso = res["default"], res["named"], res["none"]
    assert default.converged and named.converged and iso.converged
    assert default.extras["thermal_reduction"] == raceway.DEFAULT_THERMAL_REDUCTION
    assert default.kinematic_state.extras["raceway_rolling_thermal_reduction"] == "gupta_1992"
    # the same model, so the same state
    for race in ("inner", "outer"):
        np.testing.assert_allclose(getattr(default, race).rolling_force,
                                   getattr(named, race).rolling_force, rtol=1e-12, atol=0.0)
    assert default.power_loss["total"] == pytest.approx(named.power_loss["total"], rel=1e-12)
    # and not the isothermal one: inlet heating lowers the rolling loss at 4000 r/min
    roll = {k: r.power_loss["inner_rolling"] + r.power_loss["outer_rolling"]
            for k, r in res.items()}
    assert roll["default"] < 0.95 * roll["none"]


def test_heat_source_without_options_books_the_default_solve(solves):
    """The source with no options and the source naming the default reduction book the
    same rolling heat on the default state (the force the solver carried), equal to the
    solver's own rolling dissipation."""
    bearing, lub, res = solves
    state = res["default"]
    op = OperatingPoint(inner_speed=SPEED, radial_load=LOAD, axial_load=0.0)
    totals = []
    for options in ({}, {"ehl_rolling_resistance": {"thermal_reduction": "gupta_1992"}}):
        ctx = HeatContext.isothermal(T, bearing=bearing, lubricant=lub, supply=SUPPLY,
                                     operating=op, kinematics=state.kinematic_state,
                                     options=options)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            totals.append(evaluate(["ehl_rolling_resistance"], ctx)[0].total)
    assert totals[0] == pytest.approx(totals[1], rel=1e-12)
    assert totals[0] == pytest.approx(state.booked_power()["ehl_rolling_resistance"],
                                      rel=1e-10)
