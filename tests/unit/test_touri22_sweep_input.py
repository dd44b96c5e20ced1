"""User tour 22 (oil-flow what-if of an NU 214 on a 1 L/min jet at 40 degC), bad sweep input.

* ``--set supply.inlet_temperature=313`` (313 K meant) ran a 313 degC jet without a word:
  the oil node reached 285.6 degC and the rollers 236 degC; the summary flagged only the
  film limit. A swept temperature at or above the 300 degC runaway limit is now refused
  (with the kelvin reading when the number was bare), and a bare number that reads as a
  hot temperature but as a usual one in kelvin is said before the runs.
* ``--set supply.flow=`` (an empty list) was refused as ``--set = 'supply.flow=' is not
  allowed: 'path=value1,...'``, naming no field and no reason.
* ``run_sweep`` with a parameter without values returned an empty table without a word,
  and with no parameter ran the base scene as a one-case "sweep".
"""

from __future__ import annotations

import pytest
from nu214_scene import nu214_jet_scene

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.sweep import SweepParameter, parse_set, run_sweep
from thermobearing.sweep_cases import expand

SCENE = nu214_jet_scene(title="tour 22 sweep input", schedule="""radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{ speed = "3000 rpm" }]""", want='["losses"]')


@pytest.fixture(scope="module")
def scene():
    return loads_scene(SCENE)


def _runner(scene_toml: str) -> dict[str, float]:
    """A stand-in for a run: the case's inlet temperature as a number."""
    return {"mean total loss [W]": loads_scene(scene_toml).supply.inlet_temperature}


@pytest.mark.parametrize("path", ["supply.inlet_temperature",
                                  "environment.ambient_temperature",
                                  "environment.initial_temperature"])
def test_a_bare_kelvin_number_above_the_runaway_limit_is_refused_with_the_k_reading(
        scene, path):
    with pytest.raises(InputError) as err:
        parse_set(f"{path}=313", scene.to_dict())
    text = str(err.value)
    assert f"--set {path} = '313 degC'" in text
    assert "300 degC runaway limit" in text
    assert "write '313 K' (39.85 degC)" in text


@pytest.mark.parametrize("spec", ["supply.inlet_temperature=300 degC",
                                  "supply.inlet_temperature=40,320 degC",
                                  "supply.inlet_temperature=600 degF",
                                  "supply.inlet_temperature=280:320:20"])
def test_any_swept_temperature_at_or_above_the_runaway_limit_is_refused(scene, spec):
    with pytest.raises(InputError, match="below the 300 degC runaway limit"):
        parse_set(spec, scene.to_dict())


def test_an_explicit_unit_gets_no_kelvin_hint(scene):
    with pytest.raises(InputError) as err:
        parse_set("supply.inlet_temperature=313 degC", scene.to_dict())
    assert "K'" not in str(err.value)


def test_a_hot_bare_number_that_reads_as_kelvin_is_noted(scene):
    p = parse_set("supply.inlet_temperature=40,298", scene.to_dict())
    assert p.values == ("40 degC", "298 degC")  # still read in the scene's unit
    assert len(p.notes) == 1
    assert "supply.inlet_temperature = 298 is read as 298 degC" in p.notes[0]
    assert "write '298 K' (24.85 degC)" in p.notes[0]


@pytest.mark.parametrize("spec", ["supply.inlet_temperature=30,40,60",
                                  "supply.inlet_temperature=200 degC",
                                  "supply.inlet_temperature=313 K",
                                  "supply.inlet_temperature=104 degF",
                                  "supply.flow=298"])
def test_usual_values_and_explicit_units_give_no_note(scene, spec):
    assert parse_set(spec, scene.to_dict()).notes == ()


def test_the_note_is_said_before_the_runs(scene, tmp_path, capsys):
    p = parse_set("supply.inlet_temperature=250", scene.to_dict())
    df = run_sweep(scene, [p], tmp_path, runner=_runner, workers=1, progress=False,
                   check=False)
    assert df["mean total loss [W]"].tolist() == pytest.approx([523.15])
    assert "for kelvin write '250 K' (-23.15 degC)" in capsys.readouterr().err


def test_an_empty_list_names_the_field_and_asks_for_a_value(scene):
    with pytest.raises(InputError) as err:
        parse_set("supply.flow=", scene.to_dict())
    assert "--set supply.flow = ''" in str(err.value)
    assert "at least one value" in str(err.value)


def test_a_parameter_without_values_is_refused(scene, tmp_path):
    with pytest.raises(InputError, match="--set supply.flow = '' .*at least one value"):
        expand(scene, [SweepParameter("supply.flow", ())])
    with pytest.raises(InputError, match="at least one value"):
        run_sweep(scene, [SweepParameter("supply.flow", ())], tmp_path, runner=_runner,
                  workers=1, progress=False)


