"""thermobearing.toml_files: memoised TOML parsing with per-caller copies."""

import os
import tomllib

import pytest

from thermobearing.toml_files import read_toml


def test_read_toml_parses_and_hands_out_independent_copies(tmp_path):
    f = tmp_path / "a.toml"
    f.write_text('speed = "1800 rpm"\n[table]\nvalues = [1, 2, 3]\n', encoding="utf-8")
    first = read_toml(f)
    assert first == {"speed": "1800 rpm", "table": {"values": [1, 2, 3]}}
    first["table"]["values"].append(4)          # a caller edits its copy ...
    first["speed"] = "0 rpm"
    assert read_toml(f) == {"speed": "1800 rpm", "table": {"values": [1, 2, 3]}}  # ... alone


def test_read_toml_reads_an_edited_file_again(tmp_path):
    f = tmp_path / "b.toml"
    f.write_text("x = 1\n", encoding="utf-8")
    assert read_toml(f) == {"x": 1}
    st = f.stat()
    f.write_text("x = 22\n", encoding="utf-8")   # new size (and a new mtime below)
    os.utime(f, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000))
    assert read_toml(f) == {"x": 22}


def test_read_toml_errors_are_those_of_tomllib(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("x = \n", encoding="utf-8")
    with pytest.raises(tomllib.TOMLDecodeError):
        read_toml(bad)
    with pytest.raises(OSError):
        read_toml(tmp_path / "missing.toml")
