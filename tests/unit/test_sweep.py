"""Sweep machinery: expansion, bad parameters, resume after interruption, dask == serial.

The runner here is a small deterministic function of the scene (the physics runners are
tested elsewhere); what is under test is the bookkeeping."""

from __future__ import annotations

import math

import pandas as pd
import pytest

from thermobearing.errors import InputError
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import expand, finished_cases, parse_set, run_sweep

CALLS: list[str] = []


def flow_speed_runner(scene_toml: str) -> dict[str, float]:
    """Enthalpy capacity of the oil stream [W/K] and the mean speed [rad/s] of a scene."""
    sc = loads_scene(scene_toml)
    speed = sum(s.speed * s.duration for s in sc.schedule.steps) / sc.schedule.duration
    return {"flow_capacity": sc.supply.flow * 870.0 * 1900.0, "mean_speed": speed}


class Interrupt(Exception):
    pass


def test_parse_and_expand():
    scene = load_scene()
    d = scene.to_dict()
    p1 = parse_set("supply.flow=15,20,25,33", d)
    p2 = parse_set("schedule.speed=600:1800:300", d)
    assert p1.values == ("15 L/min", "20 L/min", "25 L/min", "33 L/min")
    assert len(p2.values) == 5 and p2.values[0] == "600 rpm"
    cases = expand(scene, [p1, p2])
    assert len(cases) == 20 and len({c.case_id for c in cases}) == 20
    sc = loads_scene(cases[-1].scene_toml)
    assert sc.supply.flow == pytest.approx(33e-3 / 60)
    assert all(s.speed == pytest.approx(1800 * math.pi / 30) for s in sc.schedule.steps)


def test_values_with_their_own_units():
    """Each value may carry its unit; a bare number takes the list's trailing unit, else the
    scene value's; a range takes one unit after it."""
    scene = load_scene()
    d = scene.to_dict()
    p = parse_set("supply.inlet_temperature=30degC,50 degC", d)
    assert p.values == ("30 degC", "50 degC")
    assert parse_set("supply.flow=15 L/min,0.5 L/s", d).values == ("15 L/min", "0.5 L/s")
    assert parse_set("supply.flow=15,33 L/min", d).values == ("15 L/min", "33 L/min")
    assert parse_set("supply.flow=15,33", d).values == ("15 L/min", "33 L/min")
    assert parse_set("schedule.radial_load=1:3:1 kN", d).values == ("1 kN", "2 kN", "3 kN")
    assert parse_set("lubricant.preset=ISO_VG32,ISO_VG68", d).values == ("ISO_VG32",
                                                                        "ISO_VG68")
    cases = expand(scene, [p])
    temps = [loads_scene(c.scene_toml).supply.inlet_temperature for c in cases]
    assert temps == pytest.approx([303.15, 323.15])


@pytest.mark.parametrize("spec", ["supply.colour=1,2", "nosuch.field=3", "supply.flow",
                                  "supply.flow=3:1:1"])
def test_bad_parameter(spec):
    with pytest.raises(InputError):
        parse_set(spec, load_scene().to_dict())


def test_bad_value_names_field():
    scene = load_scene()
    p = parse_set("supply.flow=-3,5", scene.to_dict())
    with pytest.raises(InputError) as info:
        expand(scene, [p])
    assert "supply.flow" in str(info.value)


def test_resume_after_interrupt(tmp_path):
    scene = load_scene()
    params = [parse_set("supply.flow=10,20,30,40", scene.to_dict())]
    calls = []

    def dying_runner(text):
        if len(calls) == 2:
            raise Interrupt
        calls.append(text)
        return flow_speed_runner(text)

    with pytest.raises(Interrupt):
        run_sweep(scene, params, tmp_path, runner=dying_runner, workers=1, progress=False)
    assert len(finished_cases(tmp_path)) == 2
    second = []

    def counting_runner(text):
        second.append(text)
        return flow_speed_runner(text)

    df = run_sweep(scene, params, tmp_path, runner=counting_runner, workers=1, progress=False)
    assert len(second) == 2 and len(df) == 4
    assert (tmp_path / "summary.csv").is_file()
    again = run_sweep(scene, params, tmp_path, runner=counting_runner, workers=1, progress=False)
    assert len(second) == 2 and again.equals(df)


def test_dask_local_cluster_matches_serial(tmp_path):
    distributed = pytest.importorskip("distributed")
    scene = load_scene()
    params = [parse_set("supply.flow=15,33", scene.to_dict()),
              parse_set("schedule.speed=600,1800", scene.to_dict())]
    serial = run_sweep(scene, params, tmp_path / "serial", runner=flow_speed_runner, workers=1,
                       progress=False)
    with distributed.LocalCluster(n_workers=2, processes=False, dashboard_address=None) as cl:
        par = run_sweep(scene, params, tmp_path / "dask", runner=flow_speed_runner,
                        scheduler=cl.scheduler_address, progress=False)
    assert par.sort_values("case").reset_index(drop=True).equals(
        serial.sort_values("case").reset_index(drop=True))


