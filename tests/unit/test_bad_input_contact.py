"""Bad-input audit, issue 2 (bearing geometry, lubricant, units, Hertz and film): each clause
of "What bad input gets" through the public API a user calls (:func:`load_bearing` with
overrides as a scene gives them, :func:`load_lubricant`, :meth:`Lubricant.from_viscosities`,
:func:`to_si`, :func:`point_contact`), asserting the error type, the field and the value.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.geometry import load_bearing
from thermobearing.hertz import line_contact, point_contact
from thermobearing.lubricant import Lubricant, load_lubricant
from thermobearing.units import to_si


@pytest.mark.parametrize(("field", "value"), [
    ("bore", "0 mm"), ("bore", "-5 mm"), ("outer_diameter", "0 mm"), ("width", "-1 mm"),
    ("ball_diameter", "0 mm"),
])
def test_negative_or_zero_dimension(field, value):
    with pytest.raises(InputError) as info:
        load_bearing("QJ1044", overrides={field: value})
    assert info.value.field == f"bearing.{field}"
    assert info.value.value <= 0 and "> 0" in info.value.allowed


def test_ball_larger_than_the_section():
    with pytest.raises(InputError) as info:
        load_bearing("QJ1044", overrides={"ball_diameter": "200 mm"})
    # QJ1044: 220 x 340 mm, section (D - d)/2 = 60 mm
    assert info.value.field == "bearing.ball_diameter" and info.value.value == pytest.approx(0.2)
    assert "radial section" in info.value.allowed and "0.06 m" in info.value.allowed


@pytest.mark.parametrize(("preset", "field"), [("QJ1044", "n_balls"), ("NU214", "n_rollers")])
def test_fewer_than_three_elements(preset, field):
    with pytest.raises(InputError) as info:
        load_bearing(preset, overrides={field: 2})
    assert info.value.field == f"bearing.{field}" and info.value.value == 2
    assert ">= 3" in info.value.allowed


def test_non_integer_number_of_elements():
    with pytest.raises(InputError) as info:
        load_bearing("QJ1044", overrides={"n_balls": 2.5})
    assert info.value.field.endswith("n_balls") and info.value.value == 2.5


@pytest.mark.parametrize("angle", ["90 deg", "-1 deg", "120 deg"])
def test_contact_angle_outside_0_90_deg(angle):
    with pytest.raises(InputError) as info:
        load_bearing("QJ1044", overrides={"contact_angle": angle})
    assert info.value.field == "bearing.contact_angle"
    assert info.value.value == pytest.approx(to_si(angle, "angle"))
    assert "[0, 1.5708)" in info.value.allowed  # [0, pi/2) rad


def test_unknown_bearing_preset_lists_known_ones():
    with pytest.raises(UnknownNameError) as info:
        load_bearing("QJ1045")
    assert info.value.value == "QJ1045"
    assert {"QJ1044", "NU214", "D1842926", "SKF6304", "CRB_50x75x16"} <= set(info.value.known)


def test_unknown_lubricant_preset_lists_known_ones():
    with pytest.raises(UnknownNameError) as info:
        load_lubricant("ISO_VG47")
    assert info.value.value == "ISO_VG47"
    assert {"ISO_VG46", "PAPER000_OIL", "OIL_4109"} <= set(info.value.known)


@pytest.mark.parametrize(("text", "kind", "si"), [
    ("1800 kg", "angular_speed", "rad/s"), ("33 kg", "volume_flow", "m**3/s"),
    ("40 mm", "angle", "rad"), ("3 kN", "temperature", "K"),
])
def test_unit_that_does_not_convert(text, kind, si):
    with pytest.raises(InputError) as info:
        to_si(text, kind, field="schedule.speed")
    assert info.value.field == "schedule.speed" and info.value.value == text
    assert si in info.value.allowed


def test_unknown_unit():
    with pytest.raises(InputError) as info:
        to_si("1800 blorps", "angular_speed", field="speed")
    assert info.value.value == "1800 blorps" and "known unit" in info.value.allowed


@pytest.mark.parametrize("temperature", [-5.0, 0.0, math.nan])
def test_lubricant_temperature_at_or_below_absolute_zero(temperature):
    oil = load_lubricant("ISO_VG46")
    with pytest.raises(InputError) as info:
        oil.dynamic_viscosity(temperature)
    assert info.value.field == "temperature"
    assert "absolute zero" in info.value.allowed or "finite" in info.value.allowed


def test_to_si_refuses_a_temperature_below_absolute_zero():
    with pytest.raises(InputError) as info:
        to_si("-300 degC", "temperature", field="supply.inlet_temperature")
    assert info.value.value == "-300 degC"
    assert info.value.field == "supply.inlet_temperature" and "absolute zero" in info.value.allowed
    with pytest.raises(InputError):
        to_si(float("nan"), "volume_flow", field="supply.flow")
    with pytest.raises(InputError):
        to_si("inf L/min", "volume_flow", field="supply.flow")
    assert to_si("-20 degC", "temperature") == pytest.approx(253.15)


def test_viscosity_data_inconsistent_nu100_above_nu40():
    with pytest.raises(InputError) as info:
        Lubricant.from_viscosities(46e-6, 60e-6, 870.0, name="bad oil")
    assert "373.15 K" in info.value.field and info.value.value == pytest.approx(60e-6)
    assert "thins as it heats" in info.value.allowed


def test_viscosity_data_negative():
    with pytest.raises(InputError) as info:
        Lubricant.from_viscosities(-46e-6, 6e-6, 870.0, name="bad oil")
    assert info.value.value == pytest.approx(-46e-6) and "> 0" in info.value.allowed


@pytest.mark.parametrize(("load", "allowed"), [(-1.0, ">= 0"), (math.nan, "finite")])
def test_hertz_bad_load(load, allowed):
    with pytest.raises(InputError) as info:
        point_contact(load, 0.01, 0.1, 2.2e11)
    assert info.value.field == "load" and allowed in info.value.allowed


def test_hertz_zero_load_gives_zeros_not_nan():
    pc = point_contact(np.array([0.0, 100.0]), 0.01, 0.1, 2.2e11)
    for arr in (pc.a, pc.b, pc.max_pressure, pc.approach):
        assert np.all(np.isfinite(arr)) and arr[0] == 0.0 and arr[1] > 0.0


def test_line_contact_zero_length():
    with pytest.raises(InputError) as info:
        line_contact(100.0, 0.0, 0.01, 2.2e11)
    assert info.value.field == "length" and "> 0" in info.value.allowed
