"""The sweep report's figures (report.fig_loss_maps / fig_whatif) on the sweeps a user makes
(a user tour of issue 6 item 6): each test is a defect found on the command line."""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd

from thermobearing import cli
from thermobearing.report import fig_loss_maps
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep


def loss_runner(scene_toml: str) -> dict[str, float]:
    """Made-up but deterministic 'losses' of a case: linear in flow and inlet temperature."""
    sc = loads_scene(scene_toml)
    return {"mean total loss [W]": 1e6 * sc.supply.flow + sc.supply.inlet_temperature,
            "churning [W]": 5e5 * sc.supply.flow}


def test_loss_maps_with_one_value_of_a_parameter_are_curves():
    # before: TypeError "Input z must be at least a (2, 2) shaped array, but has shape (1, 3)"
    df = pd.DataFrame({"x": [1.0, 2.0, 3.0], "y": [5.0, 5.0, 5.0],
                       "a [W]": [1.0, 2.0, 3.0], "b [W]": [np.nan] * 3})
    png = fig_loss_maps(df, "x", "y", ["a [W]", "b [W]"])
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    png = fig_loss_maps(df.rename(columns={"x": "y", "y": "x"}), "x", "y", ["a [W]"])
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_loss_maps_of_a_sweep_still_running_leave_gaps():
    df = pd.DataFrame({"x": [1.0, 2.0, 3.0, 1.0, 2.0], "y": [1.0, 1.0, 1.0, 2.0, 2.0],
                       "a [W]": [1.0, 2.0, 3.0, 4.0, 5.0]})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert fig_loss_maps(df, "x", "y", ["a [W]"])[:4] == b"\x89PNG"


def test_report_of_a_sweep_with_a_single_valued_parameter(tmp_path, capsys):
    # `thermobearing sweep --set supply.flow=15,33 --set supply.inlet_temperature=35` then
    # `thermobearing report DIR`: before, a traceback from matplotlib's contourf
    scene = load_scene()
    d = scene.to_dict()
    run_sweep(scene, [parse_set("supply.flow=15,33", d),
                      parse_set("supply.inlet_temperature=35", d)], tmp_path,
              runner=loss_runner, workers=1, progress=False)
    assert cli.main(["report", str(tmp_path)]) == 0
    html = (tmp_path / "report.html").read_text()
    assert "loss maps" in html and html.count("<img") >= 2


def test_loss_maps_single_case():
    df = pd.DataFrame({"x": [1.0], "y": [2.0], "a [W]": [3.0]})
    assert fig_loss_maps(df, "x", "y", ["a [W]"])[:4] == b"\x89PNG"


def _captured_figure(monkeypatch):
    """Make report._png hand back the figure instead of PNG bytes (to inspect it)."""
    import thermobearing.report as report

    seen = []
    monkeypatch.setattr(report, "_png", lambda fig: seen.append(fig) or b"")
    return seen


def test_whatif_legend_of_many_curves_is_outside_the_panels(monkeypatch):
    # before: nine curves of a 4 x 3 x 3 sweep (flow x inlet temperature x oil grade) had
    # their 'supply.inlet_temperature [degC] = 30, lubricant.preset = ISO_VG32' labels in
    # the first panel, covering its data
    from thermobearing.report import fig_whatif

    seen = _captured_figure(monkeypatch)
    rows = [{"flow [L/min]": f, "T_in [degC]": t, "oil": o, "mean total loss [W]": f * t}
            for f in (15, 20, 25, 33) for t in (30, 40, 50) for o in ("VG32", "VG46", "VG68")]
    df = pd.DataFrame(rows)
    fig_whatif(df, "flow [L/min]", ["mean total loss [W]"], group=["T_in [degC]", "oil"])
    fig = seen[-1]
    assert fig.axes[0].get_legend() is None and len(fig.legends) == 1
    legend = fig.legends[0]
    assert legend.get_title().get_text() == "T_in [degC], oil"
    labels = [t.get_text() for t in legend.get_texts()]
    assert len(labels) == 9 and labels[0] == "30, VG32"
    # two curves: the legend stays in the first panel, titled with the column
    fig_whatif(df[(df["T_in [degC]"] == 30) & (df["oil"] != "VG68")], "flow [L/min]",
               ["mean total loss [W]"], group="oil")
    inside = seen[-1].axes[0].get_legend()
    assert inside is not None and inside.get_title().get_text() == "oil"
    # no group: no legend
    fig_whatif(df[(df["T_in [degC]"] == 30) & (df["oil"] == "VG32")], "flow [L/min]",
               ["mean total loss [W]"])
    assert seen[-1].axes[0].get_legend() is None and not seen[-1].legends
    import matplotlib.pyplot as plt

    for f in seen:
        plt.close(f)


def test_whatif_over_oil_grades(monkeypatch):
    # a sweep of lubricant.preset alone had no what-if figure: fig_whatif needed a numeric x
    from thermobearing.report import fig_whatif

    seen = _captured_figure(monkeypatch)
    df = pd.DataFrame({"lubricant.preset": ["ISO_VG32", "ISO_VG68", "ISO_VG32", "ISO_VG68"],
                       "supply.flow [L/min]": [15.0, 15.0, 33.0, 33.0],
                       "mean total loss [W]": [1261.0, 1559.0, 1522.0, 1878.0]})
    fig_whatif(df, "lubricant.preset", ["mean total loss [W]"], group="supply.flow [L/min]")
    ax = seen[-1].axes[0]
    assert [t.get_text() for t in ax.get_xticklabels()] == ["ISO_VG32", "ISO_VG68"]
    lines = ax.get_lines()
    assert len(lines) == 2
    assert list(lines[1].get_ydata()) == [1522.0, 1878.0]  # 33 L/min: VG32 then VG68
    import matplotlib.pyplot as plt

    plt.close(seen[-1])
