"""Unit strings of the scene fuzzer's unusual-spelling draws (scripts/fuzz_scenes.py,
seeds 47 on): the one-character degree signs U+2103 / U+2109 (read by the measured-file
reader, refused in a scene), and an upper-case unit whose lower case is the unit meant
(``1800 RPM``: the refusal now says so)."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG32_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.units import quantity_unit, to_si

SCENE = '\ntitle = "degree signs"\n' + SKF6304_A + VG32_JET_1LPM + """\
inlet_temperature = "35 \u2103"
[environment]
ambient_temperature = "77 \u2109"
[schedule]
speed = "1500 rpm"
radial_load = "1 kN"
axial_load = "0 N"
[outputs]
mode = "steady"
want = ["film"]
"""


def test_degree_sign_characters():
    assert to_si("35 \u2103", "temperature") == pytest.approx(308.15)
    assert to_si("95 \u2109", "temperature") == pytest.approx(308.15)
    assert to_si("10 \u2103", "temperature_difference") == pytest.approx(10.0)
    assert quantity_unit("35 \u2103") == "degC"


def test_degree_signs_in_a_scene_read_back():
    scene = loads_scene(SCENE)
    assert scene.supply.inlet_temperature == pytest.approx(308.15)
    assert scene.environment.ambient_temperature == pytest.approx(298.15)
    back = loads_scene(scene.to_toml())
    assert back.supply.inlet_temperature == pytest.approx(308.15)
    assert back.environment.ambient_temperature == pytest.approx(298.15)


def test_upper_case_unit_names_the_lower_case_one():
    with pytest.raises(InputError, match=r"'1800 RPM'.*case-sensitive: 'rpm'"):
        to_si("1800 RPM", "angular_speed", field="schedule.speed")
    with pytest.raises(InputError) as err:  # no lower-case unit of that kind: no hint
        to_si("2 KN", "force")
    assert "case-sensitive" not in str(err.value)


def test_a_number_in_a_text_without_its_unit_is_told_to_add_one():
    """``thermobearing lubricant --pressure -1`` said only 'a quantity with units
    convertible to Pa', which reads as a wrong unit."""
    with pytest.raises(InputError, match=r"'-1' .*needs its unit: '-1 Pa'"):
        to_si("-1", "Pa", field="--pressure")
    assert to_si("0.5", "dimensionless") == 0.5
