"""Logger files of the kinds rigs write, read by thermobearing.measured: fixed-width columns
with spaces in the names, Excel serial dates, numeric dropout codes, repeated and
backward-stepping times, units per column, typos in the column map, file vs run span.

The fixtures in ``tests/unit/data/measured/`` carry the first eight rows of the shipped
SYNTHETIC example ``examples/synthetic_rig_temperatures.csv`` (model output + 0.1 K noise)
in those layouts; the tests compare the reader's table with those rows.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing.errors import InputError
from thermobearing.measured import (
    coverage_notes,
    measured_notes,
    read_measured_file,
)

DATA = Path(__file__).parent / "data" / "measured"
EXAMPLE = Path(__file__).parents[2] / "examples" / "synthetic_rig_temperatures.csv"


@pytest.fixture(scope="module")
def first8() -> pd.DataFrame:
    """time [s], DE, NDE of the example's first eight rows."""
    df = pd.read_csv(EXAMPLE).iloc[:8, :3]
    return pd.DataFrame({"time [s]": df["time [min]"] * 60.0, "DE": df.iloc[:, 1],
                         "NDE": df.iloc[:, 2]})


def write(path: Path, lines: list[str]) -> Path:
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


# --------------------------------------------------------------------------- 1 spaces
def test_fixed_width_names_with_spaces_blank_cell_and_flag(first8):
    """``Time [s]   TC 1 outer ring   TC 2 housing`` right-aligned, CRLF, a metadata line,
    a blank cell (a gap, not a shift of the row) and ``OVER``."""
    cols = ["TC 1 outer ring", "TC 2 housing"]
    got = read_measured_file(DATA / "fixed_width.txt", "Time [s]", cols)
    np.testing.assert_array_equal(got["time [s]"], first8["time [s]"])
    keep = [0, 1, 2, 3, 5, 6, 7]
    np.testing.assert_allclose(got[cols[0]].iloc[keep], first8["DE"].iloc[keep], atol=1e-12)
    assert np.isnan(got[cols[0]].iloc[4]) and np.isnan(got[cols[1]].iloc[6])
    keep = [0, 1, 2, 3, 4, 5, 7]
    np.testing.assert_allclose(got[cols[1]].iloc[keep], first8["NDE"].iloc[keep], atol=1e-12)
    assert measured_notes(got) == ["TC 1 outer ring: 1 of 8 readings are gaps (1 empty cell)",
                                   "TC 2 housing: 1 of 8 readings are gaps (1 dropout flag)"]


@pytest.mark.parametrize("align", ["<", ">"])
def test_aligned_columns_left_or_right_with_timestamps(tmp_path, align):
    """Names with spaces; the time cells hold a space themselves (a timestamp)."""
    w = (22, 18, 14)
    lines = [f"{'Date time':{align}{w[0]}}{'TC 1 outer ring':{align}{w[1]}}"
             f"{'TC 2':{align}{w[2]}}"]
    for k, (a, b) in enumerate([(35.27, 34.99), (35.22, 35.12), (35.8, 35.33)]):
        lines.append(f"{f'2026-11-23 10:1{k}:00':{align}{w[0]}}{a:{align}{w[1]}}"
                     f"{b:{align}{w[2]}}")
    got = read_measured_file(write(tmp_path / "a.txt", lines), "Date time",
                             ["TC 1 outer ring", "TC 2"])
    assert got["time [s]"].tolist() == [0.0, 60.0, 120.0]
    assert got["TC 2"].tolist() == [34.99, 35.12, 35.33]


def test_single_spaces_still_split_at_every_run(tmp_path):
    """Names without spaces and one space between cells: every run of spaces separates."""
    got = read_measured_file(write(tmp_path / "s.txt", ["t TC1 TC2", "0 35.5 36", "60 35.6 37"]),
                             "t", ["TC1", "TC2"])
    assert got["TC2"].tolist() == [36.0, 37.0]


def test_spaces_with_units_row_and_single_spaced_timestamps(tmp_path):
    """An aligned file with a units row (its K contradicts degC: the error), and a
    single-space file whose first column is a timestamp holding a space."""
    lines = ["Time [s]   TC 1 outer   TC 2", "s          K            K", "0.0        308.15       "
             "309.15", "60.0       308.25       309.35"]
    path = write(tmp_path / "u.txt", lines)
    with pytest.raises(InputError, match=r"measured.unit.*'K'.*units row.*'TC 1 outer'"):
        read_measured_file(path, "Time [s]", ["TC 1 outer", "TC 2"])
    got = read_measured_file(path, "Time [s]", ["TC 1 outer", "TC 2"], "K")
    np.testing.assert_allclose(got["TC 2"], [36.0, 36.2])
    lines = ["Timestamp TC1 TC2", "2026-11-23 10:15:30 35.2 35.0", "2026-11-23 10:16:30 35.3 35.1"]
    got = read_measured_file(write(tmp_path / "s.txt", lines), "Timestamp", ["TC1", "TC2"])
    assert got["time [s]"].tolist() == [0.0, 60.0] and got["TC2"].tolist() == [35.0, 35.1]


