"""What a user meets in an oil-flow what-if sweep from the command line (issue 6 item 6,
a user tour): each test is a defect found by running ``thermobearing sweep`` on the
default scene, written before its fix. The runner is a small deterministic function of the
case's scene (the physics runner is tested elsewhere); what is under test is the sweep.
"""

from __future__ import annotations

import json
import socket
import threading

import pandas as pd
import pytest

from thermobearing import cli
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import (
    SchedulerUnreachable,
    expand,
    finished_cases,
    parse_set,
    run_sweep,
)


def capacity_runner(scene_toml: str) -> dict[str, float]:
    """Enthalpy capacity of the oil stream [W/K] (870 kg/m^3, 1900 J/(kg K)) and the skid
    limit [-] of a case: enough to see which case ran with which values."""
    sc = loads_scene(scene_toml)
    skid = sc.checks.skid_limit if sc.checks is not None else float("nan")
    return {"oil capacity [W/K]": sc.supply.flow * 870.0 * 1900.0, "skid limit [-]": skid}


def loss_runner(scene_toml: str) -> dict[str, float]:
    """A 'mean total loss [W]' that grows with the flow (what the sweep report plots)."""
    return {"mean total loss [W]": 1e6 * loads_scene(scene_toml).supply.flow}


@pytest.fixture(scope="module")
def scene():
    return load_scene()  # the default scene: QJ1044 rig of paper 002, no [checks] table


# --- checks.* thresholds can be swept on a scene without a [checks] table ----------------
def test_check_thresholds_sweep_without_a_checks_table(scene):
    # before: "--set = 'checks.skid_limit' is not allowed: an existing scene field"
    d = scene.to_dict()
    assert "checks" not in d
    p = parse_set("checks.skid_limit=2%,5 %,10", d)  # a bare number is in percent
    assert p.values == ("2 %", "5 %", "10 %")
    limits = [loads_scene(c.scene_toml).checks.skid_limit for c in expand(scene, [p])]
    assert limits == pytest.approx([0.02, 0.05, 0.10])
    stress = parse_set("checks.contact_stress_limit=3000,3500", d)  # bare: MPa
    assert stress.values == ("3000 MPa", "3500 MPa")
    film = parse_set("checks.min_film_parameter=1,1.5", d)
    assert film.values == (1.0, 1.5)
    ball = parse_set("checks.contact_stress_limit.ball=3200 MPa", d)
    [case] = expand(scene, [ball, film][:1])
    assert loads_scene(case.scene_toml).checks.ball_stress_limit == pytest.approx(3.2e9)
    with pytest.raises(InputError, match="self_aligning_ball"):
        parse_set("checks.contact_stress_limit.balls=3200 MPa", d)


# --- repeated values run once -----------------------------------------------------------
def test_repeated_values_are_dropped_and_said(scene, tmp_path, capsys, monkeypatch):
    d = scene.to_dict()
    # before: 15,15,33 gave three cases, two identical ones both run (3 lines in cases.jsonl)
    p = parse_set("supply.flow=15,15,33", d)
    assert p.values == ("15 L/min", "33 L/min")
    assert p.dropped == ("'15' (= '15 L/min')",)
    # the same quantity in another unit is the same case
    q = parse_set("supply.flow=15 L/min,0.25 L/s,33", d)
    assert q.values == ("15 L/min", "33 L/min") and len(q.dropped) == 1
    assert parse_set("lubricant.preset=ISO_VG32,ISO_VG32", d).values == ("ISO_VG32",)
    # a path given twice is refused (the second --set would silently win)
    with pytest.raises(InputError, match="each path once"):
        expand(scene, [parse_set("supply.flow=15", d), parse_set("supply.flow=33", d)])
    import thermobearing.simulation as simulation

    calls = []
    monkeypatch.setattr(simulation, "summarize_scene",
                        lambda text: calls.append(text) or capacity_runner(text))
    out = tmp_path / "dup"
    code = cli.main(["sweep", "--set", "supply.flow=15,15,33", "--out", str(out),
                     "--workers", "1", "--quiet"])
    err = capsys.readouterr().err
    assert code == 0 and len(calls) == 2
    assert "repeated value left out: '15' (= '15 L/min')" in err
    assert len((out / "cases.jsonl").read_text().splitlines()) == 2


# --- a text among numbers is named, not the number before it ----------------------------
def test_text_among_numbers_names_the_text(scene):
    # before: "supply.flow = '15' is not allowed" for --set supply.flow=15,abc
    p = parse_set("supply.flow=15,abc", scene.to_dict())
    assert p.values == ("15 L/min", "abc")
    with pytest.raises(InputError) as info:
        expand(scene, [p])
    assert "'abc'" in str(info.value) and "'15'" not in str(info.value)


