"""Did-you-mean suggestions of unknown names: a value that is the last part of known names
(``VG46`` for ``ISO_VG46``) is suggested like a prefix."""

from __future__ import annotations

import pytest

from thermobearing.errors import UnknownNameError
from thermobearing.lubricant import load_lubricant

KNOWN = ["ISO_VG32", "ISO_VG46", "ISO_VG68", "ISO_VG100", "OIL_4109", "MIL_PRF_23699"]


@pytest.mark.parametrize(("value", "hint"), [
    ("VG46", "(did you mean 'ISO_VG46'?)"),
    ("vg100", "(did you mean 'ISO_VG100'?)"),
    ("4109", "(did you mean 'OIL_4109'?)"),
    ("PRF_23699", "(did you mean 'MIL_PRF_23699'?)"),
])
def test_the_end_of_a_known_name_is_suggested(value: str, hint: str) -> None:
    assert str(UnknownNameError("lubricant", value, KNOWN)).endswith(hint)


@pytest.mark.parametrize("value", ["VG", "46", "XYZ_VG46"])
def test_no_suggestion_for_a_fragment_or_a_wrong_name(value: str) -> None:
    assert "did you mean" not in str(UnknownNameError("lubricant", value, KNOWN))


def test_the_lubricant_loader_suggests_the_preset() -> None:
    with pytest.raises(UnknownNameError, match=r"did you mean 'ISO_VG46'"):
        load_lubricant("VG46")
