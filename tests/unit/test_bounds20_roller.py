"""A radial load below what the roller skidding solver's dry ring balance resolves (session
20 fuzzer): NU214, skidding, oil-air 500 mm3/h at 5e-27 N ended as 'did not converge
(residual inf): no roller touches the inner ring', a solver failure for an input the model
cannot take. It is now an InputError naming the radial load and the smallest load allowed,
the ring balance's force resolution rtol * max(1e-6 K (P_d/2)^(10/9), 1e-9)."""

from __future__ import annotations

import dataclasses
import math

import pytest

from thermobearing.bearing_config import load_bearing
from thermobearing.errors import InputError
from thermobearing.loads_roller import roller_load_distribution
from thermobearing.lubricant import load_lubricant
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.skidding.roller import (
    RING_BALANCE_RTOL,
    build_model,
    smallest_radial_load,
    solve_model,
)

SCENE = """
title = "bounds 20 roller probe"
[[bearings]]
name = "a"
preset = "NU214"
[lubricant]
preset = "ISO_VG68"
[supply]
method = "oil_air"
flow = "500 mm3/h"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "30 degC"
[schedule]
speed = "3000 rpm"
radial_load = "{radial}"
axial_load = "0 N"
step_duration = "2 min"
[models]
kinematics = "skidding"
[outputs]
mode = "steady"
want = ["losses"]
"""

OMEGA = 3000.0 * 2.0 * math.pi / 60.0


@pytest.fixture(scope="module")
def model():
    return build_model(load_bearing("NU214"), load_lubricant("ISO_VG68"), 313.15)


def test_the_scene_refuses_a_load_below_the_resolution_naming_the_radial_load() -> None:
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(SCENE.format(radial="5e-27 N")), progress=False).run()
    assert info.value.field == "radial_load"
    assert "a radial load above 6.05e-13 N" in str(info.value)
    assert "P_d = 25 um" in str(info.value)


def test_the_bound_is_the_ring_balance_tolerance(model) -> None:
    """F_min = rtol * 1e-6 K (P_d/2)^(10/9) (NU214: 6.05e-13 N). At it the dry ring balance
    returns at its start, the load unresolved (no body force: residual half the load; with
    the rollers' centrifugal force at 0.4 of 3000 r/min no roller on the inner ring); at
    1.5 F_min it iterates to a loaded roller."""
    half = 0.5 * model.diametral_clearance
    f_min = smallest_radial_load(model)
    assert f_min == pytest.approx(RING_BALANCE_RTOL * 1e-6 * model.k_inner * half ** (10 / 9),
                                  rel=1e-12)
    assert f_min == pytest.approx(6.05e-13, rel=1e-2)
    centrifugal = model.roller_mass * 0.5 * model.pitch_diameter * (0.4 * OMEGA) ** 2

    def balance(load: float, body_force: float):
        return roller_load_distribution(model.n_rollers, model.diametral_clearance, load,
                                        model.k_inner, model.k_outer, body_force=body_force)

    bare = balance(f_min, 0.0)
    assert bare.iterations == 0 and bare.residual > 0.4 * f_min
    spun = balance(f_min, centrifugal)
    assert spun.iterations == 0 and int(spun.loaded.sum()) == 0
    assert spun.residual == pytest.approx(f_min, rel=1e-12)
    above = balance(1.5 * f_min, centrifugal)
    assert int(above.loaded.sum()) >= 1 and above.residual < 1.5 * f_min


def test_just_above_the_bound_the_solver_converges_and_below_it_refuses(model) -> None:
    f_min = smallest_radial_load(model)
    res = solve_model(model, OMEGA, 1.5 * f_min)
    assert math.isfinite(res.cage_speed) and 0.0 < res.cage_speed_ratio < 0.5
    for load in (5e-27, f_min):
        with pytest.raises(InputError) as info:
            solve_model(model, OMEGA, load)
        assert info.value.field == "radial_load"
    with pytest.raises(InputError, match="radial load > 0 N") as info:
        solve_model(model, OMEGA, 0.0)  # zero load: refused before the solve
    assert info.value.field == "radial_load and axial_load"


def test_no_bound_without_clearance_or_on_films(model) -> None:
    assert smallest_radial_load(dataclasses.replace(model, diametral_clearance=0.0)) == 0.0
    assert smallest_radial_load(dataclasses.replace(model, ring_support="films")) == 0.0
