"""Run-output hygiene: what a run reports and writes says what was computed, in one line,
with units (defects found by the scene fuzzer and a loss-map tour)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scene_parts import SKF6304_A, VG68_JET_1LPM, scene_title

from thermobearing.errors import ConvergenceError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

#: a fuzzed scene (seed 14): a QJ1044 on the global friction model at 5000 r/min with a
#: 0.086 L/min jet of OIL_4109 started at -5.3 degC: 25 kW of heat, the oil node crosses
#: the 300 degC runaway limit about 2.4 s in (the chain computes no contacts: the end of
#: the oil's pressure-viscosity law at 225.6 degC does not limit it)
RUNAWAY = """
title = "runaway inside a chunk"
[[bearings]]
name = "a"
preset = "QJ1044"
[lubricant]
preset = "OIL_4109"
[supply]
method = "jet"
flow = "0.0861299 L/min"
inlet_temperature = "82.436 degF"
[environment]
ambient_temperature = "162.194 degF"
initial_temperature = "22.4438 degF"
[schedule]
speed = "5000 rpm"
radial_load = "2946.5 N"
axial_load = "0 N"
duration = "60 min"
[models]
kinematics = "none"
heat_sources = ["global_friction"]
heat_source_options = { global_friction = { model = "skf_four_term" } }
[outputs]
mode = "transient"
want = ["temperatures"]
[network]
template = "seven_node"
[network.parameters]
housing_outer_diameter = "614.4 mm"
housing_length = "103.0 mm"
shaft_diameter = "220.0 mm"
shaft_length = "770.0 mm"
[solver]
chunk = "CHUNK"
"""


def _runaway(chunk: str) -> ConvergenceError:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ConvergenceError) as info:
            Simulation(loads_scene(RUNAWAY.replace("CHUNK", chunk)), progress=False).run()
    return info.value


def test_runaway_inside_a_chunk_is_a_thermal_runaway_where_it_crosses_the_limit():
    """With a 600 s chunk the network stepper stopped 115 s in with the oil node at
    3.5e5 K (an air conductance out of its range) and the run ended with that stepper's
    error; it is a thermal runaway naming the node, where the limit was crossed and the
    remedy, at the same time as with a 114 s chunk whose end is past the limit (the same
    chunk model: the crossing does not depend on where the chunk ends)."""
    long, short = _runaway("600 s"), _runaway("114 s")
    for err in (long, short):
        text = str(err)
        assert err.solver == "coupled transient"
        assert "thermal runaway: node 'a.oil' reached the limit of 300.0 degC" in text
        assert "check the oil flow" in text and "network stepper" not in text
        assert 0.0 < err.residual < 2.0  # [K] above the limit: located, not the chunk end
    assert 1.0 < long.state["time"] < 3.0
    assert long.state["time"] == pytest.approx(short.state["time"], abs=0.05)


def test_error_state_is_one_line():
    """numpy's default line width broke a 7-node temperature vector over two lines in the
    middle of a network stepper's error; every state value is now on one line, arrays with
    5 significant digits (longer ones by their ends), nested containers element-wise."""
    import numpy as np

    T = np.array([6616.088, 3654.52, 5415.9449, 965.3721, 42253.4256, 54513.1863,
                  84334.2856])
    err = ConvergenceError("network stepper tr_bdf2", float("inf"), "conductance out of range",
                           {"time": 351.062, "temperatures": T, "long": np.arange(100.0),
                            "grid": np.eye(2), "nested": {"a.oil": np.arange(30.0)},
                            "pair": (0.1 + 0.2, "x")})
    text = str(err)
    assert "\n" not in text
    assert "temperatures=[6616.1, 3654.5, 5415.9, 965.37, 42253, 54513, 84334]" in text
    assert "long=[0, 1, 2, ..., 97, 98, 99]" in text
    assert "grid=[[1, 0], [0, 1]]" in text
    assert "nested={'a.oil': [0, 1, 2, ..., 27, 28, 29]}" in text
    assert "pair=(0.3, 'x')" in text and "time=351.062" in text


def test_input_error_shows_an_array_on_one_line():
    """An InputError's value is its repr: a viscosity grid (512 x 11) went over seven lines
    of a message (numpy's summary), inside a thermal-EHL ConvergenceError's text. Arrays
    are shown on one line, a grid by its shape and range; the value itself is kept."""
    import numpy as np

    from thermobearing.errors import InputError

    grid = np.full((512, 11), 3.6774e-2)
    grid[0, 0] = np.nan
    err = InputError("eta0", grid, "a viscosity > 6.31e-5 Pa s")
    assert str(err) == ("eta0 = (512 x 11 values from 0.036774 to 0.036774, 1 not finite) "
                        "is not allowed: a viscosity > 6.31e-5 Pa s")
    assert err.value is grid
    assert str(InputError("pressure", np.array([0.0, 1.5e9]), "finite")) == (
        "pressure = [0, 1.5e+09] is not allowed: finite")
    assert str(InputError("x", 3.0, "y")) == "x = 3.0 is not allowed: y"


#: one operating point of a QJ1044 (losses only, no network): ``KIN`` is the kinematics
POINT = """
title = "one point"
[[bearings]]
name = "a"
preset = "QJ1044"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "33 L/min"
inlet_temperature = "40 degC"
[environment]
initial_temperature = "40 degC"
[schedule]
speed = "1800 rpm"
radial_load = "4 kN"
axial_load = "0 kN"
duration = "1 min"
[models]
kinematics = "KIN"
[outputs]
want = ["losses", "kinematics"]
"""


def _point(kinematics: str, extra: str = "") -> tuple[Simulation, object]:
    text = POINT.replace("KIN", kinematics) + extra
    if kinematics == "none":
        text = text.replace('kinematics = "none"', 'kinematics = "none"\n'
                            'heat_sources = ["global_friction"]')
    sim = Simulation(loads_scene(text), progress=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return sim, sim.run()


def test_summary_prints_only_what_was_computed():
    """kinematics = "none" solves no kinematics: the summary printed the theoretical cage
    speed ratio as 'CSR at first step', 'over-skidding: max +0.00 %' and '1 kinematics
    solves' (the pure-rolling state it set); race control prints them; a film-only scene
    printed '0 kinematics solves'."""
    sim, res = _point("none")
    text = sim.summary_text(res)
    assert "total loss per bearing" in text and "wall time" in text
    for word in ("CSR", "over-skidding", "kinematics solves"):
        assert word not in text, text
    sim, res = _point("race_control")
    text = sim.summary_text(res)
    assert "CSR at first step" in text and "over-skidding" in text
    assert "1 kinematics solves" in text
    text = POINT.replace("KIN", "race_control").replace('["losses", "kinematics"]', '["film"]')
    sim = Simulation(loads_scene(text), progress=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = sim.run()
    assert "film" in res.tables and "kinematics solves" not in sim.summary_text(res)


def test_chain_lists_the_film_only_where_something_computes_one():
    """kinematics = "none" (global friction) computes no contact: `check` listed the film
    model and the pressure-viscosity law in its chain, and the runaway limit stopped where
    OIL_4109's Roelands law ends (225.6 degC); the film table or kinematics that solve
    contacts list them."""
    from thermobearing.coupled import RUNAWAY_TEMPERATURE, Coupler, build_network

    def families(kin: str, want: str) -> list[str]:
        text = POINT.replace("KIN", kin).replace('["losses", "kinematics"]', want)
        if kin == "none":
            text = text.replace('kinematics = "none"', 'kinematics = "none"\n'
                                'heat_sources = ["global_friction"]')
        return [link.family for link in Simulation(loads_scene(text), progress=False).chain]

    none = families("none", '["temperatures", "losses"]')
    assert "film" not in none and "pressure_viscosity" not in none
    assert none[:3] == ["viscosity_temperature", "kinematics", "heat_source"]
    for kin, want in (("none", '["film", "losses"]'), ("race_control", '["losses"]'),
                      ("skidding", '["kinematics"]'), ("race_control", '["film"]')):
        listed = families(kin, want)
        assert "film" in listed and "pressure_viscosity" in listed, (kin, want, listed)
    sim = Simulation(loads_scene(RUNAWAY.replace("CHUNK", "90 s")), progress=False)
    assert Coupler(sim, build_network(sim)).runaway_limit == RUNAWAY_TEMPERATURE


def test_untimed_tables_have_no_time_column(tmp_path):
    """A losses-only run (no network) and a steady run wrote 'time [s]' = 0 (and the
    steady temperatures 'time [min]' = 0) in every table: an operating point has no time.
    Transient tables keep their times."""
    import pandas as pd

    sim, _ = _point("race_control")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = sim.run(tmp_path / "point")
    for name in ("losses", "kinematics"):
        assert "time [s]" not in res.tables[name]
        written = pd.read_csv(tmp_path / "point" / f"{name}.csv")
        assert list(written.columns[:2]) == ["step", "bearing"]
    text = POINT.replace("KIN", "race_control").replace(
        'want = ["losses", "kinematics"]', 'mode = "steady"\nwant = ["temperatures", "losses"]'
    ) + '[network]\nparameters = { housing_outer_diameter = "510 mm", housing_length = "140 mm" }\n'
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        steady = Simulation(loads_scene(text), progress=False).run()
    table = steady.tables["steady_temperatures"]
    assert list(table.columns[:4]) == ["step", "speed [rpm]", "radial load [kN]",
                                       "axial load [kN]"]
    assert all(c.endswith(" [degC]") for c in table.columns[4:])
    assert "time [s]" not in table and "time [min]" not in table
    assert "time [s]" not in steady.tables["losses"]
    assert "time [s]" not in steady.tables["kinematics"]


def test_kinematics_table_units_and_noise_floor(tmp_path):
    """kinematics.csv wrote 1.9e-15 deg (skidding) and 2.1e-10 deg (race control) for the
    contact angles of a deep-groove bearing without axial load (0 by symmetry), -1.1e-14 %
    over-skidding under race control, and a 'residual' column without unit: the noise
    below the stated floors is 0, every column that holds a quantity names its unit, and a
    small real angle (1 N of axial load against 2 kN radial: about 0.025 deg) is written
    as computed."""
    import pandas as pd

    from thermobearing.simulation_tables import (
        CONTACT_ANGLE_FLOOR,
        OVER_SKID_FLOOR,
        contact_angle_columns,
    )

    def run(kin: str, axial: str, out: str) -> tuple[Simulation, pd.DataFrame]:
        text = (POINT.replace("KIN", kin).replace('preset = "QJ1044"', 'preset = "SKF6304"')
                .replace('radial_load = "4 kN"', 'radial_load = "2 kN"')
                .replace('axial_load = "0 kN"', f'axial_load = "{axial}"'))
        sim = Simulation(loads_scene(text), progress=False)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim.run(tmp_path / out)
        return sim, pd.read_csv(tmp_path / out / "kinematics.csv")

    angles = ["inner contact angle [deg]", "outer contact angle [deg]"]
    tables = {kin: run(kin, "0 N", kin)[1] for kin in ("race_control", "skidding")}
    for table in tables.values():
        assert (table[angles].to_numpy() == 0.0).all(), table[angles]
        labels = {"step", "bearing", "converged"}
        assert all(c.endswith("]") for c in table.columns if c not in labels), table.columns
        assert "residual [-]" in table and "iterations [-]" in table
    assert tables["race_control"]["over-skidding [%]"].iloc[0] == 0.0
    assert abs(tables["skidding"]["over-skidding [%]"].iloc[0]) > OVER_SKID_FLOOR  # real
    sim, table = run("race_control", "1 N", "axial")
    raw = contact_angle_columns(sim.bearings[0].last, sim.bearings[0].bearing)
    for col in angles:
        assert table[col].iloc[0] > 100.0 * CONTACT_ANGLE_FLOOR
        assert table[col].iloc[0] == pytest.approx(raw[col], rel=1e-12)


def test_global_friction_run_names_only_the_calibrated_clearance():
    """QJ1044 with kinematics = "none": the calibration file's ball force-model parameters
    are not used (no ball force model runs), only its diametral clearance; the run said it
    used the 'calibrated ball force-model parameters'."""
    import dataclasses

    from thermobearing.scene import load_scene

    scene = load_scene()
    models = dict(scene.models, kinematics="none", heat_sources=["global_friction"])
    sim = Simulation(dataclasses.replace(scene, models=models), progress=False)
    notes = [n for n in sim.notes if "calibrat" in n]
    assert notes == ["calibrated diametral clearance from QJ1044.calibration.toml; its ball "
                     "force-model parameters are not used with kinematics = \"none\""]
    assert any("force-model parameters from" in n
               for n in Simulation(scene, progress=False).notes)


FILM_AT_ZERO_LOAD = (scene_title("film only at zero load") + SKF6304_A + VG68_JET_1LPM + """\
[schedule]
steps = [{ duration = "1 min", speed = "3000 rpm", radial_load = "0 N", axial_load = "0 N" }]
[models]
kinematics = "skidding"
[outputs]
mode = "steady"
want = ["film"]
""")


def test_film_only_scene_at_zero_load_runs_and_flags_no_missing_contact():
    """A film-only scene runs no kinematics, so the skidding solver's refusal of a turning
    step without load does not apply (it was raised, naming the skidding solver). The
    unloaded inner raceway has no contact: its film is left empty, not 0 um (whose Lambda 0
    flagged boundary lubrication of a contact that does not exist); the outer contact,
    loaded by the centrifugal force, keeps its film."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(loads_scene(FILM_AT_ZERO_LOAD), progress=False)
        res = sim.run()
    film = res.tables["film"].set_index("race")
    assert film.loc["inner", "max load [N]"] == 0.0
    assert np.isnan(film.loc["inner", "central film [um]"])
    assert np.isnan(film.loc["inner", "film parameter [-]"])
    assert film.loc["outer", "max load [N]"] > 0.0
    assert film.loc["outer", "central film [um]"] > 0.0
    assert not any("Lambda" in w for w in sim.warnings)
