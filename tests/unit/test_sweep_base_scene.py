"""A sweep folder records its base scene (``DIR/scene.toml``, file paths absolute), so
``thermobearing report DIR`` names the bearing that was swept; resuming keeps it, and a
resume with another base scene replaces it as the summary is replaced, saying so."""

from __future__ import annotations

from pathlib import Path

from thermobearing.commands.report import sweep_report
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep

EXAMPLE = "qj1044_synthetic_measured"  # its measured file is a relative path


def oil_capacity_runner(scene_toml: str) -> dict[str, float]:
    """Heat capacity rate of the oil stream [W/K] (ISO VG 46 near 40 degC: 870 kg/m^3,
    1900 J/(kg K)): a cheap deterministic result; the bookkeeping is under test."""
    sc = loads_scene(scene_toml)
    return {"oil capacity rate [W/K]": sc.supply.flow * 870.0 * 1900.0}


def test_sweep_writes_its_base_scene_and_the_report_names_the_bearing(tmp_path, capsys):
    scene = load_scene(EXAMPLE)
    params = [parse_set("supply.flow=15,33", scene.to_dict())]
    out = tmp_path / "sweep"
    run_sweep(scene, params, out, runner=oil_capacity_runner, workers=1, progress=False,
              check=False)
    recorded = loads_scene((out / "scene.toml").read_text(encoding="utf-8"))
    assert recorded.title == scene.title
    assert [b.preset for b in recorded.bearings] == ["QJ1044", "QJ1044"]
    assert Path(recorded.measured.file).is_absolute()
    assert Path(recorded.measured.file) == scene.resolve_path(scene.measured.file).resolve()
    page = sweep_report(out).read_text(encoding="utf-8")
    assert f"Base scene: {scene.title}" in page and "QJ1044" in page
    assert "has no scene.toml" not in page
    # resuming the same sweep: nothing to run, the record unchanged, nothing said
    before = (out / "scene.toml").read_text(encoding="utf-8")
    capsys.readouterr()
    df = run_sweep(scene, params, out, runner=oil_capacity_runner, workers=1,
                   progress=False, check=False)
    assert len(df) == 2 and (out / "scene.toml").read_text(encoding="utf-8") == before
    assert capsys.readouterr().err == ""


def test_resuming_with_another_base_scene_replaces_the_record_and_says_so(tmp_path,
                                                                          capsys):
    out = tmp_path / "sweep"
    first = load_scene(EXAMPLE)
    params = [parse_set("supply.flow=15,33", first.to_dict())]
    run_sweep(first, params, out, runner=oil_capacity_runner, workers=1, progress=False,
              check=False)
    d = first.to_dict()
    d["supply"]["inlet_temperature"] = "50 degC"
    d["title"] = "hotter oil"
    second = type(first).from_dict(d, Path(first.base_dir))
    capsys.readouterr()
    df = run_sweep(second, params, out, runner=oil_capacity_runner, workers=1,
                   progress=False, check=False)
    err = capsys.readouterr().err
    assert "held another base scene; replaced by this sweep's" in err
    assert loads_scene((out / "scene.toml").read_text(encoding="utf-8")).title == \
        "hotter oil"
    # as the summary: this sweep's cases alone; the earlier ones stay in the store
    assert len(df) == 2
    assert len((out / "cases.jsonl").read_text(encoding="utf-8").splitlines()) == 4
