"""Session-19 user tour, the run report: a run's loss map crosses no failure and leaves out
the steps at rest,
the measured-vs-predicted table's mean error, the loss-temperature note naming its column."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from thermobearing.report import _run_loss_maps
from thermobearing.report_losses import breakdown_by_source, turning_points

#: (source, role, W at 1000 rpm and 1 kN); the power scales with speed x (1 + load)
_SOURCES = (("raceway_traction", "inner_ring", 10.0), ("churning_elements", "oil", 20.0))


def _protocol(points, bearings=("test",)) -> pd.DataFrame:
    """A long losses table with one step per (speed [rpm], axial load [kN]) point."""
    rows = []
    for b in bearings:
        for i, (n, fa) in enumerate(points):
            for src, role, w in _SOURCES:
                rows.append({"step": i, "time [s]": 600.0 * (i + 1), "bearing": b,
                             "speed [rpm]": float(n), "radial load [kN]": 1.0,
                             "axial load [kN]": float(fa), "source": src,
                             "component": src, "role": role,
                             "power [W]": w * n / 1000.0 * (1.0 + fa),
                             "load dependence": "load_dependent"})
    return pd.DataFrame(rows)


def test_a_rig_protocol_of_speed_and_load_steps_crosses_no_failure_in_its_loss_map(
        monkeypatch):
    """A speed ramp at 5 kN, a ramp at 20 kN from 1200 r/min, 40 kN at the top speed,
    then a stop: the run's loss map crossed the grid points no step ran as "no result ...
    (failed or not run)", though nothing failed, and put the stop (0 r/min, 0 kN) on the
    grid. Now the stop is left out (6 of 9 points) and the crosses say no step ran there.
    (The session-19 protocol, a ramp at 5 kN then 20 and 40 kN at the top speed, covers
    no 2 x 2 block of its grid and has no map now: test_ka24_report_units.py.)"""
    import thermobearing.report as report

    seen = []
    real = report.fig_loss_maps

    def spy(summary, x, y, components, **kw):
        seen.append((summary, kw.get("missing")))
        return real(summary, x, y, components, **kw)

    monkeypatch.setattr(report, "fig_loss_maps", spy)
    notes = []
    real_mark = report._mark_points
    monkeypatch.setattr(report, "_mark_points",
                        lambda ax, xs, ys, values, missing=report.NOT_RUN: (
                            notes.append((int((~np.isfinite(values)).sum()), values.size,
                                          missing)),
                            real_mark(ax, xs, ys, values, missing))[-1])
    steps = [(600, 5), (1200, 5), (1800, 5), (1200, 20), (1800, 20), (1800, 40), (0, 0)]
    maps = _run_loss_maps(_protocol(steps))
    assert list(maps) == ["loss_maps_test"] and maps["loss_maps_test"][:4] == b"\x89PNG"
    (drawn, missing), = seen
    assert missing == report.NOT_A_STEP == "no step of this run"
    assert sorted(set(drawn["speed [rpm]"])) == [600.0, 1200.0, 1800.0]  # no stop
    assert notes and all(n == (3, 9, report.NOT_A_STEP) for n in notes)


def test_a_full_grid_with_a_stop_step_keeps_its_map_without_the_rest_point():
    grid = [(n, fa) for n in (1000, 2000) for fa in (1, 3)]
    losses = _protocol([*grid, (0, 0)], bearings=("de", "nde"))
    wide = turning_points(breakdown_by_source(losses))
    assert sorted(set(wide["speed [rpm]"])) == [1000.0, 2000.0]  # the stop is left out
    assert len(wide) == 8
    maps = _run_loss_maps(losses)
    assert sorted(maps) == ["loss_maps_de", "loss_maps_nde"]
    assert all(png[:4] == b"\x89PNG" for png in maps.values())


def test_a_sweeps_map_still_says_failed_or_not_run(monkeypatch):
    import thermobearing.report as report

    said = []
    monkeypatch.setattr(report, "_mark_points",
                        lambda ax, xs, ys, values, missing=report.NOT_RUN: said.append(
                            (int((~np.isfinite(values)).sum()), missing)))
    summary = pd.DataFrame({"n": [1.0, 1.0, 2.0], "f": [1.0, 2.0, 1.0],
                            "total [W]": [1.0, 2.0, 3.0]})
    assert report.fig_loss_maps(summary, "n", "f", ["total [W]"])[:4] == b"\x89PNG"
    assert said == [(1, "failed or not run")]


def test_the_errors_table_gives_the_mean_error_with_its_sign():
    """A thermocouple reading 0.8 K above the prediction with noise: the RMSE (about
    0.8 K) cannot tell a model that runs cold from one that scatters; the mean error
    (predicted - measured, the calibration's sign) can."""
    from thermobearing.report_measured import temperature_errors, terminal_lines

    t = np.arange(0.0, 3601.0, 60.0)
    temps = pd.DataFrame({"time [s]": t, "test.housing [degC]": 30.0 + t / 360.0})
    rng = np.random.default_rng(3)
    noise = rng.normal(0.0, 0.15, t.size)
    measured = pd.DataFrame({"time [s]": t,
                             "TC1": 30.0 + t / 360.0 + 0.8 + noise})
    err = temperature_errors(temps, measured, {"TC1": "test.housing"}).iloc[0]
    assert err["mean error [K]"] == pytest.approx(-0.8 - noise.mean(), abs=1e-12)
    assert err["RMSE [K]"] == pytest.approx(np.sqrt(np.mean((0.8 + noise) ** 2)), abs=1e-12)
    line = terminal_lines(measured, temps, {"TC1": "test.housing"})[0]
    assert line.endswith(f"; mean error (predicted - measured): TC1 {err['mean error [K]']:+.2f} K")


def test_the_loss_temperature_note_names_the_column_it_refers_to():
    """The note said "(the time column)" above a breakdown table without one."""
    from thermobearing.report_context import loss_temperature_note

    note = loss_temperature_note({"temperatures": pd.DataFrame()}, scene=None)
    assert "time [s]" in note and "losses.csv" in note


def test_the_report_says_the_sign_of_the_mean_error(tmp_path):
    from thermobearing.report import MEAN_ERROR_NOTE, write_report
    from thermobearing.results import Results
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_synthetic_measured")
    t = np.arange(0.0, 3601.0, 60.0)
    temps = pd.DataFrame({"time [s]": t, "drive_end.housing [degC]": 35.0 + t / 600.0,
                          "non_drive_end.housing [degC]": 35.0 + t / 600.0})
    path = write_report(Results(tables={"temperatures": temps}), scene,
                        tmp_path / "report.html")
    text = path.read_text(encoding="utf-8")
    assert "mean error [K]" in text and MEAN_ERROR_NOTE in text


def test_a_sweep_whose_every_case_is_flagged_says_so_instead_of_listing_six():
    """A flow x speed sweep of the default rig: its first steps skid at every flow and
    speed, and the report named the first six of 20 cases 'and 14 more'."""
    from thermobearing.commands.report import flagged_cases

    df = pd.DataFrame({"flow [L/min]": [15.0, 15.0, 33.0, 33.0],
                       "n [rpm]": [600.0, 1800.0, 600.0, 1800.0],
                       "steps over skid limit [-]": [2, 5, 2, 4]})
    (note,) = flagged_cases(df, ["flow [L/min]", "n [rpm]"])
    assert note.startswith("4 of 4 cases have steps with cage skidding")
    assert note.endswith(": every case, 2 to 5 steps each")
    (same,) = flagged_cases(df.assign(**{"steps over skid limit [-]": 3}),
                            ["flow [L/min]", "n [rpm]"])
    assert same.endswith(": every case, 3 steps each")


def test_the_cage_speed_caption_says_which_state_it_draws():
    from thermobearing.report import _caption

    text = _caption("cage_speed_ratio")
    assert "each step's first solved state" in text and "skid warnings" in text


def test_a_transient_kinematics_table_says_its_rows_are_each_steps_first_state():
    from thermobearing.report import KINEMATICS_ROWS_NOTE, html_report
    from thermobearing.results import Results

    kin = pd.DataFrame({"step": [0], "time [s]": [0.0], "bearing": ["b"],
                        "cage speed ratio [-]": [0.4]})
    temps = pd.DataFrame({"time [s]": [0.0, 60.0], "b.oil [degC]": [35.0, 36.0]})
    text = html_report(Results(tables={"kinematics": kin, "temperatures": temps}), "t")
    import html

    note = html.escape(KINEMATICS_ROWS_NOTE)
    assert note in text
    assert note not in html_report(Results(tables={"kinematics": kin}), "t")


def test_a_stopped_runs_report_says_so_at_the_top():
    """A run stopped by a thermal runaway: its report read as a finished run down to the
    first validity warning, below the breakdown and the figures."""
    from thermobearing.report import html_report
    from thermobearing.results import Results

    why = "stopped by an error: thermal runaway: node 'test.balls' reached 300 degC"
    text = html_report(Results(stats={"stopped": why}), "rig")
    banner = text.index("This run did not finish:")
    assert text.index("<h1>rig</h1>") < banner < text.index("<h2")  # before every section
    assert "did not finish" not in html_report(Results(stats={"wall_time_s": 1.0}), "rig")


def test_no_cage_speed_figure_when_every_ratio_is_the_theoretical_one():
    """Race control of a roller bearing: CSR = CSR_th by construction; the figure drew the
    model's input as its result. A ball bearing's race-control ratio moves with its
    contact angles and keeps the figure."""
    from thermobearing.report import attach_figures
    from thermobearing.results import Results

    def kin(csr):
        return pd.DataFrame({"step": [0, 1], "bearing": ["crb", "crb"],
                             "speed [rpm]": [20000.0, 30000.0],
                             "radial load [kN]": [3.0, 3.0], "axial load [kN]": [0.2, 0.2],
                             "cage speed ratio [-]": csr,
                             "theoretical cage speed ratio [-]": [0.452, 0.452]})

    rolled = Results(tables={"kinematics": kin([0.452, 0.452])},
                     chain=[("kinematics", "race_control")])
    attach_figures(rolled, None)
    assert "cage_speed_ratio" not in rolled.figures
    moved = Results(tables={"kinematics": kin([0.452, 0.4571])},
                    chain=[("kinematics", "race_control")])
    attach_figures(moved, None)
    assert moved.figures["cage_speed_ratio"][:4] == b"\x89PNG"


def test_a_race_control_roller_run_says_why_its_raceway_contacts_book_nothing():
    from types import SimpleNamespace

    from thermobearing.report_sections import _rolling_notes

    wide = pd.DataFrame({"step": [0, 1], "raceway_traction [W]": [0.0, 0.0],
                         "total [W]": [1599.0, 3290.0]})
    rc = SimpleNamespace(models={"kinematics": "race_control"})
    (note,) = _rolling_notes(wide, rc)
    assert note.startswith("raceway contacts (rolling and sliding shear): 0 W at every step")
    # a ball bearing's race control books spin and differential sliding: no note
    assert _rolling_notes(wide.assign(**{"raceway_traction [W]": [1.5, 53.4]}), rc) == []
    assert _rolling_notes(wide, SimpleNamespace(models={"kinematics": "skidding"})) == []
    assert _rolling_notes(wide, None) == []
