"""from_si reads the unit with to_si's data-sheet spellings, so every unit a config accepts
can be written back (``mm3/h`` raised pint's UndefinedUnitError 'mm3' before)."""

from __future__ import annotations

import pytest

from thermobearing.units import format_quantity, from_si, to_si


@pytest.mark.parametrize("text, kind", [
    ("10 mm3/h", "volume_flow"), ("46 mm2/s", "kinematic_viscosity"), ("870 kg/m3", "density"),
    ("1800 r/min", "angular_speed")])
def test_data_sheet_spellings_round_trip(text, kind):
    number, unit = text.split(" ", 1)
    si = to_si(text, kind)
    assert from_si(si, unit) == pytest.approx(float(number), rel=1e-12)
    assert format_quantity(si, unit) == f"{float(number):.4g} {unit}"
