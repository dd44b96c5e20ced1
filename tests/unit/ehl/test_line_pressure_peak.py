"""The line-contact solver says when its pressure peak is not grid-converged (the films are)."""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing.ehl.line import MAX_PRESSURE_CHANGE, solve_dimensionless
from thermobearing.errors import ValidityWarning


def test_unconverged_spike_is_flagged_and_the_film_is_not():
    """M = 10, L = 20 (Barus, alpha p_H = 25): the spike is one or two nodes wide and its
    height follows the grid (1.96 -> 3.02 p_H from 512 to 1024 nodes), while h_c is
    converged to 3e-4: a ValidityWarning names the change, M, L and n."""
    with pytest.warns(ValidityWarning, match=r"not grid-converged at n=1024 for M=10, L=20"):
        sol = solve_dimensionless(10.0, 20.0, n=1024)
    assert sol.max_pressure_change > MAX_PRESSURE_CHANGE
    assert sol.error_estimate < 1e-3


def test_converged_peak_is_not_flagged():
    """M = 10, L = 5: the peak moves by less than the threshold between 512 and 1024 nodes."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        sol = solve_dimensionless(10.0, 5.0, n=1024)
    assert math.isfinite(sol.max_pressure_change)
    assert sol.max_pressure_change <= MAX_PRESSURE_CHANGE
