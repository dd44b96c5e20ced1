"""Bad-input audit, issue 6 (scenes) and its neighbours: every bad scene value is refused
when the scene loads, with an :class:`InputError` naming the field, the value given and
what is allowed (never a raw TypeError / ValueError, never a NaN carried into a run).

Each test edits one value of a small valid scene (:data:`BASE`) and loads it through the
public entry point :func:`thermobearing.scene.loads_scene` (what ``thermobearing check`` /
``run`` call first).
"""

from __future__ import annotations

import copy
import math

import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.scene import check_network, dumps_toml, loads_scene

BASE = {
    "title": "bad-input audit",
    "bearings": [{"name": "de", "preset": "QJ1044"}],
    "lubricant": {"preset": "ISO_VG46"},
    "supply": {"method": "jet", "flow": "15 L/min", "inlet_temperature": "35 degC"},
    "environment": {"ambient_temperature": "35 degC"},
    "schedule": {"speed": "1800 rpm", "radial_load": "1 kN", "axial_load": "10 kN",
                 "steps": [{"duration": "5 min"}, {"duration": "5 min", "axial_load": "20 kN"}]},
    "models": {"kinematics": "race_control"},
    "network": {"template": "four_node_paper002",
                "parameters": {"housing_outer_diameter": "510 mm", "housing_length": "140 mm"}},
    "solver": {"stepper": "tr_bdf2", "chunk": "300 s"},
    "outputs": {"want": ["temperatures", "losses"]},
}


def edited(path: str, value):
    """BASE with the dotted ``path`` set to ``value`` (``DELETE`` removes it), as TOML."""
    d = copy.deepcopy(BASE)
    keys = path.split(".")
    cur = d
    for k in keys[:-1]:
        cur = cur[int(k)] if isinstance(cur, list) else cur.setdefault(k, {})
    if value is DELETE:
        del cur[keys[-1]]
    else:
        cur[keys[-1]] = value
    return d


DELETE = object()


def load_error(path: str, value, error=InputError) -> InputError:
    with pytest.raises(error) as info:
        loads_scene(dumps_toml(edited(path, value)))
    return info.value


def test_base_scene_is_valid():
    scene = loads_scene(dumps_toml(BASE))
    assert len(scene.schedule.steps) == 2
    assert scene.supply.flow == pytest.approx(15e-3 / 60)


# --- issue 6: "a scene with an unknown key or model name (list the known ones)" ----------
@pytest.mark.parametrize(("path", "value", "field", "a_known_key"), [
    ("colour", "red", "scene.colour", "bearings"),
    ("supply.flw", "15 L/min", "supply.flw", "flow"),
    ("schedule.steps", [{"duration": "5 min", "sped": "9 rpm"}], "schedule.steps[0].sped",
     "duration"),
])
def test_unknown_key_names_it_and_lists_the_known_ones(path, value, field, a_known_key):
    err = load_error(path, value)
    assert err.field == field
    assert a_known_key in err.allowed


def test_unknown_supply_method_lists_known_ones():
    err = load_error("supply.method", "spray", UnknownNameError)
    assert err.field == "supply.method" and err.value == "spray"
    assert {"jet", "oil_bath", "grease"} <= set(err.known)


def test_unknown_output_lists_known_ones():
    err = load_error("outputs.want", ["temperatures", "vibes"], UnknownNameError)
    assert err.field == "outputs.want" and err.value == "vibes"
    assert "losses" in err.known


def test_unknown_network_template_lists_known_ones():
    err = load_error("network.template", "nine_node", UnknownNameError)
    assert err.field == "network.template" and "four_node_paper002" in err.known


def test_unknown_network_key_and_parameter():
    err = load_error("network.nodes", 4)
    assert err.field == "network.nodes" and "template" in err.allowed
    err = load_error("network.parameters.housing_colour", "red")
    assert err.field == "network.parameters.housing_colour"
    assert "housing_length" in err.allowed
    # ambient / oil come from [environment] / [supply]; not listed as settable here
    assert "oil_flow" not in err.allowed


