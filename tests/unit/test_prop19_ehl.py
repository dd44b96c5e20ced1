"""Property tests of the numerical line-contact EHL solver (:mod:`thermobearing.ehl.line`,
session 19).

On random Moes parameters (M 5-250, L 0-20, n = 1024): the pressure carries the load,
int P dX = pi/2 (p scaled by p_H, x by b: the Hertz load w = pi b p_H / 2); the film is
positive everywhere, the pressure non-negative (to the solve's tolerance); the central film
is within 10 % of Moes' formula (the validation case ehl_moes_line measures 0.3-6.8 % for
M = 10-300, L = 2-20). A grid that is the solver's only grid (n at most the start grid)
cannot estimate its error: a GridResolutionError that says so, with an infinite residual.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.ehl.line import GridResolutionError, moes_dimensionless, solve_dimensionless
from thermobearing.errors import ValidityWarning


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(log_m=st.floats(math.log(5.0), math.log(250.0)), L=st.floats(0.0, 20.0))
def test_line_ehl_carries_the_load_and_follows_moes(log_m, L):
    M = math.exp(log_m)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        sol = solve_dimensionless(M, L, n=1024)
    assert math.isclose(float(np.trapezoid(sol.P, sol.X)), math.pi / 2, rel_tol=1e-6)
    # cavitation (P >= 0) holds to the tolerance of the Newton solve at the outlet nodes:
    # measured P down to -9.6e-8 p_H (M = 20, L = 2), -2.2e-8 (M = 5.1, L = 0)
    assert np.all(sol.H > 0.0) and np.all(sol.P >= -1e-6)
    assert sol.minimum_film <= sol.central_film
    h_moes = moes_dimensionless(M, L)
    assert abs(sol.error_estimate) <= 0.05
    ratio = _central_over_moes(sol, M, L, h_moes)
    assert abs(ratio - 1.0) < 0.10


def _central_over_moes(sol, M, L, h_moes):
    """Central film of the solution over Moes' (both as h_c R / b^2 -> Moes' H)."""
    # Moes' H = (h_c / R) (2U)^(-1/2) and b^2 / R^2 = 8 W' / pi with M = W' (2U)^(-1/2):
    # h_c R / b^2 = H (2U)^(1/2) pi / (8 W') = H pi / (8 M)
    return float(np.interp(0.0, sol.X, sol.H)) / (h_moes * math.pi / (8.0 * M))


def test_single_grid_has_no_error_estimate_and_says_so():
    """Defect found by this test: n = 512 at M >= 300 (the start grid is 512 nodes) solved one
    grid only and raised "estimated central-film error nan% > 5%" with a NaN residual; now
    the error says that one grid cannot estimate its error and which n can."""
    with pytest.raises(GridResolutionError, match="n >= 1024") as info:
        solve_dimensionless(300.0, 10.0, n=512)
    assert math.isinf(info.value.residual)
    assert "nan" not in str(info.value)
