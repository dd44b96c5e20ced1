"""Number spellings of word processors and other locales in unit strings (session-19 fuzz
probes): the minus sign U+2212 reads as a minus; digit groups with an apostrophe (Swiss),
a thin space or an underscore are refused like "16 000 rpm", with the number written
without them (before: "a known unit convertible to rad/s", which sent the user to the
unit)."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.units import to_si


@pytest.mark.parametrize(("text", "unit", "si"), [
    ("\u22125 degC", "K", 268.15),
    ("\u22123.5 kN", "N", -3500.0),
    ("1e\u22123 m", "m", 1e-3),
])
def test_unicode_minus_reads_as_minus(text: str, unit: str, si: float) -> None:
    assert math.isclose(to_si(text, unit, field="f"), si, rel_tol=1e-12)


@pytest.mark.parametrize("text", ["1'800 rpm", "1\u2009800 rpm", "1_800 rpm", "1\u2019800 rpm",
                                  "1 800 rpm"])
def test_digit_groups_are_refused_with_the_plain_number(text: str) -> None:
    with pytest.raises(InputError) as info:
        to_si(text, "rad/s", field="schedule.speed")
    assert info.value.field == "schedule.speed"
    assert info.value.value == text
    assert "'1800 rpm'" in info.value.allowed
