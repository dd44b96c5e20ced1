"""`thermobearing report` on a folder whose scene.toml is damaged names the file (scene
fuzzing: it said 'scene.bearings is missing', as if the user's own scene were wrong)."""

from __future__ import annotations

import pytest

from thermobearing.commands.report import _folder_scene
from thermobearing.errors import InputError


def test_damaged_folder_scene_is_named(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text('title = "cut short"\n', encoding="utf-8")
    with pytest.raises(InputError) as info:
        _folder_scene(path)
    assert str(path) in str(info.value.field) and "bearings" in str(info.value.field)
