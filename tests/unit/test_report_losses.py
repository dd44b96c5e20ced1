"""The loss breakdown of the report: one column per source, totals that are the sums of
their parts, sources named in words, one order and colour per source in every figure."""

from __future__ import annotations

import re
from html.parser import HTMLParser

import matplotlib.axes
import numpy as np
import pandas as pd
import pytest
from scene_parts import PAPER002_JET, QJ1044_DE, scene_title

from thermobearing.errors import InputError
from thermobearing.report import html_report
from thermobearing.report_losses import (
    SOURCE_LABELS,
    breakdown_by_destination,
    breakdown_by_source,
    fig_loss_bars,
    fmt_power,
    shares,
    source_colours,
    source_order,
)
from thermobearing.results import Results, ResultsWriter

#: (source, component, role, load dependence, W at step 0); step i scales by 1 + i
_ROWS = (("raceway_traction", "inner contact", "inner_ring", "load_dependent", 12.0),
         ("raceway_traction", "outer contact", "outer_ring", "load_dependent", 8.0),
         ("churning_elements", "element churning", "oil", "load_independent", 50.0),
         ("cage_guide", "cage guide", "cage", "load_independent", 30.0),
         ("pocket_friction", "ball pocket", "elements", "load_independent", 6.0),
         ("pocket_friction", "ball pocket", "cage", "load_independent", 4.0))


def _losses(bearings=("de", "nde"), with_role=True) -> pd.DataFrame:
    rows = []
    for b in bearings:
        for i in range(3):
            for src, comp, role, cls, w in _ROWS:
                row = {"step": i, "time [s]": 180.0 * (i + 1), "bearing": b,
                       "speed [rpm]": 1800.0, "radial load [kN]": 1.0,
                       "axial load [kN]": 2.0 * i, "source": src, "component": comp,
                       "power [W]": w * (1 + i), "load dependence": cls}
                if with_role:
                    row["role"] = role
                rows.append(row)
    return pd.DataFrame(rows)


def test_breakdown_has_one_column_per_source_and_the_total_is_their_sum():
    losses = _losses()
    wide = breakdown_by_source(losses)
    assert len(wide) == 6  # 3 steps x 2 bearings
    sources = [c for c in wide.columns if c[:-4] in SOURCE_LABELS]
    # fixed order: contact friction first, then the cage, then the oil drag
    assert sources == ["raceway_traction [W]", "pocket_friction [W]", "cage_guide [W]",
                       "churning_elements [W]"]
    row = wide[(wide["step"] == 1) & (wide["bearing"] == "nde")].iloc[0]
    assert row["raceway_traction [W]"] == pytest.approx(2 * (12.0 + 8.0))
    assert row["pocket_friction [W]"] == pytest.approx(2 * 10.0)
    assert row["total [W]"] == pytest.approx(2 * 110.0)
    assert row["load-dependent [W]"] + row["load-independent [W]"] == pytest.approx(220.0)
    # the total of every point equals the long table's sum (the energy bookkeeping)
    long_total = losses.groupby(["step", "bearing"])["power [W]"].sum()
    for _, r in wide.iterrows():
        assert r["total [W]"] == pytest.approx(long_total[(r["step"], r["bearing"])])
    sh = shares(wide)
    pct = [c for c in sh.columns if c.endswith("[%]")]
    np.testing.assert_allclose(sh[pct].sum(axis=1), 100.0)


def test_breakdown_by_destination_matches_the_totals_and_names_the_components():
    losses = _losses()
    dest = breakdown_by_destination(losses)
    assert [c for c in dest.columns if c.endswith("[W]")] == [
        "inner ring [W]", "outer ring [W]", "rolling elements [W]", "cage [W]", "oil [W]",
        "total [W]"]
    np.testing.assert_allclose(dest["total [W]"], breakdown_by_source(losses)["total [W]"])
    first = dest.iloc[0]
    assert first["cage [W]"] == pytest.approx(30.0 + 4.0)
    assert breakdown_by_destination(_losses(with_role=False)) is None
    from thermobearing.report_losses import fig_destinations

    assert fig_destinations(losses)[:8] == b"\x89PNG\r\n\x1a\n"
    assert fig_destinations(_losses(with_role=False)) is None


def test_a_table_without_sources_is_refused_by_name():
    with pytest.raises(InputError, match="source"):
        breakdown_by_source(pd.DataFrame({"step": [0], "power [W]": [1.0]}))


