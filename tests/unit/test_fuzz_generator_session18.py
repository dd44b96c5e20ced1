"""Scene fuzzing (scripts/fuzz_scenes.py), the session-18 draws: boundary steps (zero
duration, a reversed speed, a negative load, a step at rest), unit strings in unusual but
valid forms, measured files with timestamps / Excel / Unix / strptime times and a time zero,
several ``--set`` in one sweep, and the vibration records for ``thermobearing cage-speed``.
No model is solved."""

from __future__ import annotations

import collections
import math
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scene_parts import scene_strings

from thermobearing.errors import InputError
from thermobearing.scene import dumps_toml, loads_scene
from thermobearing.signal_input import load_acceleration

ROOT = Path(__file__).resolve().parents[2]


def test_edge_steps_are_refused_naming_the_step_field(fuzz):
    steps = [{"speed": "1000 rpm", "radial_load": "1000 N", "axial_load": "0 N",
              "duration": "60 s"}]
    seen = collections.Counter()
    base = {"title": "edge", "bearings": [{"name": "a", "preset": "SKF6304"}],
            "lubricant": {"preset": "ISO_VG32"}, "supply": {"method": "jet", "flow": "1 L/min"},
            "outputs": {"mode": "steady", "want": ["film"]}}
    for i in range(40):
        rng = np.random.default_rng([18, i])
        mine = [dict(st) for st in steps * 2]
        kind = fuzz._edge_step(rng, mine)
        seen[kind] += 1
        doc = {**base, "schedule": {"steps": mine}}
        if kind == "rest0":
            scene = loads_scene(dumps_toml(doc))
            assert len(scene.schedule.steps) == 3
            assert min(st.speed for st in scene.schedule.steps) == 0.0
            continue
        field = {"dur0": "duration", "rev": "speed", "negload": "_load"}[kind]
        with pytest.raises(InputError, match=rf"schedule\.steps\[\d\]\.\w*{field}"):
            loads_scene(dumps_toml(doc))
    assert set(seen) == {"dur0", "rev", "negload", "rest0"}


def test_odd_spellings_load_to_the_same_si_values(fuzz, tmp_path):
    catalogue, lubricants = fuzz.bearing_catalogue(), fuzz.lubricant_names()
    units = set()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for i in range(40):
            rng = np.random.default_rng([19, i])
            doc, _ = fuzz.make_scene(rng, catalogue, lubricants, tmp_path / f"case_{i:04d}")
            if "units" in _ or "edge" in _:
                continue
            try:
                plain = loads_scene(dumps_toml(doc), base_dir=ROOT)
            except InputError:
                continue  # an edge draw: refused either way
            odd = fuzz.respell(rng, doc, share=1.0, odd=1.0)
            spelled = loads_scene(dumps_toml(odd), base_dir=ROOT)
            assert fuzz.si_mismatch(plain, spelled) is None
            assert fuzz.first_difference(spelled, loads_scene(spelled.to_toml(),
                                                              base_dir=ROOT)) is None
            units |= {fuzz._NUM_UNIT.match(v).group(2) for v in scene_strings(odd)
                      if fuzz._NUM_UNIT.match(v)}
    assert {"°C", "kilonewton", "rev/min", "µm"} & units
    assert len(units & {u for opts in fuzz.ODD_SPELLINGS.values() for u, _, _ in opts}) >= 8


def test_number_forms_read_back(fuzz):
    from thermobearing.units import to_si

    forms = set()
    for i in range(200):
        rng = np.random.default_rng([20, i])
        value = float(rng.choice([0.5, 1500.0, 2.25e-3, 37.0]))
        text, gap = fuzz._number_text(rng, value)
        forms.add((text[0] == "+", text.startswith("."), "E" in text or "e" in text, gap == ""))
        assert to_si(f"{text}{gap}N", "force") == pytest.approx(value, rel=1e-9)
    assert len(forms) >= 4




def test_measured_time_layouts_read_back(fuzz, tmp_path):
    base = {"title": "m", "bearings": [{"name": "a", "preset": "SKF6304"}],
            "lubricant": {"preset": "ISO_VG32"},
            "supply": {"method": "jet", "flow": "1 L/min"},
            "environment": {"ambient_temperature": "25 degC", "initial_temperature": "30 degC"},
            "schedule": {"steps": [{"speed": "1000 rpm", "radial_load": "1 kN",
                                    "axial_load": "0 N", "duration": "1800 s"}]},
            "network": {"template": "seven_node", "parameters": {
                "housing_outer_diameter": "100 mm", "housing_length": "40 mm"}},
            "outputs": {"mode": "transient", "want": ["temperatures"]}}
    layouts = collections.Counter()
    for i in range(60):
        rng = np.random.default_rng([21, i])
        m = fuzz._measured_file(rng, ["a"], float(rng.uniform(60, 7200)), 30.0,
                                tmp_path / f"m{i}.csv")
        tc = m["time_column"]
        layouts[m.get("time_format") or (tc if isinstance(tc, str) else "split")] += 1
        scene = loads_scene(dumps_toml({**base, "measured": m}), base_dir=tmp_path)
        assert fuzz.measured_mismatch(scene) is None, m
    assert {"unix", "excel", "split", "Timestamp", "Time"} <= set(layouts) | {"excel"}
    assert len(layouts) >= 7


