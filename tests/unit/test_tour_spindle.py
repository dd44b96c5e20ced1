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


@pytest.mark.parametrize("text, allowed", [
    ("16 000 rpm", "a number without digit-group separators ('16000 rpm')"),
    ("1,200,000 N", "a number without digit-group separators ('1200000 N')"),
    ("16,000 rpm", "an unambiguous number: '16000 rpm' (a thousands separator) or "
                   "'16.000 rpm' (a decimal comma)"),
])
def test_digit_groups_are_named_with_the_readings(text, allowed):
    """"16 000 rpm" was refused as "a known unit convertible to rad/s" (the unit is fine)."""
    with pytest.raises(InputError) as err:
        to_si(text, "rad/s" if "rpm" in text else "N", field="schedule.speed")
    assert err.value.allowed.startswith(allowed)


def test_a_temperature_in_coulomb_gets_the_celsius_spelling():
    with pytest.raises(InputError) as err:
        to_si("22 C", "temperature", field="environment.ambient_temperature")
    assert "degC" in str(err.value) and "environment.ambient_temperature" in str(err.value)
    assert to_si("22 \u00b0C", "temperature") == pytest.approx(295.15)


def test_decimal_comma_is_named_with_the_corrected_value():
    with pytest.raises(InputError) as err:
        to_si("0,5 kN", "N", field="schedule.axial_load")
    text = str(err.value)
    assert "schedule.axial_load" in text and "decimal point" in text and "'0.5 kN'" in text


# --- a sweep of the ambient temperature -------------------------------------------------
_SCENE = """
title = "spindle pair"
[[bearings]]
name = "front"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG32"
[supply]
method = "oil_air"
flow = "30 mm3/h"
[environment]
ambient_temperature = "22 degC"
{extra}
[schedule]
speed = "12000 r/min"
radial_load = "200 N"
axial_load = "0.5 kN"
steps = [{{ duration = "10 min" }}]
[outputs]
mode = "steady"
want = ["losses"]
"""


def _ambient_cases(extra: str):
    from thermobearing.scene import loads_scene
    from thermobearing.sweep_cases import expand, scene_from_case
    from thermobearing.sweep_params import parse_set

    scene = loads_scene(_SCENE.format(extra=extra))
    param = parse_set("environment.ambient_temperature=22,60", scene.to_dict())
    return [scene_from_case(c) for c in expand(scene, [param])]


def test_ambient_sweep_moves_the_temperatures_that_default_to_ambient():
    """The initial and oil-inlet temperatures a scene leaves to the ambient follow a swept
    ambient (they stayed at the base scene's ambient: a losses-only sweep of the ambient,
    evaluated at the initial temperature, gave the same losses for every value)."""
    cold, hot = _ambient_cases("")
    assert cold.environment.initial_temperature == pytest.approx(295.15)
    assert hot.environment.ambient_temperature == pytest.approx(333.15)
    assert hot.environment.initial_temperature == pytest.approx(333.15)
    assert hot.supply.inlet_temperature == pytest.approx(333.15)


def test_ambient_sweep_keeps_temperatures_the_scene_gives():
    _, hot = _ambient_cases('initial_temperature = "25 degC"')
    assert hot.environment.initial_temperature == pytest.approx(298.15)
    assert hot.supply.inlet_temperature == pytest.approx(333.15)  # inlet not given


def test_scene_round_trip_keeps_what_was_given():
    from thermobearing.scene import loads_scene

    scene = loads_scene(_SCENE.format(extra=""))
    text = scene.to_toml()
    assert "initial_temperature" not in text and "inlet_temperature" not in text
    again = loads_scene(text)
    assert again.environment == scene.environment
    assert again.supply.inlet_temperature == scene.supply.inlet_temperature
    assert not again.environment.initial_given and not again.supply.inlet_given
    given = loads_scene(_SCENE.format(extra='initial_temperature = "22 degC"'))
    assert "initial_temperature" in given.to_toml()


