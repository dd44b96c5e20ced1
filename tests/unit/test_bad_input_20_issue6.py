"""What bad input gets (session-20 issue 6): ``thermobearing check`` decides the global
friction source's refusals that ``run`` gave at its first step (a deep-groove bearing under
axial load without C0, an SKF series the designation does not give); a speed, a load, an
oil flow and a ``[solver] max_step`` beyond physical sense are refused at scene load naming
the field, the value and the range allowed (1e300 rpm was a bare OverflowError, 1e300 N
'residual nan', 1e150 L/min 'temperature = nan' in the stepper, max_step = 1e-9 s an
endless run); 'Mm' (the megametre) is refused with the 'mm' reading; a swept supply.flow
that changes no result is named before the runs, and a swept path whose cases gave
identical results is named after them."""

from __future__ import annotations

import math

import pytest

from thermobearing.commands import check as check_command
from thermobearing.errors import InputError
from thermobearing.scene import MAX_OUTPUT_ROWS, loads_scene
from thermobearing.scene_checks import check_global_friction
from thermobearing.simulation import Simulation
from thermobearing.sweep import check_cases, expand, identical_results, parse_set, run_sweep
from thermobearing.units import to_si

SCENE = """
title = "issue 6 probe"
[[bearings]]
name = "a"
{bearing}
[lubricant]
preset = "ISO_VG68"
[supply]
{supply}
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "30 degC"
[schedule]
speed = "{speed}"
radial_load = "{radial}"
axial_load = "{axial}"
step_duration = "2 min"
[models]
{models}
{extra}
[outputs]
mode = "{mode}"
want = {want}
"""

GLOBAL = 'kinematics = "none"\nheat_sources = ["global_friction"]'


def _toml(bearing: str = 'preset = "SKF6304"', supply: str = 'method = "jet"\nflow = "2 L/min"',
          speed: str = "3000 rpm", radial: str = "1000 N", axial: str = "0 N",
          models: str = 'kinematics = "race_control"', extra: str = "",
          mode: str = "steady", want: str = '["losses"]') -> str:
    return SCENE.format(bearing=bearing, supply=supply, speed=speed, radial=radial,
                        axial=axial, models=models, extra=extra, mode=mode, want=want)


def _check(text: str, tmp_path) -> None:
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")

    class Args:
        scene = str(path)

    check_command.run(Args())


# --- 1. check decides what the global_friction source refuses at run's first step -----------
def test_check_refuses_a_deep_groove_bearing_under_axial_load_without_c0(tmp_path) -> None:
    text = _toml(axial="300 N", models=GLOBAL)
    with pytest.raises(InputError) as checked:
        _check(text, tmp_path)
    with pytest.raises(InputError) as ran:
        Simulation(loads_scene(text), progress=False).run()
    assert checked.value.field == "models.heat_source_options.global_friction.static_load_rating"
    assert str(checked.value) == str(ran.value)


def test_check_refuses_the_series_a_designation_does_not_give(tmp_path) -> None:
    text = _toml(bearing='path = "../../examples/spindle_7014C_catalogue.toml"',
                 models=GLOBAL)
    # the bearing path is read from the scene's folder: write the scene beside examples/
    from pathlib import Path

    here = Path(__file__).resolve().parents[2] / "examples"
    text = text.replace("../../examples/", str(here) + "/")
    with pytest.raises(InputError) as checked:
        _check(text, tmp_path)
    with pytest.raises(InputError) as ran:
        Simulation(loads_scene(text), progress=False).run()
    assert "7014C" in str(checked.value) and "series" in str(checked.value)
    assert str(checked.value) == str(ran.value)


def test_check_refuses_the_d1842926_series(tmp_path) -> None:
    text = _toml(bearing='preset = "D1842926"', models=GLOBAL)
    with pytest.raises(InputError, match="D1842926.*series"):
        _check(text, tmp_path)


def test_check_refuses_c0_missing_at_a_later_step_of_a_load_sweep() -> None:
    text = _toml(models=GLOBAL).replace(
        'axial_load = "0 N"', 'axial_load_steps = { start = "0 N", stop = "200 N", '
        'step = "100 N" }')
    sim = Simulation(loads_scene(text), progress=False)
    with pytest.raises(InputError, match=r"\(100 N here"):
        check_global_friction(sim)


