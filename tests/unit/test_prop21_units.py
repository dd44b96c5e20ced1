"""Property tests of the unit conversions at the edges (:mod:`thermobearing.units`,
session 21): every quantity kind of :data:`SI_UNITS` with the unit strings configs and data
sheets use for it.

- round trip: ``to_si("<v> <unit>", kind)`` then :func:`format_quantity` back in the same
  unit (``kind`` given, so a temperature difference in ``degC`` stays a difference) reads
  back as the same SI value (17 digits: to 1e-14);
- :func:`from_si` inverts :func:`to_si`: the number written is the number read;
- a frequency written as a rotation speed counts revolutions: ``"1812 rpm"`` is 30.2 Hz
  and ``"6.283 rad/s"`` 1 Hz (pint takes the radian as 1: they read as 189.75 and 6.283 Hz,
  2 pi high; the validation runners' shaft and cage frequencies take such strings);
- linearity: a kind without an offset converts ``2 v`` to twice what it converts ``v``
  to, and a temperature difference is an offset-free kind whatever its unit (``"10 degC"``
  and ``"18 degF"`` as differences are 10 K; ``"18 degF"`` was refused as not convertible
  to delta_degC while ``"10 degC"`` was read).
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.units import SI_UNITS, format_quantity, from_si, quantity_unit, to_si

#: unit strings per kind: pint spellings and the data-sheet spellings the module reads
#: ("r/min", "mm2/s", "kg/m3", the one-character degree signs)
UNITS = {
    "length": ["m", "mm", "um", "\u00b5m", "cm", "in", "ft", "km", "nm"],
    "area": ["m**2", "mm**2", "mm2", "cm2", "in**2"],
    "volume": ["m**3", "mm3", "L", "mL", "cm3", "in**3"],
    "mass": ["kg", "g", "lb", "t", "mg"],
    "time": ["s", "min", "h", "ms", "hour", "day"],
    "temperature": ["K", "degC", "degF", "\u00b0C", "\u2103", "\u2109", "degR", "celsius",
                    "kelvin"],
    "temperature_difference": ["K", "degC", "\u00b0C", "\u2103", "celsius", "delta_degC",
                               "degF", "\u00b0F", "\u2109", "fahrenheit", "delta_degF",
                               "degR", "mK"],
    "angle": ["rad", "deg", "degree", "arcmin", "turn", "mrad"],
    "angular_speed": ["rad/s", "rpm", "r/min", "rev/min", "rev/s", "deg/s", "turn/s", "rps",
                      "r/s"],
    "speed": ["m/s", "mm/s", "km/h", "ft/min", "m/min"],
    "force": ["N", "kN", "lbf", "kgf", "MN", "mN"],
    "moment": ["N*m", "N*mm", "kN*m", "lbf*in", "N m"],
    "pressure": ["Pa", "MPa", "GPa", "bar", "psi", "kPa", "N/mm**2", "N/mm2", "atm"],
    "stress": ["Pa", "MPa", "GPa", "N/mm2"],
    "dynamic_viscosity": ["Pa*s", "mPa*s", "cP", "P", "Pa s"],
    "kinematic_viscosity": ["m**2/s", "mm**2/s", "mm2/s", "cSt", "St"],
    "density": ["kg/m**3", "kg/m3", "g/cm**3", "g/cm3", "kg/L", "g/mL"],
    "volume_flow": ["m**3/s", "L/min", "l/min", "mm3/h", "mL/min", "cm3/min", "L/h",
                    "gal/min"],
    "mass_flow": ["kg/s", "g/s", "kg/h", "kg/min"],
    "power": ["W", "kW", "hp", "mW"],
    "energy": ["J", "kJ", "kWh", "W*h"],
    "heat_capacity": ["J/K", "kJ/K", "J/delta_degC"],
    "specific_heat": ["J/(kg*K)", "kJ/(kg*K)", "J/kg/K", "J/(g*K)"],
    "thermal_conductivity": ["W/(m*K)", "W/m/K", "mW/(m*K)"],
    "heat_transfer_coefficient": ["W/(m**2*K)", "W/m2/K", "W/(m2*K)", "kW/(m**2*K)"],
    "conductance": ["W/K", "kW/K", "mW/K"],
    "frequency": ["Hz", "kHz", "1/s", "1/min", "rpm", "r/min", "rev/s", "rad/s", "deg/s",
                  "turn/s"],
    "inverse_pressure": ["1/Pa", "1/GPa", "1/MPa", "m**2/N", "mm2/N", "1/bar"],
    "inverse_temperature": ["1/K", "K**-1"],
    "stiffness": ["N/m", "N/mm", "N/um", "kN/mm", "N/\u00b5m"],
    "dimensionless": ["", "percent", "ppm", "dimensionless"],
}
CASES = [(kind, unit) for kind, units in UNITS.items() for unit in units]
#: kinds whose conversion has an offset (an absolute temperature)
OFFSET_KINDS = {"temperature"}


def test_every_kind_has_unit_strings():
    assert set(UNITS) == set(SI_UNITS)


def _text(v: float, unit: str) -> str:
    return f"{v!r} {unit}" if unit else repr(v)


@pytest.mark.parametrize(("kind", "unit"), CASES)
@settings(max_examples=8, deadline=None)
@given(mantissa=st.floats(1.0, 10.0), exponent=st.integers(-6, 6))
def test_round_trip_through_the_written_unit(kind, unit, mantissa, exponent):
    v = mantissa * 10.0**exponent
    if kind == "temperature":
        v = 300.0 + mantissa * 10.0 ** min(exponent, 2)  # above absolute zero in every unit
    si = to_si(_text(v, unit), kind, field="f")
    pint_unit = quantity_unit(f"1 {unit}") if unit else "dimensionless"
    back = from_si(si, pint_unit, kind)
    assert math.isclose(back, v, rel_tol=1e-12, abs_tol=1e-12 * abs(v)), (back, v)
    written = format_quantity(si, pint_unit, digits=17, kind=kind)
    again = to_si(written, kind, field="f")
    assert math.isclose(again, si, rel_tol=1e-14, abs_tol=1e-14 * abs(si)), (written, si)


@pytest.mark.parametrize(("kind", "unit"), [c for c in CASES if c[0] not in OFFSET_KINDS])
@settings(max_examples=5, deadline=None)
@given(v=st.floats(1e-3, 1e3))
def test_offset_free_kinds_are_linear(kind, unit, v):
    one = to_si(_text(v, unit), kind, field="f")
    two = to_si(_text(2.0 * v, unit), kind, field="f")
    assert math.isclose(two, 2.0 * one, rel_tol=1e-13)


@pytest.mark.parametrize(("text", "kelvin"), [
    ("10 degC", 10.0), ("10 \u00b0C", 10.0), ("10 \u2103", 10.0), ("10 K", 10.0),
    ("18 degF", 10.0), ("18 \u00b0F", 10.0), ("18 \u2109", 10.0), ("18 fahrenheit", 10.0),
    ("18 delta_degF", 10.0), ("18 degR", 10.0),
])
def test_temperature_differences_in_degrees(text, kelvin):
    assert to_si(text, "temperature_difference") == pytest.approx(kelvin, rel=1e-14)


def test_a_difference_is_written_back_as_a_difference():
    """0.5 K written in degC is '0.5 degC' as a difference (-272.65 degC as a temperature),
    in degF '0.9 degF'."""
    assert format_quantity(0.5, "degC", kind="temperature_difference") == "0.5 degC"
    assert format_quantity(0.5, "degF", kind="temperature_difference") == "0.9 degF"
    assert format_quantity(0.5, "degC") == "-272.6 degC"
    assert from_si(300.0, "degC") == pytest.approx(26.85, rel=1e-12)


@pytest.mark.parametrize(("text", "hertz"), [
    ("60 rpm", 1.0), ("1812 rpm", 30.2), ("1812 r/min", 30.2), ("1 rev/s", 1.0),
    ("6.283185307179586 rad/s", 1.0), ("360 deg/s", 1.0), ("1 turn/s", 1.0), ("1 Hz", 1.0),
    ("60 1/min", 1.0), ("25.6 kHz", 25600.0),
])
def test_rotation_speeds_as_frequencies_count_revolutions(text, hertz):
    assert to_si(text, "frequency") == pytest.approx(hertz, rel=1e-12)


def test_angular_speeds_are_unchanged():
    """The angular-speed kind keeps pint's reading (1 rpm = 2 pi / 60 rad/s) and refuses a
    frequency without an angle."""
    from thermobearing.errors import InputError

    assert to_si("1800 rpm", "angular_speed") == pytest.approx(60.0 * math.pi, rel=1e-12)
    assert from_si(60.0 * math.pi, "rpm") == pytest.approx(1800.0, rel=1e-12)
    assert from_si(30.2, "rpm", "frequency") == pytest.approx(1812.0, rel=1e-12)
    with pytest.raises(InputError, match="rpm"):
        to_si("30 Hz", "angular_speed")
