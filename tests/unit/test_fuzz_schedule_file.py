"""CSV protocol files of ``[schedule] file`` as spreadsheets export them (found by the scene
fuzzer): a UTF-8 BOM, semicolons with decimal commas, trailing empty rows and cells were
refused with a garbled column name or a KeyError; a duplicated column silently replaced the
first one. Later: units written in the cells of a column without one were refused as
'10 s s', capitalised headers were refused, and '1.000' in a decimal-comma file read as 1."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.scene_schedule import Schedule

HEAD = "duration [s],speed [rpm],radial_load [N],axial_load [N]"


def _steps(tmp_path, text: str, **defaults):
    path = tmp_path / "protocol.csv"
    path.write_bytes(text.encode("utf-8"))
    return Schedule.from_dict({"file": str(path), **defaults}).steps


def test_bom_is_skipped(tmp_path):
    (step,) = _steps(tmp_path, "\ufeff" + HEAD + "\r\n10,100,1000,0\r\n")
    assert step.duration == 10.0
    assert step.speed == pytest.approx(100 * math.pi / 30)


def test_semicolons_with_decimal_commas(tmp_path):
    text = "duration [min];speed [rpm];radial_load [kN];axial_load [kN]\n1,5;1800;2,5;0,25\n"
    (step,) = _steps(tmp_path, text)
    assert (step.duration, step.radial_load, step.axial_load) == pytest.approx(
        (90.0, 2500.0, 250.0))


def test_empty_rows_and_trailing_empty_cells_are_skipped(tmp_path):
    steps = _steps(tmp_path, HEAD + "\n10,100,1000,0,\n20,200,500,0\n,,,\n,,,,\n")
    assert [s.duration for s in steps] == [10.0, 20.0]


def test_extra_filled_cell_is_an_error_naming_the_row(tmp_path):
    with pytest.raises(InputError, match=r"schedule.file row 2.*'7'.*at most 4 cells"):
        _steps(tmp_path, HEAD + "\n10,100,1000,0\n10,100,1000,0,7\n")


def test_duplicated_column_is_an_error(tmp_path):
    text = "duration [s],speed [rpm],speed [r/min],axial_load [N]\n10,100,200,0\n"
    with pytest.raises(InputError, match=r"speed is given twice"):
        _steps(tmp_path, text, radial_load="1 kN")


def test_unknown_column_names_the_separators(tmp_path):
    with pytest.raises(InputError, match=r"column 'time \[s\]'.*separated by commas"):
        _steps(tmp_path, "time [s],speed [rpm]\n10,100\n")


def test_units_in_the_cells_of_a_column_without_one(tmp_path):
    """'10 s' under a bare 'duration' header was refused as '10 s s'."""
    text = ("duration,speed,radial_load [lbf],axial_load\n10 s,1000 rpm,200,0\n"
            "0.5 min,2 krpm,0,10 N\n")
    first, second = _steps(tmp_path, text)
    assert (first.duration, second.duration) == pytest.approx((10.0, 30.0))
    assert (first.speed, second.speed) == pytest.approx((1000 * math.pi / 30, 2000 * math.pi / 30))
    assert first.radial_load == pytest.approx(200 * 4.4482216152605)
    assert second.axial_load == pytest.approx(10.0)


def test_unit_in_a_cell_under_a_header_with_one_is_an_error(tmp_path):
    with pytest.raises(InputError, match=r"row 1.duration = '10 s'.*bare number.*\[s\]"):
        _steps(tmp_path, HEAD + "\n10 s,100,1000,0\n")


def test_capitalised_header(tmp_path):
    (step,) = _steps(tmp_path, "Duration [s],Speed [rpm],Radial_load [N],AXIAL_LOAD [N]\n"
                               "10,100,1000,5\n")
    assert (step.duration, step.radial_load, step.axial_load) == pytest.approx(
        (10.0, 1000.0, 5.0))


def test_points_group_thousands_in_a_decimal_comma_file(tmp_path):
    """'1.000' beside '2,5' in a semicolon file is a thousand, not one."""
    text = ("duration [s];speed [rpm];radial_load [N];axial_load [N]\n"
            "2,5;1.000;12.500,5;0\n")
    (step,) = _steps(tmp_path, text)
    assert step.duration == pytest.approx(2.5)
    assert step.speed == pytest.approx(1000 * math.pi / 30)
    assert step.radial_load == pytest.approx(12500.5)
    with pytest.raises(InputError, match=r"row 1.speed = '1.5'.*decimal comma"):
        _steps(tmp_path, text.replace("1.000;", "1.5;"))