# --- a bad value found by the models' set-up fails before any case runs ------------------
def test_bad_preset_fails_before_the_first_case(scene, tmp_path):
    # before: the good cases ran, then "sweep case ... lubricant preset = 'ISO_VG99' is not
    # allowed ...; the finished cases are kept" (and with one case: kept nothing)
    calls = []

    def runner(text):
        calls.append(text)
        return capacity_runner(text)

    p = parse_set("lubricant.preset=ISO_VG32,ISO_VG99", scene.to_dict())
    with pytest.raises(UnknownNameError) as info:
        run_sweep(scene, [p], tmp_path, runner=runner, workers=1, progress=False)
    msg = str(info.value)
    assert calls == []
    assert "lubricant.preset=ISO_VG99" in msg and "ISO_VG46" in msg
    assert "no case was run" in msg
    assert not (tmp_path / "cases.jsonl").exists()


def test_a_case_failing_at_run_time_says_how_many_are_kept(scene, tmp_path):
    from thermobearing.errors import ConvergenceError

    def runner(text):
        if loads_scene(text).supply.flow > 20e-3 / 60:  # the 33 L/min case
            raise ConvergenceError("coupled transient", 2.0, "thermal runaway", {})
        return capacity_runner(text)

    p = parse_set("supply.flow=15,33", scene.to_dict())
    with pytest.raises(ConvergenceError, match=r"1 finished case is kept"):
        run_sweep(scene, [p], tmp_path, runner=runner, workers=1, progress=False)


# --- summary.csv: swept quantities as numbers with the unit in the column name -----------
def test_summary_has_numeric_swept_columns_with_units(scene, tmp_path):
    # before: only 'supply.flow' with text cells "15 L/min": not a number, no unit in name
    d = scene.to_dict()
    params = [parse_set("supply.flow=15 L/min,0.5 L/s", d),
              parse_set("supply.inlet_temperature=30 degC,313.15 K", d),
              parse_set("lubricant.preset=ISO_VG32", d)]
    df = run_sweep(scene, params, tmp_path, runner=capacity_runner, workers=1,
                   progress=False)
    back = pd.read_csv(tmp_path / "summary.csv")
    for table in (df, back):
        cols = list(table.columns)
        assert cols[:7] == ["case", "supply.flow", "supply.flow [L/min]",
                            "supply.inlet_temperature", "supply.inlet_temperature [degC]",
                            "lubricant.preset", "oil capacity [W/K]"]
        assert pd.api.types.is_float_dtype(table["supply.flow [L/min]"])
        assert sorted(table["supply.flow [L/min]"]) == pytest.approx([15.0, 15.0, 30.0, 30.0])
        assert sorted(set(table["supply.inlet_temperature [degC]"])) == pytest.approx(
            [30.0, 40.0])


def test_sweep_report_reads_the_new_summary(scene, tmp_path, capsys):
    """The report of a sweep folder (commands/report.py) still draws its what-if curves
    from a summary with the numeric columns."""
    d = scene.to_dict()
    params = [parse_set("supply.flow=15,33", d), parse_set("lubricant.preset=ISO_VG32,"
                                                           "ISO_VG68", d)]
    run_sweep(scene, params, tmp_path, runner=loss_runner, workers=1, progress=False)
    assert cli.main(["report", str(tmp_path)]) == 0
    html = (tmp_path / "report.html").read_text()
    assert "what-if: supply.flow [L/min]" in html
    # the oil grade (text) gets its own what-if figure (before: skipped)
    assert "what-if: lubricant.preset" in html
    assert html.count("<img") == 2


# --- the terminal shows the main results, not 30 columns ---------------------------------
def test_terminal_table_is_compact(tmp_path, capsys, monkeypatch):
    import thermobearing.simulation as simulation

    many = {"mean total loss [W]": 1000.0, "max over-skidding [%]": 9.0,
            **{f"final n{i}.housing [degC]": 40.0 + i for i in range(12)},
            **{f"churning {i} [W]": float(i) for i in range(12)}}
    monkeypatch.setattr(simulation, "summarize_scene", lambda text: dict(many))
    out = tmp_path / "wide"
    # SCENE left out: the default scene, as for `thermobearing run` (before: an error)
    code = cli.main(["sweep", "--set", "supply.flow=15,33", "--out", str(out),
                     "--workers", "1", "--quiet"])
    text = capsys.readouterr().out
    assert code == 0
    header = text.splitlines()[0]
    assert "supply.flow" in header and "mean total loss [W]" in header
    assert "max over-skidding [%]" in header and "final n0.housing [degC]" in header
    assert "churning 5 [W]" not in header and len(header) < 160
    assert "more result columns there" in text
    assert len(pd.read_csv(out / "summary.csv").columns) == 2 + 1 + len(many)