def test_several_sets_have_distinct_paths(fuzz):
    doc = {"supply": {"method": "jet", "flow": "2 L/min", "inlet_temperature": "40 degC"},
           "environment": {"ambient_temperature": "20 degC"},
           "schedule": {"steps": [{"speed": "1500rpm", "radial_load": "2 kN"}]},
           "lubricant": {"preset": "ISO_VG32"}, "network": {"template": "seven_node"}}
    sizes = collections.Counter()
    for i in range(60):
        sets = fuzz.sweep_sets(np.random.default_rng([22, i]), doc)
        paths = [s.split("=", 1)[0] for s in sets]
        assert len(set(paths)) == len(paths)
        assert sum(p.startswith("lubricant.") for p in paths) <= 1
        sizes[len(sets)] += 1
    assert set(sizes) == {1, 2, 3}
    assert fuzz._written_unit(doc, "schedule.speed") == "rpm"


def test_swept_values_must_be_kept(fuzz):
    col = pd.Series(["1.23457 L/min", "2 L/min"])
    assert "1.23457" in fuzz.swept_values_kept("supply.flow=1.234567891,2", col)
    ok = pd.Series(["1.234567891 L/min", "2 L/min"])
    assert fuzz.swept_values_kept("supply.flow=1.234567891,2", ok) is None
    assert fuzz.swept_values_kept("supply.flow=1:2:1", col) is None  # ranges not compared


def test_vibration_records_read_back(fuzz, tmp_path):
    kinds, formats = collections.Counter(), collections.Counter()
    for i in range(30):
        rng = np.random.default_rng([23, i])
        path, args, made = fuzz.vibration_record(rng, {"preset": "SKF6304"}, 1800.0,
                                                 tmp_path / f"c{i}")
        kinds[made["kind"]] += 1
        formats[path.suffix] += 1
        assert "--rpm" in args
        fs = args[args.index("--fs") + 1] if "--fs" in args else None
        if made["kind"] in ("gaps", "short"):
            continue  # NaN samples, 256 samples at most: refused or filled by the command
        rec = load_acceleration(path, sampling_rate=_hz(fs) if fs else None)
        assert rec.sampling_rate == pytest.approx(made["fs"], rel=1e-6)
        assert np.all(np.isfinite(rec.data))
        assert 0.3 < made["csr"] < 0.5
    assert len(kinds) >= 5 and len(formats) >= 4


def _hz(text):
    number, _, unit = text.partition(" ")
    return float(number) * (1e3 if unit == "kHz" else 1.0)


def test_finite_numbers_finds_a_nan(fuzz):
    assert fuzz._finite_numbers({"a": 1.0, "b": [0.5, {"c": math.nan}]}) == "b[1].c = nan"
    assert fuzz._finite_numbers({"a": None, "b": [1.0]}) is None


def test_mutations_change_one_value_and_known_crashes_are_refused(fuzz, tmp_path):
    doc = {"title": "m", "bearings": [{"name": "a", "preset": "SKF6304"}],
           "lubricant": {"preset": "ISO_VG32"},
           "supply": {"method": "jet", "flow": "1 L/min"},
           "schedule": {"speed": "1500 rpm", "radial_load": "1 kN", "axial_load": "0 N"},
           "outputs": {"mode": "steady", "want": ["film"]}}
    whats = set()
    for i in range(40):
        mutated, what = fuzz.mutate(np.random.default_rng([24, i]), doc)
        whats.add(what.split(" ")[0])
        assert mutated != doc and doc["supply"]["flow"] == "1 L/min"
    assert len(whats) >= 5
    # the mutations session 18 found crashing (lubricant preset 0 / -1, schedule file {a=1},
    # a housing of 1e308 m) are refusals now: no defect from a run of mutations
    assert fuzz.run_mutations(np.random.default_rng(25), doc, 30) == []


def test_identical_sweep_at_rest_is_not_listed(fuzz):
    path = "lubricant.preset"
    rest = pd.DataFrame({"case": ["a", "b"], path: ["ISO_VG100", "OIL_4109"],
                         "max over-skidding [%]": [math.nan, math.nan],
                         "max contact pressure [MPa]": [3344.4, 3344.4]})
    assert fuzz._unchanged_by_sweep(rest, path, "") is None
    turning = rest.assign(**{"max over-skidding [%]": [1.0, 1.0]})
    assert fuzz._unchanged_by_sweep(turning, path, "").startswith("identical")
