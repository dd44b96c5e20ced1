"""Bad-input audit, issue 5 (skidding solvers, public :func:`thermobearing.skidding.solve`):
bad operating points are refused with the field named (an unloaded roller bearing on the dry
ring balance among them: InputError before any solve); states the model cannot solve (nothing
drives the cage of a ball bearing) fail with a ConvergenceError carrying the residual and the
state, never NaN; solver settings out of range are named before any work is done.
"""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing import skidding
from thermobearing.errors import ConvergenceError, InputError, UnknownNameError, ValidityWarning
from thermobearing.state import OilSupply

SUPPLY = OilSupply("jet", 5e-4, 308.15)


@pytest.fixture(scope="module")
def qj1044():
    from thermobearing.geometry import load_bearing

    return load_bearing("QJ1044")


@pytest.fixture(scope="module")
def vg46():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("ISO_VG46")


@pytest.mark.parametrize(("speed", "radial", "temperature", "field", "allowed"), [
    (-100.0, 1000.0, 330.0, "speed", "> 0"),
    (188.0, math.nan, 330.0, "radial_load", "finite"),
    (188.0, 1000.0, -3.0, "temperature", "absolute zero"),
])
def test_ball_solver_bad_operating_point(qj1044, vg46, speed, radial, temperature, field,
                                         allowed):
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, speed, radial, 10000.0, temperature, supply=SUPPLY)
    assert info.value.field == field and allowed in info.value.allowed


def test_ball_solver_without_supply_says_what_is_missing(qj1044, vg46):
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, 188.0, 1000.0, 10000.0, 330.0)
    assert info.value.field == "supply" and "OilSupply" in info.value.allowed


def test_ball_no_load_fails_with_residual_and_state_not_nan(qj1044, vg46):
    # Fa = 0 and Fr = 0: centrifugal force holds every ball in the outer groove
    with pytest.raises(ConvergenceError) as info:
        skidding.solve(qj1044, vg46, 188.0, 0.0, 0.0, 330.0, supply=SUPPLY)
    err = info.value
    assert err.residual == math.inf and "no ball touches the inner ring" in str(err)
    assert err.state == {"radial_load": 0.0, "axial_load": 0.0, "speed": 188.0}


def test_ball_solver_tolerance_out_of_range(qj1044, vg46):
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, 188.0, 1000.0, 10000.0, 330.0, supply=SUPPLY, tol=0.0,
                       max_iter=1)
    assert info.value.field == "tol"
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, 188.0, 1000.0, 10000.0, 330.0, supply=SUPPLY, max_iter=0)
    assert info.value.field == "max_iter"


def test_ball_solver_iteration_limit_reports_residual(qj1044, vg46):
    with pytest.raises(ConvergenceError) as info:
        skidding.solve(qj1044, vg46, 188.0, 1000.0, 10000.0, 330.0, supply=SUPPLY, max_iter=1)
    err = info.value
    assert math.isfinite(err.residual) and err.residual > 1e-3
    assert "no convergence in 1 iterations" in str(err) and "cage_speed" in err.state


def test_roller_solver_refuses_axial_load(nu214, oil):
    with pytest.raises(InputError) as info:
        skidding.solve(nu214, oil, 500.0, 1000.0, 100.0, 330.0)
    assert info.value.field == "axial_load" and info.value.value == 100.0
    assert "cylindrical roller bearing" in info.value.allowed


@pytest.mark.parametrize(("speed", "radial", "temperature", "field"), [
    (-100.0, 1000.0, 330.0, "speed"),
    (500.0, -1000.0, 330.0, "radial_load"),
    (500.0, 1000.0, math.nan, "temperature"),
])
def test_roller_solver_bad_operating_point(nu214, oil, speed, radial, temperature, field):
    with pytest.raises(InputError) as info:
        skidding.solve(nu214, oil, speed, radial, 0.0, temperature)
    assert info.value.field == field


def test_roller_no_load_is_refused_naming_the_loads(nu214, oil):
    # before: ConvergenceError 'no roller touches the inner ring' (residual inf) from the solve
    with pytest.raises(InputError) as info:
        skidding.solve(nu214, oil, 500.0, 0.0, 0.0, 330.0)
    assert info.value.field == "radial_load and axial_load"
    assert "radial load > 0 N" in str(info.value) and "ribbed bearing" in str(info.value)


@pytest.mark.parametrize(("options", "field"), [
    ({"tol": 0.0}, "tol"), ({"tol": math.nan}, "tol"), ({"tol": 2.0}, "tol"),
    ({"max_iter": 0}, "max_iter"), ({"max_iter": 2.5}, "max_iter"),
])
def test_roller_solver_settings_out_of_range(nu214, oil, options, field):
    # before: tol = 0 ran 3.6 s and returned a result marked converged
    with pytest.raises(InputError) as info:
        skidding.solve(nu214, oil, 500.0, 1000.0, 0.0, 330.0, **options)
    assert info.value.field == field and info.value.value is next(iter(options.values()))


def test_roller_unknown_drag_model_lists_known_ones(nu214, oil):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        with pytest.raises(UnknownNameError) as info:
            skidding.solve(nu214, oil, 500.0, 1000.0, 0.0, 330.0, drag_model="numeric")
    assert info.value.value == "numeric" and "closed_form" in info.value.known


def test_roller_solver_misspelt_option_lists_the_options(nu214, oil):
    # before: TypeError "build_model() got an unexpected keyword argument 'drag_modle'"
    with pytest.raises(UnknownNameError) as info:
        skidding.solve(nu214, oil, 500.0, 1000.0, 0.0, 330.0, drag_modle="closed_form")
    assert info.value.value == "drag_modle"
    assert {"drag_model", "film_model", "tol", "max_iter"} <= set(info.value.known)
