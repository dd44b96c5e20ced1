"""A catalogue bearing file (``estimate_missing = true``) with a user's mistakes (session-19
fuzz probes of bearing files): ``width = "0 mm"`` was refused as ``cage.width = 0.0`` (the
estimated cage's, no key of the file), a bore beyond the ISO 5753-1 tables as
``diametral_clearance is missing`` without the file's name, and ``bore = 30`` (mm meant,
read as 30 m) without a word that bare numbers are metres."""

from __future__ import annotations

import pytest

from thermobearing.bearing_estimates import complete_from_catalogue
from thermobearing.errors import InputError

CATALOGUE = {"name": "6206", "kind": "deep_groove", "source": "catalogue",
             "estimate_missing": True, "bore": "30 mm", "outer_diameter": "62 mm",
             "width": "16 mm", "ball_diameter": "9.525 mm", "n_balls": 9}
ORIGIN = "bearing[my_6206]"


def _refusal(**edits: object) -> InputError:
    with pytest.raises(InputError) as info:
        complete_from_catalogue({**CATALOGUE, **edits}, origin=ORIGIN)
    return info.value


@pytest.mark.parametrize(("key", "value"), [("width", "0 mm"), ("width", "-16 mm"),
                                            ("bore", "0 mm")])
def test_a_length_that_is_not_positive_names_its_key(key: str, value: str) -> None:
    exc = _refusal(**{key: value})
    assert exc.field == f"{ORIGIN}.{key}"
    assert exc.value == value


def test_a_bore_beyond_the_clearance_tables_names_the_key_to_give() -> None:
    exc = _refusal(bore="300 mm", outer_diameter="420 mm")
    assert exc.field == f"{ORIGIN}.diametral_clearance"
    assert "100 mm" in exc.allowed and "bare number" not in exc.allowed


def test_a_bare_bore_is_said_to_be_metres() -> None:
    exc = _refusal(bore=30)
    assert exc.field == f"{ORIGIN}.diametral_clearance"
    assert "bore = 30 is a bare number, read in m" in exc.allowed


def test_the_catalogue_entry_completes() -> None:
    out = complete_from_catalogue(dict(CATALOGUE), origin=ORIGIN)
    assert out["diametral_clearance"] > 0 and out["cage"]["width"] > 0
