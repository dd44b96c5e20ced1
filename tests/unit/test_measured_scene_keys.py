"""``[measured]`` keys ``time_format`` and ``missing_values``: read from the scene, checked,
written back by ``to_toml`` and passed to the reader by every caller (``check``, the
report, ``calibrate``), and ``thermobearing check`` prints the reader's notes."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from thermobearing.calibrate_model import measured_table
from thermobearing.cli import main
from thermobearing.errors import InputError
from thermobearing.measured import read_scene_measured
from thermobearing.scene import Scene, check_measured_file, load_scene, loads_scene

DATA = Path(__file__).parent / "data" / "measured"
EXAMPLE = "qj1044_synthetic_measured"


def scene_with(tmp_path: Path, name: str, **measured) -> Scene:
    shutil.copy(DATA / name, tmp_path / name)
    d = load_scene(EXAMPLE).to_dict()
    d["measured"] = {"file": name, "columns": {"TC_DE": "drive_end.housing",
                                               "TC_NDE": "non_drive_end.housing"},
                     **measured}
    return Scene.from_dict(d, tmp_path)


def test_missing_values_from_the_scene_are_gaps_counted_per_sensor(tmp_path):
    with pytest.raises(InputError, match="missing_values"):
        check_measured_file(scene_with(tmp_path, "sentinels.csv", time_column="time [s]"))
    scene = scene_with(tmp_path, "sentinels.csv", time_column="time [s]",
                       missing_values=[-999, 9999.9])
    assert scene.measured.missing_values == (-999, 9999.9)
    check_measured_file(scene)
    df = read_scene_measured(scene)
    assert np.isnan(df["TC_DE"].iloc[2]) and np.isnan(df["TC_NDE"].iloc[3])
    assert df["TC_DE"].iloc[0] == 35.27
    # the calibration reads the same table (gaps left out of its residuals)
    table = measured_table(scene, ["drive_end.housing", "non_drive_end.housing"])
    assert np.isnan(table["TC_DE"].iloc[2]) and table["TC_NDE"].iloc[0] == 34.99
    # round trip through TOML keeps the key
    again = loads_scene(scene.to_toml(), tmp_path)
    assert again.measured == scene.measured


def test_time_format_from_the_scene_reads_excel_days(tmp_path):
    scene = scene_with(tmp_path, "excel_dates.csv", time_column="Date", time_format="excel")
    df = read_scene_measured(scene)
    # 46349.4375 -> 46349.4381944444: one minute between rows
    np.testing.assert_allclose(np.diff(df["time [s]"].to_numpy())[:3], 60.0, atol=1e-3)
    assert loads_scene(scene.to_toml(), tmp_path).measured.time_format == "excel"


@pytest.mark.parametrize("key, value, match", [
    ("time_format", "fortnights", "measured.time_format"),
    ("time_format", 5, "measured.time_format"),
    ("missing_values", [], "measured.missing_values"),
    ("missing_values", [True], "measured.missing_values"),
    ("missing_values", ["  "], "measured.missing_values"),
])
def test_bad_keys_name_the_field(tmp_path, key, value, match):
    with pytest.raises(InputError, match=match):
        scene_with(tmp_path, "sentinels.csv", time_column="time [s]", **{key: value})


def test_check_prints_the_readers_notes(tmp_path, capsys):
    scene = scene_with(tmp_path, "sentinels.csv", time_column="time [s]",
                       missing_values=[-999, 9999.9])
    path = tmp_path / "scene.toml"
    path.write_text(scene.to_toml())
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "measured: sentinels.csv: 2 sensors" in out
    assert "TC_DE: 2 of 8 readings are gaps (1 dropout flag, 1 missing_values code)" in out
    # the short file against the 60-min protocol
    assert "compared with measured data only where the file has them" in out
