"""Session-20 user tour, the test-rig engineer: the measured-vs-predicted readings as a CSV,
the calibrated scene's data path, the calibration's start-value error and the units of its
run log."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing import cli
from thermobearing.errors import InputError


def _synthetic_temps() -> pd.DataFrame:
    t = np.arange(0.0, 1801.0, 90.0)  # a 30-min run of the 60-min synthetic file
    return pd.DataFrame({"time [s]": t, "time [min]": t / 60.0,
                         "drive_end.housing [degC]": 35.0 + t / 600.0,
                         "non_drive_end.housing [degC]": 35.0 + t / 900.0})


def test_a_run_with_measured_data_writes_every_compared_reading_beside_its_prediction(
        tmp_path):
    """The report had only the per-sensor RMSE / max / mean: the readings against the
    prediction, for the engineer's own plots and statistics, were nowhere in the folder."""
    from thermobearing.measured import read_scene_measured
    from thermobearing.report import COMPARISON_CSV, write_report
    from thermobearing.report_measured import temperature_errors
    from thermobearing.results import Results, ResultsWriter
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_synthetic_measured")
    temps = _synthetic_temps()
    text = write_report(Results(tables={"temperatures": temps}), scene,
                        tmp_path / "report.html").read_text(encoding="utf-8")
    assert COMPARISON_CSV == "measured_vs_predicted.csv" and COMPARISON_CSV in text
    pairs = pd.read_csv(tmp_path / COMPARISON_CSV)
    assert list(pairs.columns) == ["time [s]", "time [min]", "sensor", "node",
                                   "measured [degC]", "predicted [degC]", "error [K]"]
    # the readings inside the 30-min run only: 31 one-minute samples per sensor
    assert pairs.groupby("sensor").size().to_dict() == {"TC_DE_synthetic": 31,
                                                        "TC_NDE_synthetic": 31}
    assert pairs["time [s]"].max() == pytest.approx(1800.0)
    de = pairs[pairs["sensor"] == "TC_DE_synthetic"]
    np.testing.assert_allclose(de["predicted [degC]"], 35.0 + de["time [s]"] / 600.0,
                               rtol=0, atol=1e-12)
    np.testing.assert_allclose(pairs["error [K]"],
                               pairs["predicted [degC]"] - pairs["measured [degC]"],
                               rtol=0, atol=1e-12)
    # its errors are the report table's
    measured = read_scene_measured(scene)
    table = temperature_errors(temps, measured, scene.measured.columns).set_index("sensor")
    for sensor, group in pairs.groupby("sensor"):
        rmse = math.sqrt(float(np.mean(group["error [K]"] ** 2)))
        assert rmse == pytest.approx(table.loc[sensor, "RMSE [K]"], rel=1e-12)
    # a later run into the folder does not keep it as its own
    ResultsWriter(tmp_path)
    assert not (tmp_path / COMPARISON_CSV).exists()


def test_a_comparison_without_any_reading_inside_the_run_has_its_columns_and_no_row():
    from thermobearing.report_measured import comparison_table

    temps = _synthetic_temps()
    measured = pd.DataFrame({"time [s]": [4000.0, 5000.0], "TC1": [40.0, np.nan]})
    table = comparison_table(temps, measured, {"TC1": "drive_end.housing",
                                               "TC2": "drive_end.housing"})
    assert table.empty and "error [K]" in table.columns


def _rebased(tmp_path: Path, measured_file: str) -> str:
    from thermobearing.calibrate_result import _rebase_paths
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_synthetic_measured")
    data = scene.to_dict()
    data["measured"]["file"] = measured_file
    scene = scene.from_dict(data, scene.base_dir)
    _rebase_paths(data, scene, tmp_path / "calibration")
    return data["measured"]["file"]


def test_the_calibrated_scene_keeps_an_absolute_data_path_absolute(tmp_path):
    """A scene whose [measured] file was /work/.../rig.csv got
    "../../../../work/.../rig.csv" in its calibrated copy: a path up to the root that
    breaks as soon as the calibrated scene is moved."""
    csv = tmp_path / "logger" / "rig.csv"
    assert _rebased(tmp_path, str(csv)) == str(csv)
    # a relative path is still rewritten relative to the calibrated scene's folder
    rel = _rebased(tmp_path, "../../examples/synthetic_rig_temperatures.csv")
    assert not Path(rel).is_absolute()
    assert ((tmp_path / "calibration" / rel).resolve()
            == (Path(cli.__file__).parents[1] / "examples"
                / "synthetic_rig_temperatures.csv").resolve())


