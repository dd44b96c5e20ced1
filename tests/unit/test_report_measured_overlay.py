"""Measured temperatures in the report and on the terminal: the reader's notes and the
file's coverage of the run under "measured vs predicted", a sensor without a sample in the
run kept in the errors table with the reason, and a temperature figure whose sensors can
be told apart and whose axes are the run's."""

from __future__ import annotations

from html.parser import HTMLParser
from pathlib import Path
from types import SimpleNamespace

import matplotlib.axes
import matplotlib.figure
import numpy as np
import pandas as pd
import pytest

from thermobearing.commands.run import _print_measured
from thermobearing.report import read_measured, write_report
from thermobearing.report_measured import (
    NO_SAMPLE,
    fig_temperatures,
    short_notes,
    temperature_errors,
    terminal_lines,
)
from thermobearing.results import Results
from thermobearing.scene import Scene, load_scene

EXAMPLE = "qj1044_synthetic_measured"
COLUMNS = {"TC_DE": "drive_end.housing", "TC_NDE": "non_drive_end.housing",
           "TC_OIL": "drive_end.oil"}


def _temps() -> pd.DataFrame:
    """A 60-min run: housings warming by 10 and 12 K, the oil by 5 K (first-order rise,
    15-min time constant)."""
    t = np.arange(0.0, 3601.0, 60.0)
    rise = 1.0 - np.exp(-t / 900.0)
    return pd.DataFrame({"time [s]": t, "time [min]": t / 60.0,
                         "drive_end.housing [degC]": 35.0 + 10.0 * rise,
                         "non_drive_end.housing [degC]": 35.0 + 12.0 * rise,
                         "drive_end.oil [degC]": 35.0 + 5.0 * rise})