# --- bare sweep numbers in the scene's own units ----------------------------------------
def _spindle_scene(axial: str = '"500 N"', flow: str = '"30 mm3/h"'):
    from thermobearing.scene import loads_scene

    text = (_SCENE.format(extra="").replace('axial_load = "0.5 kN"', f"axial_load = {axial}")
            .replace('flow = "30 mm3/h"', f"flow = {flow}"))
    return loads_scene(text)


def test_bare_sweep_numbers_are_in_the_units_the_scene_was_written_in():
    """A preload written "500 N" swept with ``--set schedule.axial_load=300,800`` means
    300 and 800 N (it meant kN: 300 kN on a spindle bearing), and an oil-air flow written
    in mm^3/h is swept in mm^3/h (it meant L/min)."""
    from thermobearing.sweep_cases import expand, scene_from_case
    from thermobearing.sweep_params import parse_set

    scene = _spindle_scene()
    d = scene.to_dict()
    load = parse_set("schedule.axial_load=300,800", d)
    flow = parse_set("supply.flow=10,100", d)
    cases = [scene_from_case(c) for c in expand(scene, [load, flow])]
    assert sorted({c.schedule.steps[0].axial_load for c in cases}) == [300.0, 800.0]
    assert sorted({c.supply.flow for c in cases}) == pytest.approx([10e-9 / 3600, 100e-9 / 3600])


def test_scene_units_default_where_the_scene_gives_bare_numbers():
    scene = _spindle_scene(axial="500.0", flow="8.3e-12")
    d = scene.to_dict()
    assert d["schedule"]["steps"][0]["axial_load"] == "0.5 kN"
    assert d["supply"]["flow"].endswith("L/min")


def test_report_gives_the_oil_air_flow_in_the_scene_unit():
    from thermobearing.report_context import supply_text

    text = supply_text(_spindle_scene(), None)
    assert "30 mm^3/h at 22 degC" in text


# --- the skid check at spindle speeds ----------------------------------------------------
_SPINDLE_BEARING = {
    "name": "7014C", "kind": "angular_contact", "estimate_missing": True,
    "source": "catalogue envelope 70 x 110 x 20 mm, 15 deg; ball set typical for the size",
    "bore": "70 mm", "outer_diameter": "110 mm", "width": "20 mm",
    "ball_diameter": "11.112 mm", "n_balls": 20, "contact_angle": "15 deg",
}


def _solve(model: str, rpm: float, axial: float, radial: float = 0.0):
    from thermobearing import load_lubricant
    from thermobearing.bearing_config import bearing_from_dict
    from thermobearing.kinematic_models import KINEMATICS
    from thermobearing.state import OilSupply, OperatingPoint

    bearing = bearing_from_dict(_SPINDLE_BEARING)
    op = OperatingPoint(inner_speed=rpm * math.pi / 30, radial_load=radial, axial_load=axial)
    kin = KINEMATICS.get(model)(bearing, load_lubricant("ISO_VG32"), op,
                                contact_temperature=300.0, oil_temperature=300.0,
                                supply=OilSupply("oil_air", 30e-9 / 3600, 295.15))
    return bearing, kin


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")
def test_race_control_at_spindle_speed_is_not_reported_as_over_skidding():
    """Race control rolls by construction, yet at 24000 r/min under 300 N its cage speed
    ratio is about 6 % above paper 002's zero-speed CSR_th (the outer contact angle falls
    to a few degrees): the check said "over-skidding ... gross sliding" there."""
    from thermobearing.operating_checks import CheckLog, check_state, composite_roughness

    bearing, kin = _solve("race_control", 24000, 300.0)
    assert kin.over_skid > 0.05                      # paper 002's measure includes the shift
    check = check_state(bearing, kin)
    assert check.slip == 0.0 and check.csr_roll == kin.cage_speed_ratio
    inner, outer = (math.degrees(a) for a in check.contact_angles)
    assert inner > 20.0 > 5.0 > outer                # 15 deg nominal, turned by speed
    log = CheckLog("front", composite_roughness(bearing))
    log.record(0, check)
    lines = log.summary()
    assert not any("gross sliding of the elements" in line for line in lines), lines
    assert any("without gross sliding" in line and "outer" in line for line in lines), lines
    assert log.flagged_steps()["skid"] == 0


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")
def test_skidding_slip_is_measured_from_rolling_at_the_solved_contact_angles():
    """The skidding solver's cage at 20000 r/min, 300 N preload runs within a percent of
    rolling at its own contact angles while CSR/CSR_th - 1 is above 5 %."""
    from thermobearing.operating_checks import check_state

    bearing, kin = _solve("skidding", 20000, 300.0)
    check = check_state(bearing, kin)
    assert kin.over_skid > 0.05
    assert check.csr_roll is not None
    assert check.slip == pytest.approx(kin.cage_speed_ratio / check.csr_roll - 1.0)
    assert abs(check.slip) < 0.01


