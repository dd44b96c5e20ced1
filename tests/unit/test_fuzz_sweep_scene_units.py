"""Scene fuzzing (scripts/fuzz_scenes.py, scenes written in other units): a scene that gives
its inlet, ambient or initial temperature in kelvin or degF, or its bath level in cm, was
written back (``Scene.to_dict``) in degC and mm, so a sweep's bare numbers took those:
``--set supply.inlet_temperature=300,350`` on a scene written in kelvin ran at 300 and
350 degC (README: a bare number is in the scene's own unit of the field). The scene now
keeps the units it was written in, as it did for the flow and the schedule."""

from __future__ import annotations

import pytest

from thermobearing.scene import loads_scene
from thermobearing.sweep_params import parse_set
from thermobearing.units import to_si

SCENE = """
title = "scene in kelvin, degF and cm"

[[bearings]]
name = "a"
preset = "SKF6304"

[lubricant]
preset = "ISO_VG68"

[supply]
method = "oil_bath"
level = "1.2 cm"
inlet_temperature = "313.15 K"

[environment]
ambient_temperature = "95 degF"
initial_temperature = "280 K"

[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "500 N", axial_load = "0 N" }]

[outputs]
mode = "steady"
want = ["film"]
"""


def _swept(spec: str, kind: str) -> list[float]:
    scene = loads_scene(SCENE)
    param = parse_set(spec, scene.to_dict())
    return [to_si(v, kind) for v in param.values]


def test_written_back_in_the_scenes_units():
    d = loads_scene(SCENE).to_dict()
    assert d["supply"]["inlet_temperature"].endswith(" K")
    assert d["supply"]["level"].endswith(" cm")
    assert d["environment"]["ambient_temperature"].endswith(" degF")
    assert d["environment"]["initial_temperature"].endswith(" K")


def test_bare_sweep_numbers_are_in_the_scenes_units():
    assert _swept("supply.inlet_temperature=300,350", "temperature") == pytest.approx(
        [300.0, 350.0])
    assert _swept("supply.level=0.5,2", "length") == pytest.approx([0.005, 0.02])
    assert _swept("environment.ambient_temperature=32,212", "temperature") == pytest.approx(
        [273.15, 373.15])
    assert _swept("environment.initial_temperature=250", "temperature") == pytest.approx(
        [250.0])


def test_round_trip_keeps_the_values_and_units():
    scene = loads_scene(SCENE)
    back = loads_scene(scene.to_toml())
    assert back == scene
    assert back.to_dict() == scene.to_dict()


def test_scene_in_degc_is_written_in_degc():
    d = loads_scene(SCENE.replace('"313.15 K"', '"40 degC"').replace(
        '"95 degF"', '"35 degC"')).to_dict()
    assert d["supply"]["inlet_temperature"] == "40 degC"
    assert d["environment"]["ambient_temperature"] == "35 degC"