@pytest.mark.parametrize("extra", [
    'heat_source_options = { global_friction = { static_load_rating = "7.8 kN" } }',
    'heat_source_options = { global_friction = { model = "palmgren" } }'])
def test_check_passes_the_global_friction_scenes_that_run(extra: str) -> None:
    text = _toml(axial="300 N", models=GLOBAL + "\n" + extra)
    sim = Simulation(loads_scene(text), progress=False)
    check_global_friction(sim)
    losses = sim.run().tables["losses"]
    assert float(losses["power [W]"].sum()) > 0.0


# --- 2-4. values beyond physical sense refused at load, naming field, value and range ------
@pytest.mark.parametrize(("key", "value", "field", "words"), [
    ("speed", "1e300 rpm", "schedule.speed", "0 to 1e6 rpm"),
    ("speed", "2e6 rpm", "schedule.speed", "0 to 1e6 rpm"),
    ("radial", "1e300 N", "schedule.radial_load", "0 to 1e9 N"),
    ("axial", "2 GN", "schedule.axial_load", "0 to 1e9 N"),
])
def test_a_step_beyond_any_bearing_is_refused_at_load(key, value, field, words) -> None:
    with pytest.raises(InputError) as info:
        loads_scene(_toml(**{key: value}))
    assert info.value.field == field
    assert info.value.value == value
    assert words in info.value.allowed


def test_the_fastest_bearings_in_service_still_load() -> None:
    scene = loads_scene(_toml(speed="5e5 rpm", radial="1e8 N"))
    assert scene.schedule.steps[0].speed == pytest.approx(5e5 * math.pi / 30)


def test_a_step_made_in_code_keeps_the_bounds() -> None:
    import dataclasses

    step = loads_scene(_toml()).schedule.steps[0]
    with pytest.raises(InputError, match="step.speed"):
        dataclasses.replace(step, speed=1e300)


def test_the_ball_solver_refuses_an_overflowing_speed_by_name() -> None:
    from thermobearing import load_lubricant
    from thermobearing.geometry import load_bearing
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.skidding.ball_residual import ball_residual_system
    from thermobearing.state import OilSupply

    bearing = load_bearing("SKF6304")
    models = default_ball_models(bearing, load_lubricant("ISO_VG68"), temperature=313.15,
                                 speed=300.0, supply=OilSupply(method="jet", flow_rate=3e-5,
                                                                  inlet_temperature=313.15))
    with pytest.raises(InputError) as info:
        ball_residual_system(bearing, models, 1e300, 1000.0, 0.0)
    assert info.value.field == "speed"


@pytest.mark.parametrize("flow", ["1e150 L/min", "2e4 L/min", "1 m**3/s"])
def test_an_oil_flow_beyond_any_bearing_is_refused_at_load(flow: str) -> None:
    with pytest.raises(InputError) as info:
        loads_scene(_toml(supply=f'method = "circulation"\nflow = "{flow}"'))
    assert info.value.field == "supply.flow"
    assert info.value.value == flow
    assert "1e4 L/min" in info.value.allowed


def test_max_step_that_forces_more_steps_than_allowed_is_refused() -> None:
    with pytest.raises(InputError) as info:
        loads_scene(_toml(mode="transient", want='["temperatures"]',
                          extra='[network]\ntemplate = "four_node_paper002"\n'
                                '[solver]\nmax_step = "1e-9 s"'))
    assert info.value.field == "solver.max_step"
    floor = 120.0 / MAX_OUTPUT_ROWS
    assert f"{floor:.3g} s" in info.value.allowed


def test_max_step_at_the_floor_loads_and_a_steady_scene_does_not_care() -> None:
    network = '[network]\ntemplate = "four_node_paper002"\n'
    loads_scene(_toml(mode="transient", want='["temperatures"]',
                      extra=network + f'[solver]\nmax_step = "{120.0 / MAX_OUTPUT_ROWS} s"'))
    loads_scene(_toml(extra='[solver]\nmax_step = "1e-9 s"'))


# --- 5. megametre --------------------------------------------------------------------------
@pytest.mark.parametrize(("value", "kind", "meant"), [
    ("3 Mm", "length", "'3 mm'"),
    ("68 Mm2/s", "kinematic_viscosity", "'68 mm2/s'"),
    ("0.5 Mm**3/h", "volume_flow", "'0.5 mm**3/h'"),
])
def test_megametres_are_refused_with_the_mm_reading(value, kind, meant) -> None:
    with pytest.raises(InputError) as info:
        to_si(value, kind, field="f")
    assert info.value.field == "f" and info.value.value == value
    assert f"did you mean {meant}" in info.value.allowed


