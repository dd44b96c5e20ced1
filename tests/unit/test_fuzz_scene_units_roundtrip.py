"""Scene fuzzing (scripts/fuzz_scenes.py): the generated scenes, every quantity rewritten in
another unit (K / degF, kN / lbf, rad/s / rev/s / krpm, L/h / m**3/s, m / inch, min ...),
load to the same SI values as the plain scenes, and each loaded scene's TOML reads back to
the same scene (``Scene.to_toml``). No model is solved."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scene_parts import scene_strings

from thermobearing.scene import dumps_toml, loads_scene

ROOT = Path(__file__).resolve().parents[2]


def _scenes(fuzz, tmp_path, seed: int, n: int):
    rng = np.random.default_rng(seed)
    catalogue, lubricants = fuzz.bearing_catalogue(), fuzz.lubricant_names()
    for i in range(n):
        doc, desc = fuzz.make_scene(rng, catalogue, lubricants, tmp_path / f"case_{i:04d}")
        fuzz.sweep_sets(rng, doc)
        if not set(desc["extras"].split(",")) & fuzz.EDGE_REFUSED:
            yield doc, desc  # (a boundary step the scene refuses: not a scene to compare)


def test_respelled_scenes_load_to_the_same_si_values(fuzz, tmp_path):
    rng = np.random.default_rng(7)
    spelled_units = set()
    for doc, _ in _scenes(fuzz, tmp_path, 21, 40):
        plain = loads_scene(dumps_toml(doc), base_dir=ROOT)
        other = fuzz.respell(rng, doc, share=1.0)
        spelled_units.update(v.split()[1] for v in scene_strings(other) if fuzz._QTY.match(v))
        assert fuzz.si_mismatch(plain, loads_scene(dumps_toml(other), base_dir=ROOT)) is None
    # the rewrite did reach the other spellings (not a test of nothing)
    assert {"K", "degF", "lbf", "rad/s", "krpm", "inch"} <= spelled_units


def test_loaded_scenes_read_back_from_their_toml(fuzz, tmp_path):
    for doc, _ in _scenes(fuzz, tmp_path, 22, 40):
        scene = loads_scene(dumps_toml(doc), base_dir=ROOT)
        back = loads_scene(scene.to_toml(), base_dir=ROOT)
        assert fuzz.first_difference(scene, back) is None


def test_first_difference_names_the_field(fuzz, tmp_path):
    doc, _ = next(_scenes(fuzz, tmp_path, 23, 5))
    scene = loads_scene(dumps_toml(doc), base_dir=ROOT)
    doc["environment"]["ambient_temperature"] = "-55 degC"
    other = loads_scene(dumps_toml(doc), base_dir=ROOT)
    assert fuzz.first_difference(scene, other).startswith(
        "scene.environment.ambient_temperature")


def test_protocol_files_read_to_the_steps_they_were_written_from(fuzz, tmp_path):
    """The generator's CSV protocols (column order, units in headers or cells, capitalised
    headers, BOM, CRLF, semicolons with decimal commas and points grouping thousands)."""
    n = 0
    for seed in (24, 25, 26, 27):
        for doc, desc in _scenes(fuzz, tmp_path, seed, 60):
            if "inline" not in desc:
                continue
            n += 1
            scene = loads_scene(dumps_toml(doc), base_dir=ROOT)
            inline = loads_scene(desc["inline"], base_dir=ROOT)
            assert fuzz.steps_mismatch(inline, scene) is None
    assert n >= 10
