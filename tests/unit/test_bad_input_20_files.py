"""Bearing and lubricant values beyond physical sense (session-20 probes of single fields
at 1e-300 .. 1e300): a deep-groove clearance at which the balls leave their grooves is
refused as the scene's override (15 mm on the SKF 6304 was 'bearing.pitch_diameter ...
raceway diameter <= bore', 1.5 mm 'diametral_clearance' at the first load distribution);
a Barus alpha or a Roelands z far above any oil's is refused naming the lubricant file's
key (alpha = 2e22 1/Pa and z = 6e29 stopped the ball solver with a ZeroDivisionError,
z = 6 was refused as 'pressure = 4.7e8 Pa', no key of a file)."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import lubricant_from_dict
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "probe"
[[bearings]]
name = "a"
preset = "SKF6304"
overrides = {{ diametral_clearance = "{clearance}" }}
[lubricant]
preset = "ISO_VG68"
[supply]
method = "jet"
flow = "2 L/min"
[schedule]
speed = "3000 rpm"
radial_load = "1 kN"
axial_load = "100 N"
step_duration = "1 min"
[models]
kinematics = "race_control"
[outputs]
mode = "steady"
want = ["losses"]
"""


@pytest.mark.parametrize("clearance", ["1.5 mm", "15 mm", "1e300 mm"])
def test_a_clearance_that_frees_the_balls_is_refused_as_the_override(clearance: str) -> None:
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(SCENE.format(clearance=clearance)), progress=False)
    assert info.value.field == "bearings[0].overrides.diametral_clearance"
    assert info.value.value == clearance
    # 2 (f_i + f_o - 1) D of the SKF 6304 preset
    b = load_bearing("SKF6304")
    limit = 2 * (b.inner_conformity + b.outer_conformity - 1) * b.ball_diameter
    assert f"{limit * 1e3:.4g} mm" in info.value.allowed


def test_a_large_clearance_below_the_limit_still_runs() -> None:
    res = Simulation(loads_scene(SCENE.format(clearance="0.45 mm")), progress=False).run()
    assert float(res.tables["losses"]["power [W]"].sum()) > 0.0


def _oil(pressure: dict) -> dict:
    return {"name": "probe", "source": "probe", "kind": "mineral",
            "viscosity": {"law": "astm_d341", "nu40": "68 mm**2/s", "nu100": "8.7 mm**2/s"},
            "pressure_viscosity": pressure,
            "density": {"value": "880 kg/m**3", "reference_temperature": "15 degC",
                        "temperature_law": "astm_d1250_lube"},
            "thermal": {"model": "cragoe"}}


@pytest.mark.parametrize(("pressure", "key", "words"), [
    ({"law": "barus", "alpha": "2e22 1/Pa"}, "alpha", "up to 1e-7 1/Pa"),
    ({"law": "barus", "alpha": "2e-5 1/Pa"}, "alpha", "up to 1e-7 1/Pa"),
    ({"law": "roelands", "z": 6e29}, "z", "up to 1.5"),
    ({"law": "roelands", "z": 1.8}, "z", "up to 1.5"),
])
def test_pressure_viscosity_far_above_any_oil_is_refused(pressure, key, words) -> None:
    with pytest.raises(InputError) as info:
        lubricant_from_dict(_oil(pressure))
    assert info.value.field.endswith(f"pressure_viscosity.{key}")
    assert words in info.value.allowed


@pytest.mark.parametrize("pressure", [{"law": "barus", "alpha": "1e-7 1/Pa"},
                                      {"law": "barus", "alpha": "1.3e-8 1/Pa"},
                                      {"law": "roelands", "z": 1.5},
                                      {"law": "roelands", "z": 0.6}])
def test_pressure_viscosity_of_real_oils_loads(pressure) -> None:
    oil = lubricant_from_dict(_oil(pressure))
    assert float(oil.dynamic_viscosity(313.15)) > 0.0


SHARED = """
title = "share probe"
[[bearings]]
name = "a"
preset = "SKF6304"
load_share = {{ radial = {share} }}
[lubricant]
preset = "ISO_VG68"
[supply]
method = "jet"
flow = "2 L/min"
[schedule]
speed = "3000 rpm"
radial_load = "{radial}"
axial_load = "0 N"
step_duration = "1 min"
[outputs]
mode = "steady"
want = ["losses"]
"""


@pytest.mark.parametrize(("share", "radial", "words"), [
    ("5e29", "1 kN", "up to 100"),
    ("-200.0", "1 kN", "fraction >= 0"),
    ("50", "0.1 GN", "within 1e+09 N"),
])
def test_a_load_share_beyond_sense_is_refused_as_the_share(share, radial, words) -> None:
    with pytest.raises(InputError) as info:
        loads_scene(SHARED.format(share=share, radial=radial))
    assert info.value.field == "bearings[0].load_share.radial"
    assert words in info.value.allowed


def test_a_lever_arm_share_above_one_loads() -> None:
    scene = loads_scene(SHARED.format(share="1.5", radial="1 kN"))
    assert scene.bearings[0].radial_share == 1.5


def test_a_sweep_may_set_a_load_share_the_scene_leaves_out(tmp_path) -> None:
    from thermobearing.sweep import expand, parse_set

    scene = loads_scene(SHARED.format(share="1", radial="1 kN").replace(
        "load_share = { radial = 1 }\n", ""))
    assert scene.bearings[0].load_share == {}
    (param,) = [parse_set("bearings.0.load_share.radial=0.5,1.5", scene.to_dict())]
    cases = expand(scene, [param])
    shares = sorted(loads_scene(c.scene_toml).bearings[0].radial_share for c in cases)
    assert shares == [0.5, 1.5]
    with pytest.raises(InputError, match="load_share"):
        expand(scene, [parse_set("bearings.0.load_share.radial=1e300", scene.to_dict())])


def test_a_roller_clearance_that_leaves_no_ring_names_the_override() -> None:
    text = SCENE.format(clearance="30 mm").replace('preset = "SKF6304"', 'preset = "NU214"') \
        .replace('axial_load = "100 N"', 'axial_load = "0 N"')
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(text), progress=False)
    assert info.value.field == "bearings[0].overrides.diametral_clearance"
    b = load_bearing("NU214")
    room = 2 * min(b.pitch_diameter - b.roller_diameter - b.bore,
                   b.outer_diameter - b.pitch_diameter - b.roller_diameter)
    assert f"{room * 1e3:.4g} mm" in info.value.allowed
