"""Scene fuzzing (``[schedule] file``, semicolons with decimal commas): a protocol whose only
decimal-comma cells also group thousands with points (``1.031,5``) was not read as a
decimal-comma file, and the cell was refused as "'1.031,5 rpm' ... a known unit convertible
to rad/s", naming a unit that is fine."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.scene_schedule import Schedule


def _steps(tmp_path, text: str):
    path = tmp_path / "protocol.csv"
    path.write_text(text, encoding="utf-8")
    return Schedule.from_dict({"file": str(path)}).steps


@pytest.mark.parametrize("text", [
    "duration [s];speed [rpm];radial_load [N];axial_load [N]\n60;1.031,5;500;0\n",
    "Duration;speed;radial_load;axial_load\n60 s;1.031,5 r/min;500 N;0 N\n",
    "duration [s]\tspeed [rpm]\tradial_load [kN]\taxial_load [kN]\n60\t1.031,5\t0,5\t0\n",
])
def test_grouped_decimal_comma_reads(tmp_path, text):
    (step,) = _steps(tmp_path, text)
    assert step.speed == pytest.approx(1031.5 * math.pi / 30, rel=1e-12)
    assert step.radial_load == pytest.approx(500.0)


def test_points_without_commas_stay_decimal_points(tmp_path):
    # no decimal comma in the file: '1.5' is one and a half
    (step,) = _steps(tmp_path, "duration [s];speed [rpm];radial_load [kN];axial_load [N]\n"
                               "60;1800;1.5;0\n")
    assert step.radial_load == pytest.approx(1500.0)


def test_a_malformed_grouping_is_named(tmp_path):
    with pytest.raises(InputError, match=r"row 2\.speed.*decimal comma"):
        _steps(tmp_path, "duration [s];speed [rpm];radial_load [N];axial_load [N]\n"
                         "60;1.031,5;500;0\n60;10.31,5;500;0\n")
