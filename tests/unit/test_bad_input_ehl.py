"""Bad-input audit, issue 7 (numerical line-contact EHL): a load or speed outside the solver's
range, a grid too coarse for the Hertz zone and a non-converging case each give a clear
error with the residual, the Moes M and L and a pointer to the closed-form film models;
never a silently wrong film (or a NaN traction).
"""

from __future__ import annotations

import math

import pytest

from thermobearing.ehl import numerical_ehl, numerical_tehl, solve_dimensionless, solve_line_contact
from thermobearing.ehl.line import GridResolutionError
from thermobearing.errors import ConvergenceError, InputError

POINTER = "moes_line_central"  # the closed-form model named in every range / failure message


@pytest.mark.parametrize(("M", "L", "field"), [(1e6, 10.0, "M"), (1e-4, 10.0, "M"),
                                               (100.0, -1.0, "L"), (100.0, 80.0, "L")])
def test_moes_parameters_outside_the_solver_range(M, L, field):
    with pytest.raises(InputError) as info:
        solve_dimensionless(M, L)
    assert info.value.field == field
    assert "[0.002, 3000]" in info.value.allowed or "[0, 40]" in info.value.allowed
    assert POINTER in info.value.allowed


def test_nan_moes_parameter():
    with pytest.raises(InputError) as info:
        solve_dimensionless(math.nan, 10.0)
    assert info.value.field == "M" and "finite" in info.value.allowed


def test_load_or_speed_outside_the_range_dimensional():
    # w' = 1e9 N/m on R = 10 mm: M ~ 6.7e4, far above the solver's 3000
    with pytest.raises(InputError) as info:
        solve_line_contact(1e9, 0.01, 2.2e11, 5.0, 0.01, alpha=2e-8)
    assert info.value.field == "M" and info.value.value > 3000 and POINTER in info.value.allowed
    with pytest.raises(InputError) as info:
        solve_line_contact(1e5, 0.01, 2.2e11, 0.0, 0.01, alpha=2e-8)
    assert info.value.field == "entrainment_speed"
    with pytest.raises(InputError) as info:
        solve_line_contact(-1e5, 0.01, 2.2e11, 5.0, 0.01, alpha=2e-8)
    assert info.value.field == "load_per_length"


def test_too_few_nodes_for_the_hertz_zone():
    with pytest.raises(InputError) as info:
        solve_dimensionless(100.0, 10.0, n=32)
    assert info.value.field == "n" and info.value.value == 32
    assert "across the Hertz zone" in info.value.allowed and POINTER in info.value.allowed


def test_grid_too_coarse_to_converge_reports_residual_M_L_and_pointer():
    # M = 1000 at n = 128: the pressure spike is not resolved, the time march collapses
    with pytest.raises(ConvergenceError) as info:
        solve_dimensionless(1000.0, 10.0, n=128)
    err = info.value
    assert math.isfinite(err.residual) and err.residual > 0
    assert err.state["M"] == 1000.0 and err.state["L"] == 10.0 and err.state["n"] == 128
    assert "M=1000, L=10" in str(err) and POINTER in str(err)


def test_grid_error_above_the_limit_is_an_error_not_a_film():
    with pytest.raises(GridResolutionError) as info:
        solve_dimensionless(100.0, 10.0, n=256, max_grid_error=1e-6)
    err = info.value
    assert "grid too coarse" in str(err) and "increase n" in str(err) and POINTER in str(err)
    assert 0 < err.residual < 1  # the Richardson estimate of the central-film error
    assert err.state == {"M": 100.0, "L": 10.0}


@pytest.fixture(scope="module")
def oil4109():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("OIL_4109")


def test_numerical_ehl_nan_slide_to_roll_is_refused(oil4109):
    # before: returned a FilmPoint with traction = nan
    with pytest.raises(InputError) as info:
        numerical_ehl(3e5, 0.005, 2.26e11, 10.0, math.nan, 330.0, lubricant=oil4109)
    assert info.value.field == "slide_to_roll" and "finite" in info.value.allowed


def test_numerical_ehl_temperature_below_absolute_zero(oil4109):
    with pytest.raises(InputError) as info:
        numerical_ehl(3e5, 0.005, 2.26e11, 10.0, 0.0, -5.0, lubricant=oil4109)
    assert "absolute zero" in info.value.allowed


@pytest.mark.parametrize(("options", "field"), [
    ({"relax": 0.0}, "relax"), ({"relax": 1.5}, "relax"),
    ({"tol_temperature": 0.0}, "tol_temperature"), ({"max_outer": 0}, "max_outer"),
    ({"nz": 4}, "nz"),
])
def test_thermal_ehl_solver_settings_out_of_range(oil4109, options, field):
    # before: relax = 0 returned the isothermal film as a converged thermal one;
    # tol_temperature = 0 ended in an InputError about a viscosity array (eta0 = array(...))
    from thermobearing.materials import get_material

    with pytest.raises(InputError) as info:
        numerical_tehl(3e5, 0.005, 2.26e11, 10.0, 0.1, 330.0, lubricant=oil4109,
                       solid=get_material("STEEL_52100"), **options)
    assert info.value.field == field and info.value.value == next(iter(options.values()))


def test_thermal_ehl_slide_to_roll_both_surfaces_moving(oil4109):
    from thermobearing.materials import get_material

    with pytest.raises(InputError) as info:
        numerical_tehl(3e5, 0.005, 2.26e11, 10.0, 2.5, 330.0, lubricant=oil4109,
                       solid=get_material("STEEL_52100"))
    assert info.value.field == "slide_to_roll" and "|SRR| < 2" in info.value.allowed


@pytest.mark.parametrize(("args", "field"), [
    ((3e5, 10.0, math.nan, 330.0), "slide_to_roll"),
    ((3e5, 10.0, 0.1, math.nan), "inlet_temperature"),
    ((3e5, 10.0, 0.1, -5.0), "inlet_temperature"),
    ((-3e5, 10.0, 0.1, 330.0), "load_per_length"),
])
def test_film_table_query_refuses_bad_points_before_solving(oil4109, args, field):
    # before: a NaN slide-to-roll ratio or temperature became a garbage table index (an
    # invalid-cast RuntimeWarning) and the table solved a node far outside the range
    from thermobearing.ehl import FilmTable

    table = FilmTable("numerical_ehl", 0.005, 2.26e11, lubricant=oil4109)
    with pytest.raises(InputError) as info:
        table(*args)
    assert info.value.field == field
    assert table.solves == 0
