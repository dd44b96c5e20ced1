"""User tour 21, measured data in degF with the time in minutes (thermobearing.measured).

A rig logger exported ``Minutes,TC_DE (F),TC_NDE (F)``: a time column whose name is the unit
word itself. Before the fix the minutes were read as seconds without a word (66 min of
readings became 0-1.1 min; ``check`` said only that the file covers part of the run).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from thermobearing.measured import read_measured_file

MINUTES = [0.0, 1.5, 3.0, 66.0]
FAHRENHEIT = [95.0, 104.0, 113.0, 122.0]  # 35, 40, 45, 50 degC


def _write(path: Path, time_name: str, units_row: str | None = None) -> Path:
    lines = [f"{time_name},TC_DE (F)"]
    if units_row is not None:
        lines.append(units_row)
    lines += [f"{t},{f}" for t, f in zip(MINUTES, FAHRENHEIT, strict=True)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("name, seconds_per_unit", [
    ("Minutes", 60.0), ("Elapsed Minutes", 60.0), ("Time_min", 60.0), ("time min", 60.0),
    ("Zeit in Minuten", 60.0), ("t_s", 1.0), ("Seconds", 1.0), ("Time_h", 3600.0),
    ("Elapsed hours", 3600.0), ("time_ms", 1e-3),
])
def test_time_unit_word_in_the_column_name(tmp_path, name, seconds_per_unit):
    got = read_measured_file(_write(tmp_path / "f.csv", name), name, ["TC_DE (F)"],
                             unit="degF")
    np.testing.assert_allclose(got["time [s]"], np.array(MINUTES) * seconds_per_unit)
    np.testing.assert_allclose(got["TC_DE (F)"], [35.0, 40.0, 45.0, 50.0], atol=1e-12)


@pytest.mark.parametrize("name", ["Time", "Zeit", "Elapsed"])
def test_a_name_without_a_unit_word_stays_seconds(tmp_path, name):
    got = read_measured_file(_write(tmp_path / "f.csv", name), name, ["TC_DE (F)"],
                             unit="degF")
    np.testing.assert_allclose(got["time [s]"], MINUTES)


def test_the_units_row_wins_over_a_word_of_the_name(tmp_path):
    # the file's own units row is its explicit statement
    got = read_measured_file(_write(tmp_path / "f.csv", "Time_s", units_row="min,degF"),
                             "Time_s", ["TC_DE (F)"], unit="degF")
    np.testing.assert_allclose(got["time [s]"], np.array(MINUTES) * 60.0)


def test_two_different_unit_words_are_no_unit(tmp_path):
    # "hours minutes" names no single unit: read as documented (seconds), no guess
    got = read_measured_file(_write(tmp_path / "f.csv", "hours minutes"), "hours minutes",
                             ["TC_DE (F)"], unit="degF")
    np.testing.assert_allclose(got["time [s]"], MINUTES)


def test_a_bare_f_in_a_column_name_read_as_degc_is_noted(tmp_path):
    # the logger wrote 'TC_DE (F)'; the scene forgot unit = "degF": 95-122 read as degC
    path = _write(tmp_path / "f.csv", "Minutes")
    got = read_measured_file(path, "Minutes", ["TC_DE (F)"])
    np.testing.assert_allclose(got["TC_DE (F)"], FAHRENHEIT)  # a label, as documented
    (note,) = [n for n in got.attrs["notes"] if "label" in n]
    assert note == ("column 'TC_DE (F)': its 'F' is read as a label, not as degF; the "
                    "readings are taken in degC (measured.unit): if they are degF, set "
                    "unit = \"degF\"")
    fine = read_measured_file(path, "Minutes", ["TC_DE (F)"], unit="degF")
    assert not [n for n in fine.attrs["notes"] if "label" in n]