# --- the dask scheduler: a typo, and a port that is not a scheduler ------------------------
@pytest.mark.parametrize("address", ["localhost:notaport", "tcp://host", "http://host:8787",
                                     "tcp://host:99999", ""])
def test_malformed_scheduler_address_is_named(scene, tmp_path, address):
    # before: ValueError traceback from inside dask, then a 10-s hang in Client.__del__
    p = parse_set("supply.flow=15", scene.to_dict())
    with pytest.raises(InputError, match="--scheduler") as info:
        run_sweep(scene, [p], tmp_path, runner=capacity_runner, scheduler=address or " ",
                  progress=False)
    assert "tcp://host:8786" in str(info.value)
    assert not (tmp_path / "cases.jsonl").exists()


@pytest.fixture()
def silent_server():
    """A TCP server that accepts connections and never answers (another service on the
    port, e.g. a web dashboard waiting for a request line)."""
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    conns = []
    stop = threading.Event()

    def serve():
        srv.settimeout(0.1)
        while not stop.is_set():
            try:
                conns.append(srv.accept()[0])
            except OSError:
                continue

    th = threading.Thread(target=serve, daemon=True)
    th.start()
    yield f"tcp://127.0.0.1:{srv.getsockname()[1]}"
    stop.set()
    th.join(1.0)
    for c in conns:
        c.close()
    srv.close()


def test_server_that_is_not_a_scheduler_is_reported_not_waited_for(scene, tmp_path,
                                                                   silent_server):
    # before: the sweep waited forever in dask's handshake (its timeout covers the TCP
    # connection only)
    p = parse_set("supply.flow=15,33", scene.to_dict())
    with pytest.raises(SchedulerUnreachable, match="did not answer as a dask scheduler"):
        run_sweep(scene, [p], tmp_path / "a", runner=capacity_runner,
                  scheduler=silent_server, progress=False, connect_timeout=0.5)
    assert not (tmp_path / "a" / "cases.jsonl").exists()  # nothing ran locally unasked
    df = run_sweep(scene, [p], tmp_path / "b", runner=capacity_runner,
                   scheduler=silent_server, fallback_local=True, workers=1, progress=False,
                   connect_timeout=0.5)
    assert len(df) == 2 and len(finished_cases(tmp_path / "b")) == 2
    assert [json.loads(x)["params"]["supply.flow"] for x in
            (tmp_path / "b" / "cases.jsonl").read_text().splitlines()] == ["15 L/min",
                                                                            "33 L/min"]


# --- small things typed by hand --------------------------------------------------------
def test_out_that_is_a_file_and_values_without_commas(scene, tmp_path):
    # before: "error: File exists: afile" and "'15 33' is not allowed: a number"
    path = tmp_path / "afile"
    path.write_text("x")
    p = parse_set("supply.flow=15", scene.to_dict())
    with pytest.raises(InputError, match="--out.*this is a file"):
        run_sweep(scene, [p], path, runner=capacity_runner, workers=1, progress=False)
    with pytest.raises(InputError, match="separated by commas"):
        parse_set("supply.flow=15 33", scene.to_dict())


def test_ctrl_c_before_the_first_case_finished(tmp_path, capsys, monkeypatch):
    import thermobearing.simulation as simulation

    def interrupted(text):
        raise KeyboardInterrupt

    monkeypatch.setattr(simulation, "summarize_scene", interrupted)
    out = tmp_path / "sw"
    code = cli.main(["sweep", "--set", "supply.flow=15,33", "--out", str(out), "--workers",
                     "1", "--quiet"])
    err = capsys.readouterr().err
    # before: "0 finished case(s) are kept in .../cases.jsonl (table: .../summary.csv)",
    # two files that did not exist
    assert code == 130
    assert "before the first case finished" in err
    # the folder keeps the base scene and the planned cases (it said "nothing was kept"
    # with scene.toml written: test_hl22_report_wording)
    assert "0 of 2 planned cases finished" in err and "nothing was kept" not in err
    assert not (out / "cases.jsonl").exists()


def test_resume_does_not_depend_on_the_order_of_the_set_options(scene, tmp_path):
    # before: `--set supply.flow=... --set supply.inlet_temperature=...` and the same two
    # options the other way round gave other case ids: the rerun recomputed every case
    d = scene.to_dict()
    flow = parse_set("supply.flow=15,33", d)
    t_in = parse_set("supply.inlet_temperature=30,45", d)
    calls = []

    def runner(text):
        calls.append(text)
        return capacity_runner(text)

    first = run_sweep(scene, [flow, t_in], tmp_path, runner=runner, workers=1, progress=False)
    assert len(calls) == 4
    again = run_sweep(scene, [t_in, flow], tmp_path, runner=runner, workers=1, progress=False)
    assert len(calls) == 4
    assert sorted(again["case"]) == sorted(first["case"])


