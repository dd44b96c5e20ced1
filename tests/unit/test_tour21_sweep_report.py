"""User tour 21, the sweep report of an oil-flow x inlet-temperature x oil-grade what-if:

* its figures were only inside report.html (a run folder has its figures as PNG files; a
  sweep folder had none to put in a slide or a test report);
* the what-if figure put its six panels in one row (3026 x 397 px), which report.html
  shrank to unreadable strips.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import pandas as pd
import pytest

from thermobearing import report
from thermobearing.commands.report import sweep_figure_file, sweep_report
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep

PNG = b"\x89PNG\r\n\x1a\n"


def _runner(scene_toml: str) -> dict[str, float]:
    """A deterministic stand-in for a run: losses and temperatures from the case's flow,
    inlet temperature and oil grade."""
    sc = loads_scene(scene_toml)
    flow = sc.supply.flow * 6e4  # L/min
    t_in = sc.supply.inlet_temperature - 273.15
    grade = 1.3 if "68" in str(sc.lubricant) else 1.0
    loss = grade * (2000.0 + 30.0 * flow - 10.0 * t_in)
    return {"mean total loss [W]": loss, "raceway_traction [W]": 0.4 * loss,
            "churning_elements [W]": 0.6 * loss, "max over-skidding [%]": 10.0 - 0.1 * flow,
            "final drive_end.housing [degC]": 35.0 + 0.02 * t_in,
            "rise over initial drive_end.housing [K]": 0.02 * t_in,
            "final drive_end.oil [degC]": t_in + 1.0}


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("whatif")
    scene = load_scene()
    d = scene.to_dict()
    sets = [parse_set("supply.flow=15,25,33", d), parse_set("supply.inlet_temperature=30,45", d),
            parse_set("lubricant.preset=ISO_VG46,ISO_VG68", d)]
    run_sweep(scene, sets, out, runner=_runner, workers=1, progress=False)
    sweep_report(out)
    return out


def test_figures_are_written_as_png_files_beside_the_report(folder):
    names = sorted(p.name for p in folder.glob("sweep_*.png"))
    assert names == sorted([
        "sweep_loss_by_source.png",
        "sweep_whatif_supply.flow_L_min.png",
        "sweep_whatif_supply.inlet_temperature_degC.png",
        "sweep_whatif_lubricant.preset.png",
        "sweep_loss_maps_lubricant.preset=ISO_VG46.png",
        "sweep_loss_maps_lubricant.preset=ISO_VG68.png",
    ])
    for name in names:
        assert (folder / name).read_bytes().startswith(PNG)
    html = (folder / "report.html").read_text(encoding="utf-8")
    assert "each figure is also in the folder as a PNG file: sweep_loss_by_source.png" in html


def test_a_later_report_replaces_the_pngs_of_the_earlier_one(folder, tmp_path):
    stale = folder / "sweep_whatif_old_parameter.png"
    stale.write_bytes(PNG)
    sweep_report(folder)
    assert not stale.exists()
    assert (folder / "sweep_loss_by_source.png").is_file()


def test_figure_file_names():
    assert sweep_figure_file("what-if: supply.flow [L/min]") == "sweep_whatif_supply.flow_L_min.png"
    assert sweep_figure_file("loss maps") == "sweep_loss_maps.png"
    assert (sweep_figure_file("loss maps (lubricant.preset = ISO_VG46, checks.skid_limit = 2 %)")
            == "sweep_loss_maps_lubricant.preset=ISO_VG46_checks.skid_limit=2.png")


def test_whatif_panels_wrap_in_rows_of_three(monkeypatch):
    seen = []
    real = report._png

    def keep(fig):
        seen.append(fig)
        return real(fig)

    monkeypatch.setattr(report, "_png", keep)
    df = pd.DataFrame({"flow [L/min]": [15.0, 33.0] * 2, "oil": ["A", "A", "B", "B"],
                       **{f"r{k} [-]": [1.0, 2.0, 3.0, 4.0] for k in range(6)}})
    report.fig_whatif(df, "flow [L/min]", [f"r{k} [-]" for k in range(6)], group="oil")
    fig = seen[-1]
    visible = [ax for ax in fig.axes if ax.get_visible()]
    assert len(visible) == 6
    rows = {round(ax.get_position().y0, 3) for ax in visible}
    assert len(rows) == 2  # two rows of three
    width, height = fig.get_size_inches()
    assert width / height < 3.0  # was 25.2 x 3.5 in
    plt.close(fig)
    report.fig_whatif(df, "flow [L/min]", ["r0 [-]", "r1 [-]"], group="oil")
    assert len([ax for ax in seen[-1].axes if ax.get_visible()]) == 2
    plt.close(seen[-1])