def test_unreachable_scheduler(tmp_path):
    from thermobearing.sweep import SchedulerUnreachable

    scene = load_scene()
    params = [parse_set("supply.flow=15,33", scene.to_dict())]
    with pytest.raises(SchedulerUnreachable):
        run_sweep(scene, params, tmp_path, runner=flow_speed_runner,
                  scheduler="tcp://127.0.0.1:9", progress=False, connect_timeout=0.5)
    df = run_sweep(scene, params, tmp_path, runner=flow_speed_runner,
                   scheduler="tcp://127.0.0.1:9", fallback_local=True, workers=1,
                   progress=False, connect_timeout=0.5)
    assert len(df) == 2
    with pytest.raises(InputError, match="connect_timeout"):
        run_sweep(scene, params, tmp_path, runner=flow_speed_runner,
                  scheduler="tcp://127.0.0.1:9", progress=False, connect_timeout=0.0)


def test_summary_is_written_from_memory_not_by_rereading_the_store(tmp_path, monkeypatch):
    """The store (cases.jsonl) is read once, when the sweep starts (which cases are done);
    after each case summary.csv is rewritten from the records kept in memory (it used to
    re-read the whole store after every case: quadratic in the number of cases). The
    summary still lists every case in order, also after a resume."""
    from thermobearing import sweep_store

    reads = []
    original = sweep_store.finished_cases

    def counted(out_dir):
        reads.append(out_dir)
        return original(out_dir)

    monkeypatch.setattr(sweep_store, "finished_cases", counted)
    monkeypatch.setattr("thermobearing.sweep.finished_cases", counted)
    scene = load_scene()
    params = [parse_set("supply.flow=10,20,30,40,50", scene.to_dict())]
    df = run_sweep(scene, params, tmp_path, runner=flow_speed_runner, workers=1, progress=False)
    assert len(reads) == 1 and len(df) == 5
    assert list(df["supply.flow"]) == ["10 L/min", "20 L/min", "30 L/min", "40 L/min",
                                      "50 L/min"]
    on_disk = pd.read_csv(tmp_path / "summary.csv")
    assert list(on_disk["case"]) == list(df["case"])
    more = [parse_set("supply.flow=10,20,30,40,50,60", scene.to_dict())]
    df2 = run_sweep(scene, more, tmp_path, runner=flow_speed_runner, workers=1, progress=False)
    assert len(reads) == 2 and len(df2) == 6 and list(df2["case"])[:5] == list(df["case"])


def test_terminal_columns_fill_with_the_largest_losses():
    """Without the main results (no network: no housing rows), the terminal table fills
    with the loss columns that carry the most, not the first ones (a roller-guided cage
    books 0 W of cage-guide loss in every case)."""
    from thermobearing.commands.sweep import terminal_columns

    df = pd.DataFrame({"case": ["a", "b"], "schedule.speed": ["1 rpm", "2 rpm"],
                       "mean total loss [W]": [10.0, 20.0], "cage_guide [W]": [0.0, 0.0],
                       "churning_elements [W]": [5.0, 9.0], "raceway_traction [W]": [1.0, 2.0],
                       "steps over skid limit [-]": [0.0, 1.0]})
    shown, hidden = terminal_columns(df, ["schedule.speed"])
    assert shown == ["case", "schedule.speed", "mean total loss [W]", "churning_elements [W]",
                     "raceway_traction [W]", "steps over skid limit [-]"]
    assert hidden == 1


def test_a_resumed_sweep_says_what_it_resumed(tmp_path, capsys):
    scene = load_scene()
    params = [parse_set("supply.flow=10,20,30,40", scene.to_dict())]
    calls = []

    def dying_runner(text):
        if len(calls) == 3:
            raise Interrupt
        calls.append(text)
        return flow_speed_runner(text)

    with pytest.raises(Interrupt):
        run_sweep(scene, params, tmp_path, runner=dying_runner, workers=1, progress=None)
    first = capsys.readouterr().err
    assert "resuming" not in first
    run_sweep(scene, params, tmp_path, runner=flow_speed_runner, workers=1, progress=None)
    err = capsys.readouterr().err
    assert "sweep: resuming: 3 of 4 cases already in" in err and "1 to run" in err
    run_sweep(scene, params, tmp_path, runner=flow_speed_runner, workers=1, progress=False)
    assert "resuming" not in capsys.readouterr().err  # progress=False: nothing printed
