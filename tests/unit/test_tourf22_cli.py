"""Session-22 user tour A, the command line: the oil's property table at a cold start
(``thermobearing lubricant ISO_VG32 --temperatures -20,40``) stopped in argparse, and at
-60 degC the laws' validity warnings came through Python's warning stream, each repeated
per property with the source line that raised it."""

from __future__ import annotations

from thermobearing.cli import build_parser, join_negative_values, main


def test_a_comma_list_starting_negative_is_the_option_s_value(capsys):
    assert main(["lubricant", "ISO_VG32", "--temperatures", "-20,40"]) == 0
    rows = [ln.split() for ln in capsys.readouterr().out.splitlines()
            if ln.strip().startswith(("-20.0", "40.0"))]
    assert [r[0] for r in rows] == ["-20.0", "40.0"]


def test_only_options_taking_a_value_are_joined():
    from thermobearing.cli import _value_options

    options = _value_options(build_parser())
    assert {"--temperatures", "--out", "--set"} <= options
    assert "--quiet" not in options
    assert join_negative_values(["lubricant", "X", "--temperatures", "-20,0"], options) == \
        ["lubricant", "X", "--temperatures=-20,0"]
    assert join_negative_values(["run", "--quiet", "-3"], options) == ["run", "--quiet", "-3"]
    assert join_negative_values(["lubricant", "--temperatures", "--help"], options) == \
        ["lubricant", "--temperatures", "--help"]


def test_the_laws_warnings_are_listed_once_under_the_table(capsys):
    assert main(["lubricant", "ISO_VG32", "--temperatures=-60,40"]) == 0
    captured = capsys.readouterr()
    lines = [ln.strip() for ln in captured.out.splitlines() if "warning:" in ln]
    assert lines, "the -60 degC row is outside ASTM D341's range: said"
    assert len(lines) == len(set(lines))
    assert any("ASTM D341 used above 1e6 cSt" in ln for ln in lines)
    assert "ValidityWarning" not in captured.err
    assert "lubricant.py" not in captured.err


def test_output_piped_into_a_reader_that_stopped_ends_quietly(tmp_path, monkeypatch, capsys):
    """``thermobearing check SCENE | head -2`` printed "thermobearing check: error: Broken
    pipe" (the OSError branch meant for the user's paths)."""
    import sys

    from thermobearing.commands import check

    def closed_pipe(args):
        raise BrokenPipeError(32, "Broken pipe")

    monkeypatch.setattr(check, "run", closed_pipe)
    with (tmp_path / "stdout.txt").open("w") as fake:
        monkeypatch.setattr(sys, "stdout", fake)
        assert main(["check"]) == 141
    assert "Broken pipe" not in capsys.readouterr().err


def test_check_help_names_its_default_scene(capsys):
    """``check`` runs the embedded rig without a SCENE, which its help did not say."""
    import pytest

    with pytest.raises(SystemExit):
        main(["check", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "default: the embedded QJ1044 rig of seed paper 002" in out


def test_models_help_names_families_that_exist(capsys):
    """``models --help`` said only "one family": the names were found by trying."""
    import re

    import pytest

    from thermobearing.registry import all_registries

    with pytest.raises(SystemExit):
        main(["models", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    named = re.search(r"one family, e\.g\. (.*?) \(default", out).group(1).split(", ")
    assert len(named) >= 3 and set(named) <= set(all_registries())
