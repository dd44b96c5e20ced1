"""Session-22 user tour A: a thermocouple export whose elapsed time is written ``h:mm``
(hours and minutes, the unit in the column's name or its units row). Two-field cells were
always read as ``mm:ss``, so ``0:10`` of a ``time [h:mm]`` column was 10 s instead of
10 min: a 50-min rig log was squeezed into the first 50 s of the run."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from thermobearing.measured import read_measured_file
from thermobearing.measured_time import elapsed_hours


def _file(tmp_path: Path, header: str, rows: list[str], units: str | None = None) -> Path:
    path = tmp_path / "tc.csv"
    lines = [header] + ([units] if units else []) + rows
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


ROWS = ["0:00,20.0", "0:10,21.0", "1:05,22.5"]


@pytest.mark.parametrize("name", ["time [h:mm]", "Time (hh:mm)"])
def test_a_column_named_in_hours_and_minutes(tmp_path, name):
    df = read_measured_file(_file(tmp_path, f"{name},TC1", ROWS), name, {"TC1": "n"})
    assert df["time [s]"].tolist() == [0.0, 600.0, 3900.0]


def test_a_units_row_in_hours_and_minutes(tmp_path):
    df = read_measured_file(_file(tmp_path, "time,TC1", ROWS, units="hh:mm,°C"), "time",
                            {"TC1": "n"})
    assert df["time [s]"].tolist() == [0.0, 600.0, 3900.0]
    assert df["TC1"].tolist() == [20.0, 21.0, 22.5]


def test_without_a_unit_two_fields_stay_minutes_and_seconds(tmp_path):
    df = read_measured_file(_file(tmp_path, "time,TC1", ROWS), "time", {"TC1": "n"})
    assert df["time [s]"].tolist() == [0.0, 10.0, 65.0]
    df = read_measured_file(_file(tmp_path, "time [mm:ss],TC1", ROWS), "time [mm:ss]",
                            {"TC1": "n"})
    assert df["time [s]"].tolist() == [0.0, 10.0, 65.0]


def test_hours_minutes_cells():
    assert elapsed_hours("2:30") == 9000.0
    assert elapsed_hours("0:10.5") == 630.0  # a fraction of a minute
    assert elapsed_hours("1:00:30") == 3630.0  # three fields: hh:mm:ss as ever
    assert elapsed_hours("0:75") is None
    assert elapsed_hours("ten") is None


def test_check_says_how_the_time_column_was_read(tmp_path, capsys):
    """``check`` printed the span (``0-1.08333 min``) but not the reading, so a ``0:10``
    read as 10 s instead of 10 min showed only as a short span."""
    from test_tourf22_rig_inputs import _write

    from thermobearing.cli import main

    scene = _write(tmp_path, measured='[measured]\nfile = "tc.csv"\ntime_column = '
                   '"time [h:mm]"\nunit = "degC"\ncolumns = { TC1 = "test.housing" }\n')
    _file(tmp_path, "time [h:mm],TC1", ROWS)
    assert main(["check", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "measured: tc.csv: 1 sensor, 3 samples, 0-65 min" in out
    assert "time column 'time [h:mm]' read as elapsed h:mm (hours:minutes, as 'h:mm' says)" \
        in out


def test_a_logger_started_before_time_zero_reads_minus_to():
    """Five minutes logged before the motor started (``time_zero``) read ``-5-50 min``."""
    import pandas as pd

    from thermobearing.measured import coverage_notes, minutes_span

    assert minutes_span(-300.0, 3000.0) == "-5 to 50 min"
    assert minutes_span(0.0, 3000.0) == "0-50 min"
    df = pd.DataFrame({"time [s]": [-300.0, 0.0, 3000.0], "TC1": [20.0, 20.0, 40.0]})
    assert coverage_notes(df, 0.0, 3000.0) == [
        "1 measured sample outside the run is left out (1 before, 0 after; measured -5 to "
        "50 min, run 0-50 min)"]


def test_a_row_that_leaves_out_its_last_empty_cells_has_gaps_there(tmp_path):
    """A logger that writes ``60,22`` when the last channel dropped out: the whole file was
    refused ("at least 3 cells")."""
    path = tmp_path / "tc.csv"
    path.write_text("time [s],TC1,TC2\n0,20,21\n60,22\n120,23,24\n", encoding="utf-8")
    df = read_measured_file(path, "time [s]", {"TC1": "a", "TC2": "b"})
    assert df["TC1"].tolist() == [20.0, 22.0, 23.0]
    assert df["TC2"].tolist()[0] == 21.0 and math.isnan(df["TC2"].tolist()[1])
    assert "1 row shorter than the header row: the missing cells at the end are read as " \
        "gaps (empty cells)" in df.attrs["notes"]
    path.write_text("TC1,TC2,time [s]\n20,21,0\n22,23\n", encoding="utf-8")
    with pytest.raises(Exception, match="at least 3 cells"):  # no time: still refused
        read_measured_file(path, "time [s]", {"TC2": "b"})