def test_sources_keep_their_place_and_colour_whatever_the_table_holds():
    a = source_colours(["churning_cage", "raceway_traction", "my_plugin"])
    b = source_colours(["raceway_traction", "cage_guide"])
    assert a["raceway_traction"] == b["raceway_traction"]
    assert len({str(c) for c in source_colours(list(SOURCE_LABELS)).values()}) == len(
        SOURCE_LABELS)
    assert source_order(["my_plugin", "churning_cage", "raceway_traction"]) == [
        "raceway_traction", "churning_cage", "my_plugin"]


def test_loss_bars_stack_in_the_fixed_order_with_the_fixed_colours(monkeypatch):
    calls = []
    real = matplotlib.axes.Axes.bar

    def spy(self, x, height, *args, **kwargs):
        calls.append((kwargs.get("label"), kwargs.get("color")))
        return real(self, x, height, *args, **kwargs)

    monkeypatch.setattr(matplotlib.axes.Axes, "bar", spy)
    png = fig_loss_bars(_losses())
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    colours = source_colours(SOURCE_LABELS)
    expected = [(SOURCE_LABELS[s], colours[s]) for s in
                ("raceway_traction", "pocket_friction", "cage_guide", "churning_elements")]
    assert calls == expected * 2  # one panel per bearing, both in the same order


def test_powers_are_rounded_for_a_reader():
    assert [fmt_power(v) for v in (2016.85, 45.85, 5.788, 0.3474, 0.0)] == [
        "2,017", "46", "5.8", "0.35", "0"]


class _Tables(HTMLParser):
    """Headings and tables (header cells, body rows) of an HTML page."""

    def __init__(self) -> None:
        super().__init__()
        self.tables: list[dict] = []
        self.headings: list[str] = []
        self._cell: list[str] | None = None
        self._row: list[str] | None = None
        self._heading: list[str] | None = None
        self._in_head = False

    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables.append({"heading": self.headings[-1] if self.headings else "",
                                "head": [], "rows": []})
        elif tag == "thead":
            self._in_head = True
        elif tag == "tr":
            self._row = []
        elif tag in ("td", "th"):
            self._cell = []
        elif tag in ("h2", "h3"):
            self._heading = []

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append("".join(self._cell).strip())
            self._cell = None
        elif tag == "thead":
            self._in_head = False
        elif tag == "tr" and self._row is not None:
            table = self.tables[-1]
            if self._in_head:
                table["head"].extend(self._row)
            else:
                table["rows"].append(self._row)
            self._row = None
        elif tag in ("h2", "h3") and self._heading is not None:
            self.headings.append("".join(self._heading).strip())
            self._heading = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)
        if self._heading is not None:
            self._heading.append(data)

    def table(self, heading: str) -> dict:
        return next(t for t in self.tables if t["heading"] == heading)


def test_report_shows_the_breakdown_in_words_with_units_and_rounded():
    res = Results(tables={"losses": _losses()}, scene_toml='title = "x"\n')
    page = _Tables()
    page.feed(html_report(res, "demo"))
    t = page.table("power loss by source [W]")
    assert "raceway contacts (rolling and sliding shear) [W]" in t["head"]
    assert "total [W]" in t["head"] and "" not in t["head"]  # no index column
    assert all(c.endswith("]") for c in t["head"] if c not in ("step", "bearing"))
    assert len(t["rows"]) == 6
    total = t["head"].index("total [W]")
    assert t["rows"][0][total] == "110"
    dest = page.table("heat received by component [W]")
    assert "rolling elements [W]" in dest["head"]
    assert "what the sources are" in page.headings
    # the raw per-component rows: not cut at random rows but the first ones, with a note
    text = html_report(Results(tables={"losses": _losses(("a", "b", "c", "d"))},
                               scene_toml=""), "demo")
    assert re.search(r"first 60 of 72 rows shown; all 72 in losses.csv", text)


def test_written_breakdown_csv_has_units_in_every_value_column(tmp_path):
    res = Results(tables={"losses": _losses()})
    res.write(tmp_path)
    wide = pd.read_csv(tmp_path / "loss_breakdown.csv")
    value_cols = [c for c in wide.columns if c not in ("step", "bearing")]
    assert all(re.search(r"\[(W|rpm|kN)\]$", c) for c in value_cols)
    # a writer for a new run removes the breakdown of an earlier run in the folder
    ResultsWriter(tmp_path)
    assert not (tmp_path / "loss_breakdown.csv").exists()