def test_fitting_a_coefficient_the_template_computes_says_how_to_start_it():
    """`calibrate rig.toml --fit network.parameters.h_air` on a copy of the default rig
    (which leaves h_air to the housing's free-convection correlation) said only "a starting
    value (--x0 PATH=VALUE)": now the option is spelt out with the unit of a bare value,
    and the message says the fitted constant replaces the template's own value."""
    from thermobearing.calibrate_params import _make_parameter
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_rig")
    with pytest.raises(InputError) as info:
        _make_parameter(scene, scene.to_dict(), "network.parameters.h_air", {}, {}, {})
    text = str(info.value)
    assert "--x0 network.parameters.h_air=VALUE" in text and "W/(m**2*K)" in text
    assert "replaces" in text and "four_node_paper002" in text
    # with the start given, the parameter is made (a bare number in the unit named)
    p = _make_parameter(scene, scene.to_dict(), "network.parameters.h_air",
                        {"network.parameters.h_air": "10"}, {}, {})
    assert p.initial == pytest.approx(10.0) and p.display_unit == "W/(m**2*K)"


def test_the_calibration_run_log_has_units_in_its_columns_and_progress_lines(
        tmp_path, capsys, monkeypatch):
    """calibration_runs.csv had "network.parameters.h_air" and "supply.inlet_temperature"
    columns without units, and the progress lines "h_air=10" (W/(m^2 K)? degC?)."""
    import thermobearing.calibrate as calibrate
    from thermobearing.calibrate_params import FitParameter

    params = [FitParameter("network.parameters.h_air", "kg/s**3/K", "W/(m**2*K)", "log",
                           10.0, 0.0, math.inf, 0.01),
              FitParameter("supply.inlet_temperature", "K", "degC", "linear", 308.15,
                           -math.inf, math.inf, 0.1),
              FitParameter("bearings.0.overrides.ratio", "", "", "linear", 1.0,
                           -math.inf, math.inf, 0.01)]

    def fake_calibrate(scene, fit, *, callback=None, on_parameters=None, **kwargs):
        on_parameters(params)
        callback(1, {"network.parameters.h_air": 10.0, "supply.inlet_temperature": 35.0,
                     "bearings.0.overrides.ratio": 1.0}, 0.41)
        raise KeyboardInterrupt

    monkeypatch.setattr(calibrate, "calibrate", fake_calibrate)
    csv = tmp_path / "rig.csv"
    csv.write_text("time [min],TC1\n0,35.0\n5,36.1\n10,37.0\n", encoding="utf-8")
    src = (Path(cli.__file__).parents[1] / "configs" / "scenes"
           / "qj1044_synthetic_measured.toml").read_text(encoding="utf-8")
    src = src.replace('file = "../../examples/synthetic_rig_temperatures.csv"',
                      f'file = "{csv.as_posix()}"')
    scene = tmp_path / "rig.toml"
    scene.write_text(src, encoding="utf-8")
    out = tmp_path / "cal"
    code = cli.main(["calibrate", str(scene), "--fit", "network.parameters.h_air",
                     "--out", str(out)])
    err = capsys.readouterr().err
    assert code == 130
    assert "h_air=10 W/(m**2*K), inlet_temperature=35 degC, ratio=1  RMSE 0.41 K" in err
    header = (out / "calibration_runs.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header == ("run,network.parameters.h_air [W/(m**2*K)],"
                      "supply.inlet_temperature [degC],bearings.0.overrides.ratio,rmse [K]")


def test_bench_json_writes_null_where_a_benchmark_has_no_number():
    """`bench --json` printed NaN (no time within the error target), which is not JSON;
    `validate --json` writes null there."""
    import json

    from thermobearing.commands.bench import json_ready

    records = [{"case": "equal_accuracy", "time_s": float("nan"), "error": 1e-4,
                "ratio_vs_anchor": float("inf"), "nested": {"x": [float("nan"), 2.0]}}]
    text = json.dumps(json_ready(records), allow_nan=False)
    assert json.loads(text) == [{"case": "equal_accuracy", "time_s": None, "error": 1e-4,
                                 "ratio_vs_anchor": None, "nested": {"x": [None, 2.0]}}]


