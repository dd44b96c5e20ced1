"""Tour E (session 24): a case store whose last line was cut keeps the next record.

A sweep killed while it wrote ``cases.jsonl`` (kill -9, a full disk) leaves a cut last
line. The resumed sweep appended its first finished case onto that line, which does not
parse: the case was lost from the store and ran again at the next resume (the tour's
13-value flow sweep: 12 of 13 kept after the resume that had finished the 13th).
"""

from __future__ import annotations

import json

import pytest

from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import finished_cases, parse_set, run_sweep


def _runner(text: str) -> dict[str, float]:
    return {"flow [L/min]": loads_scene(text).supply.flow * 6e4}


def test_a_resume_after_a_cut_line_keeps_its_first_case(tmp_path):
    scene = load_scene()
    d = scene.to_dict()
    run_sweep(scene, [parse_set("supply.flow=5,10", d)], tmp_path, runner=_runner,
              workers=1, progress=False)
    store = tmp_path / "cases.jsonl"
    with store.open("a", encoding="utf-8") as fh:
        fh.write('{"case": "0123456789ab", "params": {"supply.fl')   # killed mid-write
    df = run_sweep(scene, [parse_set("supply.flow=5,10,15", d)], tmp_path, runner=_runner,
                   workers=1, progress=False)
    assert sorted(df["flow [L/min]"]) == pytest.approx([5.0, 10.0, 15.0])
    kept = finished_cases(tmp_path)
    assert sorted(r["result"]["flow [L/min]"] for r in kept.values()) == \
        pytest.approx([5.0, 10.0, 15.0])
    lines = store.read_text(encoding="utf-8").splitlines()
    assert len(lines) == 4 and lines[2].startswith('{"case": "0123456789ab"')
    assert all(json.loads(line) for line in lines[:2] + lines[3:])


def test_a_missing_oil_file_is_named_where_it_was_looked_for(tmp_path, monkeypatch):
    # README: lubricant.path is "a relative file from the current folder"; a missing one was
    # left relative and named in the scene's folder (".../configs/scenes/nonexistent.toml")
    from thermobearing.errors import InputError
    from thermobearing.sweep import check_cases, expand

    monkeypatch.chdir(tmp_path)
    scene = load_scene()
    p = parse_set("lubricant.path=nonexistent.toml", scene.to_dict())
    assert p.values == (str(tmp_path / "nonexistent.toml"),)
    with pytest.raises(InputError, match=str(tmp_path / "nonexistent.toml")):
        check_cases(expand(scene, [p]))
