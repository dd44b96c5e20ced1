"""`thermobearing run` of a loss breakdown (no network) writes the breakdown CSV and names
it, and `thermobearing report` re-renders the folder with the same breakdown."""

from __future__ import annotations

import pandas as pd
import pytest
from scene_parts import PAPER002_JET, QJ1044_DE, scene_title

from thermobearing.cli import main

_SCENE = scene_title("QJ1044 breakdown at 1800 r/min") + QJ1044_DE + PAPER002_JET + """\
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
step_duration = "3 min"
[models]
kinematics = "race_control"
[outputs]
mode = "steady"
want = ["losses", "report"]
"""


def test_run_writes_and_names_the_breakdown_and_report_rerenders_it(tmp_path, capsys):
    scene = tmp_path / "breakdown.toml"
    scene.write_text(_SCENE, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--quiet"]) == 0
    assert "loss_breakdown.csv" in capsys.readouterr().out
    wide = pd.read_csv(out / "loss_breakdown.csv")
    long = pd.read_csv(out / "losses.csv")
    assert len(wide) == 1
    assert wide["total [W]"].iloc[0] == pytest.approx(long["power [W]"].sum())
    first = (out / "report.html").read_text(encoding="utf-8")
    (out / "report.html").unlink()
    (out / "loss_breakdown.csv").unlink()  # as in a folder of an older version
    assert main(["report", str(out)]) == 0
    pd.testing.assert_frame_equal(pd.read_csv(out / "loss_breakdown.csv"), wide)
    again = (out / "report.html").read_text(encoding="utf-8")
    for text in (first, again):
        assert "<h3>power loss by source [W]</h3>" in text
        assert "Bearing and operating points" in text
        assert "inlet temperature (the scene sets no initial temperature), 35 degC" in text
