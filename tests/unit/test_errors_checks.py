"""The small argument checks of thermobearing.errors: scalars (their fast path) and arrays
give the same verdicts and name the field, the value and what is allowed."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import (
    InputError,
    check_finite,
    check_positive,
    check_range,
    check_temperature,
)

BAD = [
    (check_finite, {}, math.nan, "finite"),
    (check_finite, {}, math.inf, "finite"),
    (check_positive, {}, 0.0, "> 0"),
    (check_positive, {}, -1.0, "> 0"),
    (check_positive, {"allow_zero": True}, -1e-300, ">= 0"),
    (check_positive, {}, math.nan, "finite"),
    (check_range, {"low": 0.0, "high": 1.0}, 1.5, "[0, 1]"),
    (check_range, {"low": 0.0, "high": 1.0, "low_inclusive": False}, 0.0, "(0, 1]"),
    (check_range, {"low": 0.0, "high": 1.0, "high_inclusive": False}, 1.0, "[0, 1)"),
    (check_temperature, {}, 0.0, "absolute zero"),
    (check_temperature, {}, -5.0, "absolute zero"),
]


@pytest.mark.parametrize(("check", "kw", "value", "allowed"), BAD)
@pytest.mark.parametrize("kind", [float, np.float64, np.array, list])
def test_bad_values_are_refused_alike_as_scalars_and_arrays(check, kw, value, allowed, kind):
    arg = [1.0 if check is not check_range else 0.5, value] if kind is list else kind(value)
    if kind is np.array:
        arg = np.array([0.5, value]) if check is check_range else np.array([1.0, value])
    with pytest.raises(InputError, match=allowed.replace("[", r"\[").replace("(", r"\(")
                       .replace(")", r"\)")) as info:
        check("some.field", arg, **kw)
    assert "some.field" in str(info.value)


@pytest.mark.parametrize("value", [1, 2.5, np.float64(3.0), np.array([1.0, 2.0]), [4.0]])
def test_good_values_pass(value):
    check_finite("f", value)
    check_positive("f", value)
    check_positive("f", value, allow_zero=True)
    check_range("f", value, 0.5, 10.0)
    check_temperature("f", value)


def test_zero_allowed_only_when_asked_and_int_inputs():
    check_positive("f", 0, allow_zero=True)
    check_positive("f", 0.0, allow_zero=True)
    with pytest.raises(InputError):
        check_positive("f", 0)
    with pytest.raises(InputError, match="finite"):
        check_finite("f", float("nan"))


def test_missing_value_is_said_as_missing():
    """A field given no value reads 'is missing', not '= None is not allowed'."""
    assert str(InputError("supply.level", None, "an oil level for an oil bath")) == \
        "supply.level is missing: an oil level for an oil bath"
    assert str(InputError("supply.level", -1.0, "an oil level >= 0")) == \
        "supply.level = -1.0 is not allowed: an oil level >= 0"
