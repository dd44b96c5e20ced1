"""Scene temperatures outside the oil's property laws or the air model (session-19 fuzz
probes): each is refused before the run, naming its scene field.

An oil inlet at 5000 degC passed the scene checks (the viscosity law is finite there) and
was refused by the network build as ``temperature = 5273.15`` "set by [network] parameters
housing_length, ..." (Cragoe's conductivity of the oil is negative there): the message sent
the user to the wrong table. An ambient of 1e4 degC stopped the run as ``temperature =
5286.575`` (the air film's), naming no scene field at all."""

from __future__ import annotations

import dataclasses

import pytest

from thermobearing.errors import InputError
from thermobearing.lubricant import load_lubricant
from thermobearing.lubricant_properties import check_liquid_temperature
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.units import to_si

SCENE = """
title = "probe"
[[bearings]]
name = "de"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "3 L/min"
inlet_temperature = "{inlet}"
[environment]
ambient_temperature = "{ambient}"
initial_temperature = "{initial}"
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{{}}]
"""


#: scene field -> (section, attribute) of the Scene dataclasses
_FIELDS = {"inlet": ("supply", "inlet_temperature"),
           "ambient": ("environment", "ambient_temperature"),
           "initial": ("environment", "initial_temperature")}


def _refusal(**temps: str) -> InputError:
    """The Simulation's refusal of a scene with these temperatures. A scene file refuses
    a temperature at or above the 300 degC runaway limit itself (test_hl22_report_wording);
    the checks against the oil's laws and the air model are reached by a scene built in
    code, whose temperatures are set on the dataclasses."""
    base = loads_scene(SCENE.format(inlet="35 degC", ambient="30 degC", initial="30 degC"))
    scene = base
    for key, value in temps.items():
        section, attr = _FIELDS[key]
        scene = dataclasses.replace(scene, **{section: dataclasses.replace(
            getattr(scene, section), **{attr: to_si(value, "temperature")})})
    with pytest.raises(InputError) as info:
        Simulation(scene, progress=False)
    return info.value


@pytest.mark.parametrize(("key", "field"), [
    ("inlet", "supply.inlet_temperature"),
    ("ambient", "environment.ambient_temperature"),
    ("initial", "environment.initial_temperature"),
])
def test_a_scene_file_refuses_them_at_the_runaway_limit(key: str, field: str) -> None:
    values = {"inlet": "35 degC", "ambient": "30 degC", "initial": "30 degC", key: "5000 degC"}
    with pytest.raises(InputError) as info:
        loads_scene(SCENE.format(**values))
    assert info.value.field == field and "runaway limit" in info.value.allowed


@pytest.mark.parametrize(("key", "field", "value"), [
    ("inlet", "supply.inlet_temperature", "5000 degC"),
    ("inlet", "supply.inlet_temperature", "1e300 degC"),
    ("ambient", "environment.ambient_temperature", "1e4 degC"),
    ("initial", "environment.initial_temperature", "1e4 degC"),
])
def test_temperature_beyond_the_oil_laws_names_its_field(key: str, field: str,
                                                         value: str) -> None:
    exc = _refusal(**{key: value})
    assert exc.field == field
    assert "network" not in str(exc)
    assert "positive" in exc.allowed or "density" in exc.allowed


def test_ambient_beyond_the_air_model_names_its_field() -> None:
    # 1800 degC: the oil's laws are still positive there (Cragoe's k turns negative at
    # about 1850 degC), the air model ends at 2000 K
    exc = _refusal(ambient="1800 degC", initial="30 degC")
    assert exc.field == "environment.ambient_temperature"
    assert "2000 K for air" in exc.allowed


def test_oil_density_and_thermal_laws_checked_with_the_viscosity() -> None:
    oil = load_lubricant("ISO_VG46")
    check_liquid_temperature(oil, "x", 473.15)  # 200 degC: inside every law
    with pytest.raises(InputError) as info:
        check_liquid_temperature(oil, "supply.inlet_temperature", 5273.15)
    assert info.value.field == "supply.inlet_temperature"
    assert "cragoe" in info.value.allowed


def test_hot_but_valid_temperatures_still_run_the_checks() -> None:
    scene = loads_scene(SCENE.format(inlet="150 degC", ambient="180 degC", initial="180 degC"))
    Simulation(scene, progress=False)