def test_mm_and_mega_units_still_read() -> None:
    assert to_si("3 mm", "length") == pytest.approx(3e-3)
    assert to_si("3 MPa", "pressure") == pytest.approx(3e6)
    assert to_si("3 MN", "force") == pytest.approx(3e6)


def test_a_bearing_override_in_megametres_names_its_field() -> None:
    text = _toml(bearing='preset = "SKF6304"\noverrides = { diametral_clearance = "10 Mm" }')
    with pytest.raises(InputError, match="did you mean '10 mm'"):
        Simulation(loads_scene(text), progress=False)


# --- 6. a swept flow that changes nothing ---------------------------------------------------
@pytest.mark.parametrize(("supply", "models", "why"), [
    ('method = "jet"\nflow = "2 L/min"', 'kinematics = "race_control"', "cap of 1"),
    ('method = "oil_bath"\nlevel = "10 mm"\nflow = "1 L/min"', 'kinematics = "race_control"',
     "supply.level"),
    ('method = "circulation"\nflow = "2 L/min"', GLOBAL, "no heat source"),
])
def test_a_flow_sweep_of_a_losses_only_scene_says_the_flow_is_unused(supply, models,
                                                                     why) -> None:
    scene = loads_scene(_toml(supply=supply, models=models))
    cases = expand(scene, [parse_set("supply.flow=2,20", scene.to_dict())])
    (line,) = check_cases(cases)
    assert line.startswith("sweep: supply.flow is swept but not used")
    assert why in line


def test_a_flow_that_changes_the_churning_is_not_called_unused() -> None:
    scene = loads_scene(_toml())
    cases = expand(scene, [parse_set("supply.flow=0.01,20", scene.to_dict())])
    assert check_cases(cases) == []
    # with a network the flow is the oil stream's
    scene = loads_scene(_toml(mode="transient", want='["temperatures"]',
                              extra='[network]\ntemplate = "four_node_paper002"\nparameters = '
                                    '{ housing_outer_diameter = "80 mm", housing_length = '
                                    '"40 mm", shaft_diameter = "20 mm", shaft_length = '
                                    '"100 mm" }'))
    cases = expand(scene, [parse_set("supply.flow=2,20", scene.to_dict())])
    assert check_cases(cases) == []


def test_a_sweep_whose_cases_give_identical_results_names_the_path(tmp_path) -> None:
    scene = loads_scene(_toml())
    params = [parse_set("checks.skid_limit=2,5", scene.to_dict()),
              parse_set("schedule.speed=1000,2000", scene.to_dict())]

    def runner(toml: str) -> dict[str, float]:
        # the results depend on the speed only
        speed = loads_scene(toml).schedule.steps[0].speed
        return {"mean total loss [W]": 0.01 * speed, "max over-skidding [%]": 0.0}

    df = run_sweep(scene, params, tmp_path, runner=runner, workers=1, progress=False,
                   check=False)
    (line,) = df.attrs["identical"]
    assert line.startswith("note: checks.skid_limit changed no result")


def test_identical_results_judges_only_paths_with_two_values() -> None:
    scene = loads_scene(_toml())
    cases = expand(scene, [parse_set("checks.skid_limit=2", scene.to_dict())])
    done = {c.case_id: {"result": {"x": 1.0}} for c in cases}
    assert identical_results(cases, done) == {}


def test_check_passes_a_global_friction_scene_at_rest_as_run_does() -> None:
    """At rest the run books 0 W without calling any source, so a bearing whose SKF
    series is unknown runs (fuzz seed 72 case 23: CRB_50x75x16 at 0 rpm); check agrees."""
    text = _toml(bearing='preset = "CRB_50x75x16"', speed="0 rpm", models=GLOBAL)
    sim = Simulation(loads_scene(text), progress=False)
    check_global_friction(sim)
    assert float(sim.run().tables["losses"]["power [W]"].sum()) == 0.0
    moving = Simulation(loads_scene(_toml(bearing='preset = "CRB_50x75x16"', models=GLOBAL)),
                        progress=False)
    with pytest.raises(InputError, match="series"):
        check_global_friction(moving)
