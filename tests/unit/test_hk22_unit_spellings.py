"""Tour R9: usual spellings pint does not read as meant ("40 deg C" is degree x coulomb,
"3000 U/min" an unknown unit) were refused without a suggestion; the refusal now names
the spelling meant. They stay refused: a suggestion, never a silent reading."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.units import to_si


@pytest.mark.parametrize("value, kind, meant", [
    ("40 deg C", "temperature", "40 degC"),
    ("40 deg. C", "temperature", "40 degC"),
    ("40 \u00b0 C", "temperature", "40 degC"),
    ("40 degree C", "temperature", "40 degC"),
    ("40 Grad C", "temperature", "40 degC"),
    ("104 deg F", "temperature", "104 degF"),
    ("10 deg C", "temperature_difference", "10 degC"),
    ("3000 U/min", "angular_speed", "3000 rpm"),
    ("3000 min-1", "angular_speed", "3000 rpm"),
    ("3000 r.p.m.", "angular_speed", "3000 rpm"),
    ("3000 tr/min", "angular_speed", "3000 rpm"),
    ("50 U/s", "angular_speed", "50 rps"),
])
def test_usual_spelling_is_refused_with_the_one_meant(value, kind, meant):
    with pytest.raises(InputError) as err:
        to_si(value, kind, field="supply.inlet_temperature")
    text = str(err.value)
    assert f"did you mean '{meant}'?" in text and "supply.inlet_temperature" in text
    # the suggestion itself reads
    assert to_si(meant, kind) > 0.0


def test_suggestion_only_where_it_converts():
    with pytest.raises(InputError) as err:
        to_si("3000 U/min", "temperature")
    assert "did you mean" not in str(err.value)
    with pytest.raises(InputError) as err:
        to_si("40 deg C", "angle")
    assert "did you mean" not in str(err.value)


def test_case_hint_is_kept_for_upper_case_rpm():
    with pytest.raises(InputError) as err:
        to_si("3000 RPM", "angular_speed")
    assert "case-sensitive: 'rpm'" in str(err.value)
