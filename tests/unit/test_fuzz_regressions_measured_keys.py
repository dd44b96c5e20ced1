"""``[measured]`` keys probed while fuzzing the scene front end (session 18): a number as
``time_column`` (``5``) was looked for as a header cell, found in a data row, and the
refusal named the wrong thing ("measured.columns['TC1'] ... a column of the file: 5, 30");
``unit = "°C"`` was refused though the reader takes °C, celsius, kelvin or ℉ in the file's
own header and units row."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene_sections import Measured


def _m(**kw):
    return Measured.from_dict({"file": "rig.csv", "columns": {"TC1": "a.housing"}, **kw})


@pytest.mark.parametrize("tcol", [5, 2.5, True, "", "  "])
def test_time_column_must_be_a_name(tcol):
    with pytest.raises(InputError, match=r"measured.time_column = .*a column name \(a text"):
        _m(time_column=tcol)


@pytest.mark.parametrize(("written", "unit"), [("°C", "degC"), ("celsius", "degC"),
                                               ("\u2109", "degF"), ("kelvin", "K"),
                                               ("degF", "degF"), ("K", "K")])
def test_unit_spellings(written, unit):
    assert _m(unit=written).unit == unit


@pytest.mark.parametrize("bad", ["C", "F", "bar", 5])
def test_unit_refused_names_the_spellings(bad):
    with pytest.raises(InputError, match=r"measured.unit = .*degC, K or degF \(or °C"):
        _m(unit=bad)