def test_a_report_column_reaching_ten_thousand_groups_the_thousands_of_every_value():
    """The 7014 C map's schedule read "8000" above "12,000" in the same speed column."""
    from thermobearing.report_sections import html_table

    text = html_table(pd.DataFrame({"speed [rpm]": [4000.0, 8000.0, 12000.0],
                                    "axial load [kN]": [0.3, 0.3, 0.8],
                                    "time [s]": [900.0, 1800.0, 2700.0]}))
    assert ">4,000<" in text and ">8,000<" in text and ">12,000<" in text
    # one grouping rule for every column (session 23): a column below 1e4 groups its
    # thousands too, as the powers beside it do (2,700 s; it read 2700 beside 1,031 W)
    assert ">2,700<" in text and ">0.8<" in text


@pytest.mark.parametrize("lo, hi", [(866.9, 1745.7), (1734.0, 3491.0), (76.43, 88.91),
                                    (0.0, 2100.0), (-3e-3, 5e-2)])
def test_a_shared_loss_map_colour_scale_has_round_levels_covering_its_range(lo, hi):
    """The oil what-if sweep's maps (one figure per oil grade, one colour scale) had colour
    bars reading 866.9, 1013.4, 1159.8, 1306.3, 1452.8, 1599.2 W."""
    from thermobearing.report import map_levels

    levels = map_levels(lo, hi)
    assert levels[0] <= lo and levels[-1] >= hi and 8 <= len(levels) <= 14
    step = float(np.diff(levels)[0])
    np.testing.assert_allclose(np.diff(levels), step, rtol=1e-9)
    # the step has at most two significant digits, the levels are its multiples
    mantissa = step / 10 ** math.floor(math.log10(step))
    assert abs(mantissa - round(mantissa, 1)) < 1e-9
    np.testing.assert_allclose(levels / step, np.round(levels / step), atol=1e-9)


def test_the_sweep_cross_check_lists_the_cases_in_the_summary_order(tmp_path, monkeypatch):
    """A speed x load sweep of the NU 214 with -j 2: the catalogue cross-check listed its
    cases in the order they finished (2000 r/min 1 kN, 2000/5, 5000/1, 2000/10, ...), the
    summary below it in the swept values' order."""
    import thermobearing.report_context as report_context
    from thermobearing.commands.report import _crosscheck_html

    scene = Path(cli.__file__).parents[1] / "configs" / "scenes" / "qj1044_rig.toml"
    (tmp_path / "scene.toml").write_text(scene.read_text(encoding="utf-8"), encoding="utf-8")
    seen = []

    def spy(base, records):
        seen.extend(r["case"] for r in records)
        return pd.DataFrame({"case": [r["case"] for r in records]}), []

    monkeypatch.setattr(report_context, "sweep_catalogue_crosscheck", spy)
    df = pd.DataFrame({"case": ["a", "b", "c", "d"], "speed [rpm]": [2000, 2000, 5000, 5000]})
    finished = [{"case": c, "params": {}} for c in ("b", "c", "x", "a", "d")]
    html = _crosscheck_html(tmp_path, df, finished)
    assert seen == ["a", "b", "c", "d"] and "Catalogue cross-check" in html


@pytest.mark.parametrize("path, meant", [
    ("network.parameters.h_oill", "network.parameters.h_oil"),
    ("network.h_oil", "network.parameters.h_oil"),
    ("network.parameters.housing_lenght", "network.parameters.housing_length")])
def test_a_misspelt_network_parameter_to_fit_gets_the_nearest_name(path, meant):
    """`--fit network.parameters.h_oill` listed the template's parameters without pointing
    at h_oil (a misspelt scene path, `--fit h_air`, got "did you mean")."""
    from thermobearing.calibrate_params import _make_parameter
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_rig")
    with pytest.raises(InputError) as info:
        _make_parameter(scene, scene.to_dict(), path, {}, {}, {})
    text = str(info.value)
    assert text.endswith(f"did you mean {meant}?")
    # the fields set elsewhere (the supply, the environment) are not offered
    assert "oil_flow" not in text and "ambient_temperature" not in text


