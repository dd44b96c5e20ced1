"""Tour R10: a sensor whose every reading is a gap.

Before: ``thermobearing calibrate`` refused the scene ("measured column 'TC_NDE' = '7
gaps' ... at least one reading") while ``thermobearing run`` accepted it with a note.
After: the fit leaves the sensor out (0 points, no residual, its row kept) and the model
carries the run's note; the fit equals the fit without that sensor mapped.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing.calibrate import calibrate, synthetic_measurements
from thermobearing.calibrate_model import _all_gap_notes, _Model, measured_table
from thermobearing.measured import measured_notes, read_scene_measured
from thermobearing.scene import Scene, load_scene

SENSORS = {"TC_DE": "drive_end.housing", "TC_NDE": "non_drive_end.housing"}
FIT = ["network.parameters.h_oil"]


def _scene(tmp_path: Path, data: pd.DataFrame | None, sensors=SENSORS) -> Scene:
    """The qj1044 synthetic example cut to two 15-min steps, measured file in tmp."""
    d = load_scene("qj1044_synthetic_measured").to_dict()
    d["schedule"]["steps"] = d["schedule"]["steps"][::2]
    d.pop("measured", None)
    if data is not None:
        data.to_csv(tmp_path / "rig.csv", index=False)
        d["measured"] = {"file": "rig.csv", "time_column": "time [min]", "unit": "degC",
                         "columns": dict(sensors)}
    return Scene.from_dict(d, tmp_path)


@pytest.fixture(scope="module")
def dead_data(tmp_path_factory) -> pd.DataFrame:
    scene = _scene(tmp_path_factory.mktemp("gen"), None)
    data = synthetic_measurements(scene, SENSORS, values={FIT[0]: 400.0}, noise_sd=0.1,
                                  seed=3, every=300.0)
    data["TC_NDE"] = np.nan  # every cell empty
    return data


def test_all_gap_sensor_carries_the_runs_note(tmp_path, dead_data):
    scene = _scene(tmp_path, dead_data)
    df = measured_table(scene, ["drive_end.housing", "non_drive_end.housing"])
    notes = _all_gap_notes(df, SENSORS)
    run_note = [n for n in measured_notes(read_scene_measured(scene))
                if n.startswith("TC_NDE")]
    assert notes == run_note and len(notes) == 1
    assert "every reading" in notes[0] and "not compared with the model" in notes[0]
    model = _Model(scene, [], df, SENSORS, None)
    assert model.notes == notes
    assert int(model.keep["TC_NDE"].sum()) == 0 and int(model.keep["TC_DE"].sum()) == 7


def test_calibrate_leaves_the_all_gap_sensor_out(tmp_path, dead_data):
    res = calibrate(_scene(tmp_path, dead_data), FIT)
    rows = res.sensors.set_index("sensor")
    assert rows.loc["TC_NDE", "points"] == 0 and np.isnan(rows.loc["TC_NDE", "RMSE [K]"])
    assert rows.loc["TC_DE", "points"] == 7 and res.points == 7
    assert any("TC_NDE 7" in n and "left out" in n for n in res.notes)
    # the run's own sentence reaches the calibration's notes too
    assert any("every reading" in n and "not compared with the model" in n
               for n in res.notes)
    (tmp_path / "alone").mkdir()
    alone = calibrate(_scene(tmp_path / "alone", dead_data.drop(columns=["TC_NDE"]),
                             {"TC_DE": "drive_end.housing"}), FIT)
    assert res.parameters[0].value == pytest.approx(alone.parameters[0].value, rel=1e-9)
    assert res.rmse == pytest.approx(alone.rmse, rel=1e-9)
