"""Tour R5: the SKF catalogue cross-check of an angular-contact bearing.

Before: ``infer_skf_series`` read "7210BE" as series "72", which is not a key (the
angular-contact keys carry the contact-angle suffix, 72_BECBP ...), and a scene could not
give the series without running ``global_friction`` as a heat source (its loss then booked
into the total). After: the designation's suffix picks the angle's row, and
``heat_source_options.global_friction`` takes the catalogue inputs without the source.
"""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path

import pytest

from thermobearing.errors import InputError
from thermobearing.global_friction import BearingEnvelope, infer_skf_series
from thermobearing.scene import load_scene
from thermobearing.simulation_chain import (
    crosscheck_options,
    heat_source_names,
    scene_heat_source_options,
)

SCENE = Path(__file__).resolve().parents[2] / "configs" / "scenes" / "qj1044_rig.toml"


def _env(kind: str, name: str) -> BearingEnvelope:
    return BearingEnvelope(kind, 0.05, 0.09, 0.02, 0.0127, name)


@pytest.mark.parametrize("name, series", [
    ("7210BE", "72_BECBP"), ("7210 BECBP", "72_BECBP"), ("7310BEP", "73_BECBP"),
    ("7210ACCBM", "72_ACCBM"), ("7310AC", "73_ACCBM"), ("3210A", "32_A"), ("3310A", "33_A"),
])
def test_angular_contact_designation_with_suffix_gives_its_series(name, series):
    assert infer_skf_series(_env("angular_contact", name)) == series


@pytest.mark.parametrize("kind, name, series", [
    ("deep_groove", "6304", "63"), ("deep_groove", "SKF6304", "63"),
    ("deep_groove", "61804", "618"), ("deep_groove", "6205-2RS", "62"),
    ("cylindrical", "NU214", "2"),
])
def test_other_designations_keep_their_series(kind, name, series):
    assert infer_skf_series(_env(kind, name)) == series


def test_angular_contact_without_a_known_angle_code_is_refused_naming_it():
    with pytest.raises(InputError) as err:
        infer_skf_series(_env("angular_contact", "7210"))
    assert "no contact-angle code" in str(err.value) and "7210BE" in str(err.value)
    with pytest.raises(InputError) as err:
        infer_skf_series(_env("angular_contact", "7014C"))
    assert "reads as series '70'" in str(err.value) and "'C'" in str(err.value)


def _scene_with(options: str):
    scene = load_scene(SCENE)
    table = tomllib.loads(f"o = {options}")["o"]
    models = dict(scene.models)
    models["heat_source_options"] = table
    return dataclasses.replace(scene, models=models)


def test_series_for_the_crosscheck_without_the_source():
    scene = _scene_with('{ global_friction = { series = "72_BECBP", '
                        'static_load_rating = "15 kN" } }')
    sources = heat_source_names(scene, True)
    assert "global_friction" not in sources
    checked = scene_heat_source_options(scene, sources)
    assert checked["global_friction"] == {"series": "72_BECBP", "static_load_rating": 15e3}
    assert crosscheck_options(scene) == {"series": "72_BECBP", "static_load_rating": 15e3}


def test_booking_options_are_refused_without_the_source():
    scene = _scene_with('{ global_friction = { model = "palmgren" } }')
    sources = heat_source_names(scene, True)
    with pytest.raises(InputError) as err:
        scene_heat_source_options(scene, sources)
    text = str(err.value)
    assert "global_friction.model" in text and "series" in text and "nothing is booked" in text


def test_no_options_no_crosscheck_inputs():
    assert crosscheck_options(load_scene(SCENE)) == {}


def test_simulation_accepts_the_crosscheck_series_and_books_no_global_friction():
    from thermobearing.simulation import Simulation

    sim = Simulation(_scene_with('{ global_friction = { series = "QJ" } }'), progress=False)
    assert sim.source_options["global_friction"] == {"series": "QJ"}
    assert all("global_friction" not in b.sources for b in sim.bearings)
