"""The per-instance memo of scalar lubricant property calls (lubricant._memo_scalar)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.lubricant import load_lubricant


def test_memo_returns_the_uncached_values() -> None:
    oil = load_lubricant("ISO_VG68")
    temps = [300.0, 330.0, 365.5]
    first = [oil.dynamic_viscosity(t) for t in temps]
    again = [oil.dynamic_viscosity(t) for t in temps]
    arrays = oil.dynamic_viscosity(np.array(temps))  # array path: never memoised
    assert first == again
    np.testing.assert_allclose(arrays, first, rtol=1e-15)
    assert oil.density(330.0, 1e8) == float(oil.density(np.array([330.0]), 1e8)[0])
    assert ("dynamic_viscosity", 330.0) in oil._memo


def test_memo_is_per_instance_and_ignored_by_equality() -> None:
    a = load_lubricant("ISO_VG68")
    b = load_lubricant("ISO_VG68")
    a.dynamic_viscosity(320.0)
    assert a == b and hash(a) == hash(b)
    assert not b._memo


def test_warnings_reach_every_caller_and_are_not_memoised() -> None:
    oil = load_lubricant("ISO_VG32")
    hot = 1200.0  # far above the D341 range of a VG32: 0.15 cSt < 0.21 cSt, ValidityWarning
    for _ in range(2):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            oil.kinematic_viscosity(hot)
        assert any(issubclass(w.category, ValidityWarning) for w in caught)
    assert ("kinematic_viscosity", hot) not in oil._memo


def test_bad_input_still_raises_through_the_memo() -> None:
    oil = load_lubricant("ISO_VG68")
    with pytest.raises(Exception, match="temperature"):
        oil.dynamic_viscosity(-5.0)
