"""A machine-tool spindle engineer's first session: an angular-contact pair on oil-air at
high speed with a light preload. Each test pins one defect found on that tour."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.units import to_si


# --- units as data sheets write them --------------------------------------------------
@pytest.mark.parametrize("text, unit, expected", [
    ("16000 r/min", "rad/s", 16000 * 2 * math.pi / 60),
    ("16000 rev/min", "rad/s", 16000 * 2 * math.pi / 60),
    ("50 r/s", "rad/s", 50 * 2 * math.pi),
    ("30 mm3/h", "m**3/s", 30e-9 / 3600),
    ("32 mm2/s", "m**2/s", 32e-6),
    ("860 kg/m3", "kg/m**3", 860.0),
    ("2 cm3/min", "m**3/s", 2e-6 / 60),
])
def test_data_sheet_spellings_convert(text, unit, expected):
    assert to_si(text, unit, field="f") == pytest.approx(expected, rel=1e-12)


def test_usual_spellings_leave_pint_spellings_alone():
    assert to_si("30 mm^3/h", "m**3/s") == to_si("30 mm3/h", "m**3/s")
    assert to_si("1800 rpm", "rad/s") == pytest.approx(1800 * 2 * math.pi / 60, rel=1e-12)
    assert to_si("2 min", "s") == 120.0


def test_decimal_comma_is_named_with_the_corrected_value():
    with pytest.raises(InputError) as err:
        to_si("0,5 kN", "N", field="schedule.axial_load")
    text = str(err.value)
    assert "schedule.axial_load" in text and "decimal point" in text and "'0.5 kN'" in text
