"""A research engineer's tour of the Python API: the mistakes a notebook user makes with the
public functions (a unit string or an array where one SI number is expected, a Celsius value
passed as kelvin, a lubricant where a bearing is expected) are refused with the field, the
value and what is allowed, and numpy scalars are accepted like floats."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing import ehl, film, hertz, skidding
from thermobearing.errors import InputError
from thermobearing.state import OilSupply

SUPPLY = OilSupply("jet", 5.5e-4, 308.15)
SPEED = 1800.0 * math.pi / 30.0  # 1800 r/min [rad/s]


@pytest.fixture(scope="module")
def qj1044():
    from thermobearing.bearing_config import load_bearing

    return load_bearing("QJ1044")


@pytest.fixture(scope="module")
def vg46():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("ISO_VG46")


@pytest.mark.parametrize(("field", "value", "unit"), [
    ("speed", "1800 rpm", "rad/s"),          # before: TypeError bad operand type for abs()
    ("speed", np.array([SPEED]), "rad/s"),   # before: TypeError only 0-dimensional arrays
    ("radial_load", [1000.0], "N"),
    ("axial_load", "10 kN", "N"),
    ("temperature", "40 degC", "K"),
])
def test_skidding_solve_refuses_what_is_not_one_number(qj1044, vg46, field, value, unit):
    args = {"speed": SPEED, "radial_load": 1000.0, "axial_load": 10000.0,
            "temperature": 313.15, field: value}
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, supply=SUPPLY, **args)
    assert info.value.field == field and info.value.value is value
    assert f"one real number in {unit}" in info.value.allowed


def test_skidding_solve_names_the_speed_when_it_is_nan(qj1044, vg46):
    # before: "parker.shaft_speed = nan", a name the caller never used
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, math.nan, 1000.0, 10000.0, 313.15, supply=SUPPLY)
    assert info.value.field == "speed" and "finite" in info.value.allowed


def test_skidding_solve_refuses_swapped_or_wrong_objects(qj1044, vg46):
    # before: AttributeError from deep inside the solver
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, qj1044, SPEED, 1000.0, 10000.0, 313.15, supply=SUPPLY)
    assert info.value.field == "lubricant" and info.value.value == "BallBearing"
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, SPEED, 1000.0, 10000.0, 313.15, supply="jet")
    assert info.value.field == "supply" and "OilSupply" in info.value.allowed


def test_skidding_solve_takes_numpy_scalars_and_0d_arrays_as_floats(qj1044, vg46):
    ref = skidding.solve(qj1044, vg46, SPEED, 1000.0, 10000.0, 313.15, supply=SUPPLY)
    same = skidding.solve(qj1044, vg46, np.float32(SPEED).astype(np.float64), np.array(1000.0),
                          np.int64(10000), np.array(313.15), supply=SUPPLY)
    assert ref.converged and same.converged
    assert same.cage_speed_ratio == pytest.approx(ref.cage_speed_ratio, rel=1e-9)


def test_celsius_temperature_given_as_kelvin_says_the_unit(qj1044, vg46):
    # 40 meant as degC: the viscosity law overflows; the message now says the unit
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, SPEED, 1000.0, 10000.0, 40.0, supply=SUPPLY)
    assert info.value.field == "temperature" and info.value.value == "40 K (-233.15 degC)"
    # the viscosity law's own error says the unit too (lubricant called directly)
    with pytest.raises(InputError) as info:
        vg46.dynamic_viscosity(40.0)
    assert "40 K is -233.15 degC" in info.value.allowed


@pytest.mark.parametrize(("kelvin", "field"), [(200.0, "temperature"),
                                               (150.0, "oil_temperature")])
def test_skidding_solve_refuses_an_oil_below_its_pour_point(qj1044, vg46, kelvin, field):
    # ISO VG 46 at -73 degC: 5e8 cSt, beyond ASTM D341's 1e6 cSt (before: "pressure =
    # 5.0875e+08 Pa is not allowed", a Roelands overflow at some contact pressure)
    temps = {"temperature": 313.15, "oil_temperature": 313.15, field: kelvin}
    with pytest.raises(InputError) as info:
        skidding.solve(qj1044, vg46, SPEED, 1000.0, 10000.0, temps["temperature"],
                       supply=SUPPLY, oil_temperature=temps["oil_temperature"])
    assert info.value.field == field and "pour point" in info.value.allowed


def test_roller_result_counts_the_newton_steps_of_a_cold_start():
    # before: ``iterations`` was the last load-distribution pass's count, 0 on most states
    # (that pass started at the converged speeds), so the kinematics table said 0 for a cold
    # start from 0.8 of the epicyclic cage speed
    from thermobearing.bearing_config import load_bearing
    from thermobearing.lubricant import load_lubricant

    nu214, vg68 = load_bearing("NU214"), load_lubricant("ISO_VG68")
    cold = skidding.solve(nu214, vg68, 1000.0 * math.pi / 30.0, 500.0, 0.0, 323.15)
    assert cold.converged and cold.extras["start"].startswith("cold")
    assert cold.iterations >= 1
    again = skidding.solve(nu214, vg68, 1000.0 * math.pi / 30.0, 500.0, 0.0, 323.15,
                           guess=cold)
    assert again.iterations <= 1  # the warm start from the converged state needs none
    assert again.cage_speed == pytest.approx(cold.cage_speed, rel=1e-8)


_SCENE = """
title = "tour"
[[bearings]]
name = "b1"
preset = "QJ1044"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "33 L/min"
inlet_temperature = {inlet}
[environment]
ambient_temperature = {ambient}
[schedule]
steps = [{{ duration = "3 min", speed = "1800 rpm", radial_load = "1 kN", axial_load = "10 kN" }}]
[outputs]
mode = "steady"
want = ["losses"]
"""


@pytest.mark.parametrize(("inlet", "ambient", "field", "what"), [
    # a bare number is SI: 35 meant as degC is 35 K (before: the run stopped inside the ball
    # solver with ConvergenceError, residual 3.9e24, naming no scene field)
    ('"35 degC"', "35", "environment.ambient_temperature", "overflows"),
    ("35", '"35 degC"', "supply.inlet_temperature", "overflows"),
    # ISO VG 46 at -73 degC: 5e8 cSt, beyond ASTM D341's 1e6 cSt (before: a Roelands
    # overflow error at a contact pressure of 5.1e8 Pa)
    ('"35 degC"', "200", "environment.ambient_temperature", "pour point"),
])
def test_scene_temperature_the_oil_cannot_take_names_the_field(inlet, ambient, field, what):
    from thermobearing.scene import loads_scene
    from thermobearing.simulation import Simulation

    scene = loads_scene(_SCENE.format(inlet=inlet, ambient=ambient))
    with pytest.raises(InputError) as info:
        Simulation(scene)
    assert info.value.field == field and info.value.value.endswith("degC)")
    assert what in info.value.allowed and "a bare number in a scene is in K" in info.value.allowed


def test_scene_at_a_cold_but_liquid_temperature_still_loads():
    from thermobearing.scene import loads_scene
    from thermobearing.simulation import Simulation

    # -30 degC: ISO VG 46 is 1.7e4 cSt there, inside ASTM D341's range (up to 1e6 cSt)
    scene = loads_scene(_SCENE.format(inlet='"35 degC"', ambient='"-30 degC"'))
    nu = Simulation(scene).lubricant.kinematic_viscosity(243.15)
    assert 1e-2 < nu < 1.0


def test_vibration_statistics_of_a_result_object_says_what_to_pass():
    # passing the VibrationResult itself (before: TypeError from numpy's float conversion)
    from thermobearing import vibration

    class NotARecord:  # stands for a VibrationResult; the error depends only on the type
        pass

    with pytest.raises(InputError) as info:
        vibration.statistics(NotARecord())
    assert info.value.field == "acceleration" and info.value.value == "NotARecord"
    assert "acceleration_x" in info.value.allowed and "statistics_x" in info.value.allowed
    stats = vibration.statistics(np.sin(np.linspace(0.0, 20.0, 400)))
    assert stats.ptp == pytest.approx(2.0, rel=1e-3) and stats.kurtosis == pytest.approx(1.5,
                                                                                          rel=0.05)


E_STEEL = 2.235e11  # E' of the QJ1044's steel pair [Pa]


@pytest.mark.parametrize(("function", "args", "field"), [
    (hertz.point_contact, ("5 kN", 0.0158, 0.3085, E_STEEL), "load"),
    (hertz.point_contact, (5e3, "16 mm", 0.3085, E_STEEL), "rx"),
    (hertz.line_contact, ("3 kN", 0.013, 0.0137, E_STEEL), "load"),
    (film.hamrock_dowson_1977_central, ("13 m/s", 0.04, 2.3e-8, 5e3, 0.0158, 0.3085),
     "entrainment_speed"),
    (film.hamrock_dowson_1977_central, (13.0, "40 cP", 2.3e-8, 5e3, 0.0158, 0.3085),
     "dynamic_viscosity"),
    (ehl.solve_line_contact, ("3 kN", 0.0137, E_STEEL, 5.0, 0.04), "load_per_length"),
])
def test_physics_functions_name_a_unit_string_argument(function, args, field):
    # before: numpy's "ValueError: could not convert string to float: '5 kN'", no field
    kwargs = {"effective_modulus": E_STEEL} if function is film.hamrock_dowson_1977_central \
        else {"alpha": 2e-8} if function is ehl.solve_line_contact else {}
    with pytest.raises(InputError) as info:
        function(*args, **kwargs)
    assert info.value.field == field and "a number in SI units" in info.value.allowed


def test_global_friction_names_wrong_objects_and_unknown_options(qj1044, vg46):
    from thermobearing.global_friction import global_friction

    # before: AttributeError ('BallBearing' has no kinematic_viscosity; 'str' has no method)
    # and TypeError (palmgren() got an unexpected keyword argument 'f2')
    with pytest.raises(InputError) as info:
        global_friction("palmgren", qj1044, qj1044, 313.15, SPEED, 1e3, 1e4)
    assert info.value.field == "lubricant" and info.value.value == "BallBearing"
    with pytest.raises(InputError) as info:
        global_friction("palmgren", qj1044, vg46, 313.15, SPEED, 1e3, 1e4, supply="jet")
    assert info.value.field == "supply"
    with pytest.raises(InputError) as info:
        global_friction("palmgren", qj1044, vg46, 313.15, SPEED, 1e3, 1e4, f2=3.0)
    assert info.value.field == "palmgren options" and info.value.value == ["f2"]
    assert "f0, f1" in info.value.allowed
    with pytest.raises(InputError) as info:  # the bearing's repr was the whole message
        global_friction("palmgren", vg46, vg46, 313.15, SPEED, 1e3, 1e4)
    assert info.value.field == "bearing" and info.value.value == "Lubricant"
    res = global_friction("palmgren", qj1044, vg46, 313.15, SPEED, 1e3, 1e4, f0=2.0)
    assert res.details["f0"] == 2.0 and res.power == pytest.approx(res.torque * SPEED)


def test_package_exports_the_python_api_its_docstring_names():
    import dataclasses

    import thermobearing

    missing = [n for n in thermobearing.__all__ if not hasattr(thermobearing, n)]
    assert not missing
    assert thermobearing.Simulation.__module__ == "thermobearing.simulation"
    # the docstring's way to change a scene field in code, then run both
    scene = thermobearing.loads_scene(_SCENE.format(inlet='"35 degC"', ambient='"35 degC"'))
    less_oil = scene.with_changes(supply=dataclasses.replace(scene.supply, flow=2.5e-4))
    assert less_oil.supply.flow == 2.5e-4 and scene.supply.flow == pytest.approx(5.5e-4)
    base, changed = (thermobearing.Simulation(s).run().tables["losses"]
                     for s in (scene, less_oil))
    assert "power [W]" in base.columns
    # less oil in the bearing: less churning (paper 002's loss falls with the flow)
    assert changed["power [W]"].sum() < base["power [W]"].sum()


@pytest.mark.parametrize(("changes", "field"), [
    ({"want": ("lossess",)}, "outputs.want"),       # before: ran a film-only scene
    ({"want": "losses"}, "outputs.want"),           # before: read letter by letter
    ({"mode": "stedy"}, "outputs.mode"),            # before: ran as steady
    ({"interval": -10.0}, "outputs.interval"),
])
def test_outputs_changed_in_code_are_checked(changes, field):
    import dataclasses

    from thermobearing.scene import Outputs

    with pytest.raises(InputError) as info:
        dataclasses.replace(Outputs(), **changes)
    assert info.value.field == field


@pytest.mark.parametrize(("changes", "field"), [
    ({"duration": -10.0}, "step.duration"),         # before: ran
    ({"speed": -10.0}, "step.speed"),
    ({"radial_load": -10.0}, "step.radial_load"),   # before: reported as "0 kN" by a check
    ({"speed": "1800 rpm"}, "step.speed"),          # before: TypeError in the table rows
])
def test_steps_changed_in_code_are_checked(changes, field):
    import dataclasses

    from thermobearing.scene import Step

    step = Step(duration=180.0, speed=SPEED, radial_load=1e3, axial_load=0.0)
    with pytest.raises(InputError) as info:
        dataclasses.replace(step, **changes)
    assert info.value.field == field
    # a bearing's own step may carry a reversed axial load (a negative load_share)
    assert dataclasses.replace(step, axial_load=-5e3).axial_load == -5e3


@pytest.mark.parametrize(("changes", "field"), [
    ({"rtol": -1.0}, "solver.rtol"),        # before: accepted (a scene file refuses it)
    ({"chunk": 0.0}, "solver.chunk"),
    ({"kinematics_tolerance": 1.5}, "solver.kinematics_tolerance"),
    ({"stepper": 3}, "solver.stepper"),
])
def test_solver_settings_changed_in_code_are_checked(changes, field):
    import dataclasses

    from thermobearing.scene import Solver

    with pytest.raises(InputError) as info:
        dataclasses.replace(Solver(), **changes)
    assert info.value.field == field


def test_physics_modules_resolve_after_a_bare_package_import():
    # the README's thermobearing.skidding.solve(...) after `import thermobearing` (a fresh
    # interpreter: in this one the test suite has imported the submodules already)
    import subprocess
    import sys

    code = ("import thermobearing as tb; print(tb.skidding.solve.__name__, "
            "tb.global_friction.global_friction.__name__); tb.no_such_module")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert out.stdout.split() == ["solve", "global_friction"]
    assert "has no attribute 'no_such_module'" in out.stderr


def test_bearings_and_temperatures_changed_in_code_are_checked():
    import dataclasses

    from thermobearing.scene import BearingSpec, load_scene
    from thermobearing.simulation import Simulation

    spec = BearingSpec(name="de", preset="QJ1044")
    for share, allowed in (({"radial": -0.5}, ">= 0"), ({"radial": "0.5"}, "a number"),
                           ({"axal": 0.0}, "")):
        with pytest.raises(InputError) as info:  # before: reached the solvers
            dataclasses.replace(spec, load_share=share)
        assert info.value.field.startswith("bearings[de].load_share") \
            and allowed in info.value.allowed
    assert dataclasses.replace(spec, load_share={"axial": -1.0}).axial_share == -1.0
    scene = load_scene("qj1044_rig")
    with pytest.raises(InputError) as info:  # duplicate names: accepted before
        scene.with_changes(bearings=(scene.bearings[0], scene.bearings[0]))
    assert info.value.field == "bearings[].name"
    cold = scene.with_changes(environment=dataclasses.replace(
        scene.environment, ambient_temperature=-5.0, initial_temperature=-5.0))
    with pytest.raises(InputError) as info:
        Simulation(cold)
    assert info.value.field == "environment.ambient_temperature"
    assert "above absolute zero" in info.value.allowed


def test_vibration_and_signal_name_the_mistaken_argument():
    from thermobearing import signal, vibration
    from thermobearing.bearing_config import load_bearing

    x = np.sin(np.linspace(0.0, 2000.0, 25600))
    # a VibrationResult passed as the record (before: TypeError from numpy)
    with pytest.raises(InputError) as info:
        signal.estimate_cage_speed(object(), 25600.0, 30.0, 7, 0.37)
    assert info.value.field == "signal" and "acceleration_x" in info.value.allowed
    # the theoretical CSR as a percentage (before: an error about the sampling rate)
    with pytest.raises(InputError) as info:
        signal.estimate_cage_speed(x, 25600.0, 30.0, 7, 36.8)
    assert info.value.field == "csr_theoretical" and "(0, 0.5)" in info.value.allowed
    # r/min given as Hz: the sampling-rate error now names the shaft frequency it used
    with pytest.raises(InputError) as info:
        signal.estimate_cage_speed(x, 25600.0, 1800.0, 7, 0.37)
    assert "shaft_frequency = 1800 Hz (r/min / 60)" in info.value.allowed
    # the bearing where its vibration parameters are expected (before: AttributeError)
    with pytest.raises(InputError) as info:
        vibration.simulate(load_bearing("SKF6304"), 188.5, 500.0, traction=None)
    assert info.value.field == "params" and "from_bearing" in info.value.allowed


@pytest.mark.parametrize("module", ["hertz", "film", "global_friction", "skidding", "vibration",
                                    "signal", "ehl", "scene", "simulation", "sweep"])
def test_public_modules_list_their_names(module):
    import importlib

    mod = importlib.import_module(f"thermobearing.{module}")
    assert mod.__all__ and all(hasattr(mod, n) for n in mod.__all__)


def test_custom_lubricant_refuses_values_in_the_wrong_unit():
    from thermobearing.lubricant import Lubricant

    ok = Lubricant.from_viscosities(46e-6, 6.8e-6, 876.0)
    assert ok.kinematic_viscosity(313.15) == pytest.approx(46e-6, rel=1e-9)
    # cSt given as m^2/s (before: accepted, with a warning that the oil is below its pour
    # point at 40 degC)
    with pytest.raises(InputError) as info:
        Lubricant.from_viscosities(46.0, 6.8, 876.0)
    assert info.value.field == "custom.nu40" and "4.6e-5 m^2/s" in info.value.allowed
    with pytest.raises(InputError) as info:  # before: "nu1 = '46 mm**2/s'"
        Lubricant.from_viscosities("46 mm**2/s", 6.8e-6, 876.0)
    assert info.value.field == "custom.nu40"
    # g/cm^3 given as kg/m^3 (before: a dynamic viscosity of 2e-124 Pa s at 40 degC)
    with pytest.raises(InputError) as info:
        Lubricant.from_viscosities(46e-6, 6.8e-6, 0.876)
    assert info.value.field == "custom.density" and "800-1164" in info.value.allowed


def test_results_into_a_file_path_name_the_folder(tmp_path):
    from thermobearing.results import Results, ResultsWriter

    a_file = tmp_path / "run"
    a_file.write_text("not a folder")
    for write in (lambda: Results(tables={}).write(a_file), lambda: ResultsWriter(a_file)):
        with pytest.raises(InputError) as info:  # before: FileExistsError
            write()
        assert info.value.field == "out_dir" and "this is a file" in info.value.allowed


def test_thermal_ehl_runaway_is_a_convergence_error_naming_the_remedy():
    # NU214 inner contact, 3 kN, 5 m/s, 2 % slide, ISO VG 68 at 50 degC, Newtonian film:
    # the first temperature sweep reaches ~3e4 K (before: an InputError "eta0 = array(...)"
    # that printed a 512 x 11 grid, as if the caller's input were wrong)
    from thermobearing.bearing_config import load_bearing
    from thermobearing.errors import ConvergenceError
    from thermobearing.lubricant import load_lubricant

    nu214, vg68 = load_bearing("NU214"), load_lubricant("ISO_VG68")
    rx, _ = nu214.curvature("inner")
    steel = nu214.roller_material
    solid = ehl.SolidThermal(steel.density, steel.specific_heat, steel.thermal_conductivity)
    with pytest.raises(ConvergenceError) as info:
        ehl.solve_thermal_line_contact(3000.0 / nu214.roller_effective_length, rx,
                                       nu214.effective_modulus, 5.0, 0.02, vg68, 323.15,
                                       solid1=solid)
    err = info.value
    assert err.residual > 1e3 and err.state["max_temperature"] > 1e3
    assert "eyring_stress" in str(err) and "array(" not in str(err)


def test_roelands_index_error_shows_one_value_not_the_grid():
    from thermobearing.viscosity_laws import roelands_index_from_alpha

    with pytest.raises(InputError) as info:
        roelands_index_from_alpha(2e-8, np.full((512, 11), 1e-6))
    assert info.value.value == "1e-06 Pa s (the smallest of 5632 values)"


def test_scene_with_changes_names_an_unknown_field():
    from thermobearing.errors import UnknownNameError
    from thermobearing.scene import load_scene

    with pytest.raises(UnknownNameError) as info:  # before: TypeError from replace()
        load_scene("qj1044_rig").with_changes(suply=None)
    assert info.value.value == "suply" and "did you mean 'supply'" in str(info.value)


@pytest.mark.parametrize("not_a_scene", ["qj1044_rig", {"title": "x"}])
def test_simulation_of_something_else_than_a_scene_says_how_to_load_one(not_a_scene):
    from thermobearing.simulation import Simulation

    with pytest.raises(InputError) as info:  # before: AttributeError ... no attribute 'models'
        Simulation(not_a_scene)
    assert info.value.field == "scene" and "load_scene" in info.value.allowed


def test_ball_load_distribution_names_a_wrong_bearing_or_an_array_load(qj1044, vg46):
    from thermobearing.loads import ball_load_distribution

    with pytest.raises(InputError) as info:  # before: AttributeError (no ball_diameter)
        ball_load_distribution(vg46, 1e3, 1e4)
    assert info.value.field == "bearing" and info.value.value == "Lubricant"
    with pytest.raises(InputError) as info:  # before: "truth value of an array is ambiguous"
        ball_load_distribution(qj1044, np.array([1e3, 2e3]), 1e4)
    assert info.value.field == "radial_load"
    assert ball_load_distribution(qj1044, np.float64(1e3), np.array(1e4), SPEED).converged


def test_race_control_kinematics_name_a_wrong_bearing(vg46):
    from thermobearing import kinematics

    for call in (lambda: kinematics.pure_rolling(vg46, SPEED),
                 lambda: kinematics.race_control_for_loads(vg46, 1e3, 1e3, 0.7, 0.7)):
        with pytest.raises(InputError) as info:  # before: AttributeError
            call()
        assert info.value.field == "bearing" and info.value.value == "Lubricant"


def test_a_speed_in_rpm_passed_as_rad_per_s_gets_a_hint():
    """1800 passed to skidding.solve means 1800 rad/s (17189 r/min): for the QJ1044 (d_m
    280 mm) n d_m = 4.8e6 mm r/min, beyond any oil-lubricated bearing; the solver converges
    there (CSR 29 % below CSR_th) and used to say nothing."""
    import math
    import warnings as _w

    from thermobearing.bearing_config import load_bearing as _lb
    from thermobearing.errors import ValidityWarning as _VW
    from thermobearing.skidding import _speed_plausibility

    qj = _lb("QJ1044")
    with _w.catch_warnings(record=True) as caught:
        _w.simplefilter("always", _VW)
        _speed_plausibility(qj, 1800.0)
        _speed_plausibility(qj, 1800 * math.pi / 30)
    texts = [str(w.message) for w in caught]
    assert len(texts) == 1 and "1800 r/min would be 188.5 rad/s" in texts[0]


def test_from_viscosities_refuses_reference_temperatures_in_degc():
    """T1 = 40, T2 = 100 (degC read as kelvin) gave 1.76 cSt at 40 degC for an ISO VG 46 oil
    without a word; a reference temperature below 200 K is refused naming it."""
    from thermobearing.errors import InputError as _IE
    from thermobearing.lubricant import Lubricant

    with pytest.raises(_IE, match=r"custom\.T1 .*40 K is -233.15 degC"):
        Lubricant.from_viscosities(46e-6, 6.8e-6, 870.0, T1=40, T2=100)
    oil = Lubricant.from_viscosities(46e-6, 6.8e-6, 870.0)
    assert float(oil.kinematic_viscosity(313.15)) == pytest.approx(46e-6, rel=1e-6)