def test_large_numbers_in_report_tables_read_without_an_exponent():
    from thermobearing.report_sections import html_table

    text = html_table(pd.DataFrame({"speed [rpm]": [20000.0, 1800.0],
                                    "residual": [2.6e-11, 1.0]}))
    # a column that reaches 1e4 groups the thousands of each value (tour 20: "1800" beside
    # "20,000" in one column read unevenly)
    assert "20,000" in text and "1,800" in text and "2.6e-11" in text
    assert "e+04" not in text


def test_report_with_its_scene_names_the_bearing_the_models_and_their_ranges():
    from thermobearing.scene import loads_scene

    scene = loads_scene(scene_title("t") + QJ1044_DE + PAPER002_JET + """[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
step_duration = "3 min"
""")
    res = Results(tables={"losses": _losses(("de",))[lambda d: d["step"] == 0]},
                  chain=[("film", "hamrock_dowson_1977_central"),
                         ("heat_source", "cage_guide")])
    text = html_report(res, "t", scene=scene)
    page = _Tables()
    page.feed(text)
    bearing = page.table("Bearing and operating points")
    assert bearing["rows"][0][:4] == ["de", "QJ1044", "four point", "220 x 340 x 56"]
    chain = page.table("Model chain")
    assert chain["head"] == ["family", "model", "what it is", "valid for"]
    assert "2000 <= G <= 8000" in chain["rows"][0][3]
    # a steady breakdown (no transient): said, and the losses' temperature is named
    assert "no transient run: no energy audit of the thermal network" in text
    assert "inlet temperature (the scene sets no initial temperature), 35 degC" in text
    assert page.table("catalogue cross-check")["head"][-1] == \
        "this run vs Palmgren M0 + M1 [%]"


def test_steady_temperatures_are_drawn_against_the_swept_speed(monkeypatch):
    from thermobearing.report import attach_figures, fig_steady_temperatures

    labels = []
    real = matplotlib.axes.Axes.set_xlabel
    monkeypatch.setattr(matplotlib.axes.Axes, "set_xlabel",
                        lambda self, text, *a, **k: (labels.append(text),
                                                     real(self, text, *a, **k))[1])
    steady = pd.DataFrame({"step": [0, 1, 2], "de.oil [degC]": [35.2, 35.8, 37.1],
                           "de.housing [degC]": [36.0, 39.1, 45.4]})
    kin = pd.DataFrame({"step": [0, 1, 2], "bearing": "de", "speed [rpm]": [600.0, 1200.0,
                                                                            1800.0],
                        "radial load [kN]": 1.0, "axial load [kN]": 10.0,
                        "cage speed ratio [-]": 0.452,
                        "theoretical cage speed ratio [-]": 0.452})
    assert fig_steady_temperatures(steady, kin)[:4] == b"\x89PNG"
    assert labels == ["speed [rpm]"]
    res = Results(tables={"steady_temperatures": steady, "kinematics": kin})

    class _Scene:
        measured = None

    attach_figures(res, _Scene())
    assert "steady_temperatures" in res.figures


def test_summary_names_the_range_of_the_total_and_the_largest_source():
    from thermobearing.report_losses import summary_lines

    lines = summary_lines(breakdown_by_source(_losses()))
    assert len(lines) == 2 and lines[0].startswith("bearing de: ")
    # step 0: 110 W; step 2: 330 W, of which the element churning 150 W (45 %)
    assert ("total loss 110 W (step 0, 1800 r/min, 1 kN radial, 0 kN axial) to 330 W "
            "(step 2, 1800 r/min, 1 kN radial, 4 kN axial)") in lines[0]
    assert lines[0].endswith(f"{SOURCE_LABELS['churning_elements']}, 150 W (45 %)")


def test_figures_keep_their_file_name_as_alt_and_say_what_they_show():
    res = Results(tables={"losses": _losses()})
    res.figures["power_losses"] = fig_loss_bars(_losses())
    text = html_report(res, "demo")
    assert re.search(r'<img alt="power_losses" src="data:image/png;base64,', text)
    assert "<figcaption>power loss by source [W] per operating point and bearing" in text


def test_components_without_a_loss_class_are_shown_so_the_classes_add_up():
    losses = _losses(("de",))
    losses.loc[losses["source"] == "cage_guide", "load dependence"] = ""
    wide = breakdown_by_source(losses)
    np.testing.assert_allclose(wide["unclassified [W]"], [30.0, 60.0, 90.0])
    np.testing.assert_allclose(wide["load-dependent [W]"] + wide["load-independent [W]"]
                               + wide["unclassified [W]"], wide["total [W]"])
    assert "unclassified [%]" not in shares(wide)
    assert "unclassified [W]" not in breakdown_by_source(_losses(("de",)))