def test_network_parameter_of_wrong_dimension():
    err = load_error("network.parameters.housing_length", "140 kg")
    assert err.field == "network.parameters.housing_length" and err.value == "140 kg"


def test_missing_required_network_parameters_named_before_a_run():
    # loading a scene that never builds its network must keep working ...
    scene = loads_scene(dumps_toml(edited("network.parameters", {})))
    # ... but `run` / `check` ask check_network(require=True) first (before: TypeError
    # "four_node_paper002() missing 2 required keyword-only arguments" from deep inside)
    with pytest.raises(InputError) as info:
        check_network(scene.network, require=True)
    assert info.value.field == "network.parameters"
    assert "housing_outer_diameter" in info.value.allowed
    assert "housing_length" in info.value.allowed


# --- issue 6: "a schedule with negative or zero duration"; empty schedule -----------------
@pytest.mark.parametrize("duration", ["0 min", "-1 min", "0 s"])
def test_zero_or_negative_step_duration(duration):
    err = load_error("schedule.steps",
                     [{"duration": "5 min"}, {"duration": "5 min"}, {"duration": duration}])
    assert err.field == "schedule.steps[2].duration"
    assert err.value == duration and "> 0" in err.allowed


def test_empty_schedule():
    err = load_error("schedule.steps", [])
    assert err.field == "schedule" and "at least one step" in err.allowed


def test_steps_not_an_array_of_tables():
    # before: TypeError "string indices must be integers" / "'int' object is not iterable"
    err = load_error("schedule.steps", "5 min")
    assert err.field == "schedule.steps" and "array of tables" in err.allowed
    err = load_error("schedule.steps", [{"duration": "5 min"}, 7])
    assert err.field == "schedule.steps[1]" and err.value == 7


def test_bearings_not_tables():
    # before: TypeError "string indices must be integers"
    err = load_error("bearings", "QJ1044")
    assert err.field == "bearings" and err.value == "QJ1044"


def test_negative_load_and_speed():
    # a [schedule] default is refused under the key the scene wrote (it named the first
    # step that took it, schedule.steps[0].radial_load, a field not in the file)
    err = load_error("schedule.radial_load", "-1 kN")
    assert err.field == "schedule.radial_load" and ">= 0" in err.allowed
    assert err.value == "-1 kN"
    err = load_error("schedule.speed", "-100 rpm")
    assert err.field == "schedule.speed"


def test_axial_load_steps_with_zero_step():
    d = edited("schedule", {"speed": "1800 rpm", "radial_load": "1 kN", "step_duration": "3 min",
                            "axial_load_steps": {"start": "0 kN", "stop": "4 kN", "step": "0 kN"}})
    with pytest.raises(InputError) as info:
        loads_scene(dumps_toml(d))
    assert info.value.field == "schedule.axial_load_steps" and "step > 0" in info.value.allowed


# --- neighbours: wrong-dimension units, NaN / inf numbers ---------------------------------
@pytest.mark.parametrize(("path", "value", "dimension"), [
    ("supply.flow", "33 kg", "m**3/s"),
    ("schedule.speed", "1800 kg", "rad/s"),
    ("schedule.steps", [{"duration": "5 kg"}], "s"),
    ("solver.chunk", "90 m", "s"),
    ("environment.ambient_temperature", "35 Pa", "K"),
])
def test_unit_of_the_wrong_dimension(path, value, dimension):
    err = load_error(path, value)
    given = "5 kg" if path == "schedule.steps" else value
    assert err.value == given and repr(given) in str(err)
    assert err.field == ("schedule.steps[0].duration" if path == "schedule.steps" else path)
    assert dimension in err.allowed


@pytest.mark.parametrize(("path", "value", "field"), [
    ("supply.flow", math.nan, "supply.flow"),
    ("supply.flow", math.inf, "supply.flow"),
    ("schedule.speed", math.nan, "schedule.speed"),
    ("schedule.axial_load", -math.inf, "schedule.axial_load"),
    ("environment.ambient_temperature", math.nan, "environment.ambient_temperature"),
    ("solver.chunk", math.nan, "solver.chunk"),
    ("solver.max_step", math.inf, "solver.max_step"),
])
def test_nan_or_inf_number_is_refused_at_load(path, value, field):
    # before: a bare nan speed / ambient / chunk loaded and went on into the run
    err = load_error(path, value)
    assert err.field == field
    assert isinstance(err.value, float) and not math.isfinite(err.value)
    assert "finite" in err.allowed


