"""Tour R8: a bearing TOML with a bare number where a unit was meant.

Before: ``ball_diameter = 12.7`` (read as 12.7 m) stopped as ``cage.inner_diameter =
-5.645``, a value the estimates derived, and ``contact_angle = 40`` (read as 40 rad) as
``bearing.contact_angle = 40.0 ... [0, 1.5708) rad`` without saying a bare number is
radians. After: the given dimensions are checked first, under their own key, and a bare
number is said to be read in metres / radians with the spelling that was probably meant.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from thermobearing import load_bearing
from thermobearing.errors import InputError

HEAD = ('name = "t"\nkind = "deep_groove"\nsource = "test"\nestimate_missing = true\n'
        'bore = "30 mm"\nouter_diameter = "62 mm"\nwidth = "16 mm"\nn_balls = 9\n')


def _load(tmp_path: Path, extra: str):
    path = tmp_path / "b6206.toml"
    path.write_text(HEAD + extra, encoding="utf-8")
    return load_bearing(path)


def test_bare_ball_diameter_is_said_to_be_metres(tmp_path):
    with pytest.raises(InputError) as err:
        _load(tmp_path, "ball_diameter = 12.7\n")
    text = str(err.value)
    assert "bearing[b6206].ball_diameter = 12.7" in text
    assert "(D - d)/2 = 16 mm" in text and "metres" in text and '"12.7 mm"' in text
    assert "cage" not in text


def test_ball_diameter_with_unit_too_large_is_refused_without_the_metre_hint(tmp_path):
    with pytest.raises(InputError) as err:
        _load(tmp_path, 'ball_diameter = "17 mm"\n')
    assert "ball_diameter" in str(err.value) and "metres" not in str(err.value)


def test_bare_contact_angle_is_said_to_be_radians(tmp_path):
    with pytest.raises(InputError) as err:
        _load(tmp_path, 'ball_diameter = "9.525 mm"\ncontact_angle = 40\n')
    text = str(err.value)
    assert "bearing[b6206].contact_angle = 40" in text
    assert "[0, 90) deg" in text and "radians" in text and '"40 deg"' in text


def test_pitch_outside_the_rings_names_the_pitch(tmp_path):
    with pytest.raises(InputError) as err:
        _load(tmp_path, 'ball_diameter = "9.525 mm"\npitch_diameter = 46\n')
    text = str(err.value)
    assert "pitch_diameter = 46" in text and '"46 mm"' in text


def test_consistent_bearing_still_loads(tmp_path):
    b = _load(tmp_path, 'ball_diameter = "9.525 mm"\ncontact_angle = 0.0\n')
    assert b.ball_diameter == pytest.approx(9.525e-3)