def test_two_cells_under_one_name_is_an_error(tmp_path):
    lines = ["Time [s]    TC 1 outer ring   TC 2", "0.0   35.2   35.3   99.0   1.0"]
    with pytest.raises(InputError, match=r"measured.file.*line 2.*two or more spaces.*"
                                         r"two cells lie under column"):
        read_measured_file(write(tmp_path / "b.txt", lines), "Time [s]", ["TC 2"])


# --------------------------------------------------------------------------- 2 Excel
def test_excel_serial_dates_in_a_date_column(first8):
    """``Date`` holding day numbers (46349.4375 = 2026-11-23 10:30) with decimal commas:
    read as Excel dates (a date-named column is the sign), noted; times to the ms."""
    got = read_measured_file(DATA / "excel_dates.csv", "Date", ["TC_DE", "TC_NDE"])
    np.testing.assert_allclose(got["time [s]"], first8["time [s]"], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(got["TC_NDE"], first8["NDE"])
    assert "Excel" in measured_notes(got)[0]
    # time_zero as a timestamp of the same instant scale
    shifted = read_measured_file(DATA / "excel_dates.csv", "Date", ["TC_DE"],
                                 time_zero="2026-11-23 10:29:00")
    np.testing.assert_allclose(shifted["time [s]"], first8["time [s]"] + 60.0, atol=1e-9)


def test_excel_only_with_a_clear_sign(tmp_path):
    lines = ["Time,TC1", "46349.4375,35.0", "46349.4381944444,35.1"]
    path = write(tmp_path / "x.csv", lines)
    plain = read_measured_file(path, "Time", ["TC1"])  # seconds since midnight look alike
    np.testing.assert_allclose(plain["time [s]"], [46349.4375, 46349.4381944444])
    assert measured_notes(plain) == [
        "time column 'Time': numbers without a unit, read as seconds; row 1 (46349.4375) "
        "is also an Excel day number (2026-11-23 10:30): if the column holds Excel dates, "
        "set measured time_format = \"excel\""]
    # the run (0-20 min) then has no measured time: coverage_notes says so
    assert "no measured time inside the run" in coverage_notes(plain, 0.0, 1200.0)[0]
    asked = read_measured_file(path, "Time", ["TC1"], time_format="excel")
    np.testing.assert_allclose(asked["time [s]"], [0.0, 60.0], atol=1e-9)
    # a date-named column outside the 1950-2099 day numbers: not Excel, seconds as before
    counter = read_measured_file(write(tmp_path / "c.csv", ["Date,TC1", "0,35", "1,36"]),
                                 "Date", ["TC1"])
    assert counter["time [s]"].tolist() == [0.0, 1.0] and measured_notes(counter) == []
    # "Timestamp" may be a seconds counter: seconds, with the note
    stamp = read_measured_file(write(tmp_path / "s.csv", ["Timestamp,TC1", "20000,35",
                                                          "20001,36"]), "Timestamp", ["TC1"])
    assert stamp["time [s]"].tolist() == [20000.0, 20001.0]
    assert "Excel day number (1954-10-03 00:00)" in measured_notes(stamp)[0]


@pytest.mark.parametrize("fmt, cells, expect", [
    ("excel_1904", ["44887.4375", "44887.4381944444"], [0.0, 60.0]),
    ("unix", ["1795429800", "1795429860.5"], [0.0, 60.5]),
    ("%d/%m/%Y %H:%M:%S", ["01/02/2026 10:00:00", "01/02/2026 10:01:00"], [0.0, 60.0]),
])
def test_time_format_option(tmp_path, fmt, cells, expect):
    """Excel 1904 dates, Unix seconds and a strptime pattern (it settles the day/month
    order the reader refuses to guess)."""
    path = write(tmp_path / "f.csv", ["t;TC1", *(f"{c};35" for c in cells)])
    got = read_measured_file(path, "t", ["TC1"], time_format=fmt)
    np.testing.assert_allclose(got["time [s]"], expect, atol=1e-9)


def test_bad_time_format(tmp_path):
    path = write(tmp_path / "f.csv", ["t,TC1", "0,35"])
    with pytest.raises(InputError, match=r"measured.time_format.*'lotus'.*excel.*unix.*"
                                         r"strptime"):
        read_measured_file(path, "t", ["TC1"], time_format="lotus")
    with pytest.raises(InputError, match=r"row 1: '0'.*a time in every row.*Excel"):
        read_measured_file(path, "t", ["TC1"], time_format="excel")


# --------------------------------------------------------------------------- 3 sentinels
def test_numeric_codes_are_errors_unless_listed(first8):
    """-999 and 9999.9 are no temperatures: an error naming the value and the option;
    listed in missing_values they are gaps, counted per sensor with the text flags."""
    path = DATA / "sentinels.csv"
    with pytest.raises(InputError, match=r"measured column 'TC_DE'.*row 3: '-999' \(line 4.*"
                                         r"above absolute zero.*missing_values = \[-999\]"):
        read_measured_file(path, "time [s]", ["TC_DE", "TC_NDE"])
    with pytest.raises(InputError, match=r"measured column 'TC_NDE'.*row 4: '9999.9'.*"
                                         r"1820 degC"):
        read_measured_file(path, "time [s]", ["TC_DE", "TC_NDE"], missing_values=[-999])
    got = read_measured_file(path, "time [s]", ["TC_DE", "TC_NDE"],
                             missing_values=[-999, 9999.9])
    assert np.isnan(got["TC_DE"].iloc[[2, 5]]).all() and np.isnan(got["TC_NDE"].iloc[[3, 6]]).all()
    keep = [0, 1, 3, 4, 6, 7]
    np.testing.assert_array_equal(got["TC_DE"].iloc[keep], first8["DE"].iloc[keep])
    assert got.attrs["gaps"]["TC_DE"] == {"empty cells": 0, "dropout flags": 1,
                                          "overload codes": 0, "missing_values codes": 1}
    assert measured_notes(got) == [
        "TC_DE: 2 of 8 readings are gaps (1 dropout flag, 1 missing_values code)",
        "TC_NDE: 2 of 8 readings are gaps (1 dropout flag, 1 missing_values code)"]


def test_text_codes_decimal_comma_codes_and_kelvin(tmp_path):
    """A text code the flags do not know (``S.C.``), a code written ``-999,0`` with
    decimal commas, and a Kelvin file whose code is compared in the file's unit."""
    path = write(tmp_path / "t.csv", ["t;TC1", "0;35,5", "1;S.C.", "2;-999,0", "3;36,0"])
    with pytest.raises(InputError, match=r"row 2: 'S.C.'.*missing_values"):
        read_measured_file(path, "t", ["TC1"])
    got = read_measured_file(path, "t", ["TC1"], missing_values=["S.C.", -999])
    assert got["TC1"].isna().tolist() == [False, True, True, False]
    kelvin = write(tmp_path / "k.csv", ["t,TC1", "0,308.15", "1,0", "2,309.15"])
    got = read_measured_file(kelvin, "t", ["TC1"], "K", missing_values=[0])
    np.testing.assert_allclose(got["TC1"], [35.0, np.nan, 36.0])
    with pytest.raises(InputError, match=r"row 2: '0' \(line 3.*above absolute zero"):
        read_measured_file(kelvin, "t", ["TC1"], "K")  # 0 K: a code, not a reading
    with pytest.raises(InputError, match=r"measured.missing_values.*list"):
        read_measured_file(kelvin, "t", ["TC1"], "K", missing_values=[None])


def test_text_flags_of_the_brief_are_gaps(tmp_path):
    flags = ["OVER", "ERR", "NaN", "---", "#VALUE!"]
    path = write(tmp_path / "f.csv", ["t,TC1", *(f"{k},{f}" for k, f in enumerate(flags)),
                                      "9,35"])
    got = read_measured_file(path, "t", ["TC1"])
    assert got["TC1"].isna().sum() == len(flags)
    assert got.attrs["gaps"]["TC1"]["dropout flags"] == len(flags)


def test_open_thermocouple_range_ends_are_noted(tmp_path):
    """1372 and -270 degC (the ends of the type K range) stay readings but are named."""
    path = write(tmp_path / "o.csv", ["t,TC1,TC2", "0,35,35", "1,1372.0,35", "2,-270,35"])
    got = read_measured_file(path, "t", ["TC1", "TC2"])
    notes = measured_notes(got)
    assert len(notes) == 2 and all("TC1" in n and "missing_values" in n for n in notes)
    assert "1372 degC" in " ".join(notes) and "type K" in " ".join(notes)
    clean = read_measured_file(path, "t", ["TC1"], missing_values=[1372, -270])
    assert measured_notes(clean) == ["TC1: 2 of 3 readings are gaps (2 missing_values codes)"]


# --------------------------------------------------------------------------- 4 times
def test_repeated_times_are_averaged_and_noted(tmp_path):
    """A logger writing whole seconds at 2 Hz: rows of the same second are one sample,
    the mean of its readings (a gap left out of the mean)."""
    lines = ["Timestamp,TC1,TC2", "2026-11-23 10:00:00,35.0,40.0",
             "2026-11-23 10:00:00,35.2,OVL", "2026-11-23 10:00:01,35.4,40.4",
             "2026-11-23 10:00:01,35.6,40.6", "2026-11-23 10:00:02,35.8,OVL"]
    got = read_measured_file(write(tmp_path / "r.csv", lines), "Timestamp", ["TC1", "TC2"])
    assert got["time [s]"].tolist() == [0.0, 1.0, 2.0]
    np.testing.assert_allclose(got["TC1"], [35.1, 35.5, 35.8])
    np.testing.assert_allclose(got["TC2"], [40.0, 40.5, np.nan])
    notes = measured_notes(got)
    assert "2 row(s) repeat the time" in notes[0] and "3 of 5 rows kept" in notes[0]
    assert notes[1] == "TC2: 2 of 5 readings are gaps (2 dropout flags)"


def test_daylight_saving_step_back_names_row_and_cause():
    with pytest.raises(InputError, match=r"measured column 'Timestamp'.*row 5: 25.10.2026 "
                                         r"02:00:00 after 25.10.2026 02:59:00 \(line 6\).*"
                                         r"steps back by 3540 s.*daylight-saving.*UTC"):
        read_measured_file(DATA / "dst_step.csv", "Timestamp", ["TC_DE"])


def test_twelve_hour_timestamps_with_fractions(tmp_path):
    lines = ["Time,TC1 (C)", "11/23/2026 11:59:59.750 AM,35.0", "11/23/2026 12:00:00.250 PM,35.1"]
    got = read_measured_file(write(tmp_path / "ni.csv", lines), "Time", ["TC1 (C)"])
    np.testing.assert_allclose(got["time [s]"], [0.0, 0.5])


def test_clock_times_past_midnight(tmp_path):
    """``hh:mm:ss`` of a log running across midnight: 24 h added from the wrap, noted;
    ``time_zero`` in the same clock format."""
    lines = ["Uhrzeit;TC1", "23:58:30;35,0", "23:59:30;35,1", "00:00:30;35,2", "00:01:30;35,3"]
    got = read_measured_file(write(tmp_path / "m.csv", lines), "Uhrzeit", ["TC1"],
                             time_zero="23:58:00")
    assert got["time [s]"].tolist() == [30.0, 90.0, 150.0, 210.0]
    assert "midnight 1 time(s) (first at line 4)" in measured_notes(got)[0]


def test_logger_restart_names_row_and_cause(tmp_path):
    lines = ["t [min],TC1", "0,35", "1,36", "2,37", "0,35.5", "1,36.5"]
    with pytest.raises(InputError, match=r"row 4: 0 after 2 \(line 5\).*steps back by "
                                         r"120 s.*restarted"):
        read_measured_file(write(tmp_path / "r.csv", lines), "t [min]", ["TC1"])


def test_header_repeated_by_an_appended_recording(tmp_path):
    lines = ["Zeit;TC1", "0;35,0", "60;35,5", "Zeit;TC1", "0;36,0"]
    with pytest.raises(InputError, match=r"row 3: 'Zeit' \(line 4\).*header row again.*"
                                         r"own file"):
        read_measured_file(write(tmp_path / "a.csv", lines), "Zeit", ["TC1"])


# --------------------------------------------------------------------------- more
def test_metadata_line_with_the_time_column_name_above_the_header(tmp_path):
    """``Time;10:15:30`` in the logger's metadata: the header is the row that also has
    the mapped sensor columns."""
    lines = ["Logger;TC-08", "Date;23.11.2026", "Time;10:15:30", "", "Time;TC1;TC2",
             "s;°C;°C", "0;35,2;35,3", "60;35,4;35,5"]
    got = read_measured_file(write(tmp_path / "m.csv", lines), "Time", ["TC1", "TC2"])
    assert got.values.tolist() == [[0.0, 35.2, 35.3], [60.0, 35.4, 35.5]]



def test_units_per_column_and_fahrenheit(tmp_path):
    """``TC1 [degF]`` next to ``TC2 [degC]``: each in its own unit (noted); all degF:
    the scene must say degF (the error says so)."""
    path = write(tmp_path / "u.csv", ["t,TC1 [degF],TC2 [degC]", "0,95,35", "1,96.8,36"])
    got = read_measured_file(path, "t", ["TC1 [degF]", "TC2 [degC]"])
    np.testing.assert_allclose(got["TC1 [degF]"], [35.0, 36.0])
    np.testing.assert_allclose(got["TC2 [degC]"], [35.0, 36.0])
    assert "different units" in measured_notes(got)[0]
    units_row = write(tmp_path / "f.csv", ["t,TC1,TC2", "s,°F,°F", "0,95,95", "1,96.8,95"])
    with pytest.raises(InputError, match=r"measured.unit = 'degC'.*'degF'.*units row.*"
                                         r"set unit = \"degF\""):
        read_measured_file(units_row, "t", ["TC1", "TC2"])
    got = read_measured_file(units_row, "t", ["TC1", "TC2"], "degF")
    np.testing.assert_allclose(got["TC1"], [35.0, 36.0])


def test_units_written_quantity_slash_unit(tmp_path):
    """DIN 1313 names ``t/min`` and ``T1/°C``: the time in minutes, the unit checked;
    ``Datum/Uhrzeit`` or ``DE/NDE`` after a slash are no units."""
    path = write(tmp_path / "d.csv", ["t/min;T1/°C;T2 / K;DE/NDE", "0;35,0;308,15;1",
                                      "1,5;35,5;309,15;2"])
    got = read_measured_file(path, "t/min", ["T1/°C", "DE/NDE"])
    assert got["time [s]"].tolist() == [0.0, 90.0] and got["DE/NDE"].tolist() == [1.0, 2.0]
    with pytest.raises(InputError, match=r"measured.unit = 'degC'.*'K'.*column name.*'T2 / K'"):
        read_measured_file(path, "t/min", ["T2 / K"])
    got = read_measured_file(path, "t/min", ["T1/°C", "T2 / K"])  # each in its own unit
    np.testing.assert_allclose(got["T2 / K"], [35.0, 36.0])


def test_a_mapped_name_twice_in_the_header(tmp_path):
    path = write(tmp_path / "two.csv", ["t,TC1,TC2,TC1", "0,35,36,37"])
    with pytest.raises(InputError, match=r"header.*'TC1'.*columns 2 and 4"):
        read_measured_file(path, "t", ["TC1"])
    assert read_measured_file(path, "t", ["TC2"])["TC2"].tolist() == [36.0]


def test_a_kelvin_channel_read_as_celsius_is_noted(tmp_path):
    path = write(tmp_path / "k.csv", ["t,TC1,TC2", "0,308.42,35.0", "60,309.10,OVL"])
    got = read_measured_file(path, "t", ["TC1", "TC2"])
    assert got["TC1"].tolist() == [308.42, 309.1]  # the reading stays: only a note
    assert measured_notes(got)[0].startswith("TC1: every reading is above 273.15 (lowest "
                                             "308.42), read as degC: a channel logging in K?")
    assert not any(n.startswith("TC2") and "273.15" in n for n in measured_notes(got))
    assert measured_notes(read_measured_file(path, "t", ["TC1"], "K")) == []


def test_column_map_typo_names_the_nearest_column(tmp_path):
    path = write(tmp_path / "c.csv", ["Time [s],TC_DE_outer,TC_NDE_outer", "0,35,36"])
    with pytest.raises(InputError, match=r"measured.columns\['TC_DE_outr'\].*did you mean "
                                         r"'TC_DE_outer'"):
        read_measured_file(path, "Time [s]", ["TC_DE_outr"])
    with pytest.raises(InputError, match=r"measured.time_column.*did you mean 'Time \[s\]'"):
        read_measured_file(path, "Time[s]", ["TC_DE_outer"])


def test_coverage_of_the_run(tmp_path):
    """A file longer or shorter than the protocol: the notes count what is left out."""
    t = np.arange(0.0, 1800.1, 60.0)
    df = pd.DataFrame({"time [s]": t, "TC1": 35.0})
    assert coverage_notes(df, 0.0, 1800.0) == []
    longer = coverage_notes(df, 0.0, 1200.0)
    assert longer == ["10 measured samples outside the run are left out (0 before, 10 "
                      "after; measured 0-30 min, run 0-20 min)"]
    shorter = coverage_notes(df, 0.0, 3600.0)
    assert shorter == ["the run is compared with measured data only where the file has "
                       "them (measured 0-30 min, run 0-60 min)"]
