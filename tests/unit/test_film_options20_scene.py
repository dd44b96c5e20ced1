"""``[models] film_options`` (settings of the numerical thermal-EHL film): parsing with units,
the TOML round trip, refusals naming the field, and the values reaching the thermal solve
(the solve itself is replaced: the tests check what it is called with)."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from tehl_stand_in import CheapTable

from thermobearing.ehl import coupling, thermal
from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.kinematic_models import skidding
from thermobearing.lubricant import load_lubricant
from thermobearing.scene import load_scene, loads_scene
from thermobearing.scene_film import FILM_OPTIONS, film_options_from_models
from thermobearing.simulation_chain import (
    film_kinematics_options,
    plan_chain,
    scene_film_options,
)
from thermobearing.state import OilSupply, OperatingPoint

LUB = load_lubricant("OIL_4109")
OPTIONS = {"grid_points": 256, "temperature_step": "2 K", "load_step": 1.3,
           "speed_step": 1.2, "slide_to_roll_step": "2.5 %",
           "temperature_tolerance": "0.05 delta_degC", "max_grid_error": "4 %"}


def _scene(**models):
    base = load_scene("paper001_tehl")
    return base.with_changes(models={**base.models, **models})


def test_units_are_converted_to_the_film_model_keywords():
    got = scene_film_options(_scene(film_options=OPTIONS))
    assert got == {"n": 256, "temperature_step": pytest.approx(2.0),
                   "load_step": pytest.approx(1.3), "speed_step": pytest.approx(1.2),
                   "srr_step": pytest.approx(0.025), "tol_temperature": pytest.approx(0.05),
                   "max_grid_error": pytest.approx(0.04)}
    assert isinstance(got["n"], int)
    # a temperature step in degC is a difference, not 278 K
    assert film_options_from_models({"film": "numerical_tehl", "film_options": {
        "temperature_step": "5 degC"}}) == {"temperature_step": pytest.approx(5.0)}
    assert scene_film_options(_scene()) == {}


def test_every_option_is_a_film_model_keyword():
    import inspect

    from thermobearing.ehl.thermal import solve_thermal_line_contact

    own = set(inspect.signature(coupling.TehlFilmModel).parameters)
    solver = set(inspect.signature(solve_thermal_line_contact).parameters)
    for key, opt in FILM_OPTIONS.items():
        assert opt.keyword in own | solver, key


def test_toml_round_trip_keeps_the_options():
    scene = _scene(film_options={"grid_points": 256, "temperature_step": "2 K"})
    again = loads_scene(scene.to_toml())
    assert again.models["film_options"] == {"grid_points": 256, "temperature_step": "2 K"}
    assert scene_film_options(again) == scene_film_options(scene)


@pytest.mark.parametrize(("key", "value", "words"), [
    ("grid_points", 300, "power of two from 128 to 4096"),
    ("grid_points", 64, "power of two from 128 to 4096"),
    ("grid_points", 256.5, "power of two"),
    ("temperature_step", "0 K", "> 0 and <= 50 K"),
    ("temperature_step", "3 m", "convertible"),
    ("load_step", 1.0, "> 1 and <= 4"),
    ("slide_to_roll_step", 0.2, "> 0 and <= 0.05"),
    ("temperature_tolerance", "2 K", "> 0 and <= 1 K"),
    ("max_grid_error", "50 %", "(read as 0.5)"),
])
def test_out_of_range_values_name_the_field_and_the_interval(key, value, words):
    with pytest.raises(InputError) as err:
        plan_chain(_scene(film_options={key: value}), LUB, is_ball=False)
    assert err.value.field == f"models.film_options.{key}"
    assert words in str(err.value)


def test_unknown_keys_and_wrong_types_are_refused():
    with pytest.raises(InputError) as err:
        plan_chain(_scene(film_options={"nx": 256}), LUB, is_ball=False)
    assert err.value.field == "models.film_options.nx"
    assert "grid_points" in str(err.value) and "temperature_step" in str(err.value)
    text = load_scene("paper001_tehl").to_toml().replace(
        'film = "numerical_tehl"', 'film = "numerical_tehl"\nfilm_options = 256')
    with pytest.raises(InputError) as err:
        loads_scene(text)
    assert err.value.field == "models.film_options"


@pytest.mark.parametrize("film", [None, "pan_hamrock_central", "numerical_ehl"])
def test_options_without_the_thermal_ehl_film_are_refused(film):
    models = dict(load_scene("paper001_tehl").models)
    models.pop("film")
    if film is not None:
        models["film"] = film
    models["film_options"] = {"grid_points": 256}
    scene = load_scene("paper001_tehl").with_changes(models=models)
    with pytest.raises(InputError) as err:
        plan_chain(scene, LUB, is_ball=False)
    assert err.value.field == "models.film_options.grid_points"
    assert 'film = "numerical_tehl"' in str(err.value)
    with pytest.raises(InputError):
        film_kinematics_options(film, load_bearing("D1842926"), LUB, False, {"n": 256})


def test_chain_description_shows_the_settings():
    chain = plan_chain(_scene(film_options={"grid_points": 256}), LUB, is_ball=False)
    link = next(c for c in chain if c.name == "numerical_tehl")
    assert "grid_points 256" in link.purpose


def test_grid_and_tolerance_reach_the_thermal_solve(monkeypatch):
    seen = []

    def fake_solve(w, rx, ep, u, srr, lub, t_in, **kw):
        seen.append(kw)
        return SimpleNamespace(central_film=2e-7, minimum_film=1.5e-7, max_pressure=1e9,
                               shear_force=0.0, rolling_force=1.0, max_temperature=t_in + 5)

    monkeypatch.setattr(thermal, "solve_thermal_line_contact", fake_solve)
    opts = scene_film_options(_scene(film_options=OPTIONS))
    fm = film_kinematics_options("numerical_tehl", load_bearing("D1842926"), LUB, False,
                                 opts)["film_model"]
    tab = fm.table(0.01, 2.3e11, 320.0)
    tab(1.0e5, 20.0, 0.01, 321.0)
    assert seen and all(kw["n"] == 256 for kw in seen)
    assert all(kw["tol_temperature"] == pytest.approx(0.05) for kw in seen)
    assert all(kw["max_grid_error"] == pytest.approx(0.04) for kw in seen)
    # the table spacing: load, speed, slide-to-roll ratio, temperature
    assert tab.steps == pytest.approx((math.log(1.3), math.log(1.2), 0.025, 2.0))


def test_grid_reaches_the_table_of_the_scene_kinematics(monkeypatch):
    made = []

    class Recording(CheapTable):
        def __init__(self, *args, **kwargs):
            made.append(kwargs)
            super().__init__(*args, **kwargs)

    monkeypatch.setattr(coupling, "FilmTable", Recording)
    bearing = load_bearing("D1842926", overrides={"diametral_clearance": 40e-6})
    opts = film_kinematics_options("numerical_tehl", bearing, LUB, False,
                                   scene_film_options(_scene(film_options={
                                       "grid_points": 256})))
    op = OperatingPoint(inner_speed=13218.0 * math.pi / 30.0, radial_load=24e3)
    supply = OilSupply("jet", 2e-3 / 60.0, 303.15)
    res = skidding(bearing, LUB, op, contact_temperature=303.15, oil_temperature=303.15,
                   supply=supply, options=opts)
    assert res.raw.converged and opts["film_model"].solves > 0
    assert made and all(kw["n"] == 256 for kw in made)


def test_a_simulation_hands_the_scene_options_to_its_film_model():
    from thermobearing.simulation import Simulation

    sim = Simulation(_scene(film_options={"grid_points": 256, "temperature_step": "10 K"}),
                     progress=False)
    fm = sim.bearings[0].kin_options["film_model"]
    assert fm.n == 256 and fm.table_options["temperature_step"] == pytest.approx(10.0)
    default = Simulation(_scene(), progress=False).bearings[0].kin_options["film_model"]
    assert default.n == 512 and default.table_options["temperature_step"] == pytest.approx(5.0)
