"""Scene mistakes a user makes (session-19 fuzz, user-made mutations): a heat source listed
twice ran twice (two ``churning_cage`` loss rows, twice the cage's churning heat) without a
word; a bearing named ``""`` or ``{}`` loaded, its nodes then ``.oil`` / ``{}.oil``."""

from __future__ import annotations

import pytest
from scene_parts import VG46_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.scene_checks import check_model_names

SCENE = """
title = "probe"
[[bearings]]
{name}
preset = "SKF6304"
""" + VG46_JET_1LPM + """[schedule]
speed = "3000 rpm"
radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{{}}]
[models]
kinematics = "race_control"
heat_sources = {sources}
"""


def _scene(name: str = 'name = "a"', sources: str = '["raceway_traction"]') -> str:
    return SCENE.format(name=name, sources=sources)


def test_a_heat_source_listed_twice_is_refused_naming_the_second() -> None:
    scene = loads_scene(_scene(sources='["churning_cage", "raceway_traction", '
                                       '"churning_cage"]'))
    with pytest.raises(InputError) as info:
        check_model_names(scene)
    assert info.value.field == "models.heat_sources[2]"
    assert "models.heat_sources[0]" in info.value.allowed


def test_distinct_heat_sources_pass() -> None:
    check_model_names(loads_scene(_scene(sources='["churning_cage", "raceway_traction"]')))


@pytest.mark.parametrize("name", ['name = ""', 'name = "   "', "name = {}", "name = []",
                                  "name = true"])
def test_a_bearing_without_a_usable_name_is_refused(name: str) -> None:
    with pytest.raises(InputError) as info:
        loads_scene(_scene(name=name))
    assert info.value.field == "bearings[0].name"


@pytest.mark.parametrize(("name", "read"), [('name = "Lager-\u00dc \u8ef8\u53d7"',
                                             "Lager-\u00dc \u8ef8\u53d7"),
                                            ("name = 3", "3"), ("", "bearing1")])
def test_names_in_other_scripts_numbers_and_the_default_load(name: str, read: str) -> None:
    assert loads_scene(_scene(name=name)).bearings[0].name == read


def test_an_output_interval_asking_for_more_than_a_million_rows_is_refused() -> None:
    # two 1-min steps at interval = "1 us": 1.2e8 rows; the run built a 9e7-element time
    # array in its first chunk and did not come back
    base = _scene() + '[outputs]\nmode = "transient"\n'
    with pytest.raises(InputError) as info:
        loads_scene(base + 'interval = "1 us"\n')
    assert info.value.field == "outputs.interval"
    assert "6e-05 s" in info.value.allowed  # 60 s / 1e6 rows
    assert loads_scene(base + 'interval = "1 ms"\n').outputs.interval == pytest.approx(1e-3)
    # a steady run has no rows in time: the interval is not counted there
    loads_scene(_scene() + '[outputs]\nmode = "steady"\ninterval = "1 us"\n')


def test_a_chunk_asking_for_more_than_a_million_chunks_is_refused() -> None:
    base = _scene() + '[outputs]\nmode = "transient"\n[solver]\n'
    with pytest.raises(InputError) as info:
        loads_scene(base + 'chunk = "1 us"\n')
    assert info.value.field == "solver.chunk"
    assert loads_scene(base + 'chunk = "0.1 s"\n').solver.chunk == pytest.approx(0.1)