def test_temperature_below_absolute_zero_shows_the_value_given():
    err = load_error("environment.ambient_temperature", "-300 degC")
    # before: the message showed the converted -26.85 (K) instead of what the user wrote
    assert err.value == "-300 degC" and "absolute zero" in err.allowed
    err = load_error("supply.inlet_temperature", "-300 degC")
    assert err.field == "supply.inlet_temperature" and err.value == "-300 degC"


def test_flow_rules():
    err = load_error("supply.flow", "-1 L/min")
    assert err.field == "supply.flow" and err.value == "-1 L/min"
    err = load_error("supply.flow", "0 L/min")
    assert "zero only for an oil bath or grease" in err.allowed
    ok = loads_scene(dumps_toml(edited("supply", {"method": "grease", "flow": "0 L/min"})))
    assert ok.supply.flow == 0.0


# --- neighbours: solver settings out of range -----------------------------------------------
@pytest.mark.parametrize(("key", "value"), [
    ("rtol", 0.0), ("rtol", -1e-3), ("rtol", 5.0), ("rtol", math.nan),
    ("atol", 0.0), ("atol", math.inf),
    ("kinematics_tolerance", 0.0), ("kinematics_tolerance", 2.0),
])
def test_solver_tolerance_out_of_range(key, value):
    err = load_error(f"solver.{key}", value)
    assert err.field == f"solver.{key}"
    assert err.value == value or (math.isnan(value) and math.isnan(err.value))
    assert "(0, 1)" in err.allowed or "> 0" in err.allowed


def test_solver_tolerance_not_a_number():
    # before: ValueError "could not convert string to float: 'tight'"
    err = load_error("solver.rtol", "tight")
    assert err.field == "solver.rtol" and err.value == "tight" and "number" in err.allowed


@pytest.mark.parametrize("key", ["chunk", "max_step"])
@pytest.mark.parametrize("value", ["0 s", "-5 s"])
def test_solver_time_not_positive(key, value):
    err = load_error(f"solver.{key}", value)
    assert err.field == f"solver.{key}" and err.value == value and "> 0" in err.allowed


# --- neighbours: presets / files that do not exist ------------------------------------------
def test_unknown_scene_preset_lists_known_ones():
    from thermobearing.scene import load_scene

    with pytest.raises(UnknownNameError) as info:
        load_scene("qj1044_rgi")
    assert info.value.field == "scene" and "qj1044_rig" in info.value.known


def test_unknown_bearing_and_lubricant_presets_list_known_ones():
    from thermobearing.simulation import Simulation

    scene = loads_scene(dumps_toml(edited("bearings", [{"name": "de", "preset": "QJ1045"}])))
    with pytest.raises(UnknownNameError) as info:
        Simulation(scene, progress=False)
    assert info.value.value == "QJ1045" and "QJ1044" in info.value.known
    scene = loads_scene(dumps_toml(edited("lubricant.preset", "ISO_VG47")))
    with pytest.raises(UnknownNameError) as info:
        Simulation(scene, progress=False)
    assert info.value.value == "ISO_VG47" and "ISO_VG46" in info.value.known


def test_bearing_override_unknown_and_negative():
    from thermobearing.simulation import Simulation

    bad = [{"name": "de", "preset": "QJ1044", "overrides": {"clearance": "0.1 mm"}}]
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(dumps_toml(edited("bearings", bad))), progress=False)
    assert "clearance" in info.value.field and "diametral_clearance" in info.value.allowed
    bad = [{"name": "de", "preset": "QJ1044", "overrides": {"diametral_clearance": "-0.1 mm"}}]
    with pytest.raises(InputError) as info:
        Simulation(loads_scene(dumps_toml(edited("bearings", bad))), progress=False)
    assert info.value.field.endswith("diametral_clearance") and ">= 0" in info.value.allowed


