"""User tour 21, an oil-air flow what-if of the 7014 C spindle example (flow written
"30 mm3/h"): the sweep's bare numbers took pint's spelling of the scene's unit, so its
values, summary column and figure titles read "10 mm**3/h". They now keep the data-sheet
spelling, and a folder written with the old spelling still resumes.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep
from thermobearing.sweep_cases import expand

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "spindle_pair_oil_air.toml"


def _runner(scene_toml: str) -> dict[str, float]:
    return {"mean total loss [W]": 1e12 * loads_scene(scene_toml).supply.flow}


@pytest.fixture(scope="module")
def scene():
    return load_scene(str(EXAMPLE))


def test_bare_numbers_take_the_data_sheet_spelling(scene):
    p = parse_set("supply.flow=10,30,60", scene.to_dict())
    assert p.values == ("10 mm3/h", "30 mm3/h", "60 mm3/h")
    flows = [loads_scene(c.scene_toml).supply.flow for c in expand(scene, [p])]
    assert flows == pytest.approx([v * 1e-9 / 3600.0 for v in (10, 30, 60)], rel=1e-12)


def test_summary_column_and_resume_of_a_folder_in_pints_spelling(scene, tmp_path):
    d = scene.to_dict()
    old = run_sweep(scene, [parse_set("supply.flow=10,30 mm**3/h", d)], tmp_path,
                    runner=_runner, workers=1, progress=False)
    assert "supply.flow [mm**3/h]" in old.columns
    calls = []

    def counting(scene_toml: str) -> dict[str, float]:
        calls.append(scene_toml)
        return _runner(scene_toml)

    new = run_sweep(scene, [parse_set("supply.flow=10,30", d)], tmp_path, runner=counting,
                    workers=1, progress=False)
    assert calls == []  # the same flows: resumed, not rerun
    assert len(new) == 2
    fresh = run_sweep(scene, [parse_set("supply.flow=10,30", d)], tmp_path / "new",
                      runner=_runner, workers=1, progress=False)
    assert "supply.flow [mm3/h]" in fresh.columns
    assert list(fresh["supply.flow [mm3/h]"]) == [10.0, 30.0]


@pytest.mark.parametrize("spec, empty", [("supply.flow=15,,33", 2), (",15", 1),
                                         ("15, ,33", 2), ("15,33,,", 3)])
def test_an_empty_value_between_commas_is_refused(spec, empty):
    # "15,,33" (a typo of 15,25,33?) ran the cases 15 and 33 without a word
    from thermobearing.errors import InputError

    d = load_scene().to_dict()
    spec = spec if spec.startswith("supply.flow=") else "supply.flow=" + spec
    with pytest.raises(InputError, match=f"value {empty} is empty"):
        parse_set(spec, d)


def test_a_trailing_comma_is_allowed():
    assert parse_set("supply.flow=15,33,", load_scene().to_dict()).values == ("15 L/min",
                                                                              "33 L/min")