def test_a_sweep_of_no_field_is_refused(scene, tmp_path):
    with pytest.raises(InputError, match="params .*at least one swept field"):
        run_sweep(scene, [], tmp_path, runner=_runner, workers=1, progress=False)
    assert not (tmp_path / "cases.jsonl").exists()


def test_a_combination_the_scene_refuses_names_the_case(scene):
    # 'supply.method=jet,oil_bath' x inlet temperatures: said only "supply.level is
    # missing: an oil level for an oil bath"
    d = scene.to_dict()
    params = [parse_set("supply.method=jet,oil_bath", d),
              parse_set("supply.inlet_temperature=30,40", d)]
    with pytest.raises(InputError) as err:
        expand(scene, params)
    text = str(err.value)
    assert "(supply.method=oil_bath, supply.inlet_temperature=30 degC)" in text
    assert "supply.level is missing: an oil level for an oil bath" in text
    assert text.endswith("no case was run (every case is checked before the first one "
                         "runs)")
    assert err.value.field == "supply.level"  # the field stays the scene's


@pytest.mark.parametrize("spec, bare", [
    ("supply.inlet_temperature=313.15 K,50,104 degF", "'50'"),
    ("supply.flow=1 L/min,2,60 L/h", "'2'")])
def test_a_bare_value_among_values_with_their_own_units_is_refused(scene, spec, bare):
    # the bare 50 took the last value's unit: 50 degF (10 degC) on a scene written in degC
    with pytest.raises(InputError) as err:
        parse_set(spec, scene.to_dict())
    assert f"here {bare} has none while other values carry their own" in str(err.value)


@pytest.mark.parametrize("spec, values", [
    ("supply.flow=15,33 L/min", ("15 L/min", "33 L/min")),
    ("supply.flow=0.5 L/min,2", ("0.5 L/min", "2 L/min")),
    ("supply.inlet_temperature=30 degC,313.15 K", ("30 degC", "313.15 K"))])
def test_a_unit_after_the_list_or_with_each_value_still_reads(scene, spec, values):
    assert parse_set(spec, scene.to_dict()).values == values


RUN_UP = nu214_jet_scene(title="tour 22 run-up", schedule="""radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "5 min"
steps = [{ speed = "3000 rpm" }, { speed = "6000 rpm" }]""", want='["losses"]')


def test_a_schedule_field_that_differs_between_steps_is_said_to_be_replaced(tmp_path,
                                                                            capsys):
    # '--set schedule.speed=2000,4000' on a 3000 / 6000 r/min run-up ran both steps at
    # 2000, then 4000 r/min, without a word
    run_up = loads_scene(RUN_UP)
    p = parse_set("schedule.speed=2000,4000", run_up.to_dict())
    assert p.notes == ("sweep: schedule.speed sets the speed of every step: the scene's 2 "
                       "steps (3000 rpm, 6000 rpm) each run at the case's speed instead of "
                       "their own",)
    cases = expand(run_up, [p])
    speeds = [[s.speed * 30 / 3.141592653589793 for s in loads_scene(c.scene_toml)
               .schedule.steps] for c in cases]
    assert speeds == [pytest.approx([2000.0, 2000.0]), pytest.approx([4000.0, 4000.0])]
    run_sweep(run_up, [p], tmp_path, runner=_runner, workers=1, progress=False, check=False)
    assert "each run at the case's speed instead of their own" in capsys.readouterr().err


def test_a_schedule_field_the_steps_share_gives_no_note(scene):
    d = loads_scene(RUN_UP).to_dict()
    assert parse_set("schedule.radial_load=3,5", d).notes == ()
    assert parse_set("schedule.speed=2000,4000", scene.to_dict()).notes == ()  # one step


@pytest.mark.parametrize("spec, written", [
    ("environment.ambient_temperature=-0.3:0.3:0.1",
     ("-0.3 degC", "-0.2 degC", "-0.1 degC", "0 degC", "0.1 degC", "0.2 degC", "0.3 degC")),
    ("environment.ambient_temperature=-2.1:2.1:0.7",
     ("-2.1 degC", "-1.4 degC", "-0.7 degC", "0 degC", "0.7 degC", "1.4 degC", "2.1 degC")),
    ("supply.flow=0.1:0.3:0.1", ("0.1 L/min", "0.2 L/min", "0.3 L/min"))])
def test_a_range_is_written_to_the_digits_of_its_scale(scene, spec, written):
    # a value cancelling to zero kept the cancellation's noise: '5.55111512313e-17 degC'
    assert parse_set(spec, scene.to_dict()).values == written
