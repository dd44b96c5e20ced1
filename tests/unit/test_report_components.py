"""A run records where each source's heat goes (the ``role`` column of losses.csv): the
report's heat-by-component table and figure appear and add up to the loss by source; the
speeds in the tables are the set values, without unit-conversion round-off."""

from __future__ import annotations

from html.parser import HTMLParser

import pandas as pd
import pytest

from thermobearing.heat_sources import ROLES
from thermobearing.report_losses import breakdown_by_destination, breakdown_by_source
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.simulation_tables import set_value
from thermobearing.units import from_si, to_si

_SCENE = """
title = "heat by component"
[[bearings]]
name = "b"
preset = "{preset}"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "5 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
initial_temperature = "40 degC"
[schedule]
radial_load = "{radial}"
axial_load = "{axial}"
steps = [{{ duration = "1 min", speed = "1500 rpm" }}, {{ duration = "1 min", speed = "3000 rpm" }}]
[models]
kinematics = "race_control"
[outputs]
mode = "steady"
want = ["losses", "report"]
"""


class _Page(HTMLParser):
    """The tables of a page (by the h3 heading above them) and the figures' alt texts."""

    def __init__(self) -> None:
        super().__init__()
        self.tables: dict[str, list[list[str]]] = {}
        self.alts: list[str] = []
        self._heading: list[str] | None = None
        self._last = ""
        self._table: list[list[str]] | None = None
        self._cell: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        if tag in ("h2", "h3"):
            self._heading = []
        elif tag == "table":
            self._table = self.tables.setdefault(self._last, [])
        elif tag == "tr" and self._table is not None:
            self._table.append([])
        elif tag in ("td", "th"):
            self._cell = []
        elif tag == "img":
            self.alts.append(dict(attrs).get("alt", ""))

    def handle_endtag(self, tag):
        if tag in ("h2", "h3") and self._heading is not None:
            self._last = "".join(self._heading).strip()
            self._heading = None
        elif tag in ("td", "th") and self._cell is not None:
            self._table[-1].append("".join(self._cell).strip())
            self._cell = None
        elif tag == "table":
            self._table = None

    def handle_data(self, data):
        for part in (self._heading, self._cell):
            if part is not None:
                part.append(data)


def _number(cell: str) -> float:
    return float(cell.replace(",", ""))


@pytest.mark.parametrize("preset, radial, axial", [("SKF6304", "2 kN", "0.5 kN"),
                                                   ("NU214", "10 kN", "0 kN")],
                         ids=["ball", "roller"])
def test_losses_record_where_the_heat_goes_and_the_report_adds_it_up(tmp_path, preset,
                                                                     radial, axial):
    scene = loads_scene(_SCENE.format(preset=preset, radial=radial, axial=axial))
    res = Simulation(scene, progress=False).run(tmp_path)
    losses = pd.read_csv(tmp_path / "losses.csv")
    # every earlier column is still there, and the role beside the component (a steady
    # run's rows have no time)
    for col in ("step", "bearing", "speed [rpm]", "radial load [kN]",
                "axial load [kN]", "source", "component", "power [W]", "load dependence",
                "role"):
        assert col in losses
    assert "time [s]" not in losses
    assert set(losses["role"]) <= set(ROLES)
    # a component's rows are its split over the components it heats: the roles of one
    # (step, source, component) are distinct, and some component heats two of them
    keys = ["step", "bearing", "source", "component"]
    assert not losses.duplicated(keys + ["role"]).any()
    assert (losses.groupby(keys)["role"].nunique() > 1).any()
    by_source = breakdown_by_source(losses)
    by_dest = breakdown_by_destination(losses)
    assert by_dest is not None
    assert by_dest["total [W]"].to_numpy() == pytest.approx(
        by_source["total [W]"].to_numpy(), rel=1e-12)
    # the report shows the table and the figure; its rounded cells add up to the total
    page = _Page()
    page.feed((tmp_path / "report.html").read_text(encoding="utf-8"))
    assert "heat_destinations" in page.alts
    assert (tmp_path / "heat_destinations.png").stat().st_size > 0
    head, *rows = page.tables["heat received by component [W]"]
    assert "rolling elements [W]" in head and "oil [W]" in head
    comps = [i for i, c in enumerate(head) if c.endswith("[W]") and c != "total [W]"]
    total = head.index("total [W]")
    assert len(rows) == len(scene.schedule.steps)
    for row in rows:
        shown = sum(_number(row[i]) for i in comps)
        # each cell rounded to whole watts from 10 W, to 0.1 W from 1 W, 2 digits below
        assert shown == pytest.approx(_number(row[total]), abs=0.5 * len(comps) + 0.05)
    assert res.tables["losses"]["power [W]"].sum() == pytest.approx(
        by_source["total [W]"].sum(), rel=1e-12)


def test_speeds_are_written_as_set_without_conversion_round_off():
    # 1500 r/min through rad/s comes back as 1500.0000000000002 unrounded
    assert from_si(to_si("1500 rpm", "angular_speed"), "rpm") != 1500.0
    scene = loads_scene(_SCENE.format(preset="SKF6304", radial="2 kN", axial="0.5 kN")
                        .replace('want = ["losses", "report"]', 'want = ["kinematics"]'))
    kin = Simulation(scene, progress=False).run().tables["kinematics"]
    assert list(kin["speed [rpm]"]) == [1500.0, 3000.0]
    assert [repr(v) for v in kin["speed [rpm]"]] == ["1500.0", "3000.0"]
    assert set_value(1500.0000000000002) == 1500.0
    assert set_value(47.00000000000001) == 47.0
    assert set_value(1234.56789012345) == 1234.56789012
    assert set_value(0.0) == 0.0 and set_value(-25.000000000000004) == -25.0