def test_invalid_toml_is_an_input_error():
    with pytest.raises(InputError) as info:
        loads_scene("title = \n")
    assert info.value.field == "scene" and "valid TOML" in info.value.allowed


# --- neighbours: value types of tables a user writes by hand --------------------------------
def test_bearing_overrides_not_a_table():
    # before: ValueError "dictionary update sequence element #0 has length 1"
    err = load_error("bearings", [{"name": "de", "preset": "QJ1044", "overrides": "x"}])
    assert err.field == "bearings[0].overrides" and err.value == "x"


@pytest.mark.parametrize(("key", "value", "allowed"), [
    ("heat_sources", 5, "array of names"),        # before: TypeError 'int' not iterable
    ("heat_sources", ["raceway_traction", 3], "array of names"),
    ("film", ["hamrock_dowson_1977_central"], "a model name"),  # before: unhashable 'list'
    ("heat_source_options", "cage_guide", "a table"),
])
def test_models_value_types(key, value, allowed):
    err = load_error(f"models.{key}", value)
    assert err.field == f"models.{key}" and err.value == value and allowed in err.allowed


def test_lubricant_path_that_does_not_exist(tmp_path):
    # before: "lubricant preset = '<path>' ... known names are: ISO_VG100, ..." at run time
    d = edited("lubricant", {"path": "my_oil.toml"})
    with pytest.raises(InputError) as info:
        loads_scene(dumps_toml(d), base_dir=tmp_path)
    assert info.value.field == "lubricant.path" and info.value.value == "my_oil.toml"
    assert str(tmp_path / "my_oil.toml") in info.value.allowed


def test_negative_oil_bath_level_shows_the_value_given():
    err = load_error("supply", {"method": "oil_bath", "flow": "0 L/min", "level": "-5 mm"})
    assert err.field == "supply.level" and err.value == "-5 mm" and ">= 0" in err.allowed


@pytest.mark.parametrize(("path", "value", "field", "a_known_name"), [
    ("models.kinematics", "skiding", "models.kinematics", "skidding"),
    ("models.heat_sources", ["raceway_traction", "churnin"], "models.heat_sources[1]",
     "churning_cage"),
    ("models.heat_sources", "pocket", "models.heat_sources", "pocket_friction"),
    ("solver.stepper", "rk45", "solver.stepper", "tr_bdf2"),
])
def test_unknown_model_name_names_the_scene_field(path, value, field, a_known_name):
    # before: "kinematics model = 'skiding'", "stepper model = 'rk45'" (registry family,
    # not the scene field); `check` / `run` / `sweep` call check_model_names first
    from thermobearing.scene import check_model_names

    scene = loads_scene(dumps_toml(edited(path, value)))
    with pytest.raises(UnknownNameError) as info:
        check_model_names(scene)
    assert info.value.field == field and a_known_name in info.value.known


@pytest.mark.parametrize(("models", "field", "words"), [
    # before: TypeError "solve_ball() got an unexpected keyword argument 'control'" (run)
    ({"kinematics": "skidding", "control": "outer_race"}, "models.control", "race_control"),
    # before: passed `check`, refused by the model only at run time
    ({"kinematics": "race_control", "control": "magic"}, "models.control", "outer_race"),
    ({"kinematics": "race_control", "churning_heat_to": "sky"}, "models.churning_heat_to",
     "paper002"),
])
def test_model_options_checked_before_the_run(models, field, words):
    from thermobearing.scene import check_model_names

    scene = loads_scene(dumps_toml(edited("models", models)))
    with pytest.raises(InputError) as info:
        check_model_names(scene)
    assert info.value.field == field and words in info.value.allowed


def test_flow_at_the_written_limit_is_allowed():
    """1e4 L/min is the top of the allowed range as the refusal writes it; it converts to
    0.1666666666666667 m^3/s, an ulp above 1e4 / 60000, and was refused."""
    scene = loads_scene(dumps_toml(edited("supply.flow", "10000 L/min")))
    assert scene.supply.flow == pytest.approx(1e4 / 60_000.0, rel=1e-15)
    err = load_error("supply.flow", "10001 L/min")
    assert err.field == "supply.flow" and "1e4 L/min" in err.allowed