def test_the_calibrated_scene_says_so_in_its_title():
    """The rerun with the calibrated scene wrote a report headed exactly as the
    uncalibrated run's; the title now carries the fitted values (once, also when a
    calibrated scene is fitted again)."""
    from thermobearing.calibrate import _stamped
    from thermobearing.calibrate_result import FittedParameter
    from thermobearing.scene import load_scene

    scene = load_scene("qj1044_synthetic_measured")
    fitted = [FittedParameter("network.parameters.h_oil", "W/(m**2*K)", "log", 270.0,
                              374.8123, 339.3, 414.1, 0.05),
              FittedParameter("network.parameters.h_air", "W/(m**2*K)", "log", 10.0,
                              17.8312, 13.8, 23.1, 0.13)]
    once = _stamped(scene, fitted, scene)
    assert once.title == (f"{scene.title} (calibrated: h_oil = 374.8 W/(m**2*K), "
                          "h_air = 17.83 W/(m**2*K))")
    again = _stamped(once, fitted[:1], once)
    assert again.title == f"{scene.title} (calibrated: h_oil = 374.8 W/(m**2*K))"
    assert "Calibrated with thermobearing.calibrate" in again.source


@pytest.mark.parametrize("protocol, drawn", [(True, True), (False, False)])
def test_the_sweep_what_if_draws_the_skidding_of_a_roller_bearing(tmp_path, monkeypatch,
                                                                protocol, drawn):
    """An NU 214 speed x load sweep whose cases skid (cage slower than epicyclic) at light
    load: the what-if curves drew only the largest over-skidding, which stays near 0 in a
    protocol whose other steps roll; the smallest is drawn when it is negative and differs
    from the largest (a one-step case has them equal: its max panel shows it)."""
    import json

    import thermobearing.report as report
    from thermobearing.commands.report import sweep_report

    drawn_ys = []
    real = report.fig_whatif

    def spy(df, x, ys, **kw):
        drawn_ys.append(list(ys))
        return real(df, x, ys, **kw)

    monkeypatch.setattr(report, "fig_whatif", spy)
    rows, store = [], []
    for i, (n, fr) in enumerate(((2000, 1), (2000, 10), (8000, 1), (8000, 10))):
        params = {"schedule.speed": f"{n} rpm", "schedule.radial_load": f"{fr} kN"}
        skid = -8.9 * n / 8000 if fr == 1 else -0.01
        result = {"mean total loss [W]": n * 0.3, "max over-skidding [%]":
                  (0.0 if protocol else skid), "min over-skidding [%]": skid}
        rows.append({"case": f"c{i}", **params, **result})
        store.append(json.dumps({"case": f"c{i}", "params": params, "result": result}))
    pd.DataFrame(rows).to_csv(tmp_path / "summary.csv", index=False)
    (tmp_path / "cases.jsonl").write_text("\n".join(store) + "\n", encoding="utf-8")
    sweep_report(tmp_path)
    assert drawn_ys and all(("min over-skidding [%]" in ys) == drawn for ys in drawn_ys)
    # the largest over-skidding is drawn unless it is noise beside the smallest (0 % in every
    # case of the protocol here: below 1 % of the skid, the panel is left out)
    assert all(("max over-skidding [%]" in ys) == (not protocol) for ys in drawn_ys)


def test_the_bench_table_says_why_a_setting_has_no_time():
    """`thermobearing bench bm8_vibration` printed "time nan s  error 0.0001  ratio nan"
    for an accuracy no setting reached, without the record's note that says so."""
    from thermobearing.commands.bench import record_line

    line = record_line({"case": "equal_accuracy_steep", "method": "split vs rk4",
                        "setting": "error <= 0.0001", "time_s": float("nan"),
                        "error": 1e-4, "ratio_vs_anchor": float("nan"),
                        "note": "rk4: none within target; split: none within target"})
    assert "nan" not in line
    assert "time - s  error 0.0001  ratio -" in line
    assert line.endswith("(rk4: none within target; split: none within target)")
    plain = record_line({"case": "c", "method": "m", "setting": "s", "time_s": 0.0109,
                         "error": 7.37e-05, "ratio_vs_anchor": 4.08})
    assert plain.endswith("time 0.0109 s  error 7.37e-05  ratio 4.08")
