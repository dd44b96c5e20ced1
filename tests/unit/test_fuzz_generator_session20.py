"""Scene fuzzing (scripts/fuzz_scenes.py), the session-20 widening: structural mutations of
the kind ``extreme`` scale one number by 1e-300 .. 1e300 in its unit, and the check step of
the fuzzer evaluates the global_friction source as ``thermobearing check`` does. No model
is solved beyond the checks."""

from __future__ import annotations

import re

import numpy as np

from thermobearing.scene import dumps_toml, loads_scene

DOC = {"title": "t", "bearings": [{"name": "a", "preset": "SKF6304"}],
       "lubricant": {"preset": "ISO_VG32"},
       "supply": {"method": "jet", "flow": "1.5 L/min", "inlet_temperature": "35 degC"},
       "environment": {"ambient_temperature": "25 degC", "initial_temperature": "30 degC"},
       "schedule": {"radial_load": "1 kN", "axial_load": "0 N", "step_duration": "60 s",
                    "speed": "1500 rpm"},
       "models": {"kinematics": "race_control",
                  "heat_sources": ["raceway_traction", "churning_cage"]},
       "outputs": {"mode": "steady", "want": ["losses"]}}


def test_extreme_mutations_scale_by_the_extreme_factors(fuzz):
    factors = set()
    for i in range(400):
        drawn = fuzz.structure_mutate(np.random.default_rng([20, i]), DOC)
        if drawn is None:
            continue
        m = re.search(r"\(x([0-9.e+-]+)\)$", drawn[1])
        if m and abs(np.log10(float(m.group(1)))) >= 30:
            factors.add(float(m.group(1)))
    assert factors and factors <= set(fuzz.EXTREME_FACTORS)
    assert len(factors) >= 4


def test_extreme_mutants_are_refusals_naming_their_field(fuzz):
    """Every extreme mutant of the document either loads and passes the check or is
    refused naming a scene field; none stops with another exception."""
    from thermobearing.errors import InputError

    seen = 0
    for i in range(400):
        drawn = fuzz.structure_mutate(np.random.default_rng([20, i]), DOC)
        m = re.search(r"\(x([0-9.e+-]+)\)$", drawn[1]) if drawn else None
        if m is None or abs(np.log10(float(m.group(1)))) < 30:
            continue
        seen += 1
        try:
            scene = loads_scene(dumps_toml(drawn[0]))
            fuzz.check_scene(scene, raises=True)
        except InputError as exc:
            outcome, msg = fuzz.classify_error(exc)
            assert outcome == "REFUSED", (drawn[1], msg)
    assert seen >= 10


def test_the_check_step_refuses_what_global_friction_run_refuses(fuzz):
    doc = {**DOC, "schedule": {**DOC["schedule"], "axial_load": "300 N"},
           "models": {"kinematics": "none", "heat_sources": ["global_friction"]}}
    text = fuzz.check_scene(loads_scene(dumps_toml(doc)))
    assert text is not None and "static_load_rating" in text
