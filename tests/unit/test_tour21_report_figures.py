"""User tour 21, the temperature figure of a run with readings logged in degF.

Before the fix the legend named the sensor 'TC1 [°F] (measured, drive_end.housing)' on the
degC axis, as if the points were in degF, and stood inside the axes, over the readings of
the first 20 minutes.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from thermobearing import report_measured
from thermobearing.measured import read_measured_file


@pytest.fixture()
def figure(monkeypatch):
    """fig_temperatures' matplotlib figure (captured before it is written as PNG)."""
    box = {}

    def keep(fig):
        fig.canvas.draw()
        box["fig"] = fig
        return b""

    monkeypatch.setattr(report_measured, "_png", keep)
    return box


def _temps() -> pd.DataFrame:
    t = np.linspace(0.0, 3960.0, 45)
    return pd.DataFrame({"time [s]": t,
                         "drive_end.housing [degC]": 35.0 + 13.0 * (1 - np.exp(-t / 1500)),
                         "drive_end.oil [degC]": 35.0 + 6.0 * (1 - np.exp(-t / 60))})


def _measured(tmp_path, temps: pd.DataFrame) -> pd.DataFrame:
    lines = ["time [min];TC1 [°F]"]
    for t, c in zip(temps["time [s]"], temps["drive_end.housing [degC]"], strict=True):
        lines.append(f"{t / 60:.2f};{c * 9 / 5 + 32:.2f}".replace(".", ","))
    path = tmp_path / "rig.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return read_measured_file(path, "time [min]", ["TC1 [°F]"], unit="degF")


def test_reader_records_the_unit_each_sensor_was_converted_from(tmp_path):
    got = _measured(tmp_path, _temps())
    assert got.attrs["units"] == {"TC1 [°F]": "degF"}
    np.testing.assert_allclose(got["TC1 [°F]"], _temps()["drive_end.housing [degC]"],
                               atol=0.006)


def test_legend_says_degf_readings_are_drawn_in_degc(tmp_path, figure):
    temps = _temps()
    report_measured.fig_temperatures(temps, _measured(tmp_path, temps),
                                     {"TC1 [°F]": "drive_end.housing"})
    ax = figure["fig"].axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "TC1 [°F] (measured in degF, shown in degC, drive_end.housing)" in labels
    assert ax.get_ylabel() == "temperature [degC]"


def test_readings_logged_in_degc_keep_the_short_label(tmp_path, figure):
    temps = _temps()
    measured = pd.DataFrame({"time [s]": temps["time [s]"],
                             "TC1": temps["drive_end.housing [degC]"]})
    report_measured.fig_temperatures(temps, measured, {"TC1": "drive_end.housing"})
    labels = [t.get_text() for t in figure["fig"].axes[0].get_legend().get_texts()]
    assert "TC1 (measured, drive_end.housing)" in labels


def test_legend_stands_beside_the_axes_not_over_the_readings(tmp_path, figure):
    temps = _temps()
    report_measured.fig_temperatures(temps, _measured(tmp_path, temps),
                                     {"TC1 [°F]": "drive_end.housing"})
    fig = figure["fig"]
    ax = fig.axes[0]
    renderer = fig.canvas.get_renderer()
    legend_box = ax.get_legend().get_window_extent(renderer)
    axes_box = ax.get_window_extent(renderer)
    assert legend_box.x0 >= axes_box.x1  # wholly right of the plotting area


def test_cage_speed_figure_names_the_theoretical_line(monkeypatch):
    """The dashed epicyclic ratio was named only in the report's caption, not in the PNG
    (which the run folder also holds as a file): its legend had the bearings only."""
    from thermobearing import report

    box = {}

    def keep(fig):
        box["fig"] = fig
        return b""

    monkeypatch.setattr(report, "_png", keep)
    rows = [{"step": i, "bearing": b, "speed [rpm]": 1800.0, "radial load [kN]": 1.0,
             "axial load [kN]": 2.0 * i, "cage speed ratio [-]": 0.2 + 0.1 * i,
             "theoretical cage speed ratio [-]": 0.45}
            for i in range(3) for b in ("drive_end", "non_drive_end")]
    report.fig_csr(pd.DataFrame(rows))
    labels = [t.get_text() for t in box["fig"].axes[0].get_legend().get_texts()]
    assert labels == ["drive_end", "non_drive_end", "theoretical (epicyclic) CSR"]