def test_a_run_over_a_speed_by_load_grid_gets_loss_maps_named_by_bearing():
    from thermobearing.report import _caption, _run_loss_maps
    from thermobearing.report_losses import map_axes

    grid = _losses(("nde",))
    grid = grid[grid["source"].isin(("raceway_traction", "cage_guide"))]
    grid["speed [rpm]"] = grid["step"].map({0: 600.0, 1: 600.0, 2: 1800.0})
    # step 2 at 2 kN, as step 1 (at 4 kN the four steps covered 4 of 2 x 3 combinations,
    # no 2 x 2 block, and the map had no contour: such runs get none now)
    grid.loc[grid["step"] == 2, "axial load [kN]"] = 2.0
    extra = grid[grid["step"] == 2].assign(step=3, **{"axial load [kN]": 0.0})
    grid = pd.concat([grid, extra], ignore_index=True)  # 2 speeds x 2 axial loads
    assert map_axes(breakdown_by_source(grid)) == ("speed [rpm]", "axial load [kN]")
    assert map_axes(breakdown_by_source(_losses())) is None  # only the axial load varies
    maps = _run_loss_maps(grid)
    assert list(maps) == ["loss_maps_nde"] and maps["loss_maps_nde"][:4] == b"\x89PNG"
    assert _caption("loss_maps_nde") == "power loss maps over speed and load [W], bearing nde"


def test_a_source_that_does_not_run_on_a_bearing_is_left_empty():
    """A shaft with a ball and a roller bearing: the roller's EHL rolling resistance has no
    rows for the ball bearing, so its cell there is empty (not 0 W, which would read as a
    computed zero), and the total is the sum of the sources that ran."""
    import math

    losses = pd.DataFrame({
        "step": [0, 0, 0], "bearing": ["crb", "crb", "ball"],
        "speed [rpm]": [1000.0] * 3, "radial load [kN]": [1.0] * 3,
        "axial load [kN]": [0.0] * 3,
        "source": ["raceway_traction", "ehl_rolling_resistance", "raceway_traction"],
        "component": ["inner contact", "inner contact", "inner contact"],
        "power [W]": [3.0, 2.0, 5.0]})
    table = breakdown_by_source(losses).set_index("bearing")
    assert table.loc["crb", "ehl_rolling_resistance [W]"] == 2.0
    assert math.isnan(table.loc["ball", "ehl_rolling_resistance [W]"])
    assert table.loc["ball", "total [W]"] == 5.0 and table.loc["crb", "total [W]"] == 5.0


def test_steady_table_with_its_own_operating_columns_keeps_the_speed_axis(monkeypatch):
    """steady_temperatures.csv carries speed and loads itself (2026-11-24): merging the
    kinematics table's copies suffixed them _x / _y and the figure fell back to the step."""
    from thermobearing.report import fig_steady_temperatures, steady_with_operating

    labels = []
    real = matplotlib.axes.Axes.set_xlabel
    monkeypatch.setattr(matplotlib.axes.Axes, "set_xlabel",
                        lambda self, text, *a, **k: (labels.append(text),
                                                     real(self, text, *a, **k))[1])
    steady = pd.DataFrame({"step": [0, 1, 2], "speed [rpm]": [600.0, 1200.0, 1800.0],
                           "radial load [kN]": 1.0, "axial load [kN]": 10.0,
                           "de.oil [degC]": [35.2, 35.8, 37.1]})
    kin = pd.DataFrame({"step": [0, 1, 2], "bearing": "de",
                        "speed [rpm]": [600.0, 1200.0, 1800.0], "radial load [kN]": 1.0,
                        "axial load [kN]": 10.0})
    merged = steady_with_operating(steady, kin)
    assert list(merged.columns) == list(steady.columns)
    assert fig_steady_temperatures(steady, kin)[:4] == b"\x89PNG"
    assert labels == ["speed [rpm]"]
    # an older folder's steady table without them still gets them from the kinematics
    old = steady.drop(columns=["speed [rpm]", "radial load [kN]", "axial load [kN]"])
    assert list(steady_with_operating(old, kin)["speed [rpm]"]) == [600.0, 1200.0, 1800.0]
