"""Tour E (session 24): the sweep report's table and figures in the order of the swept values.

``--set supply.flow=33,5,10 --set lubricant.preset=ISO_VG68,ISO_VG32`` gave a report whose
summary table stood in the order typed (33, 5, 10 L/min; VG68 before VG32) while its
figures were sorted; the bars and legends sorted oil names as text (ISO_VG100 before
ISO_VG32), and the what-if axis in natural order, which put MIL_PRF_23699 (27.6 mm^2/s at
40 degC) after ISO_VG46 although the README promises viscosity order.
"""

from __future__ import annotations

import re

import pandas as pd

from thermobearing import load_lubricant
from thermobearing.commands.report import sweep_report
from thermobearing.report import category_order, sort_cases
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep

OILS = ["ISO_VG68", "ISO_VG100", "ISO_VG32", "MIL_PRF_23699", "OIL_4109", "ISO_VG46"]


def test_oils_in_order_of_their_viscosity_at_40_degC():
    order = category_order(OILS, "lubricant.preset")
    nu40 = [load_lubricant(n).kinematic_viscosity(313.15) for n in order]
    assert nu40 == sorted(nu40)
    assert order == ["OIL_4109", "MIL_PRF_23699", "ISO_VG32", "ISO_VG46", "ISO_VG68",
                     "ISO_VG100"]


def test_other_text_and_unloadable_oil_files_in_natural_order(tmp_path):
    assert category_order(["b10", "b9", "a"], "bearings.0.preset") == ["a", "b9", "b10"]
    gone = [str(tmp_path / "vg220.toml"), str(tmp_path / "vg150.toml")]
    assert category_order(gone, "lubricant.path") == [gone[1], gone[0]]


def test_sort_cases_numbers_ascending_oils_by_viscosity():
    df = pd.DataFrame({"supply.flow [L/min]": [33.0, 33.0, 5.0, 5.0],
                       "lubricant.preset": ["ISO_VG100", "ISO_VG32"] * 2,
                       "loss": [4.0, 3.0, 2.0, 1.0]})
    out = sort_cases(df, ["supply.flow [L/min]", "lubricant.preset"])
    assert list(out["loss"]) == [1.0, 2.0, 3.0, 4.0]
    assert list(out.index) == [0, 1, 2, 3]


def _runner(scene_toml: str) -> dict[str, float]:
    """Losses that rise with flow and grade (bookkeeping under test, not physics)."""
    sc = loads_scene(scene_toml)
    nu = load_lubricant(sc.lubricant["preset"]).kinematic_viscosity(313.15)
    churn = sc.supply.flow * 6e4 * 20.0
    return {"mean total loss [W]": churn + nu * 1e7, "churning_elements [W]": churn,
            "raceway_traction [W]": nu * 1e7}


def test_sweep_report_table_follows_the_swept_values(tmp_path):
    scene = load_scene()
    d = scene.to_dict()
    params = [parse_set("supply.flow=33,5,10", d),
              parse_set("lubricant.preset=ISO_VG100,ISO_VG32", d)]
    run_sweep(scene, params, tmp_path, runner=_runner, workers=1, progress=False)
    html = sweep_report(tmp_path).read_text(encoding="utf-8")
    summary = html[html.index("<h2>Summary</h2>"):]
    rows = re.findall(r"<tr>\s*<td>[^<]*</td>\s*<td>([^<]*)</td>\s*<td>([^<]*)</td>",
                      summary)
    assert rows[:6] == [
        ("5", "ISO_VG32"), ("5", "ISO_VG100"), ("10", "ISO_VG32"), ("10", "ISO_VG100"),
        ("33", "ISO_VG32"), ("33", "ISO_VG100")]


def test_lubricant_presets_listed_with_their_grades_as_numbers():
    # `thermobearing lubricant` listed ISO_VG100 before ISO_VG32 (a text sort)
    from thermobearing.lubricant import preset_names

    names = preset_names()
    grades = [n for n in names if n.startswith("ISO_VG")]
    assert grades == sorted(grades, key=lambda n: int(n[len("ISO_VG"):]))
    assert names.index("ISO_VG32") < names.index("ISO_VG100")


def test_sweep_bars_in_rows_with_every_case_labelled(monkeypatch):
    # 72 cases (6 flows x 4 inlets x 3 oils) stood in one 3100 px row labelling every
    # other case; now rows of at most 36, every bar labelled, one loss scale
    import thermobearing.report_losses as report_losses

    figs = []
    monkeypatch.setattr(report_losses, "_png", lambda fig: figs.append(fig) or b"")
    flows = [5.0, 10.0, 20.0, 33.0, 45.0, 60.0]
    rows = [(q, t, oil) for q in flows for t in (25.0, 35.0, 45.0, 60.0)
            for oil in ("ISO_VG32", "ISO_VG46", "ISO_VG68")]
    summary = pd.DataFrame({"supply.flow [L/min]": [r[0] for r in rows],
                            "supply.inlet_temperature [degC]": [r[1] for r in rows],
                            "lubricant.preset": [r[2] for r in rows],
                            "churning_elements [W]": [20.0 * r[0] for r in rows],
                            "raceway_traction [W]": [400.0 - r[1] for r in rows]})
    params = ["supply.flow [L/min]", "supply.inlet_temperature [degC]", "lubricant.preset"]
    report_losses.fig_sweep_breakdown(summary, params)
    axes = figs[-1].axes
    assert len(axes) == 2
    ticks = [t.get_text() for ax in axes for t in ax.get_xticklabels()]
    assert len(ticks) == 72 and ticks[0] == "5 / 25 / ISO_VG32" and ticks[-1] == \
        "60 / 60 / ISO_VG68"
    assert axes[0].get_ylim() == axes[1].get_ylim()
    report_losses.fig_sweep_breakdown(summary.iloc[:12], params)
    assert len(figs[-1].axes) == 1
    assert len(figs[-1].axes[0].get_xticklabels()) == 12
    import matplotlib.pyplot as plt

    for fig in figs:
        plt.close(fig)
