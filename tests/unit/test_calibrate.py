"""Calibration against (synthetic) measured temperatures, bad input, and the measured overlay.

The "measured" data here are SYNTHETIC: the model's own output with known parameter values
plus seeded Gaussian noise (thermobearing.calibrate.synthetic_measurements), so the right
answer is known. Short protocols keep the default tests quick; the full example of
examples/README.md is marked slow.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing.calibrate import calibrate, synthetic_measurements
from thermobearing.errors import InputError
from thermobearing.report import read_measured, temperature_errors
from thermobearing.scene import Scene, load_scene, loads_scene

EXAMPLE = "qj1044_synthetic_measured"
SENSORS = {"TC_DE": "drive_end.housing", "TC_NDE": "non_drive_end.housing"}
TRUE = {"network.parameters.h_oil": 400.0, "network.parameters.h_air": 15.0}


def _short_scene(tmp_path: Path, data: pd.DataFrame | None = None, *, sensors=None,
                 measured: bool = True) -> Scene:
    """The example scene cut to two 15-min steps (0 and 28 kN), measured file in tmp."""
    d = load_scene(EXAMPLE).to_dict()
    d["schedule"]["steps"] = d["schedule"]["steps"][::2]
    d.pop("measured", None)
    if measured:
        path = tmp_path / "rig.csv"
        if data is not None:
            data.to_csv(path, index=False)
        d["measured"] = {"file": "rig.csv", "time_column": "time [min]", "unit": "degC",
                         "columns": dict(sensors or SENSORS)}
    return Scene.from_dict(d, tmp_path)


@pytest.fixture(scope="module")
def short_data(tmp_path_factory) -> pd.DataFrame:
    """Synthetic readings of the short scene with the TRUE values, every 5 min, 0.1 K noise."""
    scene = _short_scene(tmp_path_factory.mktemp("gen"), measured=False)
    return synthetic_measurements(scene, SENSORS, values=TRUE, noise_sd=0.1, seed=7,
                                  every=300.0)


def test_synthetic_data_are_labelled(short_data):
    assert list(short_data.columns) == ["time [min]", "TC_DE", "TC_NDE", "data_origin"]
    assert short_data["data_origin"].str.startswith("SYNTHETIC").all()
    assert np.allclose(short_data["time [min]"], np.arange(0, 31, 5))
    # both housings start at the initial 35 degC (noise 0.1 K) and warm up
    assert abs(short_data["TC_DE"].iloc[0] - 35.0) < 0.5
    assert short_data["TC_DE"].iloc[-1] > short_data["TC_DE"].iloc[0] + 1.0


def test_recovers_known_parameters_within_confidence_intervals(tmp_path, short_data):
    """Start at the template defaults (270, 10 W/(m^2 K)), recover (400, 15) from noisy data."""
    scene = _short_scene(tmp_path, short_data)
    res = calibrate(scene, list(TRUE))
    assert res.success and res.identifiable
    for p in res.parameters:
        truth = TRUE[p.path]
        assert p.ci_low < truth < p.ci_high, (p, truth)
        assert p.ci_low < p.value < p.ci_high
        assert p.unit == "W/(m**2*K)"
    # the fit explains the data down to the noise (sd 0.1 K, rounded to 0.01 K)
    assert res.rmse < 0.15 < res.initial_rmse
    assert 0.05 < res.residual_sd < 0.15
    assert res.points == 2 * 7 and res.dof == 12
    assert res.runs >= 3 * 2  # at least two Jacobians (2 runs each) plus the start
    assert list(res.sensors["sensor"]) == ["TC_DE", "TC_NDE"]
    # the calibrated scene carries the fitted values and loads back from its folder
    paths = res.write(tmp_path / "out")
    text = paths["scene"].read_text()
    assert text.startswith("# Calibrated scene") and "linearised" in text
    back = loads_scene(text, base_dir=paths["scene"].parent)
    assert "Calibrated with thermobearing.calibrate against rig.csv" in back.source
    h_oil = back.network["parameters"]["h_oil"]
    assert math.isclose(float(h_oil.split()[0]), res.parameters[0].value, rel_tol=1e-8)
    assert back.resolve_path(back.measured.file).resolve() == (tmp_path / "rig.csv").resolve()
    summary = json.loads(paths["summary"].read_text())
    assert summary["runs"] == res.runs


def test_noise_free_data_give_the_true_values_log_and_linear(tmp_path):
    """Without noise only the finite-difference Jacobian and the solver are left: a log
    parameter (h_oil 270 -> 400 W/(m^2 K)) and a linear one in kelvin (oil inlet
    35 -> 38 degC) must come back closely. A housing and an oil sensor."""
    sensors = {"TC_DE": "drive_end.housing", "TC_oil": "non_drive_end.oil"}
    scene0 = _short_scene(tmp_path, measured=False)
    before = scene0.to_toml()
    truth = {"network.parameters.h_oil": "400 W/(m**2*K)",
             "supply.inlet_temperature": "38 degC"}
    data = synthetic_measurements(scene0, sensors, values=truth, noise_sd=0.0, every=300.0,
                                  decimals=6)
    assert scene0.to_toml() == before  # the input scene is not modified
    scene = _short_scene(tmp_path, data, sensors=sensors)
    res = calibrate(scene, list(truth))
    h_oil, t_in = res.parameters
    assert (h_oil.initial, h_oil.transform) == (pytest.approx(270.0), "log")
    assert (t_in.initial, t_in.unit, t_in.transform) == (pytest.approx(35.0), "degC", "linear")
    assert h_oil.value == pytest.approx(400.0, rel=2e-3)
    assert t_in.value == pytest.approx(38.0, abs=0.01)
    assert res.scene.supply.inlet_temperature == pytest.approx(311.15, abs=0.01)
    assert res.rmse < 1e-3 < res.initial_rmse


def test_cli_writes_calibrated_scene(tmp_path, short_data, capsys):
    from thermobearing.cli import main

    scene = _short_scene(tmp_path, short_data)
    path = tmp_path / "short.toml"
    path.write_text(scene.to_toml())
    out = tmp_path / "cal"
    code = main(["calibrate", str(path), "--fit", "network.parameters.h_oil", "--out",
                 str(out), "--bounds", "network.parameters.h_oil=50:5000", "--quiet"])
    assert code == 0
    text = capsys.readouterr().out
    assert "network.parameters.h_oil" in text and "model runs" in text
    assert "TC_DE" in text and "RMSE" in text
    cal = load_scene(out / "short_calibrated.toml")
    assert float(cal.network["parameters"]["h_oil"].split()[0]) > 270.0
    assert read_measured(cal) is not None  # the measured file still resolves


# --------------------------------------------------------------------------- bad input
def test_scene_without_measured_is_an_error(tmp_path):
    scene = _short_scene(tmp_path, measured=False)
    with pytest.raises(InputError, match=r"\[measured\]"):
        calibrate(scene, ["network.parameters.h_oil"])


@pytest.mark.parametrize("path, words", [
    ("network.parameters.h_foo", "h_oil"),            # lists the template's parameters
    ("network.parameters.oil_flow", "supply.flow"),   # set elsewhere
    ("supply.nonsense", "existing scene field"),
    ("lubricant.preset", "numeric"),
])
def test_unknown_or_non_numeric_fit_parameter(tmp_path, short_data, path, words):
    scene = _short_scene(tmp_path, short_data)
    with pytest.raises(InputError, match=re.escape(words)):
        calibrate(scene, [path])


def test_column_mapped_to_missing_node_names_column_and_nodes(tmp_path, short_data):
    scene = _short_scene(tmp_path, short_data, sensors={"TC_DE": "drive_end.outer_ring"})
    with pytest.raises(InputError) as err:
        calibrate(scene, ["network.parameters.h_oil"])
    msg = str(err.value)
    assert "TC_DE" in msg and "drive_end.housing" in msg and "non_drive_end.oil" in msg


def test_gaps_are_left_out_of_the_fit(tmp_path, short_data):
    """A gap (empty cell or logger dropout flag, NaN) leaves that sample of that sensor out
    of the residuals and is named in the notes (earlier versions refused the whole file for
    any gap); a sensor without a single reading: tests/unit/test_hk22_calibrate_gaps.py."""
    gappy = short_data.copy()
    gappy["TC_NDE"] = gappy["TC_NDE"].astype(object)
    gappy.loc[3, "TC_NDE"] = "OVL"
    res = calibrate(_short_scene(tmp_path, gappy), ["network.parameters.h_oil"])
    points = res.sensors.set_index("sensor")["points"]
    assert points["TC_NDE"] == len(short_data) - 1 and points["TC_DE"] == len(short_data)
    assert res.points == 2 * len(short_data) - 1
    assert any("TC_NDE 1" in n and "left out" in n for n in res.notes)
    full = calibrate(_short_scene(tmp_path, short_data), ["network.parameters.h_oil"])
    assert res.parameters[0].value == pytest.approx(full.parameters[0].value, rel=0.05)


def test_missing_csv_column_is_an_error(tmp_path, short_data):
    scene = _short_scene(tmp_path, short_data.drop(columns=["TC_NDE"]))
    with pytest.raises(InputError, match="TC_NDE"):
        calibrate(scene, ["network.parameters.h_oil"])


def test_default_that_is_a_correlation_needs_x0(tmp_path, short_data):
    scene = _short_scene(tmp_path, short_data)
    params = {k: v for k, v in scene.network["parameters"].items() if k != "h_air"}
    scene = Scene.from_dict({**scene.to_dict(), "network": {**scene.network,
                                                            "parameters": params}}, tmp_path)
    with pytest.raises(InputError, match="x0"):
        calibrate(scene, ["network.parameters.h_air"])


def test_bad_bounds_and_steady_mode(tmp_path, short_data):
    scene = _short_scene(tmp_path, short_data)
    with pytest.raises(InputError, match="bounds"):
        calibrate(scene, ["network.parameters.h_oil"],
                  bounds={"network.parameters.h_oil": (500.0, 100.0)})
    with pytest.raises(InputError, match="inside the bounds"):
        calibrate(scene, ["network.parameters.h_oil"],
                  bounds={"network.parameters.h_oil": ("300 W/(m**2*K)", "900 W/(m**2*K)")})
    steady = Scene.from_dict({**scene.to_dict(), "outputs": {"mode": "steady",
                                                            "want": ["temperatures"]}},
                             tmp_path)
    with pytest.raises(InputError, match="transient"):
        calibrate(steady, ["network.parameters.h_oil"])


# --------------------------------------------------------------------------- overlay
def test_measured_overlay_in_report_and_example_data_up_to_date(tmp_path):
    """Run the shipped synthetic example with out_dir at the values that made its data: the
    report has the measured-vs-predicted table (per-sensor RMSE equal to a direct
    computation) and the temperature figure, and the RMSE is the added noise (0.1 K), which
    also guards against the committed CSV going stale when the physics change."""
    from thermobearing.simulation import Simulation

    scene = load_scene(EXAMPLE)
    measured = read_measured(scene)
    assert len(measured) == 61 and measured["time [s]"].iloc[-1] == 3600.0
    d = scene.to_dict()
    d["network"]["parameters"].update({"h_oil": "400 W/(m**2*K)", "h_air": "15 W/(m**2*K)"})
    scene = Scene.from_dict(d, Path(scene.base_dir))
    res = Simulation(scene, progress=False).run(out_dir=tmp_path)
    html = (tmp_path / "report.html").read_text()
    assert "<h3>measured vs predicted</h3>" in html
    assert "TC_DE_synthetic" in html and "TC_NDE_synthetic" in html
    assert re.search(r'<img alt="temperatures" src="data:image/png;base64,', html)
    assert (tmp_path / "temperatures.png").read_bytes()[:4] == b"\x89PNG"
    temps = res.tables["temperatures"]
    err = temperature_errors(temps, measured, scene.measured.columns)
    assert list(err["points"]) == [61, 61]
    t_model = temps["time [s]"].to_numpy()
    for sensor, node in scene.measured.columns.items():
        pred = np.interp(measured["time [s]"], t_model, temps[f"{node} [degC]"])
        rmse = float(np.sqrt(np.mean((pred - measured[sensor]) ** 2)))
        row = err[err["sensor"] == sensor].iloc[0]
        assert row["RMSE [K]"] == pytest.approx(rmse, rel=1e-12)
        # noise sd 0.1 K; the scene's 300-s coupling interval vs the 60 s of the generating
        # run adds about 0.02 K. Larger: the model has changed since the CSV was made --
        # rerun examples/make_synthetic_rig_data.py and update examples/README.md.
        assert 0.06 < rmse < 0.15, ("examples/synthetic_rig_temperatures.csv is stale?", rmse)


@pytest.mark.slow
def test_full_example_recovers_generating_values():
    """The shipped example (60 rows a sensor, made with a finer 60-s coupling interval
    than the scene's 300 s): h_oil = 400, h_air = 15 W/(m^2 K) inside the intervals."""
    scene = load_scene(EXAMPLE)
    res = calibrate(scene, list(TRUE))
    for p in res.parameters:
        assert p.ci_low < TRUE[p.path] < p.ci_high, p
    assert res.rmse < 0.13