def _logger_file(path: Path, minutes: list[float]) -> Path:
    """Readings 0.3 K above the prediction of :func:`_temps` at ``minutes``; TC_DE has two
    dropout flags, TC_OIL is empty wherever the run is, minute 30 is logged twice, and a
    900 degC spike sits after the run's end."""
    temps = _temps()
    lines = ["time [min];TC_DE;TC_NDE;TC_OIL"]
    for k, m in enumerate(minutes):
        de = np.interp(m * 60, temps["time [s]"], temps["drive_end.housing [degC]"]) + 0.3
        nde = np.interp(m * 60, temps["time [s]"], temps["non_drive_end.housing [degC]"])
        de_cell = "OVL" if k in (3, 4) else f"{de:.4f}"
        nde_cell = "900" if m > 60 else f"{nde + 0.3:.4f}"
        oil_cell = "" if 0 <= m <= 60 else "36.0"
        lines.append(f"{m:g};{de_cell};{nde_cell};{oil_cell}")
        if m == 30:  # the logger wrote this second twice
            lines.append(f"{m:g};{de_cell};{nde_cell};{oil_cell}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _scene(path: Path) -> Scene:
    d = load_scene(EXAMPLE).to_dict()
    d["measured"] = {"file": path.name, "unit": "degC", "time_column": "time [min]",
                     "columns": dict(COLUMNS)}
    return Scene.from_dict(d, path.parent)


MINUTES = [-5.0, -2.0] + [float(m) for m in range(0, 61, 5)] + [65.0]


class _Page(HTMLParser):
    """The rows of the table after an h3 heading and the notes listed under it."""

    def __init__(self, heading: str) -> None:
        super().__init__()
        self.heading, self.rows, self.notes = heading, [], []
        self._h: list[str] | None = None
        self._state = "before"
        self._cell: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        if tag == "h3":
            self._h = []
            if self._state in ("table", "notes"):
                self._state = "after"
        elif tag == "tr" and self._state == "table":
            self.rows.append([])
        elif tag in ("td", "th", "li") and self._state in ("table", "notes"):
            self._cell = []

    def handle_endtag(self, tag):
        if tag == "h3" and self._h is not None:
            if "".join(self._h).strip() == self.heading and self._state == "before":
                self._state = "table"
            self._h = None
        elif tag == "table" and self._state == "table":
            self._state = "notes"
        elif tag in ("td", "th") and self._cell is not None and self._state == "table":
            self.rows[-1].append("".join(self._cell).strip())
            self._cell = None
        elif tag == "li" and self._cell is not None and self._state == "notes":
            self.notes.append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        if self._h is not None:
            self._h.append(data)
        if self._cell is not None:
            self._cell.append(data)


def test_report_lists_the_files_notes_and_keeps_a_sensor_without_samples(tmp_path):
    scene = _scene(_logger_file(tmp_path / "rig.csv", MINUTES))
    temps = _temps()
    res = Results(tables={"temperatures": temps}, scene_toml=scene.to_toml())
    page = _Page("measured vs predicted")
    page.feed(write_report(res, scene, tmp_path / "report.html").read_text(encoding="utf-8"))
    head, *rows = page.rows
    table = {r[0]: dict(zip(head, r, strict=True)) for r in rows}
    assert list(table) == ["TC_DE", "TC_NDE", "TC_OIL"]
    assert table["TC_OIL"]["note"] == NO_SAMPLE and table["TC_OIL"]["points"] == "0"
    assert table["TC_DE"]["note"] == "" and float(table["TC_DE"]["RMSE [K]"]) == \
        pytest.approx(0.3, abs=1e-3)
    # 13 minutes inside the run, two of them dropouts; the repeated minute 30 is one sample
    assert table["TC_DE"]["points"] == "11" and table["TC_NDE"]["points"] == "13"
    notes = " | ".join(page.notes)
    assert "TC_DE: 2 of 17 readings are gaps (2 dropout flags)" in notes
    # the repeated row counts: the reader counts against the file's data rows
    assert "TC_OIL: 14 of 17 readings are gaps (14 empty cells)" in notes
    assert "1 row(s) repeat the time of the row before" in notes
    assert "3 measured samples outside the run are left out (2 before, 1 after" in notes
    assert f"TC_OIL: {NO_SAMPLE} (left out of the errors)" in notes


def test_a_file_beside_the_run_says_so_and_every_sensor_keeps_its_row(tmp_path):
    scene = _scene(_logger_file(tmp_path / "late.csv", [100.0, 110.0, 120.0]))
    measured = read_measured(scene)
    err = temperature_errors(_temps(), measured, COLUMNS)
    assert list(err["sensor"]) == list(COLUMNS)
    assert (err["note"] == NO_SAMPLE).all() and (err["points"] == 0).all()
    assert err["RMSE [K]"].isna().all()
    lines = terminal_lines(measured, _temps(), COLUMNS)
    assert lines[0] == ("measured vs predicted: TC_DE no sample inside the run, TC_NDE no "
                        "sample inside the run, TC_OIL no sample inside the run")
    assert any("no measured time inside the run (measured 100-120 min, run 0-60 min)" in x
               for x in lines)
    # the overall note says it once; no per-sensor repetition
    assert not any(f": {NO_SAMPLE}" in x for x in lines[1:])


def test_run_prints_errors_and_short_notes(tmp_path, capsys):
    scene = _scene(_logger_file(tmp_path / "rig.csv", MINUTES))
    _print_measured(scene, SimpleNamespace(tables={"temperatures": _temps()}))
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("measured vs predicted: TC_DE RMSE 0.30 K (11 samples), "
                             "TC_NDE RMSE 0.30 K (13 samples), TC_OIL no sample")
    assert out[1] == "measured data notes (5):"
    assert len(out) == 7 and all(x.startswith("  - ") for x in out[2:])
    many = [f"note {i} " + "x" * 300 for i in range(9)]
    short = short_notes(many)
    assert len(short) == 7 and short[-1] == "... 3 more in the report"
    assert all(len(x) <= 160 for x in short)


def test_sensors_have_their_own_marker_in_their_nodes_colour_and_the_axes_are_the_runs(
        tmp_path, monkeypatch):
    scene = _scene(_logger_file(tmp_path / "rig.csv", MINUTES))
    measured = read_measured(scene)
    # an open thermocouple pinned at the type K range end inside the run
    measured.loc[measured["time [s]"] == 1200.0, "TC_NDE"] = 1372.0
    lines, limits = {}, {}
    real_plot = matplotlib.axes.Axes.plot

    def plot(self, *args, **kwargs):
        out = real_plot(self, *args, **kwargs)
        for line in out:
            lines[line.get_label()] = (line.get_color(), line.get_marker(), line.get_xdata())
        return out

    monkeypatch.setattr(matplotlib.axes.Axes, "plot", plot)
    real_save = matplotlib.figure.Figure.savefig

    def save(self, *args, **kwargs):
        limits["x"], limits["y"] = self.axes[0].get_xlim(), self.axes[0].get_ylim()
        return real_save(self, *args, **kwargs)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", save)
    assert fig_temperatures(_temps(), measured, COLUMNS)[:4] == b"\x89PNG"
    de, nde = lines["TC_DE (measured, drive_end.housing)"], \
        lines["TC_NDE (measured, non_drive_end.housing)"]
    assert de[0] == lines["drive_end.housing"][0] and nde[0] == lines["non_drive_end.housing"][0]
    assert de[0] == nde[0] and de[1] != nde[1]  # same node kind: told apart by the marker
    assert lines["TC_OIL (measured, drive_end.oil)"][0] == lines["drive_end.oil"][0]
    assert limits["x"] == (0.0, 60.0)
    low, high = limits["y"]
    # the predicted 35-46.8 degC and the in-run readings (up to 47.1), not the 900 degC
    # after the run nor the pinned 1372: 5 % of that span either side
    assert 34.0 < low < 35.0 and 47.1 < high < 48.0


def test_a_run_longer_than_the_file_is_compared_where_the_file_has_data(tmp_path):
    scene = _scene(_logger_file(tmp_path / "short.csv", [0.0, 10.0, 20.0, 30.0]))
    measured = read_measured(scene)
    err = temperature_errors(_temps(), measured, COLUMNS).set_index("sensor")
    assert err.loc["TC_NDE", "points"] == 4
    lines = terminal_lines(measured, _temps(), COLUMNS)
    assert any("the run is compared with measured data only where the file has them "
               "(measured 0-30 min, run 0-60 min)" in x for x in lines)
