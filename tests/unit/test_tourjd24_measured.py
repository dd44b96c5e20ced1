"""Session-24 user tour F (a test-rig engineer's thermocouple CSV against a QJ1044 / NU 214
scene): what the measured-file reader did with a channel logged in mV, a time unit that
is no time, the empty rows a spreadsheet saves below the data, and a mistyped column."""

from __future__ import annotations

from pathlib import Path

import pytest

from thermobearing.errors import InputError
from thermobearing.measured import read_measured_file
from thermobearing.measured_layout import non_temperature_units

ROWS = ["0,24.4,36.1", "0.5,24.8,36.2", "1.0,25.0,36.3"]


def _file(tmp_path: Path, lines: list[str]) -> Path:
    path = tmp_path / "rig_log.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("name", ["TC3 [mV]", "TC3 (mV)", "TC3/mV", "TC3 [%]", "TC3 [bar]"])
def test_a_sensor_column_named_in_another_unit_is_refused(tmp_path, name):
    # a type K channel logging its voltage (1-4 mV at rig temperatures) was read as 1-4 degC
    path = _file(tmp_path, [f"Zeit [min],{name},TC7"] + ROWS)
    with pytest.raises(InputError) as err:
        read_measured_file(path, "Zeit [min]", {name: "de.housing", "TC7": "de.oil"})
    msg = str(err.value)
    assert f"measured.columns[{name!r}]" in msg
    assert "no temperature unit (degC, K or degF)" in msg
    unit = name.split("/")[-1].strip("TC3 []()")
    assert repr(unit) in msg


@pytest.mark.parametrize("cell", ["mV", "V", "bar", "%"])
def test_a_units_row_with_another_unit_is_refused(tmp_path, cell):
    path = _file(tmp_path, ["time,TC3,TC7", f"min,{cell},degC"] + ROWS)
    with pytest.raises(InputError) as err:
        read_measured_file(path, "time", {"TC3": "de.housing", "TC7": "de.oil"})
    assert "measured.columns['TC3']" in str(err.value)
    assert f"units row gives it {cell!r}" in str(err.value)


@pytest.mark.parametrize("name", ["T_oil (in)", "T_oil (out)", "TC (A)", "TC (F)", "TC1 (DE)"])
def test_labels_in_brackets_stay_labels(tmp_path, name):
    # position labels that happen to be unit symbols (in: inch, A: ampere) are no unit
    path = _file(tmp_path, [f"time [min],{name},TC7"] + ROWS)
    df = read_measured_file(path, "time [min]", {name: "n1", "TC7": "n2"})
    assert df[name].tolist() == [24.4, 24.8, 25.0]
    assert df["time [s]"].tolist() == [0.0, 30.0, 60.0]


def test_temperature_units_are_not_other_units():
    header = ["t", "a [degC]", "b", "c [K]"]
    idx = {"a [degC]": 1, "b": 2, "c [K]": 3}
    assert non_temperature_units(["s", "°C", "degF", "K"], header, idx, {}) == {}
    assert non_temperature_units(["s", "-", "", "kelvin"], header, idx, {}) == {}


@pytest.mark.parametrize("unit", ["m", "Std x", "h:mm"])
def test_a_time_unit_that_is_no_time_names_the_column(tmp_path, unit):
    name = f"Zeit [{unit}]"
    path = _file(tmp_path, [f"{name},TC3,TC7"] + ROWS)
    with pytest.raises(InputError) as err:
        read_measured_file(path, name, {"TC3": "n1", "TC7": "n2"})
    msg = str(err.value)
    # it said "measured.time_column = '1 m' is not allowed" (the probe it converted)
    assert f"measured.time_column = {name!r}" in msg
    assert "s, min, h or ms" in msg
    assert f"the file gives {unit!r}" in msg
    assert ("'m' is metres: write min for minutes" in msg) == (unit == "m")


@pytest.mark.parametrize(("unit", "scale"), [("Sekunden", 1.0), ("Std", 3600.0),
                                             ("mins", 60.0), ("sec", 1.0)])
def test_time_unit_words_in_brackets(tmp_path, unit, scale):
    name = f"Zeit [{unit}]"
    path = _file(tmp_path, [f"{name},TC3,TC7"] + ROWS)
    df = read_measured_file(path, name, {"TC3": "n1", "TC7": "n2"})
    assert df["time [s]"].tolist() == pytest.approx([0.0, 0.5 * scale, 1.0 * scale])


def test_rows_of_separators_only_are_left_out_with_a_note(tmp_path):
    # a spreadsheet saves the formatted rows below the data as ',,' (was: an error asking
    # for a time in every row); a row in the middle likewise
    lines = ["time [min],TC3,TC7", ROWS[0], ",,", ROWS[1], ROWS[2], ",,", " , , ", ""]
    df = read_measured_file(_file(tmp_path, lines), "time [min]", {"TC3": "n1", "TC7": "n2"})
    assert df["time [s]"].tolist() == [0.0, 30.0, 60.0]
    assert df["TC7"].tolist() == [36.1, 36.2, 36.3]
    notes = df.attrs["notes"]
    assert any("3 rows with every cell empty left out (first at line 3" in n for n in notes)
    assert df.attrs["rows"] == 3