def test_a_sweep_whose_cases_give_no_results_says_so(tmp_path, capsys, monkeypatch):
    # `thermobearing sweep paper001_tehl --set schedule.speed=1000,2000`: 80 s of runs and
    # a summary.csv with the swept values only, without a word (a film-only scene: the
    # sweep's runner reduces losses, kinematics and temperatures)
    import thermobearing.simulation as simulation

    monkeypatch.setattr(simulation, "summarize_scene", lambda text: {})
    code = cli.main(["sweep", "--set", "supply.flow=15,33", "--out", str(tmp_path / "s"),
                     "--workers", "1", "--quiet"])
    err = capsys.readouterr().err
    assert code == 0
    assert "gave no results" in err and "summarize_scene" in err


def test_untabulated_scene_is_noted_before_the_runs(tmp_path, capsys, monkeypatch):
    import thermobearing.simulation as simulation

    calls = []

    def runner(text):
        calls.append(capsys.readouterr().err)  # what the user had read when the runs began
        return {}

    monkeypatch.setattr(simulation, "summarize_scene", runner)
    # figures alone give nothing summarize_scene tabulates (a film-only scene tabulates its
    # smallest films: test_fuzz_sweep_film_note.py)
    from thermobearing.scene import configs_dir

    text = (configs_dir() / "scenes" / "paper001_tehl.toml").read_text(encoding="utf-8")
    text = text.replace('want = ["film"]', 'want = ["figures"]')
    scene_file = tmp_path / "figures_only.toml"
    scene_file.write_text(text, encoding="utf-8")
    code = cli.main(["sweep", str(scene_file), "--set", "schedule.speed=1000,2000", "--out",
                     str(tmp_path / "s"), "--workers", "1", "--quiet"])
    err = calls[0] + capsys.readouterr().err
    assert code == 0
    assert "will give no results" in calls[0] and "figures" in calls[0]
    assert err.count("no results") == 1


def test_scheduler_without_workers_is_an_error_not_a_wait(scene, tmp_path):
    # before: a scheduler started without `dask worker` took the cases and the sweep waited
    # forever (0/2 on the progress bar, nothing on a non-terminal)
    distributed = pytest.importorskip("distributed")
    p = parse_set("supply.flow=15,33", scene.to_dict())
    with distributed.LocalCluster(n_workers=0, processes=False,
                                  dashboard_address=None) as cluster:
        with pytest.raises(SchedulerUnreachable, match="has no workers"):
            run_sweep(scene, [p], tmp_path / "a", runner=capacity_runner,
                      scheduler=cluster.scheduler_address, progress=False,
                      connect_timeout=0.5)
        df = run_sweep(scene, [p], tmp_path / "b", runner=capacity_runner,
                       scheduler=cluster.scheduler_address, fallback_local=True, workers=1,
                       progress=False, connect_timeout=0.5)
    assert len(df) == 2


def test_an_unexpected_error_in_a_case_names_the_case(scene, tmp_path):
    # before: a bare ZeroDivisionError traceback, no word on which case or what was kept
    def runner(text):
        if loads_scene(text).supply.flow > 20e-3 / 60:
            raise ZeroDivisionError("float division by zero")
        return capacity_runner(text)

    p = parse_set("supply.flow=15,33", scene.to_dict())
    with pytest.raises(ZeroDivisionError) as info:
        run_sweep(scene, [p], tmp_path, runner=runner, workers=1, progress=False)
    note = " ".join(getattr(info.value, "__notes__", []))
    assert "supply.flow=33 L/min" in note and "1 finished case is kept" in note


# --- bearing overrides: the preset's unit, whole counts, an index that exists -------------
def test_bearing_override_values(scene):
    d = scene.to_dict()
    # before: a bare 0.1 was 0.1 m (the override is not in the scene, no display unit);
    # now the unit of the preset's own value ("0.10 mm" in configs/bearings/QJ1044.toml)
    p = parse_set("bearings.0.overrides.diametral_clearance=0.1,0.2", d)
    assert p.values == ("0.1 mm", "0.2 mm")
    assert parse_set("bearings.1.overrides.cage.guide_clearance=0.4", d).values == ("0.4 mm",)
    # before: 18.0, refused as "an integer >= 3"
    n = parse_set("bearings.0.overrides.n_balls=18,20", d)
    assert n.values == (18, 20) and all(isinstance(v, int) for v in n.values)
    cases = expand(scene, [p, n])
    assert len(cases) == 4
    # before: IndexError / ValueError tracebacks
    for bad in ("bearings.5.overrides.diametral_clearance=1",
                "bearings.x.overrides.diametral_clearance=1"):
        with pytest.raises(InputError, match="0 = drive_end, 1 = non_drive_end"):
            parse_set(bad, d)
