"""Sweep ``--set`` values found by the scene fuzzer (scripts/fuzz_scenes.py, seeds 47 on):
a bare number took six significant digits (``supply.flow=1.234567891`` ran 1.23457 L/min),
and a scene that writes its quantity without a space before the unit (``"95degF"``, valid
for the scene) had bare sweep numbers read in the default unit (degC) instead of its own."""

from __future__ import annotations

import pytest
from scene_parts import SKF6304_A, VG32_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.sweep_params import parse_set
from thermobearing.units import to_si


def test_bare_numbers_keep_their_digits():
    scene = {"supply": {"flow": "33 L/min"}}
    p = parse_set("supply.flow=1.234567891,2.5", scene)
    assert p.values == ("1.234567891 L/min", "2.5 L/min")
    r = parse_set("supply.flow=0.1:0.3:0.1", scene)  # a range: no float noise in the text
    assert r.values == ("0.1 L/min", "0.2 L/min", "0.3 L/min")


@pytest.mark.parametrize(("written", "unit"), [("95degF", "degF"), ("+308.15kelvin", "kelvin"),
                                               (".5e2°C", "°C")])
def test_bare_numbers_take_a_unit_written_without_a_space(written, unit):
    scene = {"supply": {"inlet_temperature": written}}
    p = parse_set("supply.inlet_temperature=100,120", scene)
    assert p.values == (f"100 {unit}", f"120 {unit}")
    assert to_si(p.values[0], "temperature") == pytest.approx(to_si(f"100 {unit}", "K"))


def test_speed_written_without_a_space_in_a_step():
    scene = {"schedule": {"steps": [{"speed": "1.5E+03rad/min"}]}}
    p = parse_set("schedule.speed=1000,2000", scene)
    assert p.values == ("1000 rad/min", "2000 rad/min")


def test_a_range_of_a_billion_values_is_refused_before_it_is_built():
    """``--set supply.flow=1:1e9:1`` made 1e9 value strings and hung the command."""
    scene = {"supply": {"flow": "33 L/min"}}
    with pytest.raises(InputError, match=r"--set supply.flow = '1:1e9:1'.*at most 10000 "
                                         r"values \(this one gives 1e\+09"):
        parse_set("supply.flow=1:1e9:1", scene)
    with pytest.raises(InputError, match="at most 10000 values"):  # inf values, no overflow
        parse_set("supply.flow=1:1e308:1e-308", scene)
    assert len(parse_set("supply.flow=1:10000:1", scene).values) == 10_000


def test_a_product_of_too_many_cases_is_refused():
    from thermobearing.scene import loads_scene
    from thermobearing.sweep_cases import expand
    from thermobearing.sweep_params import SweepParameter

    scene = loads_scene(
        'title = "t"\n' + SKF6304_A + VG32_JET_1LPM + '[schedule]\n'
        'speed = "1500 rpm"\nradial_load = "1 kN"\naxial_load = "0 N"\n[outputs]\n'
        'mode = "steady"\nwant = ["film"]\n')
    flows = SweepParameter("supply.flow", tuple(f"{i + 1} L/min" for i in range(200)))
    speeds = SweepParameter("schedule.speed", tuple(f"{i + 1} rpm" for i in range(51)))
    with pytest.raises(InputError, match=r"supply.flow \(200\) x schedule.speed \(51\).*at "
                                         r"most 10000 cases.*10200"):
        expand(scene, [flows, speeds])