def test_a_row_with_a_time_and_empty_readings_stays_a_gap(tmp_path):
    lines = ["time [min],TC3,TC7", ROWS[0], "0.5,,", ROWS[2]]
    df = read_measured_file(_file(tmp_path, lines), "time [min]", {"TC3": "n1", "TC7": "n2"})
    assert df["time [s]"].tolist() == [0.0, 30.0, 60.0]
    assert df.attrs["gaps"]["TC3"]["empty cells"] == 1


def test_a_row_with_readings_but_no_time_is_still_an_error(tmp_path):
    lines = ["time [min],TC3,TC7", ROWS[0], ",24.9,36.2", ROWS[2]]
    with pytest.raises(InputError, match="row 2: '' \\(line 3\\)"):
        read_measured_file(_file(tmp_path, lines), "time [min]", {"TC3": "n1", "TC7": "n2"})


def test_a_missing_column_suggests_no_column_another_sensor_maps(tmp_path):
    path = _file(tmp_path, ["Zeit [min],TC3 Aussenring DE,TC7 Oel ab"] + ROWS)
    cols = {"TC3 Aussenring DE": "de.housing", "TC4 Aussenring NDE": "nde.housing"}
    with pytest.raises(InputError) as err:
        read_measured_file(path, "Zeit [min]", cols)
    msg = str(err.value)
    assert "measured.columns['TC4 Aussenring NDE']" in msg
    assert "did you mean 'TC3 Aussenring DE'" not in msg
    # a typo still gets its column
    with pytest.raises(InputError, match="did you mean 'TC7 Oel ab'"):
        read_measured_file(path, "Zeit [min]", {"TC3 Aussenring DE": "a", "TC7 Oel ap": "b"})


@pytest.mark.parametrize("zero", ["5 min", "300 s", "5", 5, "0.0833333333333 h"])
def test_time_zero_of_a_number_column_may_carry_a_unit(tmp_path, zero):
    # a logger started 5 min before the run: "5 min" was refused (only a bare 5, in the
    # column's unit), though the scene writes its other times with units
    path = _file(tmp_path, ["time [min],TC3,TC7", "5,24.4,36.1", "5.5,24.8,36.2",
                            "6,25.0,36.3"])
    df = read_measured_file(path, "time [min]", {"TC3": "n1", "TC7": "n2"}, time_zero=zero)
    assert df["time [s]"].tolist() == pytest.approx([0.0, 30.0, 60.0], abs=1e-6)


def test_time_zero_with_a_unit_for_elapsed_cells(tmp_path):
    path = _file(tmp_path, ["Elapsed,TC3,TC7", "00:05:00,24.4,36.1", "00:05:30,24.8,36.2"])
    df = read_measured_file(path, "Elapsed", {"TC3": "n1", "TC7": "n2"}, time_zero="5 min")
    assert df["time [s]"].tolist() == [0.0, 30.0]


@pytest.mark.parametrize("zero", ["5 kg", "five"])
def test_time_zero_that_is_no_time_is_refused(tmp_path, zero):
    path = _file(tmp_path, ["time [min],TC3,TC7", "5,24.4,36.1", "5.5,24.8,36.2"])
    with pytest.raises(InputError) as err:
        read_measured_file(path, "time [min]", {"TC3": "n1", "TC7": "n2"}, time_zero=zero)
    assert f"measured.time_zero = {zero!r}" in str(err.value)
    assert 'or with a unit ("5 min")' in str(err.value)


def _times(step: float, n: int = 20):
    import pandas as pd

    return pd.DataFrame({"time [s]": [k * step for k in range(n)], "TC": [20.0] * n})


def test_interval_note_when_the_file_samples_faster_than_the_chunks():
    from thermobearing.measured import interval_note

    (note,) = interval_note(_times(30.0), 90.0, None)
    assert "the file samples every 30 s (median)" in note
    assert "up to 90 s apart, [solver] chunk" in note
    assert 'set [outputs] interval = "30 s"' in note
    (note,) = interval_note(_times(1.0), 90.0, None)
    assert 'interval = "1 s"' in note


def test_no_interval_note_with_an_interval_or_a_slow_file():
    from thermobearing.measured import interval_note

    assert interval_note(_times(30.0), 90.0, 60.0) == []
    assert interval_note(_times(60.0), 90.0, None) == []  # no faster than half the chunk
    assert interval_note(_times(30.0, n=2), 90.0, None) == []


def test_check_prints_the_interval_note(tmp_path, capsys):
    from thermobearing import cli

    src = Path(__file__).resolve().parents[2] / "configs" / "scenes"
    text = (src / "qj1044_synthetic_measured.toml").read_text(encoding="utf-8")
    data = (src / "../../examples/synthetic_rig_temperatures.csv").resolve()
    text = text.replace('file = "../../examples/synthetic_rig_temperatures.csv"',
                        f'file = "{data.as_posix()}"')
    # the file samples every minute, the scene's chunks are 300 s
    scene = tmp_path / "rig.toml"
    scene.write_text(text, encoding="utf-8")
    assert cli.main(["check", str(scene)]) == 0
    out = capsys.readouterr().out
    assert 'the file samples every 60 s (median)' in out
    assert 'up to 300 s apart' in out and 'interval = "60 s"' in out
    scene.write_text(text.replace('mode = "transient"', 'mode = "transient"\ninterval = "60 s"'),
                     encoding="utf-8")
    assert cli.main(["check", str(scene)]) == 0
    assert "[outputs] interval" not in capsys.readouterr().out
