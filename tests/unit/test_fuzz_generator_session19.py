"""Scene fuzzing (scripts/fuzz_scenes.py), the session-19 mutations a user makes: unit and
number typos meant as the value written (``"35 C"``, ``"1.8 kRPM"``, ``"3,5 kN"``,
``"1 800 rpm"``, the minus sign U+2212), structural mistakes (a list element duplicated, a
table emptied, two quantities swapped, a list reversed, names in other scripts, a number
scaled by 1e-6..1e6). No model is solved."""

from __future__ import annotations

import collections

import numpy as np

DOC = {"title": "t", "bearings": [{"name": "a", "preset": "SKF6304"}],
       "lubricant": {"preset": "ISO_VG32"},
       "supply": {"method": "jet", "flow": "1.5 L/min", "inlet_temperature": "35 degC"},
       "environment": {"ambient_temperature": "25 degC", "initial_temperature": "30 degC"},
       "schedule": {"radial_load": "1 kN", "axial_load": "0 N", "step_duration": "60 s",
                    "steps": [{"speed": "1500 rpm"}, {"speed": "3000 rpm"}]},
       "models": {"kinematics": "race_control",
                  "heat_sources": ["raceway_traction", "churning_cage"]},
       "outputs": {"mode": "steady", "want": ["losses"]}}


def test_number_typos(fuzz):
    assert "3,5" in fuzz._number_typos("3.5")
    assert {"1,800", "1 800", "1'800"} <= set(fuzz._number_typos("1800"))
    assert "\u22125" in fuzz._number_typos("-5")
    assert fuzz._number_typos("7") == []


def test_typo_mutation_changes_one_quantity_and_keeps_the_document(fuzz):
    seen = set()
    for i in range(60):
        mutated, what, path, original, typo = fuzz.typo_mutate(np.random.default_rng([3, i]),
                                                               DOC)
        node = mutated
        for key in path:
            node = node[key]
        assert node == typo != original
        assert what.endswith(f"(meant {original!r})")
        seen.add(path[0])
    assert DOC["supply"]["flow"] == "1.5 L/min"
    assert {"supply", "schedule", "environment"} <= seen


def test_structure_mutations_cover_every_kind(fuzz):
    kinds = collections.Counter()
    for i in range(120):
        drawn = fuzz.structure_mutate(np.random.default_rng([4, i]), DOC)
        if drawn is None:
            continue
        mutated, what = drawn
        assert mutated != DOC
        for word in ("duplicated", "emptied", "swapped", "reversed", "x1", "name", "title"):
            if word in what:
                kinds[word] += 1
    assert len(kinds) >= 6
    assert DOC["schedule"]["steps"] == [{"speed": "1500 rpm"}, {"speed": "3000 rpm"}]


def test_user_mutations_of_a_scene_are_refusals_or_read_as_meant(fuzz):
    # no traceback, no typo read as another value; the accepted mutants are handed back
    accepted: list = []
    notes: list = []
    assert fuzz.run_mutations(np.random.default_rng(19), DOC, 40, notes, accepted) == []
    assert accepted and all(isinstance(text, str) and "title" in text
                            for _, text in accepted)


def test_a_misread_typo_is_reported(fuzz):
    from thermobearing.scene import dumps_toml, loads_scene

    doc = {**DOC, "supply": {**DOC["supply"], "flow": "1.5 L/h"}}
    # "1.5 L/h" in place of "1.5 L/min": a different value, which the check must catch
    text = dumps_toml(doc)
    found = fuzz._typo_misread(DOC, loads_scene(text), ("supply", "flow"), "1.5 L/min",
                               "1.5 L/h")
    assert found and "supply.flow" in found


def test_zero_raceway_pressure_of_a_roller_bearing_under_axial_load_alone(fuzz):
    # seed 63 case 4: a CRB with ribs on both rings at rest under 1 mN axial and no radial
    # load carries the axial load on its ribs; its raceways' 0 MPa is no defect. A ball
    # bearing's is.
    import pandas as pd

    df = pd.DataFrame({"bearing": ["crb", "ball"], "radial load [kN]": [0.0, 0.0],
                       "axial load [kN]": [1e-6, 1e-6],
                       "max contact pressure [MPa]": [0.0, 0.0]})
    found = fuzz._zero_pressure_under_load(df, frozenset({"crb"}))
    assert found and "bearing ball" in found
    assert fuzz._zero_pressure_under_load(df.iloc[:1], frozenset({"crb"})) is None
    assert fuzz._zero_pressure_under_load(df.iloc[:1]) is not None
    radial = df.iloc[:1].assign(**{"radial load [kN]": [1.0]})
    assert fuzz._zero_pressure_under_load(radial, frozenset({"crb"})) is not None
