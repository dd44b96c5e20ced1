"""The ``thermobearing lubricant`` command prints the property table of a preset."""

from __future__ import annotations

import argparse

import pytest

from thermobearing.commands import lubricant as cmd
from thermobearing.errors import UnknownNameError


def _args(**kw):
    parser = argparse.ArgumentParser()
    cmd.add_arguments(parser)
    argv = [kw.pop("name")] if "name" in kw else []
    for k, v in kw.items():
        argv += [f"--{k}", v]
    return parser.parse_args(argv)


def test_lists_presets(capsys):
    assert cmd.run(_args()) == 0
    assert "ISO_VG46" in capsys.readouterr().out


def test_table_values(capsys):
    assert cmd.run(_args(name="ISO_VG46", temperatures="40,100", pressure="0.5 GPa")) == 0
    out = capsys.readouterr().out.splitlines()
    row40 = [ln for ln in out if ln.strip().startswith("40.0")][0].split()
    assert float(row40[1]) == pytest.approx(46.0, rel=1e-3)  # nu40 of the grade
    row100 = [ln for ln in out if ln.strip().startswith("100.0")][0].split()
    assert float(row100[1]) == pytest.approx(6.8, rel=1e-3)


def test_unknown_preset():
    with pytest.raises(UnknownNameError):
        cmd.run(_args(name="ISO_VG47"))