# --- the catalogue model for a 70-series bearing ------------------------------------------
_BEARING_TOML = """name = "7014C"
kind = "angular_contact"
source = "catalogue envelope 70 x 110 x 20 mm, 15 deg; ball set typical for the size"
estimate_missing = true
bore = "70 mm"
outer_diameter = "110 mm"
width = "20 mm"
ball_diameter = "11.112 mm"
n_balls = 20
contact_angle = "15 deg"
"""


def _global_scene(tmp_path, options: str):
    from thermobearing.scene import load_scene

    (tmp_path / "b7014.toml").write_text(_BEARING_TOML, encoding="utf-8")
    text = (_SCENE.format(extra="").replace('preset = "SKF6304"', 'path = "b7014.toml"')
            .replace("[outputs]", '[models]\nkinematics = "none"\nheat_sources = '
                     f'["global_friction"]\n{options}\n[outputs]'))
    (tmp_path / "scene.toml").write_text(text, encoding="utf-8")
    return load_scene(tmp_path / "scene.toml")


def test_skf_model_for_a_series_without_constants_says_how_to_go_on(tmp_path):
    """A 7014C (series 70: the SKF constants here cover 72 / 73 / 32 / 33) stopped the
    run with "series of 7014C = '7014C' is not allowed ... series= one of [...]", naming
    no place to give the series; the series is now an option of the source."""
    from thermobearing.global_friction import BearingEnvelope, infer_skf_series
    from thermobearing.simulation import Simulation

    env = BearingEnvelope("angular_contact", 0.07, 0.11, 0.02, 0.011112, "7014C")
    with pytest.raises(InputError) as err:
        infer_skf_series(env)
    text = str(err.value)
    assert "reads as series '70'" in text and "72_ACCBM" in text
    assert "global_friction = { series" in text and 'model = "palmgren"' in text
    scene = _global_scene(tmp_path, 'heat_source_options = { global_friction = '
                                    '{ series = "72_ACCBM" } }')
    loss = Simulation(scene, progress=False).run().tables["losses"]["power [W]"].sum()
    assert loss > 0.0 and math.isfinite(loss)


def test_series_option_is_refused_with_palmgren(tmp_path):
    from thermobearing.simulation import Simulation

    scene = _global_scene(tmp_path, 'heat_source_options = { global_friction = '
                                    '{ model = "palmgren", series = "72_ACCBM" } }')
    with pytest.raises(InputError, match="SKF four-term only"):
        Simulation(scene, progress=False).run()


# --- a misspelt name ----------------------------------------------------------------------
@pytest.mark.parametrize("typed, meant", [("oil-air", "oil_air"), ("Oil_Air", "oil_air"),
                                          ("oilair", "oil_air"), ("circulating", "circulation")])
def test_misspelt_supply_method_gets_the_nearest_name(typed, meant):
    from thermobearing.scene import loads_scene

    text = _SCENE.format(extra="").replace('method = "oil_air"', f'method = "{typed}"')
    with pytest.raises(InputError) as err:
        loads_scene(text)
    assert "supply.method" in str(err.value)
    assert str(err.value).endswith(f"(did you mean '{meant}'?)")


