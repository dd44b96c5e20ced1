"""User tour 21, power-loss breakdown of an NU214 over a speed x load map: the validity
warnings said 'cage skidding ... at 1 of 9 steps (step 2)', but the loss table's row of
step 2 (10000 r/min, 1 kN: 3.5 kW, the map's corner) looked like every other. The run now
records the flagged steps per bearing (metadata.json 'flagged_steps') and the table by
source names the checks that flag each row, only on those rows.
"""

from __future__ import annotations

import json
import re

import pandas as pd
import pytest
from nu214_scene import nu214_jet_scene

from thermobearing.commands.report import run_report
from thermobearing.report_sections import _with_checks
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = nu214_jet_scene(title="tour 21 flagged rows", schedule="""axial_load = "0 kN"
step_duration = "1 min"
steps = [{ speed = "2000 rpm", radial_load = "5 kN" },
         { speed = "10000 rpm", radial_load = "1 kN" }]""",
                        want='["losses", "kinematics", "report"]')


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("flagged")
    Simulation(loads_scene(SCENE), progress=False).run(out_dir=out)
    return out


def _row_checks(html: str) -> list[str]:
    table = html[html.index("<h3>power loss by source [W]</h3>"):]
    table = table[:table.index("<h3>share of the total")]
    rows = re.findall(r"<tr[^>]*>(.*?)</tr>", table, flags=re.S)
    cells = [re.findall(r"<t[dh][^>]*>(.*?)</t[dh]>", r, flags=re.S) for r in rows]
    head = [c.strip() for c in cells[0]]
    at = head.index("operating checks")
    return [c[at].strip() for c in cells[1:]]


def test_metadata_records_the_flagged_steps(folder):
    meta = json.loads((folder / "metadata.json").read_text(encoding="utf-8"))
    # 10000 r/min at 1 kN: the cage lags by more than 5 %; 2000 r/min at 5 kN does not
    assert meta["flagged_steps"] == {"crb": {"skid": [1], "stress": [], "film": []}}
    assert any("crb: cage skidding" in w and "step 1" in w for w in meta["warnings"])


def test_the_flagged_row_says_so_and_only_it(folder):
    html = (folder / "report.html").read_text(encoding="utf-8")
    assert _row_checks(html) == ["-", "cage skidding"]
    assert "operating checks: the checks that flag the step" in html
    again = run_report(folder).read_text(encoding="utf-8")  # from the folder's files
    assert _row_checks(again) == ["-", "cage skidding"]


def test_no_column_when_nothing_is_flagged():
    table = pd.DataFrame({"step": [0, 1], "bearing": ["a", "a"], "total [W]": [1.0, 2.0]})
    assert "operating checks" not in _with_checks(table, {})
    assert "operating checks" not in _with_checks(
        table, {"a": {"skid": [], "stress": [], "film": []}})
    two = pd.DataFrame({"step": [0, 0], "bearing": ["a", "b"], "total [W]": [1.0, 2.0]})
    got = _with_checks(two, {"b": {"skid": [0], "stress": [0], "film": []}})
    assert list(got["operating checks"]) == ["-", "cage skidding, contact stress"]
