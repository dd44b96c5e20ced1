"""load_scene with a path that is not there, and the preset suggestion (session 19 tour)."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.scene import load_scene


def test_missing_toml_file_is_named(tmp_path):
    missing = tmp_path / "nosuch.toml"
    with pytest.raises(InputError) as info:
        load_scene(str(missing))
    msg = str(info.value)
    assert not isinstance(info.value, UnknownNameError)
    assert "no such file" in msg and str(missing) in msg
    assert "qj1044_rig" in msg  # the presets are still listed


def test_folder_is_named(tmp_path):
    with pytest.raises(InputError, match="a folder"):
        load_scene(str(tmp_path))


def test_preset_prefix_is_suggested():
    pattern = r"did you mean 'qj1044_rig' or 'qj1044_synthetic_measured'"
    with pytest.raises(UnknownNameError, match=pattern):
        load_scene("qj1044")


def test_misspelt_preset_still_unknown_name():
    with pytest.raises(UnknownNameError, match="known names are"):
        load_scene("qj1044_rgi_x")