def test_an_unrelated_name_gets_no_guess():
    from thermobearing.errors import UnknownNameError

    text = str(UnknownNameError("supply.method", "oil mist", ["jet", "oil_air", "oil_bath"]))
    assert text.endswith("known names are: jet, oil_air, oil_bath")


# --- the example files ----------------------------------------------------------------------
def test_spindle_example_loads_with_its_estimates_and_units():
    from pathlib import Path

    from thermobearing.scene import load_scene
    from thermobearing.simulation import Simulation

    path = Path(__file__).resolve().parents[2] / "examples" / "spindle_pair_oil_air.toml"
    scene = load_scene(path)
    assert [b.name for b in scene.bearings] == ["front", "rear"]
    assert scene.supply.method == "oil_air"
    assert scene.supply.flow == pytest.approx(30e-9 / 3600)
    assert [s.speed * 30 / math.pi for s in scene.schedule.steps] == pytest.approx(
        [4000, 8000, 12000, 16000])
    assert scene.to_dict()["schedule"]["steps"][0]["axial_load"] == "500 N"
    estimated = Simulation(scene, progress=False).estimated_inputs()
    assert "pitch_diameter" in estimated["bearing front (7014C)"]


# --- the sweep's terminal output --------------------------------------------------------
def test_sweep_terminal_names_cases_the_checks_flag():
    """A preload typed in the wrong unit (300 kN on a 7014) put every case over the ISO 76
    stress; only summary.csv's count said so, the terminal table showed the losses."""
    import pandas as pd

    from thermobearing.commands.sweep import flagged_notes

    df = pd.DataFrame({"case": ["a", "b", "c"],
                       "schedule.axial_load": ["300 N", "300 kN", "800 kN"],
                       "steps over skid limit [-]": [0.0, 0.0, 0.0],
                       "steps over stress limit [-]": [0.0, 6.0, 6.0]})
    lines = flagged_notes(df, ["schedule.axial_load"])
    assert lines == [
        "note: 2 of 3 cases have steps with contact pressure above the stress limit (ISO 76 "
        "static-rating stress unless [checks] sets another) (summary.csv column 'steps over "
        "stress limit [-]'; first: case b, schedule.axial_load = 300 kN)"]
    assert flagged_notes(df.iloc[:1], ["schedule.axial_load"]) == []


# --- a preload written as a negative clearance ------------------------------------------
def test_negative_clearance_points_to_the_axial_load():
    from thermobearing.bearing_config import bearing_from_dict

    with pytest.raises(InputError) as err:
        bearing_from_dict({**_SPINDLE_BEARING, "diametral_clearance": "-0.01 mm"})
    text = str(err.value)
    assert "bearing.diametral_clearance" in text and "-1e-05" in text
    assert "preload" in text and "axial load" in text


# --- what an oil-air supply leaves out ----------------------------------------------------
def test_oil_air_scene_says_the_carrier_air_is_not_modelled():
    from thermobearing.simulation_bearings import _supply_notes

    notes = _supply_notes(_spindle_scene())
    assert any(n.startswith("supply oil_air:") and "carrier air" in n for n in notes), notes
    jet = _spindle_scene(flow='"2 L/min"')
    jet = type(jet).from_dict({**jet.to_dict(), "supply": {"method": "jet", "flow": "2 L/min"}})
    assert not any("carrier air" in n for n in _supply_notes(jet))
    film_only = type(jet).from_dict({**_spindle_scene().to_dict(),
                                     "outputs": {"mode": "steady", "want": ["film"]}})
    assert not any("carrier air" in n for n in _supply_notes(film_only))  # no heat source


def test_grease_scene_says_its_churning_is_not_modelled():
    """The skidding chain sets the grease's oil fraction to 0 itself, so the churning
    source's own warning never ran: a grease-lubricated spindle booked 0 W of churning
    without a word."""
    from thermobearing.simulation_bearings import _supply_notes

    base = _spindle_scene()
    grease = type(base).from_dict({**base.to_dict(), "supply": {"method": "grease"}})
    notes = _supply_notes(grease)
    assert any(n.startswith("supply grease:") and "not modelled" in n for n in notes), notes
